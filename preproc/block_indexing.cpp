// SPDX-License-Identifier: MIT
#include "block_indexing.hpp"

#include <algorithm>
#include <deque>
#include <limits>

#include "core/error.hpp"

namespace gsph::preproc {

namespace {

[[noreturn]] void notStructured(const HexMesh& mesh, const HexVolume& volume,
                                const std::string& why) {
    if (mesh.dimension == 2) {
        throw MeshError(mesh.source + ": surface " + std::to_string(volume.tag) +
                        " is not a structured quad block (" + why +
                        "); mesh it with Transfinite Curve/Surface + Recombine Surface");
    }
    throw MeshError(mesh.source + ": volume " + std::to_string(volume.tag) +
                    " is not a structured hex block (" + why +
                    "); mesh it with Transfinite Curve/Surface/Volume + Recombine, or extrude a "
                    "transfinite quad surface with Layers + Recombine");
}

/// The gmsh corner bits at which `hex` holds `node`, or -1.
int cornerOf(const std::array<Index, 8>& hex, Index node) {
    for (int l = 0; l < 8; ++l) {
        if (hex[l] == node) return kGmshCorner[l];
    }
    return -1;
}

/// gmsh local node at gmsh corner bits c (kGmshCorner is its own inverse).
Index nodeAtCorner(const std::array<Index, 8>& hex, int c) {
    return hex[kGmshCorner[c]];
}

/// Corner labels (block frame) of hex `next`, entered through the face of the current hex whose
/// corners have bit d set (labels K). Returns false if those four nodes are not a face of `next`.
bool carryCorners(const std::array<Index, 8>& K, const std::array<Index, 8>& next, int d,
                  std::array<Index, 8>& carried) {
    std::array<int, 4> shared{};   // gmsh corner bits, in `next`, of the shared nodes
    std::array<int, 4> lattice{};  // their block-frame corner bits in `next` (bit d clear)
    for (int o = 0, m = 0; o < 8; ++o) {
        if (!(o >> d & 1)) continue;
        shared[m] = cornerOf(next, K[o]);
        if (shared[m] < 0) return false;
        lattice[m++] = o ^ (1 << d);
    }
    // The four must agree on one bit a of `next`'s frame: axis a crosses the shared face, and
    // each node's partner across the hex along a is the node one step further along d.
    for (int a = 0; a < 3; ++a) {
        const int v = shared[0] >> a & 1;
        if (!std::all_of(shared.begin(), shared.end(), [&](int c) { return (c >> a & 1) == v; })) {
            continue;
        }
        for (int m = 0; m < 4; ++m) {
            carried[lattice[m]] = nodeAtCorner(next, shared[m]);
            carried[lattice[m] | (1 << d)] = nodeAtCorner(next, shared[m] ^ (1 << a));
        }
        return true;
    }
    return false;
}

/// Rotation of a block frame that best aligns i, j, k with x, y, z (see indexBlock step 6).
SignedPermutation alignWithAxes(const HexMesh& mesh, const BlockLattice& block) {
    const Int3 n = block.cells;
    auto X = [&](int i, int j, int k) { return mesh.nodes[block.node(i, j, k)]; };
    std::array<Vec3, 3> chord = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    for (int k = 0; k <= n[2]; ++k) {
        for (int j = 0; j <= n[1]; ++j) chord[0] += X(n[0], j, k) - X(0, j, k);
        for (int i = 0; i <= n[0]; ++i) chord[1] += X(i, n[1], k) - X(i, 0, k);
    }
    for (int j = 0; j <= n[1]; ++j) {
        for (int i = 0; i <= n[0]; ++i) chord[2] += X(i, j, n[2]) - X(i, j, 0);
    }
    for (Vec3& v : chord) {
        if (v.norm() > 0.0) v.normalize();
    }
    SignedPermutation best;
    double bestScore = -std::numeric_limits<double>::infinity();
    for (const SignedPermutation& R : SignedPermutation::rotations()) {
        double score = 0.0;  // new axis d is old axis R.perm[d] with sign R.sign[d]
        for (int d = 0; d < 3; ++d) score += R.sign[d] * chord[R.perm[d]][d];
        if (score > bestScore + 1e-9) {  // ties keep the earlier rotation (identity first)
            bestScore = score;
            best = R;
        }
    }
    return best;
}

}  // namespace

namespace {

/// Walk state: per hex of the block (index h − firstHex), its cell and its corner nodes in the
/// block frame (corner bits c = di + 2dj + 4dk).
struct Walk {
    std::vector<Int3> cell;
    std::vector<std::array<Index, 8>> corner;
    Int3 extent = {1, 1, 1};
    int flip = 0;  // the block frame of the corner hex = gmsh's frame reflected in these bits
};

/// Step 1–2: a corner node (in exactly one hex of the block; the smallest such id) and its hex,
/// labelled so that the node is corner 0 and the three axes point into the block.
Walk startWalk(const HexMesh& mesh, const HexVolume& volume, const NodeHexAdjacency& adjacency) {
    const Index first = volume.firstHex, end = first + volume.hexCount;
    Index start = -1, startHex = -1;
    for (Index h = first; h < end; ++h) {
        for (Index n : mesh.hexes[h]) {
            if (start >= 0 && n >= start) continue;
            int within = 0;
            for (Index g : adjacency.hexesOf(n)) within += (g >= first && g < end) ? 1 : 0;
            if (within == 1) {
                start = n;
                startHex = h;
            }
        }
    }
    if (start < 0) notStructured(mesh, volume, "no corner: every node is in several hexahedra");
    Walk walk{std::vector<Int3>(volume.hexCount, Int3{-1, -1, -1}),
              std::vector<std::array<Index, 8>>(volume.hexCount),
              {1, 1, 1},
              0};
    walk.flip = cornerOf(mesh.hexes[startHex], start);
    for (int c = 0; c < 8; ++c) {
        walk.corner[startHex - first][c ^ walk.flip] = nodeAtCorner(mesh.hexes[startHex], c);
    }
    walk.cell[startHex - first] = {0, 0, 0};
    return walk;
}

/// Step 3: from every reached hex, cross its +i, +j, +k faces, carrying the corner labels.
void walkBlock(const HexMesh& mesh, const HexVolume& volume, const NodeHexAdjacency& adjacency,
               Walk& walk) {
    const Index first = volume.firstHex, end = first + volume.hexCount;
    Index startHex = first;
    while (walk.cell[startHex - first][0] < 0) ++startHex;
    std::deque<Index> queue{startHex};
    std::size_t reached = 1;
    while (!queue.empty()) {
        const Index h = queue.front();
        queue.pop_front();
        for (int d = 0; d < 3; ++d) {
            const std::array<Index, 8>& K = walk.corner[h - first];
            std::array<Index, 4> face{};
            for (int o = 0, m = 0; o < 8; ++o) {
                if (o >> d & 1) face[m++] = K[o];
            }
            std::array<Index, 2> found{};
            const int matches = adjacency.hexesWithFace(face, h, found);
            if (matches > 1) notStructured(mesh, volume, "a face is shared by three hexahedra");
            if (matches == 0 || found[0] < first || found[0] >= end) continue;  // block boundary
            const Index next = found[0];
            std::array<Index, 8> carried{};
            if (!carryCorners(K, mesh.hexes[next], d, carried)) {
                notStructured(mesh, volume, "neighbouring hexahedra do not share a whole face");
            }
            Int3 nc = walk.cell[h - first];
            ++nc[d];
            if (walk.cell[next - first][0] >= 0) {
                if (walk.cell[next - first] != nc || walk.corner[next - first] != carried) {
                    notStructured(mesh, volume,
                                  "element " + std::to_string(mesh.hexTags[next]) +
                                      " is reached at two lattice positions");
                }
                continue;
            }
            walk.cell[next - first] = nc;
            walk.corner[next - first] = carried;
            walk.extent[d] = std::max(walk.extent[d], nc[d] + 1);
            ++reached;
            queue.push_back(next);
        }
    }
    const auto count = static_cast<std::size_t>(volume.hexCount);
    if (reached != count) {
        notStructured(
            mesh, volume,
            std::to_string(count - reached) + " hexahedra cannot be reached from its corner");
    }
}

/// Step 4: the lattice arrays, every cell and every lattice node taken exactly once.
BlockLattice fillLattice(const HexMesh& mesh, const HexVolume& volume, const Walk& walk) {
    const Int3 n = walk.extent;
    const std::size_t cells = static_cast<std::size_t>(n[0]) * n[1] * n[2];
    if (cells != static_cast<std::size_t>(volume.hexCount)) {
        notStructured(mesh, volume,
                      std::to_string(volume.hexCount) + " hexahedra do not fill a " +
                          std::to_string(n[0]) + "×" + std::to_string(n[1]) + "×" +
                          std::to_string(n[2]) + " lattice");
    }
    BlockLattice block;
    block.volumeTag = volume.tag;
    block.cells = n;
    block.hexAtCell.assign(cells, -1);
    block.nodes.assign(static_cast<std::size_t>(n[0] + 1) * (n[1] + 1) * (n[2] + 1), -1);
    for (Index h = volume.firstHex; h < volume.firstHex + volume.hexCount; ++h) {
        const Int3 c = walk.cell[h - volume.firstHex];
        Index& slot = block.hexAtCell[c[0] + n[0] * (c[1] + n[1] * c[2])];
        if (slot >= 0) notStructured(mesh, volume, "two hexahedra take the same lattice cell");
        slot = h;
        for (int o = 0; o < 8; ++o) {
            const int i = c[0] + (o & 1), j = c[1] + (o >> 1 & 1), k = c[2] + (o >> 2 & 1);
            Index& node = block.nodes[i + (n[0] + 1) * (j + (n[1] + 1) * k)];
            const Index labelled = walk.corner[h - volume.firstHex][o];
            if (node >= 0 && node != labelled) {
                notStructured(mesh, volume, "two nodes take the same lattice position");
            }
            node = labelled;
        }
    }
    std::vector<Index> distinct(block.nodes);
    std::sort(distinct.begin(), distinct.end());
    if (std::adjacent_find(distinct.begin(), distinct.end()) != distinct.end()) {
        notStructured(mesh, volume, "a node takes two lattice positions");
    }
    return block;
}

}  // namespace

BlockLattice indexBlock(const HexMesh& mesh, const HexVolume& volume,
                        const NodeHexAdjacency& adjacency) {
    Walk walk = startWalk(mesh, volume, adjacency);
    walkBlock(mesh, volume, adjacency, walk);
    BlockLattice block = fillLattice(mesh, volume, walk);
    // Step 5, right-handed: gmsh's own frame is (positive Jacobians, checked before), and the
    // block frame of the corner hex reflects it in the axes set in `flip`.
    if (((walk.flip & 1) + (walk.flip >> 1 & 1) + (walk.flip >> 2 & 1)) % 2 == 1) {
        reorientBlock(block, SignedPermutation{{0, 1, 2}, {-1, 1, 1}});
    }
    // Step 6: turn the frame so that i, j, k follow x, y, z as well as the block allows.
    const SignedPermutation R = alignWithAxes(mesh, block);
    if (!(R == SignedPermutation{})) reorientBlock(block, R);
    return block;
}

void reorientBlock(BlockLattice& block, const SignedPermutation& P) {
    const Int3 n = block.cells;
    Int3 m{}, t{};
    for (int d = 0; d < 3; ++d) {
        m[d] = n[P.perm[d]];
        t[d] = P.sign[d] < 0 ? m[d] : 0;  // keeps x' in [0, m]
    }
    const LatticeTransform T{P, t};
    std::vector<Index> nodes(block.nodes.size());
    for (int k = 0; k <= n[2]; ++k) {
        for (int j = 0; j <= n[1]; ++j) {
            for (int i = 0; i <= n[0]; ++i) {
                const Int3 y = T.node({i, j, k});
                nodes[y[0] + (m[0] + 1) * (y[1] + (m[1] + 1) * y[2])] = block.node(i, j, k);
            }
        }
    }
    std::vector<Index> hexes(block.hexAtCell.size());
    for (int k = 0; k < n[2]; ++k) {
        for (int j = 0; j < n[1]; ++j) {
            for (int i = 0; i < n[0]; ++i) {
                const Int3 y = T.cell({i, j, k});
                hexes[y[0] + m[0] * (y[1] + m[1] * y[2])] = block.hex(i, j, k);
            }
        }
    }
    block.cells = m;
    block.nodes = std::move(nodes);
    block.hexAtCell = std::move(hexes);
}

}  // namespace gsph::preproc
