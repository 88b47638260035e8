// SPDX-License-Identifier: MIT
// Corrected θ-gradients and the metric of each particle, computed once (DESIGN §3).
//
//   B(a)  = Σ_b ω_b (θ_b − θ_a) ⊗ ∇W_ab                    (first-order correction, CSPM)
//   M(a)  = Σ_b ω_b (X_b − X_a) ⊗ B(a)^{-T} ∇W_ab = ∂X/∂θ  (exact for an affine map)
//   Q(a)  = M(a)^{-1} = ∂θ/∂X,   g_ab = Q(a)^T B(a)^{-T} ∇W_ab = G(a) ∇W_ab
// so that F(a) = Σ_b ω_b (x_b − x_a) ⊗ g_ab equals I to round-off at rest, and exactly the
// applied gradient under any affine motion. In 2-D the zz entries of B and M are set to 1.
//
// Also fills, per particle: ω (= Δθ^d of its space), the quadrature volume V = ω·det M (the
// volume that makes the discrete Piola identity of DESIGN §7 exact), the mass ρ0 V, the smallest
// physical spacing Δθ·σ_min(M) (time step), the physical smoothing length κΔθ (det M)^{1/d} (the
// paper's h_a of the artificial viscosity) and the condition number of M.
#pragma once

#include <cstdint>

#include "overset/interface_weights.hpp"
#include "particles/reference.hpp"

namespace gsph {

/// The first-order corrected metric of one particle (DESIGN §3).
struct ParticleMetric {
    Mat3 B = Mat3::Zero();  ///< Σ ω (θ_b − θ_a) ⊗ ∇W_ab (+ e_z⊗e_z in 2-D)
    Mat3 M = Mat3::Zero();  ///< ∂X/∂θ
    Mat3 G = Mat3::Zero();  ///< Q^T B^{-T}
    enum class Status { Ok, SingularCorrection, InvertedMetric } status = Status::Ok;
};

/// B, M and G of particle a over its pairs; with `intact` (per CSR pair, DESIGN §5) only over
/// the pairs whose bond holds, so that F = I stays exact at rest after bonds break.
/// Requires ref.pairs; G is set only when status is Ok.
ParticleMetric particleMetric(const Reference& ref, Index a, const std::uint8_t* intact = nullptr);

/// Requires ref.pairs (buildPairs). Throws NumericalError naming the particle if B or M is
/// singular or M inverts the orientation (det M ≤ 0). `progress`: the interface weights' solve
/// (overset/interface_weights.hpp).
void computeGeometry(Reference& ref, const InterfaceSolveProgress& progress = {});

}  // namespace gsph
