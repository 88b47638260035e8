// SPDX-License-Identifier: MIT
// Columns of rows read into strips (core/lanes.hpp loadColumns): at every strip width, lane j of
// column k is exactly element (index[j], first + k) of the table, for rows in any order and
// repeated rows; the wide widths also inside their instruction-set targets, as the kernels use
// them.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "core/lanes.hpp"

namespace gsph {
namespace {

constexpr std::size_t kRow = 40;

template <class L>
[[gnu::always_inline]] inline int mismatches(const std::vector<double>& table,
                                             const std::int32_t* index) {
    constexpr int W = kLanesOf<L>;
    int wrong = 0;
    for (std::size_t first = 0; first < kRow; first += W) {
        L column[W];
        loadColumns<L>(table.data(), kRow, index, first, column);
        for (int k = 0; k < W; ++k)
            for (int j = 0; j < W; ++j)
                wrong += column[k][j] != table[static_cast<std::size_t>(index[j]) * kRow + first +
                                               static_cast<std::size_t>(k)];
    }
    leaveLanes<L>();
    return wrong;
}

int mismatches2(const std::vector<double>& t, const std::int32_t* i) {
    return mismatches<Lanes2>(t, i);
}
int mismatches4(const std::vector<double>& t, const std::int32_t* i) {
    return mismatches<Lanes4>(t, i);
}
int mismatches8(const std::vector<double>& t, const std::int32_t* i) {
    return mismatches<Lanes8>(t, i);
}
GSPH_AVX2_TARGET int mismatches4Avx2(const std::vector<double>& t, const std::int32_t* i) {
    return mismatches<Lanes4>(t, i);
}
GSPH_AVX512_TARGET int mismatches8Avx512(const std::vector<double>& t, const std::int32_t* i) {
    return mismatches<Lanes8>(t, i);
}

TEST(Lanes, LoadColumnsTransposesRowsExactlyAtEveryWidth) {
    const int rows = 13;
    std::vector<double> table(static_cast<std::size_t>(rows) * kRow);
    for (std::size_t e = 0; e < table.size(); ++e) table[e] = 1.0 + static_cast<double>(e) / 7.0;
    const std::int32_t index[8] = {12, 3, 3, 0, 7, 11, 5, 9};  // any order, a row twice
    EXPECT_EQ(mismatches2(table, index), 0);
    EXPECT_EQ(mismatches4(table, index), 0);
    EXPECT_EQ(mismatches8(table, index), 0);
    if (laneWidth() >= 4) {
        EXPECT_EQ(mismatches4Avx2(table, index), 0);
    }
    if (laneWidth() >= 8) {
        EXPECT_EQ(mismatches8Avx512(table, index), 0);
    }
}

}  // namespace
}  // namespace gsph
