// SPDX-License-Identifier: MIT
// run.log of gsph-solve: every line is printed on stdout and kept; flush() rewrites
// RUNDIR/run.log atomically (after every snapshot and checkpoint, and at the end), so the log
// of a run that is killed still tells how far it got. A restart keeps the earlier lines. A run
// refused before its first snapshot writes no log.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace gsph::solver {

class RunLog {
  public:
    /// Called before a line is printed (the progress bar erases itself).
    std::function<void()> beforePrint;
    /// Keeps lines without printing them (the processes of a split run other than the first).
    bool quiet = false;

    void add(const std::string& line) {
        if (quiet) {
            lines_.push_back(line);
            return;
        }
        if (beforePrint) beforePrint();
        std::printf("%s\n", line.c_str());
        std::fflush(stdout);
        lines_.push_back(line);
    }
    /// A line for run.log only (not printed), e.g. the error main reports on stderr.
    void record(const std::string& line) { lines_.push_back(line); }

    /// Sets the file; with `keepExisting`, its current lines come first (a restart).
    void open(const std::filesystem::path& path, bool keepExisting) {
        path_ = path;
        if (!keepExisting) return;
        std::ifstream in(path);
        std::vector<std::string> earlier;
        for (std::string line; std::getline(in, line);) earlier.push_back(line);
        lines_.insert(lines_.begin(), earlier.begin(), earlier.end());
    }

    /// True once flush() wrote the file: the run started writing its folder (a run refused
    /// before that leaves no log behind).
    bool written() const { return written_; }

    /// Rewrites run.log. Throws IoError on failure.
    void flush() {
        if (path_.empty()) return;
        std::string text;
        for (const std::string& line : lines_) text.append(line).push_back('\n');
        writeTextAtomically(path_, text);
        written_ = true;
    }

  private:
    std::filesystem::path path_;
    std::vector<std::string> lines_;
    bool written_ = false;
};

}  // namespace gsph::solver
