// SPDX-License-Identifier: MIT
#include "integrator/stress_update.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "core/error.hpp"
#include "core/lanes.hpp"
#include "core/parallel.hpp"
#include "core/strip_mat3.hpp"
#include "forces/hourglass.hpp"
#include "kinematics/deformation_gradient.hpp"
#include "materials/stress_measures.hpp"
#include "particles/axisymmetry.hpp"

namespace gsph {
namespace {

enum class Failure : std::uint8_t { None, Inverted, NotFinite };

// What steps 3–4 read and write, shared by the per-block functions below.
struct KinematicsStep {
    const Reference& ref;
    State& state;
    StressFactors& factors;
    ParticleFields& fields;
    std::vector<double>& lengthScale;
    std::vector<std::uint8_t>& failure;
    std::vector<double>& damageDissipation;
    std::vector<double>& fractureEnergy;
    const std::vector<double>& averagedDriver;  // ω̄ of nonlocal damage (empty: none)
    double dt;
    bool atRest;  // only derive the factors from the current F and σ (initialisation)
    Mat3 outOfPlane;
    bool axisymmetric;  // F_zz is the hoop stretch (particles/axisymmetry.hpp)
    const BrittleBonds& bonds;
    const Mat3* G;  // per particle: the reference's, or recomputed over surviving bonds
    const ViscosityCoefficients& viscosity;
    bool plasticHourglass;      // s_a of forces/hourglass.hpp from the plastic strain (else 1)
    const PairFieldRows& rows;  // x and v of the CSR blocks' far ends (refreshMotionRows)
};

// Lower bound of the smallest stretch σ_min(F) = 1/‖F^{-1}‖₂ ≥ 1/√(‖F^{-1}‖₁‖F^{-1}‖∞):
// exact for diagonal F, cheap, and conservative for the time step. With F^{-1} = (cof F)^T/J:
// ‖F^{-1}‖₁‖F^{-1}‖∞ = ‖cof F‖∞‖cof F‖₁/J².
template <class T>
[[gnu::always_inline]] inline T smallestStretchBound(const StripMat3<T>& cof, const T& J) {
    T colSum[3], rowSum[3];
    for (int k = 0; k < 3; ++k) {
        colSum[k] = absOf(cof(0, k)) + absOf(cof(1, k)) + absOf(cof(2, k));
        rowSum[k] = absOf(cof(k, 0)) + absOf(cof(k, 1)) + absOf(cof(k, 2));
    }
    const T norm1 = maxOf(maxOf(colSum[0], colSum[1]), colSum[2]);
    const T normInf = maxOf(maxOf(rowSum[0], rowSum[1]), rowSum[2]);
    return J / sqrtOf(norm1 * normInf);
}

// The particles of a strip: lane j holds row i0 + j of a block (rows past the strip's n repeat
// its last row; they are computed and not stored). T: double (one particle) or a strip type.
template <class T>
struct StripParticles {
    static constexpr int kWidth = kLanesOf<T>;
    int n = 0;
    Index row[kWidth];
    std::size_t index[kWidth];
    bool skip[kWidth];  // detached: detachParticle takes it
    // Every lane a particle to store, lane j particle index[0] + j: per-particle arrays are
    // loaded and stored as whole strips.
    bool contiguous = false;

    StripParticles(const ParticleBlock& block, Index i0, int count, const BrittleBonds& bonds)
        : n(count) {
        bool anySkipped = false;
        for (int j = 0; j < kWidth; ++j) {
            row[j] = i0 + std::min(j, n - 1);
            const Index a = block.particle(row[j]);
            index[j] = static_cast<std::size_t>(a);
            skip[j] = j >= n || bonds.detached(a);
            anySkipped = anySkipped || skip[j];
        }
        contiguous = !anySkipped && (kWidth == 1 || block.stride == 1);
    }
    // The lanes of a per-particle array, or of a block's row-major array.
    [[gnu::always_inline]] T of(const double* perParticle) const {
        T v;
        if constexpr (std::is_arithmetic_v<T>)
            v = perParticle[index[0]];
        else if (contiguous)
            v = loadLanes<T>(perParticle + index[0]);
        else
            for (int j = 0; j < kWidth; ++j) v[j] = perParticle[index[j]];
        return v;
    }
    [[gnu::always_inline]] T of(const std::vector<double>& perParticle) const {
        return of(perParticle.data());
    }
    [[gnu::always_inline]] T ofRows(const double* rows) const {
        T v;
        if constexpr (std::is_arithmetic_v<T>)
            v = rows[row[0]];
        else if (n == kWidth)
            v = loadLanes<T>(rows + row[0]);
        else
            for (int j = 0; j < kWidth; ++j) v[j] = rows[row[j]];
        return v;
    }
    // Stores the lanes of the strip's rows (j < n) into a block's row-major array.
    [[gnu::always_inline]] void storeRows(double* rows, const T& v) const {
        if constexpr (std::is_arithmetic_v<T>)
            rows[row[0]] = v;
        else if (n == kWidth)
            storeLanes<T>(rows + row[0], v);
        else
            for (int j = 0; j < n; ++j) rows[row[j]] = v[j];
    }
    // Stores the lanes into a per-particle array (contiguous strips only).
    [[gnu::always_inline]] void store(double* perParticle, const T& v) const {
        if constexpr (std::is_arithmetic_v<T>)
            perParticle[index[0]] = v;
        else
            storeLanes<T>(perParticle + index[0], v);
    }
    [[gnu::always_inline]] void store(Mat3Field& field, const StripMat3<T>& m) const {
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) store(field.component(3 * r + c), m(r, c));
    }
    [[gnu::always_inline]] StripMat3<T> of(const Mat3* perParticle) const {
        const Mat3* m[kWidth];
        for (int j = 0; j < kWidth; ++j) m[j] = &perParticle[index[j]];
        return lanesOf<T>(m);
    }
    // A block's θ-gradients (BlockThetaGradients, component-major).
    [[gnu::always_inline]] StripMat3<T> of(const double (&g)[9][kMaxBlock]) const {
        StripMat3<T> m;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) m(r, c) = ofRows(g[3 * r + c]);
        return m;
    }
};

// Sets lane j of v (v itself for double).
template <class T>
[[gnu::always_inline]] inline void setLane(T& v, int j, double value) {
    if constexpr (std::is_arithmetic_v<T>)
        v = value;
    else
        v[j] = value;
}

// Whether a model's update runs across the lanes of a strip: the hypo-elastic one (no history,
// the Jaumann update alone); the others one particle at a time.
template <class Model>
inline constexpr bool kUpdatesInStrips = std::is_same_v<Model, HypoElastic>;

// J = det F as the factors below take it: from C = cof F's first column.
template <class T>
[[gnu::always_inline]] inline T factorsJ(const StripMat3<T>& F, const StripMat3<T>& C) {
    return F(0, 0) * C(0, 0) + F(1, 0) * C(1, 0) + F(2, 0) * C(2, 0);
}

// The factors the force loop reads, from F and σ at t_{n+1} (DESIGN §4):
// P = J σ F^{-T}; N = V J F^{-T} G = V (cof F) G, K = σ N = V P G; the density ρ0/J, the sound
// speed, the time step's length and the viscosity's switch from tr L. For the lanes of p not
// skipped; soundSpeedAt(ρ) gives the lanes' sound speed at the density ρ0/J (the hypo-elastic
// model's is a constant; a model with history takes its material point's).
template <class T, class SoundSpeed>
[[gnu::always_inline]] inline void storeFactors(double density0, KinematicsStep& s,
                                                const StripParticles<T>& p, const StripMat3<T>& F,
                                                const StripMat3<T>& cauchy, const T& trL,
                                                const SoundSpeed& soundSpeedAt) {
    const StripMat3<T> C = cofactor(F);
    const T J = factorsJ(F, C);
    const T density = density0 / J;
    const StripMat3<T> N = p.of(s.ref.quadVolume) * C * p.of(s.G);
    const StripMat3<T> K = cauchy * N;
    const T soundSpeed = soundSpeedAt(density);
    const T bound = smallestStretchBound(C, J);
    const T alpha = viscositySwitch(s.viscosity, p.of(s.ref.smoothingLength), trL, soundSpeed);
    if (p.contiguous) {
        // Whole strips where every lane is sound (J > 0, σ finite: σ − σ is 0).
        T finite = cauchy(0, 0) - cauchy(0, 0);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) finite = finite + (cauchy(r, c) - cauchy(r, c));
        bool sound = true;
        T stepFactor;
        for (int j = 0; j < p.kWidth; ++j) {
            sound = sound && laneOf(J, j) > 0.0 && laneOf(finite, j) == 0.0;
            setLane(stepFactor, j, s.bonds.stepFactor(static_cast<Index>(p.index[j])));
        }
        if (sound) {
            p.store(s.factors.N, N);
            p.store(s.factors.K, K);
            p.store(s.factors.density.data(), density);
            p.store(s.factors.soundSpeed.data(), soundSpeed);
            p.store(s.factors.viscositySwitch.data(), alpha);
            p.store(s.fields.F, F);
            // A particle whose surviving bonds raise its G stiffens its pair forces as ‖G‖²
            // (failure/brittle_bonds.hpp, stepFactor).
            p.store(s.lengthScale.data(), p.of(s.ref.spacing) * bound * stepFactor);
            for (int j = 0; j < p.kWidth; ++j)
                s.failure[p.index[j]] = static_cast<std::uint8_t>(Failure::None);
            return;
        }
    }
    for (int j = 0; j < p.kWidth; ++j) {
        if (p.skip[j]) continue;
        const std::size_t ia = p.index[j];
        const double Jj = laneOf(J, j);
        if (!(Jj > 0.0)) {
            s.failure[ia] = static_cast<std::uint8_t>(std::isfinite(Jj) ? Failure::Inverted
                                                                        : Failure::NotFinite);
            continue;
        }
        const Mat3 Nj = laneOf(N, j), Kj = laneOf(K, j), sigma = laneOf(cauchy, j);
        s.factors.N.set(ia, Nj);
        s.factors.K.set(ia, Kj);
        s.factors.density[ia] = laneOf(density, j);
        s.factors.soundSpeed[ia] = laneOf(soundSpeed, j);
        s.factors.viscositySwitch[ia] = laneOf(alpha, j);
        s.fields.F.set(ia, laneOf(F, j));
        s.lengthScale[ia] =
            s.ref.spacing[ia] * laneOf(bound, j) * s.bonds.stepFactor(static_cast<Index>(ia));
        s.failure[ia] =
            static_cast<std::uint8_t>(sigma.allFinite() ? Failure::None : Failure::NotFinite);
    }
}

// s_a of the hourglass penalty (forces/hourglass.hpp) from σ and ε̄p at t_{n+1}.
template <class Model>
void storeHourglassScale(const Model& model, KinematicsStep& s, std::size_t ia, const Mat3& cauchy,
                         double plasticStrain) {
    s.factors.hourglassScale[ia] =
        s.plasticHourglass && plasticStrain > 0.0
            ? hourglassPlasticScale(vonMises(cauchy), model.elastic().shearModulus(), plasticStrain)
            : 1.0;
}

// Step 3 for the particles of a strip from their θ-gradients (kinematics/deformation_gradient.hpp):
// F and L = Ḟ F_{n+½}^{-1} at t_{n+1}. Lanes marked skip are computed and not stored.
template <class T>
[[gnu::always_inline]] inline void stripKinematics(KinematicsStep& s, const StripParticles<T>& p,
                                                   const BlockThetaGradients& g, StripMat3<T>& F,
                                                   StripMat3<T>& L) {
    const StripMat3<T> G = p.of(s.G);
    const StripMat3<T> Fn = p.of(s.state.F.data());
    StripMat3<T> Fdot = p.of(g.v) * G.transpose();
    F = p.of(g.x) * G.transpose();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) F(r, c) = F(r, c) + s.outOfPlane(r, c);
    for (int j = 0; j < p.kWidth; ++j) {
        const std::size_t ia = p.index[j];
        if (s.axisymmetric) {
            setLane(Fdot(2, 2), j, hoopStretchRate(s.ref.X[ia], s.state.v[ia]));
            setLane(F(2, 2), j, hoopStretch(s.ref.X[ia], s.state.x[ia]));
        }
        // A particle that lost bonds in a body whose bonds break by damage integrates F in
        // time (failure/brittle_bonds.hpp, integratesF): F over the surviving bonds would jump.
        if (s.bonds.integratesF(static_cast<Index>(ia)))
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    setLane(F(r, c), j, laneOf(Fn(r, c), j) + s.dt * laneOf(Fdot(r, c), j));
    }
    L = Fdot * inverse(0.5 * (Fn + F));
}

// Steps 3–4 of the hypo-elastic model for a strip, every lane at once.
template <class T>
[[gnu::always_inline]] inline void advanceElasticStrip(const HypoElastic& model, KinematicsStep& s,
                                                       const StripParticles<T>& p,
                                                       const BlockThetaGradients& g) {
    StripMat3<T> F, L;
    stripKinematics(s, p, g, F, L);
    const StripMat3<T> D = 0.5 * (L + L.transpose());
    const StripMat3<T> W = 0.5 * (L - L.transpose());
    const StripMat3<T> cauchy =
        jaumannElasticUpdate(model.elastic(), p.of(s.state.cauchy.data()), D, W, s.dt);
    for (int j = 0; j < p.kWidth; ++j) {
        if (p.skip[j]) continue;
        s.state.F[p.index[j]] = laneOf(F, j);
        s.state.cauchy[p.index[j]] = laneOf(cauchy, j);
    }
    const double c = model.waveSpeed(MaterialPoint{});
    storeFactors(
        model.elastic().density, s, p, F, cauchy,
        L.trace(), [c](const T&) __attribute__((always_inline)) { return T{} + c; });
    for (int j = 0; j < p.kWidth; ++j)
        if (!p.skip[j]) storeHourglassScale(model, s, p.index[j], s.state.cauchy[p.index[j]], 0.0);
}

// A block's F, L and sound speed by row, between the stages of a model that updates one
// particle at a time (below).
// (J: det F for the material update; factorsDensity: ρ0/J as storeFactors takes it.)
struct BlockKinematics {
    double F[9][kMaxBlock], D[9][kMaxBlock], W[9][kMaxBlock];
    double J[kMaxBlock], factorsDensity[kMaxBlock], soundSpeed[kMaxBlock];
};

// Stage 1 for a strip: F, D, W and the two densities' J into the block's rows.
template <class T>
[[gnu::always_inline]] inline void kinematicsStrip(double density0, KinematicsStep& s,
                                                   const StripParticles<T>& p,
                                                   const BlockThetaGradients& g,
                                                   BlockKinematics& k) {
    StripMat3<T> F, L;
    stripKinematics(s, p, g, F, L);
    const StripMat3<T> D = 0.5 * (L + L.transpose());
    const StripMat3<T> W = 0.5 * (L - L.transpose());
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            p.storeRows(k.F[3 * r + c], F(r, c));
            p.storeRows(k.D[3 * r + c], D(r, c));
            p.storeRows(k.W[3 * r + c], W(r, c));
        }
    p.storeRows(k.J, determinant(F));
    p.storeRows(k.factorsDensity, density0 / factorsJ(F, cofactor(F)));
}

// Stage 3 for a strip: the force factors from F, σ_{n+1} and the sound speeds of stage 2.
template <class T>
[[gnu::always_inline]] inline void factorsStrip(double density0, KinematicsStep& s,
                                                const StripParticles<T>& p,
                                                const BlockKinematics& k) {
    StripMat3<T> F;
    for (int rc = 0; rc < 9; ++rc) F(rc / 3, rc % 3) = p.ofRows(k.F[rc]);
    // tr L = tr D: D's diagonal is L's (½ (l + l) is l exactly).
    const T trL = (p.ofRows(k.D[0]) + p.ofRows(k.D[4])) + p.ofRows(k.D[8]);
    const T soundSpeed = p.ofRows(k.soundSpeed);
    storeFactors(
        density0, s, p, F, p.of(s.state.cauchy.data()),
        trL, [&soundSpeed](const T&) __attribute__((always_inline)) { return soundSpeed; });
}

// Stage 2, one particle (row i of the block): the material update from D and W, σ_{n+1}, the
// history, and the sound speed at the density the factors take.
template <class Model>
void updateParticle(const Model& model, KinematicsStep& s, std::size_t ia, Index i,
                    BlockKinematics& k) {
    Mat3 F, D, W;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            F(r, c) = k.F[3 * r + c][i], D(r, c) = k.D[3 * r + c][i], W(r, c) = k.W[3 * r + c][i];
    const double J = k.J[i];
    MaterialPoint point;
    point.cauchy = s.state.cauchy[ia];
    point.density = model.elastic().density / J;
    if constexpr (kHasHistory<Model>) {
        loadHistory<Model>(s.state, ia, point);
        if (!s.averagedDriver.empty()) point.averagedDriver = s.averagedDriver[ia];
        point.size = s.ref.spacing[ia];
    }
    model.update(point, D, W, s.dt);
    if constexpr (kHasHistory<Model>) {
        storeHistory<Model>(point, ia, s.state);
        // Per current volume → per particle: V J (the particle's current volume).
        const double volume = s.ref.quadVolume[ia] * J;
        s.state.plasticWork[ia] += volume * point.plasticWork;
        s.damageDissipation[ia] = volume * point.damageDissipation;
    }
    s.state.F[ia] = F;
    s.state.cauchy[ia] = point.cauchy;
    point.density = k.factorsDensity[i];
    k.soundSpeed[i] = model.waveSpeed(point);
    storeHourglassScale(model, s, ia, point.cauchy, point.plasticStrain);
}

// fn(p) for the block's strips of type T in order.
template <class T, class Fn>
[[gnu::always_inline]] inline void forStrips(KinematicsStep& s, const ParticleBlock& block,
                                             const Fn& fn) {
    constexpr int width = kLanesOf<T>;
    for (Index i0 = 0; i0 < block.size(); i0 += width)
        fn(StripParticles<T>(block, i0, static_cast<int>(std::min<Index>(width, block.size() - i0)),
                             s.bonds));
    leaveLanes<T>();
}

// The strip loops, compiled for each width (the same bits at every width).
template <class T>
[[gnu::always_inline]] inline void elasticStrips(const HypoElastic& model, KinematicsStep& s,
                                                 const ParticleBlock& block,
                                                 const BlockThetaGradients& g) {
    forStrips<T>(
        s, block, [&](const StripParticles<T>& p) __attribute__((always_inline)) {
            advanceElasticStrip(model, s, p, g);
        });
}
template <class T>
[[gnu::always_inline]] inline void kinematicsStrips(double density0, KinematicsStep& s,
                                                    const ParticleBlock& block,
                                                    const BlockThetaGradients& g,
                                                    BlockKinematics& k) {
    forStrips<T>(
        s, block, [&](const StripParticles<T>& p) __attribute__((always_inline)) {
            kinematicsStrip(density0, s, p, g, k);
        });
}
template <class T>
[[gnu::always_inline]] inline void factorsStrips(double density0, KinematicsStep& s,
                                                 const ParticleBlock& block,
                                                 const BlockKinematics& k) {
    forStrips<T>(
        s, block, [&](const StripParticles<T>& p) __attribute__((always_inline)) {
            factorsStrip(density0, s, p, k);
        });
}

GSPH_AVX512_TARGET void avx512ElasticStrips(const HypoElastic& model, KinematicsStep& s,
                                            const ParticleBlock& block,
                                            const BlockThetaGradients& g) {
    elasticStrips<Lanes8>(model, s, block, g);
}
GSPH_AVX2_TARGET void avx2ElasticStrips(const HypoElastic& model, KinematicsStep& s,
                                        const ParticleBlock& block, const BlockThetaGradients& g) {
    elasticStrips<Lanes4>(model, s, block, g);
}
void sse2ElasticStrips(const HypoElastic& model, KinematicsStep& s, const ParticleBlock& block,
                       const BlockThetaGradients& g) {
    elasticStrips<Lanes2>(model, s, block, g);
}
GSPH_AVX512_TARGET void avx512KinematicsStrips(double density0, KinematicsStep& s,
                                               const ParticleBlock& block,
                                               const BlockThetaGradients& g, BlockKinematics& k) {
    kinematicsStrips<Lanes8>(density0, s, block, g, k);
}
GSPH_AVX2_TARGET void avx2KinematicsStrips(double density0, KinematicsStep& s,
                                           const ParticleBlock& block, const BlockThetaGradients& g,
                                           BlockKinematics& k) {
    kinematicsStrips<Lanes4>(density0, s, block, g, k);
}
void sse2KinematicsStrips(double density0, KinematicsStep& s, const ParticleBlock& block,
                          const BlockThetaGradients& g, BlockKinematics& k) {
    kinematicsStrips<Lanes2>(density0, s, block, g, k);
}
GSPH_AVX512_TARGET void avx512FactorsStrips(double density0, KinematicsStep& s,
                                            const ParticleBlock& block, const BlockKinematics& k) {
    factorsStrips<Lanes8>(density0, s, block, k);
}
GSPH_AVX2_TARGET void avx2FactorsStrips(double density0, KinematicsStep& s,
                                        const ParticleBlock& block, const BlockKinematics& k) {
    factorsStrips<Lanes4>(density0, s, block, k);
}
void sse2FactorsStrips(double density0, KinematicsStep& s, const ParticleBlock& block,
                       const BlockKinematics& k) {
    factorsStrips<Lanes2>(density0, s, block, k);
}

// Steps 3–4 for every particle of a block but the detached ones, the widest strips the
// processor has (the same bits at every width): the hypo-elastic model across lanes throughout;
// a model with history in three stages, F and L in strips, the material update one particle at
// a time (its return mapping branches per particle), the force factors in strips.
template <class Model>
void advanceBlock(const Model& model, KinematicsStep& s, const ParticleBlock& block,
                  const BlockThetaGradients& g) {
    if constexpr (kUpdatesInStrips<Model>) {
        widestVariant(avx512ElasticStrips, avx2ElasticStrips, sse2ElasticStrips)(model, s, block,
                                                                                 g);
    } else {
        const double density0 = model.elastic().density;
        BlockKinematics k;
        widestVariant(avx512KinematicsStrips, avx2KinematicsStrips, sse2KinematicsStrips)(
            density0, s, block, g, k);
        for (Index i = 0; i < block.size(); ++i) {
            const Index a = block.particle(i);
            if (!s.bonds.detached(a)) updateParticle(model, s, static_cast<std::size_t>(a), i, k);
        }
        widestVariant(avx512FactorsStrips, avx2FactorsStrips, sse2FactorsStrips)(density0, s, block,
                                                                                 k);
    }
}

// A detached particle (failure/brittle_bonds.hpp) keeps its last F and carries no stress; it
// still needs a sound speed and a length for the time step. The elastic energy its stress
// stored is released when σ is set to zero: V J (ψ(σ) − ψ(0)) at its kept F, booked as this
// step's fracture energy (zero on later steps, σ being zero then). The part ψ(0) of the kept F
// (the equation of state's compression energy of a Johnson–Cook particle, a function of J
// alone) stays in the elastic energy, constant from then on; booking all of ψ(σ) would book
// that part again on every step of a compressed detached particle.
template <class Model>
void detachParticle(const Model& model, KinematicsStep& s, std::size_t ia) {
    const double J = s.state.F[ia].determinant();
    MaterialPoint point;
    point.cauchy = s.state.cauchy[ia];
    point.density = model.elastic().density / J;
    if constexpr (kHasHistory<Model>) loadHistory<Model>(s.state, ia, point);
    const double stored = model.storedEnergyDensity(point);
    point.cauchy.setZero();
    s.fractureEnergy[ia] = s.ref.quadVolume[ia] * J * (stored - model.storedEnergyDensity(point));
    s.state.cauchy[ia].setZero();
    s.factors.N.set(ia, Mat3::Zero());
    s.factors.K.set(ia, Mat3::Zero());
    s.factors.density[ia] = point.density;
    s.factors.soundSpeed[ia] = model.waveSpeed(point);
    s.fields.F.set(ia, s.state.F[ia]);
    s.factors.viscositySwitch[ia] =
        viscositySwitch(s.viscosity, s.ref.smoothingLength[ia], 0.0, s.factors.soundSpeed[ia]);
    storeHourglassScale(model, s, ia, point.cauchy, point.plasticStrain);
    s.lengthScale[ia] = s.ref.spacing[ia];
    s.failure[ia] = 0;
    if (!s.damageDissipation.empty()) s.damageDissipation[ia] = 0.0;
}

template <class Model>
void updateBlock(const Model& model, KinematicsStep& s, const StencilBlocks& blocks,
                 const CsrPairWeights& staged, const ParticleBlock& block) {
    const BondView bonds = s.bonds.view(s.state);
    if (s.atRest) {
        for (Index i = 0; i < block.size(); ++i) {
            const Index a = block.particle(i);
            const auto ia = static_cast<std::size_t>(a);
            if (s.bonds.detached(a)) {
                detachParticle(model, s, ia);
                continue;
            }
            MaterialPoint point;
            point.cauchy = s.state.cauchy[ia];
            storeFactors(model.elastic().density, s, StripParticles<double>(block, i, 1, s.bonds),
                         stripOf(s.state.F[ia]), stripOf(point.cauchy), 0.0, [&](double density) {
                             point.density = density;
                             return model.waveSpeed(point);
                         });
            // A restart resumes with the scale its plastic strain gives.
            if (!s.state.plasticStrain.empty())
                storeHourglassScale(model, s, ia, point.cauchy, s.state.plasticStrain[ia]);
        }
    } else if (block.stencil != kNoStencil && bonds.allIntact(block.begin, block.end)) {
        BlockThetaGradients g;
        stencilThetaGradients(blocks.stencils[static_cast<std::size_t>(block.stencil)], block,
                              s.fields.x, s.fields.v, g);
        advanceBlock(model, s, block, g);
    } else {
        BlockThetaGradients g;
        csrThetaGradients(s.ref, &staged, bonds, block, s.fields.x, s.fields.v, g, &s.rows);
        advanceBlock(model, s, block, g);
        for (Index i = 0; i < block.size(); ++i)
            if (s.bonds.detached(block.particle(i)))
                detachParticle(model, s, static_cast<std::size_t>(block.particle(i)));
    }
}

}  // namespace

StressUpdate::StressUpdate(const Reference& ref, const std::vector<BodyRange>& bodies,
                           const BrittleBonds& bonds, const ViscosityCoefficients& viscosity,
                           HourglassModulus hourglass)
    : ref_(ref), bodies_(bodies), bonds_(bonds), viscosity_(viscosity), hourglass_(hourglass) {
    const auto n = static_cast<std::size_t>(ref.size());
    factors_.resize(n);
    fields_.resize(n);
    lengthScale_.assign(n, 0.0);
    failure_.assign(n, 0);
    for (std::size_t a = 0; a < n; ++a) fields_.X.set(a, ref.X[a]);
    for (const BodyRange& body : bodies_)
        blocks_.push_back(buildStencilBlocks(ref.pairs, body.begin, body.end, ref.oversetCoupled));
    staged_.resize(blocks_.size());
    for (std::size_t b = 0; b < blocks_.size(); ++b) stageRuns(b);
    for (const BodyRange& body : bodies_)
        if (tracksHistory(*body.material)) damageDissipation_.assign(n, 0.0);
    if (bonds_.enabled()) fractureEnergy_.assign(n, 0.0);
    for (const BodyRange& body : bodies_) {
        const JohnsonCookDamage* damage = damageModel(*body.material);
        nonlocal_.push_back(
            damage && damage->nonlocal()
                ? NonlocalAverage(ref.X, ref.quadVolume, body.begin, body.end, damage->length)
                : NonlocalAverage());
        if (damage && damage->nonlocal()) averagedDriver_.assign(n, 0.0);
    }
    owned_ = {0, ref.size()};
}

void StressUpdate::advance(State& state, double dt, bool atRest) {
    KinematicsStep s{ref_,
                     state,
                     factors_,
                     fields_,
                     lengthScale_,
                     failure_,
                     damageDissipation_,
                     fractureEnergy_,
                     averagedDriver_,
                     dt,
                     atRest,
                     ref_.dim.outOfPlane(),
                     ref_.dim.axisymmetric,
                     bonds_,
                     bonds_.G().data(),
                     viscosity_,
                     hourglass_ == HourglassModulus::Secant,
                     rows_};
    // The runs' far ends' x and v as rows, for the θ-gradients and then the force.
    for (const CsrPairWeights& staged : staged_)
        refreshMotionRows(rows_, fields_, staged, static_cast<std::size_t>(ref_.size()));
    // The nonlocal damage's averages of the drivers at t_n, before any particle updates its own.
    for (const NonlocalAverage& average : nonlocal_) {
        const Index begin = std::max(average.begin(), owned_.begin);
        const Index end = std::min(average.end(), owned_.end);
        if (!atRest && end > begin)
            parallelFor(end - begin, [&](std::ptrdiff_t i) {
                const Index a = begin + static_cast<Index>(i);
                averagedDriver_[static_cast<std::size_t>(a)] =
                    average.average(state.damageDriver, a);
            });
    }
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const StencilBlocks& blocks = blocks_[b];
        std::visit(
            [&](const auto& model) {
                parallelForBlocks(blocks.cost, [&](std::ptrdiff_t k) {
                    updateBlock(model, s, blocks, staged_[b],
                                blocks.blocks[static_cast<std::size_t>(k)]);
                });
            },
            *bodies_[b].material);
    }
    throwOnFailure(state);
}

void StressUpdate::stageRuns(std::size_t b) {
    staged_[b] = stageCsrPairs(ref_, blocks_[b]);
    refreshReferenceRows(rows_, fields_, staged_[b], static_cast<std::size_t>(ref_.size()));
}

void StressUpdate::throwOnFailure(const State& state) const {
    for (std::size_t a = 0; a < failure_.size(); ++a) {
        const auto f = static_cast<Failure>(failure_[a]);
        if (f == Failure::None) continue;
        const std::string what = f == Failure::Inverted
                                     ? "inverted particle (J ≤ 0)"
                                     : "non-finite deformation or stress (NaN/Inf)";
        throw NumericalError(
            what + ": " + describeParticle(ref_, static_cast<Index>(a), state.time),
            static_cast<long>(a), state.time);
    }
}

void StressUpdate::bookDissipation(State& state, ParticleRange owned, Domain& domain) {
    // Per body (and the fracture energy last), this process's share summed exactly, the shares
    // summed over the processes, and then booked in body order: the same bits on any number.
    dissipated_.assign(bodies_.size() + 1, ExactSum{});
    if (bonds_.enabled())
        dissipated_.back() =
            exactSum(owned, [&](Index a) { return fractureEnergy_[static_cast<std::size_t>(a)]; });
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        if (!tracksHistory(*bodies_[b].material)) continue;
        dissipated_[b] = exactSum(owned.within(bodies_[b].begin, bodies_[b].end), [&](Index a) {
            return damageDissipation_[static_cast<std::size_t>(a)];
        });
    }
    if (domain.processes() > 1) domain.sum(dissipated_);
    if (bonds_.enabled()) state.ledger.fractureEnergy += dissipated_.back().value();
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        if (tracksHistory(*bodies_[b].material))
            state.ledger.damageDissipation += dissipated_[b].value();
}

Reads StressUpdate::driverReads() const {
    return [this](Index a, std::vector<Index>& out) {
        for (const NonlocalAverage& average : nonlocal_)
            if (a >= average.begin() && a < average.end()) {
                const std::span<const Index> neighbors = average.neighbors(a);
                out.insert(out.end(), neighbors.begin(), neighbors.end());
            }
    };
}

void StressUpdate::restrictTo(ParticleRange owned) {
    owned_ = owned;
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        StencilBlocks& body = blocks_[b];
        StencilBlocks kept;
        kept.stencils = body.stencils;
        kept.cost.push_back(0);
        for (const ParticleBlock& whole : body.blocks) {
            // A strided block may be cut at the range's ends (distributed/halo_plan.hpp).
            const ParticleBlock block = whole.within(owned.begin, owned.end);
            if (block.size() == 0) continue;
            kept.blocks.push_back(block);
            kept.particles += block.size();
            kept.cost.push_back(kept.cost.back() + block.cost());
        }
        body = std::move(kept);
        stageRuns(b);
    }
}

}  // namespace gsph
