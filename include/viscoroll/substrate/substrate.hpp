// viscoroll: the bodies a roller presses, models of the Substrate concept (core/concepts.hpp):
// the half space, an elastic layer on a rigid base, and the spring bed of the belt-conveyor
// literature (docs/theory.md section 19).
#pragma once

#include <cmath>
#include <limits>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/substrate/layer_factor.hpp>

namespace viscoroll {

/// The homogeneous viscoelastic half space of the paper: T(q) = 1.
template <RealScalar Real>
struct HalfSpace {
  /// The scalar.
  using real_type = Real;
  /// A half space.
  static constexpr SubstrateKind kind = SubstrateKind::half_space;
  /// T(q) = 1 at every wavenumber q and Poisson's ratio nu.
  Real surface_factor(Real /*q*/, Real /*nu*/) const { return Real(1); }
  /// +inf: no base.
  Real thickness() const { return std::numeric_limits<Real>::infinity(); }
};

/// A layer of the material, of thickness h, on a rigid base to which it is bonded or on which it
/// slides without friction: T(q) = T(q h) of (H2) or (H3). The penetration d of a solution on a
/// layer is measured from the base (the layer's surface far from the contact).
template <RealScalar Real>
class Layer {
 public:
  /// The scalar.
  using real_type = Real;
  /// A body: T(q) tends to 1 as q -> inf.
  static constexpr SubstrateKind kind = SubstrateKind::body;

  /// Throws std::invalid_argument naming "thickness" unless 0 < thickness < inf.
  explicit Layer(Real thickness, LayerBase base = LayerBase::bonded) : h_(thickness), base_(base) {
    detail::require(thickness > 0 && thickness < std::numeric_limits<Real>::infinity(), "thickness",
                    thickness, "0 < thickness < inf");
  }

  /// T(q h) of (H2) (bonded) or (H3) (frictionless) at wavenumber q and Poisson's ratio nu.
  Real surface_factor(Real q, Real nu) const { return layer_factor(q * h_, nu, base_); }
  /// h, the layer's thickness.
  Real thickness() const { return h_; }
  /// How the layer rests on its base.
  LayerBase base() const { return base_; }

 private:
  Real h_;
  LayerBase base_;
};

/// The belt-conveyor model of a cover (a Winkler foundation): each point of the surface sinks by
/// u = h p / E(t), E = 2 (1 + nu) mu, independently of its neighbours. In the form (H1),
/// T(q) = q h / (2 (1 - nu^2)) (docs/theory.md (H6)).
template <RealScalar Real>
class SpringBed {
 public:
  /// The scalar.
  using real_type = Real;
  /// Local: each point sinks under its own pressure only.
  static constexpr SubstrateKind kind = SubstrateKind::local;

  /// Throws std::invalid_argument naming "thickness" unless 0 < thickness < inf.
  explicit SpringBed(Real thickness) : h_(thickness) {
    detail::require(thickness > 0 && thickness < std::numeric_limits<Real>::infinity(), "thickness",
                    thickness, "0 < thickness < inf");
  }

  /// T(q) = q h / (2 (1 - nu^2)) (H6); throws unless -1 < nu < 1.
  Real surface_factor(Real q, Real nu) const {
    detail::require(nu > -1 && nu < 1, "nu", nu, "-1 < nu < 1 for a spring bed");
    return q * h_ / (2 * (1 - nu * nu));
  }
  /// h, the cover's thickness.
  Real thickness() const { return h_; }

 private:
  Real h_;
};

static_assert(Substrate<HalfSpace<double>> && Substrate<Layer<double>> &&
              Substrate<SpringBed<double>>);

}  // namespace viscoroll
