// SPDX-License-Identifier: MIT
#include "signals.hpp"

#include <csignal>

namespace gsph::solver {
namespace {

volatile std::sig_atomic_t received = 0;
volatile std::sig_atomic_t deferred = 0;

void onStopSignal(int signal) {
    if (received != 0 || deferred == 0) {
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
    }
    received = signal;
}

}  // namespace

void installStopHandlers() {
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
}

void deferStopSignals() {
    deferred = 1;
}

int stopSignal() {
    return received;
}

const char* signalName(int signal) {
    if (signal == SIGINT) return "SIGINT";
    if (signal == SIGTERM) return "SIGTERM";
    return "a signal";
}

}  // namespace gsph::solver
