// SPDX-License-Identifier: MIT
// Nothing lost, nothing corrupted: the tools as a careless or unlucky user runs them. A write
// that fails (a file-size limit, RLIMIT_FSIZE: the tools ignore SIGXFSZ, so a write past it
// fails with EFBIG as one on a full disk fails with ENOSPC)
// stops the run with exit status 4 and one line naming the file and the system's reason, keeps
// the last good checkpoint, and a restart from it ends bytewise equal to a straight run; a
// restart exactly on a snapshot's step keeps the walls' forces in history.csv; a fresh run
// refuses a folder that holds an earlier run; a killed process's temporary files are cleared;
// gsph-preproc refuses to overwrite its input, --set parameters the .geo does not declare, and
// meshes too large for the machine; a crash inside gmsh is an error of ours.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "io/checkpoint.hpp"
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
const std::string kPreproc = GSPH_PREPROC_EXE;
const std::string kPost = GSPH_POST_EXE;
const fs::path kGeometries = test::kSourceDir / "geometries";
constexpr int kExitError = 1;
constexpr int kExitInterrupted = 3;
constexpr int kExitWriteFailed = 4;

// The graded bar struck at one end, with a checkpoint between every two snapshots.
const char* kBarCase = R"([run]
particles = "particles.h5"
end_time = 3.0e-5
output_interval = 3.0e-6
checkpoint_interval = 1.5e-6

[[material]]
name = "steel"
density = 7850.0
youngs_modulus = 200.0e9
poisson_ratio = 0.3

[[body]]
group = "bar"
material = "steel"

[[set]]
name = "load"
velocity = [-5.0, 0.0, 0.0]
)";

// The bar flying onto a rigid wall: its force is a history column.
const char* kWallCase = R"([run]
particles = "particles.h5"
end_time = 2.0e-5
output_interval = 4.0e-6

[[material]]
name = "steel"
density = 7850.0
youngs_modulus = 200.0e9
poisson_ratio = 0.3

[[body]]
group = "bar"
material = "steel"
velocity = [-20.0, 0.0, 0.0]

[[wall]]
name = "anvil"
point = [-1.0e-4, 0.0, 0.0]
normal = [1.0, 0.0, 0.0]
)";

class Durability : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto r = test::makeSampleParticles(dir_ / "particles.h5");
        ASSERT_EQ(r.status, 0) << r.err;
    }
    fs::path writeCase(const std::string& name, const char* text) {
        const fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p;
    }
    static std::string solve(const fs::path& caseFile, const fs::path& runDir,
                             const std::string& extra = "") {
        return kSolve + " " + quote(caseFile.string()) + " -o " + quote(runDir.string()) +
               (extra.empty() ? "" : " " + extra);
    }
    // Every .h5 file and history.csv of run A equal bytewise (dataset by dataset) in B.
    static void expectSameRun(const fs::path& a, const fs::path& b) {
        int files = 0;
        for (const auto& e : fs::directory_iterator(a)) {
            if (e.path().extension() != ".h5") continue;
            const fs::path twin = b / e.path().filename();
            ASSERT_TRUE(fs::exists(twin)) << twin;
            EXPECT_EQ(test::differingDatasets(e.path(), twin), "") << twin;
            ++files;
        }
        EXPECT_GE(files, 11);
        EXPECT_EQ(test::slurp(a / "history.csv"), test::slurp(b / "history.csv"));
    }
    static int hiddenTemporaries(const fs::path& folder) {
        int n = 0;
        for (const auto& e : fs::directory_iterator(folder))
            n += e.path().filename().string().find(".tmp-") != std::string::npos;
        return n;
    }
    TempDir dir_;
};

TEST_F(Durability, FailedCheckpointWriteKeepsTheLastGoodOneAndItRestartsExactly) {
    const fs::path caseFile = writeCase("bar.toml", kBarCase);
    const fs::path straight = dir_ / "straight", run = dir_ / "run";
    ASSERT_EQ(runCommand(solve(caseFile, straight)).status, 0);
    const auto first = runCommand(solve(caseFile, run, "--stop-after-steps 100"));
    ASSERT_EQ(first.status, kExitInterrupted) << first.err;
    const fs::path checkpoint = run / "checkpoint.h5";
    const std::string good = test::slurp(checkpoint);
    // Any file larger than the good checkpoint fails to write: the next checkpoint (its
    // history holds more rows) does; snapshots (98 kB against 120 kB) do not.
    const auto limitKb = static_cast<long>(good.size() / 1024);
    const auto limited =
        runCommand("bash -c " + quote("ulimit -f " + std::to_string(limitKb) + "; exec " +
                                      solve(caseFile, run, "--restart " + checkpoint.string())));
    EXPECT_EQ(limited.status, kExitWriteFailed) << limited.err;
    EXPECT_EQ(std::count(limited.err.begin(), limited.err.end(), '\n'), 1) << limited.err;
    EXPECT_NE(limited.err.find(checkpoint.string() + ": write failed"), std::string::npos)
        << limited.err;
    EXPECT_NE(limited.err.find("File too large"), std::string::npos) << limited.err;
    EXPECT_NE(limited.err.find("the last good checkpoint is kept"), std::string::npos)
        << limited.err;
    EXPECT_EQ(test::slurp(checkpoint), good) << "the good checkpoint is untouched";
    EXPECT_EQ(hiddenTemporaries(run), 0) << "the failed write left nothing behind";
    EXPECT_EQ(readCheckpoint(checkpoint).state.step, 100);
    const auto resumed = runCommand(solve(caseFile, run, "--restart " + checkpoint.string()));
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    expectSameRun(straight, run);
}

TEST_F(Durability, FailedSnapshotWriteStopsTheRunAndKeepsTheEarlierFiles) {
    const fs::path caseFile = writeCase("bar.toml", kBarCase);
    const fs::path run = dir_ / "run";
    // 90 kB: the snapshots (98 kB) cannot be written, history.csv and run.log can.
    const auto r = runCommand("bash -c " + quote("ulimit -f 90; exec " + solve(caseFile, run)));
    EXPECT_EQ(r.status, kExitWriteFailed) << r.err;
    EXPECT_NE(r.err.find((run / "snapshot_000000.h5").string() + ": write failed"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(run / "snapshot_000000.h5"));
    EXPECT_EQ(hiddenTemporaries(run), 0);
}

TEST_F(Durability, RestartOnASnapshotStepKeepsTheWallForceInTheHistory) {
    const fs::path caseFile = writeCase("wall.toml", kWallCase);
    const fs::path straight = dir_ / "straight", run = dir_ / "run";
    ASSERT_EQ(runCommand(solve(caseFile, straight)).status, 0);
    // The step that lands on the snapshot at t = 8 µs, when the bar presses on the wall.
    std::istringstream rows(test::slurp(straight / "history.csv"));
    std::string row;
    long step = 0;
    while (std::getline(rows, row))
        if (row.rfind("8.000000000e-06,", 0) == 0) step = std::stol(row.substr(16));
    ASSERT_GT(step, 0);
    const auto stopped =
        runCommand(solve(caseFile, run, "--stop-after-steps " + std::to_string(step)));
    ASSERT_EQ(stopped.status, kExitInterrupted) << stopped.err;
    ASSERT_EQ(
        runCommand(solve(caseFile, run, "--restart " + (run / "checkpoint.h5").string())).status,
        0);
    const std::string history = test::slurp(run / "history.csv");
    EXPECT_EQ(history, test::slurp(straight / "history.csv"));
    EXPECT_EQ(history.find("8.000000000e-06," + std::to_string(step) + ",") != std::string::npos,
              true);
}

TEST_F(Durability, AFreshRunRefusesAFolderWithAnEarlierRunUnlessOverwritten) {
    const fs::path longer = writeCase("bar.toml", kBarCase);
    const fs::path run = dir_ / "run";
    ASSERT_EQ(runCommand(solve(longer, run)).status, 0);
    const std::string lastSnapshot = test::slurp(run / "snapshot_000010.h5");
    const auto refused = runCommand(solve(longer, run));
    EXPECT_EQ(refused.status, kExitError) << refused.err;
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
    EXPECT_NE(refused.err.find("holds an earlier run"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("--overwrite"), std::string::npos) << refused.err;
    EXPECT_EQ(test::slurp(run / "snapshot_000010.h5"), lastSnapshot) << "nothing was touched";
    // A shorter run with --overwrite leaves none of the longer run's snapshots behind.
    std::string shorter = kBarCase;
    shorter.replace(shorter.find("end_time = 3.0e-5"), 17, "end_time = 1.5e-5");
    const fs::path shortCase = dir_ / "short.toml";
    std::ofstream(shortCase) << shorter;
    const auto replaced = runCommand(solve(shortCase, run, "--overwrite"));
    ASSERT_EQ(replaced.status, 0) << replaced.err;
    EXPECT_TRUE(fs::exists(run / "snapshot_000005.h5"));
    EXPECT_FALSE(fs::exists(run / "snapshot_000006.h5"));
}

TEST_F(Durability, TemporaryFilesOfAKilledProcessAreCleared) {
    const fs::path caseFile = writeCase("bar.toml", kBarCase);
    const fs::path run = dir_ / "run";
    ASSERT_EQ(runCommand(solve(caseFile, run, "--stop-after-steps 50")).status, kExitInterrupted);
    // What kill -9 during a checkpoint leaves: a hidden temporary of a process that is gone
    // (no process has an id above the kernel's pid_max, 2^22 at most).
    const fs::path stale = run / ".checkpoint.h5.tmp-99999999-0";
    std::ofstream(stale) << "half a checkpoint";
    const auto r =
        runCommand(solve(caseFile, run, "--restart " + (run / "checkpoint.h5").string()));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_NE(r.out.find("removed 1 temporary file(s)"), std::string::npos) << r.out;
}

TEST_F(Durability, ParticleFilesThatFaultInsideHdf5AreOneLineErrors) {
    // The fuzzers' particle files that crash HDF5 1.10.8's own parser or make it allocate
    // without bound (tests/fuzz/third_party_findings; the one that hangs is stopped by the
    // reader's deadline, 60 s, and left out here for time): the reader runs in a child process.
    const fs::path caseFile = writeCase("bar.toml", kBarCase);
    const fs::path findings = test::kSourceDir / "tests/fuzz/third_party_findings";
    for (const char* name : {"hdf5_H5HG_read_segv.h5", "hdf5_H5C_protect_allocation_too_big.h5",
                             "hdf5_H5O_msg_iterate_heap_overflow.h5"}) {
        const auto r = runCommand(
            solve(caseFile, dir_ / name, "--particles " + quote((findings / name).string())));
        EXPECT_EQ(r.status, kExitError) << name << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find((findings / name).string()), std::string::npos) << r.err;
    }
    const auto segv =
        runCommand(solve(caseFile, dir_ / "segv",
                         "--particles " + quote((findings / "hdf5_H5HG_read_segv.h5").string())));
    EXPECT_NE(segv.err.find("crashed or hung HDF5's reader (signal 11"), std::string::npos)
        << segv.err;
}

TEST(PreprocDurability, RefusesToOverwriteItsInput) {
    TempDir dir;
    const fs::path mesh = dir / "bar.geo";
    fs::copy_file(kGeometries / "graded_bar.geo", mesh);
    const std::string before = test::slurp(mesh);
    const auto r =
        runCommand(kPreproc + " " + quote(mesh.string()) + " -o " + quote(mesh.string()));
    EXPECT_EQ(r.status, kExitError) << r.err;
    EXPECT_NE(r.err.find("is the input file itself"), std::string::npos) << r.err;
    EXPECT_EQ(test::slurp(mesh), before);
}

TEST(PreprocDurability, AFailedWriteKeepsTheEarlierParticleFile) {
    TempDir dir;
    const fs::path out = dir / "p.h5";
    ASSERT_EQ(test::makeSampleParticles(out).status, 0);
    const std::string good = test::slurp(out);
    // The finer bar's file (215 kB) cannot be written under a 100 kB file-size limit.
    const auto r = runCommand("bash -c " + quote("ulimit -f 100; exec " + kPreproc + " " +
                                                 quote((kGeometries / "graded_bar.geo").string()) +
                                                 " -o " + quote(out.string()) + " --set refine=2"));
    EXPECT_EQ(r.status, kExitWriteFailed) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(out.string() + ": write failed"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
    EXPECT_EQ(test::slurp(out), good);
    EXPECT_EQ(dir.entries(), 1) << "no temporary file left";
}

TEST(PreprocDurability, SetParametersMustReachTheGeometry) {
    TempDir dir;
    const fs::path out = dir / "p.h5";
    const auto bar = quote((kGeometries / "graded_bar.geo").string());
    const auto unknown =
        runCommand(kPreproc + " " + bar + " -o " + quote(out.string()) + " --set nq=3");
    EXPECT_EQ(unknown.status, kExitError) << unknown.err;
    EXPECT_NE(unknown.err.find("--set nq=3: the file has no parameter 'nq'"), std::string::npos)
        << unknown.err;
    EXPECT_NE(unknown.err.find("nx, ny, nz"), std::string::npos) << "it lists the parameters";
    const auto zero =
        runCommand(kPreproc + " " + bar + " -o " + quote(out.string()) + " --set nx=0");
    EXPECT_EQ(zero.status, kExitError) << zero.err;
    EXPECT_NE(zero.err.find("nx = 0"), std::string::npos) << zero.err;
    // A plain assignment in the .geo (not a DefineConstant) cannot be overridden.
    const fs::path plain = dir / "plain.geo";
    std::ofstream(plain) << "n = 2;\nPoint(1) = {0, 0, 0};\nPoint(2) = {1, 0, 0};\n"
                            "Line(1) = {1, 2};\n"
                            "Extrude {0, 1, 0} { Line{1}; Layers{n}; Recombine; }\n"
                            "Extrude {0, 0, 1} { Surface{5}; Layers{n}; Recombine; }\n";
    const auto assigned = runCommand(kPreproc + " " + quote(plain.string()) + " -o " +
                                     quote(out.string()) + " --set n=3");
    EXPECT_EQ(assigned.status, kExitError) << assigned.err;
    EXPECT_NE(assigned.err.find("--set n=3 has no effect: the file assigns n = 2 itself"),
              std::string::npos)
        << assigned.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(PreprocDurability, AMeshTooLargeForTheMachineIsRefusedBeforeMeshing) {
    TempDir dir;
    const auto r = runCommand(kPreproc + " " + quote((kGeometries / "taylor_bar.geo").string()) +
                              " -o " + quote((dir / "p.h5").string()) + " --set refine=200");
    EXPECT_EQ(r.status, kExitError) << r.err;
    // 1 658 880 hexes at refine = 6, (200/6)³ times as many.
    EXPECT_NE(r.err.find("about 6.14e+10 hexahedra"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("GB available"), std::string::npos) << r.err;
}

TEST(PreprocDurability, ACrashInsideGmshIsAClearError) {
    TempDir dir;
    // A progression of ratio 0: gmsh 4.8 dereferences an empty node list (SIGSEGV).
    const fs::path geo = dir / "zero_ratio.geo";
    std::ofstream(geo) << "Point(1) = {0, 0, 0};\nPoint(2) = {1, 0, 0};\nLine(1) = {1, 2};\n"
                          "Transfinite Curve{1} = 5 Using Progression 0;\n"
                          "Extrude {0, 1, 0} { Line{1}; Layers{2}; Recombine; }\n"
                          "Extrude {0, 0, 1} { Surface{5}; Layers{2}; Recombine; }\n";
    const auto r =
        runCommand(kPreproc + " " + quote(geo.string()) + " -o " + quote((dir / "p.h5").string()));
    EXPECT_EQ(r.status, kExitError) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(geo.string() + ": gmsh crashed while reading or meshing it (signal 11"),
              std::string::npos)
        << r.err;
}

TEST(PreprocDurability, MshFilesThatFaultInsideGmshAreOneLineErrors) {
    // The fuzzers' inputs that crash or throw inside gmsh 4.8's own readers
    // (tests/fuzz/third_party_findings): gmsh runs in a child process, so each is our error.
    TempDir dir;
    int files = 0;
    for (const auto& e :
         fs::directory_iterator(test::kSourceDir / "tests/fuzz/third_party_findings")) {
        if (e.path().extension() != ".msh") continue;
        ++files;
        const auto r = runCommand(kPreproc + " " + quote(e.path().string()) + " -o " +
                                  quote((dir / "p.h5").string()));
        EXPECT_EQ(r.status, kExitError) << e.path() << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(e.path().string() + ": "), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir / "p.h5"));
    }
    EXPECT_GE(files, 5);
}

TEST(PostDurability, BadOptionsAndUnwritableOutputsAreOneLineErrors) {
    TempDir dir;
    ASSERT_EQ(test::makeSampleParticles(dir / "particles.h5").status, 0);
    ASSERT_EQ(test::runSampleCase(dir / "particles.h5", dir / "run").status, 0);
    const auto field = runCommand(kPost + " " + quote((dir / "run").string()) + " --field nope");
    EXPECT_EQ(field.status, kExitError) << field.err;
    // /proc takes no new folders, whoever asks (root included).
    const auto unwritable = runCommand(kPost + " " + quote((dir / "run").string()) +
                                       " -o /proc/gsph-post-output --no-pictures");
    EXPECT_EQ(unwritable.status, kExitWriteFailed) << unwritable.err;
    EXPECT_EQ(std::count(unwritable.err.begin(), unwritable.err.end(), '\n'), 1) << unwritable.err;
    EXPECT_NE(unwritable.err.find("/proc/gsph-post-output: cannot create the output folder"),
              std::string::npos)
        << unwritable.err;
}

TEST(PostDurability, SnapshotsThatFaultInsideHdf5AreOneLineErrors) {
    // A run folder whose second snapshot is one of the fuzzers' files that fault inside HDF5
    // 1.10.8's own parser (tests/fuzz/third_party_findings): gsph-post reads snapshots in a
    // child process; each is one line naming the file, exit status 1.
    TempDir dir;
    ASSERT_EQ(test::makeSampleParticles(dir / "particles.h5").status, 0);
    ASSERT_EQ(test::runSampleCase(dir / "particles.h5", dir / "run").status, 0);
    std::vector<fs::path> snapshots;
    for (const auto& e : fs::directory_iterator(dir / "run"))
        if (e.path().filename().string().rfind("snapshot_", 0) == 0) snapshots.push_back(e.path());
    std::sort(snapshots.begin(), snapshots.end());
    ASSERT_GE(snapshots.size(), 2u);
    for (const char* name : {"hdf5_H5HG_read_segv.h5", "hdf5_H5C_protect_allocation_too_big.h5",
                             "hdf5_H5O_msg_iterate_heap_overflow.h5"}) {
        fs::copy_file(test::kSourceDir / "tests/fuzz/third_party_findings" / name, snapshots[1],
                      fs::copy_options::overwrite_existing);
        const auto r = runCommand(kPost + " " + quote((dir / "run").string()) + " --no-pictures");
        EXPECT_EQ(r.status, kExitError) << name << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(snapshots[1].string() + ": "), std::string::npos) << r.err;
    }
}

}  // namespace
}  // namespace gsph
