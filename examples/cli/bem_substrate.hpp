// viscoroll-solve and the Python module: the bem solver of a material on a scene's substrate
// (the scene file's "substrate", docs/bem.md B15-B19).
#pragma once

#include <utility>
#include <viscoroll/bem/bem_solver.hpp>

#include "scene_file.hpp"

namespace viscoroll::cli {

/// The bem solver of `material` with `options` on the substrate `s`: a Layer (bonded or
/// frictionless), a SpringBed, or the half space.
template <class Material>
BemSolver<double, Material> bem_solver(Material material, const BemOptions& options,
                                       const SubstrateSpec& s) {
  if (s.model == "layer")
    return {std::move(material), options,
            Layer<double>(s.thickness,
                          s.base == "frictionless" ? LayerBase::frictionless : LayerBase::bonded)};
  if (s.model == "spring_bed")
    return {std::move(material), options, SpringBed<double>(s.thickness)};
  return BemSolver<double, Material>(std::move(material), options);
}

}  // namespace viscoroll::cli
