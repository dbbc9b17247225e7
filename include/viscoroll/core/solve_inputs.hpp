// viscoroll: the prologue every solve shares (the plane, line and boundary-element solvers): the
// scene validated, the material's instantaneous compliance c = (1 - nu)/(2 pi mu_D) (Eq. 3)
// checked representable, and the words that name the solve's inputs in its later errors
// (docs/errors.md, "std::invalid_argument: bad input"), built only when an error needs them.
#pragma once

#include <cstddef>
#include <string>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll::detail {

/// The words naming a material in a solve's errors: its compliance c and its memory, f and tau
/// of Eq. (1) for at most one term, the sum of f and the number of terms for a spectrum.
template <ConstitutiveModel M>
std::string material_inputs(const M& m) {
  std::string out = "compliance = " + format_value(m.instantaneous_compliance());
  if constexpr (SingleTimeModel<M>) {
    const auto term = single_memory_term(m);
    return out + ", f = " + format_value(term.f) + ", tau = " + format_value(term.tau);
  } else {
    return out + ", sum of f = " + format_value(m.creep_ratio()) +
           ", terms = " + std::to_string(m.memory_terms().size());
  }
}

/// A solve's inputs: the compliance c, and (called) the words naming the scene
/// (`scene.describe()`, "c1 = ..., load = ..., speed = ...") and the material, built when an
/// error's message needs them, never on the way.
template <class Scene, ConstitutiveModel M>
struct SolveInputs {
  typename M::real_type c;  ///< the instantaneous compliance (1 - nu)/(2 pi mu_D), Eq. (3)
  const Scene& scene;       ///< the scene solved
  const M& material;        ///< the material solved for
  /// "<the scene's words>, compliance = ..., f = ..., tau = ..." (a spectrum: its sum and count).
  std::string operator()() const { return scene.describe() + ", " + material_inputs(material); }
};

/// The prologue of a solve: `scene.validate()`, then c of `material` checked representable
/// (a modulus near the largest or smallest value of the scalar overflows or underflows
/// (1 - nu)/(2 pi mu_D)): an error naming the inputs, else the inputs for the solve's later
/// errors. Both arguments must outlive the returned object.
template <class Scene, ConstitutiveModel M>
SolveInputs<Scene, M> solve_prologue(const Scene& scene, const M& material) {
  scene.validate();
  const SolveInputs<Scene, M> in{material.instantaneous_compliance(), scene, material};
  representable(in.c, 0, "the instantaneous compliance c", in, false);
  return in;
}

}  // namespace viscoroll::detail
