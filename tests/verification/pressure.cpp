// SPDX-License-Identifier: MIT
// A pressure step on the free end of a slender steel bar (ν = 0, 0.2 m × 2 cm × 2 cm, 40×4×4
// particles; boundary/pressure.hpp): before the wave reaches the far end,
//   * the momentum is the impulse p A t (Verlet integrates Σf exactly and Σ internal = 0): the
//     face's current area J F^{-T} A differs from A only by the small lateral strains of the
//     loaded face's particles (measured: +6.3e-6);
//   * behind the front the particles move at the 1-D value v = p/(ρ c), c = √(E/ρ) (measured
//     +2.3 %: the wave's ringing behind a step front on 4 particles across);
//   * the energy ledger closes: kinetic + elastic + viscous + hourglass = external work
//     (measured: 7.0e-4 of it).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "boundary/pressure.hpp"
#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

TEST(Pressure, StepOnABarEndGivesTheImpulseTheWaveAndTheEnergy) {
    const ElasticConstants steel(7800.0, 200e9, 0.0);
    const double L = 0.2, W = 0.02, p = 1e7;
    const std::array<int, 3> cells = {40, 4, 4};
    SolverOptions options;
    options.hourglass = 0.05;
    options.viscosity = {0.05, 1.0};
    Simulation sim(latticeReference(gradedBoxMap(Vec3(L, W, W), {}), 3, cells, steel.density, 1.2),
                   {HypoElastic(steel)}, options);
    PressureLoad load{"end", {}, {}, {{0.0, p}}};
    for (int k = 0; k < cells[2]; ++k)
        for (int j = 0; j < cells[1]; ++j) {
            load.particles.push_back(cells[0] * (j + cells[1] * k));  // i = 0: the x = 0 face
            load.area.push_back(Vec3(-(W / cells[1]) * (W / cells[2]), 0.0, 0.0));
        }
    sim.addStage(std::make_shared<PressureStage>(sim.reference(), load));

    const double c = std::sqrt(steel.youngsModulus / steel.density);
    const double t = 0.5 * L / c;  // the front is half-way
    ASSERT_TRUE(sim.advanceTo(t));
    const EnergyReport e = sim.energy();
    const double impulse = p * W * W * sim.state().time;
    std::printf("[pressure] momentum %.9e vs p A t %.9e (%.2e); lateral %.2e\n", e.momentum[0],
                impulse, e.momentum[0] / impulse - 1, std::hypot(e.momentum[1], e.momentum[2]));
    EXPECT_NEAR(e.momentum[0] / impulse, 1.0, 1e-5);
    EXPECT_LT(std::hypot(e.momentum[1], e.momentum[2]), 1e-12 * impulse);

    // Particles between the loaded end and the front (x in [0.1, 0.4] L) move at p/(ρc).
    double v = 0.0;
    int n = 0;
    for (std::size_t a = 0; a < sim.state().v.size(); ++a) {
        const double x = sim.reference().X[a][0];
        if (x > 0.1 * L && x < 0.4 * L) v += sim.state().v[a][0], ++n;
    }
    v /= n;
    const double v1d = p / (steel.density * c);
    std::printf("[pressure] particle velocity behind the front %.5f m/s, 1-D %.5f m/s (%+.2f %%)\n",
                v, v1d, 100 * (v / v1d - 1));
    EXPECT_NEAR(v / v1d, 1.0, 0.03);

    const double balance = e.kinetic + e.elastic + e.viscousWork + e.hourglassWork - e.externalWork;
    std::printf("[pressure] external work %.6e J, balance %.3e J (%.2e of it)\n", e.externalWork,
                balance, balance / e.externalWork);
    EXPECT_LT(std::abs(balance), 1e-3 * e.externalWork);
}

}  // namespace
}  // namespace gsph
