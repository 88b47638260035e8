// SPDX-License-Identifier: MIT
// The penalty contact of contact/penalty_contact.hpp: the force is the exact gradient of the
// contact energy (also with anisotropic cells, whose ellipsoids add a tangential part), pairs
// are equal and opposite, and the search finds exactly the pairs a brute-force loop finds.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/penalty_contact.hpp"
#include "neighbors/theta_search.hpp"
#include "spaces/metric.hpp"
#include "support/contact_fixtures.hpp"

namespace gsph {
namespace {

using testing::Box;

// Two blocks of anisotropic cells (1 × 2 × 1.5 mm and 2.5 × 1 × 1 mm), the second pushed
// 1 mm into the first and shifted sideways, so that many pairs overlap at odd angles.
struct Overlap {
    Reference ref;
    std::vector<Vec3> x;
    ContactShapes shapes;
    std::vector<double> k;
};

Overlap overlappingBlocks() {
    Overlap o;
    o.ref =
        testing::boxBodies({Box{Vec3::Zero(), Vec3(0.004, 0.008, 0.006), {4, 4, 4}},
                            Box{Vec3(0.003, 0.0013, 0.0007), Vec3(0.01, 0.004, 0.004), {4, 4, 4}}});
    buildPairs(o.ref);
    computeGeometry(o.ref);
    o.x = o.ref.X;
    o.shapes = contactShapes(o.ref, 1.0);
    o.k = contactStiffness(o.ref, std::vector<double>(o.x.size(), 3.4e7), 4.0);
    return o;
}

TEST(PenaltyContact, ForceIsTheGradientOfTheContactEnergy) {
    Overlap o = overlappingBlocks();
    PenaltyContact contact(o.ref, o.k, o.shapes, ContactOptions{});
    ASSERT_TRUE(contact.active());
    const std::size_t n = o.x.size();
    std::vector<Vec3> f(n, Vec3::Zero());
    std::vector<double> w2(n, 0.0);
    contact.addForces(o.x, f, w2);
    EXPECT_GT(contact.pairsInContact(), 10);
    const auto energy = [&](const std::vector<Vec3>& x) {
        std::vector<Vec3> scratch(n, Vec3::Zero());
        std::vector<double> s2(n, 0.0);
        return contact.addForces(x, scratch, s2);
    };
    // Central differences with a step of 1e-9 m (gaps are ~1e-4 m): truncation ~1e-10 of f.
    double worst = 0.0, largest = 0.0;
    for (std::size_t a = 0; a < n; ++a) {
        if (f[a].isZero(0.0)) continue;
        for (int d = 0; d < 3; ++d) {
            std::vector<Vec3> xp = o.x, xm = o.x;
            const double step = 1e-9;
            xp[a][d] += step;
            xm[a][d] -= step;
            const double numeric = -(energy(xp) - energy(xm)) / (2 * step);
            worst = std::max(worst, std::abs(numeric - f[a][d]));
            largest = std::max(largest, std::abs(f[a][d]));
        }
    }
    std::printf("[contact gradient] worst |f + ∂U/∂x| = %.2e of the largest force component\n",
                worst / largest);
    EXPECT_LT(worst, 1e-6 * largest);
    // Equal and opposite: the total force vanishes to round-off.
    Vec3 total = Vec3::Zero();
    for (const Vec3& fa : f) total += fa;
    EXPECT_LT(total.norm(), 1e-13 * largest);
}

TEST(PenaltyContact, SearchFindsThePairsABruteForceLoopFinds) {
    Overlap o = overlappingBlocks();
    PenaltyContact contact(o.ref, o.k, o.shapes, ContactOptions{});
    std::vector<Vec3> f(o.x.size(), Vec3::Zero());
    std::vector<double> w2(o.x.size(), 0.0);
    contact.addForces(o.x, f, w2);
    long brute = 0;
    for (std::size_t a = 0; a < o.x.size(); ++a)
        for (std::size_t b = a + 1; b < o.x.size(); ++b) {
            if (o.ref.body[a] == o.ref.body[b]) continue;
            const Vec3 d = o.x[a] - o.x[b];
            const Vec3 nrm = d.normalized();
            brute += d.norm() < o.shapes.radius(a, nrm) + o.shapes.radius(b, nrm);
        }
    EXPECT_EQ(contact.pairsInContact(), brute);
}

}  // namespace
}  // namespace gsph
