// SPDX-License-Identifier: MIT
#include "progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace gsph::solver {
namespace {

constexpr double kEtaWindow = 10.0;  // [s] of wall time behind the ETA's rate

}  // namespace

ProgressBar::ProgressBar(Mode mode, double endTime, long particles, double lineInterval)
    : mode_(mode), endTime_(endTime), particles_(particles), lineInterval_(lineInterval) {}

void ProgressBar::start(double time, long step) {
    startTime_ = time;
    startStep_ = step;
    wallStart_ = std::chrono::steady_clock::now();
    lastDraw_ = mode_ == Mode::Lines ? 0.0 : -1.0;  // the first line after one interval
    sampleCount_ = sampleNext_ = 0;
}

int ProgressBar::terminalColumns() {
    winsize size{};
    if (::ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
    if (const char* columns = std::getenv("COLUMNS")) {
        const int n = std::atoi(columns);
        if (n > 0) return n;
    }
    return 80;
}

double ProgressBar::recentEta(double wall, double time) {
    // The rate since the oldest earlier draw within the window; failing that, since the latest
    // earlier draw (lines are drawn further apart than the window); failing that, since start.
    double fromWall = 0.0, fromTime = startTime_, latest = -1.0;
    bool inWindow = false;
    for (int k = 0; k < sampleCount_; ++k) {
        const auto& [w, t] = samples_[static_cast<std::size_t>(k)];
        if (wall - w <= kEtaWindow && (!inWindow || w < fromWall)) {
            inWindow = true;
            fromWall = w;
            fromTime = t;
        }
        if (!inWindow && w > latest) {
            latest = w;
            fromWall = w;
            fromTime = t;
        }
    }
    samples_[static_cast<std::size_t>(sampleNext_)] = {wall, time};
    sampleNext_ = (sampleNext_ + 1) % static_cast<int>(samples_.size());
    sampleCount_ = std::min(sampleCount_ + 1, static_cast<int>(samples_.size()));
    const double rate = (time - fromTime) / std::max(wall - fromWall, 1e-9);
    return rate > 0.0 ? (endTime_ - time) / rate : 0.0;
}

std::string ProgressBar::barText(double time, double stepsPerSecond, double eta,
                                 int columns) const {
    const double fraction = std::clamp(time / endTime_, 0.0, 1.0);
    char percent[16], clock[96], rates[96], etaText[32];
    std::snprintf(percent, sizeof percent, " %5.1f%%", 100.0 * fraction);
    std::snprintf(clock, sizeof clock, "  t = %.3e / %.3e s", time, endTime_);
    std::snprintf(rates, sizeof rates, "  %.0f steps/s  %.2e particle-steps/s", stepsPerSecond,
                  stepsPerSecond * static_cast<double>(particles_));
    std::snprintf(etaText, sizeof etaText, "  ETA %.0f s", eta);
    // The last column would wrap on some terminals. The percentage and the ETA always show;
    // the clock, then the rates, only where they fit beside a bar of at least 10.
    const int room = columns - 1;
    const auto width = [](const char* t) { return static_cast<int>(std::strlen(t)); };
    int used = width(percent) + width(etaText) + 12;
    const bool withClock = used + width(clock) <= room;
    used += withClock ? width(clock) : 0;
    const bool withRates = withClock && used + width(rates) <= room;
    std::string text(percent);
    if (withClock) text.append(clock);
    if (withRates) text.append(rates);
    text.append(etaText);
    const int barWidth = std::clamp(room - static_cast<int>(text.size()) - 2, 0, 30);
    std::string line;
    if (barWidth >= 5) {
        const int filled = static_cast<int>(fraction * barWidth);
        // (Appended piecewise: GCC 12 at -O3 gives a false -Wrestrict on "[" + std::string.)
        line.push_back('[');
        line.append(static_cast<std::size_t>(filled), '#');
        line.append(static_cast<std::size_t>(barWidth - filled), ' ');
        line.push_back(']');
    }
    line.append(text);
    if (static_cast<int>(line.size()) > room)
        line.resize(static_cast<std::size_t>(std::max(room, 0)));
    return line;
}

void ProgressBar::update(double time, long step) {
    if (mode_ == Mode::Off) return;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
    if (wall - lastDraw_ < (mode_ == Mode::Bar ? 0.2 : lineInterval_)) return;
    lastDraw_ = wall;
    const double stepsPerSecond = wall > 0.0 ? static_cast<double>(step - startStep_) / wall : 0.0;
    const double eta = recentEta(wall, time);
    if (mode_ == Mode::Lines) {
        std::printf(
            "progress: %5.1f %%, t = %.4e of %.4e s, step %ld, %.3e particle-steps/s, "
            "ETA %.0f s\n",
            100.0 * std::clamp(time / endTime_, 0.0, 1.0), time, endTime_, step,
            stepsPerSecond * static_cast<double>(particles_), eta);
        std::fflush(stdout);
        return;
    }
    std::printf("\r%s\033[K", barText(time, stepsPerSecond, eta, terminalColumns()).c_str());
    std::fflush(stdout);
    drawn_ = true;
}

void ProgressBar::status(const std::string& text) {
    if (mode_ == Mode::Off) return;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
    if (wall - lastDraw_ < (mode_ == Mode::Bar ? 0.2 : lineInterval_)) return;
    lastDraw_ = wall;
    if (mode_ == Mode::Lines) {
        std::printf("%s\n", text.c_str());
        std::fflush(stdout);
        return;
    }
    const auto room = static_cast<std::size_t>(std::max(terminalColumns() - 1, 0));
    std::printf("\r%s\033[K", text.substr(0, room).c_str());
    std::fflush(stdout);
    drawn_ = true;
}

void ProgressBar::clear() {
    if (mode_ != Mode::Bar || !drawn_) return;
    std::printf("\r\033[K");  // carriage return, erase to the end of the line
    std::fflush(stdout);
    drawn_ = false;
    lastDraw_ = -1.0;
}

}  // namespace gsph::solver
