// SPDX-License-Identifier: MIT
#include "hex_topology.hpp"

#include <algorithm>
#include <vector>

namespace gsph::preproc {

NodeHexAdjacency::NodeHexAdjacency(Index nodeCount, std::span<const std::array<Index, 8>> hexes)
    : hexes_(hexes), offset_(static_cast<std::size_t>(nodeCount) + 1, 0) {
    for (const auto& hex : hexes) {
        for (Index n : hex) ++offset_[static_cast<std::size_t>(n) + 1];
    }
    for (std::size_t n = 0; n + 1 < offset_.size(); ++n) offset_[n + 1] += offset_[n];
    list_.resize(offset_.back());
    std::vector<std::size_t> fill(offset_.begin(), offset_.end() - 1);
    for (std::size_t h = 0; h < hexes.size(); ++h) {
        for (Index n : hexes[h]) list_[fill[static_cast<std::size_t>(n)]++] = static_cast<Index>(h);
    }
    // Hexes were visited in ascending order, so every row is already sorted; a node listed twice
    // in one hex (a degenerate hex) appears twice, which hexesWithFace tolerates.
}

int NodeHexAdjacency::hexesWithFace(const std::array<Index, 4>& face, Index exclude,
                                    std::array<Index, 2>& found) const {
    // Intersect the sorted hex lists of the four nodes with merge walks. A structured mesh has
    // at most 8 hexes per node; other meshes may have more (then the buffer is on the heap).
    const auto base = hexesOf(face[0]);
    std::array<Index, 16> small{};
    std::vector<Index> large;
    Index* common = small.data();
    if (base.size() > small.size()) {
        large.resize(base.size());
        common = large.data();
    }
    std::size_t n = 0;
    for (Index h : base) {
        if (h != exclude && (n == 0 || common[n - 1] != h)) common[n++] = h;
    }
    for (int k = 1; k < 4 && n > 0; ++k) {
        const auto other = hexesOf(face[k]);
        std::size_t kept = 0;
        auto it = other.begin();
        for (std::size_t m = 0; m < n; ++m) {
            while (it != other.end() && *it < common[m]) ++it;
            if (it != other.end() && *it == common[m]) common[kept++] = common[m];
        }
        n = kept;
    }
    for (std::size_t m = 0; m < std::min<std::size_t>(n, 2); ++m) found[m] = common[m];
    return static_cast<int>(n);
}

}  // namespace gsph::preproc
