// SPDX-License-Identifier: MIT
#include "forces/internal_force.hpp"

#include <algorithm>
#include <array>

#include "core/lanes.hpp"
#include "core/parallel.hpp"
#include "forces/hourglass.hpp"

namespace gsph {
namespace {

static_assert(kMinStencilRun >= kLanesOf<Lanes4>, "a stencil block holds a 4-lane strip");

// What the hourglass penalty of a pair is (forces/hourglass.hpp): off, α E, or α E ½(s_a + s_b)
// (the secant modulus in plastic flow). A template value, so that a run without the secant
// modulus does not load s.
constexpr int kNoHourglass = 0, kElasticHourglass = 1, kSecantHourglass = 2;

// Raw component pointers of every field the pair terms read: the stencil loops index them
// directly so that the compiler sees plain contiguous streams.
struct ForceView {
    std::array<const double*, 9> K, N, F;
    const Mat3* G;  // per particle (bonds may have changed it)
    std::array<const double*, 3> x, v, X;
    const double *h, *c, *rho, *alpha, *hourglassScale, *V;
    const KernelEntry* table;
    const CsrPairWeights* staged;  // null: stage every CSR particle's pairs each time
    ViscosityCoefficients viscosity;
    double alphaE;  // α E of the hourglass penalty [Pa]
};

template <int R, int C>
std::array<const double*, R * C> components(const SoaField<R, C>& f) {
    std::array<const double*, R * C> p;
    for (int i = 0; i < R * C; ++i) p[static_cast<std::size_t>(i)] = f.component(i);
    return p;
}

// Per-particle sums of one block (component-major, filled strip by strip).
// The pair sums are split so that per pair only the neighbour's factor is applied:
//   Σ_b (K_c + K_b) w_cb = K_c Σ_b w_cb + Σ_b K_b w_cb,   w_cb = ω ∇W_cb (table),
// and the same for the viscous N terms weighted by q_cb (DESIGN §4).
struct BlockSums {
    double fK[3][kMaxBlock];     // Σ K_b w_cb
    double sumQW[3][kMaxBlock];  // Σ q_cb w_cb
    double fN[3][kMaxBlock];     // Σ q_cb N_b w_cb
    double fh[3][kMaxBlock];     // Σ hourglass pair forces
};

// Σ_b K_b w_cb for the strip of particles from a (block offset i; strip type L, read through
// `load`: consecutive or strided, core/lanes.hpp). On a symmetric stencil the mirrored entries pair
// up: Σ_{k ≥ m/2} (K_{c+δk} − K_{c−δk}) w_k.
template <class L, class Load>
[[gnu::always_inline]] inline void stressStrip(const ForceView& in, const Stencil& st,
                                               const Load& load, Index a, Index i, BlockSums& s) {
    std::array<const double*, 9> K;
    for (std::size_t j = 0; j < 9; ++j) K[j] = in.K[j] + a;
    L acc[3] = {};
    const Index m = st.size();
    for (Index k = st.symmetric ? m / 2 : 0; k < m; ++k) {
        const Index d = st.delta[static_cast<std::size_t>(k)];
        const Vec3& w = st.gradW[static_cast<std::size_t>(k)];
        const auto Kb = [&](std::size_t j) __attribute__((always_inline)) {
            return st.symmetric ? L(load(K[j] + d) - load(K[j] - d)) : load(K[j] + d);
        };
        for (std::size_t r = 0; r < 3; ++r)
            acc[r] += Kb(3 * r) * w[0] + Kb(3 * r + 1) * w[1] + Kb(3 * r + 2) * w[2];
    }
    for (int r = 0; r < 3; ++r) storeLanes(s.fK[r] + i, acc[r]);
}

// The viscous and hourglass pair terms in one sweep over the stencil, so that x_b (which both
// read) is loaded once per pair: Σ q_cb w_cb and Σ q_cb N_b w_cb (forces/artificial_viscosity.hpp,
// pair means of h, c, ρ), and the hourglass pair forces (forces/hourglass.hpp) with
// X_cb = X_c − X_b and x_cb = x_c − x_b: both signs flip against X_bc, x_bc, so ē·x keeps its
// value and the force is +κ x_cb.
template <bool Viscous, int Hourglass, class L, class Load>
[[gnu::always_inline]] inline void pairStrip(const ForceView& in, const Stencil& st,
                                             const Load& load, Index a, Index i, BlockSums& s) {
    L sumQW[3] = {}, fN[3] = {}, fh[3] = {};
    for (Index k = 0; k < st.size(); ++k) {
        const Index b = a + st.delta[static_cast<std::size_t>(k)];
        L y[3];
        for (std::size_t r = 0; r < 3; ++r) y[r] = load(in.x[r] + a) - load(in.x[r] + b);
        const L x2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
        if constexpr (Viscous) {
            L vx{};
            for (std::size_t r = 0; r < 3; ++r)
                vx += (load(in.v[r] + a) - load(in.v[r] + b)) * y[r];
            const L q = viscousPairPressure<L>(in.viscosity, vx, x2,
                                               0.5 * (load(in.h + a) + load(in.h + b)),
                                               0.5 * (load(in.c + a) + load(in.c + b)),
                                               0.5 * (load(in.rho + a) + load(in.rho + b)),
                                               0.5 * (load(in.alpha + a) + load(in.alpha + b)));
            const Vec3& w = st.gradW[static_cast<std::size_t>(k)];
            for (std::size_t r = 0; r < 3; ++r) {
                sumQW[r] += q * w[static_cast<Eigen::Index>(r)];
                fN[r] += q * (load(in.N[3 * r] + b) * w[0] + load(in.N[3 * r + 1] + b) * w[1] +
                              load(in.N[3 * r + 2] + b) * w[2]);
            }
        }
        if constexpr (Hourglass) {
            L Y[3];
            for (std::size_t r = 0; r < 3; ++r) Y[r] = load(in.X[r] + a) - load(in.X[r] + b);
            L predicted{};
            for (std::size_t r = 0; r < 3; ++r)
                for (std::size_t c = 0; c < 3; ++c)
                    predicted +=
                        y[r] * (load(in.F[3 * r + c] + a) + load(in.F[3 * r + c] + b)) * Y[c];
            L pairWeight =
                0.5 * (load(in.V + a) + load(in.V + b)) * st.W[static_cast<std::size_t>(k)];
            if constexpr (Hourglass == kSecantHourglass)
                pairWeight *= 0.5 * (load(in.hourglassScale + a) + load(in.hourglassScale + b));
            const L kappa =
                hourglassPairCoefficient<L>(in.alphaE, 0.5 * predicted, x2,
                                            Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2], pairWeight);
            for (int r = 0; r < 3; ++r) fh[r] += kappa * y[r];
        }
    }
    for (int r = 0; r < 3; ++r) {
        if constexpr (Viscous) storeLanes(s.sumQW[r] + i, sumQW[r]), storeLanes(s.fN[r] + i, fN[r]);
        if constexpr (Hourglass) storeLanes(s.fh[r] + i, fh[r]);
    }
}

// The force of particle c from its pair sums: f_c = fStress − (N_c Σqw + Σ q N_b w)
// + f_hourglass, fStress = K_c Σw + Σ K_b w (DESIGN §4).
template <bool Viscous, int Hourglass>
void finishParticle(const StressFactors& sf, Index c, const Vec3& fStress, const Vec3& sumQW,
                    const Vec3& fN, const Vec3& fh, std::vector<Vec3>& force, ForceParts& parts) {
    const auto ic = static_cast<std::size_t>(c);
    Vec3 f = fStress;
    if constexpr (Viscous) {
        const Vec3 fv = -(sf.N[ic] * sumQW + fN);
        parts.viscous[ic] = fv;
        f += fv;
    }
    if constexpr (Hourglass) {
        parts.hourglass[ic] = fh;
        f += fh;
    }
    force[ic] = f;
}

// The strips of a block (functions, not lambdas: a lambda is not always inlined into the wide
// target).
template <bool Viscous, int Hourglass, class L, class Load>
[[gnu::always_inline]] inline void blockStrips(const ForceView& in, const Stencil& st,
                                               const Load& load, const ParticleBlock& block,
                                               BlockSums& s) {
    constexpr Index width = kLanesOf<L>;
    const Index len = block.size();
    for (Index i0 = 0; i0 < len; i0 += width) {
        const Index i = std::min(i0, len - width);
        stressStrip<L>(in, st, load, block.particle(i), i, s);
        if constexpr (Viscous || Hourglass)
            pairStrip<Viscous, Hourglass, L>(in, st, load, block.particle(i), i, s);
    }
}

// A stencil block strip by strip (strip type L; a block with stride > 1 gathers); the last strip of
// a block whose length is not a multiple of the width overlaps the one before and recomputes
// (identically) a few particles.
template <bool Viscous, int Hourglass, class L>
[[gnu::always_inline]] inline void stencilBlockForce(const ForceView& in, const StressFactors& sf,
                                                     const Stencil& st, const ParticleBlock& block,
                                                     std::vector<Vec3>& force, ForceParts& parts) {
    BlockSums s{};  // terms that are off stay zero
    const Index len = block.size();
    if (block.stride == 1)
        blockStrips<Viscous, Hourglass, L>(in, st, StripLoad<L, false>{}, block, s);
    else
        blockStrips<Viscous, Hourglass, L>(in, st, StripLoad<L, true>{block.stride}, block, s);
    leaveLanes<L>();
    for (Index i = 0; i < len; ++i) {
        const auto col = [&](const double(&a)[3][kMaxBlock]) {
            return Vec3(a[0][i], a[1][i], a[2][i]);
        };
        const Index c = block.particle(i);
        finishParticle<Viscous, Hourglass>(
            sf, c, sf.K[static_cast<std::size_t>(c)] * st.sumGradW + col(s.fK), col(s.sumQW),
            col(s.fN), col(s.fh), force, parts);
    }
}

template <bool Viscous, int Hourglass>
void portableBlockForce(const ForceView& in, const StressFactors& sf, const Stencil& st,
                        const ParticleBlock& block, std::vector<Vec3>& force, ForceParts& parts) {
    stencilBlockForce<Viscous, Hourglass, Lanes2>(in, sf, st, block, force, parts);
}

template <bool Viscous, int Hourglass>
GSPH_AVX2_TARGET void avx2BlockForce(const ForceView& in, const StressFactors& sf,
                                     const Stencil& st, const ParticleBlock& block,
                                     std::vector<Vec3>& force, ForceParts& parts) {
    stencilBlockForce<Viscous, Hourglass, Lanes4>(in, sf, st, block, force, parts);
}

template <bool Viscous, int Hourglass>
GSPH_AVX512_TARGET void avx512BlockForce(const ForceView& in, const StressFactors& sf,
                                         const Stencil& st, const ParticleBlock& block,
                                         std::vector<Vec3>& force, ForceParts& parts) {
    stencilBlockForce<Viscous, Hourglass, Lanes8>(in, sf, st, block, force, parts);
}

// The general path: particle c over its CSR list, vectorised across its pairs. A scalar pass
// stages the pairs that hold (own list, then the pairs across spaces whose transposed term
// comes from the other side's list) as SoA weights, each term's weight signed and zero where
// the term is absent; a vector pass then runs the pair formulas across the staged pairs,
// gathering the neighbours' fields. The sums run in eight fixed lanes (pair j of the staged
// list adds into lane j mod 8) reduced in a fixed order at the end, whatever the strip width,
// so the result is the same for every width. A sum starts at +0 and so never becomes −0: adding
// a zero term (absent, or a lane past the list's end) leaves it unchanged bit for bit.
//
// Weights (DESIGN §4, §6): sumW takes w_cb (with c's interface corrections when c keeps all
// its bonds); fK takes K_b wT, wT = w_cb − (the mirror's correction) for a same-space pair
// (0 across spaces), −(w_bc + b's correction) for a pair of b's list across spaces; fN takes
// q N_b gN (gN = ∇W_cb same-space, 0 across, −w_bc from b's list); sumQW takes q gQ (own list
// only); the hourglass force −κ y (y = x_b − x_c) counts in full within a space and half
// across (the other half on b's side).
// Mask type of strip type L (what a comparison of two L yields).
template <class L>
using MaskOf = decltype(L{} < L{});

// A 3×3 factor (row-major components) of the neighbours times w, row r:
// (M_r0 w0 + M_r1 w1) + M_r2 w2.
template <class L>
[[gnu::always_inline]] inline void gatherTimes(const std::array<const double*, 9>& M,
                                               const Index* b, const L (&w)[3], L (&out)[3]) {
    for (std::size_t r = 0; r < 3; ++r)
        out[r] = gatherLanesAt<L>(M[3 * r], b) * w[0] + gatherLanesAt<L>(M[3 * r + 1], b) * w[1] +
                 gatherLanesAt<L>(M[3 * r + 2], b) * w[2];
}

// Per-particle sums of the CSR path, in kPairLanes lanes held as kPairLanes / width strips
// (core/lanes.hpp).
template <class L>
struct PairLaneSums {
    static constexpr int kStrips = kPairLanes / kLanesOf<L>;
    L sumW[3][kStrips] = {}, fK[3][kStrips] = {}, sumQW[3][kStrips] = {}, fN[3][kStrips] = {},
      fh[3][kStrips] = {};
    static Vec3 reduce(const L (&acc)[3][kStrips]) {
        return Vec3(sumPairLanes<L>(acc[0]), sumPairLanes<L>(acc[1]), sumPairLanes<L>(acc[2]));
    }
};

template <bool Viscous, int Hourglass, class L>
[[gnu::always_inline]] inline void csrParticleForce(const ForceView& in, const StressFactors& sf,
                                                    const StagedPairs& st, std::size_t begin,
                                                    Index size, Index c, std::vector<Vec3>& force,
                                                    ForceParts& parts) {
    constexpr int width = kLanesOf<L>;
    using Sums = PairLaneSums<L>;
    const std::size_t m = st.stride;
    const auto ic = static_cast<std::size_t>(c);
    const auto at = [ic](const double* p) { return L{} + p[ic]; };
    L xc[3], vc[3], Fc[9];
    for (std::size_t r = 0; r < 3; ++r) xc[r] = at(in.x[r]), vc[r] = at(in.v[r]);
    for (std::size_t rc = 0; rc < 9; ++rc) Fc[rc] = at(in.F[rc]);
    const L cc = at(in.c), rhoc = at(in.rho), alphac = at(in.alpha);
    L sc{};
    if constexpr (Hourglass == kSecantHourglass) sc = at(in.hourglassScale);
    Sums s;
    for (Index j0 = 0; j0 < size; j0 += kPairLanes)
        for (int u = 0; u < Sums::kStrips; ++u) {
            const std::size_t j = begin + static_cast<std::size_t>(j0 + u * width);
            const Index* b = st.b.data() + j;
            const auto load3 = [&](const std::vector<double>& v, L(&out)[3])
                __attribute__((always_inline)) {
                for (std::size_t r = 0; r < 3; ++r) out[r] = loadLanes<L>(v.data() + r * m + j);
            };
            L w[3];
            load3(st.wOwn, w);
            for (std::size_t r = 0; r < 3; ++r) s.sumW[r][u] += w[r];
            load3(st.wT, w);
            L Kw[3];
            gatherTimes<L>(in.K, b, w, Kw);
            for (std::size_t r = 0; r < 3; ++r) s.fK[r][u] += Kw[r];
            L y[3];
            for (std::size_t r = 0; r < 3; ++r) y[r] = gatherLanesAt<L>(in.x[r], b) - xc[r];
            const L y2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
            if constexpr (Viscous) {
                L vx{};
                for (std::size_t r = 0; r < 3; ++r)
                    vx += (vc[r] - gatherLanesAt<L>(in.v[r], b)) * -y[r];
                const L q =
                    viscousPairPressure<L>(in.viscosity, vx, y2, loadLanes<L>(st.hBar.data() + j),
                                           0.5 * (cc + gatherLanesAt<L>(in.c, b)),
                                           0.5 * (rhoc + gatherLanesAt<L>(in.rho, b)),
                                           0.5 * (alphac + gatherLanesAt<L>(in.alpha, b)));
                load3(st.gQ, w);
                for (std::size_t r = 0; r < 3; ++r) s.sumQW[r][u] += q * w[r];
                load3(st.gN, w);
                L Nw[3];
                gatherTimes<L>(in.N, b, w, Nw);
                for (std::size_t r = 0; r < 3; ++r) s.fN[r][u] += q * Nw[r];
            }
            if constexpr (Hourglass) {
                L Y[3];
                load3(st.Y, Y);
                L weight = loadLanes<L>(st.hgWeight.data() + j);
                if constexpr (Hourglass == kSecantHourglass)
                    weight *= 0.5 * (sc + gatherLanesAt<L>(in.hourglassScale, b));
                L predicted{};
                for (std::size_t r = 0; r < 3; ++r) {
                    L row{};
                    for (std::size_t k = 0; k < 3; ++k)
                        row += (Fc[3 * r + k] + gatherLanesAt<L>(in.F[3 * r + k], b)) * Y[k];
                    predicted += row * y[r];
                }
                const L kappa = hourglassPairCoefficient<L>(in.alphaE, 0.5 * predicted, y2,
                                                            loadLanes<L>(st.Y2.data() + j), weight);
                // Padding lanes (b = c) give 0/0: selected away.
                const MaskOf<L> valid = loadLanes<L>(st.valid.data() + j) != 0.0;
                const L share = loadLanes<L>(st.share.data() + j);
                for (std::size_t r = 0; r < 3; ++r)
                    s.fh[r][u] = valid ? s.fh[r][u] + share * (-kappa * y[r]) : s.fh[r][u];
            }
        }
    leaveLanes<L>();
    const Vec3 fStress = sf.K[ic] * Sums::reduce(s.sumW) + Sums::reduce(s.fK);
    finishParticle<Viscous, Hourglass>(sf, c, fStress, Sums::reduce(s.sumQW), Sums::reduce(s.fN),
                                       Sums::reduce(s.fh), force, parts);
}

template <bool Viscous, int Hourglass, class L>
[[gnu::always_inline]] inline void csrBlockForce(const ForceView& in, const Reference& ref,
                                                 const StressFactors& sf, const BondView& bonds,
                                                 const ParticleBlock& block,
                                                 std::vector<Vec3>& force, ForceParts& parts) {
    // Staged once when nothing is damaged (CsrPairWeights), else here, per particle.
    thread_local StagedPairs scratch;
    for (Index i = 0; i < block.size(); ++i) {
        const Index c = block.particle(i);
        if (in.staged != nullptr && !bonds.anyDamaged) {
            const auto ic = static_cast<std::size_t>(c);
            const std::size_t begin = in.staged->begin[ic];
            csrParticleForce<Viscous, Hourglass, L>(
                in, sf, in.staged->pairs, begin,
                static_cast<Index>(in.staged->begin[ic + 1] - begin), c, force, parts);
            continue;
        }
        const auto need = static_cast<std::size_t>(stagedCapacity(ref, c));
        if (scratch.stride < need) scratch.resize(std::max(need, 2 * scratch.stride));
        const Index size = stagePairs(ref, bonds, c, scratch, 0);
        csrParticleForce<Viscous, Hourglass, L>(in, sf, scratch, 0, size, c, force, parts);
    }
}

template <bool Viscous, int Hourglass>
void portableCsrForce(const ForceView& in, const Reference& ref, const StressFactors& sf,
                      const BondView& bonds, const ParticleBlock& block, std::vector<Vec3>& force,
                      ForceParts& parts) {
    csrBlockForce<Viscous, Hourglass, Lanes2>(in, ref, sf, bonds, block, force, parts);
}

template <bool Viscous, int Hourglass>
GSPH_AVX2_TARGET void avx2CsrForce(const ForceView& in, const Reference& ref,
                                   const StressFactors& sf, const BondView& bonds,
                                   const ParticleBlock& block, std::vector<Vec3>& force,
                                   ForceParts& parts) {
    csrBlockForce<Viscous, Hourglass, Lanes4>(in, ref, sf, bonds, block, force, parts);
}

template <bool Viscous, int Hourglass>
GSPH_AVX512_TARGET void avx512CsrForce(const ForceView& in, const Reference& ref,
                                       const StressFactors& sf, const BondView& bonds,
                                       const ParticleBlock& block, std::vector<Vec3>& force,
                                       ForceParts& parts) {
    csrBlockForce<Viscous, Hourglass, Lanes8>(in, ref, sf, bonds, block, force, parts);
}

template <bool Viscous, int Hourglass>
void forceLoop(const ForceView& in, const Reference& ref, const StressFactors& sf,
               const StencilBlocks& blocks, const BondView& bonds, std::vector<Vec3>& force,
               ForceParts& parts) {
    const int width = laneWidth();
    parallelForBlocks(blocks.cost, [&](std::ptrdiff_t k) {
        const ParticleBlock& block = blocks.blocks[static_cast<std::size_t>(k)];
        if (block.stencil != kNoStencil && bonds.allIntact(block.begin, block.end)) {
            const Stencil& st = blocks.stencils[static_cast<std::size_t>(block.stencil)];
            if (width >= 8 && block.size() >= 8)
                avx512BlockForce<Viscous, Hourglass>(in, sf, st, block, force, parts);
            else if (width >= 4)
                avx2BlockForce<Viscous, Hourglass>(in, sf, st, block, force, parts);
            else
                portableBlockForce<Viscous, Hourglass>(in, sf, st, block, force, parts);
            return;
        }
        // A block of stencil particles with a broken bond takes the CSR path too (stride > 1
        // included); ParticleBlock::particle walks it either way.
        if (width >= 8)
            avx512CsrForce<Viscous, Hourglass>(in, ref, sf, bonds, block, force, parts);
        else if (width >= 4)
            avx2CsrForce<Viscous, Hourglass>(in, ref, sf, bonds, block, force, parts);
        else
            portableCsrForce<Viscous, Hourglass>(in, ref, sf, bonds, block, force, parts);
    });
}

}  // namespace

void internalForce(const Reference& ref, const ParticleFields& fields, const StressFactors& factors,
                   const StencilBlocks& blocks, const ForceOptions& options,
                   std::vector<Vec3>& force, ForceParts& parts, const BondView& bonds,
                   const Mat3* G, const CsrPairWeights* staged) {
    const ForceView in{components(factors.K),
                       components(factors.N),
                       components(fields.F),
                       G != nullptr ? G : ref.G.data(),
                       components(fields.x),
                       components(fields.v),
                       components(fields.X),
                       ref.smoothingLength.data(),
                       factors.soundSpeed.data(),
                       factors.density.data(),
                       factors.viscositySwitch.data(),
                       factors.hourglassScale.data(),
                       ref.quadVolume.data(),
                       ref.pairs.table.data(),
                       staged,
                       options.viscosity,
                       options.hourglass * options.youngsModulus};
    const bool viscous = options.viscosity.enabled();
    const bool hourglass = options.hourglass != 0.0;
    const bool secant = hourglass && options.hourglassModulus == HourglassModulus::Secant;
    const auto loop = [&]<bool Viscous>() {
        if (secant)
            forceLoop<Viscous, kSecantHourglass>(in, ref, factors, blocks, bonds, force, parts);
        else if (hourglass)
            forceLoop<Viscous, kElasticHourglass>(in, ref, factors, blocks, bonds, force, parts);
        else
            forceLoop<Viscous, kNoHourglass>(in, ref, factors, blocks, bonds, force, parts);
    };
    if (viscous)
        loop.template operator()<true>();
    else
        loop.template operator()<false>();
}

}  // namespace gsph
