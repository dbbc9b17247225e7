// viscoroll: the default of a field that every scene must be given.
//
// A scene (PlaneScene, LineScene, BemScene) is an aggregate whose numeric fields default to
// detail::required_field<Real>(): a consteval call that cannot be evaluated. A scene built with
// every field named compiles as before,
//
//     viscoroll::LineScene<double>{.c1 = 1.0, .c2 = 0.08, .load = 2.09, .speed = 0.5}
//
// while one that leaves a field out uses that default and does not compile; so the plane's
// three values given to the line solver, LineScene<double>{c1, load, speed}, which would set
// c2 = load, load = speed and speed = 0, is a compile error naming required_field and the field
// (tests/needs/scene_fields.cpp).
#pragma once

namespace viscoroll::detail {

/// Never a constant expression: its use as a default member initialiser makes the field required.
template <class Real>
consteval Real required_field() {
  throw "viscoroll: every field of a scene must be given; name them with designated initialisers, "
        "e.g. LineScene<double>{.c1 = c1, .c2 = c2, .load = load, .speed = speed}";
}

}  // namespace viscoroll::detail
