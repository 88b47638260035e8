// SPDX-License-Identifier: MIT
#include "kinematics/deformation_gradient.hpp"

#include <algorithm>

#include "core/lanes.hpp"
#include "core/parallel.hpp"
#include "particles/axisymmetry.hpp"

namespace gsph {

void deformationGradient(const Reference& ref, const std::vector<Vec3>& x, std::vector<Mat3>& F) {
    F.resize(x.size());
    const Mat3 outOfPlane = ref.dim.outOfPlane();
    parallelFor(ref.size(), [&](Index a) {
        Mat3 gradX, gradV;
        thetaGradients(ref, a, x.data(), x.data(), gradX, gradV, nullptr, ref.pairCorrections(a));
        const auto ia = static_cast<std::size_t>(a);
        F[ia] = gradX * ref.G[ia].transpose() + outOfPlane;
        if (ref.dim.axisymmetric) F[ia](2, 2) = hoopStretch(ref.X[ia], x[ia]);
    });
}

namespace {

static_assert(kMinStencilRun >= kLanesOf<Lanes4>, "a stencil block holds a 4-lane strip");

// g[3r + c][i + j] = Σ_k f_r(a + js + δ_k) w_k,c − f_r(a + js) Σ_k w_k,c for the strip of
// particles a + js (strip type L, stride s = load.stride; core/lanes.hpp), with the nine sums in
// registers. A symmetric
// stencil sums mirrored pairs (f(a + δ) − f(a − δ)) ⊗ w over half the entries; its Σ_k w_k is
// exactly zero.
template <class L, class Load>
[[gnu::always_inline]] inline void stripGradient(const Stencil& st, const Load& load,
                                                 const Vec3Field& f, Index a, Index i,
                                                 double (&g)[9][kMaxBlock]) {
    const double* f0 = f.component(0) + a;
    const double* f1 = f.component(1) + a;
    const double* f2 = f.component(2) + a;
    L acc[9] = {};
    const auto add = [&acc](const L& v0, const L& v1, const L& v2, const Vec3& w)
        __attribute__((always_inline)) {
        for (int c = 0; c < 3; ++c) {
            acc[c] += v0 * w[c];
            acc[3 + c] += v1 * w[c];
            acc[6 + c] += v2 * w[c];
        }
    };
    const Index m = st.size();
    if (st.symmetric) {
        for (Index k = m / 2; k < m; ++k) {
            const Index d = st.delta[static_cast<std::size_t>(k)];
            add(load(f0 + d) - load(f0 - d), load(f1 + d) - load(f1 - d),
                load(f2 + d) - load(f2 - d), st.gradW[static_cast<std::size_t>(k)]);
        }
    } else {
        for (Index k = 0; k < m; ++k) {
            const Index d = st.delta[static_cast<std::size_t>(k)];
            add(load(f0 + d), load(f1 + d), load(f2 + d), st.gradW[static_cast<std::size_t>(k)]);
        }
        add(-load(f0), -load(f1), -load(f2), st.sumGradW);
    }
    for (int rc = 0; rc < 9; ++rc) storeLanes(g[rc] + i, acc[rc]);
}

// Strips of kLanesOf<L> particles (stride 1: consecutive); the last strip of a block whose
// length is not a multiple of the width overlaps the one before and recomputes (identically) a
// few particles.
template <class L, class Load>
[[gnu::always_inline]] inline void blockStrips(const Stencil& st, const Load& load, Index a0,
                                               Index len, const Vec3Field& x, const Vec3Field& v,
                                               BlockThetaGradients& g) {
    constexpr Index width = kLanesOf<L>;
    for (Index i = 0; i < len; i += width) {
        const Index s = std::min(i, len - width);
        stripGradient<L>(st, load, x, a0 + s * load.stride, s, g.x);
        stripGradient<L>(st, load, v, a0 + s * load.stride, s, g.v);
    }
}

// (Functions, not lambdas: a lambda is not always inlined into the wide target.)
template <class L>
[[gnu::always_inline]] inline void blockGradients(const Stencil& st, Index a0, Index len,
                                                  Index stride, const Vec3Field& x,
                                                  const Vec3Field& v, BlockThetaGradients& g) {
    if (stride == 1)
        blockStrips<L>(st, StripLoad<L, false>{}, a0, len, x, v, g);
    else
        blockStrips<L>(st, StripLoad<L, true>{stride}, a0, len, x, v, g);
    leaveLanes<L>();
}

void portableBlockGradients(const Stencil& st, Index a0, Index len, Index stride,
                            const Vec3Field& x, const Vec3Field& v, BlockThetaGradients& g) {
    blockGradients<Lanes2>(st, a0, len, stride, x, v, g);
}

GSPH_AVX2_TARGET void avx2BlockGradients(const Stencil& st, Index a0, Index len, Index stride,
                                         const Vec3Field& x, const Vec3Field& v,
                                         BlockThetaGradients& g) {
    blockGradients<Lanes4>(st, a0, len, stride, x, v, g);
}

GSPH_AVX512_TARGET void avx512BlockGradients(const Stencil& st, Index a0, Index len, Index stride,
                                             const Vec3Field& x, const Vec3Field& v,
                                             BlockThetaGradients& g) {
    blockGradients<Lanes8>(st, a0, len, stride, x, v, g);
}

// Σ_b x_b ⊗ wOwn, Σ_b v_b ⊗ wOwn and Σ wOwn (staged pairs, neighbors/staged_pairs.hpp) of a
// CSR block's particles, component-major by column.
struct CsrThetaSums {
    double x[9][kMaxBlock], v[9][kMaxBlock], w[3][kMaxBlock];
};

// The sums of one group of staged entries j … j + width − 1 into the lane sums, the
// neighbours' x and v through fetch(slot) (PairFieldSlot: a gather, a contiguous load at a + δ,
// or a column of the rows).
template <class L, class Fetch>
[[gnu::always_inline]] inline void thetaGroup(const double* wOwn, std::size_t stride, std::size_t j,
                                              const Fetch& fetch, L (&ax)[9], L (&av)[9],
                                              L (&aw)[3]) {
    L w[3];
    for (std::size_t c = 0; c < 3; ++c) {
        w[c] = loadLanes<L>(wOwn + c * stride + j);
        aw[c] += w[c];
    }
    for (int r = 0; r < 3; ++r) {
        const L xb = fetch(kSlotX + r), vb = fetch(kSlotV + r);
        for (std::size_t c = 0; c < 3; ++c) {
            ax[3 * r + c] += xb * w[c];
            av[3 * r + c] += vb * w[c];
        }
    }
}

// The SoA column of x or v at a motion slot.
inline const double* motionColumn(const Vec3Field& x, const Vec3Field& v, int slot) {
    return slot < kSlotV ? x.component(slot - kSlotX) : v.component(slot - kSlotV);
}

// A run of a particle's staged pairs across kPairLanes lanes, reduced in the fixed order of
// sumPairLanes and added into column i. FromRows: x and v of the far ends as columns of `rows`
// (every b is one of CsrPairWeights::gathered), else gathered from x and v; the same values.
template <bool FromRows, class L>
[[gnu::always_inline]] inline void gatheredThetaSums(const StagedPairs& st, std::size_t begin,
                                                     Index size, const Vec3Field& x,
                                                     const Vec3Field& v, const double* rows,
                                                     Index i, CsrThetaSums& out) {
    constexpr int width = kLanesOf<L>, strips = kPairLanes / width;
    L ax[strips][9] = {}, av[strips][9] = {}, aw[strips][3] = {};
    for (Index j0 = 0; j0 < size; j0 += kPairLanes)
        for (int u = 0; u < strips; ++u) {
            const std::size_t j = begin + static_cast<std::size_t>(j0 + u * width);
            const std::int32_t* b = st.b.data() + j;
            if constexpr (FromRows) {
                constexpr int loaded = (kMotionSlots + width - 1) / width * width;
                L column[loaded];
                for (int first = 0; first < loaded; first += width)
                    loadColumns<L>(rows, kRowLength, b, static_cast<std::size_t>(first),
                                   column + first);
                thetaGroup<L>(
                    st.wOwn.data(), st.stride,
                    j, [&column](int slot) __attribute__((always_inline)) { return column[slot]; },
                    ax[u], av[u], aw[u]);
            } else {
                thetaGroup<L>(
                    st.wOwn.data(), st.stride, j,
                    [&x, &v, b ](int slot) __attribute__((always_inline)) {
                        return gatherLanesAt<L>(motionColumn(x, v, slot), b);
                    },
                    ax[u], av[u], aw[u]);
            }
        }
    L lanes[strips];
    for (int rc = 0; rc < 9; ++rc) {
        for (int u = 0; u < strips; ++u) lanes[u] = ax[u][rc];
        out.x[rc][i] += sumPairLanes<L>(lanes);
        for (int u = 0; u < strips; ++u) lanes[u] = av[u][rc];
        out.v[rc][i] += sumPairLanes<L>(lanes);
    }
    for (int c = 0; c < 3; ++c) {
        for (int u = 0; u < strips; ++u) lanes[u] = aw[u][c];
        out.w[c][i] += sumPairLanes<L>(lanes);
    }
}

// A masked strip whose first particle is column i: each lane one particle, its entries in order.
template <class L>
[[gnu::always_inline]] inline void maskedThetaSums(const CsrPairWeights& w,
                                                   const MaskedStrip& strip, const Vec3Field& x,
                                                   const Vec3Field& v, Index i, CsrThetaSums& out) {
    constexpr int width = kLanesOf<L>;
    const Index* delta = w.delta.data() + strip.deltaBegin;
    for (int u = 0; u < kPairLanes / width; ++u) {
        L ax[9] = {}, av[9] = {}, aw[3] = {};
        for (Index e = 0; e < strip.deltaEnd - strip.deltaBegin; ++e) {
            const Index ad = strip.first + u * width + delta[e];
            thetaGroup<L>(
                w.stripPairs.wOwn.data(), w.stripPairs.stride,
                strip.base + static_cast<std::size_t>(e * kPairLanes + u * width),
                [&x, &v, ad ](int slot) __attribute__((always_inline)) {
                    return loadLanes<L>(motionColumn(x, v, slot) + ad);
                },
                ax, av, aw);
        }
        const Index col = i + u * width;
        for (int rc = 0; rc < 9; ++rc)
            storeLanes(out.x[rc] + col, ax[rc]), storeLanes(out.v[rc] + col, av[rc]);
        for (int c = 0; c < 3; ++c) storeLanes(out.w[c] + col, aw[c]);
    }
}

template <class L>
[[gnu::always_inline]] inline void csrBlockGradients(const Reference& ref,
                                                     const CsrPairWeights* staged,
                                                     const BondView& bonds,
                                                     const ParticleBlock& block, const Vec3Field& x,
                                                     const Vec3Field& v, const double* rows,
                                                     BlockThetaGradients& g) {
    CsrThetaSums s{};
    const Index len = block.size();
    bool afresh[kMaxBlock];
    stagedStrips(staged, bonds, block, afresh, [&](Index i, const MaskedStrip& strip) {
        maskedThetaSums<L>(*staged, strip, x, v, i, s);
    });
    for (Index i = 0; i < len; ++i) {
        const Index c = block.particle(i);
        const auto run = [&](const StagedPairs& st, std::size_t begin, Index size)
            __attribute__((always_inline)) {
            if (rows != nullptr)
                gatheredThetaSums<true, L>(st, begin, size, x, v, rows, i, s);
            else
                gatheredThetaSums<false, L>(st, begin, size, x, v, rows, i, s);
        };
        if (afresh[i]) {
            Index size = 0;
            const StagedPairs& st = stageIntoScratch(ref, bonds, c, size);
            run(st, 0, size);
        } else {
            const auto ic = static_cast<std::size_t>(c);
            run(staged->pairs, staged->begin[ic],
                static_cast<Index>(staged->begin[ic + 1] - staged->begin[ic]));
        }
    }
    leaveLanes<L>();
    for (Index i = 0; i < len; ++i) {
        const auto ia = static_cast<std::size_t>(block.particle(i));
        const Vec3 xa = x[ia], va = v[ia];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                g.x[3 * r + c][i] = s.x[3 * r + c][i] - xa[r] * s.w[c][i];
                g.v[3 * r + c][i] = s.v[3 * r + c][i] - va[r] * s.w[c][i];
            }
    }
}

void portableCsrGradients(const Reference& ref, const CsrPairWeights* staged, const BondView& bonds,
                          const ParticleBlock& block, const Vec3Field& x, const Vec3Field& v,
                          const double* rows, BlockThetaGradients& g) {
    csrBlockGradients<Lanes2>(ref, staged, bonds, block, x, v, rows, g);
}

GSPH_AVX2_TARGET void avx2CsrGradients(const Reference& ref, const CsrPairWeights* staged,
                                       const BondView& bonds, const ParticleBlock& block,
                                       const Vec3Field& x, const Vec3Field& v, const double* rows,
                                       BlockThetaGradients& g) {
    csrBlockGradients<Lanes4>(ref, staged, bonds, block, x, v, rows, g);
}

GSPH_AVX512_TARGET void avx512CsrGradients(const Reference& ref, const CsrPairWeights* staged,
                                           const BondView& bonds, const ParticleBlock& block,
                                           const Vec3Field& x, const Vec3Field& v,
                                           const double* rows, BlockThetaGradients& g) {
    csrBlockGradients<Lanes8>(ref, staged, bonds, block, x, v, rows, g);
}

}  // namespace

void csrThetaGradients(const Reference& ref, const CsrPairWeights* staged, const BondView& bonds,
                       const ParticleBlock& block, const Vec3Field& x, const Vec3Field& v,
                       BlockThetaGradients& g, const PairFieldRows* rows) {
    // The rows hold the far ends of the CSR blocks' runs (not of a stencil block's).
    const double* fromRows = rows != nullptr && staged != nullptr && block.stencil == kNoStencil
                                 ? rows->data()
                                 : nullptr;
    widestVariant(avx512CsrGradients, avx2CsrGradients, portableCsrGradients)(
        ref, staged, bonds, block, x, v, fromRows, g);
}

void stencilThetaGradients(const Stencil& st, const ParticleBlock& block, const Vec3Field& x,
                           const Vec3Field& v, BlockThetaGradients& g) {
    const Index len = block.size();
    widestVariant(avx512BlockGradients, avx2BlockGradients, portableBlockGradients, len)(
        st, block.begin, len, block.stride, x, v, g);
}

}  // namespace gsph
