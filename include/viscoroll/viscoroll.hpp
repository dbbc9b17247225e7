// viscoroll: umbrella header. Includes the materials, quadrature rules and the solvers that need
// nothing optional; the 3-D boundary-element reference and optional back ends have headers of
// their own.
//
// Reference: C. Panek and J. J. Kalker, "Three-dimensional contact of a rigid roller traversing a
// viscoelastic half space", J. Inst. Maths Applics (1980).
#pragma once

/// @mainpage viscoroll
///
/// The steady contact of a rigid roller rolling on viscoelastic rubber: the line-contact theory
/// of Panek & Kalker (1980), the plane problem and a 3-D boundary-element reference. Everything
/// is in namespace viscoroll (bem::, numerics::, special:: below it); this reference lists each
/// public name with its header's comments. docs/reference.md gives the API by component and
/// docs/guide.md how to use it; names in detail namespaces and headers under detail/ are
/// internal and not listed.

#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/errors.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/quadrature/adaptive.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
