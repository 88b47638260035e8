// SPDX-License-Identifier: MIT
// gmsh → HexMesh (DESIGN §1, §2): reads a .msh, or opens a .geo and meshes it in-process through
// the gmsh C++ API (in 3-D, or in 2-D when the model has surfaces but no volumes), then copies
// everything gsph-preproc needs out of gmsh in bulk (one call for all nodes, one per volume or
// surface for its elements; never one call per element). A mesh of quadrangles without 3-D
// elements is a 2-D mesh: it must lie in the plane z = 0 and comes out extruded to unit depth
// (hex_mesh.hpp), physical surfaces as bodies and physical curves as sets.
//
// Contract: gmsh is initialised and finalised inside readHexMesh and leaves no state behind
// (OpenMP's thread count, which gmsh::initialize sets to 1, is restored; ONELAB parameters are
// cleared; user gmshrc files are not read, so the result does not depend on the machine), so
// repeated calls in one process are independent. gmsh's messages are captured, not
// printed; its warnings are returned. Errors: InputError for a missing, unsupported or
// unreadable file (a .geo syntax error included), MeshError for a mesh that is not made of
// 8-node hexahedra (in 2-D: of 4-node quadrangles in the plane z = 0), that mixes 2-D and 3-D
// elements, or whose set groups are not quadrilaterals (in 2-D: 2-node lines). Every message
// starts with the file name.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "hex_mesh.hpp"

namespace gsph::preproc {

struct MeshReadOptions {
    /// .geo parameters defined before parsing, like gmsh's `-setnumber NAME VALUE`: they
    /// override DefineConstant defaults (a plain assignment in the .geo still wins). Not
    /// allowed with a .msh.
    std::vector<std::pair<std::string, double>> parameters;
};

/// @param[out] warnings gmsh's warnings and gsph-preproc's own notes on the input
HexMesh readHexMesh(const std::filesystem::path& input, const MeshReadOptions& options,
                    std::vector<std::string>& warnings);

}  // namespace gsph::preproc
