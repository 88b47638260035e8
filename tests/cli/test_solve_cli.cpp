// SPDX-License-Identifier: MIT
// gsph-solve as a user runs it: every bad case file in tests/data/bad_cases gets its own clear
// one-line message naming the file (and the line where there is one) and a non-zero exit; a
// good case runs, writes its files, balances its energy and conserves what it must.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/particle_file.hpp"
#include "io/snapshot.hpp"
#include "materials/stress_measures.hpp"
#include "support/csv.hpp"
#include "support/h5_compare.hpp"
#include "support/sample_run.hpp"
#include "tools/temp_dir.hpp"

namespace gsph {
namespace {

namespace fs = std::filesystem;
using test::readCsv;
using test::runCommand;
using test::TempDir;

const std::string kSolve = GSPH_SOLVE_EXE;
const fs::path kSource = test::kSourceDir;

void makeParticles(const TempDir& dir) {
    const auto r = test::makeSampleParticles(dir / "particles.h5");
    ASSERT_EQ(r.status, 0) << r.err;
}

// The sample bar's material and body (keys of the [[body]] table may follow).
const std::string kSteelBar =
    "[[material]]\nname = \"steel\"\ndensity = 7850.0\nyoungs_modulus = 200.0e9\n"
    "poisson_ratio = 0.3\n"
    "[[body]]\ngroup = \"bar\"\nmaterial = \"steel\"\n";

// Writes `text` as dir/NAME next to the sample particles and solves it into dir/run.
test::ProcessResult solveCaseText(const TempDir& dir, const std::string& name,
                                  const std::string& text) {
    makeParticles(dir);
    const fs::path casePath = dir / name;
    std::ofstream(casePath) << text;
    return runCommand(kSolve + " " + casePath.string() + " -o " + (dir / "run").string());
}

struct BadCase {
    const char* file;
    const char* message;  ///< expected part of the one-line error
    int line;             ///< expected line in "FILE:LINE:", 0 if the message names no line
};

TEST(SolveCli, EveryBadCaseFileGetsItsOwnClearMessage) {
    TempDir dir;
    makeParticles(dir);
    const std::vector<BadCase> cases = {
        {"unknown_key.toml", "unknown key 'end_tme' in [run]", 3},
        {"missing_material.toml", "material 'copper' is not defined", 13},
        {"unknown_set.toml", "set 'clampp' is not in", 15},
        {"bad_poisson.toml", "Poisson's ratio must lie in (-1, 0.5)", 9},
        {"missing_run.toml", "missing table [run]", 1},
        {"syntax_error.toml", "", 7},
        {"unknown_body.toml", "group 'plate' is not a body of", 11},
        {"missing_particles.toml", "no_such_particles.h5", 0},
        {"negative_end_time.toml", "'end_time' in [run] must be > 0", 3},
        {"fixed_and_velocity.toml", "is both fixed and given a velocity", 18},
        {"fixed_bad_axis.toml",
         "'fixed' in [[set]] must be a list of distinct axes \"x\", \"y\", \"z\"", 17},
        {"negative_viscosity_switch.toml", "'viscosity_switch' in [run] must be ≥ 0", 4},
        {"unknown_mass_basis.toml",
         "'mass' in [run] must be \"normalized\", \"quadrature\" or \"mesh\"", 4},
        {"unknown_dimension.toml",
         "'dimension' in [run] must be \"3d\", \"plane_strain\" or \"axisymmetric\"", 4},
        {"unknown_hourglass_modulus.toml",
         "'hourglass_modulus' in [run] must be \"elastic\" or \"secant\", got 'plastic'", 4},
        {"dimension_of_another_file.toml",
         "[run] dimension = \"axisymmetric\" needs a 2-D particle file, and ", 4},
        {"unknown_table.toml", "unknown table 'walls'", 15},
        {"density_not_a_number.toml", "'density' in [[material]] must be a number", 7},
        {"no_body.toml", "no [[body]] defined", 0},
        {"unknown_material_model.toml", "material model 'plastic' is not known", 7},
        {"jc_missing_key.toml", "missing key 'hardening_exponent' in [[material]]", 5},
        {"jc_melting_below_room.toml", "'melting_temperature' in [[material]] must exceed", 18},
        {"unknown_eos.toml", "equation of state 'ideal_gas' is not known", 19},
        {"eos_key_mismatch.toml", "unknown key 'sound_speed' in [[material]] (it belongs to eos",
         20},
        {"damage_not_five.toml", "'damage' in [[material]] must be a list of 5 numbers", 19},
        {"missing_material_file.toml", "material file 'materials/no_such_steel.toml' not found", 7},
        {"file_and_constants.toml", "unknown key 'density' in [[material]] (a [[material]] with",
         8},
        {"negative_bond_stretch.toml", "'bond_stretch' in [[material]] must be ≥ 0", 10},
        {"fracture_energy_without_bond_stretch.toml",
         "'fracture_energy' in [[material]] needs 'bond_stretch' > 0", 10},
        {"negative_checkpoint_interval.toml", "'checkpoint_interval' in [run] must be ≥ 0", 4},
        {"checkpoint_interval_not_a_number.toml", "'checkpoint_interval' in [run] must be a number",
         5},
        {"min_dt_ratio_not_below_one.toml", "'min_dt_ratio' in [run] must be < 1 (0 = off)", 4},
        {"wall_zero_normal.toml", "'normal' in [[wall]] must not be zero", 18},
        {"wall_negative_friction.toml", "'friction' in [[wall]] must be ≥ 0", 18},
        {"wall_missing_point.toml", "missing key 'point' in [[wall]]", 15},
        {"wall_unknown_key.toml", "unknown key 'mu' in [[wall]]", 18},
        {"wall_cylinder_missing_radius.toml", "missing key 'radius' in [[wall]]", 15},
        {"wall_cylinder_with_normal.toml", "'normal' in [[wall]] belongs to shape = \"plane\"", 19},
        {"wall_unknown_shape.toml", "'shape' in [[wall]] must be \"plane\" or \"cylinder\"", 17},
        {"wall_same_columns.toml",
         "wall 'left-roller' has the history columns of wall 'left roller'", 20},
        {"set_force_and_fixed.toml", "set 'load' has a 'force' and a kinematic condition", 18},
        {"contact_negative_penalty.toml", "'penalty' in [contact] must be > 0", 16},
        {"contact_unknown_key.toml", "unknown key 'stiffness' in [contact]", 16},
        {"gravity_not_three.toml", "'gravity' in [run] must be a list of 3 numbers", 4},
        {"precrack_parallel_edges.toml", "'edge1' and 'edge2' in [[precrack]] 'notch' are parallel",
         19},
        {"precrack_missing_corner.toml", "missing key 'corner' in [[precrack]]", 15},
        {"duplicate_body.toml", "[[body]] group 'bar' is given twice (also at line 11)", 16},
        {"body_named_twice.toml",
         "[[body]] group '0' names body 0 ('bar'), which the entry at line 11 ('bar') already "
         "names",
         15},
        {"duplicate_set.toml", "[[set]] 'clamp' is given twice (also at line 15)", 19},
        {"checkpoint_interval_below_dt.toml",
         ": [run] checkpoint_interval = 1.000e-300 s is below the first time step", 0},
        {"output_interval_below_dt.toml",
         ": [run] output_interval = 1.000e-12 s is below the first time step", 0},
    };
    std::size_t fixtures = 0;
    for (const auto& e : fs::directory_iterator(kSource / "tests/data/bad_cases"))
        fixtures += e.path().extension() == ".toml";
    EXPECT_EQ(fixtures, cases.size()) << "every fixture has an expectation here";
    for (const BadCase& c : cases) {
        const fs::path casePath = dir / c.file;
        fs::copy_file(kSource / "tests/data/bad_cases" / c.file, casePath,
                      fs::copy_options::overwrite_existing);
        const auto r =
            runCommand(kSolve + " " + casePath.string() + " -o " + (dir / "out").string());
        EXPECT_EQ(r.status, 1) << c.file;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.file << ": " << r.err;
        EXPECT_NE(r.err.find("gsph-solve: error: "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(c.file), std::string::npos) << c.file << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.file << ": " << r.err;
        if (c.line > 0) {
            EXPECT_NE(r.err.find(std::string(c.file) + ":" + std::to_string(c.line) + ":"),
                      std::string::npos)
                << r.err;
        }
        EXPECT_FALSE(fs::exists(dir / "out" / "snapshot_000000.h5"))
            << c.file << ": nothing is computed";
    }
}

// The serial build started by mpirun would run the whole case once per process into one
// folder: it refuses, once, before writing anything (docs/mpi.md).
#ifndef GSPH_MPI
TEST(SolveCli, ASerialBuildStartedByMpirunRefusesToRun) {
    TempDir dir;
    makeParticles(dir);
    const fs::path run = dir / "run";
    const auto r = runCommand("mpirun --allow-run-as-root --oversubscribe -np 2 " + kSolve + " " +
                              (kSource / "cases/graded_bar/case.toml").string() + " --particles " +
                              (dir / "particles.h5").string() + " -o " + run.string());
    EXPECT_NE(r.status, 0);
    const std::string said = "this gsph-solve was built without MPI";
    const auto first = r.err.find(said);
    ASSERT_NE(first, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(said, first + 1), std::string::npos) << "said once: " << r.err;
    EXPECT_FALSE(fs::exists(run)) << "nothing written";
}
#endif

TEST(SolveCli, SampleCaseRunsAndBalancesItsEnergy) {
    TempDir dir;
    makeParticles(dir);
    const fs::path run = dir / "run";
    const auto r = test::runSampleCase(dir / "particles.h5", run);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("done: t = 3.0000e-05 s"), std::string::npos) << r.out;
    for (int k = 0; k <= 10; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "snapshot_%06d.h5", k);
        EXPECT_TRUE(fs::exists(run / name)) << name;
    }
    EXPECT_TRUE(fs::exists(run / "run.log"));
    for (const auto& e : fs::directory_iterator(run))
        EXPECT_NE(e.path().filename().string()[0], '.')
            << "a temporary file was left: " << e.path();
    // Where the wall time went: the step's four phases and the rest, shares that add up to the
    // whole (each printed to 0.1 %); before them the set-up's time (one space: no band solve).
    const std::string log = test::slurp(run / "run.log");
    double setup = -1.0;
    const std::size_t setupLine = log.find("\nset-up ");
    ASSERT_NE(setupLine, std::string::npos) << log;
    ASSERT_EQ(std::sscanf(log.c_str() + setupLine, "\nset-up %lf s wall", &setup), 1);
    EXPECT_GT(setup, 0.0);
    EXPECT_EQ(log.find("interface weights", setupLine), std::string::npos) << log;
    const std::size_t timeLine = log.find("\ntime: kinematics+stress ");
    ASSERT_NE(timeLine, std::string::npos) << log;
    double shares[5] = {};
    ASSERT_EQ(std::sscanf(log.c_str() + timeLine,
                          "\ntime: kinematics+stress %lf %%, forces %lf %%, contact, walls and "
                          "loads %lf %%, other step work %lf %%, files and the rest %lf %%",
                          &shares[0], &shares[1], &shares[2], &shares[3], &shares[4]),
              5)
        << log.substr(timeLine, 200);
    double whole = 0.0;
    for (const double share : shares) {
        EXPECT_GE(share, 0.0);
        whole += share;
    }
    EXPECT_NEAR(whole, 100.0, 0.26);
    EXPECT_GT(shares[1], 0.0);  // the bar's internal force
    // Energy: the ledger balances the boundary work (the driven face) within 1 %.
    std::vector<std::string> header;
    const auto rows = readCsv(run / "history.csv", header);
    ASSERT_EQ(header.size(), 22u);
    // The documented order (docs/formats.md): clock, energies, total, momentum, then the body's
    // (the bar's) share of the energies and momentum.
    const std::vector<std::string> expected = {"time",
                                               "step",
                                               "dt",
                                               "kinetic_energy",
                                               "internal_energy",
                                               "plastic_work",
                                               "damage_dissipation",
                                               "fracture_energy",
                                               "hourglass_work",
                                               "viscous_work",
                                               "contact_energy",
                                               "external_work",
                                               "total_energy",
                                               "momentum_x",
                                               "momentum_y",
                                               "momentum_z",
                                               "body_bar_kinetic_energy",
                                               "body_bar_internal_energy",
                                               "body_bar_plastic_work",
                                               "body_bar_momentum_x",
                                               "body_bar_momentum_y",
                                               "body_bar_momentum_z"};
    EXPECT_EQ(header, expected);
    const auto col = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) -
                                        header.begin());
    };
    // history_interval (end_time / 400) is shorter than the step here: a row after every step,
    // the snapshots' included, times increasing.
    ASSERT_EQ(rows.size(), static_cast<std::size_t>(rows.back()[col("step")]) + 1);
    for (std::size_t k = 1; k < rows.size(); ++k) {
        EXPECT_EQ(rows[k][col("step")], rows[k - 1][col("step")] + 1);
        EXPECT_GT(rows[k][col("time")], rows[k - 1][col("time")]);
    }
    const double e0 = rows.front()[col("total_energy")];
    const double work = rows.back()[col("external_work")];
    EXPECT_GT(work, 1.0);
    EXPECT_LT(std::abs(rows.back()[col("total_energy")] - e0), 0.01 * work);
    // Momentum across the bar (y, z) stays zero; the last snapshot is at the end time.
    EXPECT_LT(std::abs(rows.back()[col("momentum_y")]), 1e-12);
    const Snapshot last = readSnapshot(run / "snapshot_000010.h5");
    EXPECT_NEAR(last.state.time, 3e-5, 1e-15);
    EXPECT_EQ(last.size(), 320);
}

// A case with the solver's keys: the bar thrown at 50 m/s against a wall 0.5 mm away, with
// friction, under gravity, its far face pushed by a set force. The wall is met, and the history
// balances: kinetic + internal + … + contact energy − external work stays at its initial value.
TEST(SolveCli, WallGravityAndSetForceCaseBalancesItsEnergy) {
    TempDir dir;
    const auto r = solveCaseText(
        dir, "wall.toml",
        "[run]\nparticles = \"particles.h5\"\nend_time = 3.0e-5\noutput_interval = 1.0e-6\n"
        "viscosity = [0.2, 0.2]\ngravity = [0.0, -2.0e4, 0.0]\n"
        "[contact]\npenalty = 4.0\n" +
            kSteelBar +
            "velocity = [-50.0, 0.0, 0.0]\n"
            "[[set]]\nname = \"load\"\nforce = [-2000.0, 0.0, 0.0]\n"
            "[[wall]]\nname = \"anvil\"\npoint = [-0.0005, 0.0, 0.0]\nnormal = [1.0, 0.0, 0.0]\n"
            "friction = 0.2\n");
    const fs::path run = dir / "run";
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> header;
    const auto rows = readCsv(run / "history.csv", header);
    const auto col = [&](const std::string& name) {
        const auto it = std::find(header.begin(), header.end(), name);
        EXPECT_NE(it, header.end()) << name;
        return static_cast<std::size_t>(it - header.begin());
    };
    double contact = 0.0, scale = rows.front()[col("kinetic_energy")], worst = 0.0;
    for (const auto& row : rows) {
        contact = std::max(contact, row[col("contact_energy")]);
        scale = std::max(scale, std::abs(row[col("external_work")]));
    }
    for (const auto& row : rows)
        worst =
            std::max(worst, std::abs(row[col("total_energy")] - rows.front()[col("total_energy")]));
    EXPECT_GT(contact, 0.0) << "the bar met the wall";
    EXPECT_LT(worst, 0.01 * scale);
    // Momentum: the set force and gravity act throughout; y momentum = M g_y t exactly (the
    // wall's friction acts along y and z only while the bar slides on it: bounded by μ N).
    EXPECT_LT(rows.back()[col("momentum_y")], 0.0);
}

// history_interval: a row at the first step at or past each j·1 µs, besides the snapshots' rows
// (one row where both fall on the same step).
TEST(SolveCli, HistoryIntervalWritesRowsBetweenSnapshots) {
    TempDir dir;
    const auto r = solveCaseText(
        dir, "history.toml",
        "[run]\nparticles = \"particles.h5\"\nend_time = 3.0e-5\noutput_interval = 1.0e-5\n"
        "history_interval = 1.0e-6\n" +
            kSteelBar + "velocity = [-5.0, 0.0, 0.0]\n");
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> header;
    const auto rows = readCsv(dir / "run" / "history.csv", header);
    const std::size_t time = 0, dt = 2;
    ASSERT_EQ(header[time], "time");
    ASSERT_EQ(header[dt], "dt");
    // Snapshots at 0, 10, 20, 30 µs; history rows at j = 1 … 29 µs but 10 and 20.
    ASSERT_EQ(rows.size(), 4u + 27u);
    std::size_t snapshots = 0, j = 1;
    for (const auto& row : rows) {
        const double t = row[time];
        if (std::abs(t / 1e-5 - std::round(t / 1e-5)) < 1e-9) {
            ++snapshots;
            if (t > 0.0) ++j;  // its row stands for j·1 µs too
            continue;
        }
        // The first step at or past j µs: within one step (the step size before this row's).
        EXPECT_GE(t, j * 1e-6 - 1e-18) << j;
        EXPECT_LT(t, j * 1e-6 + 1.5 * row[dt]) << j;
        ++j;
    }
    EXPECT_EQ(snapshots, 4u);
}

// The sample bar pushed by a pressure on its "load" face (x = L, 1 cm²; gsph-preproc's face
// areas) ramped to 10 MPa over 1 µs, for 10 µs, with `extra` appended to the case: the final
// momentum against the impulse −p A t = −1e7 · 1e-4 · (0.5e-6 + 9e-6), and the energy drift.
struct PushedBar {
    Vec3 momentum;
    double impulse = -1e7 * 1e-4 * 9.5e-6;
    double external = 0.0, drift = 0.0;
};
PushedBar pushBarWithPressure(const TempDir& dir, const std::string& extra) {
    const std::string text =
        "[run]\nparticles = \"particles.h5\"\nend_time = 1.0e-5\noutput_interval = 1.0e-6\n"
        "viscosity = [0.05, 1.0]\n" +
        kSteelBar + "[[set]]\nname = \"load\"\npressure = [[0.0, 0.0], [1.0e-6, 1.0e7]]\n" + extra;
    const auto r = solveCaseText(dir, "pushed.toml", text);
    EXPECT_EQ(r.status, 0) << r.err;
    std::vector<std::string> header;
    const auto rows = readCsv(dir / "run" / "history.csv", header);
    const auto col = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) -
                                        header.begin());
    };
    PushedBar out;
    const auto& last = rows.back();
    out.momentum = Vec3(last[col("momentum_x")], last[col("momentum_y")], last[col("momentum_z")]);
    out.external = last[col("external_work")];
    out.drift = last[col("total_energy")] - rows.front()[col("total_energy")];
    return out;
}

// The pressure's momentum is its impulse (up to the face's lateral strains) and the energy
// balances. A particle file without face areas (the bundled format-1.1 one) gets a one-line
// refusal.
TEST(SolveCli, PressureOnASetPushesWithItsImpulseAndBalancesItsEnergy) {
    TempDir dir;
    const PushedBar bar = pushBarWithPressure(dir, "");
    std::printf(
        "[pressure cli] momentum_x %.6e vs −p A t %.6e; external work %.4e J, energy "
        "drift %.2e J\n",
        bar.momentum[0], bar.impulse, bar.external, bar.drift);
    EXPECT_NEAR(bar.momentum[0] / bar.impulse, 1.0, 5e-5);  // measured 1.6e-5
    EXPECT_GT(bar.external, 0.0);
    EXPECT_LT(std::abs(bar.drift), 1e-5 * bar.external);  // measured 2.4e-6

    TempDir old;
    std::ofstream(old / "pressure.toml")
        << "[run]\nparticles = \"" + (kSource / "cases/graded_bar/particles.h5").string() +
               "\"\nend_time = 1.0e-6\noutput_interval = 1.0e-6\n" + kSteelBar +
               "[[set]]\nname = \"load\"\npressure = 1.0e7\n";
    const auto refused = runCommand(kSolve + " " + (old / "pressure.toml").string() + " -o " +
                                    (old / "run").string());
    EXPECT_EQ(refused.status, 1);
    EXPECT_NE(refused.err.find("a pressure on set 'load' needs its face areas"), std::string::npos)
        << refused.err;
}

// A roller (`fixed = ["y", "z"]`) on the far end holds its particles' lateral velocity at zero
// and takes no axial force: the pressure's impulse still goes whole into the axial momentum,
// the roller does no work, and its particles never move sideways.
TEST(SolveCli, RollerSetHoldsOnlyItsComponents) {
    TempDir dir;
    const PushedBar bar =
        pushBarWithPressure(dir, "[[set]]\nname = \"clamp\"\nfixed = [\"y\", \"z\"]\n");
    std::printf(
        "[roller cli] momentum_x %.6e vs −p A t %.6e; energy drift %.2e of the external "
        "work\n",
        bar.momentum[0], bar.impulse, bar.drift / bar.external);
    EXPECT_NEAR(bar.momentum[0] / bar.impulse, 1.0, 5e-5);
    EXPECT_LT(std::abs(bar.drift), 1e-5 * bar.external);
    const ParticleFile particles = readParticleFile(dir / "particles.h5");
    const Snapshot last = readSnapshot(dir / "run" / "snapshot_000010.h5");
    for (Index a : particles.sets.at("clamp")) {
        const Vec3& v = last.state.v[static_cast<std::size_t>(a)];
        EXPECT_EQ(v[1], 0.0);
        EXPECT_EQ(v[2], 0.0);
    }
}

// The Taylor bar's shape does not depend on the thread count. The sample case on a
// small O-grid (core + annulus, overset band, Johnson–Cook + Mie–Grüneisen, the anvil wall)
// through ~2 µs of impact, on 1 and 2 threads: the checkpoints (the whole state) are
// bytewise identical.
TEST(SolveCli, TaylorBarIsBitIdenticalOnOneAndTwoThreads) {
    TempDir dir;
    const fs::path particles = dir / "taylor.h5";
    const auto p =
        runCommand(std::string(GSPH_PREPROC_EXE) + " " +
                   test::quote((kSource / "geometries/taylor_bar.geo").string()) +
                   " --set n=4 --set nr=2 --set nz=12 -q -o " + test::quote(particles.string()));
    ASSERT_EQ(p.status, 0) << p.err;
    const auto solve = [&](int threads) {
        const fs::path out = dir / ("run" + std::to_string(threads));
        const auto r = runCommand(
            kSolve + " " + test::quote((kSource / "cases/taylor_bar/case.toml").string()) +
            " --particles " + test::quote(particles.string()) + " -o " + test::quote(out.string()) +
            " --threads " + std::to_string(threads) + " --stop-after-steps 400");
        EXPECT_EQ(r.status, 3) << r.err;  // interrupted, with a checkpoint
        return out / "checkpoint.h5";
    };
    const fs::path one = solve(1), two = solve(2);
    int compared = 0;
    EXPECT_EQ(test::differingDatasets(one, two, &compared), "");
    EXPECT_GT(compared, 10);
}

// An axisymmetric run from a 2-D particle file: Lamé's cylinder (ri = 10 mm, ro = 20 mm, 40 × 4
// particles, steel) held at ε_z = 0 by a roller on every particle, the bore's pressure rising
// smoothly (1 − cos) to 100 MPa over 150 µs and held. The run's mass is ρ π (ro² − ri²) H
// (run.log), and the bore particles' radial displacement averaged over the hold's snapshots is
// Lamé's at their radius, as the library's test finds (−0.62 %): the swept pressure acts on the
// bore's ring 2π ri H.
// The section ri = 10 mm ≤ x ≤ ro = 20 mm, 0 ≤ y ≤ H of a cylinder's wall as a 2-D particle file
// (40 × 4 particles of 0.25 mm): sets "all" and "bore" (x = ri, with its faces' areas per metre).
struct CylinderSection {
    double ri = 0.01, ro = 0.02;
    int nr = 40, nz = 4;
    double dr() const { return (ro - ri) / nr; }
    double height() const { return nz * dr(); }
};
ParticleFile cylinderSectionFile(const CylinderSection& c) {
    ParticleFile f;
    f.dimension = 2;
    f.spaces.resize(1);
    f.spaces[0].cells = {c.nr, c.nz, 1};
    const double dr = c.dr();
    for (int j = 0; j < c.nz; ++j)
        for (int i = 0; i < c.nr; ++i) {
            f.theta.push_back(Vec3(i + 0.5, j + 0.5, 0.0));
            f.X.push_back(Vec3(c.ri + (i + 0.5) * dr, (j + 0.5) * dr, 0.0));
            f.volume.push_back(dr * dr);
            f.space.push_back(0);
            f.body.push_back(0);
            f.sets["all"].push_back(static_cast<Index>(f.X.size() - 1));
            if (i == 0) {
                f.sets["bore"].push_back(static_cast<Index>(f.X.size() - 1));
                f.setAreas["bore"].push_back(Vec3(-dr, 0.0, 0.0));
            }
        }
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j <= c.nz; ++j)
            for (int i = 0; i <= c.nr; ++i) f.nodes.push_back(Vec3(c.ri + i * dr, j * dr, k));
    f.bodies = {{"cylinder", 1}};
    return f;
}

// The case of the cylinder section: steel, every particle on a roller in y, `run` and `pressure`
// the [run] keys and the bore's pressure.
std::string cylinderCase(const std::string& run, const std::string& pressure) {
    return "[run]\nparticles = \"cylinder.h5\"\n" + run +
           kSteelBar.substr(0, kSteelBar.find("[[body]]")) +
           "[[body]]\ngroup = \"cylinder\"\nmaterial = \"steel\"\n"
           "[[set]]\nname = \"all\"\nfixed = [\"y\"]\n"
           "[[set]]\nname = \"bore\"\npressure = " +
           pressure + "\n";
}

TEST(SolveCli, AxisymmetricRunOfATwoDimensionalFileMatchesLame) {
    TempDir dir;
    const CylinderSection c;
    const double ri = c.ri, ro = c.ro, p = 1e8, pi = 3.141592653589793;
    const int nz = c.nz;
    const double dr = c.dr(), H = c.height();
    const ParticleFile f = cylinderSectionFile(c);
    writeParticleFile(dir / "cylinder.h5", f);
    std::string curve;
    for (int k = 0; k <= 30; ++k) {
        const double t = 150e-6 * k / 30;
        char point[64];
        std::snprintf(point, sizeof point, "%s[%.9e, %.9e]", k ? ", " : "", t,
                      0.5 * p * (1 - std::cos(pi * k / 30)));
        curve += point;
    }
    std::ofstream(dir / "lame.toml") << cylinderCase(
        "dimension = \"axisymmetric\"\nend_time = 2.5e-4\noutput_interval = 2.0e-6\n",
        "[" + curve + "]");
    const auto r = runCommand(kSolve + " " + (dir / "lame.toml").string() + " -o " +
                              (dir / "run").string() + " --threads 2");
    ASSERT_EQ(r.status, 0) << r.err;
    std::ifstream logFile(dir / "run" / "run.log");
    const std::string log((std::istreambuf_iterator<char>(logFile)), {});
    const std::size_t at = log.find(", mass ");
    ASSERT_NE(at, std::string::npos) << log;
    const double mass = std::stod(log.substr(at + 7));
    const double exact = 7850.0 * pi * (ro * ro - ri * ri) * H;
    double u = 0.0;
    int samples = 0;
    for (int k = 76; k <= 125; ++k) {  // t = 152 … 250 µs
        char name[32];
        std::snprintf(name, sizeof name, "snapshot_%06d.h5", k);
        const Snapshot s = readSnapshot(dir / "run" / name);
        for (const Index a : f.sets.at("bore"))
            u += s.state.x[static_cast<std::size_t>(a)][0] - f.X[static_cast<std::size_t>(a)][0];
        samples += nz;
    }
    u /= samples;
    const double nu = 0.3, E = 200e9, A = p * ri * ri / (ro * ro - ri * ri), B = A * ro * ro;
    const double rb = ri + 0.5 * dr;
    const double lame = (1 + nu) / E * ((1 - 2 * nu) * A * rb + B / rb);
    std::printf(
        "[axisymmetric cli] mass %.9g kg (exact %.9g); bore u_r %.6e m, Lamé %.6e m "
        "(%+.2f %%)\n",
        mass, exact, u, lame, 100 * (u / lame - 1));
    EXPECT_NEAR(mass / exact, 1.0, 1e-6);  // run.log prints 6 digits
    EXPECT_NEAR(u / lame, 1.0, 0.008);
}

// The same 2-D file without [run] dimension runs in plane strain: per metre of depth, the
// bore's constant pressure p pushes the slab with the impulse p H t (every particle on a roller
// in y, so the faces keep their area: the identity holds to round-off).
TEST(SolveCli, TwoDimensionalFileRunsInPlaneStrainByDefault) {
    TempDir dir;
    const CylinderSection c;
    writeParticleFile(dir / "cylinder.h5", cylinderSectionFile(c));
    const double p = 1e7, end = 2e-6;
    std::ofstream(dir / "slab.toml")
        << cylinderCase("end_time = 2.0e-6\noutput_interval = 1.0e-6\n", "1.0e7");
    const auto r =
        runCommand(kSolve + " " + (dir / "slab.toml").string() + " -o " + (dir / "run").string());
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> header;
    const auto rows = readCsv(dir / "run" / "history.csv", header);
    const auto col = static_cast<std::size_t>(
        std::find(header.begin(), header.end(), "momentum_x") - header.begin());
    ASSERT_LT(col, header.size());
    const double impulse = p * c.height() * end;
    std::printf("[plane strain cli] momentum_x %.9e, p H t %.9e\n", rows.back()[col], impulse);
    EXPECT_NEAR(rows.back()[col] / impulse, 1.0, 1e-12);
}

// The per-wall columns of history.csv: the graded bar (M = 0.0785 kg) laid on a floor under
// g = 2e4 m/s² rings on its contact springs; the floor's force column integrated over the rows
// (trapezoid) is the momentum it gave, Δp_y + M g T, and on average it carries M g (the constant
// viscosity, without its compression switch, damps the ringing so that it rests). A second wall,
// far away and moving, has zero force and displacement velocity·t; its name is sanitised.
TEST(SolveCli, HistoryHasEachWallsForceAndDisplacement) {
    TempDir dir;
    const auto r = solveCaseText(
        dir, "floor.toml",
        "[run]\nparticles = \"particles.h5\"\nend_time = 3.0e-5\noutput_interval = 2.0e-7\n"
        "gravity = [0.0, -2.0e4, 0.0]\nviscosity_switch = 0\n" +
            kSteelBar +
            "[[wall]]\nname = \"floor\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 1.0, 0.0]\n"
            "[[wall]]\nname = \"far wall-2\"\nshape = \"cylinder\"\npoint = [0.0, 0.0, 1.0]\n"
            "axis = [1.0, 0.0, 0.0]\nradius = 0.1\nvelocity = [0.0, 0.5, 2.0]\n");
    const fs::path run = dir / "run";
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> header;
    const auto rows = readCsv(run / "history.csv", header);
    // time … momentum_z (docs/formats.md), then the walls', then the bar's.
    const std::size_t runColumns = 16;
    ASSERT_EQ(header.size(), runColumns + 2 * 6 + 6);
    const std::vector<std::string> floor = {"wall_floor_fx", "wall_floor_fy", "wall_floor_fz",
                                            "wall_floor_ux", "wall_floor_uy", "wall_floor_uz"};
    EXPECT_EQ(
        std::vector<std::string>(header.begin() + runColumns, header.begin() + runColumns + 6),
        floor);
    EXPECT_EQ(header[runColumns + 6], "wall_far_wall_2_fx");
    EXPECT_EQ(header[runColumns + 11], "wall_far_wall_2_uz");
    EXPECT_EQ(header[runColumns + 12], "body_bar_kinetic_energy");
    const auto col = [&](const std::string& name) {
        const auto it = std::find(header.begin(), header.end(), name);
        EXPECT_NE(it, header.end()) << name;
        return static_cast<std::size_t>(it - header.begin());
    };
    const double mass = 7850.0 * 0.1 * 0.01 * 0.01, g = 2.0e4;
    double impulse = 0.0, mean = 0.0;
    for (std::size_t k = 1; k < rows.size(); ++k) {
        const double dt = rows[k][col("time")] - rows[k - 1][col("time")];
        impulse += 0.5 * dt * (rows[k][col("wall_floor_fy")] + rows[k - 1][col("wall_floor_fy")]);
    }
    const double duration = rows.back()[col("time")];
    const double gained = rows.back()[col("momentum_y")] - rows.front()[col("momentum_y")];
    for (std::size_t k = rows.size() / 2; k < rows.size(); ++k)
        mean += rows[k][col("wall_floor_fy")];
    mean /= static_cast<double>(rows.size() - rows.size() / 2);
    std::printf(
        "[floor column] ∫F dt %.6e, Δp + M g T %.6e; mean force (second half) %.2f N, "
        "M g %.2f N\n",
        impulse, gained + mass * g * duration, mean, mass * g);
    EXPECT_NEAR(impulse, gained + mass * g * duration, 0.01 * mass * g * duration);
    // Resting (Δp ≈ 0): the floor carried the weight on average (the mean of the ringing
    // samples themselves is a few % off; their integral is not).
    EXPECT_NEAR(impulse / duration, mass * g, 0.02 * mass * g);
    for (const auto& row : rows) {
        EXPECT_EQ(row[col("wall_floor_fx")], 0.0);
        EXPECT_EQ(row[col("wall_floor_uy")], 0.0);
        EXPECT_EQ(row[col("wall_far_wall_2_fz")], 0.0);
        // Both columns are printed to 9 significant digits.
        EXPECT_NEAR(row[col("wall_far_wall_2_uy")], 0.5 * row[col("time")],
                    1e-9 * 0.5 * row[col("time")]);
        EXPECT_NEAR(row[col("wall_far_wall_2_uz")], 2.0 * row[col("time")],
                    1e-9 * 2.0 * row[col("time")]);
    }
}

// Two blocks as a particle file dir/particles.h5: a 12 × 12 × 6 mm anvil of 2 mm cells and a
// 6 mm cube of 2 mm cells 0.5 mm above its middle; `groups`: their physical volumes (gmsh).
test::ProcessResult twoBlocks(const TempDir& dir, const std::string& groups) {
    std::ofstream(dir / "two.geo") << R"(
Point(1) = {0, 0, 0}; Point(2) = {0.012, 0, 0}; Point(3) = {0.012, 0.012, 0};
Point(4) = {0, 0.012, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1:4} = 7; Transfinite Surface{1}; Recombine Surface{1};
a[] = Extrude {0, 0, 0.006} { Surface{1}; Layers{3}; Recombine; };
Point(101) = {0.003, 0.003, 0.0065}; Point(102) = {0.009, 0.003, 0.0065};
Point(103) = {0.009, 0.009, 0.0065}; Point(104) = {0.003, 0.009, 0.0065};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
Transfinite Curve{101:104} = 4; Transfinite Surface{101}; Recombine Surface{101};
b[] = Extrude {0, 0, 0.006} { Surface{101}; Layers{3}; Recombine; };
)" + groups;
    return runCommand(std::string(GSPH_PREPROC_EXE) + " " + (dir / "two.geo").string() + " -q -o " +
                      (dir / "particles.h5").string());
}

// Per-body columns of history.csv (LS-DYNA's matsum): a copper anvil, whose physical volume
// has no name (columns body_0_…), struck at 150 m/s by an elastic steel block named "striker-1"
// (body_striker_1_…), contact between them, a floor wall far below. After the run's and the
// wall's columns, each body's kinetic and internal energy, plastic work and momentum; in every
// row the bodies' columns add up to the run's to the digits printed (the library's sums are
// exact: EnergyReport.BodiesAddUpToTheRunExactly).
TEST(SolveCli, HistoryHasEachBodysEnergiesAndMomentum) {
    TempDir dir;
    const auto p = twoBlocks(
        dir, "Physical Volume(7) = {a[1]};\nPhysical Volume(\"striker-1\", 9) = {b[1]};\n");
    ASSERT_EQ(p.status, 0) << p.err;
    std::ofstream(dir / "two.toml")
        << "[run]\nparticles = \"particles.h5\"\nend_time = 1.2e-5\noutput_interval = 3.0e-6\n"
           "history_interval = 5.0e-7\n"
           "[contact]\nbetween_bodies = true\nself_contact = true\npenalty = 4.0\n"
           "[[material]]\nname = \"copper\"\nfile = \"" +
               (kSource / "materials/ofhc_copper.toml").string() +
               "\"\n"
               "[[material]]\nname = \"steel\"\ndensity = 7850.0\nyoungs_modulus = 200.0e9\n"
               "poisson_ratio = 0.3\n"
               "[[body]]\ngroup = \"0\"\nmaterial = \"copper\"\n"
               "[[body]]\ngroup = \"striker-1\"\nmaterial = \"steel\"\n"
               "velocity = [0.0, 0.0, -150.0]\n"
               "[[wall]]\nname = \"floor\"\npoint = [0.0, 0.0, -0.01]\n"
               "normal = [0.0, 0.0, 1.0]\n";
    const auto r =
        runCommand(kSolve + " " + (dir / "two.toml").string() + " -o " + (dir / "run").string());
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> header;
    const auto rows = readCsv(dir / "run" / "history.csv", header);
    const std::size_t runColumns = 16, wallColumns = 6, contactColumns = 3;
    const std::vector<std::string> suffixes = {"kinetic_energy", "internal_energy", "plastic_work",
                                               "momentum_x",     "momentum_y",      "momentum_z"};
    ASSERT_EQ(header.size(), runColumns + wallColumns + contactColumns + 2 * suffixes.size());
    EXPECT_EQ(header[runColumns], "wall_floor_fx");
    EXPECT_EQ(header[runColumns + wallColumns], "contact_0_striker_1_fx");
    EXPECT_EQ(header[runColumns + wallColumns + 2], "contact_0_striker_1_fz");
    const std::size_t bodyColumns = runColumns + wallColumns + contactColumns;
    for (std::size_t k = 0; k < suffixes.size(); ++k) {
        EXPECT_EQ(header[bodyColumns + k], "body_0_" + suffixes[k]);
        EXPECT_EQ(header[bodyColumns + suffixes.size() + k], "body_striker_1_" + suffixes[k]);
    }
    const auto col = [&](const std::string& name) {
        const auto it = std::find(header.begin(), header.end(), name);
        EXPECT_NE(it, header.end()) << name;
        return static_cast<std::size_t>(it - header.begin());
    };
    ASSERT_GT(rows.size(), 20u);
    double worst = 0.0;  // the largest mismatch, relative to the magnitudes summed
    for (const auto& row : rows)
        for (const std::string& suffix : suffixes) {
            const double anvil = row[col("body_0_" + suffix)];
            const double striker = row[col("body_striker_1_" + suffix)];
            const double run = row[col(suffix)];
            const double scale = std::abs(anvil) + std::abs(striker) + std::abs(run);
            // Each value is printed to 10 significant digits (relative error ≤ 5e-10).
            EXPECT_LE(std::abs(anvil + striker - run), 1e-9 * scale + 1e-300)
                << suffix << " at t = " << row[col("time")];
            if (scale > 0.0) worst = std::max(worst, std::abs(anvil + striker - run) / scale);
        }
    const auto& first = rows.front();
    const auto& last = rows.back();
    std::printf(
        "[body columns] %zu rows; worst |Σ bodies − run| / Σ|.| %.1e; at the end: anvil kinetic "
        "%.4e J, internal %.4e J, plastic %.4e J, momentum_z %.4e kg m/s; striker kinetic %.4e "
        "J (from %.4e J), plastic %.1e J\n",
        rows.size(), worst, last[col("body_0_kinetic_energy")], last[col("body_0_internal_energy")],
        last[col("body_0_plastic_work")], last[col("body_0_momentum_z")],
        last[col("body_striker_1_kinetic_energy")], first[col("body_striker_1_kinetic_energy")],
        last[col("body_striker_1_plastic_work")]);
    // At t = 0 the striker carries the run's kinetic energy and momentum, the anvil none.
    EXPECT_EQ(first[col("body_0_kinetic_energy")], 0.0);
    EXPECT_EQ(first[col("body_striker_1_kinetic_energy")], first[col("kinetic_energy")]);
    EXPECT_EQ(first[col("body_striker_1_momentum_z")], first[col("momentum_z")]);
    // The blow: the anvil took momentum and flowed; the elastic striker dissipates nothing.
    EXPECT_LT(last[col("body_0_momentum_z")], 0.0);
    EXPECT_GT(last[col("body_0_plastic_work")], 0.0);
    EXPECT_EQ(last[col("body_striker_1_plastic_work")], 0.0);
    EXPECT_LT(last[col("body_striker_1_kinetic_energy")],
              first[col("body_striker_1_kinetic_energy")]);
    // The contact force on the anvil (LS-DYNA's rcforc): none before the blocks meet (0.5 mm
    // apart, beyond the contact distance), then downwards; the blow is centred, so it has no
    // sideways part beyond round-off.
    EXPECT_EQ(first[col("contact_0_striker_1_fz")], 0.0);
    double strongest = 0.0, sideways = 0.0;
    for (const auto& row : rows) {
        EXPECT_LE(row[col("contact_0_striker_1_fz")], 0.0) << "at t = " << row[col("time")];
        strongest = std::max(strongest, -row[col("contact_0_striker_1_fz")]);
        sideways = std::max({sideways, std::abs(row[col("contact_0_striker_1_fx")]),
                             std::abs(row[col("contact_0_striker_1_fy")])});
    }
    std::printf("[contact columns] largest push on the anvil %.4e N, sideways up to %.1e N\n",
                strongest, sideways);
    EXPECT_GT(strongest, 1e3);
    EXPECT_LT(sideways, 1e-11 * strongest);  // measured 1.1e-12
}

// [[probe]] (LS-DYNA's nodout): probes.csv holds, at every history.csv row, the fields of the
// probes' particles; the values at snapshot times are the snapshots' own. A point probe takes
// the nearest particle (the striker's, 1.5 mm below the point; with body = "0" the anvil's,
// √3 mm away, lowest index among four at that distance), an index probe its particle.
TEST(SolveCli, ProbesWriteTheirParticlesFieldsAtEveryHistoryRow) {
    TempDir dir;
    const auto p = twoBlocks(
        dir,
        "Physical Volume(\"anvil\", 7) = {a[1]};\nPhysical Volume(\"striker\", 9) = {b[1]};\n");
    ASSERT_EQ(p.status, 0) << p.err;
    std::ofstream(dir / "probes.toml")
        << "[run]\nparticles = \"particles.h5\"\nend_time = 1.2e-5\noutput_interval = 3.0e-6\n"
           "history_interval = 5.0e-7\n"
           "[[material]]\nname = \"copper\"\nfile = \"" +
               (kSource / "materials/ofhc_copper.toml").string() +
               "\"\n"
               "[[body]]\ngroup = \"anvil\"\nmaterial = \"copper\"\n"
               "[[body]]\ngroup = \"striker\"\nmaterial = \"copper\"\n"
               "velocity = [0.0, 0.0, -150.0]\n"
               "[[probe]]\nname = \"tip\"\npoint = [0.006, 0.006, 0.006]\n"
               "[[probe]]\nname = \"anvil_top\"\npoint = [0.006, 0.006, 0.006]\n"
               "body = \"anvil\"\n"
               "[[probe]]\nname = \"corner\"\nparticle = 0\n";
    const auto r =
        runCommand(kSolve + " " + (dir / "probes.toml").string() + " -o " + (dir / "run").string());
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string log = test::slurp(dir / "run" / "run.log");
    EXPECT_NE(log.find("probe 'tip': particle "), std::string::npos) << log;
    EXPECT_NE(log.find("0.0015 m from its point"), std::string::npos) << log;
    std::vector<std::string> header, historyHeader;
    const auto rows = readCsv(dir / "run" / "probes.csv", header);
    const auto history = readCsv(dir / "run" / "history.csv", historyHeader);
    const std::size_t fields = 24;
    ASSERT_EQ(header.size(), 2 + 3 * fields);
    EXPECT_EQ(header[2], "tip_x");
    EXPECT_EQ(header[2 + fields], "anvil_top_x");
    EXPECT_EQ(header[2 + 2 * fields + 18], "corner_von_mises");
    // The same rows as history.csv.
    ASSERT_EQ(rows.size(), history.size());
    for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(rows[i][0], history[i][0]);
    const auto col = [&](const std::string& name) {
        const auto it = std::find(header.begin(), header.end(), name);
        EXPECT_NE(it, header.end()) << name;
        return static_cast<std::size_t>(it - header.begin());
    };
    // The particles chosen, from the first row (x = X at t = 0).
    const auto& first = rows.front();
    EXPECT_NEAR(first[col("tip_z")], 0.0075, 1e-12);
    EXPECT_EQ(first[col("tip_vz")], -150.0);
    EXPECT_NEAR(first[col("anvil_top_x")], 0.005, 1e-12);
    EXPECT_NEAR(first[col("anvil_top_y")], 0.005, 1e-12);
    EXPECT_NEAR(first[col("anvil_top_z")], 0.005, 1e-12);
    EXPECT_EQ(first[col("anvil_top_vz")], 0.0);
    EXPECT_NEAR(first[col("corner_x")], 0.001, 1e-12);
    // At each snapshot's time, the probes' values are the snapshot's, to the digits printed.
    int matched = 0;
    for (const auto& e : fs::directory_iterator(dir / "run")) {
        if (e.path().filename().string().rfind("snapshot_", 0) != 0) continue;
        const Snapshot snap = readSnapshot(e.path());
        const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& rw) {
            return std::abs(rw[0] - snap.state.time) <= 1e-9 * std::max(snap.state.time, 1e-12);
        });
        ASSERT_NE(row, rows.end()) << e.path();
        for (const std::string probe : {"tip", "anvil_top", "corner"}) {
            const auto near = [&](const std::string& column, double expected) {
                EXPECT_NEAR((*row)[col(probe + "_" + column)], expected,
                            5e-10 * std::abs(expected) + 1e-300)
                    << probe << "_" << column << " at t = " << snap.state.time;
            };
            // The probe's particle: the one at its x with its displacement.
            std::size_t a = 0;
            for (; a < snap.state.x.size(); ++a)
                if ((snap.state.x[a] - Vec3((*row)[col(probe + "_x")], (*row)[col(probe + "_y")],
                                            (*row)[col(probe + "_z")]))
                            .norm() < 1e-9 &&
                    (snap.state.x[a] - snap.X[a] -
                     Vec3((*row)[col(probe + "_ux")], (*row)[col(probe + "_uy")],
                          (*row)[col(probe + "_uz")]))
                            .norm() < 1e-9)
                    break;
            ASSERT_LT(a, snap.state.x.size()) << probe << " at t = " << snap.state.time;
            near("vz", snap.state.v[a][2]);
            near("stress_zz", snap.state.cauchy[a](2, 2));
            near("stress_xy", snap.state.cauchy[a](0, 1));
            near("von_mises", vonMises(snap.state.cauchy[a]));
            near("pressure", -snap.state.cauchy[a].trace() / 3.0);
            near("J", snap.state.F[a].determinant());
            near("plastic_strain", snap.state.plasticStrain[a]);
            near("temperature", snap.state.temperature[a]);
        }
        ++matched;
    }
    EXPECT_EQ(matched, 5);
    // The blow reached the anvil's top: it moved down and flowed.
    const auto& last = rows.back();
    EXPECT_LT(last[col("anvil_top_uz")], 0.0);
    EXPECT_GT(last[col("anvil_top_plastic_strain")], 0.0);
}

// A probe that names no particle of the run is refused before the run starts, naming the line.
TEST(SolveCli, ABadProbeIsRefusedNamingItsLine) {
    TempDir dir;
    const auto p = test::makeSampleParticles(dir / "particles.h5");
    ASSERT_EQ(p.status, 0) << p.err;
    const std::string base =
        "[run]\nparticles = \"particles.h5\"\nend_time = 1.0e-6\n"
        "[[material]]\nname = \"steel\"\ndensity = 7850.0\n"
        "youngs_modulus = 200.0e9\npoisson_ratio = 0.3\n"
        "[[body]]\ngroup = \"bar\"\nmaterial = \"steel\"\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"[[probe]]\nname = \"p\"\nparticle = 100000\n",
         "probes.toml:12: [[probe]] 'p': particle 100000 is not in"},
        {"[[probe]]\nname = \"p\"\npoint = [0.0, 0.0, 0.0]\nbody = \"ball\"\n",
         "probes.toml:12: [[probe]] 'p': body 'ball' is not a body of"},
        {"[[probe]]\nname = \"p q\"\nparticle = 1\n",
         "probes.toml:13: [[probe]] name 'p q' must be letters, digits and '_'"},
        {"[[probe]]\nname = \"p\"\nparticle = 1\npoint = [0.0, 0.0, 0.0]\n",
         "probes.toml:12: [[probe]] 'p' needs either 'point' or 'particle' (not both)"},
        {"[[probe]]\nname = \"p\"\nparticle = 1\n[[probe]]\nname = \"p\"\nparticle = 2\n",
         "probes.toml:15: [[probe]] 'p' is given twice (also at line 12)"},
    };
    for (const auto& [probe, message] : cases) {
        std::ofstream(dir / "probes.toml") << base + probe;
        const auto r = runCommand(kSolve + " " + (dir / "probes.toml").string() + " -o " +
                                  (dir / "run").string() + " --overwrite");
        EXPECT_EQ(r.status, 1) << probe;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

// Two bodies whose names make the same columns (body_ball_1_…) are refused before the run
// starts, with one line naming both.
TEST(SolveCli, BodiesWithTheSameHistoryColumnsAreRefused) {
    TempDir dir;
    const auto p = twoBlocks(dir,
                             "Physical Volume(\"ball-1\", 7) = {a[1]};\n"
                             "Physical Volume(\"ball_1\", 9) = {b[1]};\n");
    ASSERT_EQ(p.status, 0) << p.err;
    std::ofstream(dir / "same.toml") << "[run]\nparticles = \"particles.h5\"\nend_time = 1.0e-6\n" +
                                            kSteelBar.substr(0, kSteelBar.find("[[body]]")) +
                                            "[[body]]\ngroup = \"ball-1\"\nmaterial = \"steel\"\n"
                                            "[[body]]\ngroup = \"ball_1\"\nmaterial = \"steel\"\n";
    const auto r =
        runCommand(kSolve + " " + (dir / "same.toml").string() + " -o " + (dir / "run").string());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("bodies 'ball-1' and 'ball_1' would have the same history columns "
                         "(body_ball_1_…)"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "run" / "history.csv"));
}

}  // namespace
}  // namespace gsph
