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

/// Accumulates the θ-gradients Σ_b ω (x_b − x_a) ⊗ ∇W_ab and the same of v at particle a (the
/// inner pair loop of the step), as Σ_b x_b ⊗ w_ab − x_a ⊗ Σ_b w_ab with w_ab = ω ∇W_ab.
inline void thetaGradients(const Reference& ref, Index a, const Vec3* x, const Vec3* v, Mat3& gradX,
                           Mat3& gradV) {
    const PairList& P = ref.pairs;
    const auto ia = static_cast<std::size_t>(a);
    Mat3 sx = Mat3::Zero();
    Mat3 sv = Mat3::Zero();
    Vec3 sw = Vec3::Zero();
    const Index* nb = P.neighbor.data();
    const Index* id = P.kernelId.data();
    const KernelEntry* table = P.table.data();
    for (Index k = P.begin(a); k < P.end(a); ++k) {
        const auto b = static_cast<std::size_t>(nb[k]);
        const Vec3& w = table[id[k]].gradW;
        sw += w;
        sx.noalias() += x[b] * w.transpose();
        sv.noalias() += v[b] * w.transpose();
    }
    gradX = sx - x[ia] * sw.transpose();
    gradV = sv - v[ia] * sw.transpose();
}

/// F for every particle from positions x (used by tests and diagnostics; the integrator fuses
/// this loop with the stress update).
void deformationGradient(const Reference& ref, const std::vector<Vec3>& x, std::vector<Mat3>& F);

}  // namespace gsph
