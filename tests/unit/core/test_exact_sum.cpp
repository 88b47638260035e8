// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "core/exact_sum.hpp"
#include "core/parallel.hpp"

namespace gsph {
namespace {

double exactSumOf(const std::vector<double>& terms) {
    ExactSum s;
    for (double t : terms) s.add(t);
    return s.value();
}

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof(double)) == 0;
}

TEST(ExactSum, RoundsOnceToNearestTiesToEven) {
    const double u = std::ldexp(1.0, -53);             // half an ulp of 1
    EXPECT_TRUE(sameBits(exactSumOf({1.0, u}), 1.0));  // tie: to even
    EXPECT_TRUE(sameBits(exactSumOf({1.0, u, std::ldexp(1.0, -300)}), 1.0 + 2 * u));  // above
    EXPECT_TRUE(sameBits(exactSumOf({1.0 + 2 * u, u}), 1.0 + 4 * u));          // tie: odd goes up
    EXPECT_TRUE(sameBits(exactSumOf({1.0, u, -std::ldexp(1.0, -300)}), 1.0));  // below the tie
    // Cancellation that a running sum gets wrong: 1e16 + 1 − 1e16 = 1 exactly.
    EXPECT_TRUE(sameBits(exactSumOf({1e16, 1.0, -1e16}), 1.0));
    EXPECT_TRUE(sameBits(
        exactSumOf({std::numeric_limits<double>::max(), 1.0, -std::numeric_limits<double>::max()}),
        1.0));
    // The doubles nearest 0.1, 0.2 and 0.3 sum to 2^−55 exactly (a running sum gives 2^−54).
    EXPECT_TRUE(sameBits(exactSumOf({0.1, 0.2, -0.3}), std::ldexp(1.0, -55)));
    EXPECT_TRUE(sameBits(exactSumOf({-2.5, 0.5}), -2.0));
    EXPECT_TRUE(sameBits(exactSumOf({}), 0.0));
}

TEST(ExactSum, SubnormalsOverflowAndSpecials) {
    const double tiny = std::numeric_limits<double>::denorm_min();
    EXPECT_TRUE(sameBits(exactSumOf({tiny, tiny, tiny}), 3 * tiny));
    EXPECT_TRUE(sameBits(exactSumOf({std::numeric_limits<double>::min(), -tiny}),
                         std::numeric_limits<double>::min() - tiny));
    const double big = std::ldexp(1.0, 1023);
    EXPECT_EQ(exactSumOf({big, big}), std::numeric_limits<double>::infinity());
    EXPECT_EQ(exactSumOf({-big, -big}), -std::numeric_limits<double>::infinity());
    EXPECT_TRUE(sameBits(exactSumOf({big, big, -big}), big));  // no overflow on the way
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(exactSumOf({1.0, inf}), inf);
    EXPECT_TRUE(std::isnan(exactSumOf({inf, -inf})));
    EXPECT_TRUE(std::isnan(exactSumOf({1.0, std::numeric_limits<double>::quiet_NaN()})));
}

// Terms whose exponents span 2^±20: their exact sum has fewer than 113 bits, so a binary128
// running sum is exact and one conversion rounds it correctly: the reference.
TEST(ExactSum, EqualsTheCorrectlyRoundedSumInAnyOrder) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-20, 20);
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<double> terms(1000);
        for (double& t : terms) t = std::ldexp(mantissa(rng), exponent(rng));
        __extension__ __float128 reference = 0;
        for (double t : terms) reference += t;
        const double expected = static_cast<double>(reference);
        const double sum = exactSumOf(terms);
        EXPECT_TRUE(sameBits(sum, expected)) << sum << " against " << expected;
        std::shuffle(terms.begin(), terms.end(), rng);
        EXPECT_TRUE(sameBits(exactSumOf(terms), sum));
        // Split into parts summed apart and merged, as threads and processes do.
        ExactSum a, b, whole;
        for (std::size_t i = 0; i < terms.size(); ++i) (i % 3 == 0 ? a : b).add(terms[i]);
        std::array<std::int64_t, ExactSum::kWords> words{};
        b.toWords(words);
        ExactSum travelled;
        travelled.fromWords(words);
        whole.add(travelled);
        whole.add(a);
        EXPECT_TRUE(sameBits(whole.value(), sum));
    }
}

TEST(ExactSum, ManyTermsSettleTheirCarries) {
    // 2^29 + 1 terms of 2^1000: past the limbs' settling interval and beyond a running sum's
    // precision relative to a small term added last.
    ExactSum s;
    const double big = std::ldexp(1.0, 1000);
    for (int i = 0; i < (1 << 29); ++i) s.add(i % 2 == 0 ? big : -big);
    s.add(3.0);
    EXPECT_TRUE(sameBits(s.value(), 3.0));
}

TEST(ExactSum, ParticleRangeSumIsTheSameForAnyThreadCount) {
    const ParticleRange range{17, 200017};
    auto term = [](Index a) { return std::sin(static_cast<double>(a)) * std::exp2(a % 60 - 30); };
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const double one = exactSum(range, term).value();
    omp_set_num_threads(2);
    const double two = exactSum(range, term).value();
    omp_set_num_threads(saved);
    EXPECT_TRUE(sameBits(one, two));
    // Two "processes" with a cut anywhere give the same bits.
    ExactSum first = exactSum(ParticleRange{17, 123457}, term);
    first.add(exactSum(ParticleRange{123457, 200017}, term));
    EXPECT_TRUE(sameBits(first.value(), one));
}

}  // namespace
}  // namespace gsph
