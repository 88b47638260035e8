// SPDX-License-Identifier: MIT
#include "core/lanes.hpp"

namespace gsph {
namespace {

bool processorHasWideLanes() {
#if defined(__x86_64__) || defined(__i386__)
    return __builtin_cpu_supports("avx2") != 0;
#else
    return false;
#endif
}

bool& portableLanesForced() {
    static bool forced = false;
    return forced;
}

}  // namespace

bool wideLanes() {
    static const bool available = processorHasWideLanes();
    return available && !portableLanesForced();
}

void usePortableLanes(bool portable) {
    portableLanesForced() = portable;
}

}  // namespace gsph
