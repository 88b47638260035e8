// SPDX-License-Identifier: MIT
// Initial cracks (failure/brittle_bonds.hpp, breakBondsAcross): the bonds whose reference segment
// crosses a patch break, both directions of a pair alike, and no other; checked against a brute
// force segment–parallelogram test on a lattice.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "failure/brittle_bonds.hpp"
#include "reference/reference_builder.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

// Does the segment P → Q cross the parallelogram corner + s e1 + t e2 (s, t ∈ [0, 1])? A point on
// the plane counts on the side of e1 × e2.
bool crosses(const Vec3& P, const Vec3& Q, const CrackPatch& c) {
    const Vec3 n = c.edge1.cross(c.edge2);
    const double dp = (P - c.corner).dot(n), dq = (Q - c.corner).dot(n);
    if ((dp >= 0.0) == (dq >= 0.0)) return false;
    const Vec3 hit = P + (Q - P) * (dp / (dp - dq));
    const Vec3 r = hit - c.corner;
    const double e11 = c.edge1.squaredNorm(), e22 = c.edge2.squaredNorm(),
                 e12 = c.edge1.dot(c.edge2), det = e11 * e22 - e12 * e12;
    const double s = (r.dot(c.edge1) * e22 - r.dot(c.edge2) * e12) / det;
    const double t = (r.dot(c.edge2) * e11 - r.dot(c.edge1) * e12) / det;
    return s >= 0.0 && s <= 1.0 && t >= 0.0 && t <= 1.0;
}

TEST(CrackPatch, BreaksExactlyTheBondsThatCrossIt) {
    Reference ref =
        latticeReference(gradedBoxMap(Vec3(0.08, 0.08, 0.02), {}), 3, {8, 8, 2}, 7850.0, 1.2);
    completeReference(ref);
    // Half-way across the block in x, from y = 0 to the middle; off the lattice's planes.
    const CrackPatch patch{Vec3(0.0415, -0.01, -0.01), Vec3(0.0, 0.0505, 0.0),
                           Vec3(0.0, 0.0, 0.04)};
    std::vector<std::uint8_t> intact(static_cast<std::size_t>(ref.pairs.pairs()), 1);
    const Index broken = breakBondsAcross(ref, {patch}, intact);
    Index expected = 0;
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const Index b = ref.pairs.neighbor[static_cast<std::size_t>(k)];
            const bool cut = crosses(ref.X[static_cast<std::size_t>(a)],
                                     ref.X[static_cast<std::size_t>(b)], patch);
            EXPECT_EQ(intact[static_cast<std::size_t>(k)], cut ? 0 : 1) << a << " " << b;
            if (cut && a < b) ++expected;
        }
    std::printf("[crack patch] %d pairs broken\n", broken);
    EXPECT_GT(expected, 0);
    EXPECT_EQ(broken, expected);
}

}  // namespace
}  // namespace gsph
