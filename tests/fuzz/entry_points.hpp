// SPDX-License-Identifier: MIT
// The reader entry points the fuzz targets drive (tests/fuzz, docs/testing.md), shared with the
// regression test of their findings (tests/tools/test_fuzz_regressions.cpp) so that both run
// exactly the same calls. Each returns on success and lets the reader's error pass: a typed
// gsph::Error (core/error.hpp) is the expected answer to a bad file; anything else (a crash, a
// sanitizer report, another exception) is a bug.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "case_config.hpp"
#include "conversion.hpp"
#include "gmsh_input.hpp"
#include "io/particle_file.hpp"
#include "material_config.hpp"

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

/// readParticleFile, validateParticleFile and, when they succeed, buildReference.
inline void readParticles(const std::filesystem::path& path) {
    const ParticleFile file = readParticleFile(path);
    validateParticleFile(file);
    const std::vector<double> density(file.bodies.size(), kDensity);
    (void)buildReference(file, density, kKappa);
}

/// readHexMesh, then convertHexMesh with the default options.
inline void readMesh(const std::filesystem::path& path) {
    std::vector<std::string> warnings;
    const preproc::HexMesh mesh = preproc::readHexMesh(path, {}, warnings);
    (void)preproc::convertHexMesh(mesh);
}

}  // namespace gsph::fuzz
