// SPDX-License-Identifier: MIT
// 2-D gmsh meshes of quadrangles, converted in-process into 2-D particle files: the samples
// geometries/taylor_bar_axisymmetric.geo and plate_2d.geo, the O-grid disc (an overset body in
// the plane), the uniform lattice, and the 2-D inputs that are refused. Each particle file must
// read back and give a reference whose metric computes: F = I at rest.
#include <gmsh.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "conversion.hpp"
#include "core/error.hpp"
#include "gmsh_input.hpp"
#include "kinematics/deformation_gradient.hpp"
#include "mesh_errors.hpp"
#include "particle_checks.hpp"
#include "reference/reference_builder.hpp"
#include "temp_dir.hpp"

namespace gsph::preproc {
namespace {

using Parameters = std::vector<std::pair<std::string, double>>;

std::string geometry(const std::string& name) {
    return std::string(GSPH_SOURCE_DIR) + "/geometries/" + name;
}
std::string fixture(const std::string& name) {
    return std::string(GSPH_SOURCE_DIR) + "/tests/data/" + name;
}

Conversion convert(const std::string& path, const ConversionOptions& options = {},
                   const Parameters& parameters = {}) {
    std::vector<std::string> warnings;
    const HexMesh mesh = readHexMesh(path, MeshReadOptions{parameters}, warnings);
    EXPECT_EQ(mesh.dimension, 2);
    Conversion c = convertHexMesh(mesh, options);
    warnings.insert(warnings.end(), c.warnings.begin(), c.warnings.end());
    for (const std::string& w : warnings) ADD_FAILURE() << path << ": warning: " << w;
    return c;
}

double totalVolume(const ParticleFile& f) {
    double v = 0.0;
    for (double x : f.volume) v += x;
    return v;
}

Vec3 totalArea(const ParticleFile& f, const std::string& set) {
    Vec3 sum = Vec3::Zero();
    for (const Vec3& a : f.setAreas.at(set)) sum += a;
    return sum;
}

/// What every 2-D file holds: dimension 2, one cell along index 2, X_z = θ_z = 0 (overset
/// entries included), set areas in the plane, and nodes as two layers (z = 0, z = 1) of the
/// same in-plane points.
void expectPlaneFile(const ParticleFile& f) {
    ASSERT_EQ(f.dimension, 2);
    validateParticleFile(f);
    for (const LatticeSpace& s : f.spaces) {
        EXPECT_EQ(s.cells[2], 1);
        EXPECT_FALSE(s.periodic[2]);
    }
    for (Index a = 0; a < f.size(); ++a) {
        ASSERT_EQ(f.X[a][2], 0.0);
        ASSERT_EQ(f.theta[a][2], 0.0);
        ASSERT_EQ(f.latticeIndex[a][2], 0);
        ASSERT_GT(f.volume[a], 0.0);
    }
    for (const Vec3& theta : f.overset.theta) ASSERT_EQ(theta[2], 0.0);
    for (const auto& [name, areas] : f.setAreas)
        for (const Vec3& area : areas) ASSERT_EQ(area[2], 0.0) << name;
    ASSERT_EQ(f.nodes.size(), nodeCount(f.spaces));
    std::size_t first = 0;
    for (const LatticeSpace& s : f.spaces) {
        const auto m = nodeExtent(s);
        ASSERT_EQ(m[2], 2u);
        for (std::size_t j = 0; j < m[1]; ++j)
            for (std::size_t i = 0; i < m[0]; ++i) {
                const Vec3& bottom = f.nodes[first + nodeRow(s, int(i), int(j), 0)];
                const Vec3& top = f.nodes[first + nodeRow(s, int(i), int(j), 1)];
                ASSERT_EQ(bottom[2], 0.0);
                ASSERT_EQ(top[2], 1.0);
                ASSERT_EQ(bottom.head<2>(), top.head<2>());
            }
        first += m[0] * m[1] * m[2];
    }
}

/// Writes and reads back the file (the same content), builds its reference in 2-D and
/// returns the largest |F − I| at rest.
double restDeformationError(const ParticleFile& converted, double kappa = 1.2) {
    test::TempDir dir;
    const auto path = dir / "plane.h5";
    ParticleFile toWrite = converted;
    toWrite.provenance = {"test", "0", "plane", "", "", "SI"};
    writeParticleFile(path, toWrite);
    const ParticleFile f = readParticleFile(path);
    EXPECT_EQ(f.dimension, 2);
    EXPECT_EQ(f.X, converted.X);
    EXPECT_EQ(f.volume, converted.volume);
    EXPECT_EQ(f.nodes, converted.nodes);
    EXPECT_EQ(f.setAreas, converted.setAreas);
    Reference ref =
        buildReference(f, std::vector<double>(f.bodies.size(), 8960.0), kappa);  // copper
    EXPECT_EQ(ref.dim.value, 2);
    completeReference(ref);
    std::vector<Mat3> F;
    deformationGradient(ref, ref.X, F);
    double worst = 0.0;
    for (const Mat3& Fa : F) worst = std::max(worst, (Fa - Mat3::Identity()).cwiseAbs().maxCoeff());
    return worst;
}

TEST(Preproc2d, TaylorBarAxisymmetricSection) {
    const double R = 3.8e-3, L = 25.4e-3;
    const Conversion c = convert(geometry("taylor_bar_axisymmetric.geo"));
    const ParticleFile& f = c.particles;
    expectPlaneFile(f);
    test::expectLatticeLayout(f);
    // 8 cells across the radius, round(8 L / R) = 53 along the axis: one space.
    ASSERT_EQ(f.spaces.size(), 1u);
    EXPECT_EQ(f.spaces[0].cells, (Int3{8, 53, 1}));
    EXPECT_EQ(f.size(), 8 * 53);
    ASSERT_EQ(f.bodies.size(), 1u);
    EXPECT_EQ(f.bodies[0].name, "rod");
    EXPECT_NEAR(totalVolume(f), R * L, 1e-12 * R * L);
    for (Index a = 0; a < f.size(); ++a) EXPECT_GT(f.X[a][0], 0.0);  // r > 0 everywhere
    // The straight edges' sets: one cell row each, Σ area = length × outward normal.
    const std::map<std::string, std::pair<std::size_t, Vec3>> edges = {
        {"impact", {8, Vec3(0, -R, 0)}},
        {"free_end", {8, Vec3(0, R, 0)}},
        {"axis", {53, Vec3(-L, 0, 0)}},
        {"lateral", {53, Vec3(L, 0, 0)}}};
    for (const auto& [name, expected] : edges) {
        ASSERT_EQ(f.sets.count(name), 1u) << name;
        EXPECT_EQ(f.sets.at(name).size(), expected.first) << name;
        EXPECT_LT((totalArea(f, name) - expected.second).norm(), 1e-12 * expected.second.norm())
            << name;
    }
    for (Index a : f.sets.at("impact")) EXPECT_EQ(f.latticeIndex[a][1], 0);
    for (Index a : f.sets.at("axis")) EXPECT_EQ(f.latticeIndex[a][0], 0);
    const double error = restDeformationError(f);
    std::printf(
        "[2-D] taylor_bar_axisymmetric: %ld particles, sum V - R L = %.2e m^2, "
        "|F - I| at rest %.2e\n",
        static_cast<long>(f.size()), totalVolume(f) - R * L, error);
    EXPECT_LT(error, 1e-13);
}

TEST(Preproc2d, TaylorBarAxisymmetricRefines) {
    const Conversion c = convert(geometry("taylor_bar_axisymmetric.geo"), {}, {{"refine", 2}});
    EXPECT_EQ(c.particles.spaces[0].cells, (Int3{16, 107, 1}));
}

// Refined, a graded section keeps its layout: every cell `refine` times smaller, the ratio of
// successive cells its refine-th root (as taylor_bar.geo refines).
TEST(Preproc2d, TaylorBarAxisymmetricRefinesItsGrading) {
    const Conversion c = convert(geometry("taylor_bar_axisymmetric.geo"), {},
                                 {{"nr", 6}, {"nz", 30}, {"grading", 1.08}, {"refine", 2}});
    const ParticleFile& f = c.particles;
    const Int3 cells = f.spaces[0].cells;
    ASSERT_EQ(cells, (Int3{12, 60, 1}));
    // The cells next to the axis, first and last along it (areas: lip 1, equal widths).
    const double first = f.volume[0];
    const double last = f.volume[static_cast<std::size_t>(cells[0] * (cells[1] - 1))];
    const double expected = std::pow(1.08, (cells[1] - 1) / 2.0);
    EXPECT_NEAR(last / first, expected, 1e-7 * expected);
}

TEST(Preproc2d, GradedPlate) {
    const double W = 0.04, H = 0.02;
    const Conversion c = convert(geometry("plate_2d.geo"));
    const ParticleFile& f = c.particles;
    expectPlaneFile(f);
    test::expectLatticeLayout(f);
    EXPECT_EQ(f.size(), 20 * 12);
    EXPECT_NEAR(totalVolume(f), W * H, 1e-12 * W * H);
    // Graded towards y = 0: the cells of the first row are the smallest, by 1.1^11 from the
    // last row's (gmsh places the progression's nodes to ~1e-8).
    const double bottom = f.volume[0], topRow = f.volume[static_cast<std::size_t>(f.size() - 1)];
    EXPECT_NEAR(topRow / bottom, std::pow(1.1, 11), 1e-7);
    const std::map<std::string, Vec3> normals = {{"bottom", Vec3(0, -W, 0)},
                                                 {"top", Vec3(0, W, 0)},
                                                 {"left", Vec3(-H, 0, 0)},
                                                 {"right", Vec3(H, 0, 0)}};
    for (const auto& [name, expected] : normals) {  // the edges' sets
        ASSERT_EQ(f.sets.count(name), 1u) << name;
        EXPECT_LT((totalArea(f, name) - expected).norm(), 1e-12 * expected.norm()) << name;
    }
    EXPECT_EQ(f.sets.at("left").size(), 12u);
    EXPECT_EQ(f.sets.at("bottom").size(), 20u);
    const double error = restDeformationError(f);
    std::printf("[2-D] plate_2d: |F - I| at rest %.2e\n", error);
    EXPECT_LT(error, 1e-13);
}

TEST(Preproc2d, OgridDiscIsAnOversetBodyInThePlane) {
    const Conversion c = convert(fixture("ogrid_disc_2d.geo"));
    const ParticleFile& f = c.particles;
    expectPlaneFile(f);
    test::expectLatticeLayout(f);
    // The core (8 × 8) and the annulus (4 blocks of 8 × 4, periodic in its angular index).
    ASSERT_EQ(f.spaces.size(), 2u);
    EXPECT_EQ(f.spaces[0].cells, (Int3{8, 8, 1}));
    const Int3 annulus = f.spaces[1].cells;
    EXPECT_EQ(annulus[0] * annulus[1], 32 * 4);
    EXPECT_TRUE(f.spaces[1].periodic[0] || f.spaces[1].periodic[1]);
    EXPECT_EQ(f.size(), 64 + 128);  // the spaces abut: nothing is cut
    // Σ V: the 32-gon of the rim's nodes (straight cell edges), to round-off.
    const double R = 3.8e-3, polygon = 16.0 * R * R * std::sin(std::numbers::pi / 16.0);
    EXPECT_NEAR(totalVolume(f), polygon, 1e-12 * polygon);
    EXPECT_LT((totalArea(f, "rim")).norm(), 1e-12 * R);  // a closed curve: Σ n dl = 0
    EXPECT_EQ(f.sets.at("rim").size(), 32u);
    ASSERT_EQ(f.sets.count("curve_77"), 1u);  // an unnamed physical curve: a quarter of the rim
    EXPECT_EQ(f.sets.at("curve_77").size(), 8u);
    // Transients both ways across the interface, with finite θ in the plane.
    ASSERT_GT(f.overset.size(), 0u);
    int intoCore = 0, intoAnnulus = 0;
    for (std::size_t e = 0; e < f.overset.size(); ++e) {
        (f.overset.space[e] == 0 ? intoCore : intoAnnulus) += 1;
        EXPECT_TRUE(f.overset.theta[e].allFinite());
    }
    EXPECT_GT(intoCore, 0);
    EXPECT_GT(intoAnnulus, 0);
    const double error = restDeformationError(f);
    std::printf(
        "[2-D] O-grid disc: %ld particles, %zu overset entries (%d into the core, %d into "
        "the annulus), |F - I| at rest %.2e\n",
        static_cast<long>(f.size()), f.overset.size(), intoCore, intoAnnulus, error);
    EXPECT_LT(error, 1e-13);
}

TEST(Preproc2d, ClockwiseQuadsConvertLikeCounterClockwiseOnes) {
    // gmsh's quads run clockwise here (normal −z): turned before extrusion, they give positive
    // volumes and a right-handed in-plane frame.
    const Conversion c = convert(fixture("clockwise_square_2d.geo"));
    const ParticleFile& f = c.particles;
    expectPlaneFile(f);
    test::expectLatticeLayout(f);
    EXPECT_EQ(f.size(), 9);
    EXPECT_NEAR(totalVolume(f), 1.0, 1e-12);
    EXPECT_LT((totalArea(f, "bottom") - Vec3(0, -1, 0)).norm(), 1e-12);
    EXPECT_LT(restDeformationError(f), 1e-13);
}

TEST(Preproc2d, UniformLatticeInThePlane) {
    const double W = 0.04, H = 0.02;
    ConversionOptions options;
    options.latticeSpacing = 1e-3;
    const Conversion c = convert(geometry("plate_2d.geo"), options);
    const ParticleFile& f = c.particles;
    expectPlaneFile(f);
    test::expectLatticeLayout(f);
    ASSERT_EQ(f.spaces.size(), 1u);
    EXPECT_EQ(f.spaces[0].cells, (Int3{40, 20, 1}));
    EXPECT_EQ(f.size(), 800);
    EXPECT_NEAR(totalVolume(f), W * H, 1e-12 * W * H);
    EXPECT_LT((totalArea(f, "bottom") - Vec3(0, -W, 0)).norm(), 1e-12 * W);
    EXPECT_LT((totalArea(f, "right") - Vec3(H, 0, 0)).norm(), 1e-12 * H);
    EXPECT_EQ(f.sets.at("bottom").size(), 40u);
    const double error = restDeformationError(f);
    std::printf("[2-D] plate_2d --lattice 1e-3: |F - I| at rest %.2e\n", error);
    EXPECT_LT(error, 1e-13);
}

TEST(Preproc2d, MshGivesTheSameParticlesAsGeo) {
    test::TempDir dir;
    const std::string geo = geometry("plate_2d.geo");
    const std::string msh = (dir / "plate_2d.msh").string();
    const int threads = omp_get_max_threads();  // gmsh::initialize sets it to 1
    gmsh::initialize(0, nullptr, false);        // gmsh -2 plate_2d.geo -o plate_2d.msh
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::onelab::clear();
    gmsh::open(geo);
    gmsh::model::mesh::generate(2);
    gmsh::write(msh);
    gmsh::finalize();
    omp_set_num_threads(threads);
    const Conversion a = convert(geo);
    const Conversion b = convert(msh);
    expectPlaneFile(b.particles);
    ASSERT_EQ(a.particles.size(), b.particles.size());
    EXPECT_EQ(a.particles.latticeIndex, b.particles.latticeIndex);
    EXPECT_EQ(a.particles.sets, b.particles.sets);
    EXPECT_EQ(a.elementOfParticle, b.elementOfParticle);
    double worst = 0.0;  // the .msh stores coordinates in decimal: equal to round-off
    for (Index p = 0; p < a.particles.size(); ++p)
        worst = std::max(worst, (a.particles.X[p] - b.particles.X[p]).norm());
    EXPECT_LT(worst, 1e-17);
}

TEST(Preproc2d, BadPlaneMeshesGiveClearErrors) {
    EXPECT_NE(test::meshErrorOf<MeshError>("triangles_2d.geo")
                  .find("surface 1 holds 18 3-node triangles; gsph-preproc needs structured "
                        "blocks of 4-node quadrangles in 2-D"),
              std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("unstructured_quads_2d.geo")
                  .find("surface 1 is not a structured quad block"),
              std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("mixed_2d_3d.geo")
                  .find("the mesh mixes 2-D and 3-D elements (surface 101"),
              std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("no_volume.geo").find("no hexahedra or quadrangles"),
              std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("off_plane_2d.geo")
                  .find("a 2-D mesh must lie in the plane z = 0 (its node at (0, 0, 1) does not)"),
              std::string::npos);
}

}  // namespace
}  // namespace gsph::preproc
