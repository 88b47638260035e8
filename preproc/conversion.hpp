// SPDX-License-Identifier: MIT
// Hex mesh → particles (DESIGN §2), after the mesh has left gmsh: bodies from physical volume
// groups, blocks indexed (block_indexing), blocks glued into spaces (space_gluing), one particle
// per hex at its parametric centre with its exact volume and θ = (i+½, j+½, k+½)·Δθ, Δθ = 1,
// and particle sets from physical surface groups.
//
// Bodies: body id = rank of the physical volume group's tag. With no physical volume group at
// all, the whole mesh is body 0. With groups, a volume with hexahedra in no group, or in two,
// is an error (gmsh -3 would silently drop it from a .msh; here it is reported instead).
// Sets: a surface group "name" (or "surface_<tag>" if unnamed) holds every particle whose hex
// has a face on one of its surfaces.
// Order: particles sorted by body, then space (spaces sorted by body, then smallest volume tag),
// then lattice order within the space (i fastest, then j, then k).
// Errors: MeshError naming mesh.source and the fault (no hexahedra, inverted element, block not
// structured, bad group).
#pragma once

#include <string>
#include <vector>

#include "hex_mesh.hpp"
#include "io/particle_file.hpp"

namespace gsph::preproc {

struct ConversionStats {
    std::size_t hexes = 0;
    double minEdge = 0.0, maxEdge = 0.0;  ///< shortest and longest hex edge [m]
    int sharedFaces = 0;                  ///< block faces shared by two blocks of one body
    int honouredFaces = 0;                ///< of which inside one space
    bool exhaustiveGluing = true;
    std::vector<std::vector<int>> spaceVolumes;  ///< gmsh volume tags of each space's blocks
};

struct Conversion {
    ParticleFile particles;                      ///< everything but the provenance
    std::vector<std::size_t> elementOfParticle;  ///< source hex (gmsh element tag) per particle
    ConversionStats stats;
    std::vector<std::string> warnings;
};

Conversion convertHexMesh(const HexMesh& mesh);

}  // namespace gsph::preproc
