// SPDX-License-Identifier: MIT
#include "progress.hpp"

#include <algorithm>
#include <cstdio>

namespace gsph::solver {

ProgressBar::ProgressBar(bool enabled, double endTime, long particles)
    : enabled_(enabled), endTime_(endTime), particles_(particles) {}

void ProgressBar::start(double time, long step) {
    startTime_ = time;
    startStep_ = step;
    wallStart_ = std::chrono::steady_clock::now();
    lastDraw_ = -1.0;
}

void ProgressBar::update(double time, long step) {
    if (!enabled_) return;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
    if (wall - lastDraw_ < 0.2) return;
    lastDraw_ = wall;
    constexpr int kWidth = 30;
    const double fraction = std::clamp(time / endTime_, 0.0, 1.0);
    const int filled = static_cast<int>(fraction * kWidth);
    const double stepsPerSecond = wall > 0.0 ? static_cast<double>(step - startStep_) / wall : 0.0;
    // ETA from this invocation's pace in simulated time.
    const double done = time - startTime_;
    const double eta = done > 0.0 ? wall * (endTime_ - time) / done : 0.0;
    std::printf(
        "\r[%.*s%*s] %5.1f%%  t = %.3e / %.3e s  %.0f steps/s  %.2e particle-steps/s  "
        "ETA %.0f s  ",
        filled, "##############################", kWidth - filled, "", 100.0 * fraction, time,
        endTime_, stepsPerSecond, stepsPerSecond * static_cast<double>(particles_), eta);
    std::fflush(stdout);
    drawn_ = true;
}

void ProgressBar::clear() {
    if (!enabled_ || !drawn_) return;
    std::printf("\r\033[K");  // carriage return, erase to the end of the line
    std::fflush(stdout);
    drawn_ = false;
    lastDraw_ = -1.0;
}

}  // namespace gsph::solver
