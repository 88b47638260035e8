// SPDX-License-Identifier: MIT
// gsph-preproc as a process: a sample converts with a summary and a traceable file; every bad
// input gives one line on stderr naming the file and the fault, exit status 1, and no file.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/version.hpp"
#include "io/particle_file.hpp"
#include "io/sha256.hpp"
#include "support/process.hpp"
#include "temp_dir.hpp"

namespace gsph {
namespace {

using test::ProcessResult;
using test::quote;
using test::runCommand;
using test::slurp;

std::string source(const std::string& relative) {
    return std::string(GSPH_SOURCE_DIR) + "/" + relative;
}

/// Runs gsph-preproc with `args`.
ProcessResult preproc(const std::string& args) {
    return runCommand(quote(GSPH_PREPROC) + " " + args);
}

TEST(PreprocCli, ConvertsASampleWithSummaryAndProvenance) {
    test::TempDir dir;
    const std::string input = source("geometries/graded_bar.geo");
    const auto output = dir / "bar.h5";
    const ProcessResult r = preproc(quote(input) + " -o " + quote(output.string()));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "") << "the samples convert without warnings";
    for (const char* expected :
         {"particles  320 in 1 space", "cells 20x4x4", "'bar'", "spacing    hex edge length from",
          "'clamp' 16", "'load' 16", "time       read+mesh"}) {
        EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\n" << r.out;
    }
    const ParticleFile f = readParticleFile(output);
    EXPECT_EQ(f.size(), 320);
    EXPECT_EQ(f.provenance.tool, "gsph-preproc");
    EXPECT_EQ(f.provenance.toolVersion, kVersion);
    EXPECT_EQ(f.provenance.sourceFile, input);
    EXPECT_EQ(f.provenance.sourceSha256, sha256File(input));
    EXPECT_EQ(f.provenance.units, "SI");
    EXPECT_EQ(dir.entries(), 1);
}

TEST(PreprocCli, ConvertsA2dQuadMeshIntoA2dFile) {
    test::TempDir dir;
    const std::string input = source("geometries/taylor_bar_axisymmetric.geo");
    const auto output = dir / "taylor_rz.h5";
    const ProcessResult r = preproc(quote(input) + " -o " + quote(output.string()));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "") << "the samples convert without warnings";
    for (const char* expected :
         {"particles  424 in 1 space, 1 body, from 424 quadrangles (2-D)", "cells 8x53x1",
          "gmsh surfaces 1", "'rod'", "area 9.652000e-05 m^2", "'axis' 53", "'impact' 8",
          "'lateral' 53", "'free_end' 8",
          "spacing    quad edge length from 4.7500e-04 m to 4.7925e-04 m",
          "metric     space 0   worst cond(dX/dtheta) in the plane 1.009"}) {
        EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\n" << r.out;
    }
    const ParticleFile f = readParticleFile(output);
    EXPECT_EQ(f.dimension, 2);
    EXPECT_EQ(f.size(), 424);
}

TEST(PreprocCli, ParametersAndReplacingAnOutput) {
    test::TempDir dir;
    const auto output = dir / "bar.h5";
    std::ofstream(output) << "an older file";
    const ProcessResult r =
        preproc(quote(source("geometries/graded_bar.geo")) + " -o " + quote(output.string()) +
                " --set refine=2 --set grading=1.05 --quiet");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "");
    const ParticleFile f = readParticleFile(output);
    EXPECT_EQ(f.size(), 320 * 8);
    EXPECT_EQ(f.provenance.parameters, "refine=2,grading=1.05");
    EXPECT_EQ(dir.entries(), 1);
}

TEST(PreprocCli, OutputReadableByH5py) {
    test::TempDir dir;
    const auto output = dir / "taylor.h5";
    ASSERT_EQ(preproc(quote(source("geometries/taylor_bar.geo")) + " -o " + quote(output.string()) +
                      " -q")
                  .status,
              0);
    const std::string script =
        "import h5py\n"
        "f = h5py.File('" +
        output.string() +
        "', 'r')\n"
        "print(f['particles/X'].shape[0], f['spaces/periodic'][:].tolist(),\n"
        "      f['spaces/cells'][:].tolist(), len(f['sets/impact']),\n"
        "      [n.decode() for n in f['bodies/name'][:]], f.attrs['units'])\n";
    std::ofstream(dir / "check.py") << script;
    test::TempDir logs;
    const std::string command = "/usr/bin/python3 " + quote((dir / "check.py").string()) + " > " +
                                quote((logs / "out").string()) + " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << slurp(logs / "out");
    EXPECT_EQ(slurp(logs / "out"),
              "7680 [[0, 0, 0], [0, 1, 0]] [[8, 8, 40], [4, 32, 40]] 192 ['rod'] SI\n");
}

TEST(PreprocCli, OversetSummaryAndFile) {
    test::TempDir dir;
    const auto output = dir / "blocks.h5";
    const ProcessResult r =
        preproc(quote(source("geometries/two_blocks.geo")) + " -o " + quote(output.string()) +
                " --set overlap=2 --set plane=1 --overset-kappa 1.2");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    for (const char* expected :
         {"particles  160 in 2 spaces, 1 body, from 160 hexahedra",
          "kept       152 particles after hole cutting",
          "metric     space 0   worst cond(dX/dtheta) 1.000 (in-plane 1.000: one cell along k)",
          "overset    kappa 1.2", "cut        space 0 by space 1: 8 particles",
          "gap 0.000e+00 m^3, double-counted 0.000e+00 m^3",
          "transient  space 1 in space 0: ", "transient  space 0 in space 1: 4 particles"}) {
        EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\n" << r.out;
    }
    const ParticleFile f = readParticleFile(output);
    EXPECT_EQ(f.size(), 152);
    EXPECT_EQ(f.overset.kappa, 1.2);
    EXPECT_EQ(f.transient.size(), 152u);
    EXPECT_GT(f.overset.size(), 0u);
}

/// A failing run: status 1, on stdout at most the spaces (printed before overset, which may
/// fail naming them), one line on stderr that names `file` and holds `fault`, and no file in
/// the output folder (an existing output stays as it was).
void expectCleanFailure(const std::string& args, const std::string& file,
                        const std::string& fault) {
    test::TempDir dir;
    const auto output = dir / "out.h5";
    const ProcessResult r = preproc(args + " -o " + quote(output.string()));
    EXPECT_EQ(r.status, 1) << args;
    std::istringstream out(r.out);
    for (std::string line; std::getline(out, line);) {
        EXPECT_TRUE(line.rfind("gsph-preproc ", 0) == 0 || line.rfind("  particles ", 0) == 0 ||
                    line.rfind("  space ", 0) == 0)
            << args << ": " << line;
    }
    ASSERT_FALSE(r.err.empty()) << args;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line only:\n" << r.err;
    EXPECT_EQ(r.err.rfind("gsph-preproc: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(fault), std::string::npos) << r.err;
    EXPECT_EQ(dir.entries(), 0) << "a failed run leaves no file behind: " << args;
}

TEST(PreprocCli, BadInputsFailCleanly) {
    struct Case {
        const char* file;
        const char* fault;
    };
    const Case cases[] = {
        {"missing.geo", "no such file"},
        {"bad_syntax.geo", "syntax error"},
        {"tetrahedra.geo", "4-node tetrahedra"},
        {"mixed.msh", "1 6-node prisms besides 1 8-node hexahedra"},
        {"unstructured_hex.geo", "not a structured hex block"},
        {"inverted.msh", "inverted"},
        {"folded.msh", "inverted"},
        {"empty.msh", "no hexahedra"},
        {"no_volume.geo", "no hexahedra"},
        {"ungrouped_volume.geo", "no physical volume group"},
        {"bad_transfinite.geo", "cannot mesh it"},
        {"cylinder_single_space.geo", "collapses onto the line"},
        {"triangles_2d.geo",
         "3-node triangles; gsph-preproc needs structured blocks of 4-node "
         "quadrangles in 2-D"},
        {"unstructured_quads_2d.geo", "surface 1 is not a structured quad block"},
        {"mixed_2d_3d.geo", "mixes 2-D and 3-D elements"},
    };
    for (const Case& c : cases) {
        const std::string path = source("tests/data/") + c.file;
        expectCleanFailure(quote(path), path, c.fault);
    }
}

TEST(PreprocCli, BadOptionsFailCleanly) {
    const std::string bar = source("geometries/graded_bar.geo");
    expectCleanFailure(quote(bar) + " --set refine=two", "refine=two", "NAME=VALUE");
    expectCleanFailure(quote(bar) + " --set 2x=1", "2x=1", "NAME=VALUE");
    const std::string msh = source("tests/data/inverted.msh");
    expectCleanFailure(quote(msh) + " --set refine=2", msh, ".geo files only");
    const std::string text = source("tests/data/README.md");
    expectCleanFailure(quote(text), text, "expected a .geo or .msh file");
    const std::string blocks = source("geometries/two_blocks.geo");
    expectCleanFailure(quote(blocks) + " --priority core", "--priority core", "VOLUME=N");
    expectCleanFailure(quote(blocks) + " --priority 2=x", "--priority 2=x", "VOLUME=N");
    expectCleanFailure(quote(blocks) + " --priority core=2", blocks,
                       "no physical volume group named 'core'");
    expectCleanFailure(quote(blocks) + " --priority 1=1 --priority plate=2", blocks,
                       "conflicting priorities");
    expectCleanFailure(quote(blocks) + " --overset-kappa 0", blocks, "overset kappa");
    expectCleanFailure(quote(blocks) + " --set overlap=8", blocks, "lies entirely inside");
}

TEST(PreprocCli, UnwritableOutputFailsCleanly) {
    test::TempDir dir;
    const std::string bar = source("geometries/graded_bar.geo");
    const auto output = dir / "no-such-folder" / "bar.h5";
    const ProcessResult r = preproc(quote(bar) + " -o " + quote(output.string()));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
    EXPECT_EQ(dir.entries(), 0);
}

TEST(PreprocCli, FailureKeepsAnExistingOutput) {
    test::TempDir dir;
    const auto output = dir / "out.h5";
    std::ofstream(output) << "keep me";
    const ProcessResult r =
        preproc(quote(source("tests/data/inverted.msh")) + " -o " + quote(output.string()));
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(slurp(output), "keep me");
    EXPECT_EQ(dir.entries(), 1);
}

}  // namespace
}  // namespace gsph
