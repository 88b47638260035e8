// SPDX-License-Identifier: MIT
// The reader entry points the fuzz targets drive (tests/fuzz, docs/testing.md), shared with the
// regression test of their findings (tests/tools/test_fuzz_regressions.cpp) so that both run
// exactly the same calls. Each returns on success and lets the reader's error pass: a typed
// gsph::Error (core/error.hpp) is the expected answer to a bad file; anything else (a crash, a
// sanitizer report, another exception) is a bug.
//
// The particle-file and .msh readers come in two forms: as the tools call them (gsph-solve reads
// through readParticleFileIsolated, gsph-preproc through readHexMeshInChild: HDF5's and gmsh's
// parsers run in a child process, so a crash inside them is a typed error), and in process
// (the parsers and our code around them under the fuzzer's coverage and sanitizers, where a
// crash inside HDF5 or gmsh is theirs: tests/fuzz/third_party_findings).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "case_config.hpp"
#include "conversion.hpp"
#include "gmsh_input.hpp"
#include "io/particle_file.hpp"
#include "material_config.hpp"
#include "mesh_process.hpp"
#include "reference/reference_builder.hpp"

namespace gsph::fuzz {

/// ρ0 per body and κ for buildReference (the values tests/tools/test_particle_file.cpp uses).
inline constexpr double kDensity = 1000.0;  // [kg/m³]
inline constexpr double kKappa = 1.2;

inline void readCase(const std::filesystem::path& path) {
    (void)solver::readCaseFile(path);
}

inline void readMaterial(const std::filesystem::path& path) {
    (void)solver::readMaterialFile(path);
}

inline void checkParticles(const ParticleFile& file) {
    validateParticleFile(file);
    const std::vector<double> density(file.bodies.size(), kDensity);
    (void)buildReference(file, density, kKappa);
}

/// As gsph-solve reads: readParticleFileIsolated, validateParticleFile, buildReference; the
/// reader's deadline (a hang inside HDF5) is 5 s instead of gsph-solve's 60 s, for inputs of a few
/// kB that a working reader reads in milliseconds.
inline constexpr unsigned kReadDeadline = 5;  // [s]
inline void readParticles(const std::filesystem::path& path) {
    checkParticles(readParticleFileIsolated(path, kReadDeadline));
}

/// readParticleFile in this process, then the same checks.
inline void readParticlesInProcess(const std::filesystem::path& path) {
    checkParticles(readParticleFile(path));
}

/// As gsph-preproc reads: readHexMeshInChild, then convertHexMesh with the default options.
inline void readMesh(const std::filesystem::path& path) {
    std::vector<std::string> warnings;
    (void)preproc::convertHexMesh(preproc::readHexMeshInChild(path, {}, warnings));
}

/// readHexMesh in this process, then the same conversion.
inline void readMeshInProcess(const std::filesystem::path& path) {
    std::vector<std::string> warnings;
    (void)preproc::convertHexMesh(preproc::readHexMesh(path, {}, warnings));
}

}  // namespace gsph::fuzz
