// SPDX-License-Identifier: MIT
#include "material_config.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>

#include "core/error.hpp"
#include "toml_keys.hpp"

namespace gsph::solver {
namespace {

using Sign = TomlKeys::Sign;
using Keys = std::vector<std::string>;

// Keys every model takes; `notes` and `sources` document a material (the library's files cite
// a source for every constant) and have no effect on the run.
const Keys kCommonKeys = {"model",        "density",         "youngs_modulus", "poisson_ratio",
                          "bond_stretch", "fracture_energy", "notes",          "sources"};
// The keys that regularize a Johnson–Cook damage (docs/materials.md): a choice of the model
// tied to the layout's cells, so a case may set them beside a material file's constants.
const Keys kRegularizationKeys = {"damage_length", "damage_size"};
// Keys of a plastic solid besides its strength model's: the parts it composes
// (libgsph/materials/plastic_solid.hpp).
const Keys kPlasticPartKeys = {"eos", "damage", kRegularizationKeys[0], kRegularizationKeys[1]};

JohnsonCookParams readJohnsonCook(const TomlKeys& keys, const std::string& where);
LinearHardeningParams readLinearHardening(const TomlKeys& keys, const std::string& where);

// A material model of `model = "NAME"`: its constants' keys and how it is built from them. A
// plastic model composes its strength with an equation of state (`eos`, kEquationsOfState) and
// an optional damage model (`damage`). The keys a material may have, and the hint for a key of
// another model, follow from these lists: adding a model is one entry here and its reader.
// The parts a model is built from, besides its own constants (read by `build`).
struct ModelParts {
    const TomlKeys& keys;
    std::string where;  ///< "[[material]]" or "material 'NAME'", for messages of its keys
    std::string name;   ///< the material's name
    ElasticConstants elastic;
    /// A plastic model's equation of state, built when called (its keys and checks then fail
    /// inside the model's `located`, as the model's own checks do).
    std::function<EquationOfState()> eos;
    std::optional<JohnsonCookDamage> damage;
};

// Builds a model from constants already read: an InputError of its checks (or of its equation
// of state's) names the material.
template <class Make>
Material located(const ModelParts& parts, Make&& make) {
    try {
        return make();
    } catch (const InputError& e) {
        parts.keys.fail("", std::string(e.what()) + " in material '" + parts.name + "'");
    }
}

struct ModelReader {
    const char* name;
    Keys keys;
    bool plastic;
    Material (*build)(const ModelParts& parts);
};

const ModelReader kModels[] = {
    {"elastic", {}, false, [](const ModelParts& p) -> Material { return HypoElastic(p.elastic); }},
    {"johnson_cook",
     {"yield_stress", "hardening_modulus", "hardening_exponent", "strain_rate_coefficient",
      "reference_strain_rate", "thermal_softening_exponent", "room_temperature",
      "melting_temperature", "specific_heat", "taylor_quinney", "strain_rate_form"},
     true,
     [](const ModelParts& p) {
         const JohnsonCookParams params = readJohnsonCook(p.keys, p.where);
         return located(p, [&] { return JohnsonCook(p.elastic, params, p.eos(), p.damage); });
     }},
    {"linear_hardening",
     {"yield_stress", "hardening_modulus", "room_temperature", "specific_heat", "taylor_quinney",
      "reference_strain_rate"},
     true,
     [](const ModelParts& p) {
         const LinearHardeningParams params = readLinearHardening(p.keys, p.where);
         return located(p, [&] { return LinearHardening(p.elastic, params, p.eos(), p.damage); });
     }},
};

// An equation of state of a plastic model, `eos = "NAME"` (libgsph/materials/eos.hpp).
struct EosReader {
    const char* name;
    Keys keys;
    EquationOfState (*build)(const TomlKeys& keys, const ElasticConstants& e);
};

const EosReader kEquationsOfState[] = {
    {"linear",
     {"bulk_modulus"},
     [](const TomlKeys& keys, const ElasticConstants& e) {
         return EquationOfState::linear(
             e.density, keys.number("bulk_modulus", e.bulkModulus(), Sign::Positive));
     }},
    {"mie_gruneisen",
     {"sound_speed", "hugoniot_slope", "gruneisen_gamma"},
     [](const TomlKeys& keys, const ElasticConstants& e) {
         return EquationOfState::mieGruneisen(e.density,
                                              {keys.number("sound_speed", Sign::Positive),
                                               keys.number("hugoniot_slope", Sign::NonNegative),
                                               keys.number("gruneisen_gamma", Sign::NonNegative)});
     }},
};

template <class Reader, std::size_t N>
std::string namesOf(const Reader (&readers)[N]) {
    std::string names;
    for (const Reader& r : readers) names += (names.empty() ? "" : ", ") + std::string(r.name);
    return names;
}

std::string shortNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

bool contains(const Keys& keys, const std::string& key) {
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

Keys operator+(Keys a, const Keys& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// Where a key that the chosen model or equation of state does not take belongs instead.
std::string belongsTo(const std::string& key) {
    std::string models;
    for (const ModelReader& m : kModels)
        if (contains(m.keys, key) || (m.plastic && contains(kPlasticPartKeys, key)))
            models += (models.empty() ? "\"" : " or \"") + std::string(m.name) + "\"";
    if (!models.empty()) return "(it belongs to model = " + models + ")";
    for (const EosReader& e : kEquationsOfState)
        if (contains(e.keys, key)) return "(it belongs to eos = \"" + std::string(e.name) + "\")";
    return "";
}

// `sources` is a table of citations, one per constant the material sets.
void checkSources(const TomlKeys& keys, const toml::table& table, const Keys& constants) {
    const toml::node* node = table.get("sources");
    if (!node) return;
    const toml::table* sources = node->as_table();
    if (!sources)
        keys.fail("sources", "'sources' must be a table: constant = \"where it comes from\"");
    for (const auto& [k, v] : *sources) {
        const std::string key(k.str());
        const std::optional<std::string> text = v.value<std::string>();
        if (!contains(constants, key) || !text || text->empty())
            throw InputError(keys.file() + ":" + std::to_string(v.source().begin.line) +
                             ": sources." + key +
                             " must cite a constant of this material "
                             "with a non-empty string");
    }
}

JohnsonCookParams readJohnsonCook(const TomlKeys& keys, const std::string& where) {
    JohnsonCookParams p;
    p.yieldStress = keys.number("yield_stress", Sign::NonNegative);
    p.hardeningModulus = keys.number("hardening_modulus", Sign::NonNegative);
    p.hardeningExponent = keys.number("hardening_exponent", Sign::Positive);
    p.strainRateCoefficient = keys.number("strain_rate_coefficient", Sign::NonNegative);
    p.referenceStrainRate = keys.number("reference_strain_rate", Sign::Positive);
    p.thermalSofteningExponent = keys.number("thermal_softening_exponent", Sign::Positive);
    p.roomTemperature = keys.number("room_temperature", p.roomTemperature, Sign::Positive);
    p.meltingTemperature = keys.number("melting_temperature", Sign::Positive);
    if (!(p.meltingTemperature > p.roomTemperature))
        keys.fail("melting_temperature", "'melting_temperature' in " + where +
                                             " must exceed room_temperature (" +
                                             shortNumber(p.roomTemperature) + " K)");
    p.specificHeat = keys.number("specific_heat", Sign::Positive);
    p.taylorQuinney = keys.number("taylor_quinney", p.taylorQuinney, Sign::NonNegative);
    if (p.taylorQuinney > 1.0)
        keys.fail("taylor_quinney", "'taylor_quinney' in " + where + " must lie in [0, 1]");
    const std::string form = keys.text("strain_rate_form", "log");
    if (form != "log" && form != "power")
        keys.fail("strain_rate_form", "'strain_rate_form' in " + where +
                                          " must be \"log\" (1 + C ln ε̇*) or \"power\" "
                                          "((1 + ε̇*)^C), got \"" +
                                          form + "\"");
    p.rateForm = form == "power" ? StrainRateForm::Power : StrainRateForm::Logarithmic;
    return p;
}

LinearHardeningParams readLinearHardening(const TomlKeys& keys, const std::string& where) {
    LinearHardeningParams p;
    p.yieldStress = keys.number("yield_stress", Sign::NonNegative);
    p.hardeningModulus = keys.number("hardening_modulus", Sign::NonNegative);
    p.roomTemperature = keys.number("room_temperature", p.roomTemperature, Sign::Positive);
    p.specificHeat = keys.number("specific_heat", p.specificHeat, Sign::NonNegative);
    p.taylorQuinney = keys.number("taylor_quinney", p.taylorQuinney, Sign::NonNegative);
    if (p.taylorQuinney > 1.0)
        keys.fail("taylor_quinney", "'taylor_quinney' in " + where + " must lie in [0, 1]");
    if (p.taylorQuinney > 0.0 && !(p.specificHeat > 0.0))
        keys.fail("specific_heat", "'taylor_quinney' > 0 in " + where +
                                       " heats the material: give specific_heat > 0");
    p.referenceStrainRate =
        keys.number("reference_strain_rate", p.referenceStrainRate, Sign::Positive);
    return p;
}

// Where a damage's regularization is read: the material's own keys, or a case's [[material]]
// keys that replace the file's (both keys, when the case names either).
struct RegularizationKeys {
    const TomlKeys* keys = nullptr;
    std::string where;
};

// The constants of one material, from an inline [[material]] table or a material file;
// `caseRegularization`: the [[material]] table that named the file, if it sets a regularization.
void readConstants(const TomlKeys& keys, const toml::table& table, const Keys& extraKeys,
                   const std::string& where, MaterialSpec& m,
                   const RegularizationKeys& caseRegularization = {}) {
    const RegularizationKeys regularization =
        caseRegularization.keys != nullptr ? caseRegularization : RegularizationKeys{&keys, where};
    const TomlKeys& reg = *regularization.keys;
    m.model = keys.text("model", "elastic");
    const ModelReader* model = nullptr;
    for (const ModelReader& candidate : kModels)
        if (m.model == candidate.name) model = &candidate;
    if (!model)
        keys.fail("model", "material model '" + m.model +
                               "' is not known (available: " + namesOf(kModels) + ")");
    const std::string eosName = model->plastic ? keys.text("eos", "linear") : "";
    const EosReader* eos = nullptr;
    for (const EosReader& candidate : kEquationsOfState)
        if (eosName == candidate.name) eos = &candidate;
    if (model->plastic && !eos)
        keys.fail("eos", "equation of state '" + eosName +
                             "' is not known (available: " + namesOf(kEquationsOfState) + ")");
    const Keys constants =
        kCommonKeys + model->keys + (model->plastic ? kPlasticPartKeys + eos->keys : Keys{});
    keys.rejectUnknown(constants + extraKeys, belongsTo);
    checkSources(keys, table, constants);
    if (keys.has("notes")) keys.text("notes", "");

    const double rho = keys.number("density", Sign::Positive);
    const double E = keys.number("youngs_modulus", Sign::Positive);
    const double nu = keys.number("poisson_ratio", Sign::Any);
    try {
        m.elastic = ElasticConstants(rho, E, nu);
    } catch (const InputError& e) {
        keys.fail("poisson_ratio", std::string(e.what()) + " in material '" + m.name + "'");
    }
    m.bondStretch = keys.number("bond_stretch", 0.0, Sign::NonNegative);
    m.fractureEnergy = keys.number("fracture_energy", 0.0, Sign::NonNegative);
    if (m.fractureEnergy > 0.0 && m.bondStretch == 0.0)
        keys.fail("fracture_energy", "'fracture_energy' in " + where +
                                         " needs 'bond_stretch' > 0: the stretch at which its "
                                         "bonds start to soften");
    ModelParts parts{keys, where, m.name, m.elastic, {}, std::nullopt};
    if (model->plastic) {
        if (keys.has("damage")) {
            const std::vector<double> d = keys.numbers("damage", 5);
            parts.damage = JohnsonCookDamage{{d[0], d[1], d[2], d[3], d[4]}};
            parts.damage->length = reg.number("damage_length", 0.0, Sign::NonNegative);
            parts.damage->referenceSize = reg.number("damage_size", 0.0, Sign::NonNegative);
            if (parts.damage->nonlocal() && parts.damage->referenceSize > 0.0)
                reg.fail("damage_size", "'damage_size' in " + regularization.where +
                                            " and 'damage_length' exclude each other (two "
                                            "regularizations of one damage)");
        } else {
            for (const std::string& key : kRegularizationKeys)
                if (reg.has(key))
                    reg.fail(key, "'" + key + "' in " + regularization.where +
                                      " needs 'damage' (the Johnson–Cook constants it "
                                      "regularizes)" +
                                      (&reg != &keys ? " in its file" : ""));
        }
        parts.eos = [&keys, eos, &m] { return eos->build(keys, m.elastic); };
    }
    if (!model->plastic && &reg != &keys)
        for (const std::string& key : kRegularizationKeys)
            if (reg.has(key))
                reg.fail(key, "'" + key + "' in " + regularization.where +
                                  " needs a Johnson–Cook damage; its file's model is '" + m.model +
                                  "'");
    m.material = model->build(parts);
}

MaterialSpec readMaterialFile(const std::filesystem::path& path,
                              const RegularizationKeys& caseRegularization) {
    const std::string file = path.string();
    if (!std::filesystem::is_regular_file(path)) throw InputError(file + ": no such material file");
    const toml::table root = parseTomlFile(file);
    MaterialSpec m;
    m.name = path.stem().string();
    m.file = path;
    m.line = 1;
    const std::string where = "material '" + m.name + "'";
    readConstants(TomlKeys(file, root, where), root, {}, where, m, caseRegularization);
    return m;
}

}  // namespace

std::filesystem::path materialLibraryFolder() {
    if (const char* env = std::getenv("GSPH_MATERIALS_DIR"); env && *env) return env;
    // Installed (cmake --install): PREFIX/bin/gsph-solve beside PREFIX/share/gsph/materials.
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const std::filesystem::path installed =
            exe.parent_path().parent_path() / "share" / "gsph" / "materials";
        if (std::filesystem::is_directory(installed, ec)) return installed;
    }
    return GSPH_MATERIALS_DIR;  // the source tree's library (a build tree)
}

std::filesystem::path resolveMaterialFile(const std::filesystem::path& caseFolder,
                                          const std::string& file,
                                          std::vector<std::filesystem::path>* tried) {
    namespace fs = std::filesystem;
    const fs::path given(file);
    std::vector<fs::path> candidates;
    if (given.is_absolute()) {
        candidates.push_back(given);
    } else {
        candidates.push_back(caseFolder / given);
        const fs::path library = materialLibraryFolder();
        candidates.push_back(library / given);
        if (!given.empty() && *given.begin() == "materials")
            candidates.push_back(library / given.lexically_relative("materials"));
    }
    for (const fs::path& c : candidates)
        if (fs::is_regular_file(c)) return c;
    if (tried) *tried = candidates;
    return {};
}

MaterialSpec readMaterialFile(const std::filesystem::path& path) {
    return readMaterialFile(path, RegularizationKeys{});
}

MaterialSpec readMaterialTable(const std::filesystem::path& caseFile, const toml::table& table) {
    const TomlKeys keys(caseFile.string(), table, "[[material]]");
    if (!keys.has("name")) keys.fail("", "missing key 'name' in [[material]]");
    MaterialSpec m;
    m.line = keys.line();
    m.name = keys.text("name", "");
    if (!keys.has("file")) {
        readConstants(keys, table, {"name"}, "[[material]]", m);
        return m;
    }
    keys.rejectUnknown(Keys{"name", "file"} + kRegularizationKeys, [](const std::string&) {
        return "(a [[material]] with 'file' takes every constant from that file; beside it only "
               "the damage's regularization, damage_length or damage_size)";
    });
    const std::string file = keys.text("file", "");
    std::vector<std::filesystem::path> tried;
    const std::filesystem::path path = resolveMaterialFile(caseFile.parent_path(), file, &tried);
    if (path.empty()) {
        std::string looked;
        for (const auto& t : tried) looked += (looked.empty() ? "" : ", ") + t.string();
        keys.fail("file", "material file '" + file + "' not found (looked for " + looked + ")");
    }
    bool regularized = false;
    for (const std::string& key : kRegularizationKeys) regularized = regularized || keys.has(key);
    MaterialSpec fromFile = readMaterialFile(
        path, regularized ? RegularizationKeys{&keys, "[[material]] '" + m.name + "'"}
                          : RegularizationKeys{});
    fromFile.name = m.name;
    fromFile.line = m.line;
    return fromFile;
}

}  // namespace gsph::solver
