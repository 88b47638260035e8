// SPDX-License-Identifier: MIT
// The exact volume of a trilinear (8-node) hexahedron, X(ξ) = Σ_c N_c(ξ) X_c on ξ ∈ [−1,1]³
// (DESIGN §2): the volume a particle's cell has in the mesh (gsph-preproc) and in the current
// configuration of gsph-post's solid.
//
// Corners in corner-bit order: X_c with c = di + 2dj + 4dk sits at ξ = (2di−1, 2dj−1, 2dk−1).
// (VTK_HEXAHEDRON and gmsh order the corners (0,0,0), (1,0,0), (1,1,0), (0,1,0), then the same
// at k = 1: swap corners 2 ↔ 3 and 6 ↔ 7.)
#pragma once

#include <array>

#include "core/types.hpp"

namespace gsph {

/// Σ over the 2×2×2 Gauss points of det ∂X/∂ξ (weights 1): exact, det J being at most quadratic
/// in each ξ [m³]; negative for an inverted hexahedron.
double hexVolume(const std::array<Vec3, 8>& corners);

}  // namespace gsph
