// SPDX-License-Identifier: MIT
// The uniform Cartesian layout of standard SPH, from the same gmsh geometry (`gsph-preproc
// --lattice H`): what GSPH is compared against, without a second mesh to draw.
//
// Per body: the bounding box of its hexes is divided into n_d = max(1, round(extent_d / H))
// cells along each axis (spacing h_d = extent_d / n_d, within ½H/extent of H, so a box-shaped
// body is tiled exactly); a lattice site (the centre of a cell) becomes a particle when it
// lies in the body's meshed region (inside one of its hexes or on a hex face). The result is
// one Cartesian space per body: θ = (i+½, j+½, k+½)Δθ with Δθ = 1, X = origin + θ∘h, volume
// h_x h_y h_z. A curved body becomes a staircase of cells; its volume differs from the mesh's
// (both are reported).
// Sets: a physical surface's set holds, for sample points spread over each of its faces (at
// most ½h apart, nudged into the face's hex), the body's particle whose cell holds the point,
// or, where that cell was not kept (a staircase under a curved face), the nearest particle of
// the body.
// Errors: InputError for H ≤ 0 or a lattice beyond kMaxLatticeSites; MeshError naming
// mesh.source when a body keeps no site (H larger than the body).
#pragma once

#include <vector>

#include "block_indexing.hpp"
#include "conversion.hpp"
#include "space_gluing.hpp"

namespace gsph::preproc {

/// The largest lattice (sites of one body's bounding box) --lattice builds.
inline constexpr double kMaxLatticeSites = 2e8;

/// Fills out.particles (X, θ, volume, space, body, latticeIndex, spaces, sets; bodies must be
/// set) and out.stats (lattice, metric, hexes) with the uniform layout of spacing `spacing`.
/// `bodyOfVolume`: body id per entry of mesh.volumes.
void fillUniformLattice(const HexMesh& mesh, const std::vector<BlockLattice>& blocks,
                        const GluingResult& glued, const std::vector<Index>& bodyOfVolume,
                        const NodeHexAdjacency& adjacency, double spacing, Conversion& out);

}  // namespace gsph::preproc
