// SPDX-License-Identifier: MIT
// history.csv of a run (docs/formats.md): one row per snapshot, the columns defined in one
// list (kHistoryColumns in history.cpp) — adding a column is one line there and one line in
// docs/formats.md. The whole table is rewritten atomically at every flush, and its text goes
// into checkpoints so that a restarted run writes the same file as an uninterrupted one.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "integrator/energy.hpp"
#include "particles/state.hpp"

namespace gsph::solver {

class History {
  public:
    explicit History(std::filesystem::path path);

    /// The column names, in the file's order.
    static std::vector<std::string> columnNames();

    void add(const State& state, const EnergyReport& energy);
    /// Header and rows so far (what a checkpoint stores).
    const std::string& text() const { return text_; }
    /// Replaces the table by one a checkpoint stored. Throws InputError if its header is not
    /// this build's.
    void restore(const std::string& text, const std::string& source);
    /// Writes the table to the path, atomically. Throws IoError on failure.
    void flush() const;

  private:
    std::filesystem::path path_;
    std::string text_;
};

}  // namespace gsph::solver
