// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>

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

}  // namespace
}  // namespace gsph
