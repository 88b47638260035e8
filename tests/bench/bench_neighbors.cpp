// SPDX-License-Identifier: MIT
// Neighbour search on a 3-D θ-lattice: the cell list against nanoflann's k-d tree, for 1e5 and
// 1e6 particles (the library defaults to the winner).
// Run: build/tests/bench/bench_neighbors
#include <benchmark/benchmark.h>

#include "neighbors/theta_search.hpp"
#include "spaces/analytic_maps.hpp"

namespace {

void searchLattice(benchmark::State& state, gsph::SearchMethod method) {
    const int n = static_cast<int>(state.range(0));
    const gsph::Reference base = gsph::latticeReference(gsph::gradedBoxMap(gsph::Vec3(1, 1, 1), {}),
                                                        3, {n, n, n}, 1000.0, 1.2);
    for (auto _ : state) {
        gsph::Reference ref = base;
        gsph::buildPairs(ref, method);
        benchmark::DoNotOptimize(ref.pairs.neighbor.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long>(n) * n * n);
    state.SetLabel(std::to_string(n * n * n) + " particles");
}

void CellList(benchmark::State& s) {
    searchLattice(s, gsph::SearchMethod::CellList);
}
void KdTree(benchmark::State& s) {
    searchLattice(s, gsph::SearchMethod::KdTree);
}

BENCHMARK(CellList)->Arg(46)->Arg(100)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(KdTree)->Arg(46)->Arg(100)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
