// SPDX-License-Identifier: MIT
// The particle file: round trip, h5py readability, validation, Reference from a file.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "io/hdf5_file.hpp"
#include "io/particle_file.hpp"
#include "io/sha256.hpp"
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
    f.provenance = {"gsph-test", "9.9.9", "plate.geo", std::string(64, 'a'), "refine=2", "SI"};
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
    std::ofstream(dir / "check.py") << script;
    int status = 0;
    const std::string out =
        run("/usr/bin/python3 " + (dir / "check.py").string() + " 2>&1", status);
    ASSERT_EQ(status, 0) << out;
    // Python prints a float in its shortest round-trip form: compare by value, exactly.
    EXPECT_NE(out.find("gsph-particles 1.0 SI"), std::string::npos) << out;
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
    }
    EXPECT_THROW(readParticleFile(dir / "other.h5"), IoError);
    {
        h5::File future(dir / "future.h5", h5::File::Mode::Create);
        future.setAttribute("/", "format", std::string(kParticleFormat));
        future.setAttribute("/", "format_version", std::string("2.0"));
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
