// SPDX-License-Identifier: MIT
// Every sample geometry in geometries/, converted in-process, checked against gmsh's own view of
// the same mesh: one particle per hex at its centre with its exact volume, θ on a uniform
// lattice whose neighbours are face neighbours in the mesh, bodies and sets as the .geo says,
// Σ V equal to the domain's volume (exact for straight-edged blocks, second order for curved).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "conversion.hpp"
#include "core/error.hpp"
#include "gmsh_input.hpp"
#include "gmsh_reference.hpp"
#include "particle_checks.hpp"
#include "temp_dir.hpp"

namespace gsph::preproc {
namespace {

using Parameters = std::vector<std::pair<std::string, double>>;

std::string geometry(const std::string& name) {
    return std::string(GSPH_SOURCE_DIR) + "/geometries/" + name;
}

Conversion convert(const std::string& path, const Parameters& parameters = {}) {
    std::vector<std::string> warnings;
    const HexMesh mesh = readHexMesh(path, MeshReadOptions{parameters}, warnings);
    Conversion c = convertHexMesh(mesh);
    warnings.insert(warnings.end(), c.warnings.begin(), c.warnings.end());
    for (const std::string& w : warnings) ADD_FAILURE() << path << ": warning: " << w;
    return c;
}

double totalVolume(const ParticleFile& f, Index body = -1) {
    double v = 0.0;
    for (Index a = 0; a < f.size(); ++a) v += (body < 0 || f.body[a] == body) ? f.volume[a] : 0.0;
    return v;
}

/// The checks shared by every sample: particle ↔ gmsh hex, centre, volume, lattice, neighbours.
void expectMatchesGmsh(const std::string& path, const Conversion& c,
                       const Parameters& parameters = {}) {
    const test::GmshHexes g = test::gmshHexes(path, parameters);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(static_cast<std::size_t>(f.size()), g.tags.size()) << "one particle per hex";
    test::expectLatticeLayout(f);
    validateParticleFile(f);

    double scale = 0.0, gmshTotal = 0.0;
    for (const Vec3& x : g.barycentre) scale = std::max(scale, x.cwiseAbs().maxCoeff());
    for (double v : g.volume) gmshTotal += v;
    std::vector<std::size_t> hexOf(f.size());
    std::vector<char> seen(g.tags.size(), 0);
    for (Index a = 0; a < f.size(); ++a) {
        const auto it = g.indexOfTag.find(c.elementOfParticle[a]);
        ASSERT_NE(it, g.indexOfTag.end());
        const std::size_t e = it->second;
        ASSERT_EQ(seen[e]++, 0) << "hex " << g.tags[e] << " gave two particles";
        hexOf[a] = e;
        // X(θ) is the hex's parametric centre = gmsh's barycentre of its 8 nodes.
        ASSERT_NEAR((f.X[a] - g.barycentre[e]).norm(), 0.0, 1e-14 * scale) << "particle " << a;
        ASSERT_NEAR(f.volume[a], g.volume[e], 1e-12 * g.volume[e]) << "particle " << a;
    }
    EXPECT_NEAR(totalVolume(f), gmshTotal, 1e-12 * gmshTotal);

    // Lattice neighbours (across periodic seams too) are face neighbours in gmsh's connectivity.
    Index first = 0;
    for (std::size_t s = 0; s < f.spaces.size(); ++s) {
        const auto n = f.spaces[s].cells;
        auto at = [&](int i, int j, int k) { return first + i + n[0] * (j + n[1] * k); };
        for (int k = 0; k < n[2]; ++k) {
            for (int j = 0; j < n[1]; ++j) {
                for (int i = 0; i < n[0]; ++i) {
                    for (int d = 0; d < 3; ++d) {
                        std::array<int, 3> m = {i, j, k};
                        if (++m[d] == n[d]) {
                            if (!f.spaces[s].periodic[d]) continue;
                            m[d] = 0;
                        }
                        const auto& p = g.nodes[hexOf[at(i, j, k)]];
                        const auto& q = g.nodes[hexOf[at(m[0], m[1], m[2])]];
                        int shared = 0;
                        for (std::size_t x : p)
                            shared += std::count(q.begin(), q.end(), x) > 0 ? 1 : 0;
                        ASSERT_EQ(shared, 4) << "space " << s << " cell " << i << "," << j << ","
                                             << k << " and its +"
                                             << "ijk"[d] << " neighbour";
                    }
                }
            }
        }
        first += n[0] * n[1] * n[2];
    }
}

int periodicAxes(const LatticeSpace& s) {
    return s.periodic[0] + s.periodic[1] + s.periodic[2];
}

TEST(Geometries, GradedBar) {
    const std::string path = geometry("graded_bar.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 1u);
    EXPECT_EQ(f.spaces[0].cells, (std::array<int, 3>{20, 4, 4}));
    EXPECT_NEAR(totalVolume(f), 0.1 * 0.01 * 0.01, 1e-10 * 1e-5);  // straight edges: exact
    ASSERT_EQ(f.bodies.size(), 1u);
    EXPECT_EQ(f.bodies[0].name, "bar");
    ASSERT_EQ(f.sets.at("clamp").size(), 16u);
    for (Index a : f.sets.at("clamp")) EXPECT_EQ(f.latticeIndex[a][0], 0);
    for (Index a : f.sets.at("load")) EXPECT_EQ(f.latticeIndex[a][0], 19);
    // Graded along x: cells grow by the grading ratio 1.1 from the clamp (gmsh places the
    // progression's nodes to about 1e-8).
    EXPECT_NEAR(f.volume[1] / f.volume[0], 1.1, 1e-6);
}

TEST(Geometries, BendingPlate) {
    const std::string path = geometry("bending_plate.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 1u) << "the 7 blocks along x glue into one space";
    EXPECT_EQ(f.spaces[0].cells, (std::array<int, 3>{100, 20, 6}));
    EXPECT_EQ(c.stats.spaceVolumes[0].size(), 7u);
    EXPECT_NEAR(totalVolume(f), 0.2 * 0.04 * 0.005, 1e-10 * 4e-5);
    for (const char* set : {"support_left", "support_right", "load"}) {
        EXPECT_EQ(f.sets.at(set).size(), 40u) << set;  // a 2-cell strip across the 20-cell width
    }
    for (Index a : f.sets.at("load")) EXPECT_EQ(f.latticeIndex[a][2], 5);
    for (Index a : f.sets.at("support_left")) EXPECT_EQ(f.latticeIndex[a][2], 0);
}

TEST(Geometries, QuarterCylinder) {
    const std::string path = geometry("quarter_cylinder.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 2u) << "Cartesian core and cylindrical outer block";
    EXPECT_EQ(f.spaces[0].cells, (std::array<int, 3>{8, 8, 1}));
    EXPECT_EQ(f.spaces[1].cells[0] * f.spaces[1].cells[1], 16 * 6);
    EXPECT_EQ(periodicAxes(f.spaces[0]) + periodicAxes(f.spaces[1]), 0);
    const double exact = M_PI * 0.01 * 0.01 * 0.001 / 4.0;
    EXPECT_NEAR(totalVolume(f) / exact, 1.0, 2e-3);
    EXPECT_EQ(f.sets.at("outer").size(), 16u);
    EXPECT_EQ(f.sets.at("symmetry_x").size(), 14u);
}

TEST(Geometries, TaylorBarOgrid) {
    const std::string path = geometry("taylor_bar.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 2u);
    const LatticeSpace& core = f.spaces[0];
    const LatticeSpace& ring = f.spaces[1];
    EXPECT_EQ(core.cells, (std::array<int, 3>{8, 8, 40}));
    EXPECT_EQ(periodicAxes(core), 0);
    ASSERT_EQ(periodicAxes(ring), 1) << "the annulus closes on itself in its angular index";
    for (int d = 0; d < 3; ++d) {
        if (ring.periodic[d]) {
            EXPECT_EQ(ring.cells[d], 32);  // 4 quarters × 8
        }
    }
    EXPECT_EQ(c.stats.spaceVolumes[1].size(), 4u);
    const double exact = M_PI * 3.8e-3 * 3.8e-3 * 25.4e-3;
    EXPECT_NEAR(totalVolume(f) / exact, 1.0, 1e-2);
    ASSERT_EQ(f.sets.at("impact").size(), 8u * 8u + 4u * 8u * 4u);
    for (Index a : f.sets.at("impact")) EXPECT_EQ(f.latticeIndex[a][2], 0);
    EXPECT_EQ(f.sets.at("lateral").size(), 32u * 40u);
}

TEST(Geometries, NotchedPlate) {
    const std::string path = geometry("notched_plate.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 3u);
    EXPECT_EQ(f.spaces[2].cells, (std::array<int, 3>{25, 51, 2})) << "the ligament";
    EXPECT_NEAR(totalVolume(f), 0.1 * 0.1 * 0.004 - 0.05 * 0.002 * 0.004, 1e-10 * 4e-5);
    EXPECT_EQ(f.sets.at("notch_tip").size(), 2u);
}

TEST(Geometries, PlateAndProjectile) {
    const std::string path = geometry("plate_projectile.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.bodies.size(), 2u);
    EXPECT_EQ(f.bodies[0].name, "plate");
    EXPECT_EQ(f.bodies[1].name, "projectile");
    ASSERT_EQ(f.spaces.size(), 3u);  // plate; projectile core; projectile annulus
    EXPECT_EQ(periodicAxes(f.spaces[2]), 1);
    EXPECT_NEAR(totalVolume(f, 0), 0.1 * 0.1 * 0.012, 1e-10 * 1.2e-4);
    EXPECT_NEAR(totalVolume(f, 1) / (M_PI * 0.01 * 0.01 * 0.08), 1.0, 2e-2);
    for (Index a : f.sets.at("nose")) EXPECT_EQ(f.body[a], 1);
    for (Index a : f.sets.at("plate_rim")) EXPECT_EQ(f.body[a], 0);
}

TEST(Geometries, MshGivesTheSameParticlesAsGeo) {
    test::TempDir dir;
    const std::string path = geometry("taylor_bar.geo");
    const std::string msh = (dir / "taylor_bar.msh").string();
    test::gmshHexes(path, {}, msh);  // gmsh -3 taylor_bar.geo -o taylor_bar.msh
    const Conversion a = convert(path);
    const Conversion b = convert(msh);
    ASSERT_EQ(a.particles.size(), b.particles.size());
    EXPECT_EQ(a.particles.latticeIndex, b.particles.latticeIndex);
    EXPECT_EQ(a.particles.space, b.particles.space);
    EXPECT_EQ(a.particles.sets, b.particles.sets);
    EXPECT_EQ(a.elementOfParticle, b.elementOfParticle);
    for (Index p = 0; p < a.particles.size(); ++p) {
        // The .msh stores coordinates in decimal: equal to round-off.
        ASSERT_NEAR((a.particles.X[p] - b.particles.X[p]).norm(), 0.0, 1e-15);
    }
}

/// Observed order of the volume error of a curved geometry over refinements 1, 2, 4.
std::vector<double> observedOrders(const std::string& name, const Parameters& fixed, double exact) {
    std::vector<double> errors;
    for (double refine : {1.0, 2.0, 4.0}) {
        Parameters p = fixed;
        p.emplace_back("refine", refine);
        const Conversion c = convert(geometry(name), p);
        errors.push_back(std::abs(totalVolume(c.particles) - exact) / exact);
    }
    const std::vector<double> orders = {std::log2(errors[0] / errors[1]),
                                        std::log2(errors[1] / errors[2])};
    std::printf("%s: relative volume errors %.3e %.3e %.3e, observed orders %.3f %.3f\n",
                name.c_str(), errors[0], errors[1], errors[2], orders[0], orders[1]);
    return orders;
}

TEST(Geometries, CurvedBlocksConvergeAtSecondOrder) {
    // Quarter cylinder (R = 10 mm, slab 1 mm thick) and the O-grid Taylor bar cut to one layer.
    for (double p : observedOrders("quarter_cylinder.geo", {}, M_PI * 1e-4 * 1e-3 / 4.0)) {
        EXPECT_GE(p, 1.8);
    }
    const double R = 3.8e-3, L = 1e-3;
    for (double p : observedOrders("taylor_bar.geo", {{"L", L}, {"nz", 1}}, M_PI * R * R * L)) {
        EXPECT_GE(p, 1.8);
    }
}

}  // namespace
}  // namespace gsph::preproc

namespace gsph::preproc {
namespace {

TEST(Geometries, ParametersDoNotLeakBetweenCalls) {
    // gmsh keeps some parser state for the whole process; readHexMesh must not let one call's
    // parameters (or one .geo's DefineConstant values) reach the next call.
    const std::string taylor = geometry("taylor_bar.geo");
    const double before = totalVolume(convert(taylor).particles);
    convert(geometry("quarter_cylinder.geo"), {{"R", 0.05}, {"refine", 2}});
    convert(taylor, {{"L", 0.001}, {"nz", 1}});
    const double after = totalVolume(convert(taylor).particles);
    EXPECT_EQ(before, after);  // the same mesh, converted the same way: bit-identical
}

/// Reads and converts a fixture from tests/data; returns the error message, "" if none.
template <class Error>
std::string errorOf(const std::string& file, const Parameters& parameters = {}) {
    const std::string path = std::string(GSPH_SOURCE_DIR) + "/tests/data/" + file;
    try {
        std::vector<std::string> warnings;
        convertHexMesh(readHexMesh(path, MeshReadOptions{parameters}, warnings));
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path + ": ", 0), 0u)
            << "the message must start with the file: " << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        return what;
    }
    ADD_FAILURE() << file << ": no error";
    return "";
}

TEST(PreprocErrors, BadInputsGiveClearErrors) {
    EXPECT_NE(errorOf<InputError>("missing.geo").find("no such file"), std::string::npos);
    EXPECT_NE(errorOf<InputError>("bad_syntax.geo").find("line 3: syntax error"),
              std::string::npos);
    EXPECT_NE(errorOf<MeshError>("tetrahedra.geo").find("4-node tetrahedra"), std::string::npos);
    EXPECT_NE(errorOf<MeshError>("mixed.msh").find("6-node prisms"), std::string::npos);
    EXPECT_NE(errorOf<MeshError>("unstructured_hex.geo").find("not a structured hex block"),
              std::string::npos);
    EXPECT_NE(errorOf<MeshError>("inverted.msh").find("element 2 in volume 1 is inverted"),
              std::string::npos);
    EXPECT_NE(errorOf<MeshError>("folded.msh").find("folds"), std::string::npos);
    EXPECT_NE(errorOf<MeshError>("empty.msh").find("no hexahedra"), std::string::npos);
    EXPECT_NE(errorOf<MeshError>("no_volume.geo").find("no hexahedra"), std::string::npos);
    EXPECT_NE(errorOf<MeshError>("ungrouped_volume.geo").find("volume 2 is in no physical volume"),
              std::string::npos);
    EXPECT_NE(errorOf<MeshError>("bad_transfinite.geo").find("transfinite"), std::string::npos);
    EXPECT_NE(errorOf<InputError>("inverted.msh", {{"refine", 2}}).find(".geo files only"),
              std::string::npos);
}

}  // namespace
}  // namespace gsph::preproc
