// SPDX-License-Identifier: MIT
// The progress of gsph-solve: simulated time / end time, steps per second, particle-steps per
// second and the estimated wall time left. On a terminal, a bar redrawn at most 5 times a
// second on one line of stdout, never wider than the terminal (it shortens, then drops its
// rates, so it never wraps); elsewhere (a pipe, a batch job's log), one plain line every
// `lineInterval` seconds of wall time. The ETA comes from the rate of simulated time over the
// last 10 s of wall time (the time step shrinks after an impact: the run's mean rate would
// promise too much). Rates count only this invocation's steps, so they stay right after a
// restart. Before the first step it can show a set-up stage's progress instead (status).
#pragma once

#include <array>
#include <chrono>
#include <string>

namespace gsph::solver {

class ProgressBar {
  public:
    enum class Mode { Off, Bar, Lines };

    ProgressBar(Mode mode, double endTime, long particles, double lineInterval = 60.0);
    ~ProgressBar() { clear(); }
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    /// Where this invocation starts (t and step of the first state; a restart's are > 0).
    void start(double time, long step);
    /// Redraws the bar if 0.2 s have passed since the last draw (a line: `lineInterval`).
    void update(double time, long step);
    /// Shows `text` instead of the bar (a set-up stage's progress, before the first step; after
    /// start), at the bar's pace: redrawn at most 5 times a second on a terminal, a line every
    /// `lineInterval` elsewhere (none for a stage shorter than that).
    void status(const std::string& text);
    /// Erases the bar (before a log line is printed); the next update redraws it.
    void clear();

    /// The bar's text for a terminal of `columns` columns (at most columns − 1 characters).
    std::string barText(double time, double stepsPerSecond, double eta, int columns) const;
    /// Width of the terminal on stdout: its window size, else $COLUMNS, else 80.
    static int terminalColumns();

  private:
    double recentEta(double wall, double time);

    Mode mode_;
    double endTime_;
    long particles_;
    double lineInterval_;
    double startTime_ = 0.0;
    long startStep_ = 0;
    std::chrono::steady_clock::time_point wallStart_;
    double lastDraw_ = -1.0;
    bool drawn_ = false;
    // (wall, simulated time) at recent draws, a ring: the window of the ETA's rate.
    std::array<std::array<double, 2>, 64> samples_{};
    int sampleCount_ = 0, sampleNext_ = 0;
};

}  // namespace gsph::solver
