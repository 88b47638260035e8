// SPDX-License-Identifier: MIT
#include "integrator/time_step.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph {

double stableTimeStep(const Reference& ref, const State& state, const TimeStepRule& rule,
                      const std::vector<double>& lengthScale, const std::vector<double>& soundSpeed,
                      const std::vector<double>& frequency2, ParticleRange owned, Domain& domain) {
    if (rule.fixedTimeStep > 0.0) return rule.fixedTimeStep;
    const auto ratioOf = [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        const double wave = lengthScale[ia] / (soundSpeed[ia] + state.v[ia].norm());
        if (frequency2.empty() || frequency2[ia] == 0.0) return wave;
        // Springs in parallel: ω² = (2/wave)² + ω_contact², Δt = CFL · 2/ω.
        return 1.0 / std::sqrt(1.0 / (wave * wave) + 0.25 * frequency2[ia]);
    };
    // A NaN ratio (a NaN velocity or sound speed) counts as −1: min() would pass over it.
    const double local = parallelMin(owned, std::numeric_limits<double>::infinity(), [&](Index a) {
        const double r = ratioOf(a);
        return std::isnan(r) ? -1.0 : r;
    });
    const double ratio = domain.processes() > 1 ? domain.minimum(local) : local;
    const double dt = rule.cfl * ratio;
    const double floor = rule.minTimeStepRatio * state.initialDt;
    if (ratio > 0.0 && std::isfinite(ratio) && !(dt < floor)) return dt;
    if (local != ratio)
        throw NumericalError("time step collapsed on another process", -1, state.time);
    // Failure only: name the particle that limits Δt (the first NaN, or the smallest ratio).
    // (On the process that owns it; the others stop at the next exchange.)
    Index worst = owned.begin;
    double worstRatio = owned.size() > 0 ? ratioOf(owned.begin) : 0.0;
    for (Index a = owned.begin; a < owned.end && !std::isnan(worstRatio); ++a) {
        const double r = ratioOf(a);
        if (std::isnan(r) || r < worstRatio) {
            worst = a;
            worstRatio = r;
        }
    }
    const auto iw = static_cast<std::size_t>(worst);
    char detail[200];
    std::snprintf(detail, sizeof detail,
                  "time step collapsed: Δt = %.3e s, below %.3g × Δt0 (Δt0 = %.3e s; spacing "
                  "%.3e m, wave speed %.3e m/s, |v| = %.3e m/s): ",
                  dt, rule.minTimeStepRatio, state.initialDt, lengthScale[iw], soundSpeed[iw],
                  state.v[iw].norm());
    throw NumericalError(detail + describeParticle(ref, worst, state.time), worst, state.time);
}

}  // namespace gsph
