// SPDX-License-Identifier: MIT
// gsph-solve: runs a case.
//
// Usage:   gsph-solve CASE.toml [-o RUNDIR] [--particles FILE] [--restart CHECKPOINT.h5]
//                     [--threads N] [--overwrite] [--end-time T] [--output-interval DT]
//                     [--checkpoint-interval DT] [--stop-after-steps N]
//          gsph-solve --material-point MATERIAL.toml --path PATH [-o OUT.csv] [--temperature T]
// Sample:  gsph-preproc geometries/graded_bar.geo -o run/bar/particles.h5
//          gsph-solve cases/graded_bar/case.toml -o run/bar
//          gsph-solve cases/graded_bar/case.toml --restart run/bar/checkpoint.h5
//          gsph-solve cases/graded_bar/case.toml --restart run/bar/checkpoint.h5 --end-time 6e-5
//          gsph-solve --material-point materials/ofhc_copper.toml
//                     --path materials/paths/uniaxial_stress_1e3.toml -o copper.csv
// Description: reads the case file (docs/case-format.md) and the particle file it names, runs
// the total Lagrangian GSPH solver, and writes snapshot_NNNNNN.h5, history.csv and run.log in
// RUNDIR (default: run/<case name>; with --restart, the checkpoint's folder), and
// checkpoint.h5 at the case's checkpoint interval and on SIGINT/SIGTERM. Exit codes: 0 done,
// 1 bad input or a file error (one line on stderr), 2 numerical breakdown (NaN, inverted
// particle, collapsed time step: a final snapshot is written), 3 interrupted (a signal or
// --stop-after-steps: checkpoint and snapshot written, the message says how to restart), 4 an
// output file could not be written (disk full, quota, file-size limit: the message names the
// file and the system's reason; every file it would have replaced, the last good checkpoint
// included, is kept).
// Built with GSPH_MPI, `mpirun -np N gsph-solve CASE.toml ...` splits the run over N processes
// (docs/mpi.md): the same files, the first process writes them. A fault on any process ends all
// of them (MPI_Abort) with the exit code above; a numerical breakdown then writes no final
// snapshot.
#include <omp.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "case_config.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "material_point_cli.hpp"
#include "run.hpp"
#include "run_log.hpp"
#include "signals.hpp"
#ifdef GSPH_MPI
#include <mpi.h>

#include "distributed/mpi_domain.hpp"
#endif

namespace {

constexpr int kExitError = 1;
constexpr int kExitNumerical = 2;
constexpr int kExitInterrupted = 3;
constexpr int kExitWriteFailed = 4;

// run.log, written atomically; a failure is reported, not thrown (true: written).
bool flushLog(gsph::solver::RunLog& log) {
    try {
        log.flush();
        return true;
    } catch (const gsph::Error& e) {
        std::fprintf(stderr, "gsph-solve: error: %s\n", e.what());
        return false;
    }
}

}  // namespace

// The processes of a split run (1: serial), this one's rank; ends them all on a fault.
struct Processes {
    int count = 1, rank = 0;
#ifdef GSPH_MPI
    Processes(int& argc, char**& argv) {
        int provided = 0;
        MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
        MPI_Comm_size(MPI_COMM_WORLD, &count);
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    }
    ~Processes() {
        MPI_Finalize();
    }
    [[noreturn]] void abort(int status) const {
        std::fflush(stdout);
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, status);
        std::_Exit(status);
    }
#else
    // Started by mpirun all the same: every process would run the whole case into one folder.
    Processes(int&, char**&) {
        for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
            if (const char* value = std::getenv(name))
                launched = std::max(launched, std::atoi(value));
        for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
            if (const char* value = std::getenv(name)) rank = std::atoi(value);
    }
    [[noreturn]] void abort(int status) const {
        std::_Exit(status);
    }
    int launched = 1;  ///< processes mpirun started (this build runs alone)
#endif
    Processes(const Processes&) = delete;
    Processes& operator=(const Processes&) = delete;
};

int main(int argc, char** argv) {
    Processes processes(argc, argv);
    // A file-size limit (ulimit -f) is a failed write with its own message, not a kill.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app{"gsph-solve: total Lagrangian GSPH solver"};
    app.set_version_flag("--version", gsph::kVersion);
    std::string casePath, runDir, particles, restart;
    int threads = 0;
    long stopAfterSteps = 0;
    app.add_option("case", casePath, "case file (TOML)")->required();
    app.add_option("-o,--output", runDir, "run folder (default: run/<case name>)");
    app.add_option("--particles", particles,
                   "particle file, instead of the case's [run] particles");
    app.add_option("--threads", threads, "OpenMP threads (default: OMP_NUM_THREADS or all cores)")
        ->check(CLI::Range(1, 1024));
    app.add_option("--restart", restart,
                   "continue the run from this checkpoint (same case and particle file)");
    double endTime = 0.0, outputInterval = 0.0, checkpointInterval = -1.0;
    app.add_option("--end-time", endTime,
                   "T [s]: instead of the case's end_time; with --restart, continues a finished "
                   "(or stopped) run to T")
        ->check(CLI::PositiveNumber);
    app.add_option("--output-interval", outputInterval,
                   "[s] between snapshots, instead of the case's output_interval (also on a "
                   "restart: the schedule continues from the checkpoint's time)")
        ->check(CLI::PositiveNumber);
    app.add_option("--checkpoint-interval", checkpointInterval,
                   "[s] between checkpoints, instead of the case's (0: only on a signal and at "
                   "the end)")
        ->check(CLI::NonNegativeNumber);
    bool overwrite = false;
    app.add_flag("--overwrite", overwrite,
                 "start afresh in a run folder that holds an earlier run, removing its "
                 "snapshots, checkpoint, history.csv and run.log (without it such a folder is "
                 "refused)");
    app.add_option("--stop-after-steps", stopAfterSteps,
                   "stop as on SIGTERM once the step counter reaches N (for tests)")
        ->check(CLI::PositiveNumber);
    gsph::solver::MaterialPointOptions materialPoint;
    gsph::solver::addMaterialPointOptions(app, materialPoint);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 1;  // --help, --version: 0; a bad option: 1
    }
#ifndef GSPH_MPI
    if (processes.launched > 1) {
        if (processes.rank == 0)
            std::fprintf(stderr,
                         "gsph-solve: error: started as one of %d processes (mpirun), but this "
                         "gsph-solve was built without MPI: each would run the whole case into "
                         "the same folder; run it alone, or build with -DGSPH_MPI=ON "
                         "(docs/mpi.md)\n",
                         processes.launched);
        return kExitError;
    }
#endif
    if (threads > 0) omp_set_num_threads(threads);
    if (materialPoint.requested()) return gsph::solver::runMaterialPoint(materialPoint, runDir);

    gsph::solver::RunLog log;
    gsph::solver::RunOptions options;
    options.log = &log;
    const bool writes = processes.rank == 0;
    log.quiet = !writes;
#ifdef GSPH_MPI
    if (processes.count > 1) options.domain = gsph::makeMpiDomain();
#endif
    options.restart = restart;
    options.stopAfterSteps = stopAfterSteps;
    options.overwrite = overwrite;
    options.stopSignal = gsph::solver::stopSignal;
    options.steppingStarts = gsph::solver::deferStopSignals;
    gsph::solver::installStopHandlers();
    int status = 0;
    gsph::solver::RunSummary summary;
    try {
        gsph::solver::CaseConfig config = gsph::solver::readCaseFile(casePath);
        if (!particles.empty()) config.particles = particles;
        if (endTime > 0.0) config.endTime = endTime;
        if (outputInterval > 0.0) config.outputInterval = outputInterval;
        if (checkpointInterval >= 0.0) config.checkpointInterval = checkpointInterval;
        // Default run folder: the checkpoint's folder on a restart; else run/<name of the
        // case's folder>, or run/<case file stem>.
        const std::string caseName = config.caseFile.parent_path().filename().string();
        options.runDir = !runDir.empty()    ? std::filesystem::path(runDir)
                         : !restart.empty() ? std::filesystem::absolute(restart).parent_path()
                         : caseName.empty() || caseName == "."
                             ? std::filesystem::path("run") / config.caseFile.stem()
                             : std::filesystem::path("run") / caseName;
        // Under mpirun stdout is mpirun's pseudo-terminal even when its output goes to a file:
        // a split run prints plain lines.
        const bool terminal = isatty(STDOUT_FILENO) != 0 && processes.count == 1;
        options.progress = !writes    ? gsph::solver::ProgressBar::Mode::Off
                           : terminal ? gsph::solver::ProgressBar::Mode::Bar
                                      : gsph::solver::ProgressBar::Mode::Lines;
        if (writes) log.open(options.runDir / "run.log", !restart.empty());
        log.add(
            "gsph-solve " + std::string(gsph::kVersion) + ": " + casePath + " -> " +
            options.runDir.string() + " (" + std::to_string(omp_get_max_threads()) + " threads" +
            (processes.count > 1 ? " on each of " + std::to_string(processes.count) + " processes"
                                 : std::string()) +
            ")");
        summary = gsph::solver::runCase(config, options);
    } catch (const gsph::NumericalError& e) {
        // Split, only the process that owns the particle knows it: each says what it saw.
        if (processes.count > 1)
            std::fprintf(stderr, "gsph-solve: process %d: error: %s\n", processes.rank, e.what());
        else
            std::fprintf(stderr, "gsph-solve: error: %s\n", e.what());
        log.record(std::string("error: ") + e.what());
        status = kExitNumerical;
    } catch (const gsph::WriteError& e) {
        const std::filesystem::path kept = options.runDir / gsph::solver::kCheckpointName;
        std::error_code ec;
        const std::string restartHint =
            std::filesystem::exists(kept, ec)
                ? "; the last good checkpoint is kept: restart with --restart " + kept.string()
                : "";
        std::fprintf(stderr, "gsph-solve: error: %s%s\n", e.what(), restartHint.c_str());
        log.record(std::string("error: ") + e.what());
        status = kExitWriteFailed;
    } catch (const std::exception& e) {  // gsph::Error, and e.g. a folder that cannot be made
        // Split, bad input is the same on every process: process 0 says it and ends them all;
        // another process says it only if process 0 has not ended it by then (a fault of its
        // own).
        if (writes) {
            std::fprintf(stderr, "gsph-solve: error: %s\n", e.what());
        } else {
            std::this_thread::sleep_for(std::chrono::seconds(3));
            std::fprintf(stderr, "gsph-solve: process %d: error: %s\n", processes.rank, e.what());
        }
        log.record(std::string("error: ") + e.what());
        status = kExitError;
    }
    if (summary.interrupted && writes) {
        std::fprintf(stderr,
                     "gsph-solve: interrupted by %s at t = %.6e s (step %ld); continue with: "
                     "gsph-solve %s%s --restart %s\n",
                     summary.stopReason.c_str(), summary.time, summary.steps, casePath.c_str(),
                     particles.empty() ? "" : (" --particles " + particles).c_str(),
                     summary.checkpoint.string().c_str());
    }
    if (summary.interrupted) status = kExitInterrupted;
    // A run refused before its first snapshot leaves no log (nor anything else).
    if (log.written() && !flushLog(log)) status = status == 0 ? kExitError : status;
    // Split, the other processes may be waiting for this one: a fault ends them all.
    if (processes.count > 1 && status != 0 && status != kExitInterrupted) processes.abort(status);
    return status;
}
