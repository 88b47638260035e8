// SPDX-License-Identifier: MIT
#include "core/lanes.hpp"

#include <algorithm>

namespace gsph {
namespace {

int processorLaneWidth() {
#if defined(__x86_64__) || defined(__i386__)
    if (__builtin_cpu_supports("avx512f")) return 8;
    if (__builtin_cpu_supports("avx2")) return 4;
#endif
    return 2;
}

int& laneLimit() {
    static int limit = 8;
    return limit;
}

}  // namespace

int laneWidth() {
    static const int available = processorLaneWidth();
    return std::min(available, laneLimit());
}

void limitLanes(int width) {
    laneLimit() = width;
}

}  // namespace gsph
