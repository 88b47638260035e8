// SPDX-License-Identifier: MIT
#include "forces/hourglass_diagnostic.hpp"

#include <cmath>

#include "core/parallel.hpp"

namespace gsph {

double hourglassError(const Reference& ref, const State& state) {
    const PairList& P = ref.pairs;
    struct Sums {
        double error = 0.0, weight = 0.0;
        Sums& operator+=(const Sums& o) {
            error += o.error;
            weight += o.weight;
            return *this;
        }
    };
    const Sums total = deterministicSum(ref.size(), Sums{}, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        Sums s;
        for (Index k = P.begin(a); k < P.end(a); ++k) {
            const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
            const double w =
                P.table[static_cast<std::size_t>(P.kernelId[static_cast<std::size_t>(k)])].W;
            const Vec3 Xab = ref.X[b] - ref.X[ia];
            const Vec3 e = state.x[b] - state.x[ia] - state.F[ia] * Xab;
            s.error += w * e.squaredNorm() / Xab.squaredNorm();
            s.weight += w;
        }
        return s;
    });
    return total.weight > 0.0 ? std::sqrt(total.error / total.weight) : 0.0;
}

}  // namespace gsph
