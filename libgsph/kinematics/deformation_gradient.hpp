// SPDX-License-Identifier: MIT
// Deformation gradient and its rate at a particle (DESIGN §3):
//   F(a) = Σ_b ω_b (x_b − x_a) ⊗ g_ab = [Σ_b ω_b (x_b − x_a) ⊗ ∇W_ab] G(a)^T (+ e_z⊗e_z in 2-D)
//   Ḟ(a) = [Σ_b ω_b (v_b − v_a) ⊗ ∇W_ab] G(a)^T
// Since M = ∂X/∂θ is taken by the same sum (spaces/metric.hpp), F = (∂x/∂θ)(∂X/∂θ)^{-1} and
// F = I holds to round-off at rest; an affine motion x = A X + c gives F = A to round-off.
// Broken bonds leave the pair list (and G is recomputed), so both properties survive fracture.
#pragma once

#include <vector>

#include "particles/reference.hpp"

namespace gsph {

/// Accumulates the θ-gradients of x and v at particle a (the inner pair loop of the step).
inline void thetaGradients(const Reference& ref, Index a, const Vec3* x, const Vec3* v, Mat3& gradX,
                           Mat3& gradV) {
    const PairList& P = ref.pairs;
    const auto ia = static_cast<std::size_t>(a);
    gradX.setZero();
    gradV.setZero();
    const Vec3 xa = x[ia];
    const Vec3 va = v[ia];
    for (Index k = P.begin(a); k < P.end(a); ++k) {
        const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
        const Vec3 w =
            ref.omega[b] *
            P.table[static_cast<std::size_t>(P.kernelId[static_cast<std::size_t>(k)])].gradW;
        gradX.noalias() += (x[b] - xa) * w.transpose();
        gradV.noalias() += (v[b] - va) * w.transpose();
    }
}

/// F for every particle from positions x (used by tests and diagnostics; the integrator fuses
/// this loop with the stress update).
void deformationGradient(const Reference& ref, const std::vector<Vec3>& x, std::vector<Mat3>& F);

}  // namespace gsph
