// SPDX-License-Identifier: MIT
// Checks every particle file from gsph-preproc must pass (DESIGN §2): particles sorted by body,
// then space, then lattice order (i fastest); θ = (i+½, j+½, k+½)·Δθ exactly, each lattice cell
// of a space used once.
#pragma once

#include <gtest/gtest.h>

#include "io/particle_file.hpp"

namespace gsph::test {

inline void expectLatticeLayout(const ParticleFile& f) {
    ASSERT_EQ(f.latticeIndex.size(), f.X.size());
    Index a = 0;
    for (std::size_t s = 0; s < f.spaces.size(); ++s) {
        const LatticeSpace& sp = f.spaces[s];
        ASSERT_EQ(sp.dtheta, 1.0);  // DESIGN §2: Δθ = 1, exactly
        const Index body = f.body[a];
        // Lattice order: particle a of the space is cell (i, j, k) with i fastest, so every
        // cell appears exactly once.
        for (int k = 0; k < sp.cells[2]; ++k) {
            for (int j = 0; j < sp.cells[1]; ++j) {
                for (int i = 0; i < sp.cells[0]; ++i, ++a) {
                    ASSERT_LT(a, f.size());
                    ASSERT_EQ(f.space[a], static_cast<Index>(s));
                    ASSERT_EQ(f.body[a], body) << "a space spans two bodies";
                    ASSERT_EQ(f.latticeIndex[a], (std::array<Index, 3>{i, j, k}));
                    // Integers + ½ times Δθ = 1 are exact in floating point; a 2-D file has
                    // θ_z = 0.
                    ASSERT_EQ(f.theta[a], Vec3(i + 0.5, j + 0.5, f.dimension == 2 ? 0.0 : k + 0.5));
                }
            }
        }
        if (a < f.size()) {
            ASSERT_GE(f.body[a], body) << "particles not sorted by body";
        }
    }
    ASSERT_EQ(a, f.size());
}

}  // namespace gsph::test
