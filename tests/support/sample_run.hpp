// SPDX-License-Identifier: MIT
// The sample job of the tool tests: the graded bar (geometries/graded_bar.geo, 320 particles,
// sets 'clamp' and 'load') through gsph-preproc and gsph-solve (cases/graded_bar/case.toml).
// Needs GSPH_PREPROC_EXE, GSPH_SOLVE_EXE and GSPH_SOURCE_DIR defined by the test target.
#pragma once

#include <filesystem>
#include <string>

#include "support/process.hpp"

namespace gsph::test {

inline const std::filesystem::path kSourceDir = GSPH_SOURCE_DIR;

/// gsph-preproc on the sample geometry, writing `particles`.
inline ProcessResult makeSampleParticles(const std::filesystem::path& particles) {
    return runCommand(std::string(GSPH_PREPROC_EXE) + " " +
                      quote((kSourceDir / "geometries/graded_bar.geo").string()) + " -o " +
                      quote(particles.string()));
}

/// gsph-solve on the sample case with `particles`, writing into `runDir`.
inline ProcessResult runSampleCase(const std::filesystem::path& particles,
                                   const std::filesystem::path& runDir) {
    return runCommand(std::string(GSPH_SOLVE_EXE) + " " +
                      quote((kSourceDir / "cases/graded_bar/case.toml").string()) +
                      " --particles " + quote(particles.string()) + " -o " +
                      quote(runDir.string()));
}

}  // namespace gsph::test
