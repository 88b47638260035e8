// SPDX-License-Identifier: MIT
// history.csv of a run (docs/formats.md): rows at snapshots and history intervals, the columns
// defined in three lists in history.cpp — kHistoryColumns (the run's: clock, energy, momentum),
// kWallColumns (repeated for every wall, named wall_<name>_<suffix>) and kBodyColumns (repeated
// for every body, named body_<name>_<suffix>) — adding a column is one line there and one line
// in docs/formats.md. The whole table is rewritten atomically at every flush, and its text goes
// into checkpoints so that a restarted run writes the same file as an uninterrupted one.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "contact/walls.hpp"
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
    /// order, their columns after the run's. Throws InputError if two bodies' names make the
    /// same columns.
    History(std::filesystem::path path, const std::vector<std::string>& bodies,
            std::vector<Wall> walls);

    /// The column names, in the file's order.
    std::vector<std::string> columnNames() const;

    /// A row; `energy` has one entry per body (EnergyReport::bodies); `wallForces`: per wall,
    /// its force on the bodies (RigidWalls::totalForces; empty if the run has no walls).
    void add(const State& state, const EnergyReport& energy, const std::vector<Vec3>& wallForces);
    /// Header and rows so far (what a checkpoint stores).
    const std::string& text() const { return text_; }
    /// Replaces the table by one a checkpoint stored. Throws InputError if its header is not
    /// this run's.
    void restore(const std::string& text, const std::string& source);
    /// Writes the table to the path, atomically. Throws IoError on failure.
    void flush() const;

  private:
    std::string header() const;

    std::filesystem::path path_;
    std::vector<std::string> bodies_;  ///< column-safe names, in body order
    std::vector<Wall> walls_;
    std::string text_;
};

}  // namespace gsph::solver
