// SPDX-License-Identifier: MIT
// The overset interface band (DESIGN §6).
//
// Across an interface between spaces, the pairwise force of DESIGN §4 is not consistent: under
// a uniform stress it leaves a spurious interface force density growing as 1/spacing (the
// interface acts like a crack). The band is where that is repaired: its pairs get corrected
// weights (overset/interface_weights.hpp) that make the force exact for uniform and linear
// stress while it stays the gradient of an energy. Pairs across spaces need not have a mirror
// (Reference::crossPair lists their transposed terms under the other particle).
//
// Seeds: every particle with a pair across spaces (in its own list, or in a list that holds
// it). The band: every particle joined to a seed through pairs within one coarse kernel support
// 2 h_max, h_max the largest physical smoothing length of a seed (the coarse side): the
// particles whose Piola sums the interface disturbs, with a margin.
// Band particles whose kernel support reaches a free face of their space's lattice box (a face
// with no transient neighbour beyond it) are marked kBandNearFreeFace: the Piola sum there is
// the face's traction, so only their consistency is imposed.
#pragma once

#include "particles/reference.hpp"

namespace gsph {

/// Fills ref.oversetBand (Reference::kBandInterior / kBandNearFreeFace), the transposed cross
/// pairs and ref.oversetCoupled (all left empty
/// when no pair crosses spaces). Needs ref.pairs and
/// ref.smoothingLength (computeGeometry calls it last).
void markOversetBand(Reference& ref);

}  // namespace gsph
