// SPDX-License-Identifier: MIT
// Checkpoint and restart of gsph-solve as a user runs it: a run interrupted (by
// --stop-after-steps or SIGTERM) and restarted from its checkpoint writes snapshots, history
// and checkpoint bit-identical to an uninterrupted run — every dataset compared bytewise — for
// an elastic case and a Johnson–Cook case with damage and brittle bonds; a restart against a
// changed case or particle file is refused. And the guards: an inverted particle and a
// collapsed time step stop the run with one line naming the particle, after a final snapshot.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include "io/checkpoint.hpp"
#include "io/snapshot.hpp"
#include "support/h5_compare.hpp"
#include "support/sample_run.hpp"
#include "tools/temp_dir.hpp"

namespace gsph {
namespace {

namespace fs = std::filesystem;
using test::quote;
using test::runCommand;
using test::TempDir;

const std::string kSolve = GSPH_SOLVE_EXE;
const fs::path kSampleCase = test::kSourceDir / "cases/graded_bar/case.toml";
constexpr int kExitNumerical = 2;
constexpr int kExitInterrupted = 3;

std::string solve(const fs::path& caseFile, const fs::path& particles, const fs::path& runDir,
                  const std::string& extra = "") {
    return kSolve + " " + quote(caseFile.string()) + " --particles " + quote(particles.string()) +
           " -o " + quote(runDir.string()) + (extra.empty() ? "" : " " + extra);
}

// A gsph-solve command line run by script(1) on a pseudo-terminal of `columns` columns.
test::ProcessResult solveOnTerminal(int columns, const std::string& command) {
    return runCommand("script -qec " +
                      quote("stty cols " + std::to_string(columns) + "; " + command) +
                      " /dev/null");
}

std::string readText(const fs::path& p) {
    return test::slurp(p);
}

// Every snapshot and the checkpoint of run A have a bytewise twin in run B; history.csv and
// probes.csv too.
void expectSameOutputs(const fs::path& a, const fs::path& b, int minimumSnapshots) {
    int snapshots = 0;
    for (const auto& e : fs::directory_iterator(a)) {
        const std::string name = e.path().filename().string();
        if (e.path().extension() != ".h5") continue;
        ASSERT_TRUE(fs::exists(b / name)) << name;
        int datasets = 0;
        EXPECT_EQ(test::differingDatasets(e.path(), b / name, &datasets), "") << name;
        EXPECT_GE(datasets, 10) << name;
        snapshots += name.rfind("snapshot_", 0) == 0;
    }
    EXPECT_GE(snapshots, minimumSnapshots);
    EXPECT_EQ(readText(a / "history.csv"), readText(b / "history.csv"));
    EXPECT_EQ(fs::exists(a / "probes.csv"), fs::exists(b / "probes.csv"));
    if (fs::exists(a / "probes.csv")) {
        EXPECT_EQ(readText(a / "probes.csv"), readText(b / "probes.csv"));
    }
}

class Restart : public ::testing::Test {
  protected:
    void SetUp() override {
        particles_ = dir_ / "particles.h5";
        const auto r = test::makeSampleParticles(particles_);
        ASSERT_EQ(r.status, 0) << r.err;
    }
    // A straight through; B stopped after `stopStep` steps, then restarted. Returns the state
    // B stopped in.
    State interruptAndRestart(const fs::path& caseFile, long stopStep) {
        const fs::path a = dir_ / "A", b = dir_ / "B";
        const auto ra = runCommand(solve(caseFile, particles_, a));
        EXPECT_EQ(ra.status, 0) << ra.err;
        EXPECT_EQ(ra.out.find('\r'), std::string::npos) << "no progress bar into a pipe";
        const auto rb = runCommand(
            solve(caseFile, particles_, b, "--stop-after-steps " + std::to_string(stopStep)));
        EXPECT_EQ(rb.status, kExitInterrupted) << rb.err;
        EXPECT_EQ(std::count(rb.err.begin(), rb.err.end(), '\n'), 1) << rb.err;
        EXPECT_NE(rb.err.find("interrupted by --stop-after-steps"), std::string::npos) << rb.err;
        EXPECT_NE(rb.err.find("--restart " + (b / "checkpoint.h5").string()), std::string::npos)
            << rb.err;
        const Checkpoint c = readCheckpoint(b / "checkpoint.h5");
        EXPECT_EQ(c.state.step, stopStep);
        const auto rr = runCommand(kSolve + " " + quote(caseFile.string()) + " --particles " +
                                   quote(particles_.string()) + " --restart " +
                                   quote((b / "checkpoint.h5").string()));
        EXPECT_EQ(rr.status, 0) << rr.err;
        EXPECT_NE(rr.out.find("restart from"), std::string::npos) << rr.out;
        expectSameOutputs(a, b, 6);
        return c.state;
    }
    TempDir dir_;
    fs::path particles_;
};

TEST_F(Restart, ElasticRunInterruptedAndRestartedIsBitIdentical) {
    // 320 steps in all; step 150 lies between the snapshots at steps 128 and 160.
    interruptAndRestart(kSampleCase, 150);
}

// Johnson–Cook steel with damage and brittle bonds, its end pulled at 200 m/s: plastic flow,
// failing particles and broken bonds all happen before the interruption and after it.
const char* kJohnsonCookCase = R"([run]
particles = "particles.h5"
end_time = 2.0e-5
output_interval = 4.0e-6

[[material]]
name = "metal"
model = "johnson_cook"
density = 7850.0
youngs_modulus = 200.0e9
poisson_ratio = 0.3
yield_stress = 200.0e6
hardening_modulus = 300.0e6
hardening_exponent = 0.3
strain_rate_coefficient = 0.01
reference_strain_rate = 1.0
thermal_softening_exponent = 1.0
melting_temperature = 1800.0
specific_heat = 450.0
damage = [0.0, 0.02, 0.0, 0.0, 0.0]
bond_stretch = 0.05

[[body]]
group = "bar"
material = "metal"

[[set]]
name = "clamp"
fixed = true

[[set]]
name = "load"
velocity = [200.0, 0.0, 0.0]

[[probe]]
name = "middle"
point = [0.05, 0.0, 0.0]

[[probe]]
name = "first"
particle = 0
)";

TEST_F(Restart, JohnsonCookRunWithDamageAndBrokenBondsIsBitIdentical) {
    const fs::path caseFile = dir_ / "jc.toml";
    std::ofstream(caseFile) << kJohnsonCookCase;
    const State stopped = interruptAndRestart(caseFile, 100);
    EXPECT_TRUE(fs::exists(dir_ / "B/probes.csv"));
    const auto broken = [](const std::vector<std::uint8_t>& intact) {
        return std::count(intact.begin(), intact.end(), std::uint8_t{0}) / 2;
    };
    EXPECT_GT(*std::max_element(stopped.plasticWork.begin(), stopped.plasticWork.end()), 0.0);
    EXPECT_GT(stopped.ledger.damageDissipation, 0.0);
    const Snapshot last = readSnapshot(dir_ / "B/snapshot_000005.h5");
    EXPECT_NEAR(last.state.time, 2e-5, 1e-15);
    double damage = 0.0, plastic = 0.0;
    for (Index a = 0; a < last.size(); ++a) {
        damage = std::max(damage, last.state.damage[static_cast<std::size_t>(a)]);
        plastic = std::max(plastic, last.state.plasticStrain[static_cast<std::size_t>(a)]);
    }
    EXPECT_GE(damage, 1.0) << "particles failed";
    EXPECT_GT(plastic, 0.01);
    EXPECT_GT(static_cast<long>(last.brokenBonds.size()), broken(stopped.bondIntact))
        << "bonds broke after the restart";
    EXPECT_GT(broken(stopped.bondIntact), 0) << "bonds broke before the interruption";
}

// The bar flying into a rigid wall with friction, under gravity and a force on one set: the
// wall's push and friction, the loads' work and the contact energy carry across the restart.
const char* kWallCase = R"([run]
particles = "particles.h5"
end_time = 4.0e-5
output_interval = 4.0e-6
gravity = [0.0, 0.0, -9.81]

[[material]]
name = "steel"
model = "elastic"
density = 7850.0
youngs_modulus = 200.0e9
poisson_ratio = 0.3

[[body]]
group = "bar"
material = "steel"
velocity = [-20.0, 0.0, 1.0]

[[set]]
name = "load"
force = [0.0, 50.0, 0.0]

[[wall]]
name = "anvil"
point = [-1.0e-4, 0.0, 0.0]
normal = [1.0, 0.0, 0.0]
friction = 0.3
)";

TEST_F(Restart, WallGravityAndSetForceRunIsBitIdentical) {
    const fs::path caseFile = dir_ / "wall.toml";
    std::ofstream(caseFile) << kWallCase;
    const State stopped = interruptAndRestart(caseFile, 150);
    EXPECT_GT(stopped.ledger.contactEnergy, 0.0) << "the bar presses on the wall at the stop";
    const Snapshot last = readSnapshot(dir_ / "B/snapshot_000010.h5");
    double momentumX = 0.0;
    for (Index a = 0; a < last.size(); ++a)
        momentumX += last.state.v[static_cast<std::size_t>(a)].x();
    EXPECT_GT(momentumX, 0.0) << "the wall turned the bar round after the restart";
}

TEST_F(Restart, SigtermWritesACheckpointThatContinuesTheRunExactly) {
    // A long run, stopped by SIGTERM once it is stepping (its first snapshot exists, so the
    // handler is installed); then A runs straight to 40 steps past that point and B restarts
    // from the checkpoint to the same step: both stop there with identical files.
    const fs::path caseFile = dir_ / "long.toml";
    std::string text = readText(kSampleCase);
    text.replace(text.find("end_time = 3.0e-5"), 17, "end_time = 3.0e-3");
    std::ofstream(caseFile) << text;
    const fs::path b = dir_ / "B";
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        const std::string command = "exec " + solve(caseFile, particles_, b) + " > " +
                                    quote((dir_ / "b.out").string()) + " 2> " +
                                    quote((dir_ / "b.err").string());
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    for (int i = 0; i < 6000 && !fs::exists(b / "snapshot_000000.h5"); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(fs::exists(b / "snapshot_000000.h5"));
    kill(pid, SIGTERM);
    int raw = 0;
    waitpid(pid, &raw, 0);
    ASSERT_TRUE(WIFEXITED(raw));
    const std::string err = readText(dir_ / "b.err");
    EXPECT_EQ(WEXITSTATUS(raw), kExitInterrupted) << err;
    EXPECT_NE(err.find("gsph-solve: interrupted by SIGTERM"), std::string::npos) << err;
    EXPECT_NE(err.find("--restart"), std::string::npos) << err;
    const Checkpoint c = readCheckpoint(b / "checkpoint.h5");
    ASSERT_GT(c.state.step, 0);
    EXPECT_LT(c.state.time, 3e-3);
    const std::string stop = "--stop-after-steps " + std::to_string(c.state.step + 40);
    const auto ra = runCommand(solve(caseFile, particles_, dir_ / "A", stop));
    ASSERT_EQ(ra.status, kExitInterrupted) << ra.err;
    const auto rb = runCommand(kSolve + " " + quote(caseFile.string()) + " --particles " +
                               quote(particles_.string()) + " --restart " +
                               quote((b / "checkpoint.h5").string()) + " " + stop);
    ASSERT_EQ(rb.status, kExitInterrupted) << rb.err;
    expectSameOutputs(dir_ / "A", b, 2);
}

TEST_F(Restart, RefusesAChangedCaseOrParticleFile) {
    const fs::path b = dir_ / "B";
    ASSERT_EQ(runCommand(solve(kSampleCase, particles_, b, "--stop-after-steps 50")).status,
              kExitInterrupted);
    const fs::path checkpoint = b / "checkpoint.h5";
    const std::string logBefore = readText(b / "run.log");
    // The same case with another Courant number.
    const fs::path changed = dir_ / "changed.toml";
    std::string text = readText(kSampleCase);
    text.replace(text.find("cfl = 0.3"), 9, "cfl = 0.2");
    std::ofstream(changed) << text;
    auto r = runCommand(kSolve + " " + quote(changed.string()) + " --particles " +
                        quote(particles_.string()) + " --restart " + quote(checkpoint.string()));
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(checkpoint.string() + ": case file '" + changed.string() +
                         "' differs from the one the checkpoint was written with"),
              std::string::npos)
        << r.err;
    // Other particles (another resolution of the same bar).
    const fs::path other = dir_ / "other.h5";
    ASSERT_EQ(runCommand(std::string(GSPH_PREPROC_EXE) + " " +
                         quote((test::kSourceDir / "geometries/graded_bar.geo").string()) +
                         " --set L=0.12 -o " + quote(other.string()))
                  .status,
              0);
    r = runCommand(kSolve + " " + quote(kSampleCase.string()) + " --particles " +
                   quote(other.string()) + " --restart " + quote(checkpoint.string()));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("particles file '" + other.string() + "' differs"), std::string::npos)
        << r.err;
    // Not a checkpoint.
    r = runCommand(kSolve + " " + quote(kSampleCase.string()) + " --particles " +
                   quote(particles_.string()) + " --restart " + quote(particles_.string()));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find(particles_.string() + ": not a gsph-checkpoint file"), std::string::npos)
        << r.err;
    // Refused restarts leave the run folder as it was.
    EXPECT_EQ(readText(b / "run.log"), logBefore);
}

// The sample bar with its end driven at `speed` into it: a shock far faster than the bar's
// wave speed (5.9 km/s) crushes the first particles.
fs::path crushedBarCase(const TempDir& dir, const std::string& name, const std::string& speed,
                        const std::string& runKeys) {
    std::string text = readText(kSampleCase);
    text.replace(text.find("velocity = [-5.0, 0.0, 0.0]"), 27,
                 "velocity = [-" + speed + ", 0.0, 0.0]");
    text.replace(text.find("cfl = 0.3"), 9, runKeys);
    const fs::path p = dir / name;
    std::ofstream(p) << text;
    return p;
}

long particleNamedIn(const std::string& err) {
    std::smatch m;
    const std::regex pattern("particle ([0-9]+) at X = \\(");
    return std::regex_search(err, m, pattern) ? std::stol(m[1]) : -1;
}

// A checkpoint records the run's mass basis, and a restart continues with it: one written
// before the record held it (when the default was "quadrature") continues as a quadrature run
// although the case, unchanged, now selects "normalized" by default. Made here from a run of
// the case with mass = "quadrature" stopped at step 150, its record then given the default
// case's inputs and stripped of the basis; the restart with the default case must end as the
// quadrature run run straight through, every snapshot's dataset bytewise.
TEST_F(Restart, AnOlderCheckpointContinuesWithTheMassBasisOfItsRun) {
    const fs::path quadratureCase = dir_ / "quadrature.toml";
    std::string text = readText(kSampleCase);
    const std::size_t run = text.find("[run]\n");
    ASSERT_NE(run, std::string::npos);
    text.insert(run + 6, "mass = \"quadrature\"\n");
    std::ofstream(quadratureCase) << text;
    const fs::path a = dir_ / "A", b = dir_ / "B", defaults = dir_ / "defaults";
    ASSERT_EQ(runCommand(solve(quadratureCase, particles_, a)).status, 0);
    ASSERT_EQ(runCommand(solve(quadratureCase, particles_, b, "--stop-after-steps 150")).status,
              kExitInterrupted);
    ASSERT_EQ(runCommand(solve(kSampleCase, particles_, defaults, "--stop-after-steps 1")).status,
              kExitInterrupted);
    const Checkpoint current = readCheckpoint(defaults / "checkpoint.h5");
    ASSERT_EQ(current.run.texts.count("mass"), 1u);
    EXPECT_EQ(current.run.texts.at("mass"), "normalized");

    Checkpoint older = readCheckpoint(b / "checkpoint.h5");
    EXPECT_EQ(older.run.texts.at("mass"), "quadrature");
    older.run.texts.erase("mass");
    older.run.inputs = current.run.inputs;
    writeCheckpoint(b / "checkpoint.h5", older.state, older.run, older.provenance);
    const auto r = runCommand(kSolve + " " + quote(kSampleCase.string()) + " --particles " +
                              quote(particles_.string()) + " --restart " +
                              quote((b / "checkpoint.h5").string()));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("mass = \"quadrature\" as the checkpoint's run (the case's is "
                         "\"normalized\")"),
              std::string::npos)
        << r.out;
    // The continued run records the basis it kept; its final checkpoint differs from A's only
    // in the case it names (the inputs), so the snapshots and history are compared.
    EXPECT_EQ(readCheckpoint(b / "checkpoint.h5").run.texts.at("mass"), "quadrature");
    fs::remove(a / "checkpoint.h5");
    fs::remove(b / "checkpoint.h5");
    expectSameOutputs(a, b, 6);
}

TEST_F(Restart, InvertedParticleStopsTheRunNamingIt) {
    // 10 km/s at a Courant number of 0.9: within a step the shock folds a particle (J ≤ 0).
    // (With the viscosity's compression switch the driven layer is crushed ever thinner
    // instead, the case of the next test: the constant coefficients keep this one.)
    const fs::path caseFile = crushedBarCase(dir_, "inverted.toml", "1.0e4",
                                             "cfl = 0.9\nmin_dt_ratio = 0\nviscosity_switch = 0");
    const auto r = runCommand(solve(caseFile, particles_, dir_ / "run"));
    EXPECT_EQ(r.status, kExitNumerical) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("gsph-solve: error: inverted particle (J ≤ 0): particle "),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find(" m, t = "), std::string::npos) << r.err;
    const long a = particleNamedIn(r.err);
    ASSERT_GE(a, 0) << r.err;
    // The final snapshot holds the failing state: the named particle's F has det F ≤ 0.
    fs::path last;
    for (const auto& e : fs::directory_iterator(dir_ / "run"))
        if (e.path().filename().string().rfind("snapshot_", 0) == 0 && e.path() > last)
            last = e.path();
    const Snapshot s = readSnapshot(last);
    EXPECT_GT(s.state.time, 0.0);
    EXPECT_LE(s.state.F[static_cast<std::size_t>(a)].determinant(), 0.0);
    EXPECT_NE(readText(dir_ / "run/run.log").find("error: inverted particle"), std::string::npos);
}

TEST_F(Restart, CollapsedTimeStepStopsTheRunNamingTheParticle) {
    // 20 km/s: the driven layer is crushed ever thinner and Δt with it (the CFL step keeps it
    // from folding); the default min_dt_ratio = 1e-3 stops the run.
    const fs::path caseFile = crushedBarCase(dir_, "collapse.toml", "2.0e4", "cfl = 0.3");
    const auto r = runCommand(solve(caseFile, particles_, dir_ / "run"));
    EXPECT_EQ(r.status, kExitNumerical) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    std::smatch m;
    const std::regex pattern(
        "time step collapsed: Δt = ([-+.e0-9]+) s, below 0.001 × Δt0 \\(Δt0 = ([-+.e0-9]+) s");
    ASSERT_TRUE(std::regex_search(r.err, m, pattern)) << r.err;
    EXPECT_LT(std::stod(m[1]), 1e-3 * std::stod(m[2]));
    EXPECT_GE(particleNamedIn(r.err), 0) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "run/snapshot_000001.h5")) << "final snapshot";
}

TEST_F(Restart, FinishedRunExtendedByEndTimeEqualsAStraightRun) {
    // A to 60 µs straight; B to the case's 30 µs, then continued with --end-time 60 µs from
    // the checkpoint a finished run ends with.
    const fs::path a = dir_ / "A", b = dir_ / "B";
    ASSERT_EQ(runCommand(solve(kSampleCase, particles_, a, "--end-time 6e-5")).status, 0);
    ASSERT_EQ(runCommand(solve(kSampleCase, particles_, b)).status, 0);
    const fs::path checkpoint = b / "checkpoint.h5";
    EXPECT_NEAR(readCheckpoint(checkpoint).state.time, 3e-5, 1e-18);
    const std::string restart = kSolve + " " + quote(kSampleCase.string()) + " --particles " +
                                quote(particles_.string()) + " --restart " +
                                quote(checkpoint.string());
    const auto done = runCommand(restart);
    EXPECT_EQ(done.status, 1) << "already at its end";
    EXPECT_NE(done.err.find("give a later --end-time to continue it"), std::string::npos)
        << done.err;
    const auto extended = runCommand(restart + " --end-time 6e-5");
    ASSERT_EQ(extended.status, 0) << extended.err;
    expectSameOutputs(a, b, 20);
}

TEST_F(Restart, ARestartMayChangeTheOutputInterval) {
    const fs::path b = dir_ / "B";
    ASSERT_EQ(runCommand(solve(kSampleCase, particles_, b, "--stop-after-steps 150")).status,
              kExitInterrupted);
    const Checkpoint c = readCheckpoint(b / "checkpoint.h5");
    // Snapshots every 6 µs from the checkpoint's time on (instead of 3 µs).
    const auto r = runCommand(kSolve + " " + quote(kSampleCase.string()) + " --particles " +
                              quote(particles_.string()) + " --restart " +
                              quote((b / "checkpoint.h5").string()) + " --output-interval 6e-6");
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<double> times;
    for (int k = 0;; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "snapshot_%06d.h5", k);
        if (!fs::exists(b / name)) break;
        times.push_back(readSnapshot(b / name).state.time);
    }
    ASSERT_GE(times.size(), 3u);
    EXPECT_NEAR(times.back(), 3e-5, 1e-15);
    for (std::size_t k = 1; k < times.size(); ++k) {
        if (times[k - 1] < c.state.time) continue;
        EXPECT_NEAR(times[k] - times[k - 1], 6e-6, 1e-12) << k;
    }
}

TEST_F(Restart, ProgressBarShowsOnATerminal) {
    // script(1) runs the solver on a pseudo-terminal: the bar shows simulated time against the
    // end time, both rates and the ETA (in a pipe it stays quiet: interruptAndRestart).
    const auto onTerminal = [&](int columns, const std::string& name) {
        return solveOnTerminal(columns, solve(kSampleCase, particles_, dir_ / name));
    };
    const auto r = onTerminal(160, "tty");
    ASSERT_EQ(r.status, 0) << r.err;
    std::smatch m;
    const std::regex bar(
        "\\r\\[#* *\\] +[0-9.]+%  t = [-+.e0-9]+ / 3\\.000e-05 s  [0-9]+ steps/s  "
        "[-+.e0-9]+ particle-steps/s  ETA [0-9]+ s");
    EXPECT_TRUE(std::regex_search(r.out, m, bar)) << r.out.substr(0, 2000);
    EXPECT_NE(r.out.find("done: t = 3.0000e-05 s"), std::string::npos);
    // On a narrow terminal every redraw fits in one line (no wrapping, no stacked copies).
    const auto narrow = onTerminal(50, "narrow");
    ASSERT_EQ(narrow.status, 0) << narrow.err;
    int bars = 0;
    std::size_t from = 0;
    for (std::size_t at = narrow.out.find('\r'); at != std::string::npos;
         from = at + 1, at = narrow.out.find('\r', from)) {
        const std::size_t end = narrow.out.find_first_of("\r\n\033", at + 1);
        const std::string line = narrow.out.substr(at + 1, end - at - 1);
        if (line.find('%') == std::string::npos) continue;
        ++bars;
        EXPECT_LE(line.size(), 49u) << line;
        EXPECT_NE(line.find("ETA"), std::string::npos) << line;
    }
    EXPECT_GT(bars, 0) << narrow.out.substr(0, 2000);
}

TEST_F(Restart, OversetSetUpShowsTheInterfaceWeightsSolveOnATerminal) {
    // The quick start's O-grid, coarser: its band's interface weights are solved during set-up,
    // and the bar's line follows the solve's iterations (the first one drawn at once) and fits
    // a narrow terminal; into a pipe nothing of it (a line a minute only).
    const fs::path ogrid = dir_ / "ogrid.h5";
    const auto made = runCommand(std::string(GSPH_PREPROC_EXE) + " " +
                                 quote((test::kSourceDir / "geometries/taylor_bar.geo").string()) +
                                 " --set n=4 --set nr=2 --set nz=12 -o " + quote(ogrid.string()));
    ASSERT_EQ(made.status, 0) << made.err;
    const fs::path taylor = test::kSourceDir / "cases/taylor_bar/case.toml";
    const auto onTerminal = [&](int columns, const std::string& name) {
        return solveOnTerminal(columns, solve(taylor, ogrid, dir_ / name, "--end-time 2e-7"));
    };
    const auto r = onTerminal(160, "tty");
    ASSERT_EQ(r.status, 0) << r.err;
    std::smatch m;
    const std::regex first(
        "\\rset-up: overset interface weights, CG iteration 1, residual "
        "[-+.e0-9]+ \\(to 1e-14\\)");
    EXPECT_TRUE(std::regex_search(r.out, m, first)) << r.out.substr(0, 2000);
    const auto narrow = onTerminal(50, "narrow");
    ASSERT_EQ(narrow.status, 0) << narrow.err;
    int lines = 0;
    for (std::size_t at = narrow.out.find("\rset-up:"); at != std::string::npos;
         at = narrow.out.find("\rset-up:", at + 1), ++lines) {
        const std::size_t end = narrow.out.find_first_of("\r\n\033", at + 1);
        EXPECT_LE(end - at - 1, 49u) << narrow.out.substr(at + 1, end - at - 1);
    }
    EXPECT_GT(lines, 0) << narrow.out.substr(0, 2000);
    const auto piped = runCommand(solve(taylor, ogrid, dir_ / "pipe", "--end-time 2e-7"));
    ASSERT_EQ(piped.status, 0) << piped.err;
    EXPECT_EQ(piped.out.find("set-up: overset"), std::string::npos) << piped.out;
}

}  // namespace
}  // namespace gsph
