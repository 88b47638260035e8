// SPDX-License-Identifier: MIT
#include "run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"
#include "io/particle_file.hpp"
#include "io/snapshot.hpp"
#include "simulation.hpp"

namespace gsph::solver {
namespace {

using Clock = std::chrono::steady_clock;

// Materials per body id, and the initial velocity of each body, from the [[body]] entries.
struct BodySetup {
    std::vector<Material> materials;
    std::vector<double> density;
    std::vector<Vec3> velocity;
};

BodySetup matchBodies(const CaseConfig& c, const ParticleFile& file) {
    for (const BodySpec& s : c.bodies) {
        bool found = false;
        for (std::size_t b = 0; b < file.bodies.size(); ++b)
            found = found || s.group == file.bodies[b].name || s.group == std::to_string(b);
        if (!found)
            throw InputError(c.caseFile.string() + ":" + std::to_string(s.line) +
                             ": [[body]] group '" + s.group + "' is not a body of " +
                             c.particles.string());
    }
    BodySetup setup;
    for (std::size_t b = 0; b < file.bodies.size(); ++b) {
        const BodyInfo& info = file.bodies[b];
        const BodySpec* spec = nullptr;
        for (const BodySpec& s : c.bodies)
            if (s.group == info.name || s.group == std::to_string(b)) spec = &s;
        if (!spec) {
            throw InputError(c.caseFile.string() + ": body " + std::to_string(b) + " ('" +
                             info.name + "') of " + c.particles.string() +
                             " has no [[body]] entry");
        }
        const MaterialSpec* m = nullptr;
        for (const MaterialSpec& candidate : c.materials)
            if (candidate.name == spec->material) m = &candidate;
        setup.materials.push_back(*m->material);
        setup.density.push_back(m->elastic.density);
        setup.velocity.push_back(spec->velocity);
    }
    return setup;
}

// The [[set]] conditions: kinematic ones become constraints, forces become loads.
struct SetConditions {
    std::vector<VelocityConstraint> constraints;
    std::vector<SetForce> forces;
};

SetConditions matchSets(const CaseConfig& c, const ParticleFile& file) {
    SetConditions out;
    for (const SetSpec& s : c.sets) {
        const auto it = file.sets.find(s.name);
        if (it == file.sets.end()) {
            std::string known;
            for (const auto& [name, ids] : file.sets) known += (known.empty() ? "" : ", ") + name;
            throw InputError(c.caseFile.string() + ":" + std::to_string(s.line) + ": set '" +
                             s.name + "' is not in " + c.particles.string() +
                             " (sets there: " + (known.empty() ? "none" : known) + ")");
        }
        if (s.kind == SetSpec::Kind::Force) {
            out.forces.push_back({s.name, it->second, s.force});
            continue;
        }
        VelocityConstraint vc{s.name, it->second, {}};
        if (s.kind == SetSpec::Kind::Velocity) {
            const Vec3 v = s.velocity;
            vc.velocity = [v](double, const Vec3&) { return v; };
        }
        out.constraints.push_back(std::move(vc));
    }
    return out;
}

class History {
  public:
    explicit History(std::filesystem::path path) : path_(std::move(path)) {
        rows_ << "time,step,dt,kinetic_energy,internal_energy,hourglass_work,viscous_work,external_"
                 "work,"
                 "total_energy,momentum_x,momentum_y,momentum_z,plastic_work,damage_dissipation,"
                 "contact_energy\n";
    }
    void add(const State& s, const EnergyReport& e) {
        char line[512];
        std::snprintf(line, sizeof line,
                      "%.9e,%ld,%.6e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e\n",
                      s.time, s.step, s.dt, e.kinetic, e.elastic, e.hourglassWork, e.viscousWork,
                      e.boundaryWork + e.externalWork, e.total(), e.momentum[0], e.momentum[1],
                      e.momentum[2], e.plasticWork, e.damageDissipation, e.contactEnergy);
        rows_ << line;
    }
    void flush() const {
        writeAtomically(path_, [&](const std::filesystem::path& temp) {
            std::ofstream out(temp);
            out << rows_.str();
            if (!out.flush()) throw IoError(path_.string() + ": write failed (disk full?)");
        });
    }

  private:
    std::filesystem::path path_;
    std::ostringstream rows_;
};

void drawProgress(double t, double end, long steps, double wall, int particles) {
    const double fraction = std::min(1.0, t / end);
    const int width = 30;
    const int filled = static_cast<int>(fraction * width);
    const double rate = wall > 0 ? steps / wall : 0.0;
    const double eta = fraction > 0 ? wall * (1.0 - fraction) / fraction : 0.0;
    std::fprintf(
        stderr,
        "\r[%.*s%*s] %5.1f%%  t = %.3e s  %.0f steps/s  %.2e particle-steps/s  ETA %.0f s   ",
        filled, "##############################", width - filled, "", 100 * fraction, t, rate,
        rate * particles, eta);
    std::fflush(stderr);
}

}  // namespace

RunSummary runCase(const CaseConfig& c, const RunOptions& options) {
    ParticleFile file;
    try {
        file = readParticleFile(c.particles);
    } catch (const Error& e) {
        throw InputError(c.caseFile.string() + ":" + std::to_string(c.particlesLine) +
                         ": particle file: " + e.what());
    }
    BodySetup bodies = matchBodies(c, file);
    SetConditions sets = matchSets(c, file);
    SolverOptions solverOptions;
    solverOptions.cfl = c.cfl;
    solverOptions.viscosity = c.viscosity;
    solverOptions.hourglass = c.hourglass;
    solverOptions.contact = {c.contact.betweenBodies, c.contact.penalty, c.contact.distance};
    Simulation sim(buildReference(file, bodies.density, c.kappa), std::move(bodies.materials),
                   solverOptions);
    for (VelocityConstraint& vc : sets.constraints) sim.constrain(std::move(vc));
    for (SetForce& f : sets.forces) sim.applyForce(std::move(f));
    for (const WallSpec& w : c.walls)
        sim.addWall({w.name, w.point, w.normal, w.velocity, w.friction});
    sim.setGravity(c.gravity);
    const Reference& ref = sim.reference();
    std::vector<Vec3> initial(static_cast<std::size_t>(ref.size()));
    for (Index a = 0; a < ref.size(); ++a)
        initial[static_cast<std::size_t>(a)] =
            bodies.velocity[static_cast<std::size_t>(ref.body[static_cast<std::size_t>(a)])];
    sim.setVelocities(initial);

    std::filesystem::create_directories(options.runDir);
    const Provenance provenance = provenanceOf("gsph-solve", kVersion, c.caseFile);
    History history(options.runDir / "history.csv");
    RunSummary summary;
    summary.particles = ref.size();
    double totalMass = 0, meshMass = 0;
    for (Index a = 0; a < ref.size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        totalMass += ref.mass[ia];
        meshMass += ref.density[ia] * ref.volume[ia];
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "particles %d, pairs %d, mass %.6g kg (ρ0 × mesh volume: %.6g kg)", ref.size(),
                  ref.pairs.pairs(), totalMass, meshMass);
    options.log(line);

    auto snapshot = [&](const State& s) {
        char name[64];
        std::snprintf(name, sizeof name, "snapshot_%06d.h5", summary.snapshots++);
        writeSnapshot(options.runDir / name, ref, s, provenance);
        history.flush();
    };
    sim.start();
    history.add(sim.state(), sim.energy());
    snapshot(sim.state());
    const auto t0 = Clock::now();
    double lastDraw = -1.0;
    try {
        for (int k = 1; sim.state().time < c.endTime * (1 - 1e-12); ++k) {
            const double target = std::min(c.endTime, k * c.outputInterval);
            sim.advanceTo(target, [&](const State& s) {
                const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
                if (options.progress && wall - lastDraw > 0.2) {
                    drawProgress(s.time, c.endTime, s.step, wall, summary.particles);
                    lastDraw = wall;
                }
            });
            history.add(sim.state(), sim.energy());
            snapshot(sim.state());
        }
    } catch (const NumericalError& e) {
        snapshot(sim.state());
        options.log(std::string("stopped: ") + e.what() + "; final state written");
        throw;
    }
    summary.wallSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (options.progress) std::fprintf(stderr, "\n");
    summary.steps = sim.state().step;
    summary.particleStepsPerSecond =
        summary.steps * static_cast<double>(summary.particles) / summary.wallSeconds;
    const EnergyReport e = sim.energy();
    std::snprintf(line, sizeof line,
                  "done: t = %.4e s, %ld steps, %d snapshots, %.2f s wall, %.3e particle-steps/s",
                  sim.state().time, summary.steps, summary.snapshots, summary.wallSeconds,
                  summary.particleStepsPerSecond);
    options.log(line);
    std::snprintf(line, sizeof line,
                  "energy: kinetic %.4e J, elastic %.4e J, hourglass %.3e J, viscous %.3e J, "
                  "external work %.3e J, plastic work %.3e J, damage dissipation %.3e J, "
                  "contact energy %.3e J",
                  e.kinetic, e.elastic, e.hourglassWork, e.viscousWork,
                  e.boundaryWork + e.externalWork, e.plasticWork, e.damageDissipation,
                  e.contactEnergy);
    options.log(line);
    return summary;
}

}  // namespace gsph::solver
