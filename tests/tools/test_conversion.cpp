// SPDX-License-Identifier: MIT
// Hex mesh → particles on meshes built in code: layout, positions, volumes, bodies, sets, errors.
#include <gtest/gtest.h>

#include <cmath>

#include "conversion.hpp"
#include "core/error.hpp"
#include "hex_geometry.hpp"
#include "hex_topology.hpp"
#include "particle_checks.hpp"
#include "synthetic_mesh.hpp"

namespace gsph::preproc {
namespace {

using test::MeshBuilder;

Vec3 graded(const MeshBuilder::Key& k) {
    return Vec3(std::pow(1.2, k[0]) + 0.1 * k[1], 0.5 * k[1] + 0.05 * k[0] * k[2], 0.3 * k[2]);
}

/// Two bodies: a 2-block bar (volumes 1, 2: body "bar") and a separate box (volume 3: "box").
HexMesh twoBodies() {
    MeshBuilder builder(11);
    builder.addBlock(3, {2, 2, 2}, test::offsetKey({20, 0, 0}), graded);
    builder.addBlock(1, {3, 2, 2}, test::offsetKey({0, 0, 0}), graded);
    builder.addBlock(2, {4, 2, 2}, test::offsetKey({3, 0, 0}), graded);
    HexMesh& raw = builder.raw();
    std::sort(raw.volumes.begin(), raw.volumes.end(),
              [](const HexVolume& a, const HexVolume& b) { return a.tag < b.tag; });
    raw.volumeGroups = {{10, "bar", {1, 2}}, {20, "box", {3}}};
    // Surface group "end": the bar's face at key x = 0 (2×2 quads); unnamed group 7: the box's
    // face at key x = 22.
    SurfaceGroup end{5, "end", {}}, far{7, "", {}};
    for (int k = 0; k < 2; ++k) {
        for (int j = 0; j < 2; ++j) {
            end.quads.push_back({builder.nodeOf({0, j, k}), builder.nodeOf({0, j + 1, k}),
                                 builder.nodeOf({0, j + 1, k + 1}), builder.nodeOf({0, j, k + 1})});
            far.quads.push_back({builder.nodeOf({22, j, k}), builder.nodeOf({22, j + 1, k}),
                                 builder.nodeOf({22, j + 1, k + 1}),
                                 builder.nodeOf({22, j, k + 1})});
        }
    }
    raw.surfaceGroups = {end, far};
    return builder.build();
}

TEST(Conversion, LayoutPositionsVolumesBodiesSets) {
    const HexMesh mesh = twoBodies();
    const Conversion conv = convertHexMesh(mesh);
    const ParticleFile& f = conv.particles;
    ASSERT_EQ(f.size(), 12 + 16 + 8);
    test::expectLatticeLayout(f);
    validateParticleFile(f);

    ASSERT_EQ(f.spaces.size(), 2u);
    EXPECT_EQ(f.spaces[0].cells, (Int3{7, 2, 2}));  // volumes 1 + 2 glued
    EXPECT_EQ(f.spaces[1].cells, (Int3{2, 2, 2}));
    ASSERT_EQ(f.bodies.size(), 2u);
    EXPECT_EQ(f.bodies[0].name, "bar");
    EXPECT_EQ(f.bodies[0].sourceTag, 10);
    EXPECT_EQ(f.bodies[1].name, "box");
    EXPECT_EQ(f.body.front(), 0);
    EXPECT_EQ(f.body.back(), 1);
    EXPECT_EQ(conv.stats.spaceVolumes, (std::vector<std::vector<int>>{{1, 2}, {3}}));

    // Every particle is the centre of one hex (mean of its nodes in any order), with that hex's
    // volume; matched by nearest centre, which is unique here.
    std::vector<char> used(mesh.hexes.size(), 0);
    double total = 0.0, expectedTotal = 0.0;
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
        HexCorners x;
        for (int c = 0; c < 8; ++c) x[c] = mesh.nodes[mesh.hexes[h][kGmshCorner[c]]];
        expectedTotal += hexVolume(x);
    }
    for (Index a = 0; a < f.size(); ++a) {
        std::size_t best = 0;
        double bestDistance = INFINITY;
        Vec3 mean;
        for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
            Vec3 m = Vec3::Zero();
            for (Index n : mesh.hexes[h]) m += mesh.nodes[n] / 8.0;
            if ((m - f.X[a]).norm() < bestDistance) {
                bestDistance = (m - f.X[a]).norm();
                best = h;
                mean = m;
            }
        }
        EXPECT_LT(bestDistance, 1e-14);
        EXPECT_EQ(used[best]++, 0);
        HexCorners x;
        for (int c = 0; c < 8; ++c) x[c] = mesh.nodes[mesh.hexes[best][kGmshCorner[c]]];
        EXPECT_NEAR(f.volume[a], hexVolume(x), 1e-14 * hexVolume(x));
        total += f.volume[a];
    }
    EXPECT_NEAR(total, expectedTotal, 1e-13 * expectedTotal);

    // Sets: the bar's end face is lattice i = 0 of space 0; the unnamed group gets its tag.
    ASSERT_EQ(f.sets.count("end"), 1u);
    const auto& end = f.sets.at("end");
    ASSERT_EQ(end.size(), 4u);
    for (Index a : end) {
        EXPECT_EQ(f.space[a], 0);
        EXPECT_EQ(f.latticeIndex[a][0], 0);
    }
    ASSERT_EQ(f.sets.count("surface_7"), 1u);
    EXPECT_EQ(f.sets.at("surface_7").size(), 4u);
    for (Index a : f.sets.at("surface_7")) EXPECT_EQ(f.body[a], 1);
    EXPECT_TRUE(conv.warnings.empty());
}

// --lattice on a box body meshed with graded cells and a second, separate box: the lattice
// tiles each box exactly (spacing adjusted per axis), one Cartesian space per body, and a face
// group's set is the lattice layer on that face.
TEST(Conversion, UniformLatticeTilesBoxBodies) {
    MeshBuilder builder(5);
    const auto gradedBox = [](const MeshBuilder::Key& k) {  // [0, 3] × [0, 1] × [0, 2], graded
        return Vec3(3.0 * std::pow(k[0] / 3.0, 1.3), 0.5 * k[1], std::pow(k[2] / 2.0, 0.8) * 2.0);
    };
    builder.addBlock(1, {3, 2, 2}, test::offsetKey({0, 0, 0}), gradedBox);
    builder.addBlock(2, {1, 1, 1}, test::offsetKey({10, 0, 0}), [](const MeshBuilder::Key& k) {
        return Vec3(5.0 + 0.1 * (k[0] - 10), 0.1 * k[1], 0.1 * k[2]);  // [5, 5.1] × [0, 0.1]²
    });
    HexMesh& raw = builder.raw();
    raw.volumeGroups = {{10, "bar", {1}}, {20, "cube", {2}}};
    SurfaceGroup end{5, "end", {}};
    for (int k = 0; k < 2; ++k) {
        for (int j = 0; j < 2; ++j) {
            end.quads.push_back({builder.nodeOf({0, j, k}), builder.nodeOf({0, j + 1, k}),
                                 builder.nodeOf({0, j + 1, k + 1}), builder.nodeOf({0, j, k + 1})});
        }
    }
    raw.surfaceGroups = {end};
    ConversionOptions options;
    options.latticeSpacing = 0.26;  // → 12 × 4 × 8 cells of 0.25 on the bar, 1 cell on the cube
    const Conversion conv = convertHexMesh(builder.build(), options);
    const ParticleFile& f = conv.particles;
    validateParticleFile(f);
    test::expectLatticeLayout(f);
    ASSERT_EQ(f.spaces.size(), 2u);
    EXPECT_EQ(f.spaces[0].cells, (Int3{12, 4, 8}));
    EXPECT_EQ(f.spaces[1].cells, (Int3{1, 1, 1}));
    ASSERT_EQ(f.size(), 12 * 4 * 8 + 1);
    double barVolume = 0.0;
    for (Index a = 0; a < f.size(); ++a) {
        if (f.body[a] != 0) continue;
        const auto& c = f.latticeIndex[a];
        EXPECT_LT(
            (f.X[a] - Vec3(0.25 * (c[0] + 0.5), 0.25 * (c[1] + 0.5), 0.25 * (c[2] + 0.5))).norm(),
            1e-14);
        EXPECT_EQ(f.theta[a], Vec3(c[0] + 0.5, c[1] + 0.5, c[2] + 0.5));
        barVolume += f.volume[a];
    }
    EXPECT_NEAR(barVolume, 6.0, 1e-13);
    EXPECT_LT((f.X.back() - Vec3(5.05, 0.05, 0.05)).norm(), 1e-14);
    EXPECT_NEAR(f.volume.back(), 1e-3, 1e-17);
    ASSERT_EQ(conv.stats.lattice.size(), 2u);
    EXPECT_NEAR(conv.stats.lattice[0].meshVolume, 6.0, 1e-13);
    const auto& members = f.sets.at("end");
    ASSERT_EQ(members.size(), 4u * 8u);
    for (Index a : members) EXPECT_EQ(f.latticeIndex[a][0], 0);

    options.latticeSpacing = -1.0;
    EXPECT_THROW(convertHexMesh(builder.build(), options), InputError);
}

TEST(Conversion, NoGroupsMeansOneBody) {
    HexMesh mesh = twoBodies();
    mesh.volumeGroups.clear();
    const Conversion conv = convertHexMesh(mesh);
    ASSERT_EQ(conv.particles.bodies.size(), 1u);
    EXPECT_EQ(conv.particles.bodies[0].sourceTag, -1);
    for (Index b : conv.particles.body) EXPECT_EQ(b, 0);
}

void expectMeshError(const HexMesh& mesh, const std::string& fault) {
    try {
        convertHexMesh(mesh);
        FAIL() << "no error for: " << fault;
    } catch (const MeshError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("synthetic.msh: ", 0), 0u) << what;
        EXPECT_NE(what.find(fault), std::string::npos) << what;
    }
}

TEST(Conversion, BadGroupsAreErrors) {
    HexMesh mesh = twoBodies();
    mesh.volumeGroups = {{10, "bar", {1, 2}}};
    expectMeshError(mesh, "volume 3 is in no physical volume group");
    mesh.volumeGroups = {{10, "bar", {1, 2}}, {20, "box", {3, 2}}};
    expectMeshError(mesh, "volume 2 is in two physical volume groups");
    mesh.volumeGroups = {{10, "bar", {1, 2, 3}}, {20, "ghost", {99}}};
    expectMeshError(mesh, "physical volume 'ghost' holds no hexahedra");
    mesh = twoBodies();
    mesh.surfaceGroups[0].quads.push_back({0, 1, 2, 3});  // not a hex face
    expectMeshError(mesh, "not a face of any hexahedron");
}

TEST(Conversion, InvertedAndEmptyMeshesAreErrors) {
    HexMesh mesh = twoBodies();
    auto& h = mesh.hexes[5];
    std::swap_ranges(h.begin(), h.begin() + 4, h.begin() + 4);  // bottom ↔ top: mirrored
    expectMeshError(mesh, "is inverted");
    HexMesh empty;
    empty.source = "synthetic.msh";
    expectMeshError(empty, "no hexahedra");
}

}  // namespace
}  // namespace gsph::preproc
