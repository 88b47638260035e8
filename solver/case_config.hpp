// SPDX-License-Identifier: MIT
// The case file of gsph-solve (TOML; docs/case-format.md). Parsed into plain structs; every
// fault is an InputError "FILE:LINE: what" naming the key, so the user can fix it at once.
// Unknown keys are errors (a misspelt key must never be silently ignored).
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "core/types.hpp"
#include "forces/artificial_viscosity.hpp"
#include "forces/hourglass.hpp"
#include "io/particle_file.hpp"
#include "material_config.hpp"      // MaterialSpec: [[material]] tables and material files
#include "particles/reference.hpp"  // MassBasis

namespace gsph::solver {

struct BodySpec {
    std::string group;  ///< physical-group name in the particle file, or the body id as text
    std::string material;
    Vec3 velocity = Vec3::Zero();  ///< initial velocity [m/s]
    /// `failed_bonds`: "keep" (default), "either" or "both": a bond breaks once either or both
    /// of its particles have failed by Johnson–Cook damage; "cut": as "either", and also once
    /// its reference segment passes through a failed particle's cell (failure/brittle_bonds.hpp);
    /// not "keep" needs a johnson_cook material with damage.
    std::string failedBonds = "keep";
    int line = 0;
};

struct SetSpec {
    enum class Kind { Fixed, Velocity, Force, Pressure };
    std::string name;  ///< named particle set of the particle file
    Kind kind = Kind::Fixed;
    bool fixed = false;  ///< v = 0 on the held components
    /// The components `fixed` holds (x, y, z): all for `fixed = true`; those listed for
    /// `fixed = ["x", …]` (a symmetry plane or roller).
    std::array<bool, 3> holds = {true, true, true};
    Vec3 velocity = Vec3::Zero();  ///< prescribed velocity [m/s] (Kind::Velocity)
    Vec3 force = Vec3::Zero();     ///< total force on the set, shared by mass [N] (Kind::Force)
    /// (t [s], p [Pa]) points of the pressure on the set's faces (Kind::Pressure,
    /// libgsph/boundary/pressure.hpp); one point: constant.
    std::vector<std::pair<double, double>> pressure;
    int line = 0;
};

/// A rigid plane or cylinder (libgsph/contact/walls.hpp); a plane's normal points to the
/// bodies' side, a cylinder's bodies are outside it.
struct WallSpec {
    std::string name;
    bool cylinder = false;         ///< shape = "cylinder" (else "plane")
    Vec3 point = Vec3::Zero();     ///< a point of the plane or of the cylinder's axis [m]
    Vec3 normal = Vec3::UnitZ();   ///< plane: non-zero (normalised by the library)
    Vec3 axis = Vec3::UnitY();     ///< cylinder: non-zero (normalised by the library)
    double radius = 0.0;           ///< cylinder: R > 0 [m]
    Vec3 velocity = Vec3::Zero();  ///< [m/s]
    double friction = 0.0;         ///< Coulomb μ
    double rampTime = 0.0;         ///< [s] the speed rises linearly to `velocity` over it
    int line = 0;
};

/// [[precrack]]: an initial crack, the parallelogram corner + s·edge1 + t·edge2 (s, t ∈ [0, 1],
/// reference configuration): the bonds crossing it start broken (libgsph/failure/
/// brittle_bonds.hpp). Particles on its plane count on the side of edge1 × edge2.
struct PrecrackSpec {
    std::string name;
    Vec3 corner = Vec3::Zero();  ///< [m]
    Vec3 edge1 = Vec3::Zero();   ///< [m]
    Vec3 edge2 = Vec3::Zero();   ///< [m]
    int line = 0;
};

/// [[probe]]: a particle whose fields go to probes.csv at every history row (LS-DYNA's nodout):
/// the one given by index, or the one nearest to a point of the reference configuration
/// (among a body's particles if `body` is given; the lowest index on a tie).
struct ProbeSpec {
    std::string name;           ///< its columns are <name>_<field> (letters, digits, '_')
    bool atPoint = false;       ///< `point` given (else `particle`)
    Vec3 point = Vec3::Zero();  ///< [m], reference configuration
    long particle = -1;         ///< particle index in the particle file
    std::string body;           ///< physical group or body id to search ("": every body)
    int line = 0;
};

struct CaseConfig {
    std::filesystem::path caseFile;
    std::filesystem::path particles;  ///< resolved against the case file's folder
    int particlesLine = 0;            ///< where [run] particles is set (for messages)
    double endTime = 0.0;             ///< [s]
    double outputInterval = 0.0;      ///< [s]
    /// [s] between history.csv rows besides the snapshots' (default end_time / 400; 0: a row
    /// per snapshot only).
    double historyInterval = 0.0;
    double cfl = 0.3;
    double kappa = 1.2;
    /// [run] mass: "normalized" (ρ0 ω det M scaled per body to its meshed volume, default),
    /// "quadrature" (ρ0 ω det M) or "mesh" (ρ0 × the cell's meshed volume).
    MassBasis massBasis = MassBasis::NormalizedQuadratureVolume;
    /// [run] dimension: "3d", "plane_strain" or "axisymmetric"; empty: the particle file's
    /// (a 2-D file runs in plane strain). Checked against the file by the run.
    std::string dimension;
    int dimensionLine = 0;  ///< where it is set (for messages)
    ViscosityCoefficients viscosity = kDefaultViscosity;
    double hourglass = 0.1;
    /// [run] hourglass_modulus: "elastic" (default) or "secant" (forces/hourglass.hpp).
    HourglassModulus hourglassModulus = HourglassModulus::Elastic;
    /// [s] of simulated time between checkpoints (default: output_interval; 0 = only on a
    /// signal).
    double checkpointInterval = 0.0;
    /// A stable Δt below this fraction of the first Δt stops the run (0 = off).
    double minDtRatio = 1e-3;
    Vec3 gravity = Vec3::Zero();  ///< [run] gravity [m/s²]
    ContactOptions contact;       ///< [contact]: the penalty law (contact/penalty_contact.hpp)
    std::vector<WallSpec> walls;
    std::vector<MaterialSpec> materials;
    std::vector<BodySpec> bodies;
    std::vector<SetSpec> sets;
    std::vector<PrecrackSpec> precracks;
    std::vector<ProbeSpec> probes;
};

/// Whether `group` (a [[body]] group, a [[probe]] body) names body `id` of `file`: its physical
/// group's name, or its id as text.
bool namesBody(const std::string& group, const ParticleFile& file, std::size_t id);

/// Parses and validates a case file. Throws InputError "FILE:LINE: ..." on any fault.
CaseConfig readCaseFile(const std::filesystem::path& path);

/// The [run] mass key's word for a basis ("normalized", "quadrature", "mesh").
std::string massBasisKey(MassBasis basis);
/// The basis a [run] mass word names (none for another word).
std::optional<MassBasis> massBasisNamed(const std::string& key);

}  // namespace gsph::solver
