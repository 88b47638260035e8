// SPDX-License-Identifier: MIT
// Topology of 8-node hexahedra (DESIGN §2): the corner numbering used throughout gsph-preproc
// and the node → hex adjacency that finds face neighbours without a per-face hash table.
//
// Corner numbering: a hex corner is named by its bits c = di + 2·dj + 4·dk, (di,dj,dk) ∈ {0,1}³
// being its offset in the hex's (i,j,k) frame. The corners across an edge from c are c^1, c^2,
// c^4; the face "bit a = v" holds the four corners whose bit a equals v. gmsh's hex8 local node
// l sits at corner kGmshCorner[l] of gmsh's own (ξ,η,ζ) frame.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/types.hpp"

namespace gsph::preproc {

/// gmsh hex8 local node → corner bits in gmsh's (ξ,η,ζ) frame (nodes 2,3 and 6,7 swap).
inline constexpr std::array<int, 8> kGmshCorner = {0, 1, 3, 2, 4, 5, 7, 6};

/// Node → hexes adjacency in compressed rows: hexesOf(n) lists, ascending, every hex that has
/// node n. Built once for the whole mesh (8 entries per hex).
class NodeHexAdjacency {
  public:
    NodeHexAdjacency(Index nodeCount, std::span<const std::array<Index, 8>> hexes);

    std::span<const Index> hexesOf(Index node) const {
        const auto n = static_cast<std::size_t>(node);
        return {list_.data() + offset_[n], list_.data() + offset_[n + 1]};
    }

    /// Hexes other than `exclude` that hold all four nodes, written to `found` (at most 2 are
    /// kept); returns how many there are. A conforming mesh has at most one besides `exclude`.
    int hexesWithFace(const std::array<Index, 4>& face, Index exclude,
                      std::array<Index, 2>& found) const;

  private:
    std::span<const std::array<Index, 8>> hexes_;
    std::vector<std::size_t> offset_;
    std::vector<Index> list_;
};

}  // namespace gsph::preproc
