// SPDX-License-Identifier: MIT
// A body of a run: its contiguous particle range (Reference invariant) and its material.
#pragma once

#include <vector>

#include "core/parallel.hpp"
#include "core/types.hpp"
#include "materials/material.hpp"

namespace gsph {

struct BodyRange {
    Index begin = 0, end = 0;
    const Material* material = nullptr;
};

}  // namespace gsph
