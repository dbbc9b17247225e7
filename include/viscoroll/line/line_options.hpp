// viscoroll: the runtime settings of the line solver (line_solver.hpp): its discretisation, its
// iteration and the fast setting. Apart from the solver, so that a caller's configuration can hold
// them without the solver's numerics (the command line's and the Python module's option parsing).
#pragma once

#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/line_basis.hpp>

namespace viscoroll {

/// How the line solver forms the Jacobian of its residual.
enum class LineJacobian {
  analytic,    ///< chain rule through the shape and the strip functions (LineResidual::jacobian)
  difference,  ///< forward differences, 2 terms + 3 residual evaluations
};

/// Runtime settings of the line solver.
struct LineOptions {
  /// Discretisation: ln a(y) has `terms` Chebyshev coefficients, b(y) has terms + 1; the
  /// equations are collocated at terms + 1 points.
  int terms = 8;
  /// Levenberg-Marquardt iterations allowed (each costs one residual evaluation per damping try,
  /// plus one Jacobian when it is refreshed: ~2.5 residual evaluations semi-analytic, 2 terms + 3
  /// by differences).
  int max_iterations = 100;
  /// Expansion variable of a(y), b(y); LineBasis::s_mapped with oversampling for the slow regime.
  LineBasis basis = LineBasis::t_squared;
  /// Collocation points per coefficient of b(y): the equations hold at oversampling (terms + 1)
  /// points. 1: the square system, solved exactly where it has a root. k > 1: the least-squares
  /// fit of the paper (Section 7), which converges with `terms` where the line equations have no
  /// solution at all (the slow regime, V tau <~ 0.1 a0; docs/line-solver.md, "Oversampling").
  int oversampling = 1;
  /// How the Jacobian is formed: semi-analytic (LineResidual::jacobian, default) or by forward
  /// differences.
  LineJacobian jacobian = LineJacobian::analytic;
  /// Where Levenberg-Marquardt stops at a least-squares minimum with no root of the equations
  /// near it, minimise |r|^2 there by Newton's method with its second-order term (the paper's
  /// least-squares solution, Section 7; docs/line-solver.md, "Least-squares minima"). Needs the
  /// semi-analytic Jacobian; otherwise such a stop is reported not converged.
  bool least_squares = true;
  /// The relative accuracy of the residual's integrals (LineNodeRule, docs/theory.md section 7),
  /// at most 1e-4: 0, the default, the scalar's epsilon (every integral exact to rounding); a
  /// larger tolerance builds fewer quadrature nodes (a cheaper residual). The bound is
  /// pessimistic: on the paper's scene 1e-8 moved the solution by at most 1e-12 and 1e-4 by at
  /// most 6e-8 (docs/performance.md, "The fast setting").
  double quadrature_tolerance = 0;
  /// max |r| of the scaled equations at which an intermediate stage of the continuation in N
  /// (docs/line-solver.md, "Continuation in N") stops and seeds the next: 0, the default, a root
  /// of every stage; at most 0.1. A stage's iterate only seeds the next, so a loose stop saves
  /// its end game (the Newton steps to a root) where the last stage lands on the same root
  /// (docs/performance.md, "The fast setting").
  double stage_tolerance = 0;
  /// Levenberg-Marquardt's starting damping at the stages after the first (the first, from the
  /// cold start or a seed, starts at 1e-3): the default 1e-3; 1e-12 ... 1. A stage starts from
  /// the previous stage's solution padded with zero coefficients, near its root, where an
  /// undamped Gauss-Newton step is the right first step.
  double stage_damping = 1e-3;

  /// The fast setting: the smallest discretisation measured within 1% of the converged
  /// least-squares solution (oversampled, 24 terms in s) in a(0), l, d, chi and b(0) (the last
  /// relative to a(0)) at 100 speeds V tau/a0 = 1e-3 ... 1e3 of the paper's scene
  /// (docs/performance.md, "The fast setting"): 5 terms, integrals to 1e-4, intermediate stages
  /// to 1e-2 and started at the damping 1e-9. Its quadrature rule is the solver's template
  /// argument: 6-point panels (FastLineSolverD) serve this tolerance with half the nodes of the
  /// default 12-point ones, at the same errors.
  static LineOptions fast() {
    LineOptions options;
    options.terms = 5;
    options.quadrature_tolerance = 1e-4;
    options.stage_tolerance = 1e-2;
    options.stage_damping = 1e-9;
    return options;
  }

  /// Throws std::invalid_argument naming the first setting out of its range.
  void validate() const {
    detail::require(terms >= 1 && terms <= 64, "terms", terms, "1 <= terms <= 64");
    detail::require(oversampling >= 1 && oversampling <= 8, "oversampling", oversampling,
                    "1 <= oversampling <= 8");
    detail::require(max_iterations >= 1 && max_iterations <= 100000, "max_iterations",
                    max_iterations, "1 <= max_iterations <= 100000");
    detail::require(quadrature_tolerance >= 0 && quadrature_tolerance <= 1e-4,
                    "quadrature_tolerance", quadrature_tolerance,
                    "0 <= quadrature_tolerance <= 1e-4 (0: the scalar's epsilon)");
    detail::require(stage_tolerance >= 0 && stage_tolerance <= 0.1, "stage_tolerance",
                    stage_tolerance, "0 <= stage_tolerance <= 0.1 (0: a root of every stage)");
    detail::require(stage_damping >= 1e-12 && stage_damping <= 1, "stage_damping", stage_damping,
                    "1e-12 <= stage_damping <= 1");
  }
};

}  // namespace viscoroll
