// viscoroll: the contact along the roller's axis, as the BEM (BemSolution::along_roller) and the
// line solver (LineSolution::along_roller) return it (docs/rollers.md, "Outputs along the
// roller").
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>
#include <viscoroll/core/concepts.hpp>

namespace viscoroll {

/// The contact along the roller's axis (docs/rollers.md, "Outputs along the roller"): at each
/// station y, the load per unit length F0(y) (Eq. 33), the half width a(y) and the offset b(y)
/// of the contact's centre ahead of the roller's axis (Eq. 29), and the largest pressure there;
/// the contact's ends y_minus < y_plus and the peak of F0.
template <RealScalar Real>
struct AlongRoller {
  std::vector<Real> y;      ///< stations (the BEM: its grid's rows from y_minus to y_plus; the line
                            ///< solver: evenly spaced inside (-l, l))
  std::vector<Real> f0;     ///< load per unit length, N/m
  std::vector<Real> a;      ///< half width of the contact, m
  std::vector<Real> b;      ///< offset of its centre ahead of the axis, m
  std::vector<Real> p_max;  ///< largest pressure across the contact, Pa
  ///@{
  Real y_minus = 0, y_plus = 0;  ///< the contact's ends along y
  ///@}
  Real f0_max = 0;    ///< the largest F0
  Real f0_max_y = 0;  ///< where it is (the first station, if several)

  /// F0 at the station nearest `at` (the first of two equally near); 0 without stations. With
  /// at = 0: the F0(0) that an edge peak f0_max is compared with.
  Real f0_nearest(Real at) const {
    using std::abs;
    std::size_t k = 0;
    for (std::size_t i = 1; i < y.size(); ++i)
      if (abs(y[i] - at) < abs(y[k] - at)) k = i;
    return f0.empty() ? Real(0) : f0[k];
  }
};

}  // namespace viscoroll
