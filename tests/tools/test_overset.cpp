// SPDX-License-Identifier: MIT
// Overset in gsph-preproc on meshes built in code (DESIGN §6): the space map and its inverse,
// transient particles against a brute-force count with analytic θ and ω, hole cutting with
// aligned and non-aligned overlaps, priorities, and the errors of bad overset input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "conversion.hpp"
#include "core/error.hpp"
#include "overset_checks.hpp"
#include "synthetic_mesh.hpp"

namespace gsph::preproc {
namespace {

using test::MeshBuilder;

/// An axis-aligned Cartesian block: gmsh volume `tag`, cells of side h from `origin`. Its node
/// keys start at 1000·tag along x, so blocks never share nodes (never glue) unless asked to.
struct Box {
    int tag;
    Int3 cells;
    Vec3 origin;
    double h;
};

void addBox(MeshBuilder& builder, const Box& b) {
    const int offset = 1000 * b.tag;
    builder.addBlock(b.tag, b.cells, test::offsetKey({offset, 0, 0}),
                     [b, offset](const MeshBuilder::Key& k) {
                         return Vec3(b.origin[0] + b.h * (k[0] - offset), b.origin[1] + b.h * k[1],
                                     b.origin[2] + b.h * k[2]);
                     });
}

HexMesh boxes(const std::vector<Box>& list) {
    MeshBuilder builder(7);
    for (const Box& b : list) addBox(builder, b);
    return builder.build();
}

/// A coarse block (h = 1, x ∈ [0, 8]) and a fine one (h = ½) of 8×4×4 cells from x = x0.
HexMesh coarseAndFine(double x0) {
    return boxes({{1, {8, 2, 2}, Vec3::Zero(), 1.0}, {2, {8, 4, 4}, Vec3(x0, 0, 0), 0.5}});
}

double totalVolume(const ParticleFile& f) {
    double v = 0.0;
    for (double x : f.volume) v += x;
    return v;
}

TEST(SpaceMap, LocateInvertsThePeriodicAnnulusMapAndItsExtension) {
    // Four quarter blocks glue into one annulus space, periodic in j; r graded, z straight.
    constexpr int m = 3;
    MeshBuilder builder(5);
    for (int q = 0; q < 4; ++q) {
        builder.addBlock(
            q + 1, {4, m, 2},
            [q](int i, int j, int k) {
                return MeshBuilder::Key{i, (q * m + j) % (4 * m), k};
            },
            [](const MeshBuilder::Key& k) {
                const double r = 1.0 + 0.3 * k[0] + 0.02 * k[0] * k[0];
                const double phi = 2.0 * M_PI * k[1] / (4 * m);
                return Vec3(r * std::cos(phi), r * std::sin(phi), 0.4 * k[2] + 0.01 * k[0]);
            });
    }
    const HexMesh mesh = builder.build();
    const auto maps = test::spaceMapsOf(mesh);
    ASSERT_EQ(maps.size(), 1u);
    const SpaceMap& map = *maps[0];
    // The frame may order the axes differently: 4 radial, 4m around (periodic), 2 along z.
    Int3 sorted = map.cells();
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted, (Int3{2, 4, 4 * m}));
    int periodicAxes = 0;
    for (int d = 0; d < 3; ++d) periodicAxes += map.periodic()[d] ? 1 : 0;
    ASSERT_EQ(periodicAxes, 1);
    ASSERT_EQ(map.cells()[map.periodic()[0] ? 0 : map.periodic()[1] ? 1 : 2], 4 * m);
    // u up to 1.5 cells past the boundary along each open axis (≤ 2.2 cells away in all).
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto sample = [&] {
        Vec3 u;
        for (int d = 0; d < 3; ++d) {
            const double n = map.cells()[d];
            u[d] = map.periodic()[d] ? n * unit(rng) : -1.5 + (n + 3.0) * unit(rng);
        }
        return u;
    };
    double worst = 0.0;
    int outside = 0;
    for (int n = 0; n < 2000; ++n) {
        const Vec3 u = sample();
        const std::optional<SpaceLocation> loc = map.locate(map.position(u), 3.0);
        ASSERT_TRUE(loc) << u.transpose();
        Vec3 d = loc->u - u;
        for (int a = 0; a < 3; ++a) {
            if (map.periodic()[a]) d[a] -= 4 * m * std::round(d[a] / (4 * m));
        }
        worst = std::max(worst, d.norm());
        outside += loc->outside > 0.0 ? 1 : 0;
        EXPECT_GT(loc->detJ, 0.0);
    }
    EXPECT_LT(worst, 1e-10);
    EXPECT_GT(outside, 500) << "the sample reaches into the extension";
    // Beyond the extension nothing is found.
    const int open = map.periodic()[0] ? 1 : 0;
    Vec3 far = Vec3::Constant(0.5);
    far[open] = -2.5;
    EXPECT_FALSE(map.locate(map.position(far), 2.0));
    EXPECT_TRUE(map.locate(map.position(far), 2.6));
}

TEST(Overset, TransientsOfTwoAbuttingCartesianBlocksMatchBruteForce) {
    const HexMesh mesh = coarseAndFine(8.0);
    const Conversion c = convertHexMesh(mesh);
    const ParticleFile& f = c.particles;
    validateParticleFile(f);
    ASSERT_EQ(f.spaces.size(), 2u);
    ASSERT_EQ(f.size(), 32 + 128) << "abutting blocks: nothing is cut";
    EXPECT_NEAR(f.overset.kappa, 1.5, 0.0);
    const Vec3 origin[2] = {Vec3::Zero(), Vec3(8, 0, 0)};
    const double h[2] = {1.0, 0.5};
    const double reach = 3.0;  // 2κ with the default κ = 1.5
    const auto entries = test::entryOf(f);
    long expected = 0;
    for (Index b = 0; b < f.size(); ++b) {
        const Index s = 1 - f.space[b];
        const Vec3 u = (f.X[b] - origin[s]) / h[s];  // θ in the Cartesian space s (Δθ = 1)
        double nearest = INFINITY;
        for (Index a = 0; a < f.size(); ++a) {
            if (f.space[a] == s) nearest = std::min(nearest, (u - f.theta[a]).norm());
        }
        const auto it = entries.find({b, s});
        if (nearest >= reach) {
            EXPECT_EQ(it, entries.end()) << "particle " << b << " is not within reach";
            EXPECT_EQ(f.transient[b], 0);
            continue;
        }
        ++expected;
        ASSERT_NE(it, entries.end()) << "particle " << b << " should be transient in " << s;
        EXPECT_EQ(f.transient[b], 1);
        EXPECT_LE((f.overset.theta[it->second] - u).norm(), 1e-12);
        // DESIGN §3: ω = V_b / det(∂X/∂θ_s) = (h_b / h_s)³ between Cartesian spaces.
        const double ratio = std::pow(h[f.space[b]] / h[s], 3);
        EXPECT_NEAR(f.overset.omega[it->second], ratio, 1e-12 * ratio);
    }
    EXPECT_EQ(static_cast<long>(f.overset.size()), expected);
    // Fine particles reach 3 coarse cells: 5 fine columns of 16; coarse ones 1.5 fine cells:
    // one coarse column of 4.
    EXPECT_EQ(expected, 5 * 16 + 4);
    test::expectEntriesReproduceX(f, test::spaceMapsOf(mesh), 12.0);
    ASSERT_EQ(c.stats.transients.size(), 2u);
    EXPECT_EQ(c.stats.transients[0].space, 1);  // fine particles in the coarse space
    EXPECT_EQ(c.stats.transients[0].particles, 80);
    EXPECT_NEAR(c.stats.transients[0].maxExtrapolation, 2.25, 1e-12);
    EXPECT_EQ(c.stats.transients[1].particles, 4);
    EXPECT_NEAR(c.stats.transients[1].maxExtrapolation, 1.0, 1e-12);
}

TEST(Overset, AlignedOverlapCutsExactlyTheCoveredParticles) {
    // The fine block covers coarse cells 6 and 7 (x ∈ [6, 8]): their 8 particles are cut and
    // the kept volume is the union's, [0, 10] × [0, 2]².
    const HexMesh mesh = coarseAndFine(6.0);
    const Conversion c = convertHexMesh(mesh);
    const ParticleFile& f = c.particles;
    validateParticleFile(f);
    ASSERT_EQ(f.size(), 32 - 8 + 128);
    for (Index a = 0; a < f.size(); ++a) {
        if (f.space[a] == 0) {
            EXPECT_LT(f.X[a][0], 6.0) << "coarse particle " << a;
        }
    }
    EXPECT_NEAR(totalVolume(f), 40.0, 1e-10 * 40.0);
    ASSERT_EQ(c.stats.cuts.size(), 1u);
    const HoleCutReport& cut = c.stats.cuts[0];
    EXPECT_EQ(cut.space, 0);
    EXPECT_EQ(cut.by, 1);
    EXPECT_EQ(cut.particles, 8);
    EXPECT_NEAR(cut.volume, 8.0, 1e-12);
    EXPECT_NEAR(cut.gap, 0.0, 1e-12);
    EXPECT_NEAR(cut.doubleCounted, 0.0, 1e-12);
    // Lattice indices stay those of the full lattice: the cut cells are simply absent.
    for (Index a = 0; a < f.size(); ++a) {
        if (f.space[a] == 0) {
            EXPECT_LT(f.latticeIndex[a][0], 6);
        }
    }
    test::expectEntriesReproduceX(f, test::spaceMapsOf(mesh), 12.0);

    // A higher priority for the coarse block (gmsh volume 1) turns it round: 4 fine columns
    // of 16 go, the union stays.
    ConversionOptions coarseWins;
    coarseWins.priorities = {{"1", 1}};
    const Conversion d = convertHexMesh(mesh, coarseWins);
    EXPECT_EQ(d.particles.size(), 32 + 128 - 64);
    EXPECT_NEAR(totalVolume(d.particles), 40.0, 1e-10 * 40.0);
    ASSERT_EQ(d.stats.cuts.size(), 1u);
    EXPECT_EQ(d.stats.cuts[0].space, 1);
}

TEST(Overset, MisalignedOverlapReportsGapOrDoubleCount) {
    // Fine block from x = 6.25: coarse cell 6 (centre 6.5, inside) is cut, leaving x ∈ [6, 6.25]
    // uncovered: a gap of a quarter column, 0.25 × 2 × 2 = 1; the union is 10.25 × 2 × 2.
    Conversion c = convertHexMesh(coarseAndFine(6.25));
    ASSERT_EQ(c.stats.cuts.size(), 1u);
    EXPECT_EQ(c.stats.cuts[0].particles, 8);
    EXPECT_NEAR(c.stats.cuts[0].gap, 1.0, 1e-12);
    EXPECT_NEAR(c.stats.cuts[0].doubleCounted, 0.0, 1e-12);
    EXPECT_NEAR(totalVolume(c.particles), 41.0 - 1.0, 1e-10);
    // From x = 6.75: cell 6 (centre 6.5, outside) stays and overlaps the fine block by a
    // quarter column; the union is 10.75 × 2 × 2.
    c = convertHexMesh(coarseAndFine(6.75));
    EXPECT_EQ(c.stats.cuts[0].particles, 4);
    EXPECT_NEAR(c.stats.cuts[0].gap, 0.0, 1e-12);
    EXPECT_NEAR(c.stats.cuts[0].doubleCounted, 1.0, 1e-12);
    EXPECT_NEAR(totalVolume(c.particles), 43.0 + 1.0, 1e-10);
}

/// convertHexMesh must throw Error with a message holding `fault`.
template <class Error>
void expectError(const HexMesh& mesh, const ConversionOptions& options, const std::string& fault) {
    try {
        convertHexMesh(mesh, options);
        FAIL() << "no error for: " << fault;
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("synthetic.msh: ", 0), 0u) << what;
        EXPECT_NE(what.find(fault), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(Overset, ConflictingPrioritiesAreErrors) {
    // Same spacing, overlapping by one cell, no priority: undecided.
    const HexMesh same =
        boxes({{1, {4, 2, 2}, Vec3::Zero(), 1.0}, {2, {4, 2, 2}, Vec3(3, 0, 0), 1.0}});
    expectError<MeshError>(same, {}, "with the same priority and the same spacing");
    ConversionOptions decided;
    decided.priorities = {{"2", 5}};
    EXPECT_EQ(convertHexMesh(same, decided).particles.size(), 3 * 4 + 16);

    // One volume given two priorities (by tag and by its group's name).
    HexMesh grouped = same;
    grouped.volumeGroups = {{7, "plate", {1, 2}}};
    ConversionOptions twice;
    twice.priorities = {{"1", 1}, {"plate", 2}};
    expectError<InputError>(grouped, twice, "conflicting priorities");
    ConversionOptions unknown;
    unknown.priorities = {{"9", 1}};
    expectError<InputError>(grouped, unknown, "no gmsh volume 9");

    // Two blocks that glue into one space (shared nodes) with different priorities.
    MeshBuilder builder(3);
    const auto unit = [](const MeshBuilder::Key& k) { return Vec3(k[0], k[1], k[2]); };
    builder.addBlock(1, {2, 2, 2}, test::offsetKey({0, 0, 0}), unit);
    builder.addBlock(2, {2, 2, 2}, test::offsetKey({2, 0, 0}), unit);
    ConversionOptions split;
    split.priorities = {{"1", 1}};
    expectError<MeshError>(builder.build(), split, "glue into one generalized space");

    ConversionOptions kappa;
    kappa.oversetKappa = 0.0;
    expectError<InputError>(same, kappa, "overset kappa");
}

TEST(Overset, SpaceCoveredEntirelyIsAnError) {
    const HexMesh inside =
        boxes({{1, {2, 2, 2}, Vec3(1, 1, 1), 1.0}, {2, {8, 8, 8}, Vec3::Zero(), 0.5}});
    expectError<MeshError>(inside, {}, "lies entirely inside");
}

TEST(Overset, TransientInAFoldedExtensionIsAnError) {
    // Block B's only cell is a trapezoid whose sides, extended back past its face x = 1, cross
    // at x = ½: beyond, its map folds. Block A's particle at x = ¼ is within reach of B's
    // particle, but only through the fold (det ∂X/∂θ < 0): it cannot get θ in B.
    MeshBuilder builder(9);
    builder.addBlock(1, {2, 1, 1}, test::offsetKey({0, 0, 0}),
                     [](const MeshBuilder::Key& k) { return Vec3(0.5 * k[0], k[1], k[2]); });
    builder.addBlock(2, {1, 1, 1}, test::offsetKey({1000, 0, 0}), [](const MeshBuilder::Key& k) {
        const int i = k[0] - 1000;
        const double y = i == 0 ? k[1] : (k[1] == 0 ? -1.0 : 2.0);
        return Vec3(1.0 + i, y, k[2]);
    });
    expectError<MeshError>(builder.build(), {}, "folds");
    // The error names the particle's hex and both spaces by their gmsh volumes.
    expectError<MeshError>(builder.build(), {}, "(gmsh element ");
    expectError<MeshError>(builder.build(), {}, "of space 0 of body 0 (gmsh volume 1)");
    expectError<MeshError>(builder.build(), {}, "support of space 1 of body 0 (gmsh volume 2)");

    // On the fold line itself (x = ½) ∂X/∂θ of B's extension is singular and Newton stalls.
    MeshBuilder onFold(9);
    onFold.addBlock(1, {1, 1, 1}, test::offsetKey({0, 0, 0}),
                    [](const MeshBuilder::Key& k) { return Vec3(0.25 + 0.5 * k[0], k[1], k[2]); });
    onFold.addBlock(2, {1, 1, 1}, test::offsetKey({1000, 0, 0}), [](const MeshBuilder::Key& k) {
        const int i = k[0] - 1000;
        const double y = i == 0 ? k[1] : (k[1] == 0 ? -1.0 : 2.0);
        return Vec3(1.0 + i, y, k[2]);
    });
    expectError<MeshError>(onFold.build(), {}, "cannot be located there: the Newton iterations");
}

TEST(Overset, BlockCollapsedOntoAnAxisIsRefused) {
    // A quarter cylinder as one block in (r, φ, z): the nodes at r = 0 coincide, so the hexes
    // next to the axis have collapsed edges there.
    MeshBuilder builder(4);
    builder.addBlock(1, {3, 3, 2}, test::offsetKey({0, 0, 0}), [](const MeshBuilder::Key& k) {
        const double r = k[0], phi = 0.5 * M_PI * k[1] / 3.0;
        return Vec3(r * std::cos(phi), r * std::sin(phi), k[2]);
    });
    expectError<MeshError>(builder.build(), {}, "collapses onto a line or point");
}

}  // namespace
}  // namespace gsph::preproc
