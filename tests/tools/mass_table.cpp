// SPDX-License-Identifier: MIT
// The mass table of docs/theory.md ("Volumes and mass"): every 3-D sample geometry at its
// defaults, Σ ρ0 ω det M (the quadrature mass) against ρ0 × the meshed volume, and the run's mass
// with [run] mass = "normalized" (the default) and "mesh", which must be ρ0 × the meshed volume
// body by body. Two minutes (fifteen conversions, 45 metrics): label validation.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "converted_layout.hpp"

namespace gsph {
namespace {

// Every 3-D sample at its defaults: the quadrature mass Σ ρ0 ω det M against ρ0 × the meshed
// volume (printed: docs/theory.md "Volumes and mass" holds the table), and the normalized and
// mesh bases' masses, which are ρ0 × each body's meshed volume by construction.
// quarter_cylinder.geo is one cell thick (a 2-D sample: its kernel correction is singular in 3-D)
// and is left out.
TEST(MassTable, QuadratureMassAgainstTheMeshedVolume) {
    for (const char* name :
         {"graded_bar.geo", "bending_plate.geo", "three_point_bending.geo", "taylor_bar.geo",
          "notched_plate.geo", "two_blocks.geo", "plate_projectile.geo", "plate_perforation.geo",
          "kalthoff_winkler.geo", "kalthoff_winkler_slotted.geo", "sphere.geo",
          "projectile_hemispherical_nose.geo", "spherical_shell.geo", "pipe_elbow.geo",
          "sphere_impact.geo"}) {
        const preproc::Conversion c = test::convertSample(name, {});
        const std::vector<double> density(c.particles.bodies.size(), 1000.0);
        Reference quadrature = buildReference(c.particles, density, 1.2);
        buildPairs(quadrature);
        quadrature.massBasis = MassBasis::QuadratureVolume;
        Reference mesh = quadrature, normalized = quadrature;
        mesh.massBasis = MassBasis::MeshVolume;
        normalized.massBasis = MassBasis::NormalizedQuadratureVolume;
        computeGeometry(quadrature);
        computeGeometry(mesh);
        computeGeometry(normalized);
        const std::size_t bodies = c.particles.bodies.size();
        std::vector<double> meshed(bodies, 0.0), mq(bodies, 0.0), mm(bodies, 0.0), mn(bodies, 0.0);
        for (std::size_t a = 0; a < quadrature.mass.size(); ++a) {
            const auto b = static_cast<std::size_t>(quadrature.body[a]);
            meshed[b] += 1000.0 * quadrature.volume[a];
            mq[b] += quadrature.mass[a];
            mm[b] += mesh.mass[a];
            mn[b] += normalized.mass[a];
        }
        const auto total = [](const std::vector<double>& v) {
            double s = 0.0;
            for (double x : v) s += x;
            return s;
        };
        std::printf(
            "[mass] %-36s %6d particles, %zu spaces: Σm/ρ0V quadrature %.4f, normalized "
            "%.4f, mesh %.4f\n",
            name, quadrature.size(), c.particles.spaces.size(), total(mq) / total(meshed),
            total(mn) / total(meshed), total(mm) / total(meshed));
        for (std::size_t b = 0; b < bodies; ++b) {
            EXPECT_NEAR(mm[b] / meshed[b], 1.0, 1e-13) << name << ", body " << b;
            EXPECT_NEAR(mn[b] / meshed[b], 1.0, 1e-13) << name << ", body " << b;
        }
    }
}

}  // namespace
}  // namespace gsph
