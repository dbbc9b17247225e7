// viscoroll: the roller's profile, a policy of the solvers (docs/rollers.md).
//
// The rigid roller's surface, measured from the plane of its lowest point, is (Eq. 27 generalised)
//   S(x, y) = d - C1 x^2 / 2 - h(y),
// C1 = 1/R the curvature across the roller (R its radius) and h(y) the drop along its axis. The
// paper's ellipsoid has h = C2 y^2 / 2; a bearing or guide roller is a cylinder whose ends drop
// away (a circular or a logarithmic crown) and which may run misaligned (a tilt theta adds
// theta y to h). Every profile is a type modelling RollerProfile; each validates its parameters
// (std::invalid_argument naming the parameter and its range).
#pragma once

#include <algorithm>
#include <boost/math/interpolators/makima.hpp>
#include <cmath>
#include <concepts>
#include <limits>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

/// A roller profile, documented by its members:
///   - `real_type`: the scalar;
///   - `c1() const`: the curvature 1/R across the roller (> 0);
///   - `drop(y) const`: h(y), the rise of the gap along the axis at y (S = d - C1 x^2/2 - h(y));
///   - `drop_slope(y) const`: h'(y);
///   - `y_min() const`, `y_max() const`: where the roller's body ends (-inf, +inf if it does not);
///     drop and drop_slope are defined strictly between them;
///   - `symmetric() const`: h(-y) = h(y) and y_min = -y_max (the line solver's even
///     representation applies; otherwise it adds the odd parts and the contact's centre).
template <class P>
concept RollerProfile = RealScalar<typename P::real_type> &&
    requires(const P& p, typename P::real_type y) {
  { p.c1() } -> std::convertible_to<typename P::real_type>;
  { p.drop(y) } -> std::convertible_to<typename P::real_type>;
  { p.drop_slope(y) } -> std::convertible_to<typename P::real_type>;
  { p.y_min() } -> std::convertible_to<typename P::real_type>;
  { p.y_max() } -> std::convertible_to<typename P::real_type>;
  { p.symmetric() } -> std::convertible_to<bool>;
};

/// The paper's doubly curved roller (Eq. 27): h = C2 y^2 / 2, unbounded.
template <RealScalar Real>
class EllipsoidProfile {
 public:
  /// The scalar.
  using real_type = Real;
  /// Throws unless c1 > 0 and c2 > 0 (finite).
  EllipsoidProfile(Real c1, Real c2) : c1_(c1), c2_(c2) {
    detail::require_positive("c1", c1);
    detail::require_positive("c2", c2);
  }
  /// C1 = 1/R, the curvature across the roller.
  Real c1() const { return c1_; }
  /// C2, the curvature along the axis.
  Real c2() const { return c2_; }
  /// h(y) = C2 y^2 / 2.
  Real drop(Real y) const { return c2_ * y * y / 2; }
  /// h'(y) = C2 y.
  Real drop_slope(Real y) const { return c2_ * y; }
  /// -inf: the ellipsoid has no ends.
  Real y_min() const { return -std::numeric_limits<Real>::infinity(); }
  /// +inf: the ellipsoid has no ends.
  Real y_max() const { return std::numeric_limits<Real>::infinity(); }
  /// Always true: h is even.
  bool symmetric() const { return true; }

 private:
  Real c1_, c2_;
};

/// A cylinder of radius R with a flat (cylindrical) part of length L_f and circular crowns of
/// radius R_c beyond it, the whole roller of length L (L = +inf: crowned to the crown circle's
/// end, L_f/2 + R_c from the centre):
///   h(y) = 0 for |y| <= L_f/2,  h(y) = R_c - sqrt(R_c^2 - s^2),  s = |y| - L_f/2,
/// evaluated as s^2 / (R_c + sqrt(R_c^2 - s^2)) (no cancellation for s << R_c). L_f = 0 is a
/// barrel roller, whose h = y^2/(2 R_c) + O(y^4/R_c^3): the ellipsoid with C2 = 1/R_c near y = 0.
template <RealScalar Real>
class CrownedCylinder {
 public:
  /// The scalar.
  using real_type = Real;
  /// Throws unless radius > 0, flat_length >= 0, crown_radius > 0 (finite) and
  /// length > flat_length (length may be +inf).
  CrownedCylinder(Real radius, Real flat_length, Real crown_radius,
                  Real length = std::numeric_limits<Real>::infinity())
      : radius_(radius), flat_(flat_length), crown_(crown_radius), length_(length) {
    detail::require_positive("radius", radius);
    detail::require_non_negative("flat_length", flat_length);
    detail::require_positive("crown_radius", crown_radius);
    detail::require(!(length <= flat_length) && !std::isnan(static_cast<double>(length)), "length",
                    length, "length > flat_length");
  }
  /// C1 = 1/R.
  Real c1() const { return 1 / radius_; }
  /// R, the roller's radius.
  Real radius() const { return radius_; }
  /// L_f, the length of the flat (cylindrical) part.
  Real flat_length() const { return flat_; }
  /// R_c, the radius of the crowns.
  Real crown_radius() const { return crown_; }
  /// L, the roller's length (may be +inf).
  Real length() const { return length_; }
  /// h(y): 0 on the flat part, R_c - sqrt(R_c^2 - s^2) on the crowns.
  Real drop(Real y) const {
    using std::abs;
    using std::sqrt;
    const Real s = abs(y) - flat_ / 2;
    if (s <= 0) return 0;
    return s * s / (crown_ + sqrt((crown_ - s) * (crown_ + s)));
  }
  /// h'(y): 0 on the flat part, s / sqrt(R_c^2 - s^2) (signed as y) on the crowns.
  Real drop_slope(Real y) const {
    using std::abs;
    using std::sqrt;
    const Real s = abs(y) - flat_ / 2;
    if (s <= 0) return 0;
    const Real slope = s / sqrt((crown_ - s) * (crown_ + s));
    return y < 0 ? -slope : slope;
  }
  /// min(L/2, L_f/2 + R_c): the roller's end or the end of the crown circle.
  Real y_max() const { return std::min(length_ / 2, flat_ / 2 + crown_); }
  /// -y_max().
  Real y_min() const { return -y_max(); }
  /// Always true: h is even.
  bool symmetric() const { return true; }

 private:
  Real radius_, flat_, crown_, length_;
};

/// A logarithmic crown on a roller of radius R and length L:
///   h(y) = -A ln(1 - k (2y/L)^2),  k = 1 - exp(-z_m / A),
/// with A > 0 (a length: near the centre h ~ A k (2y/L)^2) and z_m > 0 the drop at the ends
/// (h(+-L/2) = z_m). z_m = +inf (k = 1) is Lundberg's profile, whose drop is infinite at the ends
/// and whose A for a design load W per roller of a material with Young's modulus E and Poisson's
/// ratio nu is A = 2 W (1 - nu^2) / (pi E L) (`lundberg_scale`); a finite z_m is the usual
/// modification that bounds the drop at the ends.
template <RealScalar Real>
class LogarithmicCrown {
 public:
  /// The scalar.
  using real_type = Real;
  /// Throws unless radius, length, scale > 0 (finite) and end_drop > 0 (may be +inf).
  LogarithmicCrown(Real radius, Real length, Real scale,
                   Real end_drop = std::numeric_limits<Real>::infinity())
      : radius_(radius), length_(length), scale_(scale), end_drop_(end_drop) {
    using std::expm1;
    detail::require_positive("radius", radius);
    detail::require_positive("length", length);
    detail::require_positive("scale", scale);
    detail::require(end_drop > 0, "end_drop", end_drop, "end_drop > 0 (or +inf)");
    k_ = end_drop == std::numeric_limits<Real>::infinity() ? Real(1) : -expm1(-end_drop / scale);
  }
  /// Lundberg's A = 2 W (1 - nu^2) / (pi E L) for the design load W (N), Young's modulus E (Pa),
  /// Poisson's ratio nu and roller length L (m).
  static Real lundberg_scale(Real load, Real youngs_modulus, Real nu, Real length) {
    detail::require_positive("load", load);
    detail::require_positive("youngs_modulus", youngs_modulus);
    detail::require_poisson_ratio(nu);
    detail::require_positive("length", length);
    const Real pi = std::acos(Real(-1));
    return 2 * load * (1 - nu * nu) / (pi * youngs_modulus * length);
  }
  /// C1 = 1/R.
  Real c1() const { return 1 / radius_; }
  /// L, the roller's length.
  Real length() const { return length_; }
  /// A, the crown's scale (a length).
  Real scale() const { return scale_; }
  /// z_m, the drop at the ends (+inf for Lundberg's profile).
  Real end_drop() const { return end_drop_; }
  /// h(y) = -A ln(1 - k (2y/L)^2).
  Real drop(Real y) const {
    using std::log1p;
    const Real u = 2 * y / length_;
    return -scale_ * log1p(-k_ * u * u);
  }
  /// h'(y) = 8 A k y / (L^2 (1 - k (2y/L)^2)).
  Real drop_slope(Real y) const {
    const Real u = 2 * y / length_;
    return scale_ * k_ * 2 * u * (2 / length_) / (1 - k_ * u * u);
  }
  /// L/2.
  Real y_max() const { return length_ / 2; }
  /// -L/2.
  Real y_min() const { return -length_ / 2; }
  /// Always true: h is even.
  bool symmetric() const { return true; }

 private:
  Real radius_, length_, scale_, end_drop_, k_{};
};

/// A drop h(y) tabulated at points y_0 < y_1 < ... (at least 4), interpolated by the modified
/// Akima spline (boost::math::interpolators::makima: continuous slope, no overshoot at steps in
/// the data); the roller ends at the table's ends.
template <RealScalar Real>
class TabulatedProfile {
 public:
  /// The scalar.
  using real_type = Real;
  /// Throws unless radius > 0, y and h have the same size >= 4, y strictly increasing and
  /// every value finite (named "y[3]", "h[0]").
  TabulatedProfile(Real radius, std::vector<Real> y, std::vector<Real> h)
      : radius_(radius),
        y_(std::move(y)),
        h_(std::move(h)),
        symmetric_(is_symmetric(y_, h_)),
        spline_(checked(y_, h_.size()), std::vector<Real>(h_)) {
    detail::require_positive("radius", radius);
  }
  /// C1 = 1/R.
  Real c1() const { return 1 / radius_; }
  /// h(y), the spline through the table.
  Real drop(Real y) const { return spline_(y); }
  /// h'(y), the spline's slope.
  Real drop_slope(Real y) const { return spline_.prime(y); }
  /// The table's first point y_0.
  Real y_min() const { return y_.front(); }
  /// The table's last point.
  Real y_max() const { return y_.back(); }
  /// Whether the table is mirror-symmetric: y_i = -y_(n-1-i) and h_i = h_(n-1-i).
  bool symmetric() const { return symmetric_; }
  /// The tabulated points y_i.
  const std::vector<Real>& y() const { return y_; }
  /// The tabulated drops h_i.
  const std::vector<Real>& h() const { return h_; }

 private:
  static std::vector<Real> checked(const std::vector<Real>& y, std::size_t h_size) {
    detail::require(y.size() >= 4, "y.size()", y.size(), "at least 4 points");
    detail::require(h_size == y.size(), "h.size()", h_size, "h.size() == y.size()");
    for (std::size_t i = 0; i < y.size(); ++i) {
      detail::require_finite("y[" + std::to_string(i) + "]", y[i], "finite");
      if (i > 0)
        detail::require(y[i] > y[i - 1], "y[" + std::to_string(i) + "]", y[i],
                        "y strictly increasing");
    }
    return y;
  }
  static bool is_symmetric(const std::vector<Real>& y, const std::vector<Real>& h) {
    for (std::size_t i = 0; i < h.size(); ++i)
      detail::require_finite("h[" + std::to_string(i) + "]", h[i], "finite");
    if (y.size() != h.size()) return false;
    for (std::size_t i = 0, j = y.size(); i < y.size(); ++i)
      if (y[i] != -y[--j] || h[i] != h[j]) return false;
    return true;
  }

  Real radius_;
  std::vector<Real> y_, h_;
  bool symmetric_;
  boost::math::interpolators::makima<std::vector<Real>> spline_;
};

/// A profile run misaligned by the angle theta (rad): h(y) = base.h(y) + theta y. The contact
/// shifts towards the side pressed harder (y < 0 for theta > 0).
template <RollerProfile Base>
class Tilted {
 public:
  /// The base profile's scalar.
  using real_type = typename Base::real_type;
  /// Throws unless |theta| < 0.1 rad (the small-slope theory: the roller's axis stays nearly
  /// parallel to the surface) and finite.
  Tilted(Base base, real_type theta) : base_(std::move(base)), theta_(theta) {
    using std::abs;
    detail::require(abs(theta) < real_type(0.1), "tilt", theta, "|tilt| < 0.1 rad");
  }
  /// The aligned profile.
  const Base& base() const { return base_; }
  /// theta (rad).
  real_type tilt() const { return theta_; }
  /// The base's C1.
  real_type c1() const { return base_.c1(); }
  /// base.h(y) + theta y.
  real_type drop(real_type y) const { return base_.drop(y) + theta_ * y; }
  /// base.h'(y) + theta.
  real_type drop_slope(real_type y) const { return base_.drop_slope(y) + theta_; }
  /// The base's y_min().
  real_type y_min() const { return base_.y_min(); }
  /// The base's y_max().
  real_type y_max() const { return base_.y_max(); }
  /// True only untilted (theta = 0) on a symmetric base.
  bool symmetric() const { return theta_ == 0 && base_.symmetric(); }

 private:
  Base base_;
  real_type theta_;
};

/// A view of any RollerProfile over Real, itself a RollerProfile: it refers to the profile (which
/// must outlive it) and calls its drop and drop_slope through two function pointers. The line
/// solver solves every profile through a ProfileView, so that its rolling iteration is compiled
/// once per scalar and material rather than once per profile type (docs/building.md, "Build
/// cost"); the same arithmetic, so the same digits, as the profile's own.
template <RealScalar Real>
class ProfileView {
 public:
  /// The scalar.
  using real_type = Real;
  /// A view of profile, which must outlive the view.
  template <RollerProfile P>
  requires(std::same_as<typename P::real_type, Real> &&
           !std::same_as<P, ProfileView>) explicit ProfileView(const P& profile)
      : profile_(&profile),
        drop_([](const void* p, Real y) -> Real { return static_cast<const P*>(p)->drop(y); }),
        slope_(
            [](const void* p, Real y) -> Real { return static_cast<const P*>(p)->drop_slope(y); }),
        c1_(profile.c1()),
        y_min_(profile.y_min()),
        y_max_(profile.y_max()),
        symmetric_(profile.symmetric()) {}
  /// The profile's C1.
  Real c1() const { return c1_; }
  /// The profile's h(y).
  Real drop(Real y) const { return drop_(profile_, y); }
  /// The profile's h'(y).
  Real drop_slope(Real y) const { return slope_(profile_, y); }
  /// The profile's y_min().
  Real y_min() const { return y_min_; }
  /// The profile's y_max().
  Real y_max() const { return y_max_; }
  /// The profile's symmetric().
  bool symmetric() const { return symmetric_; }

 private:
  const void* profile_;
  Real (*drop_)(const void*, Real);
  Real (*slope_)(const void*, Real);
  Real c1_, y_min_, y_max_;
  bool symmetric_;
};

}  // namespace viscoroll
