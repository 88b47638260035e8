// SPDX-License-Identifier: MIT
// Block indexing (DESIGN §2): (i,j,k) recovered from connectivity alone, whatever the node ids,
// the hex order and each hex's local node order; non-structured blocks are refused.
#include <gtest/gtest.h>

#include <cmath>

#include "block_indexing.hpp"
#include "core/error.hpp"
#include "hex_geometry.hpp"
#include "synthetic_mesh.hpp"

namespace gsph::preproc {
namespace {

using test::MeshBuilder;

Vec3 boxPosition(const MeshBuilder::Key& k) {
    return Vec3(1.0 * k[0], 2.0 * k[1], 3.0 * k[2]);
}

BlockLattice indexOnly(const HexMesh& mesh) {
    const NodeHexAdjacency adjacency(static_cast<Index>(mesh.nodes.size()), mesh.hexes);
    return indexBlock(mesh, mesh.volumes.at(0), adjacency);
}

HexCorners cornersOf(const HexMesh& mesh, const BlockLattice& b, int i, int j, int k) {
    HexCorners x;
    for (int c = 0; c < 8; ++c)
        x[c] = mesh.nodes[b.node(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1))];
    return x;
}

TEST(BlockIndexing, ShuffledBoxGivesItsLattice) {
    for (unsigned seed = 1; seed <= 6; ++seed) {
        MeshBuilder builder(seed);
        builder.addBlock(7, {3, 4, 5}, test::offsetKey({0, 0, 0}), boxPosition);
        const HexMesh mesh = builder.build();
        const BlockLattice b = indexOnly(mesh);
        ASSERT_EQ(b.cells, (Int3{3, 4, 5})) << "seed " << seed;
        EXPECT_EQ(b.volumeTag, 7);
        for (int k = 0; k <= 5; ++k) {
            for (int j = 0; j <= 4; ++j) {
                for (int i = 0; i <= 3; ++i) {
                    EXPECT_NEAR((mesh.nodes[b.node(i, j, k)] - boxPosition({i, j, k})).norm(), 0.0,
                                1e-15);
                }
            }
        }
        // Every cell holds the hex whose nodes are its corners.
        for (int k = 0; k < 5; ++k) {
            for (int j = 0; j < 4; ++j) {
                for (int i = 0; i < 3; ++i) {
                    auto expected = mesh.hexes[b.hex(i, j, k)];
                    std::array<Index, 8> corners{};
                    for (int c = 0; c < 8; ++c)
                        corners[c] = b.node(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1));
                    std::sort(expected.begin(), expected.end());
                    std::sort(corners.begin(), corners.end());
                    EXPECT_EQ(expected, corners);
                }
            }
        }
    }
}

TEST(BlockIndexing, FrameIsRightHandedAndFollowsXyz) {
    // A graded block turned 90° about z: lattice axis 0 of the map runs along +y. Indexing must
    // still give i along +x, j along +y, k along +z, with positive Jacobians everywhere.
    auto graded = [](int i) { return std::pow(1.3, i); };
    auto position = [&](const MeshBuilder::Key& k) {
        return Vec3(-2.0 * k[1], graded(k[0]), 0.5 * k[2]);
    };
    for (unsigned seed = 1; seed <= 4; ++seed) {
        MeshBuilder builder(seed);
        builder.addBlock(1, {6, 3, 2}, test::offsetKey({0, 0, 0}), position);
        const HexMesh mesh = builder.build();
        const BlockLattice b = indexOnly(mesh);
        ASSERT_EQ(b.cells, (Int3{3, 6, 2}));
        for (int k = 0; k < 2; ++k) {
            for (int j = 0; j < 6; ++j) {
                for (int i = 0; i < 3; ++i) {
                    const HexCorners x = cornersOf(mesh, b, i, j, k);
                    EXPECT_GT(minCornerJacobian(x), 0.0);
                    EXPECT_GT(x[1][0] - x[0][0], 0.0);  // +i is +x
                    EXPECT_GT(x[2][1] - x[0][1], 0.0);  // +j is +y
                    EXPECT_GT(x[4][2] - x[0][2], 0.0);  // +k is +z
                }
            }
        }
    }
}

TEST(BlockIndexing, ThinBlocks) {
    for (Int3 n : {Int3{1, 1, 1}, Int3{5, 1, 1}, Int3{1, 4, 1}, Int3{1, 1, 7}, Int3{2, 1, 3}}) {
        MeshBuilder builder(3);
        builder.addBlock(1, n, test::offsetKey({0, 0, 0}), boxPosition);
        const BlockLattice b = indexOnly(builder.build());
        EXPECT_EQ(b.cells, n);
    }
}

void expectNotStructured(const HexMesh& mesh) {
    try {
        indexOnly(mesh);
        FAIL() << "accepted a block that is not structured";
    } catch (const MeshError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("synthetic.msh"), std::string::npos) << what;
        EXPECT_NE(what.find("not a structured hex block"), std::string::npos) << what;
    }
}

TEST(BlockIndexing, HoleIsRefused) {
    MeshBuilder builder;
    builder.addBlock(1, {3, 3, 3}, test::offsetKey({0, 0, 0}), boxPosition,
                     [](int i, int j, int k) { return i == 1 && j == 1 && k == 1; });
    expectNotStructured(builder.build());
}

TEST(BlockIndexing, LShapeIsRefused) {
    MeshBuilder builder;
    builder.addBlock(1, {2, 2, 1}, test::offsetKey({0, 0, 0}), boxPosition,
                     [](int i, int j, int) { return i == 1 && j == 1; });
    expectNotStructured(builder.build());
}

TEST(BlockIndexing, TwoPiecesInOneVolumeAreRefused) {
    MeshBuilder builder;
    builder.addBlock(1, {2, 2, 2}, test::offsetKey({0, 0, 0}), boxPosition);
    builder.addBlock(1, {2, 2, 2}, test::offsetKey({10, 0, 0}), boxPosition);
    builder.mergeVolumes(1);
    expectNotStructured(builder.build());
}

TEST(BlockIndexing, TwoBoxesSideBySideInOneVolumeAreOneBlock) {
    // Merged into one volume, two boxes that share a whole face form one structured grid.
    MeshBuilder builder;
    builder.addBlock(1, {2, 3, 2}, test::offsetKey({0, 0, 0}), boxPosition);
    builder.addBlock(1, {3, 3, 2}, test::offsetKey({2, 0, 0}), boxPosition);
    builder.mergeVolumes(1);
    EXPECT_EQ(indexOnly(builder.build()).cells, (Int3{5, 3, 2}));
}

TEST(BlockIndexing, NonManifoldFaceIsRefused) {
    MeshBuilder builder;
    builder.addBlock(1, {2, 1, 1}, test::offsetKey({0, 0, 0}), boxPosition);
    HexMesh& raw = builder.raw();
    raw.hexes.push_back(raw.hexes.front());  // a second hex on the same nodes
    raw.hexTags.push_back(99);
    builder.mergeVolumes(1);
    expectNotStructured(builder.build());
}

TEST(BlockIndexing, ClosedRingHasNoCornerAndIsRefused) {
    // One volume closing on itself around an axis (periodic in j): no node is in only one hex.
    const int nphi = 8;
    MeshBuilder builder;
    builder.addBlock(
        1, {2, nphi, 1},
        [](int i, int j, int k) {
            return MeshBuilder::Key{i, j % 8, k};
        },
        [](const MeshBuilder::Key& k) {
            const double r = 1.0 + k[0], phi = 2.0 * M_PI * k[1] / 8.0;
            return Vec3(r * std::cos(phi), r * std::sin(phi), 1.0 * k[2]);
        });
    expectNotStructured(builder.build());
}

TEST(BlockIndexing, HelicalRampIsRefused) {
    // A ring whose seam joins angular cell 5 of layer k to cell 0 of layer k + 1: structured
    // around every hex, yet walking +j from the corner comes back to an already indexed hex.
    MeshBuilder builder;
    builder.addBlock(
        1, {2, 6, 3},
        [](int i, int j, int k) {
            return j == 6 ? MeshBuilder::Key{i, 0, k + 1} : MeshBuilder::Key{i, j, k};
        },
        [](const MeshBuilder::Key& k) {
            const double r = 1.0 + k[0], phi = 2.0 * M_PI * k[1] / 6.0;
            return Vec3(r * std::cos(phi), r * std::sin(phi), 1.0 * k[2]);
        });
    expectNotStructured(builder.build());
}

TEST(BlockIndexing, ReorientKeepsCellsAndNodesTogether) {
    MeshBuilder builder;
    builder.addBlock(1, {2, 3, 4}, test::offsetKey({0, 0, 0}), boxPosition);
    const HexMesh mesh = builder.build();
    const BlockLattice b = indexOnly(mesh);
    for (const SignedPermutation& R : SignedPermutation::rotations()) {
        BlockLattice r = b;
        reorientBlock(r, R);
        for (int k = 0; k < r.cells[2]; ++k) {
            for (int j = 0; j < r.cells[1]; ++j) {
                for (int i = 0; i < r.cells[0]; ++i) {
                    const HexCorners x = cornersOf(mesh, r, i, j, k);
                    EXPECT_GT(minCornerJacobian(x), 0.0);  // rotations keep right-handedness
                    auto expected = mesh.hexes[r.hex(i, j, k)];
                    std::array<Index, 8> corners{};
                    for (int c = 0; c < 8; ++c)
                        corners[c] = r.node(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1));
                    std::sort(expected.begin(), expected.end());
                    std::sort(corners.begin(), corners.end());
                    EXPECT_EQ(expected, corners);
                }
            }
        }
    }
}

}  // namespace
}  // namespace gsph::preproc
