// SPDX-License-Identifier: MIT
// SIGINT/SIGTERM for gsph-solve: during set-up (reading, neighbour lists: nothing to save) a
// signal terminates at once (the default action); once stepping, the first signal only sets a
// flag (async-signal-safe), the step loop sees it after the current step, writes a checkpoint
// and a final snapshot and exits. A second signal terminates at once.
#pragma once

namespace gsph::solver {

/// Installs the handlers for SIGINT and SIGTERM.
void installStopHandlers();
/// From now on the first signal waits for the end of the current step.
void deferStopSignals();
/// The signal received (SIGINT, SIGTERM), or 0 if none.
int stopSignal();
/// "SIGINT", "SIGTERM" or "signal N".
const char* signalName(int signal);

}  // namespace gsph::solver
