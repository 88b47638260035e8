// SPDX-License-Identifier: MIT
// One run of gsph-solve: case file + particle file → snapshots, history.csv, run.log and
// checkpoints in the run folder. Every file is written under a temporary name and renamed
// (io/atomic_file.hpp).
//
// Schedule: snapshot k at t = k·output_interval (the steps land on it), a checkpoint after the
// first step at or past each m·checkpoint_interval (checkpoints never change the steps). A
// stop request (SIGINT/SIGTERM, or stopAfterSteps) ends the run after the current step with a
// checkpoint and a snapshot of that state; a restart from a checkpoint continues the schedule
// and the trajectory bit for bit (same case and particle file, checked by their SHA-256).
// A numerical breakdown (NaN, inverted particle, collapsed time step) writes a final snapshot
// of the failing state, then rethrows the NumericalError naming the particle and the time.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "case_config.hpp"
#include "distributed/domain.hpp"
#include "progress.hpp"
#include "run_log.hpp"

namespace gsph::solver {

struct RunOptions {
    std::filesystem::path runDir;
    /// A bar on a terminal, plain lines every minute elsewhere (progress.hpp), or none.
    ProgressBar::Mode progress = ProgressBar::Mode::Off;
    RunLog* log = nullptr;            ///< run.log (lines are also printed)
    std::filesystem::path restart;    ///< checkpoint to continue from (empty: start at t = 0)
    long stopAfterSteps = 0;          ///< > 0: stop as on a signal once the step counter reaches it
    std::function<int()> stopSignal;  ///< the signal received, or 0 (checked after every step)
    /// Called once the run is set up, before it writes its first file: from then on a signal
    /// stops the run after the current step with a checkpoint (before, there is nothing to
    /// save).
    std::function<void()> steppingStarts;
    /// A fresh run into a folder that holds an earlier run's files (snapshots, checkpoint,
    /// history): false refuses with InputError, true removes them first.
    bool overwrite = false;
    /// A run split over processes (null or one process: serial). Every process runs runCase
    /// alike; the one whose domain writesFiles() writes the run folder, the others only step.
    std::shared_ptr<Domain> domain;
};

struct RunSummary {
    long steps = 0;
    int snapshots = 0;
    double wallSeconds = 0.0;
    double particleStepsPerSecond = 0.0;
    int particles = 0;
    bool interrupted = false;          ///< stopped early; a checkpoint was written
    std::string stopReason;            ///< "SIGTERM", "--stop-after-steps 40", ...
    std::filesystem::path checkpoint;  ///< the checkpoint to restart from
    double time = 0.0;                 ///< simulated time reached [s]
};

/// Name of the rolling checkpoint in a run folder.
inline constexpr const char* kCheckpointName = "checkpoint.h5";

/// The files of an earlier run in a folder (snapshot_*.h5, checkpoint.h5, history.csv, probes.csv,
/// run.log), sorted; empty if the folder does not exist.
std::vector<std::filesystem::path> earlierRunFiles(const std::filesystem::path& runDir);

RunSummary runCase(const CaseConfig& config, const RunOptions& options);

}  // namespace gsph::solver
