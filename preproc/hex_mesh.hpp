// SPDX-License-Identifier: MIT
// The hexahedral mesh as gsph-preproc sees it once it has left gmsh (DESIGN §2): nodes, 8-node
// hexahedra grouped by gmsh volume, physical volume groups (bodies) and physical surface groups
// (particle sets). Plain data with no gmsh types, so everything after reading is testable on
// meshes built in code.
//
// Invariants: hexes of one volume are contiguous ([firstHex, firstHex + hexCount)); node ids
// index `nodes`; hex node order is gmsh's (= VTK's) hex8 order; volumes are sorted by tag.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace gsph::preproc {

/// One gmsh volume that holds hexahedra: a candidate structured block.
struct HexVolume {
    int tag = 0;         ///< gmsh volume (elementary entity) tag
    Index firstHex = 0;  ///< its hexes are [firstHex, firstHex + hexCount)
    Index hexCount = 0;
};

/// A physical volume group: one body.
struct VolumeGroup {
    int tag = 0;
    std::string name;          ///< empty if the group has no name
    std::vector<int> volumes;  ///< gmsh volume tags
};

/// A physical surface group: one named particle set (the particles whose hex has a face on it).
struct SurfaceGroup {
    int tag = 0;
    std::string name;                         ///< empty if the group has no name
    std::vector<std::array<Index, 4>> quads;  ///< its quadrilateral faces (node ids)
};

struct HexMesh {
    std::string source;                       ///< input file, for messages
    std::vector<Vec3> nodes;                  ///< node coordinates [m], indexed by node id
    std::vector<std::array<Index, 8>> hexes;  ///< node ids in gmsh hex8 order
    std::vector<std::size_t> hexTags;         ///< gmsh element tag of each hex (messages)
    std::vector<HexVolume> volumes;           ///< sorted by tag
    std::vector<VolumeGroup> volumeGroups;    ///< sorted by tag
    std::vector<SurfaceGroup> surfaceGroups;  ///< sorted by tag
};

}  // namespace gsph::preproc
