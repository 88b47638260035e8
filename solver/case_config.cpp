// SPDX-License-Identifier: MIT
#include "case_config.hpp"

#include <toml++/toml.h>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "history.hpp"  // columnName: each wall its own columns
#include "toml_keys.hpp"

namespace gsph::solver {
namespace {

// The [run] mass words in the order the case reader's error lists them.
constexpr MassBasis kMassBases[] = {MassBasis::NormalizedQuadratureVolume,
                                    MassBasis::QuadratureVolume, MassBasis::MeshVolume};

using Sign = TomlKeys::Sign;

const toml::array* arrayOfTables(const std::string& file, const toml::table& root,
                                 const std::string& key) {
    const toml::node* n = root.get(key);
    if (!n) return nullptr;
    const toml::array* arr = n->as_array();
    if (!arr || !arr->is_array_of_tables())
        throw InputError(file + ":" + std::to_string(n->source().begin.line) + ": '" + key +
                         "' must be written [[" + key + "]]");
    return arr;
}

void readRun(const std::string& file, const toml::table& root, CaseConfig& c) {
    const toml::table* run = root["run"].as_table();
    if (!run) throw InputError(file + ":1: missing table [run]");
    const TomlKeys r(
        file, *run, "[run]",
        {"particles", "end_time", "output_interval", "history_interval", "cfl", "kappa", "mass",
         "viscosity", "viscosity_switch", "hourglass", "hourglass_modulus", "checkpoint_interval",
         "min_dt_ratio", "gravity", "dimension"});
    c.particlesLine = run->get("particles")
                          ? static_cast<int>(run->get("particles")->source().begin.line)
                          : r.line();
    c.particles = r.text("particles");
    if (c.particles.is_relative()) c.particles = c.caseFile.parent_path() / c.particles;
    c.endTime = r.number("end_time", Sign::Positive);
    c.outputInterval = r.number("output_interval", c.endTime / 10.0, Sign::Positive);
    c.historyInterval = r.number("history_interval", c.endTime / 400.0, Sign::NonNegative);
    c.cfl = r.number("cfl", c.cfl, Sign::Positive);
    if (c.cfl > 1.0) r.fail("cfl", "'cfl' in [run] must be ≤ 1");
    c.kappa = r.number("kappa", c.kappa, Sign::Positive);
    std::vector<std::string> bases;
    for (MassBasis b : kMassBases) bases.push_back(massBasisKey(b));
    c.massBasis = *massBasisNamed(r.choice("mass", massBasisKey(c.massBasis), bases));
    c.dimension = r.choice("dimension", "", {"3d", "plane_strain", "axisymmetric"});
    c.dimensionLine = run->get("dimension")
                          ? static_cast<int>(run->get("dimension")->source().begin.line)
                          : r.line();
    if (r.has("viscosity")) {
        const std::vector<double> beta = r.numbers("viscosity", 2);
        if (beta[0] < 0.0 || beta[1] < 0.0) r.fail("viscosity", "'viscosity' in [run] must be ≥ 0");
        c.viscosity.linear = beta[0];
        c.viscosity.quadratic = beta[1];
    }
    c.viscosity.switchMach =
        r.number("viscosity_switch", c.viscosity.switchMach, Sign::NonNegative);
    c.hourglass = r.number("hourglass", c.hourglass, Sign::NonNegative);
    const std::string modulus = r.choice("hourglass_modulus", "elastic", {"elastic", "secant"});
    c.hourglassModulus =
        modulus == "elastic" ? HourglassModulus::Elastic : HourglassModulus::Secant;
    c.checkpointInterval = r.number("checkpoint_interval", c.outputInterval, Sign::NonNegative);
    c.minDtRatio = r.number("min_dt_ratio", c.minDtRatio, Sign::NonNegative);
    if (c.minDtRatio >= 1.0)
        r.fail("min_dt_ratio", "'min_dt_ratio' in [run] must be < 1 (0 = off)");
    if (r.has("gravity")) c.gravity = r.vector("gravity");
}

void readContact(const std::string& file, const toml::table& root, CaseConfig& c) {
    const toml::node* n = root.get("contact");
    if (!n) return;
    const toml::table* t = n->as_table();
    if (!t)
        throw InputError(file + ":" + std::to_string(n->source().begin.line) +
                         ": 'contact' must be a table [contact]");
    const TomlKeys r(file, *t, "[contact]",
                     {"between_bodies", "self_contact", "penalty", "distance"});
    c.contact.betweenBodies = r.flag("between_bodies", c.contact.betweenBodies);
    c.contact.selfContact = r.flag("self_contact", c.contact.selfContact);
    c.contact.penalty = r.number("penalty", c.contact.penalty, Sign::Positive);
    c.contact.distance = r.number("distance", c.contact.distance, Sign::Positive);
}

WallSpec readWall(const std::string& file, const toml::table& t, std::size_t index) {
    const TomlKeys r(file, t, "[[wall]]",
                     {"name", "shape", "point", "normal", "axis", "radius", "velocity", "friction",
                      "ramp_time"});
    WallSpec w;
    w.line = r.line();
    w.name = r.text("name", "wall " + std::to_string(index));
    const std::string shape = r.choice("shape", "plane", {"plane", "cylinder"});
    w.cylinder = shape == "cylinder";
    // The keys of the other shape are errors, not silently ignored.
    const std::vector<std::string> otherKeys = w.cylinder
                                                   ? std::vector<std::string>{"normal"}
                                                   : std::vector<std::string>{"axis", "radius"};
    for (const std::string& key : otherKeys)
        if (r.has(key))
            r.fail(key, "'" + key + "' in [[wall]] belongs to shape = \"" +
                            (w.cylinder ? "plane" : "cylinder") + "\"");
    if (!r.has("point")) r.fail("", "missing key 'point' in [[wall]]");
    w.point = r.vector("point");
    if (w.cylinder) {
        if (!r.has("axis")) r.fail("", "missing key 'axis' in [[wall]] (shape = \"cylinder\")");
        w.axis = r.vector("axis");
        if (w.axis.isZero(0.0)) r.fail("axis", "'axis' in [[wall]] must not be zero");
        w.radius = r.number("radius", Sign::Positive);
    } else {
        if (!r.has("normal")) r.fail("", "missing key 'normal' in [[wall]]");
        w.normal = r.vector("normal");
        if (w.normal.isZero(0.0)) r.fail("normal", "'normal' in [[wall]] must not be zero");
    }
    if (r.has("velocity")) w.velocity = r.vector("velocity");
    w.friction = r.number("friction", 0.0, Sign::NonNegative);
    w.rampTime = r.number("ramp_time", 0.0, Sign::NonNegative);
    return w;
}

SetSpec readSet(const std::string& file, const toml::table& t) {
    const TomlKeys r(file, t, "[[set]]", {"name", "fixed", "velocity", "force", "pressure"});
    SetSpec s;
    s.line = r.line();
    s.name = r.text("name");
    if (const auto axes = r.axes("fixed")) {
        s.fixed = true;
        s.holds = *axes;
    } else {
        s.fixed = r.flag("fixed", false);
    }
    if (r.has("force") && (s.fixed || r.has("velocity")))
        r.fail("force", "set '" + s.name +
                            "' has a 'force' and a kinematic condition (fixed or "
                            "velocity): give one of the three");
    if (r.has("pressure") && (s.fixed || r.has("velocity") || r.has("force")))
        r.fail("pressure", "set '" + s.name +
                               "' has a 'pressure' and another condition (fixed, velocity "
                               "or force): give one");
    if (r.has("velocity")) {
        if (s.fixed) r.fail("velocity", "set '" + s.name + "' is both fixed and given a velocity");
        s.kind = SetSpec::Kind::Velocity;
        s.velocity = r.vector("velocity");
    } else if (r.has("force")) {
        s.kind = SetSpec::Kind::Force;
        s.force = r.vector("force");
    } else if (r.has("pressure")) {
        s.kind = SetSpec::Kind::Pressure;
        s.pressure = r.curve("pressure");
    } else if (!s.fixed) {
        r.fail("", "set '" + s.name +
                       "' needs 'fixed = true', a 'velocity', a 'force' or a 'pressure'");
    }
    return s;
}

PrecrackSpec readPrecrack(const std::string& file, const toml::table& t, std::size_t index) {
    const TomlKeys r(file, t, "[[precrack]]", {"name", "corner", "edge1", "edge2"});
    PrecrackSpec p;
    p.line = r.line();
    p.name = r.text("name", "precrack " + std::to_string(index));
    for (const char* key : {"corner", "edge1", "edge2"})
        if (!r.has(key)) r.fail("", std::string("missing key '") + key + "' in [[precrack]]");
    p.corner = r.vector("corner");
    p.edge1 = r.vector("edge1");
    p.edge2 = r.vector("edge2");
    for (const char* key : {"edge1", "edge2"})
        if ((std::string(key) == "edge1" ? p.edge1 : p.edge2).isZero(0.0))
            r.fail(key, std::string("'") + key + "' in [[precrack]] must not be zero");
    // Parallel edges span no plane (relative to the edges' lengths, so units do not matter).
    if (p.edge1.cross(p.edge2).norm() <= 1e-9 * p.edge1.norm() * p.edge2.norm())
        r.fail("edge2", "'edge1' and 'edge2' in [[precrack]] '" + p.name +
                            "' are parallel: they must "
                            "span the crack's plane");
    return p;
}

ProbeSpec readProbe(const std::string& file, const toml::table& t) {
    const TomlKeys r(file, t, "[[probe]]", {"name", "point", "particle", "body"});
    ProbeSpec p;
    p.line = r.line();
    if (!r.has("name")) r.fail("", "missing key 'name' in [[probe]]");
    p.name = r.text("name", "");
    if (p.name.empty() || columnName(p.name) != p.name)
        r.fail("name", "[[probe]] name '" + p.name +
                           "' must be letters, digits and '_' (it names probes.csv columns)");
    if (r.has("point") == r.has("particle"))
        r.fail("", "[[probe]] '" + p.name + "' needs either 'point' or 'particle' (not both)");
    p.atPoint = r.has("point");
    if (p.atPoint) p.point = r.vector("point");
    p.particle = r.integer("particle", -1, 0);
    if (r.has("body")) {
        if (!p.atPoint)
            r.fail("body", "'body' in [[probe]] '" + p.name + "' only narrows a 'point' search");
        p.body = r.text("body", "");
    }
    return p;
}

}  // namespace

bool namesBody(const std::string& group, const ParticleFile& file, std::size_t id) {
    return group == file.bodies[id].name || group == std::to_string(id);
}

CaseConfig readCaseFile(const std::filesystem::path& path) {
    const std::string file = path.string();
    if (!std::filesystem::exists(path)) throw InputError(file + ": no such case file");
    const toml::table root = parseTomlFile(file);
    CaseConfig c;
    c.caseFile = path;
    for (const auto& [key, node] : root) {
        const std::string k(key.str());
        if (k != "run" && k != "material" && k != "body" && k != "set" && k != "wall" &&
            k != "contact" && k != "precrack" && k != "probe")
            throw InputError(file + ":" + std::to_string(node.source().begin.line) +
                             ": unknown table '" + k +
                             "' (expected [run], [contact], [[material]], [[body]], [[set]], "
                             "[[wall]], [[precrack]], [[probe]])");
    }
    readRun(file, root, c);
    readContact(file, root, c);
    if (const toml::array* walls = arrayOfTables(file, root, "wall"))
        for (const toml::node& n : *walls)
            c.walls.push_back(readWall(file, *n.as_table(), c.walls.size()));
    // Each wall has its own history.csv columns (wall_<name>_…).
    for (std::size_t i = 0; i < c.walls.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (columnName(c.walls[i].name) == columnName(c.walls[j].name))
                throw InputError(file + ":" + std::to_string(c.walls[i].line) + ": wall '" +
                                 c.walls[i].name + "' has the history columns of wall '" +
                                 c.walls[j].name + "' (line " + std::to_string(c.walls[j].line) +
                                 "): give the walls names that differ in letters or digits");

    if (const toml::array* materials = arrayOfTables(file, root, "material"))
        for (const toml::node& n : *materials) {
            MaterialSpec m = readMaterialTable(path, *n.as_table());
            for (const MaterialSpec& other : c.materials)
                if (other.name == m.name)
                    throw InputError(file + ":" + std::to_string(m.line) + ": material '" + m.name +
                                     "' is defined twice");
            c.materials.push_back(std::move(m));
        }
    if (c.materials.empty()) throw InputError(file + ": no [[material]] defined");

    if (const toml::array* bodies = arrayOfTables(file, root, "body"))
        for (const toml::node& n : *bodies) {
            const TomlKeys r(file, *n.as_table(), "[[body]]",
                             {"group", "material", "velocity", "failed_bonds"});
            BodySpec b;
            b.line = r.line();
            b.group = r.text("group");
            b.material = r.text("material");
            const MaterialSpec* material = nullptr;
            for (const MaterialSpec& m : c.materials)
                if (m.name == b.material) material = &m;
            if (material == nullptr)
                r.fail("material", "material '" + b.material + "' is not defined");
            if (r.has("velocity")) b.velocity = r.vector("velocity");
            b.failedBonds = r.text("failed_bonds", "keep");
            if (b.failedBonds != "keep" && b.failedBonds != "either" && b.failedBonds != "both" &&
                b.failedBonds != "cut")
                r.fail("failed_bonds",
                       "'failed_bonds' must be \"keep\", \"either\", \"both\" or \"cut\", got \"" +
                           b.failedBonds + "\"");
            if (b.failedBonds != "keep" && damageModel(*material->material) == nullptr)
                r.fail("failed_bonds",
                       "'failed_bonds' needs a plastic material with damage; material '" +
                           b.material + "' has none");
            for (const BodySpec& other : c.bodies)
                if (other.group == b.group)
                    r.fail("group", "[[body]] group '" + b.group +
                                        "' is given twice (also at line " +
                                        std::to_string(other.line) + ")");
            c.bodies.push_back(b);
        }
    if (c.bodies.empty()) throw InputError(file + ": no [[body]] defined");

    if (const toml::array* sets = arrayOfTables(file, root, "set"))
        for (const toml::node& n : *sets) {
            SetSpec s = readSet(file, *n.as_table());
            for (const SetSpec& other : c.sets)
                if (other.name == s.name)
                    throw InputError(file + ":" + std::to_string(s.line) + ": [[set]] '" + s.name +
                                     "' is given twice (also at line " +
                                     std::to_string(other.line) + "): one condition per set");
            c.sets.push_back(std::move(s));
        }
    if (const toml::array* cracks = arrayOfTables(file, root, "precrack"))
        for (const toml::node& n : *cracks)
            c.precracks.push_back(readPrecrack(file, *n.as_table(), c.precracks.size()));
    if (const toml::array* probes = arrayOfTables(file, root, "probe"))
        for (const toml::node& n : *probes) {
            ProbeSpec p = readProbe(file, *n.as_table());
            for (const ProbeSpec& other : c.probes)
                if (other.name == p.name)
                    throw InputError(file + ":" + std::to_string(p.line) + ": [[probe]] '" +
                                     p.name + "' is given twice (also at line " +
                                     std::to_string(other.line) + ")");
            c.probes.push_back(std::move(p));
        }
    return c;
}

std::optional<MassBasis> massBasisNamed(const std::string& key) {
    for (MassBasis b : kMassBases)
        if (key == massBasisKey(b)) return b;
    return std::nullopt;
}

std::string massBasisKey(MassBasis basis) {
    switch (basis) {
        case MassBasis::QuadratureVolume:
            return "quadrature";
        case MassBasis::MeshVolume:
            return "mesh";
        case MassBasis::NormalizedQuadratureVolume:
            break;
    }
    return "normalized";
}

}  // namespace gsph::solver
