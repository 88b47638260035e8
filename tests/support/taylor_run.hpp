// SPDX-License-Identifier: MIT
// The Taylor bar as a user runs and measures it: gsph-preproc on a geometry of the repository,
// gsph-solve with a case of it, scripts/validation/taylor.py on one snapshot. The including test
// defines GSPH_PREPROC_EXE, GSPH_SOLVE_EXE and GSPH_SOURCE_DIR.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/process.hpp"
#include "support/sample_run.hpp"

namespace gsph::test {

struct TaylorShape {
    double length = 0.0, footprint = 0.0;  // [mm]
    double regionStrain = 0.0;             // ε̄p over the impact face's centre region
};

/// The number taylor.py prints after `label` (0 and a failure when the label is missing).
inline double numberAfter(const std::string& out, const std::string& label) {
    const std::size_t at = out.find(label);
    EXPECT_NE(at, std::string::npos) << label << " not in: " << out;
    return at == std::string::npos ? 0.0 : std::stod(out.substr(at + label.size()));
}

/// Meshes `geometry` with `sets` into `dir`, runs `caseFile` on it (with `solveOptions`; the
/// solver's exit status must be `solveStatus`) and measures `snapshot` of the run.
inline TaylorShape runAndMeasureTaylor(const std::filesystem::path& dir,
                                       const std::string& geometry, const std::string& sets,
                                       const std::string& caseFile,
                                       const std::string& solveOptions = "", int solveStatus = 0,
                                       const std::string& snapshot = "snapshot_000010.h5") {
    const std::filesystem::path particles = dir / "particles.h5", run = dir / "run";
    const auto p =
        runCommand(std::string(GSPH_PREPROC_EXE) + " " + quote((kSourceDir / geometry).string()) +
                   " " + sets + " -q -o " + quote(particles.string()));
    EXPECT_EQ(p.status, 0) << p.err;
    const auto s =
        runCommand(std::string(GSPH_SOLVE_EXE) + " " + quote((kSourceDir / caseFile).string()) +
                   " --particles " + quote(particles.string()) + " -o " + quote(run.string()) +
                   " " + solveOptions);
    EXPECT_EQ(s.status, solveStatus) << s.err;
    const auto m = runCommand("/usr/bin/python3 " +
                              quote((kSourceDir / "scripts/validation/taylor.py").string()) + " " +
                              quote(particles.string()) + " " + quote((run / snapshot).string()));
    EXPECT_EQ(m.status, 0) << m.err;
    TaylorShape shape;
    shape.length = numberAfter(m.out, "length ");
    shape.footprint = numberAfter(m.out, "footprint diameter ");
    shape.regionStrain =
        numberAfter(m.out, "centre region (r < R0/5, the first L0/50): plastic strain ");
    return shape;
}

}  // namespace gsph::test
