// SPDX-License-Identifier: MIT
// Neighbour pairs in θ-space, built once in the reference configuration (DESIGN §3).
//
// CSR layout: the neighbours of particle a are neighbor[offset[a] .. offset[a+1]), sorted by
// index. Each pair also carries kernelId into a small table of kernel data: on a uniform
// θ-lattice every pair with the same lattice offset has the same W and ∇W, so ~60 table entries
// serve every pair of a space (the "lattice gift" of DESIGN §3) and a pair costs 8 bytes.
// Entries are keyed by the θ-offset, so off-lattice pairs (overset) simply add entries.
//
// Invariants: symmetric (b ∈ N(a) ⇔ a ∈ N(b)); table[id(a,b)].gradW = −table[id(b,a)].gradW.
#pragma once

#include <vector>

#include "core/types.hpp"

namespace gsph {

/// Kernel data shared by every pair with the same θ-offset r = θ_a − θ_b. Values carry the
/// quadrature weight ω (θ-volume, DESIGN §3) of the pair's space: within one lattice space every
/// particle has the same ω = Δθ^d, so ω_a = ω_b and the weight folds into the table.
struct KernelEntry {
    Vec3 gradW = Vec3::Zero();        ///< ω ∇_a W_ab, ∇_a W_ab = ∂W(θ_a − θ_b)/∂θ_a
    double W = 0.0;                   ///< ω W_ab
    Vec3 thetaOffset = Vec3::Zero();  ///< r = θ_a − θ_b (minimum image across periodic indices)
};

struct PairList {
    std::vector<Index> offset;    ///< size n+1
    std::vector<Index> neighbor;  ///< b, per pair
    std::vector<Index> kernelId;  ///< into table, per pair
    std::vector<KernelEntry> table;

    Index particles() const { return offset.empty() ? 0 : static_cast<Index>(offset.size() - 1); }
    Index pairs() const { return static_cast<Index>(neighbor.size()); }
    Index begin(Index a) const { return offset[static_cast<std::size_t>(a)]; }
    Index end(Index a) const { return offset[static_cast<std::size_t>(a) + 1]; }
    std::size_t bytes() const;
};

}  // namespace gsph
