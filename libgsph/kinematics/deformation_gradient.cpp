// SPDX-License-Identifier: MIT
#include "kinematics/deformation_gradient.hpp"

#include "core/parallel.hpp"

namespace gsph {

void deformationGradient(const Reference& ref, const std::vector<Vec3>& x, std::vector<Mat3>& F) {
    F.resize(x.size());
    const Mat3 outOfPlane = ref.dim.outOfPlane();
    parallelFor(ref.size(), [&](Index a) {
        Mat3 gradX, gradV;
        thetaGradients(ref, a, x.data(), x.data(), gradX, gradV);
        F[static_cast<std::size_t>(a)] =
            gradX * ref.G[static_cast<std::size_t>(a)].transpose() + outOfPlane;
    });
}

}  // namespace gsph
