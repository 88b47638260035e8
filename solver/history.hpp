// SPDX-License-Identifier: MIT
// history.csv of a run (docs/formats.md): rows at snapshots and history intervals, the columns
// defined in lists in history.cpp — kHistoryColumns (the run's: clock, energy, momentum; with
// softening bonds kCohesiveColumn after them),
// kWallColumns (repeated for every wall, named wall_<name>_<suffix>), kContactColumns (for every
// pair of bodies in contact, contact_<name>_<name>_<suffix>) and kBodyColumns (repeated for every
// body, named body_<name>_<suffix>) — adding a column is one line there and one line in
// docs/formats.md. Written as a CsvTable (csv_table.hpp): rewritten atomically at every flush,
// its text in checkpoints.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "contact/walls.hpp"
#include "csv_table.hpp"
#include "integrator/energy.hpp"
#include "particles/state.hpp"

namespace gsph::solver {

/// A wall's or body's name as it appears in column names: letters, digits and '_' kept,
/// anything else (spaces, '-', non-ASCII bytes) replaced by '_'.
std::string columnName(const std::string& name);

class History {
  public:
    /// `bodies`: per body of the run (Simulation::bodies, in order), the name of its columns
    /// (its physical group's, or its id), which follow the walls'. `walls`: the run's walls, in
    /// order, their columns after the run's. `contactBetweenBodies`: the run has contact between
    /// its bodies (contactBetweenBodies, contact/contact_stages.hpp): a force column per pair of
    /// bodies, after the walls'. `softeningBonds`: some body's bonds soften (a fracture
    /// energy): their cohesive work follows the run's columns. Throws InputError if two bodies'
    /// names make the same columns.
    History(std::filesystem::path path, const std::vector<std::string>& bodies,
            std::vector<Wall> walls, bool contactBetweenBodies, bool softeningBonds = false);

    /// The column names, in the file's order.
    std::vector<std::string> columnNames() const;

    /// A row; `energy` has one entry per body (EnergyReport::bodies); `wallForces`: per wall,
    /// its force on the bodies (RigidWalls::totalForces; empty if the run has no walls);
    /// `contactForces`: per ordered pair of bodies, the force between them
    /// (Simulation::contactForces; empty without contact between bodies).
    void add(const State& state, const EnergyReport& energy, const std::vector<Vec3>& wallForces,
             const std::vector<Vec3>& contactForces);
    /// The table (its text, restore from a checkpoint, flush).
    CsvTable& table() { return table_; }
    const CsvTable& table() const { return table_; }

  private:
    std::vector<std::string> bodies_;  ///< column-safe names, in body order
    std::vector<Wall> walls_;
    bool contact_ = false;
    bool cohesive_ = false;
    CsvTable table_;
};

}  // namespace gsph::solver
