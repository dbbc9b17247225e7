// The centre row y = 0 of a BEM solution (a grid of odd ny, centred on y = 0): its load per unit
// length w = sum_i p(i, 0) hx and first moment sum_i x_i p(i, 0) hx, the quantities a plane
// solution at load w is compared with (its chi = C1 moment / w, Eq. 51).
#pragma once

namespace viscoroll::testing {

struct CentreRow {
  double load = 0;    ///< w, per unit length
  double moment = 0;  ///< int x p dx over the row
};

template <class BemSolution>
CentreRow centre_row(const BemSolution& s) {
  const int j0 = (s.grid.ny - 1) / 2;
  CentreRow row;
  for (int i = 0; i < s.grid.nx; ++i) {
    row.load += static_cast<double>(s.p(i, j0) * s.grid.hx);
    row.moment += static_cast<double>(s.grid.x(i) * s.p(i, j0) * s.grid.hx);
  }
  return row;
}

}  // namespace viscoroll::testing
