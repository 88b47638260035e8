// SPDX-License-Identifier: MIT
// Space gluing (DESIGN §2): blocks whose indices glue form one space (periodic when the blocks
// close on themselves); the rest are spaces of their own. Every glued space is checked against
// the mesh: each lattice cell holds one hex, and neighbouring cells hold face neighbours.
#include <gtest/gtest.h>

#include <cmath>

#include "block_indexing.hpp"
#include "space_gluing.hpp"
#include "synthetic_mesh.hpp"

namespace gsph::preproc {
namespace {

using test::MeshBuilder;

Vec3 unitPosition(const MeshBuilder::Key& k) {
    return Vec3(k[0], k[1], k[2]);
}

struct Glued {
    HexMesh mesh;
    std::vector<BlockLattice> blocks;
    GluingResult result;
};

Glued glue(HexMesh mesh, std::vector<Index> bodies = {}) {
    Glued g{std::move(mesh), {}, {}};
    const NodeHexAdjacency adjacency(static_cast<Index>(g.mesh.nodes.size()), g.mesh.hexes);
    for (const HexVolume& v : g.mesh.volumes) g.blocks.push_back(indexBlock(g.mesh, v, adjacency));
    if (bodies.empty()) bodies.assign(g.blocks.size(), 0);
    g.result = glueBlocks(g.blocks, bodies);
    return g;
}

int sharedNodes(const std::array<Index, 8>& a, const std::array<Index, 8>& b) {
    int n = 0;
    for (Index x : a) n += std::count(b.begin(), b.end(), x) > 0 ? 1 : 0;
    return n;
}

/// Each cell of the space holds one hex; cells adjacent along any axis (across the seam of a
/// periodic axis too) hold hexes that share a face.
void expectConsistentSpace(const Glued& g, const GluedSpace& space) {
    const Int3 n = space.cells;
    std::vector<Index> hexAt(static_cast<std::size_t>(n[0]) * n[1] * n[2], -1);
    for (std::size_t e = 0; e < space.blocks.size(); ++e) {
        const BlockLattice& b = g.blocks[space.blocks[e]];
        for (int k = 0; k < b.cells[2]; ++k) {
            for (int j = 0; j < b.cells[1]; ++j) {
                for (int i = 0; i < b.cells[0]; ++i) {
                    const Int3 c = space.cellOf(e, {i, j, k});
                    for (int d = 0; d < 3; ++d) ASSERT_TRUE(c[d] >= 0 && c[d] < n[d]);
                    Index& slot = hexAt[c[0] + n[0] * (c[1] + n[1] * c[2])];
                    ASSERT_EQ(slot, -1) << "cell used twice";
                    slot = b.hex(i, j, k);
                }
            }
        }
    }
    for (Index h : hexAt) ASSERT_GE(h, 0) << "cell left empty";
    for (int k = 0; k < n[2]; ++k) {
        for (int j = 0; j < n[1]; ++j) {
            for (int i = 0; i < n[0]; ++i) {
                const Int3 c = {i, j, k};
                for (int d = 0; d < 3; ++d) {
                    Int3 next = c;
                    if (++next[d] == n[d]) {
                        if (!space.periodic[d]) continue;
                        next[d] = 0;
                    }
                    const Index a = hexAt[c[0] + n[0] * (c[1] + n[1] * c[2])];
                    const Index b = hexAt[next[0] + n[0] * (next[1] + n[1] * next[2])];
                    EXPECT_EQ(sharedNodes(g.mesh.hexes[a], g.mesh.hexes[b]), 4)
                        << "cells " << i << "," << j << "," << k << " and the next along " << d;
                }
            }
        }
    }
}

TEST(SpaceGluing, StackedBoxesFormOneSpace) {
    MeshBuilder builder;
    builder.addBlock(1, {2, 3, 2}, test::offsetKey({0, 0, 0}), unitPosition);
    builder.addBlock(2, {3, 3, 2}, test::offsetKey({2, 0, 0}), unitPosition);
    const Glued g = glue(builder.build());
    ASSERT_EQ(g.result.spaces.size(), 1u);
    EXPECT_EQ(g.result.spaces[0].cells, (Int3{5, 3, 2}));
    EXPECT_EQ(g.result.spaces[0].periodic, (std::array<bool, 3>{false, false, false}));
    EXPECT_EQ(g.result.sharedFaces, 1);
    EXPECT_EQ(g.result.honouredFaces, 1);
    expectConsistentSpace(g, g.result.spaces[0]);
}

TEST(SpaceGluing, DifferentBodiesNeverGlue) {
    MeshBuilder builder;
    builder.addBlock(1, {2, 3, 2}, test::offsetKey({0, 0, 0}), unitPosition);
    builder.addBlock(2, {3, 3, 2}, test::offsetKey({2, 0, 0}), unitPosition);
    const Glued g = glue(builder.build(), {0, 1});
    ASSERT_EQ(g.result.spaces.size(), 2u);
    EXPECT_EQ(g.result.spaces[0].body, 0);
    EXPECT_EQ(g.result.spaces[1].body, 1);
    EXPECT_EQ(g.result.sharedFaces, 0);
}

TEST(SpaceGluing, PartlySharedSideGivesTwoSpaces) {
    MeshBuilder builder;
    builder.addBlock(1, {2, 4, 2}, test::offsetKey({0, 0, 0}), unitPosition);
    builder.addBlock(2, {2, 2, 2}, test::offsetKey({2, 0, 0}), unitPosition);  // half of A's side
    const Glued g = glue(builder.build());
    ASSERT_EQ(g.result.spaces.size(), 2u);
    EXPECT_EQ(g.result.sharedFaces, 0);
}

TEST(SpaceGluing, GridOfBlocksFormsOneSpace) {
    // 3×3×2 blocks of 2×3×1 cells each: one 6×9×2 space.
    MeshBuilder builder;
    int tag = 1;
    for (int c = 0; c < 2; ++c) {
        for (int b = 0; b < 3; ++b) {
            for (int a = 0; a < 3; ++a) {
                builder.addBlock(tag++, {2, 3, 1}, test::offsetKey({2 * a, 3 * b, c}),
                                 unitPosition);
            }
        }
    }
    const Glued g = glue(builder.build());
    ASSERT_EQ(g.result.spaces.size(), 1u);
    EXPECT_EQ(g.result.spaces[0].cells, (Int3{6, 9, 2}));
    EXPECT_EQ(g.result.honouredFaces, g.result.sharedFaces);
    expectConsistentSpace(g, g.result.spaces[0]);
}

TEST(SpaceGluing, LShapeKeepsOnePairTogether) {
    MeshBuilder builder;
    builder.addBlock(1, {2, 2, 1}, test::offsetKey({0, 0, 0}), unitPosition);
    builder.addBlock(2, {2, 2, 1}, test::offsetKey({2, 0, 0}), unitPosition);
    builder.addBlock(3, {2, 2, 1}, test::offsetKey({0, 2, 0}), unitPosition);
    const Glued g = glue(builder.build());
    ASSERT_EQ(g.result.spaces.size(), 2u);
    EXPECT_EQ(g.result.sharedFaces, 2);
    EXPECT_EQ(g.result.honouredFaces, 1);
    for (const GluedSpace& s : g.result.spaces) expectConsistentSpace(g, s);
}

TEST(SpaceGluing, TurnedBlockStillGlues) {
    // Turn the second block's frame by every rotation: the glued space must not change shape.
    MeshBuilder builder;
    builder.addBlock(1, {2, 3, 2}, test::offsetKey({0, 0, 0}), unitPosition);
    builder.addBlock(2, {3, 3, 2}, test::offsetKey({2, 0, 0}), unitPosition);
    Glued base = glue(builder.build());
    for (const SignedPermutation& R : SignedPermutation::rotations()) {
        Glued g = base;
        reorientBlock(g.blocks[1], R);
        g.result = glueBlocks(g.blocks, {0, 0});
        ASSERT_EQ(g.result.spaces.size(), 1u);
        EXPECT_EQ(g.result.spaces[0].cells, (Int3{5, 3, 2}));
        expectConsistentSpace(g, g.result.spaces[0]);
    }
}

/// O-grid section extruded along z: a core of n×n cells covering [-c, c]², and 4 annulus
/// blocks of nr (radial) × n (angular) cells out to radius R. Node keys are shared on block
/// faces, so the blocks are conforming.
void addOgrid(MeshBuilder& builder, int n, int nr, int nz, bool withCore, int segment = 0) {
    const int k0 = segment * nz, tag0 = 5 * segment;
    const double c = 0.4, R = 1.0;
    auto corePoint = [=](int i, int j) {
        return Vec3(-c + 2 * c * i / n, -c + 2 * c * j / n, 0.0);
    };
    // Core boundary, counterclockwise from (c, -c), at angular parameter a ∈ [0, 4n).
    auto boundaryKey = [=](int a) {
        const int q = a / n, t = a % n;
        const int ij[4][2] = {{n, t}, {n - t, n}, {0, n - t}, {t, 0}};
        return std::array<int, 2>{ij[q][0], ij[q][1]};
    };
    auto key = [=](int q) {
        return [=](int r, int t, int k) {
            const int a = (q * n + t) % (4 * n);
            if (r == 0) {
                const auto ij = boundaryKey(a);
                return MeshBuilder::Key{ij[0], ij[1], k0 + k};
            }
            return MeshBuilder::Key{1000 + r, a, k0 + k};
        };
    };
    auto position = [=](const MeshBuilder::Key& k) {
        if (k[0] < 1000) return Vec3(corePoint(k[0], k[1]) + Vec3(0, 0, 0.1 * k[2]));
        const int r = k[0] - 1000, a = k[1];
        const auto ij = boundaryKey(a);
        const double phi = -M_PI / 4 + 2 * M_PI * a / (4.0 * n), s = double(r) / nr;
        const Vec3 inner = corePoint(ij[0], ij[1]);
        const Vec3 outer(R * std::cos(phi), R * std::sin(phi), 0.0);
        return Vec3((1 - s) * inner + s * outer + Vec3(0, 0, 0.1 * k[2]));
    };
    if (withCore) {
        builder.addBlock(
            tag0 + 1, {n, n, nz},
            [=](int i, int j, int k) {
                return MeshBuilder::Key{i, j, k0 + k};
            },
            position);
    }
    for (int q = 0; q < 4; ++q) builder.addBlock(tag0 + 2 + q, {nr, n, nz}, key(q), position);
}

TEST(SpaceGluing, AnnulusClosesIntoAPeriodicSpace) {
    MeshBuilder builder(5);
    addOgrid(builder, 3, 2, 2, false);
    const Glued g = glue(builder.build());
    ASSERT_EQ(g.result.spaces.size(), 1u);
    const GluedSpace& ring = g.result.spaces[0];
    EXPECT_EQ(ring.blocks.size(), 4u);
    EXPECT_EQ(g.result.sharedFaces, 4);
    EXPECT_EQ(g.result.honouredFaces, 4);
    int periodicAxes = 0;
    for (int d = 0; d < 3; ++d) {
        if (ring.periodic[d]) {
            ++periodicAxes;
            EXPECT_EQ(ring.cells[d], 12);  // 4 quarters × 3 angular cells
        }
    }
    EXPECT_EQ(periodicAxes, 1);
    expectConsistentSpace(g, ring);
}

TEST(SpaceGluing, OgridCoreStaysApartFromThePeriodicAnnulus) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
        MeshBuilder builder(seed);
        addOgrid(builder, 4, 2, 3, true);
        const Glued g = glue(builder.build());
        ASSERT_EQ(g.result.spaces.size(), 2u);
        const GluedSpace& core = g.result.spaces[0];
        const GluedSpace& ring = g.result.spaces[1];
        EXPECT_EQ(core.blocks, std::vector<Index>{0});
        EXPECT_EQ(core.cells, (Int3{4, 4, 3}));
        EXPECT_EQ(core.periodic, (std::array<bool, 3>{false, false, false}));
        EXPECT_EQ(ring.blocks.size(), 4u);
        EXPECT_EQ(std::count(ring.periodic.begin(), ring.periodic.end(), true), 1);
        EXPECT_EQ(g.result.sharedFaces, 8);
        EXPECT_EQ(g.result.honouredFaces, 4);
        EXPECT_TRUE(g.result.exhaustive);
        expectConsistentSpace(g, core);
        expectConsistentSpace(g, ring);
    }
}

TEST(SpaceGluing, StackedOgridsGlueIntoACoreAndAnAnnulus) {
    // An O-grid cylinder cut along its axis into segments (5 blocks each, as a user grading the
    // rod in segments would build it): the cores stack into one space, the annulus blocks into
    // one periodic space; only the core–annulus faces stay interfaces.
    for (int segments : {3, 10}) {
        MeshBuilder builder(2);
        for (int s = 0; s < segments; ++s) addOgrid(builder, 2, 1, 1, true, s);
        const Glued g = glue(builder.build());
        ASSERT_EQ(g.result.spaces.size(), 2u) << segments << " segments";
        EXPECT_EQ(g.result.spaces[0].cells, (Int3{2, 2, segments}));
        EXPECT_EQ(g.result.spaces[0].blocks.size(), static_cast<std::size_t>(segments));
        EXPECT_EQ(g.result.spaces[1].blocks.size(), static_cast<std::size_t>(4 * segments));
        EXPECT_EQ(g.result.sharedFaces, 8 * segments + 5 * (segments - 1));
        EXPECT_EQ(g.result.honouredFaces, g.result.sharedFaces - 4 * segments);
        EXPECT_TRUE(g.result.exhaustive) << segments << " segments";
        for (const GluedSpace& s : g.result.spaces) expectConsistentSpace(g, s);
    }
}

}  // namespace
}  // namespace gsph::preproc
