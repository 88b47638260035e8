// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"
#include "neighbors/theta_search.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

// Lattice offsets o ≠ 0 with |o| < 2κ (the cubic spline's support in cells).
int stencilSize(int dim, double kappa) {
    const int m = static_cast<int>(std::ceil(2 * kappa));
    int count = 0;
    for (int i = -m; i <= m; ++i)
        for (int j = -m; j <= m; ++j)
            for (int k = (dim == 3 ? -m : 0); k <= (dim == 3 ? m : 0); ++k) {
                const double r2 = i * i + j * j + k * k;
                if (r2 > 0 && r2 < 4 * kappa * kappa * (1 - 1e-10)) ++count;
            }
    return count;
}

Reference box(int dim, std::array<int, 3> cells, double kappa) {
    return latticeReference(
        gradedBoxMap(Vec3(1, 1, 1),
                     {AxisGrading{AxisGrading::Kind::OneSided, 4.0}, AxisGrading{}, AxisGrading{}}),
        dim, cells, 1000.0, kappa);
}

TEST(ThetaSearch, InteriorParticlesSeeTheFullStencil) {
    for (double kappa : {0.8, 1.0, 1.2, 1.5}) {
        Reference ref = box(3, {9, 9, 9}, kappa);
        buildPairs(ref);
        const Index centre = latticeIndex(ref.spaces[0].cells, 4, 4, 4);
        EXPECT_EQ(ref.pairs.end(centre) - ref.pairs.begin(centre), stencilSize(3, kappa))
            << "κ = " << kappa;
    }
    EXPECT_EQ(stencilSize(3, 1.2), 56);  // "about 55 neighbours"
    Reference ref2 = box(2, {9, 9, 1}, 1.2);
    buildPairs(ref2);
    const Index c2 = latticeIndex(ref2.spaces[0].cells, 4, 4, 0);
    EXPECT_EQ(ref2.pairs.end(c2) - ref2.pairs.begin(c2), stencilSize(2, 1.2));
}

TEST(ThetaSearch, PairsAreSymmetricSortedAndAntisymmetricInGradient) {
    Reference ref = box(3, {7, 6, 5}, 1.2);
    buildPairs(ref);
    std::set<std::pair<Index, Index>> pairs;
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            pairs.insert({a, ref.pairs.neighbor[static_cast<std::size_t>(k)]});
            if (k > ref.pairs.begin(a)) {
                EXPECT_LT(ref.pairs.neighbor[static_cast<std::size_t>(k - 1)],
                          ref.pairs.neighbor[static_cast<std::size_t>(k)]);
            }
        }
    for (const auto& [a, b] : pairs) {
        ASSERT_TRUE(pairs.count({b, a})) << a << " " << b;
        EXPECT_NE(a, b);
    }
    // ∇W_ab = −∇W_ba through the shared table.
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const Index b = ref.pairs.neighbor[static_cast<std::size_t>(k)];
            Index back = -1;
            for (Index q = ref.pairs.begin(b); q < ref.pairs.end(b); ++q)
                if (ref.pairs.neighbor[static_cast<std::size_t>(q)] == a) back = q;
            const Vec3 g1 = ref.pairs
                                .table[static_cast<std::size_t>(
                                    ref.pairs.kernelId[static_cast<std::size_t>(k)])]
                                .gradW;
            const Vec3 g2 = ref.pairs
                                .table[static_cast<std::size_t>(
                                    ref.pairs.kernelId[static_cast<std::size_t>(back)])]
                                .gradW;
            EXPECT_NEAR((g1 + g2).norm(), 0.0, 1e-15);
        }
}

TEST(ThetaSearch, CellListAndKdTreeGiveTheSamePairs) {
    for (const AnalyticMap& map :
         {gradedBoxMap(Vec3(1, 2, 1), {}), annulusMap(0.5, 1.0, 0.0, 2 * std::acos(-1.0), 0.3)}) {
        Reference a = latticeReference(map, 3, {6, 20, 5}, 1000.0, 1.2);
        Reference b = a;
        buildPairs(a, SearchMethod::CellList);
        buildPairs(b, SearchMethod::KdTree);
        EXPECT_EQ(a.pairs.offset, b.pairs.offset);
        EXPECT_EQ(a.pairs.neighbor, b.pairs.neighbor);
        EXPECT_EQ(a.pairs.kernelId, b.pairs.kernelId);
    }
}

TEST(ThetaSearch, PeriodicIndexClosesTheSpace) {
    // Full annulus: periodic in the angular index, so every particle has the full angular
    // neighbourhood; the sector of the same lattice does not.
    Reference ring = latticeReference(annulusMap(0.5, 1.0, 0.0, 2 * std::acos(-1.0), 0.3), 3,
                                      {9, 24, 9}, 1000.0, 1.2);
    Reference sector =
        latticeReference(annulusMap(0.5, 1.0, 0.0, 3.0, 0.3), 3, {9, 24, 9}, 1000.0, 1.2);
    ASSERT_TRUE(ring.spaces[0].periodic[1]);
    ASSERT_FALSE(sector.spaces[0].periodic[1]);
    buildPairs(ring);
    buildPairs(sector);
    const Index seam = latticeIndex(ring.spaces[0].cells, 4, 0, 4);  // first angular cell
    EXPECT_EQ(ring.pairs.end(seam) - ring.pairs.begin(seam), stencilSize(3, 1.2));
    EXPECT_LT(sector.pairs.end(seam) - sector.pairs.begin(seam), stencilSize(3, 1.2));
}

TEST(ThetaSearch, BodiesNeverShareAPair) {
    Reference ref = box(3, {6, 6, 6}, 1.2);
    for (std::size_t a = 0; a < ref.body.size(); ++a) ref.body[a] = a < ref.body.size() / 2 ? 0 : 1;
    buildPairs(ref);
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k)
            EXPECT_EQ(ref.body[static_cast<std::size_t>(a)],
                      ref.body[static_cast<std::size_t>(
                          ref.pairs.neighbor[static_cast<std::size_t>(k)])]);
}

TEST(ThetaSearch, RejectsInconsistentInput) {
    Reference ref = box(3, {4, 4, 4}, 1.2);
    ref.space[3] = 7;
    EXPECT_THROW(buildPairs(ref), InputError);
    Reference unsorted = box(3, {4, 4, 4}, 1.2);
    unsorted.body[0] = 1;
    EXPECT_THROW(buildPairs(unsorted), InputError);
    Reference empty;
    EXPECT_THROW(buildPairs(empty), InputError);
}

}  // namespace
}  // namespace gsph
