// SPDX-License-Identifier: MIT
// A strip of consecutive particles evaluated together in SIMD lanes.
//
// The stencil kernels (kinematics/deformation_gradient.cpp, forces/internal_force.cpp) run a
// strip of particles through a whole stencil with the per-particle sums held in registers. A
// strip is a GCC vector of doubles: Lanes2 (SSE2, every x86-64), Lanes4 (AVX2) or Lanes8
// (AVX-512F). The kernels are templates on the strip type, compiled once per width, the wide
// ones inside functions with GSPH_AVX2_TARGET / GSPH_AVX512_TARGET, which the library calls when
// the processor has that instruction set (laneWidth()). So the portable build uses the wide
// strips where the machine has them, without -march=native. Each lane does the same operations
// in the same order whatever the width, and the library is built with -ffp-contract=off (no
// fused multiply-add where a target offers it), so every width gives bit-identical results.
// Pair formulas written as templates on the scalar type (double or a strip type) serve the
// strip kernels and the one-pair-at-a-time CSR path alike.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

// The strip types never cross a function boundary that is not inlined (every function on strips
// is always_inline, so it inlines into its target function: no lambdas, no plain member
// functions), so the ABI note on AVX vectors does not apply. The sanitizer build compiles the
// kernels' files unoptimized, where a call left out of line would show (libgsph/CMakeLists.txt).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace gsph {

typedef double Lanes2 __attribute__((vector_size(16)));
typedef double Lanes4 __attribute__((vector_size(32)));
typedef double Lanes8 __attribute__((vector_size(64)));

/// Particles per strip of strip type L.
template <class L>
inline constexpr int kLanesOf = static_cast<int>(sizeof(L) / sizeof(double));

#if defined(__x86_64__) || defined(__i386__)
#define GSPH_AVX2_TARGET [[gnu::target("avx2")]]
#define GSPH_AVX512_TARGET [[gnu::target("avx512f")]]
#else
#define GSPH_AVX2_TARGET
#define GSPH_AVX512_TARGET
#endif

/// The widest strip the stencil kernels take: 8 with AVX-512F, 4 with AVX2, else 2, at most
/// the limit of limitLanes(). A block of fewer particles than that takes the next width that
/// fits (stencil blocks hold at least kMinStencilRun = 4). Decided once; cheap to call.
int laneWidth();
/// Caps laneWidth() at `width` (2, 4 or 8; tests and gsph-bench compare the widths); not
/// thread-safe, call before a run.
void limitLanes(int width);

/// The variant of a strip loop compiled for the widest strips the processor has (laneWidth()),
/// at most `fits` lanes wide (a stencil block shorter than 8 particles takes 4): its AVX-512F,
/// AVX2 or SSE2 instance.
template <class Fn>
Fn* widestVariant(Fn* avx512, Fn* avx2, Fn* sse2, int fits = 8) {
    const int width = laneWidth();
    return width >= 8 && fits >= 8 ? avx512 : width >= 4 ? avx2 : sse2;
}

/// Call at the end of the strip loops of type L (before scalar code or a return). For Lanes4
/// and Lanes8 this clears the upper halves of the AVX registers, which otherwise slow down the SSE
/// code that follows (measured: the CSR path 3× slower) and which GCC does not clear around the
/// calls and returns of a target function. An asm statement, so that it inlines into any target;
/// it clobbers every vector register, so no value is kept across it.
template <class L>
[[gnu::always_inline]] inline void leaveLanes() {
#if defined(__x86_64__)
    if constexpr (sizeof(L) > 16)
        asm volatile("vzeroupper" ::
                         : "xmm0", "xmm1", "xmm2", "xmm3", "xmm4", "xmm5", "xmm6", "xmm7", "xmm8",
                           "xmm9", "xmm10", "xmm11", "xmm12", "xmm13", "xmm14", "xmm15");
#endif
}

/// The lanes at p, p + 1, ... (unaligned).
template <class L>
[[gnu::always_inline]] inline L loadLanes(const double* p) {
    L v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
template <class L>
[[gnu::always_inline]] inline void storeLanes(double* p, const L& v) {
    std::memcpy(p, &v, sizeof v);
}

/// The lanes at p, p + stride, p + 2 stride, ... (a strip across rows).
template <class L>
[[gnu::always_inline]] inline L gatherLanes(const double* p, long stride) {
    L v;
    for (int j = 0; j < kLanesOf<L>; ++j) v[j] = p[j * stride];
    return v;
}

/// Reads a strip's lanes: consecutive (Strided = false) or `stride` apart.
template <class L, bool Strided>
struct StripLoad {
    long stride = 1;
    [[gnu::always_inline]] L operator()(const double* p) const {
        if constexpr (Strided)
            return gatherLanes<L>(p, stride);
        else
            return loadLanes<L>(p);
    }
};

/// The lanes p[index[0]], p[index[1]], ... (a gather). With 4 or 8 lanes the processor's gather
/// instruction, from an asm statement: the intrinsics cannot be inlined into the generic
/// templates that the wide targets inline, an asm statement can. The asm does not tell the
/// compiler that it reads *p: call it only on arrays the loop does not write.
template <class L>
[[gnu::always_inline]] inline L gatherLanesAt(const double* p, const std::int32_t* index) {
#if defined(__x86_64__)
    if constexpr (kLanesOf<L> == 8) {
        typedef std::int32_t Index8 __attribute__((vector_size(32)));
        Index8 i;
        std::memcpy(&i, index, sizeof i);
        L v;
        asm("kxnorw %%k1, %%k1, %%k1\n\tvgatherdpd (%1,%2,8), %0%{%%k1%}"
            : "=&v"(v)
            : "r"(p), "v"(i)
            : "k1");
        return v;
    } else if constexpr (kLanesOf<L> == 4) {
        typedef std::int32_t Index4 __attribute__((vector_size(16)));
        Index4 i;
        std::memcpy(&i, index, sizeof i);
        L v, mask;
        asm("vpcmpeqd %1, %1, %1\n\tvgatherdpd %1, (%2,%3,8), %0"
            : "=&x"(v), "=&x"(mask)
            : "r"(p), "x"(i));
        return v;
    }
#endif
    L v;
    for (int j = 0; j < kLanesOf<L>; ++j) v[j] = p[index[j]];
    return v;
}

/// r[0] … r[W − 1] (W = the strip's width) transposed in registers: afterwards lane j of r[k]
/// is what lane k of r[j] was. log2 W rounds of two-vector shuffles; round d exchanges the
/// off-diagonal d × d blocks (lane p of row i, p & d set, with lane p − d of row i + d).
template <int D, class L, int... P>
[[gnu::always_inline]] inline void transposeRound(L* r, std::integer_sequence<int, P...>) {
    constexpr int W = kLanesOf<L>;
    typedef std::int64_t Mask __attribute__((vector_size(sizeof(L))));
    const Mask low = {((P & D) == 0 ? P : W + P - D)...};
    const Mask high = {((P & D) == 0 ? P + D : W + P)...};
    for (int i = 0; i < W; ++i)
        if ((i & D) == 0) {
            const L a = r[i], b = r[i + D];
            r[i] = __builtin_shuffle(a, b, low);
            r[i + D] = __builtin_shuffle(a, b, high);
        }
}
template <class L>
[[gnu::always_inline]] inline void transposeLanes(L* r) {
    constexpr int width = kLanesOf<L>;
    constexpr auto lanes = std::make_integer_sequence<int, width>{};
    transposeRound<1>(r, lanes);
    if constexpr (width > 2) transposeRound<2>(r, lanes);
    if constexpr (width > 4) transposeRound<4>(r, lanes);
}

/// Columns first … first + W − 1 of the rows index[0] … index[W − 1] of a row-major table of
/// `rowLength` doubles a row, W = the strip's width: out[k], lane j = table[index[j]][first + k].
/// W loads and a transposition in registers; where a pair loop reads many fields of the same
/// far ends, this replaces W gathers of one field each (on this project's machine a gather
/// costs about what a whole transposed load of W fields does, docs/performance.md).
template <class L>
[[gnu::always_inline]] inline void loadColumns(const double* table, std::size_t rowLength,
                                               const std::int32_t* index, std::size_t first,
                                               L* out) {
    for (int j = 0; j < kLanesOf<L>; ++j)
        out[j] = loadLanes<L>(table + static_cast<std::size_t>(index[j]) * rowLength + first);
    transposeLanes(out);
}

/// The SIMD lanes of the pair loops that run across one particle's pairs (neighbors/
/// staged_pairs.hpp): pair j adds into lane j mod kPairLanes whatever the strip width (a strip
/// of width L holds kPairLanes / width such lanes), and the lanes are summed in one fixed
/// order, so every width gives the same bits.
inline constexpr int kPairLanes = 8;

/// Σ of the kPairLanes lanes held in `acc` (kPairLanes / width strips of type L), in the fixed
/// order ((l0 + l4) + (l2 + l6)) + ((l1 + l5) + (l3 + l7)).
template <class L>
[[gnu::always_inline]] inline double sumPairLanes(const L* acc) {
    double l[kPairLanes];
    for (int u = 0; u < kPairLanes / kLanesOf<L>; ++u)
        for (int j = 0; j < kLanesOf<L>; ++j) l[u * kLanesOf<L> + j] = acc[u][j];
    return ((l[0] + l[4]) + (l[2] + l[6])) + ((l[1] + l[5]) + (l[3] + l[7]));
}

/// q where s < 0, else 0 (lane by lane): a select, not a branch, so that it vectorises.
[[gnu::always_inline]] inline double whereNegative(double s, double q) {
    return s < 0.0 ? q : 0.0;
}
template <class L>
requires(!std::is_arithmetic_v<L>) [[gnu::always_inline]] inline L
    whereNegative(const L& s, const L& q) {
    return s < 0.0 ? q : L{};
}

/// Whether some lane of s is negative (s < 0): a strip's pairs with no lane approaching have
/// no viscous pressure, and their whole viscous term can be skipped.
[[gnu::always_inline]] inline bool anyNegative(double s) {
    return s < 0.0;
}
template <class L>
requires(!std::is_arithmetic_v<L>) [[gnu::always_inline]] inline bool anyNegative(const L& s) {
    const auto negative = s < 0.0;  // lanes of all ones or 0
    std::int64_t any = 0;
    for (int j = 0; j < kLanesOf<L>; ++j) any |= negative[j];
    return any != 0;
}

}  // namespace gsph
