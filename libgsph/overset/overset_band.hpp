// SPDX-License-Identifier: MIT
// The overset interface band (DESIGN §6).
//
// Across an interface between spaces, the pairwise force of DESIGN §4 is not consistent: under
// a uniform stress it leaves a spurious interface force density growing as 1/spacing (the
// interface acts like a crack). Particles within two kernel supports of the coarser side of an
// interface therefore take the difference form
//     f_c = V_c Σ_b ω_b (P(b) − P(c)) g_cb,
// which is the corrected divergence of P: exact for uniform and linear stress. Every other
// particle keeps the pairwise form and still receives the transposed term from each neighbour,
// band or not (for a pair across spaces, read from the neighbour's own list, since such pairs
// need not have a mirror: Reference::crossPair), so momentum is exact away from the band and its
// error, confined to the band, falls with the spacing.
//
// Seeds: every particle with a pair across spaces (in its own list, or in a list that holds
// it). The band: every particle joined to a seed through pairs within the physical distance
// 2 × (2 h_max), h_max the largest physical smoothing length of a seed (the coarse side),
// except particles whose kernel support reaches a free face of their space's lattice box (a face
// with no transient neighbour beyond it): they keep the pairwise form, which carries the
// surface traction σn that the difference form lacks.
#pragma once

#include "particles/reference.hpp"

namespace gsph {

/// Fills ref.oversetBand, the transposed cross pairs and ref.oversetCoupled (all left empty
/// when no pair crosses spaces). Needs ref.pairs and
/// ref.smoothingLength (computeGeometry calls it last).
void markOversetBand(Reference& ref);

}  // namespace gsph
