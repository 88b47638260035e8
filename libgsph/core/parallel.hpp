// SPDX-License-Identifier: MIT
// The one parallel seam of the library (style habit 6).
// - parallelFor(n, body): body(i) for i in [0, n), OpenMP static schedule (parallelForBlocks:
//   ranges of equal cost). Each i must write only its own entries (gather, never scatter), so
//   results do not depend on the thread count.
// - deterministicSum(n, term): Σ term(i) summed in fixed chunks and a fixed order, so the
//   result is bit-identical for any thread count (an OpenMP reduction would not be). The
//   overload with a `partial` scratch vector does not allocate once that has grown.
// - exactSum(range, term): Σ term(a) exactly rounded, the same bits however the particles are
//   split over threads or processes (what a split run's reductions use).
// - ParticleRange: the particles this process advances (all of them in a serial run; one
//   rank's share in a distributed one, distributed/domain.hpp); the loops above take it too.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/exact_sum.hpp"
#include "core/types.hpp"

namespace gsph {

/// The particles [begin, end) one process advances.
struct ParticleRange {
    Index begin = 0, end = 0;
    Index size() const { return end - begin; }
    bool contains(Index a) const { return a >= begin && a < end; }
    /// The particles of [first, last) in this range (empty, at its place, when none are).
    ParticleRange within(Index first, Index last) const {
        const Index lo = first > begin ? first : begin;
        const Index hi = last < end ? last : end;
        return {lo, hi > lo ? hi : lo};
    }
};

/// Loops shorter than this run on the calling thread: a parallel region costs a few µs of
/// fork/join, and on a loaded machine spinning threads make tiny regions far slower (measured:
/// 1000 particles, 2 threads on a busy 2-core machine, 15× slower than 1 thread).
inline constexpr std::ptrdiff_t kParallelThreshold = 4096;

template <class Body>
inline void parallelFor(std::ptrdiff_t n, Body&& body) {
#pragma omp parallel for schedule(static) if (n >= kParallelThreshold)
    for (std::ptrdiff_t i = 0; i < n; ++i) body(i);
}

/// body(i) for the blocks i of a sweep whose costs run up as `cost` (size blocks + 1, cost[0] =
/// 0: StencilBlocks::cost), each thread taking one contiguous range of equal cost. Blocks differ
/// in cost (a stencil strip against the CSR particles of an overset band, several times
/// dearer): an even split of the blocks left one thread idle for a third of an O-grid sweep. The
/// ranges depend only on the costs and the thread count, so the stress update and the force
/// loop give each thread the same particles (they stay in its cache). Below
/// kParallelThreshold of cost the sweep runs on the calling thread. Each block writes only its
/// own entries: the split never changes a result.
template <class Body>
inline void parallelForBlocks(const std::vector<std::ptrdiff_t>& cost, Body&& body) {
    const auto n = static_cast<std::ptrdiff_t>(cost.size()) - 1;
    if (n <= 0) return;
    const std::ptrdiff_t total = cost.back();
#pragma omp parallel if (total >= kParallelThreshold)
    {
        const std::ptrdiff_t threads = omp_get_num_threads(), t = omp_get_thread_num();
        const auto at = [&](std::ptrdiff_t share) {
            return std::lower_bound(cost.begin(), cost.end() - 1, total * share / threads) -
                   cost.begin();
        };
        const std::ptrdiff_t end = t + 1 == threads ? n : at(t + 1);
        for (std::ptrdiff_t i = at(t); i < end; ++i) body(i);
    }
}

/// body(a) for the particles a of `range`.
template <class Body>
inline void parallelFor(ParticleRange range, Body&& body) {
    parallelFor(range.size(), [&](std::ptrdiff_t i) { body(range.begin + static_cast<Index>(i)); });
}

/// Chunk size of deterministicSum; fixed so that the summation order never changes.
inline constexpr std::ptrdiff_t kReductionChunk = 2048;

template <class T, class Term>
inline T deterministicSum(std::ptrdiff_t n, T zero, Term&& term, std::vector<T>& partial) {
    const std::ptrdiff_t chunks = (n + kReductionChunk - 1) / kReductionChunk;
    partial.assign(static_cast<std::size_t>(chunks), zero);
#pragma omp parallel for schedule(static) if (n >= kParallelThreshold)
    for (std::ptrdiff_t c = 0; c < chunks; ++c) {
        T s = zero;
        const std::ptrdiff_t end = std::min(n, (c + 1) * kReductionChunk);
        for (std::ptrdiff_t i = c * kReductionChunk; i < end; ++i) s += term(i);
        partial[static_cast<std::size_t>(c)] = s;
    }
    T total = zero;
    for (const T& s : partial) total += s;
    return total;
}

template <class T, class Term>
inline T deterministicSum(std::ptrdiff_t n, T zero, Term&& term) {
    std::vector<T> partial;
    return deterministicSum(n, zero, std::forward<Term>(term), partial);
}

/// Σ term(a) over the particles of `range`, exactly rounded (core/exact_sum.hpp): the same bits
/// for any thread count and any split of the particles over processes (sum the ExactSums).
template <class Term>
inline ExactSum exactSum(ParticleRange range, Term&& term) {
    ExactSum total;
#pragma omp parallel if (range.size() >= kParallelThreshold)
    {
        ExactSum mine;
#pragma omp for schedule(static) nowait
        for (Index a = range.begin; a < range.end; ++a) mine.add(term(a));
#pragma omp critical(gsph_exact_sum)
        total.add(mine);  // integers: the order of the merges does not matter
    }
    return total;
}

/// Minimum of term(i) over [0, n); exact, so independent of the thread count.
template <class Term>
inline double parallelMin(std::ptrdiff_t n, double init, Term&& term) {
    double m = init;
#pragma omp parallel for schedule(static) reduction(min : m) if (n >= kParallelThreshold)
    for (std::ptrdiff_t i = 0; i < n; ++i) m = std::min(m, term(i));
    return m;
}

/// Minimum of term(a) over the particles of `range`; exact.
template <class Term>
inline double parallelMin(ParticleRange range, double init, Term&& term) {
    return parallelMin(range.size(), init,
                       [&](std::ptrdiff_t i) { return term(range.begin + static_cast<Index>(i)); });
}

}  // namespace gsph
