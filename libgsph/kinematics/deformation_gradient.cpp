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

// Σ_b f_b ⊗ wOwn and Σ wOwn over a's staged pairs, in kPairLanes lanes (strip type L).
template <class L>
[[gnu::always_inline]] inline void stagedSums(const StagedPairs& st, std::size_t begin, Index size,
                                              const Vec3Field& x, const Vec3Field& v,
                                              double (&sx)[9], double (&sv)[9], double (&sw)[3]) {
    constexpr int strips = kPairLanes / kLanesOf<L>;
    L ax[9][strips] = {}, av[9][strips] = {}, aw[3][strips] = {};
    const std::size_t m = st.stride;
    for (Index j0 = 0; j0 < size; j0 += kPairLanes)
        for (int u = 0; u < strips; ++u) {
            const std::size_t j = begin + static_cast<std::size_t>(j0 + u * kLanesOf<L>);
            const std::int32_t* b = st.b.data() + j;
            L w[3];
            for (std::size_t c = 0; c < 3; ++c) {
                w[c] = loadLanes<L>(st.wOwn.data() + c * m + j);
                aw[c][u] += w[c];
            }
            for (int r = 0; r < 3; ++r) {
                const L xb = gatherLanesAt<L>(x.component(r), b);
                const L vb = gatherLanesAt<L>(v.component(r), b);
                for (std::size_t c = 0; c < 3; ++c) {
                    ax[3 * r + c][u] += xb * w[c];
                    av[3 * r + c][u] += vb * w[c];
                }
            }
        }
    for (int rc = 0; rc < 9; ++rc)
        sx[rc] = sumPairLanes<L>(ax[rc]), sv[rc] = sumPairLanes<L>(av[rc]);
    for (int c = 0; c < 3; ++c) sw[c] = sumPairLanes<L>(aw[c]);
    leaveLanes<L>();
}

void portableStagedSums(const StagedPairs& st, std::size_t begin, Index size, const Vec3Field& x,
                        const Vec3Field& v, double (&sx)[9], double (&sv)[9], double (&sw)[3]) {
    stagedSums<Lanes2>(st, begin, size, x, v, sx, sv, sw);
}

GSPH_AVX2_TARGET void avx2StagedSums(const StagedPairs& st, std::size_t begin, Index size,
                                     const Vec3Field& x, const Vec3Field& v, double (&sx)[9],
                                     double (&sv)[9], double (&sw)[3]) {
    stagedSums<Lanes4>(st, begin, size, x, v, sx, sv, sw);
}

GSPH_AVX512_TARGET void avx512StagedSums(const StagedPairs& st, std::size_t begin, Index size,
                                         const Vec3Field& x, const Vec3Field& v, double (&sx)[9],
                                         double (&sv)[9], double (&sw)[3]) {
    stagedSums<Lanes8>(st, begin, size, x, v, sx, sv, sw);
}

}  // namespace

void stagedThetaGradients(const StagedPairs& st, std::size_t begin, Index size, const Vec3Field& x,
                          const Vec3Field& v, Index a, Mat3& gradX, Mat3& gradV) {
    double sx[9], sv[9], sw[3];
    const int width = laneWidth();
    if (width >= 8)
        avx512StagedSums(st, begin, size, x, v, sx, sv, sw);
    else if (width >= 4)
        avx2StagedSums(st, begin, size, x, v, sx, sv, sw);
    else
        portableStagedSums(st, begin, size, x, v, sx, sv, sw);
    const auto ia = static_cast<std::size_t>(a);
    const Vec3 xa = x[ia], va = v[ia];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            gradX(r, c) = sx[3 * r + c] - xa[r] * sw[c];
            gradV(r, c) = sv[3 * r + c] - va[r] * sw[c];
        }
}

void stencilThetaGradients(const Stencil& st, const ParticleBlock& block, const Vec3Field& x,
                           const Vec3Field& v, BlockThetaGradients& g) {
    const Index len = block.size();
    const int width = laneWidth();
    if (width >= 8 && len >= 8)
        avx512BlockGradients(st, block.begin, len, block.stride, x, v, g);
    else if (width >= 4)
        avx2BlockGradients(st, block.begin, len, block.stride, x, v, g);
    else
        portableBlockGradients(st, block.begin, len, block.stride, x, v, g);
}

}  // namespace gsph
