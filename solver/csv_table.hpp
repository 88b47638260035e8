// SPDX-License-Identifier: MIT
// A table a run writes as it goes (history.csv, probes.csv): a header of column names, rows
// appended cell by cell, the whole text rewritten atomically at every flush and stored in
// checkpoints, so that a restarted run writes the same file as an uninterrupted one.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gsph::solver {

class CsvTable {
  public:
    CsvTable(std::filesystem::path path, const std::vector<std::string>& columns);

    /// Appends a cell to the row being written (printf `format` of one double).
    void cell(const char* format, double value);
    /// Ends the row. Throws std::logic_error if it has not one cell per column.
    void endRow();

    /// Header and rows so far (what a checkpoint stores).
    const std::string& text() const { return text_; }
    /// Replaces the table by one a checkpoint stored. Throws InputError naming `source` if its
    /// header is not this table's.
    void restore(const std::string& text, const std::string& source);
    /// Writes the table to its path, atomically. Throws IoError on failure.
    void flush() const;

  private:
    std::filesystem::path path_;
    std::string header_;
    std::size_t columns_ = 0;
    std::size_t cells_ = 0;  ///< in the row being written
    std::string text_;
};

}  // namespace gsph::solver
