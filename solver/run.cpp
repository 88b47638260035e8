// SPDX-License-Identifier: MIT
#include "run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "core/error.hpp"
#include "core/version.hpp"
#include "history.hpp"
#include "io/checkpoint.hpp"
#include "io/particle_file.hpp"
#include "io/sha256.hpp"
#include "io/snapshot.hpp"
#include "progress.hpp"
#include "signals.hpp"
#include "simulation.hpp"

namespace gsph::solver {
namespace {

using Clock = std::chrono::steady_clock;

// Materials per body id, and the initial velocity of each body, from the [[body]] entries.
struct BodySetup {
    std::vector<Material> materials;
    std::vector<double> density;
    std::vector<Vec3> velocity;
    std::vector<double> bondStretch;  ///< εmax per body (0: its bonds never break)
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
        setup.bondStretch.push_back(m->bondStretch);
    }
    return setup;
}

std::vector<VelocityConstraint> matchSets(const CaseConfig& c, const ParticleFile& file) {
    std::vector<VelocityConstraint> out;
    for (const SetSpec& s : c.sets) {
        const auto it = file.sets.find(s.name);
        if (it == file.sets.end()) {
            std::string known;
            for (const auto& [name, ids] : file.sets) known += (known.empty() ? "" : ", ") + name;
            throw InputError(c.caseFile.string() + ":" + std::to_string(s.line) + ": set '" +
                             s.name + "' is not in " + c.particles.string() +
                             " (sets there: " + (known.empty() ? "none" : known) + ")");
        }
        VelocityConstraint vc{s.name, it->second, {}};
        if (!s.fixed) {
            const Vec3 v = s.velocity;
            vc.velocity = [v](double, const Vec3&) { return v; };
        }
        out.push_back(std::move(vc));
    }
    return out;
}

// Where the run is in its schedule: what a checkpoint's counters hold besides the State.
struct Schedule {
    long nextOutput = 1;      ///< k of the next scheduled snapshot time k·output_interval
    long nextSnapshot = 0;    ///< number of the next snapshot file
    long nextCheckpoint = 1;  ///< m of the next checkpoint time m·checkpoint_interval
};

// The files the run is built from, with their hashes (a restart must find them unchanged).
std::vector<CheckpointInput> inputsOf(const CaseConfig& c) {
    return {{"case", c.caseFile.string(), sha256File(c.caseFile)},
            {"particles", c.particles.string(), sha256File(c.particles)}};
}

// One line naming the file that changed since the checkpoint was written.
void checkInputs(const std::vector<CheckpointInput>& then, const std::vector<CheckpointInput>& now,
                 const std::filesystem::path& checkpoint) {
    for (const CheckpointInput& current : now) {
        const CheckpointInput* old = nullptr;
        for (const CheckpointInput& candidate : then)
            if (candidate.role == current.role) old = &candidate;
        if (!old) throw InputError(checkpoint.string() + ": records no " + current.role + " file");
        if (old->sha256 != current.sha256)
            throw InputError(checkpoint.string() + ": " + current.role + " file '" + current.file +
                             "' differs from the one the checkpoint was written " + "with ('" +
                             old->file + "', sha256 " + old->sha256.substr(0, 12) + "…, now " +
                             current.sha256.substr(0, 12) + "…); a restart needs the same " +
                             current.role + " file");
    }
}

long counter(const RunRecord& run, const std::string& name, const std::filesystem::path& file) {
    const auto it = run.counters.find(name);
    if (it == run.counters.end())
        throw InputError(file.string() + ": checkpoint lacks the run counter '" + name + "'");
    return static_cast<long>(it->second);
}

RunRecord recordOf(const std::vector<CheckpointInput>& inputs, const Schedule& schedule,
                   const History& history) {
    RunRecord r;
    r.inputs = inputs;
    r.counters["next_output"] = schedule.nextOutput;
    r.counters["next_snapshot"] = schedule.nextSnapshot;
    r.counters["next_checkpoint"] = schedule.nextCheckpoint;
    r.texts["history"] = history.text();
    return r;
}

std::string format(const char* fmt, double a, long b) {
    char line[160];
    std::snprintf(line, sizeof line, fmt, a, b);
    return line;
}

}  // namespace

RunSummary runCase(const CaseConfig& c, const RunOptions& options) {
    RunLog& log = *options.log;
    ParticleFile file;
    try {
        file = readParticleFile(c.particles);
    } catch (const Error& e) {
        throw InputError(c.caseFile.string() + ":" + std::to_string(c.particlesLine) +
                         ": particle file: " + e.what());
    }
    const std::vector<CheckpointInput> inputs = inputsOf(c);
    // A restart is checked before anything is built: the same case and particle file.
    std::optional<Checkpoint> checkpoint;
    if (!options.restart.empty()) {
        checkpoint = readCheckpoint(options.restart);
        checkInputs(checkpoint->run.inputs, inputs, options.restart);
    }
    BodySetup bodies = matchBodies(c, file);
    std::vector<VelocityConstraint> constraints = matchSets(c, file);
    SolverOptions solverOptions;
    solverOptions.cfl = c.cfl;
    solverOptions.viscosity = c.viscosity;
    solverOptions.hourglass = c.hourglass;
    solverOptions.minTimeStepRatio = c.minDtRatio;
    solverOptions.bondStretch = bodies.bondStretch;
    Simulation sim(buildReference(file, bodies.density, c.kappa), std::move(bodies.materials),
                   solverOptions);
    for (VelocityConstraint& vc : constraints) sim.constrain(std::move(vc));
    const Reference& ref = sim.reference();

    std::filesystem::create_directories(options.runDir);
    const Provenance provenance = provenanceOf("gsph-solve", kVersion, c.caseFile);
    const std::filesystem::path checkpointPath = options.runDir / kCheckpointName;
    History history(options.runDir / "history.csv");
    ProgressBar progress(options.progress, c.endTime, ref.size());
    log.beforePrint = [&] { progress.clear(); };
    struct DetachBar {  // the log outlives this run's progress bar, also on an exception
        RunLog& log;
        ~DetachBar() { log.beforePrint = nullptr; }
    } detachBar{log};
    RunSummary summary;
    summary.particles = ref.size();
    double totalMass = 0, meshMass = 0;
    for (Index a = 0; a < ref.size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        totalMass += ref.mass[ia];
        meshMass += ref.density[ia] * ref.volume[ia];
    }
    char line[256];
    std::snprintf(line, sizeof line,
                  "particles %d, pairs %d, mass %.6g kg (ρ0 × mesh volume: %.6g kg)", ref.size(),
                  ref.pairs.pairs(), totalMass, meshMass);
    log.add(line);

    Schedule schedule;
    const auto snapshot = [&](const State& s) {
        char name[64];
        std::snprintf(name, sizeof name, "snapshot_%06ld.h5", schedule.nextSnapshot++);
        writeSnapshot(options.runDir / name, ref, s, provenance);
        history.flush();
        ++summary.snapshots;
        log.add(std::string(name) + format(": t = %.6e s, step %ld", s.time, s.step));
        log.flush();
    };
    const auto writeCheckpointNow = [&](const State& s) {
        const auto t0 = Clock::now();
        writeCheckpoint(checkpointPath, s, recordOf(inputs, schedule, history), provenance);
        const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
        std::snprintf(line, sizeof line, "%s: t = %.6e s, step %ld (%.1f kB, written in %.3f s)",
                      kCheckpointName, s.time, s.step,
                      static_cast<double>(std::filesystem::file_size(checkpointPath)) / 1e3,
                      seconds);
        log.add(line);
        log.flush();
    };

    if (checkpoint) {
        const RunRecord& run = checkpoint->run;
        schedule.nextOutput = counter(run, "next_output", options.restart);
        schedule.nextSnapshot = counter(run, "next_snapshot", options.restart);
        schedule.nextCheckpoint = counter(run, "next_checkpoint", options.restart);
        const auto text = run.texts.find("history");
        if (text == run.texts.end())
            throw InputError(options.restart.string() + ": checkpoint lacks the history");
        history.restore(text->second, options.restart.string());
        sim.resume(std::move(checkpoint->state), options.restart.string());
        checkpoint.reset();
        log.add("restart from " + options.restart.string() +
                format(": t = %.6e s, step %ld", sim.state().time, sim.state().step));
    } else {
        std::vector<Vec3> initial(static_cast<std::size_t>(ref.size()));
        for (Index a = 0; a < ref.size(); ++a)
            initial[static_cast<std::size_t>(a)] =
                bodies.velocity[static_cast<std::size_t>(ref.body[static_cast<std::size_t>(a)])];
        sim.setVelocities(initial);
        sim.start();
        history.add(sim.state(), sim.energy());
        snapshot(sim.state());
    }

    // Tolerance of "this time is reached", as Simulation::advanceTo lands on its end time.
    const double reachedTolerance = 1e-12 * std::max(1.0, c.endTime);
    const auto afterStep = [&](const State& s) {
        progress.update(s.time, s.step);
        if (c.checkpointInterval <= 0.0 || s.time >= c.endTime - reachedTolerance) return;
        const auto due = [&] {
            return s.time >= static_cast<double>(schedule.nextCheckpoint) * c.checkpointInterval -
                                 reachedTolerance;
        };
        if (!due()) return;
        while (due()) ++schedule.nextCheckpoint;
        writeCheckpointNow(s);
    };
    const auto stop = [&](const State& s) {
        if (const int signal = options.stopSignal ? options.stopSignal() : 0) {
            summary.stopReason = signalName(signal);
            return true;
        }
        if (options.stopAfterSteps > 0 && s.step >= options.stopAfterSteps) {
            summary.stopReason = "--stop-after-steps " + std::to_string(options.stopAfterSteps);
            return true;
        }
        return false;
    };
    const long firstStep = sim.state().step;
    progress.start(sim.state().time, firstStep);
    const auto t0 = Clock::now();
    try {
        for (bool last = false; !last; ++schedule.nextOutput) {
            const double target =
                std::min(c.endTime, static_cast<double>(schedule.nextOutput) * c.outputInterval);
            last = target >= c.endTime * (1 - 1e-12);
            if (!sim.advanceTo(target, afterStep, stop)) {
                // Interrupted: the checkpoint resumes this interval; the snapshot shows the
                // state (its number is rewritten by the restarted run's scheduled snapshot).
                writeCheckpointNow(sim.state());
                history.add(sim.state(), sim.energy());
                snapshot(sim.state());
                summary.interrupted = true;
                summary.checkpoint = checkpointPath;
                break;
            }
            history.add(sim.state(), sim.energy());
            snapshot(sim.state());
        }
    } catch (const NumericalError& e) {
        snapshot(sim.state());
        log.add(std::string("stopped: ") + e.what() + "; final state written");
        throw;
    }
    progress.clear();
    summary.wallSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    summary.steps = sim.state().step;
    summary.time = sim.state().time;
    summary.particleStepsPerSecond = static_cast<double>(summary.steps - firstStep) *
                                     static_cast<double>(summary.particles) /
                                     std::max(summary.wallSeconds, 1e-9);
    if (summary.interrupted) {
        log.add("interrupted (" + summary.stopReason +
                format("): t = %.6e s, step %ld; restart with --restart ", summary.time,
                       summary.steps) +
                checkpointPath.string());
        return summary;
    }
    const EnergyReport e = sim.energy();
    std::snprintf(line, sizeof line,
                  "done: t = %.4e s, %ld steps, %d snapshots, %.2f s wall, %.3e particle-steps/s",
                  sim.state().time, summary.steps, summary.snapshots, summary.wallSeconds,
                  summary.particleStepsPerSecond);
    log.add(line);
    std::snprintf(line, sizeof line,
                  "energy: kinetic %.4e J, elastic %.4e J, hourglass %.3e J, viscous %.3e J, "
                  "external work %.3e J, plastic work %.3e J, damage dissipation %.3e J",
                  e.kinetic, e.elastic, e.hourglassWork, e.viscousWork, e.boundaryWork,
                  e.plasticWork, e.damageDissipation);
    log.add(line);
    return summary;
}

}  // namespace gsph::solver
