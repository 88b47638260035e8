// SPDX-License-Identifier: MIT
#include "forces/internal_force.hpp"

#include <algorithm>
#include <array>
#include <type_traits>

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
    // Every field the pair terms read, by slot (neighbors/pair_field_rows.hpp): the SoA column of
    // each component. The stencil kernels and the centres read them at(slot); the CSR pair
    // groups read the far ends from these columns or from the rows.
    std::array<const double*, kPairSlots> slot;
    const double* rows;  // null: the gathered runs gather from the SoA fields
    const Mat3* G;       // per particle (bonds may have changed it)
    const KernelEntry* table;
    const CsrPairWeights* staged;  // null: stage every CSR particle's pairs each time
    ViscosityCoefficients viscosity;
    double alphaE;  // α E of the hourglass penalty [Pa]

    [[gnu::always_inline]] const double* at(std::size_t s) const { return slot[s]; }
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
    for (std::size_t j = 0; j < 9; ++j) K[j] = in.at(kSlotK + j) + a;
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
        // Component `slot` at the centres (a) and at the neighbours (b), and their pair mean.
        const auto atA = [&](std::size_t slot) __attribute__((always_inline))->L {
            return load(in.at(static_cast<std::size_t>(slot)) + a);
        };
        const auto atB = [&](std::size_t slot) __attribute__((always_inline))->L {
            return load(in.at(static_cast<std::size_t>(slot)) + b);
        };
        const auto mean = [&](std::size_t slot) __attribute__((always_inline))->L {
            return 0.5 * (atA(slot) + atB(slot));
        };
        L y[3];
        for (std::size_t r = 0; r < 3; ++r) y[r] = atA(kSlotX + r) - atB(kSlotX + r);
        const L x2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
        if constexpr (Viscous) {
            L vx{};
            for (std::size_t r = 0; r < 3; ++r) vx += (atA(kSlotV + r) - atB(kSlotV + r)) * y[r];
            if (anyNegative(vx)) {  // else q = 0 in every lane: nothing to add (the same bits)
                const L q = viscousPairPressure<L>(in.viscosity, vx, x2, mean(kSlotSmoothingLength),
                                                   mean(kSlotSoundSpeed), mean(kSlotDensity),
                                                   mean(kSlotViscositySwitch));
                const Vec3& w = st.gradW[static_cast<std::size_t>(k)];
                for (std::size_t r = 0; r < 3; ++r) {
                    sumQW[r] += q * w[static_cast<Eigen::Index>(r)];
                    fN[r] += q * (atB(kSlotN + 3 * r) * w[0] + atB(kSlotN + 3 * r + 1) * w[1] +
                                  atB(kSlotN + 3 * r + 2) * w[2]);
                }
            }
        }
        if constexpr (Hourglass) {
            L Y[3];
            for (std::size_t r = 0; r < 3; ++r)
                Y[r] = atA(kSlotReferenceX + r) - atB(kSlotReferenceX + r);
            L predicted{};
            for (std::size_t r = 0; r < 3; ++r)
                for (std::size_t c = 0; c < 3; ++c)
                    predicted += y[r] * (atA(kSlotF + 3 * r + c) + atB(kSlotF + 3 * r + c)) * Y[c];
            L pairWeight = mean(kSlotVolume) * st.W[static_cast<std::size_t>(k)];
            if constexpr (Hourglass == kSecantHourglass) pairWeight *= mean(kSlotHourglassScale);
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

// The general path: the CSR particles, from their staged pairs (neighbors/staged_pairs.hpp
// says what each weight is, DESIGN §4, §6): masked strips (8 particles in the lanes, their
// same-space pairs as a stencil with per-lane weights) and gathered runs (one particle's other
// pairs, 8 at a time in the lanes). A strip lane sums its entries in order; a run's sums go into
// kPairLanes fixed lanes reduced in a fixed order (core/lanes.hpp); so every strip width gives
// the same bits. A sum starts at +0 and so never becomes −0: a zero weight (a term the pair does
// not have) adds nothing, bit for bit, and lanes without a pair are selected away.

// Mask type of strip type L (what a comparison of two L yields).
template <class L>
using MaskOf = decltype(L{} < L{});

// The sums of one lane of the CSR path (one particle's, or one of a particle's kPairLanes).
template <class L>
struct PairSums {
    L sumW[3] = {}, fK[3] = {}, sumQW[3] = {}, fN[3] = {}, fh[3] = {};
};

// The centre's fields, per lane: one particle's in every lane (a run of its pairs), or the
// particles of a masked strip.
template <class L>
struct PairCentre {
    L x[3], v[3], F[9], X[3], c, rho, alpha, h, V, s{};
};

template <int Hourglass, class L, class Load>
[[gnu::always_inline]] inline void loadCentre(const ForceView& in, const Load& load,
                                              PairCentre<L>& o) {
    for (std::size_t r = 0; r < 3; ++r) {
        o.x[r] = load(in.at(kSlotX + r));
        o.v[r] = load(in.at(kSlotV + r));
        o.X[r] = load(in.at(kSlotReferenceX + r));
    }
    for (std::size_t rc = 0; rc < 9; ++rc) o.F[rc] = load(in.at(kSlotF + rc));
    o.c = load(in.at(kSlotSoundSpeed));
    o.rho = load(in.at(kSlotDensity));
    o.alpha = load(in.at(kSlotViscositySwitch));
    o.h = load(in.at(kSlotSmoothingLength));
    o.V = load(in.at(kSlotVolume));
    if constexpr (Hourglass == kSecantHourglass) o.s = load(in.at(kSlotHourglassScale));
}

// Rows j … j + width − 1 of staged weights (component r of a vector weight at r · stride).
template <class L>
struct WeightRows {
    std::size_t stride, j;
    [[gnu::always_inline]] void vec(const std::vector<double>& v, L (&out)[3]) const {
        for (std::size_t r = 0; r < 3; ++r) out[r] = loadLanes<L>(v.data() + r * stride + j);
    }
    [[gnu::always_inline]] L scalar(const std::vector<double>& v) const {
        return loadLanes<L>(v.data() + j);
    }
};

// The weights of staged entries j … j + width − 1 of a run (StagedPairs: all stored).
// SumsOwn: the run sums wOwn itself (a run staged afresh); else the stress term's Σ w comes
// from CsrPairWeights::ownSum.
template <class L, bool SumsOwn>
struct RunWeights {
    static constexpr bool kSumsOwn = SumsOwn;
    const StagedPairs& st;
    WeightRows<L> at;
    [[gnu::always_inline]] void own(L (&w)[3]) const { at.vec(st.wOwn, w); }
    [[gnu::always_inline]] void transposed(L (&w)[3]) const { at.vec(st.wT, w); }
    [[gnu::always_inline]] void viscous(L (&w)[3]) const { at.vec(st.gQ, w); }
    [[gnu::always_inline]] void viscousTransposed(L (&w)[3]) const { at.vec(st.gN, w); }
    [[gnu::always_inline]] L hBar(const PairCentre<L>&, auto&&) const { return at.scalar(st.hBar); }
    [[gnu::always_inline]] L hourglassWeight(const PairCentre<L>&, auto&&) const {
        return at.scalar(st.hgWeight);
    }
    [[gnu::always_inline]] L share() const { return at.scalar(st.share); }
    [[gnu::always_inline]] L valid() const { return share(); }  // 0 only for padding
};

// The weights of a masked strip's entries (StripPairs): the reference offset, h̄ and the
// hourglass weight formed from the neighbours' X, h and V as a run's staging forms them.
template <class L>
struct StripWeights {
    static constexpr bool kSumsOwn = false;  // CsrPairWeights::ownSum has Σ w
    const StripPairs& sp;
    WeightRows<L> at;
    [[gnu::always_inline]] void own(L (&w)[3]) const { at.vec(sp.wOwn, w); }
    [[gnu::always_inline]] void transposed(L (&w)[3]) const { at.vec(sp.wT, w); }
    [[gnu::always_inline]] void viscous(L (&w)[3]) const { at.vec(sp.g, w); }
    [[gnu::always_inline]] void viscousTransposed(L (&w)[3]) const { at.vec(sp.g, w); }
    template <class Fetch>
    [[gnu::always_inline]] L hBar(const PairCentre<L>& o, const Fetch& fetch) const {
        return 0.5 * (o.h + fetch(kSlotSmoothingLength));
    }
    template <class Fetch>
    [[gnu::always_inline]] L hourglassWeight(const PairCentre<L>& o, const Fetch& fetch) const {
        return 0.5 * (o.V + fetch(kSlotVolume)) * at.scalar(sp.W);
    }
    [[gnu::always_inline]] L share() const { return valid(); }
    [[gnu::always_inline]] L valid() const { return at.scalar(sp.valid); }
};

// The pair terms of one group of entries (one per lane) into s, the weights from `wt`
// (RunWeights or StripWeights), the neighbours' fields through fetch(slot) (PairFieldSlot: a
// contiguous load at a + δ, columns of the rows, or a gather). Lanes without a pair (valid 0)
// add nothing.
template <bool Viscous, int Hourglass, class L, class Weights, class Fetch>
[[gnu::always_inline]] inline void pairGroup(const ForceView& in, const Weights& wt,
                                             const PairCentre<L>& o, const Fetch& fetch,
                                             PairSums<L>& s) {
    const auto times = [&](int M, const L(&w)[3], L(&out)[3]) __attribute__((always_inline)) {
        for (int r = 0; r < 3; ++r)
            out[r] =
                fetch(M + 3 * r) * w[0] + fetch(M + 3 * r + 1) * w[1] + fetch(M + 3 * r + 2) * w[2];
    };
    const MaskOf<L> valid = wt.valid() != 0.0;
    L w[3];
    if constexpr (Weights::kSumsOwn) {
        wt.own(w);
        for (std::size_t r = 0; r < 3; ++r) s.sumW[r] += w[r];
    }
    wt.transposed(w);
    L Kw[3];
    times(kSlotK, w, Kw);
    for (std::size_t r = 0; r < 3; ++r) s.fK[r] += Kw[r];
    L y[3];
    for (int r = 0; r < 3; ++r) y[r] = fetch(kSlotX + r) - o.x[r];
    const L y2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
    if constexpr (Viscous) {
        L vx{};
        for (int r = 0; r < 3; ++r) vx += (o.v[r] - fetch(kSlotV + r)) * -y[r];
        if (anyNegative(vx)) {  // else q = 0 in every lane: nothing to add (the same bits)
            const L q = viscousPairPressure<L>(
                in.viscosity, vx, y2, wt.hBar(o, fetch), 0.5 * (o.c + fetch(kSlotSoundSpeed)),
                0.5 * (o.rho + fetch(kSlotDensity)), 0.5 * (o.alpha + fetch(kSlotViscositySwitch)));
            wt.viscous(w);
            for (std::size_t r = 0; r < 3; ++r)
                s.sumQW[r] = valid ? s.sumQW[r] + q * w[r] : s.sumQW[r];
            wt.viscousTransposed(w);
            L Nw[3];
            times(kSlotN, w, Nw);
            for (std::size_t r = 0; r < 3; ++r) s.fN[r] = valid ? s.fN[r] + q * Nw[r] : s.fN[r];
        }
    }
    if constexpr (Hourglass) {
        // The reference offset X_b − X_c, formed as staging formed it (the same bits).
        L Y[3];
        for (int r = 0; r < 3; ++r) Y[r] = fetch(kSlotReferenceX + r) - o.X[r];
        const L Y2 = Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2];
        L weight = wt.hourglassWeight(o, fetch);
        if constexpr (Hourglass == kSecantHourglass)
            weight *= 0.5 * (o.s + fetch(kSlotHourglassScale));
        L predicted{};
        for (int r = 0; r < 3; ++r) {
            L row{};
            for (int k = 0; k < 3; ++k) row += (o.F[3 * r + k] + fetch(kSlotF + 3 * r + k)) * Y[k];
            predicted += row * y[r];
        }
        const L kappa = hourglassPairCoefficient<L>(in.alphaE, 0.5 * predicted, y2, Y2, weight);
        const L share = wt.share();
        for (std::size_t r = 0; r < 3; ++r)
            s.fh[r] = valid ? s.fh[r] + share * (-kappa * y[r]) : s.fh[r];
    }
}

// The sums of the CSR path for one block's particles (component-major, as BlockSums).
struct CsrSums {
    double sumW[3][kMaxBlock], fK[3][kMaxBlock], sumQW[3][kMaxBlock], fN[3][kMaxBlock],
        fh[3][kMaxBlock];
};

// A run of c's staged pairs [begin, begin + size) across kPairLanes lanes (pair j into lane
// j mod kPairLanes), reduced in the fixed order of sumPairLanes, added into column i of out.
// FromRows: the neighbours' fields are read as columns of in.rows (every b is one of
// CsrPairWeights::gathered), else gathered from the SoA fields; the same values either way.
template <bool Viscous, int Hourglass, bool FromRows, bool SumsOwn, class L>
[[gnu::always_inline]] inline void gatheredPairs(const ForceView& in, const StagedPairs& st,
                                                 std::size_t begin, Index size, Index c, Index i,
                                                 CsrSums& out) {
    constexpr int width = kLanesOf<L>, strips = kPairLanes / width;
    const auto ic = static_cast<std::size_t>(c);
    PairCentre<L> o;
    loadCentre<Hourglass, L>(
        in, [ic](const double* p) __attribute__((always_inline)) { return L{} + p[ic]; }, o);
    PairSums<L> s[strips];
    for (Index j0 = 0; j0 < size; j0 += kPairLanes)
        for (int u = 0; u < strips; ++u) {
            const std::size_t j = begin + static_cast<std::size_t>(j0 + u * width);
            const Index* b = st.b.data() + j;
            const RunWeights<L, SumsOwn> weights{st, {st.stride, j}};
            if constexpr (FromRows) {
                L column[kRowLength];
                for (std::size_t first = 0; first < kRowLength; first += width)
                    loadColumns<L>(in.rows, kRowLength, b, first, column + first);
                pairGroup<Viscous, Hourglass, L>(
                    in, weights,
                    o, [&column](int slot) __attribute__((always_inline)) { return column[slot]; },
                    s[u]);
            } else {
                pairGroup<Viscous, Hourglass, L>(
                    in, weights, o, [&in, b ](int slot) __attribute__((always_inline)) {
                        return gatherLanesAt<L>(in.at(static_cast<std::size_t>(slot)), b);
                    },
                    s[u]);
            }
        }
    const auto add = [&](L(PairSums<L>::*sum)[3], double(&column)[3][kMaxBlock])
        __attribute__((always_inline)) {
        for (std::size_t r = 0; r < 3; ++r) {
            L lanes[strips];
            for (int u = 0; u < strips; ++u) lanes[u] = (s[u].*sum)[r];
            column[r][i] += sumPairLanes<L>(lanes);
        }
    };
    if constexpr (SumsOwn) add(&PairSums<L>::sumW, out.sumW);
    add(&PairSums<L>::fK, out.fK);
    add(&PairSums<L>::sumQW, out.sumQW), add(&PairSums<L>::fN, out.fN);
    add(&PairSums<L>::fh, out.fh);
}

// A masked strip (neighbors/staged_pairs.hpp) whose first particle is column i of out: each
// lane one particle, its entries in order; the sums written into the strip's columns.
template <bool Viscous, int Hourglass, class L>
[[gnu::always_inline]] inline void maskedStrip(const ForceView& in, const CsrPairWeights& w,
                                               const MaskedStrip& strip, Index i, CsrSums& out) {
    constexpr int width = kLanesOf<L>;
    const Index* delta = w.delta.data() + strip.deltaBegin;
    const Index entries = strip.deltaEnd - strip.deltaBegin;
    for (int u = 0; u < kPairLanes / width; ++u) {
        const Index a = strip.first + u * width;
        PairCentre<L> o;
        loadCentre<Hourglass, L>(
            in, [a](const double* p) __attribute__((always_inline)) { return loadLanes<L>(p + a); },
            o);
        PairSums<L> s;
        for (Index e = 0; e < entries; ++e) {
            const Index ad = a + delta[e];
            pairGroup<Viscous, Hourglass, L>(
                in,
                StripWeights<L>{
                    w.stripPairs,
                    {w.stripPairs.stride,
                     strip.base + static_cast<std::size_t>(e * kPairLanes + u * width)}},
                o, [&in, ad ](int slot) __attribute__((always_inline)) {
                    return loadLanes<L>(in.at(static_cast<std::size_t>(slot)) + ad);
                },
                s);
        }
        const auto store = [&](const L(&sum)[3], double(&column)[3][kMaxBlock])
            __attribute__((always_inline)) {
            for (std::size_t r = 0; r < 3; ++r) storeLanes(column[r] + i + u * width, sum[r]);
        };
        store(s.sumW, out.sumW), store(s.fK, out.fK), store(s.sumQW, out.sumQW);
        store(s.fN, out.fN), store(s.fh, out.fh);
    }
}

template <bool Viscous, int Hourglass, class L>
[[gnu::always_inline]] inline void csrBlockForce(const ForceView& in, const Reference& ref,
                                                 const StressFactors& sf, const BondView& bonds,
                                                 const ParticleBlock& block,
                                                 std::vector<Vec3>& force, ForceParts& parts) {
    CsrSums s{};
    const Index len = block.size();
    bool afresh[kMaxBlock];
    stagedStrips(in.staged, bonds, block, afresh, [&](Index i, const MaskedStrip& strip) {
        maskedStrip<Viscous, Hourglass, L>(in, *in.staged, strip, i, s);
    });
    // The rows hold the far ends of the CSR blocks' runs (not of a stencil block's here).
    const bool fromRows = in.rows != nullptr && block.stencil == kNoStencil;
    // SumsOwn (a std::bool_constant): the run sums wOwn itself (staged afresh), else
    // CsrPairWeights::ownSum has it.
    const auto run = [&](auto sumsOwn, const StagedPairs& st, std::size_t begin, Index size,
                         Index c, Index i) __attribute__((always_inline)) {
        constexpr bool SumsOwn = decltype(sumsOwn)::value;
        if (fromRows)
            gatheredPairs<Viscous, Hourglass, true, SumsOwn, L>(in, st, begin, size, c, i, s);
        else
            gatheredPairs<Viscous, Hourglass, false, SumsOwn, L>(in, st, begin, size, c, i, s);
    };
    for (Index i = 0; i < len; ++i) {
        const Index c = block.particle(i);
        if (afresh[i]) {
            Index size = 0;
            const StagedPairs& st = stageIntoScratch(ref, bonds, c, size);
            run(std::true_type{}, st, 0, size, c, i);
        } else {
            const CsrPairWeights& w = *in.staged;
            const auto ic = static_cast<std::size_t>(c);
            run(std::false_type{}, w.pairs, w.begin[ic],
                static_cast<Index>(w.begin[ic + 1] - w.begin[ic]), c, i);
        }
    }
    leaveLanes<L>();
    for (Index i = 0; i < len; ++i) {
        const auto col = [&](const double(&a)[3][kMaxBlock]) {
            return Vec3(a[0][i], a[1][i], a[2][i]);
        };
        const Index c = block.particle(i);
        const auto ic = static_cast<std::size_t>(c);
        const Vec3 sumW = afresh[i] ? col(s.sumW) : in.staged->ownSum[ic];
        finishParticle<Viscous, Hourglass>(sf, c, sf.K[ic] * sumW + col(s.fK), col(s.sumQW),
                                           col(s.fN), col(s.fh), force, parts);
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
    const auto csrForce =
        widestVariant(avx512CsrForce<Viscous, Hourglass>, avx2CsrForce<Viscous, Hourglass>,
                      portableCsrForce<Viscous, Hourglass>);
    parallelForBlocks(blocks.cost, [&](std::ptrdiff_t k) {
        const ParticleBlock& block = blocks.blocks[static_cast<std::size_t>(k)];
        if (block.stencil != kNoStencil && bonds.allIntact(block.begin, block.end)) {
            const Stencil& st = blocks.stencils[static_cast<std::size_t>(block.stencil)];
            widestVariant(avx512BlockForce<Viscous, Hourglass>, avx2BlockForce<Viscous, Hourglass>,
                          portableBlockForce<Viscous, Hourglass>,
                          block.size())(in, sf, st, block, force, parts);
            return;
        }
        // A block of stencil particles with a broken bond takes the CSR path too (stride > 1
        // included); ParticleBlock::particle walks it either way.
        csrForce(in, ref, sf, bonds, block, force, parts);
    });
}

}  // namespace

void refreshReferenceRows(PairFieldRows& rows, const ParticleFields& fields,
                          const CsrPairWeights& staged, std::size_t n) {
    if (staged.gathered.empty()) return;
    const std::array<const double*, kRowFields - kSlotReferenceX> column{
        fields.X.component(0), fields.X.component(1), fields.X.component(2)};
    rows.refresh(kSlotReferenceX, column, staged.gathered, n);
}

void refreshMotionRows(PairFieldRows& rows, const ParticleFields& fields,
                       const CsrPairWeights& staged, std::size_t n) {
    if (staged.gathered.empty()) return;
    const std::array<const double*, kMotionSlots> column{
        fields.x.component(0), fields.x.component(1), fields.x.component(2),
        fields.v.component(0), fields.v.component(1), fields.v.component(2)};
    rows.refresh(kSlotX, column, staged.gathered, n);
}

void internalForce(const Reference& ref, const ParticleFields& fields, const StressFactors& factors,
                   const StencilBlocks& blocks, const ForceOptions& options,
                   std::vector<Vec3>& force, ForceParts& parts, const BondView& bonds,
                   const Mat3* G, const CsrPairWeights* staged, PairFieldRows* rows) {
    std::array<const double*, kPairSlots> slot{};
    const auto place = [&](int first, const auto& columns) {
        for (std::size_t k = 0; k < columns.size(); ++k)
            slot[static_cast<std::size_t>(first) + k] = columns[k];
    };
    place(kSlotX, components(fields.x)), place(kSlotV, components(fields.v));
    place(kSlotF, components(fields.F)), place(kSlotK, components(factors.K));
    place(kSlotN, components(factors.N)), place(kSlotReferenceX, components(fields.X));
    slot[kSlotSoundSpeed] = factors.soundSpeed.data();
    slot[kSlotDensity] = factors.density.data();
    slot[kSlotViscositySwitch] = factors.viscositySwitch.data();
    slot[kSlotHourglassScale] = factors.hourglassScale.data();
    slot[kSlotSmoothingLength] = ref.smoothingLength.data();
    slot[kSlotVolume] = ref.quadVolume.data();
    const bool useRows = rows != nullptr && staged != nullptr && !staged->gathered.empty();
    if (useRows)  // x and v after the drift (refreshMotionRows), X once (refreshReferenceRows)
        rows->refresh(kMotionSlots,
                      std::span<const double* const>(slot.data() + kMotionSlots,
                                                     slot.data() + kSlotReferenceX),
                      staged->gathered, static_cast<std::size_t>(ref.size()));
    const ForceView in{slot,
                       useRows ? rows->data() : nullptr,
                       G != nullptr ? G : ref.G.data(),
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
