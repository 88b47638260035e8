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
#include "overset_checks.hpp"
#include "simulation.hpp"

namespace gsph {
namespace {

constexpr double kRadius = 5e-3;
constexpr double kSteelDensity = 7800.0;

ElasticConstants steel() {
    return ElasticConstants(kSteelDensity, 200e9, 0.3);
}

preproc::Conversion convertSphere(const test::Parameters& parameters,
                                  preproc::TransientRule rule = preproc::TransientRule::Automatic,
                                  preproc::HexMesh* meshOut = nullptr) {
    return test::convertSample("sphere.geo", parameters, rule, meshOut);
}

TEST(CubedSphere, VolumeConvergesAtSecondOrder) {
    const double exact = 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
    const test::VolumeConvergence v = test::volumeConvergence("sphere", "sphere.geo", {}, exact);
    EXPECT_NEAR(v.order12, 2.0, 0.05);
    EXPECT_NEAR(v.order23, 2.0, 0.05);
}

// With the default rule, the pairs whose transients come from the extended map (the ring's
// particles in the column's space) map back to their X through it to 1e-12 of the radius, with
// ω = V / det ∂X/∂θ there.
TEST(CubedSphere, MappedTransientsMapBackToTheirX) {
    preproc::HexMesh mesh;
    const preproc::Conversion c = convertSphere({}, preproc::TransientRule::Automatic, &mesh);
    const ParticleFile& f = c.particles;
    const auto maps = test::spaceMapsOf(mesh);
    std::set<std::pair<Index, Index>> mapped;  // (home space, space)
    for (const preproc::TransientReport& r : c.stats.transients)
        if (!r.continued && r.particles > 0) mapped.insert({r.space, r.in});
    ASSERT_FALSE(mapped.empty());
    double worst = 0.0;
    long checked = 0;
    for (std::size_t e = 0; e < f.overset.size(); ++e) {
        const Index b = f.overset.particle[e], s = f.overset.space[e];
        if (mapped.count({f.space[b], s}) == 0) continue;
        const Vec3 u = f.overset.theta[e] / f.spaces[s].dtheta;
        worst = std::max(worst, (maps[s]->position(u) - f.X[b]).norm() / kRadius);
        const double det = maps[s]->jacobian(u).determinant();
        EXPECT_NEAR(f.overset.omega[e], f.volume[b] / det, 1e-12 * f.overset.omega[e]);
        ++checked;
    }
    std::printf("[sphere] %ld mapped entries: |X(θ) − X| ≤ %.1e of the radius\n", checked, worst);
    EXPECT_LE(worst, 1e-12);
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
        const test::RestAndAffine r =
            test::restAndAffine(std::move(ref), steel(), 300, Vec3(3e-3, -2e-3, 1e-3));
        std::printf(
            "[sphere] transients %s: %d particles, %zu transient entries; affine F error %.1e, "
            "at rest |F − I| %.1e, |v| over 300 steps %.1e m/s\n",
            rule == preproc::TransientRule::Lattice ? "lattice" : "auto", r.particles, r.entries,
            r.affine, r.rest, r.speed);
        EXPECT_LE(r.affine, 1e-10);
        EXPECT_LE(r.rest, 1e-12);
        EXPECT_LE(r.speed, 1e-12);
    }
}

}  // namespace
}  // namespace gsph
