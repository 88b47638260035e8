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

/// Σ over the body's particles of term(a), a the particle index, in deterministicSum's fixed
/// order; `partial` is its scratch.
template <class T, class Term>
T sumOverBody(const BodyRange& body, T zero, Term&& term, std::vector<T>& partial) {
    return deterministicSum(ParticleRange{body.begin, body.end}, zero, std::forward<Term>(term),
                            partial);
}

}  // namespace gsph
