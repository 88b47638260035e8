// SPDX-License-Identifier: MIT
// The progress bar of gsph-solve on a terminal: simulated time / end time, steps per second,
// particle-steps per second and the estimated wall time left, redrawn at most 5 times a
// second on one line of stdout. Disabled (draws nothing) when stdout is not a terminal. Rates
// and ETA count only this invocation's steps, so they stay right after a restart.
#pragma once

#include <chrono>

namespace gsph::solver {

class ProgressBar {
  public:
    /// `enabled` false: every call does nothing.
    ProgressBar(bool enabled, double endTime, long particles);
    ~ProgressBar() { clear(); }
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    /// Where this invocation starts (t and step of the first state; a restart's are > 0).
    void start(double time, long step);
    /// Redraws if 0.2 s have passed since the last draw.
    void update(double time, long step);
    /// Erases the bar (before a log line is printed); the next update redraws it.
    void clear();

  private:
    bool enabled_;
    double endTime_;
    long particles_;
    double startTime_ = 0.0;
    long startStep_ = 0;
    std::chrono::steady_clock::time_point wallStart_;
    double lastDraw_ = -1.0;
    bool drawn_ = false;
};

}  // namespace gsph::solver
