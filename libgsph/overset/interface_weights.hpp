// SPDX-License-Identifier: MIT
// Interface weights: a conservative and consistent coupling of overset spaces (DESIGN §6).
//
// The pairwise force of DESIGN §4 is the gradient of E = Σ_a V_a Ψ(F_a) with
// F_a = Σ_b (x_b − x_a) ⊗ γ_ab, γ_ab = G(a) w_ab (w_ab = ω_b ∇W_ab, the pair's table entry):
//     f_c = Σ_b V_c P_c γ_cb − Σ_{a: c ∈ N(a)} V_a P_a γ_ac,
// so it conserves linear momentum and energy on any set of pairs. Within one space its weights
// satisfy the discrete Piola identity (uniform stress ⇒ no interior force); across an overset
// interface the pair sets of the two spaces do not mirror each other and the identity fails by
// O(1/h): the interface acts like a crack.
//
// Instead of leaving the energy (a difference form), this keeps it and corrects the weights.
// On the pairs (a, b) with both particles in the interface band (overset/overset_band.hpp:
// within two coarse kernel supports of an interface) the weights become γ_ab + δγ_ab, with δγ
// the smallest correction (least squares over the pairs) such that
//   (1) Σ_b (X_b − X_a) ⊗ γ_ab = I              F exact for affine motion, F = I at rest,
//       at every band particle;
//   (2) V_c Σ_b γ_cb − Σ_a V_a γ_ac = 0         uniform stress: no force,
//   (3) Σ_a V_a (X_a − X_c) ⊗ γ_ac = −V_c I     linear stress: the force is V_c ∇·P,
//       at every band particle whose support does not reach a free face.
// (1) holds before the correction and is kept; (2) and (3) hold to round-off inside a space on
// the maps of DESIGN §7 and are imposed across the interface. Near a free face the Piola sum
// (2) is the face's traction, not zero: those particles take only (1), and with it whatever
// the interface leaves (Σ_c of (2) over all particles vanishes identically, so the band alone
// could not satisfy (2) everywhere). The correction is found once, in the reference
// configuration, by conjugate gradients on the normal equations of the constraints. The force
// stays the gradient of an energy: momentum and energy are conserved to round-off across the
// interface.
//
// Storage: per particle whose list holds a corrected pair (its own, or the mirror (b, a) of a
// same-space pair), the corrections of its whole list in θ units (δw_ab = G(a)^{-1} δγ_ab,
// added to the table's gradW) and those of the mirrors (Reference::correctionBegin).
#pragma once

#include <functional>

#include "particles/reference.hpp"

namespace gsph {

/// The interface weights' solve reporting its progress: called after each conjugate-gradient
/// iteration with its number and the relative residual (the solve stops below 1e-14), on the
/// calling thread. On a large band the solve is most of a run's set-up (docs/performance.md).
using InterfaceSolveProgress = std::function<void(int iteration, double relativeResidual)>;

/// Fills ref.correctionBegin, ref.pairCorrection and ref.mirrorCorrection (empty when there is
/// no band) and adds every particle with a corrected pair to ref.oversetCoupled (CSR path).
/// Needs ref.G, ref.quadVolume, ref.smoothingLength, ref.oversetBand (markOversetBand).
/// Throws NumericalError when the constraints cannot be met (a band without enough pairs).
void correctInterfaceWeights(Reference& ref, const InterfaceSolveProgress& progress = {});

}  // namespace gsph
