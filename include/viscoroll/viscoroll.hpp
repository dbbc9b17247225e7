// viscoroll: umbrella header. Includes the materials, quadrature rules and the solvers that need
// nothing optional; the 3-D boundary-element reference and optional back ends have headers of
// their own.
//
// Reference: C. Panek and J. J. Kalker, "Three-dimensional contact of a rigid roller traversing a
// viscoelastic half space", J. Inst. Maths Applics (1980).
#pragma once

#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/errors.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/quadrature/adaptive.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
