// SPDX-License-Identifier: MIT
// One run of gsph-solve: case file + particle file → snapshots, history.csv and run.log in the
// run folder. Every file is written under a temporary name and renamed (io/atomic_file.hpp).
// A numerical breakdown (NaN, inverted particle, collapsed time step) writes a final snapshot
// of the failing state, then rethrows with the particle and the time.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "case_config.hpp"

namespace gsph::solver {

struct RunOptions {
    std::filesystem::path runDir;
    bool progress = false;  ///< draw a progress line on stderr (only on a terminal)
    std::function<void(const std::string&)> log;  ///< one line of the run log (also printed)
};

struct RunSummary {
    long steps = 0;
    int snapshots = 0;
    double wallSeconds = 0.0;
    double particleStepsPerSecond = 0.0;
    int particles = 0;
};

RunSummary runCase(const CaseConfig& config, const RunOptions& options);

}  // namespace gsph::solver
