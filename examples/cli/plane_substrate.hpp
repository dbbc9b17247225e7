// viscoroll-solve and the Python module: the plane method on a scene's layer or spring bed (the
// scene file's "substrate"), PlaneSubstrateSolver (docs/plane-substrate.md, (Q1)-(Q14)); the half
// space stays Hunter's closed form, PlaneSolver.
#pragma once

#include <stdexcept>
#include <utility>
#include <viscoroll/plane/plane_substrate_solver.hpp>
#include <viscoroll/substrate/substrate.hpp>

#include "scene_file.hpp"

namespace viscoroll::cli {

/// PlaneSubstrateOptions asking `tolerance` (relative, in a, d and chi; (Q13)), the other
/// settings the library's defaults.
inline PlaneSubstrateOptions plane_substrate_options(double tolerance) {
  PlaneSubstrateOptions options;
  options.tolerance = tolerance;
  return options;
}

/// f(body) with the body of the substrate `s`: a Layer (bonded or frictionless) or a SpringBed
/// of its thickness. The half space is PlaneSolver's (std::logic_error here).
template <class F>
decltype(auto) visit_plane_body(const SubstrateSpec& s, F&& f) {
  if (s.model == "layer")
    return std::forward<F>(f)(Layer<double>(
        s.thickness, s.base == "frictionless" ? LayerBase::frictionless : LayerBase::bonded));
  if (s.model == "spring_bed") return std::forward<F>(f)(SpringBed<double>(s.thickness));
  throw std::logic_error("viscoroll: the plane method on the half space is PlaneSolver's, not " +
                         s.describe());
}

}  // namespace viscoroll::cli
