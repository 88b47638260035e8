// SPDX-License-Identifier: MIT
// Deformation gradient and its rate at a particle (DESIGN §3):
//   F(a) = Σ_b ω_b (x_b − x_a) ⊗ g_ab = [Σ_b ω_b (x_b − x_a) ⊗ ∇W_ab] G(a)^T (+ e_z⊗e_z in 2-D)
//   Ḟ(a) = [Σ_b ω_b (v_b − v_a) ⊗ ∇W_ab] G(a)^T
// Since M = ∂X/∂θ is taken by the same sum (spaces/metric.hpp), F = (∂x/∂θ)(∂X/∂θ)^{-1} and
// F = I holds to round-off at rest; an affine motion x = A X + c gives F = A to round-off.
// In an axisymmetric run the zz entries are the hoop stretch r/R and its rate v_r/R instead
// (particles/axisymmetry.hpp), set by the callers that build F from these sums.
// Broken bonds leave the pair list (and G is recomputed), so both properties survive fracture.
// Three evaluations of the same sum: thetaGradients (one particle, its CSR list, one pair at a
// time), csrThetaGradients (a CSR block from its staged pairs, vectorised) and
// stencilThetaGradients (a block of particles sharing one stencil, SoA x and v, vectorised
// across the block). Both accumulate Σ_b x_b ⊗ w_ab in list order, then subtract
// x_a ⊗ Σ_b w_ab; on a symmetric stencil the block sums (x_{a+δ} − x_{a−δ}) ⊗ w over mirrored
// pairs instead (neighbors/stencil_blocks.hpp), equal up to round-off.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "core/soa_field.hpp"
#include "core/strip_mat3.hpp"
#include "neighbors/pair_field_rows.hpp"
#include "neighbors/staged_pairs.hpp"
#include "neighbors/stencil_blocks.hpp"
#include "particles/reference.hpp"

namespace gsph {

/// Cofactor matrix cof F = J F^{-T}, columns F₁×F₂, F₂×F₀, F₀×F₁ (F_i: columns of F). The force
/// factors and Nanson's formula need J F^{-T} only, so taking it directly saves the inverse and
/// its division.
inline Mat3 cofactor(const Mat3& F) {
    return eigenOf(cofactor(stripOf(F)));
}

/// Accumulates the θ-gradients Σ_b ω (x_b − x_a) ⊗ ∇W_ab and the same of v at particle a (the
/// inner pair loop of the step), as Σ_b x_b ⊗ w_ab − x_a ⊗ Σ_b w_ab with w_ab = ω ∇W_ab.
/// With `intact` (per CSR pair, failure/brittle_bonds.hpp) only over the bonds that hold; with
/// `correction` (a's interface weight corrections along its list, Reference::pairCorrections)
/// w_ab + δw_ab in place of w_ab.
inline void thetaGradients(const Reference& ref, Index a, const Vec3* x, const Vec3* v, Mat3& gradX,
                           Mat3& gradV, const std::uint8_t* intact = nullptr,
                           const Vec3* correction = nullptr) {
    const PairList& P = ref.pairs;
    const auto ia = static_cast<std::size_t>(a);
    Mat3 sx = Mat3::Zero();
    Mat3 sv = Mat3::Zero();
    Vec3 sw = Vec3::Zero();
    const Index* nb = P.neighbor.data();
    const Index* id = P.kernelId.data();
    const KernelEntry* table = P.table.data();
    for (Index k = P.begin(a); k < P.end(a); ++k) {
        if (intact != nullptr && intact[k] == 0) continue;
        const auto b = static_cast<std::size_t>(nb[k]);
        const Vec3 w = correction != nullptr ? Vec3(table[id[k]].gradW + correction[k - P.begin(a)])
                                             : table[id[k]].gradW;
        sw += w;
        sx.noalias() += x[b] * w.transpose();
        sv.noalias() += v[b] * w.transpose();
    }
    gradX = sx - x[ia] * sw.transpose();
    gradV = sv - v[ia] * sw.transpose();
}

/// θ-gradients of one block, component-major (row r, column c at [3r + c][i]) so that the
/// accumulation loops vectorise across the block's particles i.
struct BlockThetaGradients {
    double x[9][kMaxBlock];
    double v[9][kMaxBlock];
    Mat3 gradX(Index i) const { return at(x, i); }
    Mat3 gradV(Index i) const { return at(v, i); }

  private:
    static Mat3 at(const double (&g)[9][kMaxBlock], Index i) {
        Mat3 m;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) m(r, c) = g[3 * r + c][i];
        return m;
    }
};

/// thetaGradients for the particles of a CSR block (row i of g is block.particle(i)) from their
/// staged pairs (neighbors/staged_pairs.hpp), vectorised across pairs and across the particles
/// of masked strips: `staged` (the body's, all bonds intact) while no particle is damaged, else
/// staged here over the bonds that hold, each particle with its interface corrections while it
/// keeps all its bonds. The same bits at every strip width; equal to thetaGradients to round-off.
/// `rows`: the gathered runs read the neighbours' x and v from them (neighbors/pair_field_rows.hpp,
/// refreshed for staged->gathered; only for a block of CSR particles, with `staged`), else they
/// gather x and v; the same bits.
void csrThetaGradients(const Reference& ref, const CsrPairWeights* staged, const BondView& bonds,
                       const ParticleBlock& block, const Vec3Field& x, const Vec3Field& v,
                       BlockThetaGradients& g, const PairFieldRows* rows = nullptr);

/// thetaGradients for the particles of a stencil block (kMinStencilRun ≤ size ≤ kMaxBlock;
/// row i of g is block.particle(i)): b = a + st.delta[k], w_ab = st.gradW[k].
void stencilThetaGradients(const Stencil& st, const ParticleBlock& block, const Vec3Field& x,
                           const Vec3Field& v, BlockThetaGradients& g);

/// F for every particle from positions x (used by tests and diagnostics; the integrator fuses
/// this loop with the stress update).
void deformationGradient(const Reference& ref, const std::vector<Vec3>& x, std::vector<Mat3>& F);

}  // namespace gsph
