// SPDX-License-Identifier: MIT
#include "hex_topology.hpp"

#include <algorithm>

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
    int count = 0;
    Index previous = -1;
    for (Index h : hexesOf(face[0])) {
        if (h == exclude || h == previous) continue;
        previous = h;
        const auto& nodes = hexes_[static_cast<std::size_t>(h)];
        auto has = [&](Index n) { return std::find(nodes.begin(), nodes.end(), n) != nodes.end(); };
        if (has(face[1]) && has(face[2]) && has(face[3])) {
            if (count < 2) found[static_cast<std::size_t>(count)] = h;
            ++count;
        }
    }
    return count;
}

}  // namespace gsph::preproc
