// SPDX-License-Identifier: MIT
// Integer maps between lattice frames (DESIGN §2): a block's (i,j,k) frame and its space's frame
// differ by a signed permutation of the axes and a shift. Node coordinates map as x' = R x + t;
// a cell with lower corner c (its centre c + ½) maps to the cell with lower corner
// R(c + ½) + t − ½, computed exactly in doubled integers.
//
// Invariants: R is a signed permutation ((R x)_d = sign[d]·x[perm[d]]); rotations (det +1) keep
// a right-handed frame right-handed; compose/inverse are exact.
#pragma once

#include <array>
#include <vector>

namespace gsph::preproc {

using Int3 = std::array<int, 3>;

struct SignedPermutation {
    Int3 perm = {0, 1, 2};
    Int3 sign = {1, 1, 1};

    Int3 apply(const Int3& x) const {
        return {sign[0] * x[perm[0]], sign[1] * x[perm[1]], sign[2] * x[perm[2]]};
    }
    int determinant() const {
        // Parity of the permutation times the product of the signs.
        const int inversions = (perm[0] > perm[1]) + (perm[0] > perm[2]) + (perm[1] > perm[2]);
        return (inversions % 2 == 0 ? 1 : -1) * sign[0] * sign[1] * sign[2];
    }
    /// (this ∘ other)(x) = this(other(x)).
    SignedPermutation after(const SignedPermutation& other) const {
        SignedPermutation r;
        for (int d = 0; d < 3; ++d) {
            r.perm[d] = other.perm[perm[d]];
            r.sign[d] = sign[d] * other.sign[perm[d]];
        }
        return r;
    }
    SignedPermutation inverse() const {
        SignedPermutation r;
        for (int d = 0; d < 3; ++d) {
            r.perm[perm[d]] = d;
            r.sign[perm[d]] = sign[d];
        }
        return r;
    }
    bool operator==(const SignedPermutation&) const = default;

    /// The 24 rotations (det +1), identity first, in a fixed order.
    static const std::vector<SignedPermutation>& rotations() {
        static const std::vector<SignedPermutation> all = [] {
            std::vector<SignedPermutation> out;
            const Int3 perms[6] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                   {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
            for (const Int3& p : perms) {
                for (int s = 0; s < 8; ++s) {
                    SignedPermutation r{p, {(s & 1) ? -1 : 1, (s & 2) ? -1 : 1, (s & 4) ? -1 : 1}};
                    if (r.determinant() == 1) out.push_back(r);
                }
            }
            return out;
        }();
        return all;
    }
};

/// x' = R x + t on node coordinates.
struct LatticeTransform {
    SignedPermutation R;
    Int3 t = {0, 0, 0};

    Int3 node(const Int3& x) const {
        Int3 y = R.apply(x);
        for (int d = 0; d < 3; ++d) y[d] += t[d];
        return y;
    }
    /// The image of the cell whose lower corner is c.
    Int3 cell(const Int3& c) const {
        const Int3 twice = R.apply({2 * c[0] + 1, 2 * c[1] + 1, 2 * c[2] + 1});
        return {(twice[0] - 1) / 2 + t[0], (twice[1] - 1) / 2 + t[1], (twice[2] - 1) / 2 + t[2]};
    }
    /// (this ∘ other)(x) = this(other(x)).
    LatticeTransform after(const LatticeTransform& other) const {
        LatticeTransform r;
        r.R = R.after(other.R);
        r.t = node(other.t);
        return r;
    }
    LatticeTransform inverse() const {
        LatticeTransform r;
        r.R = R.inverse();
        const Int3 rt = r.R.apply(t);
        r.t = {-rt[0], -rt[1], -rt[2]};
        return r;
    }
    bool operator==(const LatticeTransform&) const = default;
};

}  // namespace gsph::preproc
