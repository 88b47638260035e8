// SPDX-License-Identifier: MIT
// Convergence on a problem with a known answer: the first free–free axial mode of a
// bar, u = A cos(πx/L) sin(ωt), ω = πc/L, c = √(E/ρ). With ν = 0 plane strain is exactly
// uniaxial, so the 2-D bar has the 1-D answer T = 2L/c. The bar is graded 3:1 along its
// length, so the test also covers a graded space. The period error is measured at four
// resolutions and the observed order reported (least-squares slope).
#include <gtest/gtest.h>

#include <cmath>

#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

double periodError(int n, double* particleSpacing) {
    const double L = 1.0, rho = 2700.0;
    const ElasticConstants e(rho, 70e9, 0.0);
    const double c = e.barWaveSpeed(), T = 2.0 * L / c;
    const AnalyticMap map =
        gradedBoxMap(Vec3(L, 0.1, 0.0),
                     {AxisGrading{AxisGrading::Kind::OneSided, 3.0}, AxisGrading{}, AxisGrading{}});
    Simulation sim(latticeReference(map, 2, {n, std::max(3, n / 10), 1}, rho, 1.2),
                   {HypoElastic(e)}, SolverOptions{});
    const double pi = std::acos(-1.0);
    sim.setVelocity(
        [&](const Vec3& X) { return Vec3(1e-3 * c * std::cos(pi * X[0] / L), 0.0, 0.0); });
    std::vector<Index> rightEnd;
    for (Index a = 0; a < sim.reference().size(); ++a)
        if (sim.reference().theta[static_cast<std::size_t>(a)][0] > n - 1) rightEnd.push_back(a);
    // u(L, t) = −A sin ωt: crossings upward at T/2, downward at T; measure T = 2 (t_down − t_up).
    double previous = 0.0, up = 0.0, down = 0.0;
    sim.advanceTo(1.2 * T, [&](const State& s) {
        double u = 0.0;
        for (Index a : rightEnd)
            u += s.x[static_cast<std::size_t>(a)][0] -
                 sim.reference().X[static_cast<std::size_t>(a)][0];
        const double tCross = s.time - s.dt * u / (u - previous);
        if (previous < 0.0 && u >= 0.0 && up == 0.0) up = tCross;
        if (previous > 0.0 && u <= 0.0 && up > 0.0 && down == 0.0) down = tCross;
        previous = u;
    });
    double hmax = 0.0;
    for (double s : sim.reference().spacing) hmax = std::max(hmax, s);
    *particleSpacing = hmax;
    return std::abs(2.0 * (down - up) / T - 1.0);
}

TEST(Convergence, AxialModePeriodConvergesAtSecondOrder) {
    std::vector<double> h, err;
    for (int n : {20, 40, 80, 160}) {
        double spacing = 0.0;
        err.push_back(periodError(n, &spacing));
        h.push_back(spacing);
    }
    double mh = 0, me = 0;
    for (std::size_t i = 0; i < h.size(); ++i) mh += std::log(h[i]) / 4, me += std::log(err[i]) / 4;
    double she = 0, shh = 0;
    for (std::size_t i = 0; i < h.size(); ++i)
        she += (std::log(h[i]) - mh) * (std::log(err[i]) - me),
            shh += (std::log(h[i]) - mh) * (std::log(h[i]) - mh);
    const double order = she / shh;
    std::printf("[convergence] free-free bar (graded 3:1), period error:");
    for (std::size_t i = 0; i < h.size(); ++i) std::printf(" %.2e (h=%.4f)", err[i], h[i]);
    std::printf("; observed order %.2f\n", order);
    EXPECT_GT(order, 1.7);
    EXPECT_LT(err.back(), 1e-3);
}

}  // namespace
}  // namespace gsph
