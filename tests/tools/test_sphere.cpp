// SPDX-License-Identifier: MIT
// The cubed sphere (geometries/sphere.geo) end to end: a cube core and six shell blocks, three
// at every edge of the cube, glued into two spaces coupled across the faces they share
// (preproc/overset.hpp). Its volume converges at second order to the sphere's; the continued
// lattices are the mesh's own cells across each shared face; at rest nothing moves; an affine
// motion gives F exactly on both spaces.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "converted_layout.hpp"
#include "gmsh_input.hpp"
#include "kinematics/deformation_gradient.hpp"
#include "overset_checks.hpp"
#include "simulation.hpp"

namespace gsph {
namespace {

constexpr double kRadius = 5e-3;
constexpr double kSteelDensity = 7800.0;

ElasticConstants steel() {
    return ElasticConstants(kSteelDensity, 200e9, 0.3);
}

preproc::Conversion convertSphere(const std::vector<std::pair<std::string, double>>& parameters,
                                  preproc::TransientRule rule = preproc::TransientRule::Automatic,
                                  preproc::HexMesh* meshOut = nullptr) {
    const std::string path = std::string(GSPH_SOURCE_DIR) + "/geometries/sphere.geo";
    std::vector<std::string> warnings;
    preproc::HexMesh mesh =
        preproc::readHexMesh(path, preproc::MeshReadOptions{parameters}, warnings);
    preproc::ConversionOptions options;
    options.transients = rule;
    preproc::Conversion c = preproc::convertHexMesh(mesh, options);
    warnings.insert(warnings.end(), c.warnings.begin(), c.warnings.end());
    for (const std::string& w : warnings) ADD_FAILURE() << path << ": warning: " << w;
    validateParticleFile(c.particles);
    if (meshOut != nullptr) *meshOut = std::move(mesh);
    return c;
}

double volumeOf(const ParticleFile& f) {
    double v = 0.0;
    for (double V : f.volume) v += V;
    return v;
}

TEST(CubedSphere, VolumeConvergesAtSecondOrder) {
    const double exact = 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
    double error[3];
    for (int r = 1; r <= 3; ++r) {
        const preproc::Conversion c = convertSphere({{"refine", r}});
        error[r - 1] = std::abs(volumeOf(c.particles) - exact) / exact;
        std::printf("[sphere] refine %d: %d particles in %zu spaces, volume error %.3e\n", r,
                    c.particles.size(), c.particles.spaces.size(), error[r - 1]);
    }
    const double order12 = std::log(error[0] / error[1]) / std::log(2.0);
    const double order23 = std::log(error[1] / error[2]) / std::log(1.5);
    std::printf("[sphere] observed order %.3f (refine 1→2), %.3f (2→3)\n", order12, order23);
    EXPECT_NEAR(order12, 2.0, 0.05);
    EXPECT_NEAR(order23, 2.0, 0.05);
}

// Each continued entry sits on a cell centre of the space it is transient in, on no other
// particle's θ; one just across a shared face (half a cell past the lattice) has a particle of
// that space one cell away in θ whose hexahedron shares that face with its own (4 nodes).
TEST(CubedSphere, ContinuedLatticeIsTheMeshAcrossEachSharedFace) {
    preproc::HexMesh mesh;
    const preproc::Conversion c = convertSphere({}, preproc::TransientRule::Lattice, &mesh);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 2u);
    const auto maps = test::spaceMapsOf(mesh);
    std::set<std::tuple<Index, long, long, long>> occupied;
    for (Index a = 0; a < f.size(); ++a) {
        const Vec3& t = f.theta[a];
        occupied.insert(
            {f.space[a], std::lround(2 * t[0]), std::lround(2 * t[1]), std::lround(2 * t[2])});
    }
    long faceNeighbours = 0;
    for (std::size_t e = 0; e < f.overset.size(); ++e) {
        const Index b = f.overset.particle[e], s = f.overset.space[e];
        const Vec3& t = f.overset.theta[e];
        for (int d = 0; d < 3; ++d) ASSERT_EQ(t[d] - std::floor(t[d]), 0.5) << "entry " << e;
        ASSERT_TRUE(
            occupied
                .insert({s, std::lround(2 * t[0]), std::lround(2 * t[1]), std::lround(2 * t[2])})
                .second)
            << "entry " << e << " lands on another particle's theta";
        // ω = V / det ∂X/∂θ of b's own hex.
        const auto& cb = f.latticeIndex[b];
        const preproc::HexCorners xb = maps[f.space[b]]->corners({cb[0], cb[1], cb[2]});
        EXPECT_NEAR(f.overset.omega[e],
                    f.volume[b] / (8.0 * preproc::hexJacobian(xb, Vec3::Zero()).determinant()),
                    1e-12 * f.overset.omega[e]);
        for (Index a = 0; a < f.size(); ++a) {
            if (f.space[a] != s || (f.theta[a] - t).norm() != 1.0) continue;
            const auto& ca = f.latticeIndex[a];
            const preproc::HexCorners xa = maps[s]->corners({ca[0], ca[1], ca[2]});
            int shared = 0;
            for (const Vec3& p : xa)
                for (const Vec3& q : xb) shared += p == q ? 1 : 0;
            EXPECT_EQ(shared, 4) << "entry " << e << " and particle " << a;
            ++faceNeighbours;
        }
    }
    std::printf("[sphere] %zu continued entries, %ld pairs across a shared face checked\n",
                f.overset.size(), faceNeighbours);
    EXPECT_GT(faceNeighbours, 0);
}

// The extended map alone cannot reach across the column's concave bends: the error names the
// particle's hex and both spaces by gmsh volumes and body.
TEST(CubedSphere, ExtendedMapAloneFoldsAndSaysWhere) {
    try {
        convertSphere({}, preproc::TransientRule::Map);
        FAIL() << "--transients map converted the cubed sphere";
    } catch (const MeshError& e) {
        const std::string what = e.what();
        for (const char* part : {"sphere.geo: particle ", "(gmsh element ",
                                 "of body 'ball' (gmsh volumes ", "cannot be located there"}) {
            EXPECT_NE(what.find(part), std::string::npos) << part << "\n" << what;
        }
    }
}

TEST(CubedSphere, StaysAtRestAndAffineMotionGivesExactF) {
    for (const preproc::TransientRule rule :
         {preproc::TransientRule::Automatic, preproc::TransientRule::Lattice}) {
        const preproc::Conversion c = convertSphere({}, rule);
        Reference ref = buildReference(c.particles, std::vector<double>{kSteelDensity}, 1.2);
        buildPairs(ref);
        computeGeometry(ref);
        const Mat3 A =
            (Mat3() << 1.10, 0.07, -0.03, -0.05, 0.92, 0.04, 0.02, -0.06, 1.05).finished();
        std::vector<Vec3> x(ref.X.size());
        for (std::size_t a = 0; a < x.size(); ++a) x[a] = A * ref.X[a] + Vec3(3e-3, -2e-3, 1e-3);
        std::vector<Mat3> F;
        deformationGradient(ref, x, F);
        double affine = 0.0;
        for (const Mat3& Fa : F) affine = std::max(affine, (Fa - A).cwiseAbs().maxCoeff());
        deformationGradient(ref, ref.X, F);
        double rest = 0.0;
        for (const Mat3& Fa : F) rest = std::max(rest, (Fa - Mat3::Identity()).norm());
        SolverOptions options;  // the cases' defaults, with viscosity and hourglass control on
        options.viscosity = {1.0, 1.0};
        options.hourglass = 0.1;
        Simulation sim(std::move(ref), {HypoElastic(steel())}, options);
        double speed = 0.0;
        for (int s = 0; s < 300; ++s) {
            sim.step();
            for (const Vec3& v : sim.state().v) speed = std::max(speed, v.norm());
        }
        std::printf(
            "[sphere] transients %s: %d particles, %zu transient entries; affine F error %.1e, "
            "at rest |F − I| %.1e, |v| over 300 steps %.1e m/s\n",
            rule == preproc::TransientRule::Lattice ? "lattice" : "auto", sim.reference().size(),
            sim.reference().overset.size(), affine, rest, speed);
        EXPECT_LE(affine, 1e-10);
        EXPECT_LE(rest, 1e-12);
        EXPECT_LE(speed, 1e-12);
    }
}

}  // namespace
}  // namespace gsph
