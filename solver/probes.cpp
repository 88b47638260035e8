// SPDX-License-Identifier: MIT
#include "probes.hpp"

#include <Eigen/LU>
#include <cmath>
#include <iterator>
#include <limits>

#include "core/error.hpp"
#include "materials/stress_measures.hpp"

namespace gsph::solver {
namespace {

struct ProbeField {
    const char* suffix;  ///< the column is <probe>_<suffix>
    double (*value)(const Reference&, const State&, std::size_t a);
};

// Per probe, in order: position, displacement, velocity, acceleration (nodout), the Cauchy
// stress's components and measures, and the material's history variables (elout).
const ProbeField kProbeFields[] = {
    {"x", [](const Reference&, const State& s, std::size_t a) { return s.x[a][0]; }},
    {"y", [](const Reference&, const State& s, std::size_t a) { return s.x[a][1]; }},
    {"z", [](const Reference&, const State& s, std::size_t a) { return s.x[a][2]; }},
    {"ux", [](const Reference& r, const State& s, std::size_t a) { return s.x[a][0] - r.X[a][0]; }},
    {"uy", [](const Reference& r, const State& s, std::size_t a) { return s.x[a][1] - r.X[a][1]; }},
    {"uz", [](const Reference& r, const State& s, std::size_t a) { return s.x[a][2] - r.X[a][2]; }},
    {"vx", [](const Reference&, const State& s, std::size_t a) { return s.v[a][0]; }},
    {"vy", [](const Reference&, const State& s, std::size_t a) { return s.v[a][1]; }},
    {"vz", [](const Reference&, const State& s, std::size_t a) { return s.v[a][2]; }},
    {"ax", [](const Reference&, const State& s, std::size_t a) { return s.acceleration[a][0]; }},
    {"ay", [](const Reference&, const State& s, std::size_t a) { return s.acceleration[a][1]; }},
    {"az", [](const Reference&, const State& s, std::size_t a) { return s.acceleration[a][2]; }},
    {"stress_xx",
     [](const Reference&, const State& s, std::size_t a) { return s.cauchy[a](0, 0); }},
    {"stress_yy",
     [](const Reference&, const State& s, std::size_t a) { return s.cauchy[a](1, 1); }},
    {"stress_zz",
     [](const Reference&, const State& s, std::size_t a) { return s.cauchy[a](2, 2); }},
    {"stress_xy",
     [](const Reference&, const State& s, std::size_t a) { return s.cauchy[a](0, 1); }},
    {"stress_yz",
     [](const Reference&, const State& s, std::size_t a) { return s.cauchy[a](1, 2); }},
    {"stress_zx",
     [](const Reference&, const State& s, std::size_t a) { return s.cauchy[a](2, 0); }},
    {"von_mises",
     [](const Reference&, const State& s, std::size_t a) { return vonMises(s.cauchy[a]); }},
    {"pressure",
     [](const Reference&, const State& s, std::size_t a) { return pressure(s.cauchy[a]); }},
    {"J", [](const Reference&, const State& s, std::size_t a) { return s.F[a].determinant(); }},
    {"plastic_strain",
     [](const Reference&, const State& s, std::size_t a) { return s.plasticStrain[a]; }},
    {"temperature",
     [](const Reference&, const State& s, std::size_t a) { return s.temperature[a]; }},
    {"damage", [](const Reference&, const State& s, std::size_t a) { return s.damage[a]; }},
};

}  // namespace

std::vector<Probe> findProbes(const CaseConfig& c, const Reference& ref, const ParticleFile& file) {
    std::vector<Probe> probes;
    for (const ProbeSpec& spec : c.probes) {
        const std::string at = c.caseFile.string() + ":" + std::to_string(spec.line) + ": ";
        Probe probe{spec.name, 0, 0.0};
        if (!spec.atPoint) {
            if (spec.particle >= ref.size())
                throw InputError(at + "[[probe]] '" + spec.name + "': particle " +
                                 std::to_string(spec.particle) + " is not in " +
                                 c.particles.string() + " (it has " + std::to_string(ref.size()) +
                                 " particles, 0 to " + std::to_string(ref.size() - 1) + ")");
            probe.particle = static_cast<Index>(spec.particle);
            probes.push_back(probe);
            continue;
        }
        Index body = -1;
        if (!spec.body.empty()) {
            for (std::size_t b = 0; b < file.bodies.size() && body < 0; ++b)
                if (namesBody(spec.body, file, b)) body = static_cast<Index>(b);
            if (body < 0)
                throw InputError(at + "[[probe]] '" + spec.name + "': body '" + spec.body +
                                 "' is not a body of " + c.particles.string());
        }
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t a = 0; a < ref.X.size(); ++a) {
            if (body >= 0 && ref.body[a] != body) continue;
            const double d = (ref.X[a] - spec.point).squaredNorm();
            if (d < best) {
                best = d;
                probe.particle = static_cast<Index>(a);
            }
        }
        probe.distance = std::sqrt(best);
        probes.push_back(probe);
    }
    return probes;
}

Probes::Probes(std::filesystem::path path, std::vector<Probe> probes)
    : probes_(std::move(probes)), table_(std::move(path), columnNames()) {}

std::vector<std::string> Probes::columnNames() const {
    std::vector<std::string> names = {"time", "step"};
    for (const Probe& p : probes_)
        for (const ProbeField& f : kProbeFields) names.push_back(p.name + "_" + f.suffix);
    return names;
}

void Probes::add(const Reference& ref, const State& state, ParticleRange owned, Domain* domain) {
    values_.assign(probes_.size() * std::size(kProbeFields),
                   std::numeric_limits<double>::infinity());
    auto value = values_.begin();
    for (const Probe& p : probes_)
        for (const ProbeField& f : kProbeFields) {
            if (owned.contains(p.particle))
                *value = f.value(ref, state, static_cast<std::size_t>(p.particle));
            ++value;
        }
    if (domain != nullptr) domain->minimum(values_);
    table_.cell("%.9e", state.time);
    table_.cell("%.0f", static_cast<double>(state.step));
    for (const double v : values_) table_.cell("%.9e", v);
    table_.endRow();
}

}  // namespace gsph::solver
