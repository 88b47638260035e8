// SPDX-License-Identifier: MIT
// Generalized spaces from structured blocks (DESIGN §2): blocks whose indices glue into one
// index space become one space, possibly closing on itself (periodic in one index, e.g. the
// four quarter blocks of an annulus); every other block is a space of its own.
//
// Two blocks of the same body *share a face* when a whole side of one is a whole side of the
// other, node for node; the face then fixes the integer map between their frames. A set of
// blocks is *consistent* when one frame honours every face shared inside the set, up to a
// translation by a period along one index, and the blocks tile a box (a periodic box along
// periodic indices) exactly, without holes or overlaps. Among the partitions of the blocks into
// consistent sets, gluing picks the one that honours the most shared faces (so the fewest
// faces are left as interfaces between spaces), then the fewest spaces, then the largest
// spaces. The search (branch and bound over the shared faces: inside a space or not) tries
// faces away from irregular block edges first and bounds with "one face per triple around an
// edge where three blocks meet"; it is exact up to kMaxSearchSteps steps and keeps the best
// partition found beyond (reported, never inconsistent).
//
// Output: spaces sorted by (body, first block); each space's frame is its first block's frame
// (block_indexing.hpp), shifted so that cells lie in [0, cells); periodic indices wrap.
#pragma once

#include <array>
#include <vector>

#include "block_indexing.hpp"
#include "lattice_transform.hpp"

namespace gsph::preproc {

inline constexpr long kMaxSearchSteps = 200000;

struct GluedSpace {
    Index body = 0;
    std::vector<Index> blocks;              ///< ascending block indices
    std::vector<LatticeTransform> toSpace;  ///< per entry of `blocks`: block → space nodes
    Int3 cells = {0, 0, 0};                 ///< space extent (the period along periodic axes)
    std::array<bool, 3> periodic = {false, false, false};

    /// Space cell of a block cell, wrapped into [0, cells) along periodic axes.
    Int3 cellOf(std::size_t entry, const Int3& blockCell) const;
};

/// A whole side of block b that is a whole side of block a, node for node; bToA maps b's node
/// coordinates to a's, b lying outside a.
struct SharedFace {
    Index a = 0, b = 0;
    LatticeTransform bToA;
};

struct GluingResult {
    std::vector<GluedSpace> spaces;
    /// The shared faces between blocks of two different spaces (the interfaces across which
    /// an overset body's lattices continue, overset.hpp).
    std::vector<SharedFace> interfaces;
    int sharedFaces = 0;     ///< faces shared by two blocks of one body
    int honouredFaces = 0;   ///< of which inside one space
    bool exhaustive = true;  ///< false if the search stopped at kMaxSearchSteps
};

/// @param[in] blocks     indexed blocks, sorted by volume tag
/// @param[in] bodyOfBlock body id per block; blocks of different bodies never glue
GluingResult glueBlocks(const std::vector<BlockLattice>& blocks,
                        const std::vector<Index>& bodyOfBlock);

}  // namespace gsph::preproc
