// SPDX-License-Identifier: MIT
// Which bonds (CSR pairs) of the reference's pair list hold, as the pair loops read it: a view
// of the state's bondIntact and the per-particle flags failure/brittle_bonds.hpp derives from
// it. A default view (null pointers) means every bond holds.
#pragma once

#include <cstdint>

#include "core/types.hpp"

namespace gsph {

/// What the pair loops need of the bonds: null pointers when no body can break.
struct BondView {
    const std::uint8_t* intact = nullptr;   ///< per CSR pair: 1 holds, 0 broken
    const std::uint8_t* damaged = nullptr;  ///< per particle: 1 if any of its bonds broke
    /// Per particle: 1 if it or a particle it pairs with (either list) has a broken bond, so the
    /// pair weights staged in the reference configuration (neighbors/staged_pairs.hpp) no longer
    /// hold for it: its pairs are staged afresh at each evaluation.
    const std::uint8_t* stale = nullptr;
    /// True when every particle of [begin, end) keeps all its bonds (stencil path allowed).
    bool allIntact(Index begin, Index end) const {
        if (damaged == nullptr) return true;
        for (Index a = begin; a < end; ++a)
            if (damaged[a] != 0) return false;
        return true;
    }
    /// True when particle a's staged pair weights still hold (see stale).
    bool keepsStaged(Index a) const { return stale == nullptr || stale[a] == 0; }
    bool holds(Index pair) const { return intact == nullptr || intact[pair] != 0; }
    /// True when particle a keeps all its bonds (its interface weight corrections apply).
    bool keepsAll(Index a) const { return damaged == nullptr || damaged[a] == 0; }
};

}  // namespace gsph
