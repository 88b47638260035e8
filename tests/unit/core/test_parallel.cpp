// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>
#include <omp.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/parallel.hpp"

namespace gsph {
namespace {

TEST(Parallel, DeterministicSumIsBitIdenticalForAnyThreadCount) {
    const std::ptrdiff_t n = 100003;
    auto term = [](std::ptrdiff_t i) { return 1.0 / (1.0 + static_cast<double>(i) * 0.37); };
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const double one = deterministicSum(n, 0.0, term);
    omp_set_num_threads(2);
    const double two = deterministicSum(n, 0.0, term);
    omp_set_num_threads(saved);
    EXPECT_EQ(std::memcmp(&one, &two, sizeof(double)), 0);
    long double reference = 0.0L;  // sequential sum in extended precision
    for (std::ptrdiff_t i = 0; i < n; ++i) reference += term(i);
    EXPECT_NEAR(one, static_cast<double>(reference), 1e-12 * one);
}

TEST(Parallel, ParallelForVisitsEveryIndexOnce) {
    std::vector<int> hits(1000, 0);
    parallelFor(1000, [&](std::ptrdiff_t i) { hits[static_cast<std::size_t>(i)] += 1; });
    for (int h : hits) EXPECT_EQ(h, 1);
    EXPECT_DOUBLE_EQ(
        parallelMin(5, 10.0, [](std::ptrdiff_t i) { return 7.0 - static_cast<double>(i); }), 3.0);
}

// The block loops: every block once, each thread one contiguous range, the ranges' costs even
// to within one block's cost (blocks of cost 1 and 4, as stencil and CSR blocks), for 1, 2 and
// 3 threads; below the threshold, all on the calling thread.
TEST(Parallel, ParallelForBlocksSplitsTheCostEvenly) {
    std::vector<std::ptrdiff_t> cost = {0};
    for (int i = 0; i < 3000; ++i) cost.push_back(cost.back() + ((i / 500) % 2 == 0 ? 1 : 4));
    const auto n = static_cast<std::size_t>(cost.size() - 1);
    const int saved = omp_get_max_threads();
    for (int threads : {1, 2, 3}) {
        omp_set_num_threads(threads);
        std::vector<int> hits(n, 0), owner(n, -1);
        parallelForBlocks(cost, [&](std::ptrdiff_t i) {
            hits[static_cast<std::size_t>(i)] += 1;
            owner[static_cast<std::size_t>(i)] = omp_get_thread_num();
        });
        std::vector<std::ptrdiff_t> share(static_cast<std::size_t>(threads), 0);
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_EQ(hits[i], 1) << i;
            if (i > 0) {
                EXPECT_GE(owner[i], owner[i - 1]) << "contiguous ranges, in thread order";
            }
            share[static_cast<std::size_t>(owner[i])] += cost[i + 1] - cost[i];
        }
        for (std::ptrdiff_t s : share)
            EXPECT_LE(std::abs(s - cost.back() / threads), 4) << threads << " threads";
    }
    omp_set_num_threads(2);
    const std::vector<std::ptrdiff_t> small = {0, 1, 2, 3};  // below kParallelThreshold
    std::vector<int> owner(3, -1);
    parallelForBlocks(small, [&](std::ptrdiff_t i) {
        owner[static_cast<std::size_t>(i)] = omp_get_thread_num();
    });
    EXPECT_EQ(owner, std::vector<int>(3, 0));
    omp_set_num_threads(saved);
}

}  // namespace
}  // namespace gsph
