// A scene that leaves a field out must fail to compile (core/required_field.hpp): each numeric
// field of PlaneScene, LineScene and BemScene defaults to detail::required_field<Real>(), which
// is never a constant expression. tests/CMakeLists.txt compiles this file once per case and
// looks for required_field in the compiler's message (cases 1-5), or for a clean compile
// (case 0: every field named, in each scalar). Not part of any executable.
#include <viscoroll/bem/bem_scene.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/plane/plane_solver.hpp>

#if VISCOROLL_SCENE_CASE == 0
// Every field named: compiles, in float, double and long double, with and without a profile.
template <class Real>
Real all_named(Real c1, Real c2, Real load, Real speed) {
  const viscoroll::PlaneScene<Real> plane{.c1 = c1, .load = load, .speed = speed};
  const viscoroll::LineScene<Real> line{.c1 = c1, .c2 = c2, .load = load, .speed = speed};
  const viscoroll::BemScene<Real> bem{.c1 = c1, .c2 = c2, .load = load, .speed = speed};
  const viscoroll::BemScene<Real> shaped{
      .c1 = c1, .c2 = c2, .load = load, .speed = speed, .profile = [](Real x, Real y) {
        return x * x + y * y;
      }};
  return plane.c1 + line.c2 + bem.load + shaped.speed;
}
template float all_named(float, float, float, float);
template double all_named(double, double, double, double);
template long double all_named(long double, long double, long double, long double);
#elif VISCOROLL_SCENE_CASE == 1
// The plane's three values given to the line solver's scene: c2 = load, load = speed, and
// speed left out.
double mixed_up(double c1, double load, double speed) {
  const viscoroll::LineScene<double> scene{c1, load, speed};
  return scene.speed;
}
#elif VISCOROLL_SCENE_CASE == 2
// The same mix-up with designated initialisers: c2 left out.
double mixed_up(double c1, double load, double speed) {
  const viscoroll::LineScene<double> scene{.c1 = c1, .load = load, .speed = speed};
  return scene.c2;
}
#elif VISCOROLL_SCENE_CASE == 3
// A plane scene without its speed.
double no_speed(double c1, double load) {
  const viscoroll::PlaneScene<double> scene{c1, load};
  return scene.speed;
}
#elif VISCOROLL_SCENE_CASE == 4
// The bem scene: the plane's three values.
double mixed_up(double c1, double load, double speed) {
  const viscoroll::BemScene<double> scene{c1, load, speed};
  return scene.speed;
}
#elif VISCOROLL_SCENE_CASE == 5
// A default-constructed scene, filled in afterwards.
double filled_later(double c1, double c2, double load, double speed) {
  viscoroll::LineScene<double> scene;
  scene.c1 = c1, scene.c2 = c2, scene.load = load, scene.speed = speed;
  return scene.c1;
}
#endif
