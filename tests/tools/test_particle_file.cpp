// SPDX-License-Identifier: MIT
// The particle file: round trip, h5py readability, validation, Reference from a file.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "io/hdf5_file.hpp"
#include "io/particle_file.hpp"
#include "io/sha256.hpp"
#include "reference/reference_builder.hpp"
#include "temp_dir.hpp"

namespace gsph {
namespace {

/// Two bodies; body 0 has a 2×2×1 space, body 1 a periodic 3×1×1 space.
ParticleFile sampleFile() {
    ParticleFile f;
    f.spaces.resize(2);
    f.spaces[0].cells = {2, 2, 1};
    f.spaces[1].cells = {3, 1, 1};
    f.spaces[1].periodic = {true, false, false};
    f.spaces[1].dtheta = 1.0;
    auto add = [&](Index s, Index b, std::array<Index, 3> ijk) {
        const Vec3 theta(ijk[0] + 0.5, ijk[1] + 0.5, ijk[2] + 0.5);
        f.theta.push_back(theta);
        f.X.push_back(1e-3 * theta + Vec3(0.1 * b, 1.0 / 3.0, -2.5e-7));
        f.volume.push_back(1e-9 * (1.0 + 0.1 * static_cast<double>(f.X.size())) / 3.0);
        f.space.push_back(s);
        f.body.push_back(b);
        f.latticeIndex.push_back(ijk);
    };
    for (Index j = 0; j < 2; ++j) {
        for (Index i = 0; i < 2; ++i) add(0, 0, {i, j, 0});
    }
    for (Index i = 0; i < 3; ++i) add(1, 1, {i, 0, 0});
    f.bodies = {{"plate", 1}, {"projectile", 2}};
    f.sets["clamp"] = {0, 2};
    f.sets["tip face"] = {4, 5, 6};
    f.sets["empty"] = {};
    f.setAreas["tip face"] = {Vec3(0.0, 0.0, 1e-6), Vec3(0.0, 0.0, 2e-6), Vec3(1e-7, 0.0, 1e-6)};
    f.provenance = {"gsph-test", "9.9.9", "plate.geo", std::string(64, 'a'), "refine=2", "SI"};
    return f;
}

/// One body of two spaces with transient particles (DESIGN §6), and a body of one space.
ParticleFile oversetFile() {
    ParticleFile f;
    f.spaces.resize(3);
    f.spaces[0].cells = {2, 2, 1};
    f.spaces[1].cells = {3, 1, 1};
    f.spaces[1].dtheta = 0.5;
    f.spaces[2].cells = {2, 1, 1};
    auto add = [&](Index s, Index b, std::array<Index, 3> ijk) {
        const double d = f.spaces[s].dtheta;
        const Vec3 theta = d * Vec3(ijk[0] + 0.5, ijk[1] + 0.5, ijk[2] + 0.5);
        f.theta.push_back(theta);
        f.X.push_back(1e-3 * theta + Vec3(0.1 * s, 0.0, 0.0));
        f.volume.push_back(1e-9);
        f.space.push_back(s);
        f.body.push_back(b);
        f.latticeIndex.push_back(ijk);
    };
    for (Index j = 0; j < 2; ++j) {
        for (Index i = 0; i < 2; ++i) add(0, 0, {i, j, 0});
    }
    for (Index i = 0; i < 3; ++i) add(1, 0, {i, 0, 0});
    for (Index i = 0; i < 2; ++i) add(2, 1, {i, 0, 0});
    f.bodies = {{"rod", 1}, {"anvil", 2}};
    f.transient = {0, 1, 0, 1, 1, 1, 0, 0, 0};
    f.overset.kappa = 1.5;
    // Sorted by (space, particle): particles 4 and 5 in space 0, particles 1 and 3 in space 1.
    f.overset.particle = {4, 5, 1, 3};
    f.overset.space = {0, 0, 1, 1};
    f.overset.theta = {Vec3(2.25, 0.5, 0.5), Vec3(2.75, 0.5, 1.0 / 3.0), Vec3(-0.25, 0.5, 0.25),
                       Vec3(-0.75, 0.5, 0.25)};
    f.overset.omega = {0.125, 0.125, 8.0, 8.0 + 1e-9};
    f.provenance = {"gsph-test", "9.9.9", "rod.geo", std::string(64, 'b'), "", "SI"};
    return f;
}

bool bitwiseEqual(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    // A file round trip must give back the very same bits, so exact comparison is the point.
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0);
}

bool bitwiseEqual(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

/// Runs a command and returns its standard output; `status` receives the exit status.
std::string run(const std::string& command, int& status) {
    std::string out;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) {
        status = -1;
        return out;
    }
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) out += buffer;
    status = ::pclose(pipe);
    return out;
}

/// Runs a Python script (h5py) from `dir`; returns its output, `status` its exit status.
std::string runPython(const test::TempDir& dir, const std::string& script, int& status) {
    std::ofstream(dir / "check.py") << script;
    return run("/usr/bin/python3 " + (dir / "check.py").string() + " 2>&1", status);
}

TEST(ParticleFile, RoundTripGivesIdenticalArrays) {
    test::TempDir dir;
    const ParticleFile f = sampleFile();
    writeParticleFile(dir / "p.h5", f);
    const ParticleFile g = readParticleFile(dir / "p.h5");

    EXPECT_TRUE(bitwiseEqual(f.X, g.X));
    EXPECT_TRUE(bitwiseEqual(f.theta, g.theta));
    EXPECT_TRUE(bitwiseEqual(f.volume, g.volume));
    EXPECT_EQ(f.space, g.space);
    EXPECT_EQ(f.body, g.body);
    EXPECT_EQ(f.latticeIndex, g.latticeIndex);
    ASSERT_EQ(g.spaces.size(), f.spaces.size());
    for (std::size_t s = 0; s < f.spaces.size(); ++s) {
        EXPECT_EQ(g.spaces[s].cells, f.spaces[s].cells);
        EXPECT_EQ(g.spaces[s].periodic, f.spaces[s].periodic);
        EXPECT_EQ(std::memcmp(&g.spaces[s].dtheta, &f.spaces[s].dtheta, sizeof(double)), 0);
    }
    ASSERT_EQ(g.bodies.size(), 2u);
    EXPECT_EQ(g.bodies[1].name, "projectile");
    EXPECT_EQ(g.bodies[1].sourceTag, 2);
    EXPECT_EQ(g.sets, f.sets);
    ASSERT_EQ(g.setAreas.size(), 1u);
    EXPECT_TRUE(bitwiseEqual(f.setAreas.at("tip face"), g.setAreas.at("tip face")));
    // The child-process reader (gsph-solve's) carries the sets and their areas too.
    const ParticleFile h = readParticleFileIsolated(dir / "p.h5");
    EXPECT_EQ(h.sets, f.sets);
    ASSERT_EQ(h.setAreas.size(), 1u);
    EXPECT_TRUE(bitwiseEqual(f.setAreas.at("tip face"), h.setAreas.at("tip face")));
    EXPECT_EQ(g.provenance.tool, "gsph-test");
    EXPECT_EQ(g.provenance.toolVersion, "9.9.9");
    EXPECT_EQ(g.provenance.sourceFile, "plate.geo");
    EXPECT_EQ(g.provenance.sourceSha256, std::string(64, 'a'));
    EXPECT_EQ(g.provenance.parameters, "refine=2");
    EXPECT_EQ(g.provenance.units, "SI");
    EXPECT_EQ(dir.entries(), 1);  // no temporary file left
}

TEST(ParticleFile, WithoutLatticeIndex) {
    test::TempDir dir;
    ParticleFile f = sampleFile();
    f.latticeIndex.clear();
    writeParticleFile(dir / "p.h5", f);
    EXPECT_TRUE(readParticleFile(dir / "p.h5").latticeIndex.empty());
}

// The lattice nodes (since 1.3): space after space, a periodic index with n nodes, read back
// exactly by both readers; a count that does not fit the spaces is refused.
TEST(ParticleFile, NodesRoundTripAndTheirCountIsChecked) {
    test::TempDir dir;
    ParticleFile f = sampleFile();
    f.spaces[0].periodic = {false, true, false};
    std::size_t expected = 0;
    for (const LatticeSpace& s : f.spaces)
        expected += static_cast<std::size_t>(s.cells[0] + (s.periodic[0] ? 0 : 1)) *
                    (s.cells[1] + (s.periodic[1] ? 0 : 1)) * (s.cells[2] + (s.periodic[2] ? 0 : 1));
    ASSERT_EQ(nodeCount(f.spaces), expected);
    for (std::size_t r = 0; r < expected; ++r)
        f.nodes.push_back(Vec3(0.1 * r, 1.0 / (r + 1), -3.0));
    EXPECT_EQ(nodeRow(f.spaces[0], 0, f.spaces[0].cells[1], 0), nodeRow(f.spaces[0], 0, 0, 0));
    writeParticleFile(dir / "p.h5", f);
    EXPECT_TRUE(bitwiseEqual(readParticleFile(dir / "p.h5").nodes, f.nodes));
    EXPECT_TRUE(bitwiseEqual(readParticleFileIsolated(dir / "p.h5").nodes, f.nodes));
    f.nodes.pop_back();
    EXPECT_THROW(writeParticleFile(dir / "q.h5", f), InputError);
    EXPECT_FALSE(std::filesystem::exists(dir / "q.h5"));
}

/// A 2-D file: the section 1 ≤ x ≤ 2, 0 ≤ y ≤ 1 in 3 × 2 cells, with its nodes (two layers of
/// unit depth) and a set "corner" holding particle 0's faces x = 1 and y = 0.
ParticleFile sectionFile() {
    ParticleFile f;
    f.dimension = 2;
    f.spaces.resize(1);
    f.spaces[0].cells = {3, 2, 1};
    const double dx = 1.0 / 3.0, dy = 0.5;
    for (Index j = 0; j < 2; ++j)
        for (Index i = 0; i < 3; ++i) {
            f.theta.push_back(Vec3(i + 0.5, j + 0.5, 0.0));
            f.X.push_back(Vec3(1.0 + (i + 0.5) * dx, (j + 0.5) * dy, 0.0));
            f.volume.push_back(dx * dy);
            f.space.push_back(0);
            f.body.push_back(0);
        }
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j <= 2; ++j)
            for (int i = 0; i <= 3; ++i) f.nodes.push_back(Vec3(1.0 + i * dx, j * dy, k));
    f.bodies = {{"ring", 1}};
    f.sets["corner"] = {0, 1};
    f.setAreas["corner"] = {Vec3(-dy, -dx, 0.0), Vec3(0.0, -0.5 * dx, 0.0)};
    return f;
}

// Dimension 2 is stored and read back by both readers; a 2-D file with two cells along a
// space's third index, or a particle off the plane z = 0, is refused.
TEST(ParticleFile, TwoDimensionalFilesRoundTripAndAreChecked) {
    test::TempDir dir;
    const ParticleFile f = sectionFile();
    writeParticleFile(dir / "p.h5", f);
    EXPECT_EQ(readParticleFile(dir / "p.h5").dimension, 2);
    EXPECT_EQ(readParticleFileIsolated(dir / "p.h5").dimension, 2);
    writeParticleFile(dir / "q.h5", sampleFile());
    EXPECT_EQ(readParticleFile(dir / "q.h5").dimension, 3);
    ParticleFile thick = f;
    thick.spaces[0].cells[2] = 2;
    EXPECT_THROW(writeParticleFile(dir / "r.h5", thick), InputError);
    ParticleFile lifted = f;
    lifted.X[3][2] = 1e-3;
    EXPECT_THROW(writeParticleFile(dir / "r.h5", lifted), InputError);
    ParticleFile fourD = f;
    fourD.dimension = 4;
    EXPECT_THROW(writeParticleFile(dir / "r.h5", fourD), InputError);
    EXPECT_FALSE(std::filesystem::exists(dir / "r.h5"));
}

// Swept about the y axis, each face becomes the ring 2π r_face |e| n: particle 0's two faces
// at their own radii (x = 1 and x = 1 + dx/2), exactly; particle 1's area, half its face's, does
// not split into edges, so its own radius stands in.
TEST(ParticleFile, SweptSetAreasTakeEachFaceAtItsRadius) {
    const ParticleFile f = sectionFile();
    const double pi = 3.141592653589793, dx = 1.0 / 3.0, dy = 0.5;
    const std::vector<Vec3> swept = sweptSetAreas(f, "corner");
    ASSERT_EQ(swept.size(), 2u);
    const Vec3 corner = 2 * pi * 1.0 * Vec3(-dy, 0, 0) + 2 * pi * (1.0 + dx / 2) * Vec3(0, -dx, 0);
    EXPECT_LE((swept[0] - corner).norm(), 1e-15 * corner.norm()) << swept[0].transpose();
    const Vec3 fallback = 2 * pi * f.X[1][0] * Vec3(0, -0.5 * dx, 0);
    EXPECT_LE((swept[1] - fallback).norm(), 1e-15 * fallback.norm()) << swept[1].transpose();
    EXPECT_THROW(sweptSetAreas(sampleFile(), "tip face"), InputError);
    EXPECT_THROW(sweptSetAreas(f, "none"), InputError);
}

TEST(ParticleFile, SameDataGivesSameBytes) {
    test::TempDir dir;
    writeParticleFile(dir / "a.h5", sampleFile());
    writeParticleFile(dir / "b.h5", sampleFile());
    EXPECT_EQ(sha256File(dir / "a.h5"), sha256File(dir / "b.h5"));
}

TEST(ParticleFile, ReadableByH5py) {
    test::TempDir dir;
    const ParticleFile f = sampleFile();
    writeParticleFile(dir / "p.h5", f);
    const std::string script =
        "import h5py\n"
        "f = h5py.File('" +
        (dir / "p.h5").string() +
        "', 'r')\n"
        "p = f['particles']\n"
        "print(f.attrs['format'], f.attrs['format_version'], f.attrs['units'])\n"
        "print(p['X'].shape, p['theta'].shape, p['volume'].shape, p['lattice_index'].shape)\n"
        "print(repr(float(p['X'][5, 1])), int(p['space'][6]), int(p['body'][6]))\n"
        "print(f['spaces/cells'][1].tolist(), f['spaces/periodic'][1].tolist())\n"
        "print(sorted(f['sets'].keys()), f['sets/tip face'][:].tolist())\n"
        "print([n.decode() for n in f['bodies/name'][:]], p['X'].attrs['units'])\n";
    int status = 0;
    const std::string out = runPython(dir, script, status);
    ASSERT_EQ(status, 0) << out;
    // Python prints a float in its shortest round-trip form: compare by value, exactly.
    EXPECT_NE(out.find("gsph-particles 1.4 SI"), std::string::npos) << out;
    EXPECT_NE(out.find("(7, 3) (7, 3) (7,) (7, 3)"), std::string::npos) << out;
    EXPECT_NE(out.find("[3, 1, 1] [1, 0, 0]"), std::string::npos) << out;
    EXPECT_NE(out.find("['clamp', 'empty', 'tip face'] [4, 5, 6]"), std::string::npos) << out;
    EXPECT_NE(out.find("['plate', 'projectile'] m"), std::string::npos) << out;
    const std::size_t line3 = out.find('\n', out.find('\n') + 1) + 1;
    EXPECT_EQ(std::stod(out.substr(line3)), f.X[5][1]) << out;  // exact: same bits
}

TEST(ParticleFile, InvalidContentIsRejectedAndNothingIsWritten) {
    test::TempDir dir;
    ParticleFile f = sampleFile();
    f.body[0] = 1;  // body 1 before body 0: not sorted
    EXPECT_THROW(writeParticleFile(dir / "p.h5", f), InputError);
    f = sampleFile();
    f.volume[3] = -1.0;
    EXPECT_THROW(writeParticleFile(dir / "p.h5", f), InputError);
    f = sampleFile();
    f.sets["clamp"] = {2, 0};
    EXPECT_THROW(writeParticleFile(dir / "p.h5", f), InputError);
    f = sampleFile();
    f.sets["a/b"] = {0};
    EXPECT_THROW(writeParticleFile(dir / "p.h5", f), InputError);
    f = sampleFile();
    f.latticeIndex[6] = {3, 0, 0};
    EXPECT_THROW(writeParticleFile(dir / "p.h5", f), InputError);
    f = sampleFile();
    f.setAreas["tip face"].pop_back();  // an area per particle of the set, or none
    EXPECT_THROW(writeParticleFile(dir / "p.h5", f), InputError);
    f = sampleFile();
    f.setAreas["no such set"] = {};
    EXPECT_THROW(writeParticleFile(dir / "p.h5", f), InputError);
    f = sampleFile();
    f.setAreas["tip face"][0][1] = std::nan("");
    EXPECT_THROW(writeParticleFile(dir / "p.h5", f), InputError);
    EXPECT_EQ(dir.entries(), 0);
}

TEST(ParticleFile, OversetRoundTrip) {
    test::TempDir dir;
    const ParticleFile f = oversetFile();
    writeParticleFile(dir / "p.h5", f);
    const ParticleFile g = readParticleFile(dir / "p.h5");
    EXPECT_EQ(g.transient, f.transient);
    EXPECT_EQ(g.overset.particle, f.overset.particle);
    EXPECT_EQ(g.overset.space, f.overset.space);
    EXPECT_TRUE(bitwiseEqual(g.overset.theta, f.overset.theta));
    EXPECT_TRUE(bitwiseEqual(g.overset.omega, f.overset.omega));
    EXPECT_EQ(std::memcmp(&g.overset.kappa, &f.overset.kappa, sizeof(double)), 0);
    const Reference ref = buildReference(g, std::vector<double>{8960.0, 7850.0}, 1.2);
    ASSERT_EQ(ref.overset.size(), f.overset.size());
    for (std::size_t e = 0; e < f.overset.size(); ++e) {
        EXPECT_EQ(ref.overset[e].particle, f.overset.particle[e]);
        EXPECT_EQ(ref.overset[e].space, f.overset.space[e]);
        EXPECT_EQ(
            std::memcmp(ref.overset[e].theta.data(), f.overset.theta[e].data(), 3 * sizeof(double)),
            0);
        EXPECT_EQ(std::memcmp(&ref.overset[e].omega, &f.overset.omega[e], sizeof(double)), 0);
    }
}

TEST(ParticleFile, OversetReadableByH5pyAndFormat10StillReads) {
    test::TempDir dir;
    const ParticleFile f = oversetFile();
    writeParticleFile(dir / "p.h5", f);
    // Read the overset data with h5py, then strip it and label the file 1.0, as an older
    // gsph-preproc wrote it.
    const std::string script =
        "import h5py\n"
        "f = h5py.File('" +
        (dir / "p.h5").string() +
        "', 'r+')\n"
        "o = f['overset']\n"
        "print(f.attrs['format_version'], o['particle'].shape, o['theta'].shape, "
        "o['omega'][2], o['kappa'][0], f['particles/transient'][:].tolist())\n"
        "del f['overset']\n"
        "del f['particles/transient']\n"
        "f.attrs['format_version'] = '1.0'\n";
    int status = 0;
    const std::string out = runPython(dir, script, status);
    ASSERT_EQ(status, 0) << out;
    EXPECT_EQ(out, "1.4 (4,) (4, 3) 8.0 1.5 [0, 1, 0, 1, 1, 1, 0, 0, 0]\n");
    const ParticleFile old = readParticleFile(dir / "p.h5");
    EXPECT_TRUE(old.transient.empty());
    EXPECT_EQ(old.overset.size(), 0u);
    EXPECT_EQ(old.size(), f.size());
}

TEST(ParticleFile, InvalidOversetIsRejected) {
    test::TempDir dir;
    const std::vector<std::pair<std::string, std::function<void(ParticleFile&)>>> faults = {
        {"particle out of range", [](ParticleFile& f) { f.overset.particle[3] = 9; }},
        {"space out of range", [](ParticleFile& f) { f.overset.space[3] = 3; }},
        {"own home space", [](ParticleFile& f) { f.overset.particle[0] = 0; }},
        {"another body", [](ParticleFile& f) { f.overset.space[3] = 2; }},
        {"not sorted",
         [](ParticleFile& f) { std::swap(f.overset.particle[0], f.overset.particle[1]); }},
        {"not sorted", [](ParticleFile& f) { f.overset.particle[1] = 4; }},
        {"theta", [](ParticleFile& f) { f.overset.theta[1][0] = NAN; }},
        {"theta", [](ParticleFile& f) { f.overset.theta[2][0] = -1.6; }},  // 2κΔθ = 1.5 in space 1
        {"omega", [](ParticleFile& f) { f.overset.omega[2] = 0.0; }},
        {"omega", [](ParticleFile& f) { f.overset.omega[2] = INFINITY; }},
        {"do not match", [](ParticleFile& f) { f.transient[6] = 1; }},
        {"do not match", [](ParticleFile& f) { f.transient[1] = 0; }},
        {"wrong length", [](ParticleFile& f) { f.transient.pop_back(); }},
        {"without /particles/transient", [](ParticleFile& f) { f.transient.clear(); }},
        {"differ in length", [](ParticleFile& f) { f.overset.omega.pop_back(); }},
        {"kappa", [](ParticleFile& f) { f.overset.kappa = 0.0; }},
    };
    for (const auto& [fault, mutate] : faults) {
        ParticleFile f = oversetFile();
        mutate(f);
        try {
            writeParticleFile(dir / "p.h5", f);
            ADD_FAILURE() << "no error for: " << fault;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(fault), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(dir.entries(), 0);
}

TEST(ParticleFile, ReadErrorsNameTheFile) {
    test::TempDir dir;
    const auto missing = dir / "missing.h5";
    try {
        readParticleFile(missing);
        FAIL() << "no error";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
    }
    std::ofstream(dir / "text.h5") << "not hdf5";
    EXPECT_THROW(readParticleFile(dir / "text.h5"), IoError);
    {
        h5::File other(dir / "other.h5", h5::File::Mode::Create);
        other.setAttribute("/", "format", std::string("something-else"));
        other.close();
    }
    EXPECT_THROW(readParticleFile(dir / "other.h5"), IoError);
    {
        h5::File future(dir / "future.h5", h5::File::Mode::Create);
        future.setAttribute("/", "format", std::string(kParticleFormat));
        future.setAttribute("/", "format_version", std::string("2.0"));
        future.close();
    }
    try {
        readParticleFile(dir / "future.h5");
        FAIL() << "no error";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("2.0"), std::string::npos) << e.what();
    }
}

TEST(ParticleFile, ProvenanceOfASource) {
    test::TempDir dir;
    std::ofstream(dir / "model.geo") << "Point(1) = {0, 0, 0};\n";
    const Provenance p = provenanceOf("gsph-test", "1.2.3", dir / "model.geo", "refine=2");
    EXPECT_EQ(p.tool, "gsph-test");
    EXPECT_EQ(p.toolVersion, "1.2.3");
    EXPECT_EQ(p.sourceFile, (dir / "model.geo").string());
    EXPECT_EQ(p.sourceSha256, sha256Hex("Point(1) = {0, 0, 0};\n"));
    EXPECT_EQ(p.parameters, "refine=2");
    EXPECT_EQ(p.units, "SI");
    EXPECT_THROW(provenanceOf("gsph-test", "1.2.3", dir / "missing.geo"), IoError);
}

TEST(ParticleFile, BuildReference) {
    const ParticleFile f = sampleFile();
    const std::vector<double> rho = {7850.0, 8960.0};
    const Reference ref = buildReference(f, rho, 1.5);
    ASSERT_EQ(ref.size(), f.size());
    EXPECT_EQ(ref.dim.value, 3);
    EXPECT_DOUBLE_EQ(ref.kappa, 1.5);
    EXPECT_EQ(ref.spaces.size(), 2u);
    EXPECT_TRUE(ref.spaces[1].periodic[0]);
    for (Index a = 0; a < f.size(); ++a) {
        EXPECT_NEAR(ref.density[a], rho[f.body[a]], 1e-15 * ref.density[a]);
    }
    EXPECT_EQ(ref.body, f.body);
    EXPECT_EQ(ref.space, f.space);
    EXPECT_THROW(buildReference(f, std::vector<double>{7850.0}, 1.5), InputError);
    EXPECT_THROW(buildReference(f, std::vector<double>{7850.0, -1.0}, 1.5), InputError);
    EXPECT_THROW(buildReference(f, rho, 0.0), InputError);
}

}  // namespace
}  // namespace gsph
