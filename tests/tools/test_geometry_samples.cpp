// SPDX-License-Identifier: MIT
// The curved structured samples beside the cubed sphere, end to end: the projectile with a
// hemispherical nose (an O-grid cylinder and half a cubed sphere: two spaces coupled by the
// overset method), the thick spherical shell (a cubed sphere's six shell blocks: two spaces)
// and the pipe elbow (an annulus swept along a bent axis: one space, periodic around the axis).
// Each converts without a warning into a valid particle file with θ on a uniform lattice per
// space; Σ V converges at second order to the exact volume; at rest nothing moves, and an
// affine motion gives F exactly. Coarse parameters keep the whole test to seconds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "converted_layout.hpp"
#include "particle_checks.hpp"

namespace gsph {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSteelDensity = 7800.0;

ElasticConstants steel() {
    return ElasticConstants(kSteelDensity, 200e9, 0.3);
}

struct Sample {
    std::string tag;                ///< the test's name
    std::string file;               ///< in geometries/
    test::Parameters coarse;        ///< dimensions and cell counts at refine = 1
    double exact = 0.0;             ///< the domain's volume [m³]
    std::size_t spaces = 0;         ///< generalized spaces gsph-preproc glues the blocks into
    std::string body;               ///< the physical volume's name
    std::vector<std::string> sets;  ///< the physical surfaces' names
};

// Dimensions given explicitly, so that the exact volumes do not depend on the defaults.
Sample projectile() {
    const double R = 5e-3, L = 10e-3;
    return {"ProjectileHemisphericalNose",
            "projectile_hemispherical_nose.geo",
            {{"R", R}, {"L", L}, {"n", 4}, {"nr", 2}, {"nz", 8}},
            2.0 / 3.0 * kPi * R * R * R + kPi * R * R * L,
            2,
            "projectile",
            {"nose", "rear"}};
}

Sample sphericalShell() {
    const double Ri = 3e-3, Ro = 5e-3;
    return {"SphericalShell",
            "spherical_shell.geo",
            {{"Ri", Ri}, {"Ro", Ro}, {"n", 4}, {"nr", 2}},
            4.0 / 3.0 * kPi * (Ro * Ro * Ro - Ri * Ri * Ri),
            2,
            "shell",
            {"inner", "outer"}};
}

Sample pipeElbow() {
    const double Ri = 3.5e-3, Ro = 5e-3, Rb = 15e-3, L1 = 10e-3, L2 = 10e-3;
    return {"PipeElbow",
            "pipe_elbow.geo",
            {{"Ri", Ri},
             {"Ro", Ro},
             {"Rb", Rb},
             {"L1", L1},
             {"L2", L2},
             {"n", 6},
             {"nr", 2},
             {"n1", 8},
             {"nb", 16},
             {"n2", 8}},
            kPi * (Ro * Ro - Ri * Ri) * (L1 + L2 + kPi / 2 * Rb),  // Pappus: section × axis
            1,
            "pipe",
            {"inlet", "outlet", "inner", "outer"}};
}

// gtest names a failing parameter by this.
void PrintTo(const Sample& s, std::ostream* out) {
    *out << s.file;
}

class GeometrySample : public ::testing::TestWithParam<Sample> {};

// As shipped (the defaults) and at the coarse parameters: no warning and a valid file
// (convertSample), θ = (i+½, j+½, k+½) of each particle's lattice index in its space, the
// spaces, body and sets the .geo describes, cells close to cubes. Prints the summary.
TEST_P(GeometrySample, ConvertsWithoutWarningsOnAUniformLatticePerSpace) {
    const Sample& s = GetParam();
    for (const test::Parameters& parameters : {test::Parameters{}, s.coarse}) {
        const char* which = parameters.empty() ? "defaults" : "coarse";
        SCOPED_TRACE(which);
        const preproc::Conversion c = test::convertSample(s.file, parameters);
        const ParticleFile& f = c.particles;
        test::expectLatticeLayout(f);
        ASSERT_EQ(f.spaces.size(), s.spaces);
        ASSERT_EQ(f.bodies.size(), 1u);
        EXPECT_EQ(f.bodies[0].name, s.body);
        for (const std::string& set : s.sets) {
            ASSERT_EQ(f.sets.count(set), 1u) << set;
            EXPECT_FALSE(f.sets.at(set).empty()) << set;
        }
        EXPECT_EQ(f.overset.size() > 0, s.spaces > 1) << "transients only between spaces";
        std::printf("[%s] %s: %d particles in %zu spaces\n", s.tag.c_str(), which, f.size(),
                    f.spaces.size());
        for (std::size_t k = 0; k < f.spaces.size(); ++k) {
            const LatticeSpace& sp = f.spaces[k];
            std::printf(
                "[%s]   space %zu: cells %dx%dx%d, periodic %c%c%c, %zu gmsh volumes, "
                "worst cond(dX/dtheta) %.3f\n",
                s.tag.c_str(), k, sp.cells[0], sp.cells[1], sp.cells[2], sp.periodic[0] ? 'i' : '-',
                sp.periodic[1] ? 'j' : '-', sp.periodic[2] ? 'k' : '-',
                c.stats.spaceVolumes[k].size(), c.stats.metric[k].condition);
            EXPECT_LT(c.stats.metric[k].condition, 5.0) << "space " << k;
        }
        for (const preproc::TransientReport& t : c.stats.transients) {
            std::printf("[%s]   space %d in space %d: %ld transients, %s\n", s.tag.c_str(), t.space,
                        t.in, t.particles, t.continued ? "continued lattice" : "extended map");
        }
    }
}

TEST_P(GeometrySample, VolumeConvergesAtSecondOrder) {
    const Sample& s = GetParam();
    const test::VolumeConvergence v =
        test::volumeConvergence(s.tag.c_str(), s.file, s.coarse, s.exact);
    EXPECT_NEAR(v.order12, 2.0, 0.1);
    EXPECT_NEAR(v.order23, 2.0, 0.1);
}

TEST_P(GeometrySample, StaysAtRestAndAffineMotionGivesExactF) {
    const Sample& s = GetParam();
    test::ConvertedLayout layout = test::convertAndBuild(s.file, s.coarse, kSteelDensity);
    const test::RestAndAffine r =
        test::restAndAffine(std::move(layout.ref), steel(), 100, Vec3(3e-3, -2e-3, 1e-3));
    std::printf(
        "[%s] %d particles, %zu transient entries; affine F error %.1e, at rest |F − I| %.1e, "
        "|v| over 100 steps %.1e m/s\n",
        s.tag.c_str(), r.particles, r.entries, r.affine, r.rest, r.speed);
    EXPECT_LE(r.affine, 1e-10);
    EXPECT_LE(r.rest, 1e-12);
    EXPECT_LE(r.speed, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Samples, GeometrySample,
                         ::testing::Values(projectile(), sphericalShell(), pipeElbow()),
                         [](const ::testing::TestParamInfo<Sample>& sample) {
                             return sample.param.tag;
                         });

}  // namespace
}  // namespace gsph
