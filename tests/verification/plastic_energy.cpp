// SPDX-License-Identifier: MIT
// Energy bookkeeping with Johnson–Cook plasticity: kinetic + elastic + plastic work
// + damage dissipation + the ledger's viscous and hourglass works − boundary work stays equal
// to its initial value within 1 % of the energy that moved.
//   * PlasticImpact: a short copper bar (10 × 2 × 2 mm, 25 × 5 × 5 particles) at 150 m/s
//     against a rigid support (its end layer fixed), heating on, until most of its kinetic
//     energy has gone into plastic work.
//   * DuctileTension: a steel bar pulled apart at both ends until particles fail (Johnson–Cook
//     damage), so the failure loss enters the balance too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"
#include "support/ductile_bar.hpp"
#include "support/johnson_cook_materials.hpp"

namespace gsph {
namespace {

std::vector<Index> particlesWhere(const Reference& ref, const std::function<bool(const Vec3&)>& f) {
    std::vector<Index> out;
    for (Index a = 0; a < ref.size(); ++a)
        if (f(ref.X[static_cast<std::size_t>(a)])) out.push_back(a);
    return out;
}

// The bar at 150 m/s against its fixed end layer until 95 % of its kinetic energy has gone:
// the worst imbalance, the final report, and Σ m Cp ΔT over χ × the plastic work.
struct ImpactResult {
    EnergyReport start, end;
    double worst = 0.0, heatOverWork = 0.0;
};
ImpactResult plasticImpact(const Material& material, double specificHeat, double chi) {
    const double length = 0.01, width = 0.002, v0 = 150.0, spacing = length / 25;
    SolverOptions options;
    options.viscosity = {1.0, 1.0};
    options.hourglass = 0.1;
    Simulation sim(
        latticeReference(gradedBoxMap(Vec3(length, width, width), {}), 3, {25, 5, 5}, 8960.0, 1.2),
        {material}, options);
    sim.constrain({"support",
                   particlesWhere(sim.reference(), [&](const Vec3& X) { return X[0] < spacing; }),
                   {}});
    sim.setVelocity([&](const Vec3&) { return Vec3(-v0, 0.0, 0.0); });
    sim.start();
    ImpactResult r;
    r.start = sim.energy();
    EXPECT_NEAR(sim.state().temperature.front(), 293.15, 1e-12) << "starts at the material's Tr";
    r.end = r.start;
    for (int k = 1; k <= 40 && r.end.kinetic > 0.05 * r.start.kinetic; ++k) {
        sim.advanceTo(k * 1e-6);
        r.end = sim.energy();
        r.worst = std::max(r.worst, std::abs(r.end.total() - r.start.total()) / r.start.kinetic);
    }
    double heat = 0.0;
    for (Index a = 0; a < sim.reference().size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        heat += sim.reference().mass[ia] * specificHeat * (sim.state().temperature[ia] - 293.15);
    }
    r.heatOverWork = heat / (chi * r.end.plasticWork);
    const EnergyReport& e = r.end;
    std::printf(
        "[plastic impact] t = %.1f µs: kinetic %.3f J of %.3f J, elastic %.3f, plastic "
        "%.3f, viscous %.3f, hourglass %.4f J; worst imbalance %.2e of the initial kinetic "
        "energy; max ε̄p %.2f, max T %.0f K\n",
        sim.state().time * 1e6, e.kinetic, r.start.kinetic, e.elastic, e.plasticWork, e.viscousWork,
        e.hourglassWork, r.worst,
        *std::max_element(sim.state().plasticStrain.begin(), sim.state().plasticStrain.end()),
        *std::max_element(sim.state().temperature.begin(), sim.state().temperature.end()));
    return r;
}

TEST(PlasticEnergy, PlasticImpactOnARigidSupportBalancesItsEnergy) {
    const ImpactResult r = plasticImpact(
        testing::withLinearEos(testing::kCopperElastic, testing::copperParams()), 383.0, 0.9);
    EXPECT_LT(r.end.kinetic, 0.2 * r.start.kinetic) << "most kinetic energy is gone";
    // With the default viscosity (β1 = β2 = 1) the shock at the support takes about half of
    // it (measured: 49 %; 22 % with β = (0.2, 0.4), 0 without): plastic work is the other half.
    EXPECT_GT(r.end.plasticWork, 0.4 * r.start.kinetic);
    EXPECT_LT(r.worst, 0.01);
    EXPECT_EQ(r.end.damageDissipation, 0.0);
    // The plastic work heated the bar: Σ m Cp ΔT = χ × plastic work (χ = 0.9).
    EXPECT_NEAR(r.heatOverWork, 1.0, 1e-6);
}

// The same blow on a bilinear (linear-hardening) copper-like bar, heating on: the composed
// plastic solid books its plastic work and heat as Johnson–Cook's does.
TEST(PlasticEnergy, LinearHardeningImpactBalancesItsEnergy) {
    LinearHardeningParams p;
    p.yieldStress = 120e6;
    p.hardeningModulus = 500e6;
    p.specificHeat = 383.0;
    p.taylorQuinney = 0.9;
    const ElasticConstants& e = testing::kCopperElastic;
    const ImpactResult r = plasticImpact(
        LinearHardening(e, p, EquationOfState::linear(e.density, e.bulkModulus())), 383.0, 0.9);
    EXPECT_LT(r.end.kinetic, 0.2 * r.start.kinetic) << "most kinetic energy is gone";
    EXPECT_GT(r.end.plasticWork, 0.35 * r.start.kinetic);  // measured 38 %, viscosity 57 %
    EXPECT_LT(r.worst, 0.005);                             // measured 1.3e-3
    EXPECT_NEAR(r.heatOverWork, 1.0, 1e-6);
}

// The bar pulled until a particle fails and 3 µs more: the failed particles, the final report
// and the worst imbalance over the energy moved.
struct TensionResult {
    int failed = 0;
    EnergyReport end;
    double worst = 0.0;
};
TensionResult ductileTension(double damageLength) {
    // Weldox 460E strength (Børvik et al. 2001) with damage constants scaled down so that the
    // bar fails within a short pull (εf ≈ 0.15 at σ* = 1/3); ends pulled apart at ±20 m/s.
    testing::PulledWeldoxBar bar({}, damageLength);
    Simulation& sim = bar.sim;
    sim.start();
    const EnergyReport e0 = sim.energy();
    double worst = 0.0, scale = e0.kinetic;
    EnergyReport e1 = e0;
    int failed = 0;
    for (int k = 1; k <= 60 && failed == 0; ++k) {
        sim.advanceTo(k * 1e-6);
        e1 = sim.energy();
        scale = std::max({scale, e1.boundaryWork, e0.kinetic});
        worst = std::max(worst, std::abs(e1.total() - e0.total()));
        failed =
            static_cast<int>(std::count_if(sim.state().damage.begin(), sim.state().damage.end(),
                                           [](double d) { return d >= 1.0; }));
    }
    // A few more µs after the first failure, so the failed particles unload.
    for (int k = 1; k <= 3; ++k) {
        sim.advanceTo(sim.state().time + 1e-6);
        e1 = sim.energy();
        scale = std::max(scale, e1.boundaryWork);
        worst = std::max(worst, std::abs(e1.total() - e0.total()));
    }
    failed = static_cast<int>(std::count_if(sim.state().damage.begin(), sim.state().damage.end(),
                                            [](double d) { return d >= 1.0; }));
    std::printf(
        "[ductile tension] t = %.1f µs: %d failed particles; boundary work %.3f J, "
        "kinetic %.3f, elastic %.3f, plastic %.3f, damage %.4f, viscous %.3f, hourglass "
        "%.4f J; worst imbalance %.2e of the energy moved\n",
        sim.state().time * 1e6, failed, e1.boundaryWork, e1.kinetic, e1.elastic, e1.plasticWork,
        e1.damageDissipation, e1.viscousWork, e1.hourglassWork, worst / scale);
    return {failed, e1, worst / scale};
}

TEST(PlasticEnergy, DuctileTensionToFailureBalancesItsEnergy) {
    const TensionResult r = ductileTension(0.0);
    EXPECT_GT(r.failed, 0);
    EXPECT_GT(r.end.damageDissipation, 0.0);
    EXPECT_LT(r.worst, 0.01);
}

// Nonlocal damage over ℓ = 1 mm (2.5 spacings): particles fail by their neighbourhood's
// driver, and the failure losses keep the ledger closed.
TEST(PlasticEnergy, NonlocalDuctileTensionToFailureBalancesItsEnergy) {
    const TensionResult r = ductileTension(1e-3);
    EXPECT_GT(r.failed, 0);
    EXPECT_GT(r.end.damageDissipation, 0.0);
    EXPECT_LT(r.worst, 5e-4);  // measured 1.5e-4 (local: 8.3e-5)
    // The failed zone is wider than the local one's (measured 150 particles against 100: six
    // cross-sections of 25 against four).
    EXPECT_GT(r.failed, ductileTension(0.0).failed);
}

}  // namespace
}  // namespace gsph
