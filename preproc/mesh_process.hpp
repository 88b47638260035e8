// SPDX-License-Identifier: MIT
// gmsh in a child process: readHexMesh (gmsh_input.hpp) runs in a fork, and the HexMesh, its
// warnings or its typed error come back through a pipe. gmsh is a large C++ code that can
// crash on some inputs (a zero grading, a damaged .msh); in the child, a crash is a clear
// MeshError of ours instead of the end of gsph-preproc, and gmsh's memory goes back to the
// system when the child exits.
//
// Contract: same results and errors as readHexMesh (InputError, MeshError, IoError keep their
// type and message); a child killed by a signal (SIGSEGV, SIGABRT, the out-of-memory killer) or
// one that exits without an answer gives MeshError naming the file and the signal.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "gmsh_input.hpp"

namespace gsph::preproc {

HexMesh readHexMeshInChild(const std::filesystem::path& input, const MeshReadOptions& options,
                           std::vector<std::string>& warnings);

}  // namespace gsph::preproc
