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

// The general path: particle c over its CSR list, the same pair formulas one pair at a time.
// Pair weights carry the interface corrections (overset/interface_weights.hpp) of particles
// that keep all their bonds: c's own on its pairs, b's on the transposed terms (the mirror's
// for a same-space pair, b's own list entry for a pair across spaces).
template <bool Viscous, int Hourglass>
void csrParticleForce(const ForceView& in, const Reference& ref, const ParticleFields& pf,
                      const StressFactors& sf, const BondView& bonds, Index c,
                      std::vector<Vec3>& force, ForceParts& parts) {
    const PairList& P = ref.pairs;
    const auto ic = static_cast<std::size_t>(c);
    Vec3 sumW = Vec3::Zero(), fK = Vec3::Zero(), sumQW = Vec3::Zero(), fN = Vec3::Zero();
    Vec3 fh = Vec3::Zero();
    const Vec3 xc = pf.x[ic], vc = pf.v[ic], Xc = pf.X[ic];
    const Mat3 Fc = pf.F[ic];
    const Vec3* own = bonds.keepsAll(c) ? ref.pairCorrections(c) : nullptr;
    const Vec3* mirror = ref.mirrorCorrections(c);
    for (Index k = P.begin(c); k < P.end(c); ++k) {
        if (!bonds.holds(k)) continue;
        const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
        const KernelEntry& e = in.table[P.kernelId[static_cast<std::size_t>(k)]];
        // A pair across spaces has no mirror: its transposed term comes from b's list below.
        const bool across = ref.space[b] != ref.space[ic];
        const std::size_t slot = static_cast<std::size_t>(k - P.begin(c));
        sumW += own != nullptr ? Vec3(e.gradW + own[slot]) : e.gradW;
        if (!across) {
            // −K_b w_bc with w_bc = −w_cb + (the mirror's correction)
            if (mirror != nullptr && bonds.keepsAll(static_cast<Index>(b)))
                fK.noalias() += sf.K[b] * (e.gradW - mirror[slot]);
            else
                fK.noalias() += sf.K[b] * e.gradW;
        }
        const Vec3 xcb = xc - pf.x[b];
        if constexpr (Viscous) {
            const double q = viscousPairPressure(
                in.viscosity, (vc - pf.v[b]).dot(xcb), xcb.squaredNorm(),
                0.5 * (in.h[ic] + in.h[b]), 0.5 * (in.c[ic] + in.c[b]),
                0.5 * (in.rho[ic] + in.rho[b]), 0.5 * (in.alpha[ic] + in.alpha[b]));
            sumQW += q * e.gradW;
            if (!across) fN.noalias() += q * (sf.N[b] * e.gradW);
        }
        if constexpr (Hourglass) {
            double weight = 0.5 * (in.V[ic] + in.V[b]) * e.W;
            if constexpr (Hourglass == kSecantHourglass)
                weight *= 0.5 * (in.hourglassScale[ic] + in.hourglassScale[b]);
            const Vec3 pair =
                hourglassPairForce(in.alphaE, Fc, pf.F[b], pf.X[b] - Xc, -xcb, weight);
            fh += across ? Vec3(0.5 * pair) : pair;  // across: half here, half on b (below)
        }
    }
    // Transposed terms of the pairs (b, c) across spaces that b's list holds (DESIGN §4, §6).
    for (Index slot = ref.crossOffset.empty() ? 0 : ref.crossOffset[ic];
         !ref.crossOffset.empty() && slot < ref.crossOffset[ic + 1]; ++slot) {
        const Index k = ref.crossPair[static_cast<std::size_t>(slot)];
        if (!bonds.holds(k)) continue;
        const Index owner = ref.crossOwner[static_cast<std::size_t>(slot)];
        const auto b = static_cast<std::size_t>(owner);
        const KernelEntry& e = in.table[P.kernelId[static_cast<std::size_t>(k)]];  // w_bc
        const Vec3* ownerCorrection = bonds.keepsAll(owner) ? ref.pairCorrections(owner) : nullptr;
        if (ownerCorrection != nullptr)
            fK.noalias() -= sf.K[b] * (e.gradW + ownerCorrection[k - P.begin(owner)]);
        else
            fK.noalias() -= sf.K[b] * e.gradW;
        const Vec3 xbc = pf.x[b] - xc;
        if constexpr (Viscous) {
            const double q = viscousPairPressure(
                in.viscosity, (pf.v[b] - vc).dot(xbc), xbc.squaredNorm(),
                0.5 * (in.h[ic] + in.h[b]), 0.5 * (in.c[ic] + in.c[b]),
                0.5 * (in.rho[ic] + in.rho[b]), 0.5 * (in.alpha[ic] + in.alpha[b]));
            fN.noalias() -= q * (sf.N[b] * e.gradW);
        }
        if constexpr (Hourglass) {
            double weight = 0.5 * (in.V[ic] + in.V[b]) * e.W;
            if constexpr (Hourglass == kSecantHourglass)
                weight *= 0.5 * (in.hourglassScale[ic] + in.hourglassScale[b]);
            fh -= 0.5 * hourglassPairForce(in.alphaE, pf.F[b], Fc, Xc - pf.X[b], -xbc, weight);
        }
    }
    const Vec3 fStress = sf.K[ic] * sumW + fK;
    finishParticle<Viscous, Hourglass>(sf, c, fStress, sumQW, fN, fh, force, parts);
}

template <bool Viscous, int Hourglass>
void forceLoop(const ForceView& in, const Reference& ref, const ParticleFields& pf,
               const StressFactors& sf, const StencilBlocks& blocks, const BondView& bonds,
               std::vector<Vec3>& force, ForceParts& parts) {
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
        for (Index i = 0; i < block.size(); ++i)
            csrParticleForce<Viscous, Hourglass>(in, ref, pf, sf, bonds, block.particle(i), force,
                                                 parts);
    });
}

}  // namespace

void internalForce(const Reference& ref, const ParticleFields& fields, const StressFactors& factors,
                   const StencilBlocks& blocks, const ForceOptions& options,
                   std::vector<Vec3>& force, ForceParts& parts, const BondView& bonds,
                   const Mat3* G) {
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
                       options.viscosity,
                       options.hourglass * options.youngsModulus};
    const bool viscous = options.viscosity.enabled();
    const bool hourglass = options.hourglass != 0.0;
    const bool secant = hourglass && options.hourglassModulus == HourglassModulus::Secant;
    const auto loop = [&]<bool Viscous>() {
        if (secant)
            forceLoop<Viscous, kSecantHourglass>(in, ref, fields, factors, blocks, bonds, force,
                                                 parts);
        else if (hourglass)
            forceLoop<Viscous, kElasticHourglass>(in, ref, fields, factors, blocks, bonds, force,
                                                  parts);
        else
            forceLoop<Viscous, kNoHourglass>(in, ref, fields, factors, blocks, bonds, force, parts);
    };
    if (viscous)
        loop.template operator()<true>();
    else
        loop.template operator()<false>();
}

}  // namespace gsph
