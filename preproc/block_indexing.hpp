// SPDX-License-Identifier: MIT
// Structured (i,j,k) indices of one block from its hex connectivity (DESIGN §2: "walk face
// neighbours from a corner hex; do not rely on gmsh's internal node ordering").
//
// Method: start at a corner node (a node in exactly one hex of the block), give that hex the
// cell (0,0,0) and its corners the offsets {0,1}³, then walk across the +i, +j, +k faces,
// carrying the corner labels through each shared face. Every node gets one lattice position;
// any contradiction (a node or hex reached at two positions, a cell used twice, a missing cell)
// means the block is not a structured grid and is reported as a MeshError.
// Output invariants: the frame is right-handed (det ∂X/∂θ > 0 given valid hexes) and turned so
// that i, j, k follow x, y, z as closely as the block allows; cells[d] ≥ 1; `nodes` and
// `hexAtCell` are complete, i fastest.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "hex_mesh.hpp"
#include "hex_topology.hpp"
#include "lattice_transform.hpp"

namespace gsph::preproc {

struct BlockLattice {
    int volumeTag = 0;
    Int3 cells = {0, 0, 0};        ///< n_i, n_j, n_k
    std::vector<Index> nodes;      ///< node id at lattice node (i,j,k), (n+1)³ layout, i fastest
    std::vector<Index> hexAtCell;  ///< hex id of cell (i,j,k), i fastest

    Index node(int i, int j, int k) const {
        return nodes[static_cast<std::size_t>(i + (cells[0] + 1) * (j + (cells[1] + 1) * k))];
    }
    Index hex(int i, int j, int k) const {
        return hexAtCell[static_cast<std::size_t>(i + cells[0] * (j + cells[1] * k))];
    }
    Index cellCount() const { return static_cast<Index>(hexAtCell.size()); }
};

/// Indexes the hexes of `volume`. Hexes must have positive Jacobians in their own node order
/// (checked before). Throws MeshError naming mesh.source and the volume if it is not a
/// structured hex grid.
BlockLattice indexBlock(const HexMesh& mesh, const HexVolume& volume,
                        const NodeHexAdjacency& adjacency);

/// Re-expresses a block in the frame x' = P x + t, t chosen so that x' ∈ [0, n'] (P may be a
/// reflection).
void reorientBlock(BlockLattice& block, const SignedPermutation& P);

}  // namespace gsph::preproc
