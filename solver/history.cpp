// SPDX-License-Identifier: MIT
#include "history.hpp"

#include <cstdio>
#include <fstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace gsph::solver {
namespace {

struct HistoryColumn {
    const char* name;
    const char* format;  ///< printf format of the value
    double (*value)(const State&, const EnergyReport&);
};

// The columns of history.csv, in order: the run's clock, the energy channels (the total is
// kinetic + internal + every dissipated/stored work − external work, conserved), momentum.
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

std::string header() {
    std::string line;
    for (const HistoryColumn& c : kHistoryColumns) {
        if (!line.empty()) line.push_back(',');
        line.append(c.name);
    }
    line.push_back('\n');
    return line;
}

}  // namespace

History::History(std::filesystem::path path) : path_(std::move(path)), text_(header()) {}

std::vector<std::string> History::columnNames() {
    std::vector<std::string> names;
    for (const HistoryColumn& c : kHistoryColumns) names.emplace_back(c.name);
    return names;
}

void History::add(const State& state, const EnergyReport& energy) {
    bool first = true;
    for (const HistoryColumn& c : kHistoryColumns) {
        char cell[64];
        std::snprintf(cell, sizeof cell, c.format, c.value(state, energy));
        if (!first) text_ += ',';
        text_ += cell;
        first = false;
    }
    text_ += '\n';
}

void History::restore(const std::string& text, const std::string& source) {
    if (text.compare(0, header().size(), header()) != 0)
        throw InputError(source + ": its history has other columns than this gsph-solve writes");
    text_ = text;
}

void History::flush() const {
    writeAtomically(path_, [&](const std::filesystem::path& temp) {
        std::ofstream out(temp);
        out << text_;
        if (!out.flush()) throw IoError(path_.string() + ": write failed (disk full?)");
    });
}

}  // namespace gsph::solver
