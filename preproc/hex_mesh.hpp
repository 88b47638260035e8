// SPDX-License-Identifier: MIT
// The hexahedral mesh as gsph-preproc sees it once it has left gmsh (DESIGN §2): nodes, 8-node
// hexahedra grouped by gmsh volume, physical volume groups (bodies) and physical surface groups
// (particle sets). Plain data with no gmsh types, so everything after reading is testable on
// meshes built in code.
//
// A 2-D mesh (quadrangles in the plane z = 0) arrives here extruded to one layer of unit depth,
// so that the whole hex machinery (block indexing, gluing, overset) serves it unchanged: each
// quad becomes a hex with its nodes at z = 0 and z = 1, each gmsh surface a "volume", each
// physical surface a body and each physical curve a set (its segments extruded into quads).
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
    /// 3, or 2 for extruded quadrangles: volumes and groups then stand for gmsh surfaces and
    /// physical surfaces, surface groups for physical curves.
    int dimension = 3;
};

/// What a block's gmsh entity is called in messages: "surface" in 2-D, else "volume".
inline const char* blockEntity(const HexMesh& mesh) {
    return mesh.dimension == 2 ? "surface" : "volume";
}

/// What a set's gmsh entity is called in messages and unnamed set names: "curve" in 2-D, else
/// "surface".
inline const char* setEntity(const HexMesh& mesh) {
    return mesh.dimension == 2 ? "curve" : "surface";
}

/// The message tail for a set element that bounds no block element.
inline const char* strayFaceFault(const HexMesh& mesh) {
    return mesh.dimension == 2 ? "' has a segment that is not an edge of any quadrangle"
                               : "' has a quadrilateral that is not a face of any hexahedron";
}

}  // namespace gsph::preproc
