// SPDX-License-Identifier: MIT
// The Domain of a run over MPI processes (MPI_COMM_WORLD; built with GSPH_MPI only). The split
// and the ghosts are distributed/halo_plan.hpp's; each exchange sends every peer its ghosts'
// columns in one message (nonblocking, all peers at once). Sums gather every process's partial
// sums and add them in process order, so every process gets the same bits on every run.
// The caller initialises MPI (MPI_THREAD_FUNNELED: only the main thread calls it) and
// finalises it after the last Domain call.
#pragma once

#include <memory>

#include "distributed/domain.hpp"

namespace gsph {

std::shared_ptr<Domain> makeMpiDomain();

}  // namespace gsph
