// SPDX-License-Identifier: MIT
#include "run.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "boundary/pressure.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "history.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/particle_file.hpp"
#include "io/sha256.hpp"
#include "io/snapshot.hpp"
#include "probes.hpp"
#include "progress.hpp"
#include "reference/reference_builder.hpp"
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
    std::vector<double> bondStretch;          ///< εmax per body (0: its bonds never break)
    std::vector<double> fractureEnergy;       ///< G0 per body (0: its bonds break sharply)
    std::vector<FailedBondRule> failedBonds;  ///< per body: bonds of failed particles
};

BodySetup matchBodies(const CaseConfig& c, const ParticleFile& file) {
    for (const BodySpec& s : c.bodies) {
        bool found = false;
        for (std::size_t b = 0; b < file.bodies.size(); ++b)
            found = found || namesBody(s.group, file, b);
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
            if (namesBody(s.group, file, b)) {
                if (spec)
                    throw InputError(c.caseFile.string() + ":" + std::to_string(s.line) +
                                     ": [[body]] group '" + s.group + "' names body " +
                                     std::to_string(b) + " ('" + info.name +
                                     "'), which the entry at line " + std::to_string(spec->line) +
                                     " ('" + spec->group + "') already names");
                spec = &s;
            }
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
        setup.fractureEnergy.push_back(m->fractureEnergy);
        setup.failedBonds.push_back(spec->failedBonds == "either" ? FailedBondRule::Either
                                    : spec->failedBonds == "both" ? FailedBondRule::Both
                                    : spec->failedBonds == "cut"  ? FailedBondRule::Cut
                                                                  : FailedBondRule::Keep);
    }
    return setup;
}

// The [[set]] conditions: kinematic ones become constraints, forces become loads, pressures
// become force stages.
struct SetConditions {
    std::vector<VelocityConstraint> constraints;
    std::vector<SetForce> forces;
    std::vector<PressureLoad> pressures;
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
        if (s.kind == SetSpec::Kind::Pressure) {
            const auto areas = file.setAreas.find(s.name);
            if (areas == file.setAreas.end())
                throw InputError(c.caseFile.string() + ":" + std::to_string(s.line) +
                                 ": a pressure on set '" + s.name + "' needs its face areas, and " +
                                 c.particles.string() +
                                 " has none (written by an older gsph-preproc: convert again)");
            out.pressures.push_back({s.name, it->second, areas->second, s.pressure});
            continue;
        }
        VelocityConstraint vc{s.name, it->second, {}, s.holds};
        if (s.kind == SetSpec::Kind::Velocity) {
            const Vec3 v = s.velocity;
            vc.velocity = [v](double, const Vec3&) { return v; };
        }
        out.constraints.push_back(std::move(vc));
    }
    return out;
}

// Where the run is in its schedule: what a checkpoint's counters hold besides the State.
struct Schedule {
    long nextOutput = 1;      ///< k of the next scheduled snapshot time k·output_interval
    long nextSnapshot = 0;    ///< number of the next snapshot file
    long nextCheckpoint = 1;  ///< m of the next checkpoint time m·checkpoint_interval
    long nextHistory = 1;     ///< j of the next history row time j·history_interval
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
                             "' differs from the one the checkpoint was written with ('" +
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

// A double as text that reads back to the same bits.
std::string exactText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::string format(const char* fmt, double a, long b) {
    char line[160];
    std::snprintf(line, sizeof line, fmt, a, b);
    return line;
}

// The library's wall of a [[wall]] entry.
Wall wallOf(const WallSpec& w) {
    Wall out{w.name, w.point, w.normal, w.velocity, w.friction};
    out.shape = w.cylinder ? WallShape::Cylinder : WallShape::Plane;
    out.axis = w.axis;
    out.radius = w.radius;
    out.rampTime = w.rampTime;
    return out;
}

// Per body of the simulation, the name of its history.csv columns: its physical group's, or
// its id when the group has no name.
std::vector<std::string> bodyNamesOf(const ParticleFile& file, const Simulation& sim) {
    std::vector<std::string> names;
    for (const BodyRange& range : sim.bodies()) {
        const Index id = sim.reference().body[static_cast<std::size_t>(range.begin)];
        const std::string& name = file.bodies[static_cast<std::size_t>(id)].name;
        names.push_back(name.empty() ? std::to_string(id) : name);
    }
    return names;
}

// Whether this process writes the run folder (a serial run, or process 0 of a split one).
bool writesFiles(const RunOptions& options) {
    return !options.domain || options.domain->writesFiles();
}

std::vector<Wall> wallsOf(const CaseConfig& c) {
    std::vector<Wall> walls;
    for (const WallSpec& w : c.walls) walls.push_back(wallOf(w));
    return walls;
}

// The run folder's files and the schedule that says when they are written: snapshots,
// history.csv, checkpoint.h5, run.log, and the progress bar between them.
class RunOutputs {
  public:
    /// `file`: the run's particle file (its bodies' names for the columns and the probes).
    RunOutputs(const CaseConfig& c, const RunOptions& options, Simulation& sim,
               const ParticleFile& file, std::vector<CheckpointInput> inputs)
        : c_(c),
          options_(options),
          sim_(sim),
          writes_(writesFiles(options)),
          log_(*options.log),
          ref_(sim.reference()),
          inputs_(std::move(inputs)),
          provenance_(provenanceOf("gsph-solve", kVersion, c.caseFile)),
          history_(options.runDir / "history.csv", bodyNamesOf(file, sim), wallsOf(c),
                   contactBetweenBodies(sim.options().contact, sim.bodies().size()),
                   softensBonds(sim.options())),
          probes_(options.runDir / "probes.csv", findProbes(c, ref_, file)),
          progress_(options.progress, c.endTime, ref_.size()) {
        log_.beforePrint = [this] { progress_.clear(); };
        // What each body's material carries between steps (and what its arrays in the
        // snapshots mean): its model's history variables.
        const std::vector<std::string> names = bodyNamesOf(file, sim);
        for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
            const BodyRange& body = sim.bodies()[b];
            std::string line = "body '" + names[b] + "': " + std::to_string(body.end - body.begin) +
                               " particles, history variables:";
            const auto history = historyVariables(*body.material);
            for (const HistoryVariable& h : history)
                line += std::string(" ") + h.field->name + " [" + h.field->unit + "]";
            log_.add(history.empty() ? line + " none" : line);
        }
        for (const Probe& p : probes_.probes()) {
            const Vec3& X = ref_.X[static_cast<std::size_t>(p.particle)];
            char line[320];
            std::snprintf(line, sizeof line,
                          "probe '%s': particle %d at X = (%.6g, %.6g, %.6g) m, %.3g m from its "
                          "point",
                          p.name.c_str(), p.particle, X[0], X[1], X[2], p.distance);
            log_.add(line);
        }
    }
    ~RunOutputs() { log_.beforePrint = nullptr; }  // the log outlives the progress bar
    RunOutputs(const RunOutputs&) = delete;
    RunOutputs& operator=(const RunOutputs&) = delete;

    Schedule schedule;
    ProgressBar& progress() { return progress_; }
    std::filesystem::path checkpointPath() const { return options_.runDir / kCheckpointName; }
    int snapshotsWritten() const { return snapshots_; }
    /// A split run's gathers of the state to process 0 for the files: how many, and their time.
    int gathers() const { return gathers_; }
    double gatherSeconds() const { return gatherSeconds_; }

    /// A history row and a snapshot of the simulation's state (a scheduled one, or the last
    /// of a stopped run).
    void snapshot(const Simulation& sim) {
        addRow(sim);
        writeSnapshotOnly(sim.state());
    }
    /// A snapshot without a history row (the failing state of a numerical breakdown).
    void writeSnapshotOnly(const State& s) {
        gather();
        char name[64];
        std::snprintf(name, sizeof name, "snapshot_%06ld.h5", schedule.nextSnapshot++);
        ++snapshots_;
        if (!writes_) return;
        writeSnapshot(options_.runDir / name, ref_, s, provenance_);
        history_.table().flush();
        if (!probes_.empty()) probes_.table().flush();
        log_.add(std::string(name) + format(": t = %.6e s, step %ld", s.time, s.step));
        log_.flush();
    }
    void checkpoint(const State& s) {
        gather();
        if (!writes_) return;
        const auto t0 = Clock::now();
        RunRecord r;
        r.inputs = inputs_;
        r.counters["next_output"] = schedule.nextOutput;
        r.counters["next_snapshot"] = schedule.nextSnapshot;
        r.counters["next_checkpoint"] = schedule.nextCheckpoint;
        r.counters["next_history"] = schedule.nextHistory;
        // The intervals the counters count in: a restart with other intervals re-counts them.
        r.texts["output_interval"] = exactText(c_.outputInterval);
        r.texts["checkpoint_interval"] = exactText(c_.checkpointInterval);
        r.texts["mass"] = massBasisKey(c_.massBasis);  // a restart continues with it
        r.texts["history"] = history_.table().text();
        if (!probes_.empty()) r.texts["probes"] = probes_.table().text();
        writeCheckpoint(checkpointPath(), s, r, provenance_);
        const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
        char line[160];
        std::snprintf(line, sizeof line, "%s: t = %.6e s, step %ld (%.1f kB, written in %.3f s)",
                      kCheckpointName, s.time, s.step,
                      static_cast<double>(std::filesystem::file_size(checkpointPath())) / 1e3,
                      seconds);
        log_.add(line);
        log_.flush();
    }
    /// The schedule and history a checkpoint stored.
    void restore(const RunRecord& run, double time) {
        const std::filesystem::path& file = options_.restart;
        schedule.nextOutput = counter(run, "next_output", file);
        schedule.nextSnapshot = counter(run, "next_snapshot", file);
        schedule.nextCheckpoint = counter(run, "next_checkpoint", file);
        // Checkpoints written before history rows between snapshots existed have no counter.
        schedule.nextHistory =
            run.counters.count("next_history") != 0 ? counter(run, "next_history", file) : 1;
        const auto text = run.texts.find("history");
        if (text == run.texts.end())
            throw InputError(file.string() + ": checkpoint lacks the history");
        history_.table().restore(text->second, file.string());
        if (!probes_.empty()) {
            const auto probeText = run.texts.find("probes");
            if (probeText == run.texts.end())
                throw InputError(file.string() + ": checkpoint lacks the probes");
            probes_.table().restore(probeText->second, file.string());
        }
        // Intervals changed on the command line (--output-interval, --checkpoint-interval):
        // the schedule goes on from the checkpoint's time in the new intervals.
        const auto firstPast = [&](double interval) { return firstMultiplePast(time, interval); };
        const auto changed = [&](const char* key, double now) {
            const auto it = run.texts.find(key);
            return it != run.texts.end() && it->second != exactText(now);
        };
        if (changed("output_interval", c_.outputInterval))
            schedule.nextOutput = firstPast(c_.outputInterval);
        if (changed("checkpoint_interval", c_.checkpointInterval) && c_.checkpointInterval > 0.0)
            schedule.nextCheckpoint = firstPast(c_.checkpointInterval);
        if (run.counters.count("next_history") == 0 && c_.historyInterval > 0.0)
            schedule.nextHistory = firstPast(c_.historyInterval);
        if (time >= c_.endTime - reachedTolerance()) {
            char at[64];
            std::snprintf(at, sizeof at, "%.6e", time);
            throw InputError(file.string() + ": the run is at t = " + at +
                             " s, already at its end time; give a later --end-time to continue it");
        }
    }
    /// After every step: the progress bar, a history row at the first step at or past each
    /// j·history_interval (unless a snapshot, which writes its own row, ends this step), and a
    /// checkpoint at the first step at or past each m·checkpoint_interval (none at the end
    /// time: the run is done then). `outputTarget`: the time of the next snapshot.
    void afterStep(const Simulation& sim, double outputTarget) {
        const State& s = sim.state();
        progress_.update(s.time, s.step);
        const double tol = reachedTolerance();
        if (c_.historyInterval > 0.0 &&
            s.time >= static_cast<double>(schedule.nextHistory) * c_.historyInterval - tol) {
            if (s.time < outputTarget - tol) addRow(sim);
            schedule.nextHistory = firstMultiplePast(s.time, c_.historyInterval);
        }
        if (c_.checkpointInterval <= 0.0 || s.time >= c_.endTime - tol) return;
        const auto due = [&](long m) {
            return s.time >= static_cast<double>(m) * c_.checkpointInterval - reachedTolerance();
        };
        if (!due(schedule.nextCheckpoint)) return;
        // The first multiple past this time: started within one of it (counting up from the
        // last one would spin for long on a tiny interval).
        long next = std::max(schedule.nextCheckpoint,
                             static_cast<long>(std::floor(s.time / c_.checkpointInterval)));
        while (due(next)) ++next;
        schedule.nextCheckpoint = next;
        checkpoint(s);
    }
    /// Tolerance of "this time is reached", as Simulation::advanceTo lands on its end time.
    double reachedTolerance() const { return 1e-12 * std::max(1.0, c_.endTime); }
    /// The first k ≥ 1 with k·interval past `time` (counted from time/interval, so a tiny
    /// interval does not spin).
    long firstMultiplePast(double time, double interval) const {
        long k = std::max(1L, static_cast<long>(std::floor(time / interval)));
        while (static_cast<double>(k) * interval <= time + reachedTolerance()) ++k;
        return k;
    }

  private:
    /// The split run's domain; null when serial.
    Domain* domain() const {
        return options_.domain && options_.domain->processes() > 1 ? options_.domain.get()
                                                                   : nullptr;
    }

    /// A split run's state is whole on the writing process only after a gather (collective:
    /// every process calls it at the same points, once per step at most).
    void gather() {
        if (gatheredStep_ == sim_.state().step || domain() == nullptr) return;
        const auto t0 = Clock::now();
        sim_.gatherState();
        gatherSeconds_ += std::chrono::duration<double>(Clock::now() - t0).count();
        ++gathers_;
        gatheredStep_ = sim_.state().step;
    }

    /// A row of history.csv and of probes.csv.
    void addRow(const Simulation& sim) {
        // The energies are summed over the processes, the probes read where their particles are.
        history_.add(sim.state(), sim.energy(), sim.wallForces(), sim.contactForces());
        if (!probes_.empty()) probes_.add(ref_, sim.state(), sim.integrator().owned(), domain());
    }

    const CaseConfig& c_;
    const RunOptions& options_;
    Simulation& sim_;
    bool writes_;  ///< this process writes the files (the others keep them in memory only)
    long gatheredStep_ = -1;
    int gathers_ = 0;
    double gatherSeconds_ = 0.0;
    RunLog& log_;
    const Reference& ref_;
    std::vector<CheckpointInput> inputs_;
    Provenance provenance_;
    History history_;
    Probes probes_;
    ProgressBar progress_;
    int snapshots_ = 0;
};

// The case's simulation, built from the case and its particle file (constraints set, not
// started).
std::unique_ptr<Simulation> buildSimulation(const CaseConfig& c, const ParticleFile& file,
                                            BodySetup& bodies, ProgressBar::Mode progress) {
    SetConditions sets = matchSets(c, file);
    SolverOptions solverOptions;
    solverOptions.cfl = c.cfl;
    solverOptions.viscosity = c.viscosity;
    solverOptions.hourglass = c.hourglass;
    solverOptions.hourglassModulus = c.hourglassModulus;
    solverOptions.minTimeStepRatio = c.minDtRatio;
    solverOptions.bondStretch = bodies.bondStretch;
    solverOptions.fractureEnergy = bodies.fractureEnergy;
    for (const PrecrackSpec& p : c.precracks)
        solverOptions.precracks.push_back({p.corner, p.edge1, p.edge2});
    solverOptions.failedBonds = bodies.failedBonds;
    solverOptions.contact = c.contact;
    Reference ref = buildReference(file, bodies.density, c.kappa);
    ref.massBasis = c.massBasis;
    if (!c.dimension.empty()) {
        const int wanted = c.dimension == "3d" ? 3 : 2;
        if (wanted != file.dimension)
            throw InputError(c.caseFile.string() + ":" + std::to_string(c.dimensionLine) +
                             ": [run] dimension = \"" + c.dimension + "\" needs a " +
                             std::to_string(wanted) + "-D particle file, and " +
                             c.particles.string() + " is " + std::to_string(file.dimension) + "-D");
        ref.dim.axisymmetric = c.dimension == "axisymmetric";
    }
    {
        // The derived fields here rather than silently in Simulation: on a large overset band
        // the interface weights' solve takes minutes, and the user sees it advance.
        ProgressBar setup(progress, c.endTime, ref.size());
        setup.start(0.0, 0);
        completeReference(ref, SearchMethod::CellList, [&](int iteration, double residual) {
            char text[160];
            std::snprintf(
                text, sizeof text,
                "set-up: overset interface weights, CG iteration %d, residual %.1e (to 1e-14)",
                iteration, residual);
            setup.status(text);
        });
    }
    auto sim =
        std::make_unique<Simulation>(std::move(ref), std::move(bodies.materials), solverOptions);
    for (VelocityConstraint& vc : sets.constraints) sim->constrain(std::move(vc));
    for (SetForce& f : sets.forces) sim->applyForce(std::move(f));
    for (PressureLoad& p : sets.pressures) {
        if (sim->reference().dim.axisymmetric) p.area = sweptSetAreas(file, p.name);
        sim->addStage(std::make_shared<PressureStage>(sim->reference(), std::move(p)));
    }
    for (const WallSpec& w : c.walls) sim->addWall(wallOf(w));
    sim->setGravity(c.gravity);
    return sim;
}

// Snapshots and checkpoints are written at intervals of simulated time; one shorter than the
// first step would write a file after every step (or spin on its schedule).
void checkIntervals(const CaseConfig& c, double dt0) {
    const auto refuse = [&](const char* key, double value, const char* remedy) {
        char line[400];
        std::snprintf(line, sizeof line,
                      ": [run] %s = %.3e s is below the first time step (Δt0 = %.3e s): every "
                      "step would write a file; %s",
                      key, value, dt0, remedy);
        throw InputError(c.caseFile.string() + line);
    };
    if (c.outputInterval < dt0)
        refuse("output_interval", c.outputInterval,
               "give output_interval ≥ Δt0 (or leave it out: end_time / 10)");
    if (c.checkpointInterval > 0.0 && c.checkpointInterval < dt0)
        refuse("checkpoint_interval", c.checkpointInterval,
               "give checkpoint_interval ≥ Δt0 (0: checkpoints on a signal only)");
}

std::string sizeLine(const Reference& ref) {
    double totalMass = 0, meshMass = 0;
    for (Index a = 0; a < ref.size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        totalMass += ref.mass[ia];
        meshMass += ref.density[ia] * ref.meshVolume(ia);
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "particles %d, pairs %d, mass %.6g kg (ρ0 × mesh volume: %.6g kg)", ref.size(),
                  ref.pairs.pairs(), totalMass, meshMass);
    return line;
}

// The end of a finished run: its size and speed, where the time went (the step's phases, as
// gsph-bench prints them, and the rest: snapshots, checkpoints, history), the energies.
void logEnd(RunLog& log, const RunSummary& summary, const PhaseTimes& phases,
            const EnergyReport& e) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "done: t = %.4e s, %ld steps, %d snapshots, %.2f s wall, %.3e particle-steps/s",
                  summary.time, summary.steps, summary.snapshots, summary.wallSeconds,
                  summary.particleStepsPerSecond);
    log.add(line);
    const double wall = std::max(summary.wallSeconds, 1e-9);
    const double rest =
        wall - phases.kinematicsAndStress - phases.forces - phases.contact - phases.other;
    std::snprintf(line, sizeof line,
                  "time: kinematics+stress %.1f %%, forces %.1f %%, contact, walls and loads "
                  "%.1f %%, other step work %.1f %%, files and the rest %.1f %% of the wall time",
                  100 * phases.kinematicsAndStress / wall, 100 * phases.forces / wall,
                  100 * phases.contact / wall, 100 * phases.other / wall,
                  100 * std::max(rest, 0.0) / wall);
    log.add(line);
    std::snprintf(line, sizeof line,
                  "energy: kinetic %.4e J, elastic %.4e J, hourglass %.3e J, viscous %.3e J, "
                  "external work %.3e J, plastic work %.3e J, damage dissipation %.3e J, "
                  "fracture energy %.3e J, cohesive work %.3e J, contact energy %.3e J",
                  e.kinetic, e.elastic, e.hourglassWork, e.viscousWork,
                  e.boundaryWork + e.externalWork, e.plasticWork, e.damageDissipation,
                  e.fractureEnergy, e.cohesiveWork, e.contactEnergy);
    log.add(line);
}

// The mass basis a checkpoint's run used: its record's, or, in a checkpoint written before the
// record held it, the default of then ("quadrature") unless the case chose "mesh" (never a
// default). A restart continues with it, so that it goes on as the run it continues.
MassBasis massBasisOf(const RunRecord& run, const CaseConfig& c) {
    const auto it = run.texts.find("mass");
    if (it == run.texts.end())
        return c.massBasis == MassBasis::MeshVolume ? MassBasis::MeshVolume
                                                    : MassBasis::QuadratureVolume;
    if (const std::optional<MassBasis> basis = massBasisNamed(it->second)) return *basis;
    throw InputError("checkpoint: unknown mass basis '" + it->second + "'");
}

}  // namespace

std::vector<std::filesystem::path> earlierRunFiles(const std::filesystem::path& runDir) {
    std::vector<std::filesystem::path> out;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(runDir, ec), end; !ec && it != end;
         it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const bool snapshot = name.rfind("snapshot_", 0) == 0 && it->path().extension() == ".h5";
        if (snapshot || name == kCheckpointName || name == "history.csv" || name == "probes.csv" ||
            name == "run.log")
            out.push_back(it->path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// What the set-up took (reading the inputs, the reference configuration, the first forces), and
// the overset band's interface-weight solve, the part that grows fastest with an O-grid.
std::string setupLine(const Reference& ref, double seconds) {
    char line[400];
    const int n = std::snprintf(
        line, sizeof line, "set-up %.2f s wall (inputs, reference configuration, first forces)",
        seconds);
    const Reference::InterfaceSolve& s = ref.interfaceSolve;
    if (s.rows > 0 && n > 0 && static_cast<std::size_t>(n) < sizeof line)
        std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n),
                      "; the overset band's interface weights: %d constraint rows, %d "
                      "conjugate-gradient iterations, relative residual %.1e",
                      s.rows, s.iterations, s.residual);
    return line;
}

RunSummary runCase(const CaseConfig& caseConfig, const RunOptions& options) {
    const auto setupStart = Clock::now();
    CaseConfig c = caseConfig;
    ParticleFile file;
    try {
        file = readParticleFileIsolated(c.particles);
    } catch (const Error& e) {
        throw InputError(c.caseFile.string() + ":" + std::to_string(c.particlesLine) +
                         ": particle file: " + e.what());
    }
    std::vector<CheckpointInput> inputs = inputsOf(c);
    // A restart is checked before anything is built: the same case and particle file.
    std::optional<Checkpoint> checkpoint;
    if (!options.restart.empty()) {
        checkpoint = readCheckpoint(options.restart);
        checkInputs(checkpoint->run.inputs, inputs, options.restart);
        try {
            c.massBasis = massBasisOf(checkpoint->run, c);
        } catch (const InputError& e) {
            throw InputError(options.restart.string() + ": " + e.what());
        }
    }
    // A fresh run never mixes its files with an earlier run's (gsph-post would read both).
    if (!checkpoint) {
        const std::vector<std::filesystem::path> earlier = earlierRunFiles(options.runDir);
        if (!earlier.empty() && !options.overwrite)
            throw InputError(options.runDir.string() + ": holds an earlier run (" +
                             std::to_string(earlier.size()) + " files, e.g. " +
                             earlier.front().filename().string() +
                             "); give another -o, continue it with --restart, or pass "
                             "--overwrite to replace it");
        if (writesFiles(options))
            for (const std::filesystem::path& p : earlier) std::filesystem::remove(p);
    }
    BodySetup bodies = matchBodies(c, file);
    const std::unique_ptr<Simulation> simulation =
        buildSimulation(c, file, bodies, options.progress);
    Simulation& sim = *simulation;
    const Reference& ref = sim.reference();
    const bool split = options.domain && options.domain->processes() > 1;
    if (split) sim.setDomain(options.domain);
    const bool writes = writesFiles(options);
    if (writes) std::filesystem::create_directories(options.runDir);
    if (const int stale = writes ? removeStaleTemporaries(options.runDir) : 0)
        options.log->add("removed " + std::to_string(stale) +
                         " temporary file(s) that an earlier, killed process left in " +
                         options.runDir.string());
    RunOutputs out(c, options, sim, file, std::move(inputs));
    options.log->add(sizeLine(ref));
    // From here on the run writes its folder: a signal stops it after a step, with a checkpoint.
    if (options.steppingStarts) options.steppingStarts();
    if (checkpoint) {
        out.restore(checkpoint->run, checkpoint->state.time);
        sim.resume(std::move(checkpoint->state), options.restart.string());
        checkpoint.reset();
        checkIntervals(c, sim.state().initialDt);
        options.log->add("restart from " + options.restart.string() +
                         format(": t = %.6e s, step %ld", sim.state().time, sim.state().step));
        if (c.massBasis != caseConfig.massBasis)
            options.log->add("mass = \"" + massBasisKey(c.massBasis) +
                             "\" as the checkpoint's run (the case's is \"" +
                             massBasisKey(caseConfig.massBasis) + "\")");
    } else {
        std::vector<Vec3> initial(static_cast<std::size_t>(ref.size()));
        for (Index a = 0; a < ref.size(); ++a)
            initial[static_cast<std::size_t>(a)] =
                bodies.velocity[static_cast<std::size_t>(ref.body[static_cast<std::size_t>(a)])];
        sim.setVelocities(initial);
        sim.start();
        checkIntervals(c, sim.state().initialDt);
        const EnergyReport initialEnergy = sim.energy();
        // Bodies placed inside a contact distance (of a wall or of each other) start on
        // compressed penalty springs that release this energy at once: say so.
        if (initialEnergy.contactEnergy > 0.0) {
            char line[400];
            std::snprintf(
                line, sizeof line,
                "warning: at t = 0 particles lie inside a contact distance (contact "
                "energy %.3e J, %.3g %% of the kinetic energy): the penalty springs "
                "push them apart at once; leave a gap of half a particle spacing "
                "(docs/theory.md, Contact)",
                initialEnergy.contactEnergy,
                100.0 * initialEnergy.contactEnergy / std::max(initialEnergy.kinetic, 1e-300));
            options.log->add(line);
        }
        out.snapshot(sim);
    }
    options.log->add(
        setupLine(ref, std::chrono::duration<double>(Clock::now() - setupStart).count()));

    if (split) options.log->add(sim.integrator().domain().describe());
    RunSummary summary;
    summary.particles = ref.size();
    const auto stop = [&](const State& s) {
        const int signal = options.stopSignal ? options.stopSignal() : 0;
        // A split run stops on every process after the same step.
        if (split ? options.domain->any(signal != 0) : signal != 0) {
            summary.stopReason = signal != 0 ? signalName(signal) : "a signal to another process";
            return true;
        }
        if (options.stopAfterSteps > 0 && s.step >= options.stopAfterSteps) {
            summary.stopReason = "--stop-after-steps " + std::to_string(options.stopAfterSteps);
            return true;
        }
        return false;
    };
    const long firstStep = sim.state().step;
    out.progress().start(sim.state().time, firstStep);
    const auto t0 = Clock::now();
    try {
        for (bool last = false; !last; ++out.schedule.nextOutput) {
            const double target = std::min(
                c.endTime, static_cast<double>(out.schedule.nextOutput) * c.outputInterval);
            last = target >= c.endTime * (1 - 1e-12);
            if (!sim.advanceTo(
                    target, [&](const State&) { out.afterStep(sim, target); }, stop)) {
                // Stopped: the checkpoint resumes this interval; the snapshot shows the state
                // (the restarted run rewrites its number with the scheduled snapshot).
                out.checkpoint(sim.state());
                out.snapshot(sim);
                summary.interrupted = true;
                summary.checkpoint = out.checkpointPath();
                break;
            }
            out.snapshot(sim);
        }
    } catch (const NumericalError& e) {
        // Split, the other processes are waiting in an exchange: no final snapshot (main ends
        // them all).
        if (split) throw;
        out.writeSnapshotOnly(sim.state());
        options.log->add(std::string("stopped: ") + e.what() + "; final state written");
        throw;
    }
    out.progress().clear();
    // A finished run ends with a checkpoint too: --restart --end-time continues it.
    if (!summary.interrupted && c.checkpointInterval > 0.0) out.checkpoint(sim.state());
    summary.wallSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    summary.steps = sim.state().step;
    summary.time = sim.state().time;
    summary.snapshots = out.snapshotsWritten();
    summary.particleStepsPerSecond = static_cast<double>(summary.steps - firstStep) *
                                     static_cast<double>(summary.particles) /
                                     std::max(summary.wallSeconds, 1e-9);
    if (summary.interrupted) {
        options.log->add("interrupted (" + summary.stopReason +
                         format("): t = %.6e s, step %ld; restart with --restart ", summary.time,
                                summary.steps) +
                         summary.checkpoint.string());
    } else {
        logEnd(*options.log, summary, sim.integrator().phaseTimes(), sim.energy());
        if (split) {
            const PhaseTimes& t = sim.integrator().phaseTimes();
            char line[400];
            const Domain::BytesSent sent = options.domain->bytesSent();
            const double steps = static_cast<double>(std::max<long>(summary.steps - firstStep, 1));
            std::snprintf(line, sizeof line,
                          "process 0: %.2f s of the steps exchanging ghosts' columns (of %.2f s "
                          "in the steps); sent per step: %.1f kB of its particles' columns to "
                          "others' ghosts, %.1f kB of contact positions; %d gathers of the state "
                          "for the files, %.3g s",
                          t.exchange, t.kinematicsAndStress + t.forces + t.contact + t.other,
                          sent.ghosts / 1e3 / steps, sent.contact / 1e3 / steps, out.gathers(),
                          out.gatherSeconds());
            options.log->add(line);
        }
        const BrittleBonds& bonds = sim.integrator().bonds();
        if (bonds.enabled()) {
            // Each process counts its own particles; the counts are summed over the processes.
            const ParticleRange owned = sim.integrator().owned();
            std::array<ExactSum, 2> counts = {
                exactSum(owned, [&](Index a) { return bonds.detached(a) ? 1.0 : 0.0; }),
                exactSum(owned, [&](Index a) {
                    return sim.state().damage[static_cast<std::size_t>(a)] >= 1.0 ? 1.0 : 0.0;
                })};
            if (split) options.domain->sum(counts);
            const auto detached = static_cast<Index>(counts[0].value());
            const auto failed = static_cast<Index>(counts[1].value());
            // The initial cracks' share, from the reference alone (also after a restart).
            Index initial = 0;
            if (!sim.integrator().options().precracks.empty()) {
                std::vector<std::uint8_t> intact(static_cast<std::size_t>(ref.pairs.pairs()), 1);
                initial = breakBondsAcross(ref, sim.integrator().options().precracks, intact);
            }
            char line[240];
            std::snprintf(line, sizeof line,
                          "bonds: %d pairs broken (%d of them by the initial cracks), %d "
                          "particles detached (no stress), %d failed (D ≥ 1); no particle is "
                          "removed",
                          bonds.brokenPairs(), initial, detached, failed);
            options.log->add(line);
        }
    }
    return summary;
}

}  // namespace gsph::solver
