// SPDX-License-Identifier: MIT
#include "history.hpp"

#include <cstdio>
#include <stdexcept>

#include "core/error.hpp"

namespace gsph::solver {
namespace {

struct HistoryColumn {
    const char* name;
    const char* format;  ///< printf format of the value
    double (*value)(const State&, const EnergyReport&);
};

// The columns of history.csv, in order: the run's clock, the energy channels (the total is
// kinetic + internal + every dissipated/stored work − external work, conserved; with softening
// bonds it includes their cohesive work, kCohesiveColumn), momentum.
const HistoryColumn kHistoryColumns[] = {
    {"time", "%.9e", [](const State& s, const EnergyReport&) { return s.time; }},
    {"step", "%.0f", [](const State& s, const EnergyReport&) { return double(s.step); }},
    {"dt", "%.6e", [](const State& s, const EnergyReport&) { return s.dt; }},
    {"kinetic_energy", "%.9e", [](const State&, const EnergyReport& e) { return e.kinetic; }},
    {"internal_energy", "%.9e", [](const State&, const EnergyReport& e) { return e.elastic; }},
    {"plastic_work", "%.9e", [](const State&, const EnergyReport& e) { return e.plasticWork; }},
    {"damage_dissipation", "%.9e",
     [](const State&, const EnergyReport& e) { return e.damageDissipation; }},
    {"fracture_energy", "%.9e",
     [](const State&, const EnergyReport& e) { return e.fractureEnergy; }},
    {"hourglass_work", "%.9e", [](const State&, const EnergyReport& e) { return e.hourglassWork; }},
    {"viscous_work", "%.9e", [](const State&, const EnergyReport& e) { return e.viscousWork; }},
    {"contact_energy", "%.9e", [](const State&, const EnergyReport& e) { return e.contactEnergy; }},
    {"external_work", "%.9e",
     [](const State&, const EnergyReport& e) { return e.boundaryWork + e.externalWork; }},
    {"total_energy", "%.9e", [](const State&, const EnergyReport& e) { return e.total(); }},
    {"momentum_x", "%.9e", [](const State&, const EnergyReport& e) { return e.momentum[0]; }},
    {"momentum_y", "%.9e", [](const State&, const EnergyReport& e) { return e.momentum[1]; }},
    {"momentum_z", "%.9e", [](const State&, const EnergyReport& e) { return e.momentum[2]; }},
};

// In runs with softening bonds only, after the run's columns: their cohesive work.
const HistoryColumn kCohesiveColumn = {
    "cohesive_work", "%.9e", [](const State&, const EnergyReport& e) { return e.cohesiveWork; }};

struct WallColumn {
    const char* suffix;  ///< the column is wall_<name>_<suffix>
    const char* format;
    double (*value)(const State&, const Wall&, const Vec3& force);
};

// Per wall, after the run's columns: the force it exerts on the bodies (normal push and
// friction; the bodies push the wall with the opposite) and its displacement velocity·t.
const WallColumn kWallColumns[] = {
    {"fx", "%.9e", [](const State&, const Wall&, const Vec3& f) { return f[0]; }},
    {"fy", "%.9e", [](const State&, const Wall&, const Vec3& f) { return f[1]; }},
    {"fz", "%.9e", [](const State&, const Wall&, const Vec3& f) { return f[2]; }},
    {"ux", "%.9e",
     [](const State& s, const Wall& w, const Vec3&) { return w.displacement(s.time)[0]; }},
    {"uy", "%.9e",
     [](const State& s, const Wall& w, const Vec3&) { return w.displacement(s.time)[1]; }},
    {"uz", "%.9e",
     [](const State& s, const Wall& w, const Vec3&) { return w.displacement(s.time)[2]; }},
};

// Per pair of bodies (i, j), i before j, after the walls' columns (LS-DYNA's rcforc): the force
// that j exerts on i through their contact (i exerts the opposite on j).
const char* const kContactColumns[] = {"fx", "fy", "fz"};

struct BodyColumn {
    const char* suffix;  ///< the column is body_<name>_<suffix>
    const char* format;
    double (*value)(const BodyEnergy&);
};

// Per body, after the walls' columns (LS-DYNA's matsum): its share of the run's energies and
// momentum of the same names, so that the bodies' columns add up to the run's.
const BodyColumn kBodyColumns[] = {
    {"kinetic_energy", "%.9e", [](const BodyEnergy& b) { return b.kinetic; }},
    {"internal_energy", "%.9e", [](const BodyEnergy& b) { return b.elastic; }},
    {"plastic_work", "%.9e", [](const BodyEnergy& b) { return b.plasticWork; }},
    {"momentum_x", "%.9e", [](const BodyEnergy& b) { return b.momentum[0]; }},
    {"momentum_y", "%.9e", [](const BodyEnergy& b) { return b.momentum[1]; }},
    {"momentum_z", "%.9e", [](const BodyEnergy& b) { return b.momentum[2]; }},
};

std::vector<std::string> columnNamesOf(const std::vector<std::string>& names) {
    std::vector<std::string> out;
    for (const std::string& name : names) out.push_back(columnName(name));
    return out;
}

}  // namespace

std::string columnName(const std::string& name) {
    std::string out = name;
    for (char& c : out) {
        const bool keep =
            (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        if (!keep) c = '_';
    }
    return out;
}

History::History(std::filesystem::path path, const std::vector<std::string>& bodies,
                 std::vector<Wall> walls, bool contactBetweenBodies, bool softeningBonds)
    : bodies_(columnNamesOf(bodies)),
      walls_(std::move(walls)),
      contact_(contactBetweenBodies),
      cohesive_(softeningBonds),
      table_(std::move(path), columnNames()) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        for (std::size_t other = 0; other < b; ++other)
            if (bodies_[other] == bodies_[b])
                throw InputError("bodies '" + bodies[other] + "' and '" + bodies[b] +
                                 "' would have the same history columns (body_" + bodies_[b] +
                                 "_…): give their physical groups names that differ in letters "
                                 "or digits");
    }
}

std::vector<std::string> History::columnNames() const {
    std::vector<std::string> names;
    for (const HistoryColumn& c : kHistoryColumns) names.emplace_back(c.name);
    if (cohesive_) names.emplace_back(kCohesiveColumn.name);
    for (const Wall& w : walls_)
        for (const WallColumn& c : kWallColumns)
            names.push_back("wall_" + columnName(w.name) + "_" + c.suffix);
    if (contact_)
        for (std::size_t i = 0; i < bodies_.size(); ++i)
            for (std::size_t j = i + 1; j < bodies_.size(); ++j)
                for (const char* suffix : kContactColumns)
                    names.push_back("contact_" + bodies_[i] + "_" + bodies_[j] + "_" + suffix);
    for (const std::string& body : bodies_)
        for (const BodyColumn& c : kBodyColumns) names.push_back("body_" + body + "_" + c.suffix);
    return names;
}

void History::add(const State& state, const EnergyReport& energy,
                  const std::vector<Vec3>& wallForces, const std::vector<Vec3>& contactForces) {
    if (wallForces.size() != walls_.size())
        throw std::logic_error("History::add: " + std::to_string(wallForces.size()) +
                               " wall forces for " + std::to_string(walls_.size()) + " walls");
    if (energy.bodies.size() != bodies_.size())
        throw std::logic_error("History::add: the energy of " +
                               std::to_string(energy.bodies.size()) + " bodies for " +
                               std::to_string(bodies_.size()) + " bodies");
    const std::size_t bodies = bodies_.size();
    if (contactForces.size() != (contact_ ? bodies * bodies : 0))
        throw std::logic_error("History::add: " + std::to_string(contactForces.size()) +
                               " contact forces for " + std::to_string(bodies) + " bodies");
    const auto cell = [&](const char* format, double value) { table_.cell(format, value); };
    for (const HistoryColumn& c : kHistoryColumns) cell(c.format, c.value(state, energy));
    if (cohesive_) cell(kCohesiveColumn.format, kCohesiveColumn.value(state, energy));
    for (std::size_t w = 0; w < walls_.size(); ++w)
        for (const WallColumn& c : kWallColumns)
            cell(c.format, c.value(state, walls_[w], wallForces[w]));
    if (contact_)
        for (std::size_t i = 0; i < bodies; ++i)
            for (std::size_t j = i + 1; j < bodies; ++j)
                for (int d = 0; d < 3; ++d) cell("%.9e", contactForces[i * bodies + j][d]);
    for (const BodyEnergy& body : energy.bodies)
        for (const BodyColumn& c : kBodyColumns) cell(c.format, c.value(body));
    table_.endRow();
}

}  // namespace gsph::solver
