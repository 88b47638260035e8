// SPDX-License-Identifier: MIT
// The material library (materials/*.toml), material files in case files, and
// `gsph-solve --material-point` as a user runs it: every library file parses and cites a source
// for every constant; a driven copper point follows the Johnson–Cook closed form through the
// CSV; bad material and path files get one-line FILE:LINE messages.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "case_config.hpp"
#include "core/error.hpp"
#include "support/csv.hpp"
#include "support/sample_run.hpp"
#include "tools/temp_dir.hpp"

namespace gsph {
namespace {

namespace fs = std::filesystem;
using test::readCsv;
using test::runCommand;
using test::TempDir;

const std::string kSolve = GSPH_SOLVE_EXE;
const fs::path kLibrary = test::kSourceDir / "materials";

void write(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
}

TEST(MaterialLibrary, EveryFileParsesAndCitesASourceForEveryConstant) {
    int files = 0;
    for (const auto& entry : fs::directory_iterator(kLibrary)) {
        if (entry.path().extension() != ".toml") continue;
        ++files;
        const solver::MaterialSpec m = solver::readMaterialFile(entry.path());
        ASSERT_TRUE(m.material.has_value()) << entry.path();
        const toml::table root = toml::parse_file(entry.path().string());
        const toml::table* sources = root["sources"].as_table();
        ASSERT_NE(sources, nullptr) << entry.path() << " has no [sources]";
        for (const auto& [key, node] : root) {
            const std::string k(key.str());
            if (k == "model" || k == "eos" || k == "notes" || k == "sources") continue;
            const std::optional<std::string> source = (*sources)[k].value<std::string>();
            EXPECT_TRUE(source && !source->empty()) << entry.path() << ": no source for " << k;
        }
    }
    EXPECT_EQ(files, 5) << "copper, Weldox 460E, Armco iron, 6061-T6, PMMA";
}

TEST(MaterialLibrary, FilesHoldTheIssueConstants) {
    const solver::MaterialSpec cu = solver::readMaterialFile(kLibrary / "ofhc_copper.toml");
    const auto& copper = std::get<JohnsonCook>(*cu.material);
    EXPECT_EQ(copper.strength().params().yieldStress, 90e6);
    EXPECT_EQ(copper.strength().params().hardeningModulus, 292e6);
    EXPECT_EQ(copper.strength().params().hardeningExponent, 0.31);
    EXPECT_EQ(copper.strength().params().strainRateCoefficient, 0.025);
    EXPECT_EQ(copper.strength().params().thermalSofteningExponent, 1.09);
    EXPECT_EQ(copper.strength().params().meltingTemperature, 1356.0);
    EXPECT_EQ(cu.elastic.density, 8960.0);
    EXPECT_EQ(cu.elastic.youngsModulus, 124e9);
    EXPECT_EQ(copper.eos().kind(), EquationOfState::Kind::MieGruneisen);

    const solver::MaterialSpec w = solver::readMaterialFile(kLibrary / "weldox_460e.toml");
    const auto& weldox = std::get<JohnsonCook>(*w.material);
    ASSERT_TRUE(weldox.damage().has_value());
    const std::array<double, 5> paper = {0.0705, 1.732, -0.54, -0.015, 0.0};
    EXPECT_EQ(weldox.damage()->D, paper);
    std::ifstream in(kLibrary / "weldox_460e.toml");
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(text.find("-0.0123"), std::string::npos) << "both D4 values are recorded";

    const solver::MaterialSpec pmma = solver::readMaterialFile(kLibrary / "pmma.toml");
    EXPECT_EQ(pmma.model, "elastic");
    EXPECT_EQ(pmma.bondStretch, 0.03);
}

TEST(MaterialLibrary, CaseFilesFindMaterialFilesNextToThemThenInTheLibrary) {
    TempDir dir;
    const std::string body =
        "[run]\nparticles = \"p.h5\"\nend_time = 1e-6\n\n[[material]]\nname = \"cu\"\nfile = "
        "\"FILE\"\n\n[[body]]\ngroup = \"0\"\nmaterial = \"cu\"\n";
    const auto caseWith = [&](const std::string& file) {
        std::string text = body;
        text.replace(text.find("FILE"), 4, file);
        write(dir / "case.toml", text);
        return solver::readCaseFile(dir / "case.toml");
    };
    for (const std::string file : {"materials/ofhc_copper.toml", "ofhc_copper.toml"}) {
        const solver::CaseConfig c = caseWith(file);
        EXPECT_EQ(c.materials[0].name, "cu");
        EXPECT_EQ(fs::canonical(c.materials[0].file), fs::canonical(kLibrary / "ofhc_copper.toml"));
    }
    // A file next to the case wins over the library.
    fs::create_directories(dir / "materials");
    fs::copy_file(kLibrary / "armco_iron.toml", dir / "materials/ofhc_copper.toml");
    EXPECT_EQ(fs::canonical(caseWith("materials/ofhc_copper.toml").materials[0].file),
              fs::canonical(dir / "materials/ofhc_copper.toml"));
}

// A case sets the damage's regularization beside a material file (a choice tied to its layout,
// not a constant of the material): it replaces the file's, both keys at once; nothing else may
// stand beside `file`, and a regularization without a Johnson–Cook damage names the case's line.
TEST(MaterialLibrary, CaseFilesSetTheDamageRegularizationBesideAMaterialFile) {
    TempDir dir;
    const auto caseWith = [&](const std::string& file, const std::string& extra) {
        write(dir / "case.toml",
              "[run]\nparticles = \"p.h5\"\nend_time = 1e-6\n\n[[material]]\n"
              "name = \"steel\"\nfile = \"" +
                  file + "\"\n" + extra + "\n[[body]]\ngroup = \"0\"\nmaterial = \"steel\"\n");
        return solver::readCaseFile(dir / "case.toml");
    };
    const auto damageOf = [](const solver::CaseConfig& c) {
        return damageModel(*c.materials[0].material);
    };
    const solver::CaseConfig plain = caseWith("materials/weldox_460e.toml", "");
    ASSERT_NE(damageOf(plain), nullptr);
    EXPECT_EQ(damageOf(plain)->length, 0.0);
    const solver::CaseConfig nonlocal =
        caseWith("materials/weldox_460e.toml", "damage_length = 2e-3\n");
    EXPECT_EQ(damageOf(nonlocal)->length, 2e-3);
    EXPECT_EQ(damageOf(nonlocal)->D, damageOf(plain)->D) << "the file's constants otherwise";
    // The case's replaces the file's: a file with ℓ, a case with the size scaling.
    std::string weldox(
        (std::istreambuf_iterator<char>(std::ifstream(kLibrary / "weldox_460e.toml").rdbuf())), {});
    weldox.insert(weldox.find("yield_stress"), "damage_length = 1.5e-3\n");
    write(dir / "weldox_nonlocal.toml", weldox);
    const solver::CaseConfig sized = caseWith("weldox_nonlocal.toml", "damage_size = 1e-3\n");
    EXPECT_EQ(damageOf(sized)->length, 0.0);
    EXPECT_EQ(damageOf(sized)->referenceSize, 1e-3);
    EXPECT_EQ(damageOf(caseWith("weldox_nonlocal.toml", ""))->length, 1.5e-3);
    const auto expectError = [&](const std::string& file, const std::string& extra,
                                 const std::string& what) {
        try {
            caseWith(file, extra);
            ADD_FAILURE() << "accepted: " << extra;
        } catch (const InputError& e) {
            const std::string msg = e.what();
            EXPECT_NE(msg.find((dir / "case.toml").string() + ":8:"), std::string::npos) << msg;
            EXPECT_NE(msg.find(what), std::string::npos) << msg;
        }
    };
    expectError("materials/weldox_460e.toml", "damage_length = -1e-3\n", "must be");
    expectError("materials/weldox_460e.toml", "yield_stress = 1e9\n", "unknown key 'yield_stress'");
    expectError("materials/ofhc_copper.toml", "damage_length = 1e-3\n",
                "'damage_length' in [[material]] 'steel' needs 'damage'");
    expectError("materials/pmma.toml", "damage_size = 1e-3\n",
                "needs a Johnson–Cook damage; its file's model is 'elastic'");
}

TEST(MaterialLibrary, BadMaterialFilesNameTheirLine) {
    TempDir dir;
    std::ifstream in(kLibrary / "ofhc_copper.toml");
    std::string copper((std::istreambuf_iterator<char>(in)), {});
    const auto expectError = [&](const std::string& text, const std::string& where,
                                 const std::string& what) {
        write(dir / "bad.toml", text);
        try {
            solver::readMaterialFile(dir / "bad.toml");
            ADD_FAILURE() << "accepted: " << what;
        } catch (const InputError& e) {
            const std::string msg = e.what();
            EXPECT_NE(msg.find((dir / "bad.toml").string() + ":" + where), std::string::npos)
                << msg;
            EXPECT_NE(msg.find(what), std::string::npos) << msg;
        }
    };
    std::string typo = copper;
    typo.replace(typo.find("yield_stress"), 12, "yeild_stress");
    expectError(typo, "8:", "unknown key 'yeild_stress' in material 'bad'");
    std::string negative = copper;
    negative.replace(negative.find("0.31 "), 4, "-0.3");
    expectError(negative, "10:", "'hardening_exponent' in material 'bad' must be > 0");
    std::string uncited = copper;
    const std::string cited = "\nspecific_heat = \"J";  // the source line, not the constant
    uncited.replace(uncited.find(cited), cited.size(), "\nspecfic_heat = \"J");
    expectError(uncited, "", "sources.specfic_heat must cite a constant of this material");
    // A nonlocal damage length needs the damage it averages, and must not be negative.
    std::string lengthAlone = copper;
    lengthAlone.insert(lengthAlone.find("yield_stress"), "damage_length = 1e-3\n");
    expectError(lengthAlone, "8:", "'damage_length' in material 'bad' needs 'damage'");
    std::ifstream weldoxIn(kLibrary / "weldox_460e.toml");
    std::string weldox((std::istreambuf_iterator<char>(weldoxIn)), {});
    weldox.insert(weldox.find("yield_stress"), "damage_length = 1.5e-3\n");
    write(dir / "nonlocal.toml", weldox);
    const solver::MaterialSpec nonlocal = solver::readMaterialFile(dir / "nonlocal.toml");
    ASSERT_TRUE(nonlocal.material);
    const JohnsonCookDamage* damage = damageModel(*nonlocal.material);
    ASSERT_NE(damage, nullptr);
    EXPECT_EQ(damage->length, 1.5e-3);
    weldox.replace(weldox.find("1.5e-3"), 6, "-1e-3");
    expectError(weldox, "8:", "'damage_length' in material 'bad' must be");
    // The size regularization: read, needs the damage, excludes the nonlocal average.
    std::string sized(
        (std::istreambuf_iterator<char>(std::ifstream(kLibrary / "weldox_460e.toml").rdbuf())), {});
    sized.insert(sized.find("yield_stress"), "damage_size = 1e-3\n");
    write(dir / "sized.toml", sized);
    const solver::MaterialSpec sizedSpec = solver::readMaterialFile(dir / "sized.toml");
    ASSERT_TRUE(sizedSpec.material);
    EXPECT_EQ(damageModel(*sizedSpec.material)->referenceSize, 1e-3);
    std::string sizeAlone = copper;
    sizeAlone.insert(sizeAlone.find("yield_stress"), "damage_size = 1e-3\n");
    expectError(sizeAlone, "8:", "'damage_size' in material 'bad' needs 'damage'");
    std::string both = sized;
    both.insert(both.find("yield_stress"), "damage_length = 1e-3\n");
    expectError(both,
                "8:", "'damage_size' in material 'bad' and 'damage_length' exclude each other");
}

TEST(MaterialPointCli, CopperInUniaxialStressFollowsTheClosedForm) {
    // materials/paths/uniaxial_stress_600K.toml: 1/s, from 600 K, adiabatic; σ_xx against
    // (A + B ε̄p^n)(1 − T*^m) at each row's ε̄p and T (rate term 1 at ε̇ = ε̇0), within 0.5 %.
    TempDir dir;
    const auto r =
        runCommand(kSolve + " --material-point " + (kLibrary / "ofhc_copper.toml").string() +
                   " --path " + (kLibrary / "paths/uniaxial_stress_600K.toml").string() + " -o " +
                   (dir / "cu.csv").string());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("101 rows"), std::string::npos) << r.out;
    std::vector<std::string> header;
    const auto rows = readCsv(dir / "cu.csv", header);
    const std::vector<std::string> expected = {
        "time",           "strain",      "sigma_xx", "sigma_yy",    "sigma_zz",
        "sigma_xy",       "sigma_yz",    "sigma_zx", "pressure",    "von_mises",
        "plastic_strain", "temperature", "damage",   "plastic_work"};
    ASSERT_EQ(header, expected);
    ASSERT_EQ(rows.size(), 101u);
    EXPECT_NEAR(rows.front()[11], 600.0, 1e-9);
    EXPECT_NEAR(rows.back()[1], 0.3, 1e-12);
    int checked = 0;
    for (const auto& row : rows) {
        if (row[10] < 0.02) continue;
        const double Tstar = (row[11] - 293.15) / (1356.0 - 293.15);
        const double sigma = (90e6 + 292e6 * std::pow(row[10], 0.31)) * (1 - std::pow(Tstar, 1.09));
        EXPECT_NEAR(row[2] / sigma, 1.0, 0.005) << "ε̄p " << row[10];
        EXPECT_LT(std::abs(row[3]), 1e-3 * row[2]) << "lateral stress vanishes";
        ++checked;
    }
    EXPECT_GT(checked, 90);
    EXPECT_GT(rows.back()[11], 600.0) << "adiabatic heating";
}

// A linear-hardening steel written as a user would (model = "linear_hardening", the Mie–
// Grüneisen equation of state composed with it) through the material-point driver: past yield
// σ_xx = σ0 + H ε̄p at each row's ε̄p (the return uses ε̄p of the increment before: within one
// increment's H Δε̄p, 20 % margin for the increments' spread), isothermal without χ. A Johnson–Cook
// key in it is refused with a hint.
TEST(MaterialPointCli, LinearHardeningSteelFollowsItsBilinearLine) {
    TempDir dir;
    const std::string steel =
        "model = \"linear_hardening\"\ndensity = 7850.0\nyoungs_modulus = 200.0e9\n"
        "poisson_ratio = 0.3\nyield_stress = 350.0e6\nhardening_modulus = 1.5e9\n"
        "eos = \"mie_gruneisen\"\nsound_speed = 4570.0\nhugoniot_slope = 1.49\n"
        "gruneisen_gamma = 1.93\n";
    write(dir / "steel.toml", steel);
    const solver::MaterialSpec spec = solver::readMaterialFile(dir / "steel.toml");
    const auto& model = std::get<LinearHardening>(*spec.material);
    EXPECT_EQ(model.strength().params().yieldStress, 350e6);
    EXPECT_EQ(model.strength().params().hardeningModulus, 1.5e9);
    EXPECT_EQ(model.eos().kind(), EquationOfState::Kind::MieGruneisen);
    const auto r = runCommand(kSolve + " --material-point " + (dir / "steel.toml").string() +
                              " --path " + (kLibrary / "paths/uniaxial_stress_1e3.toml").string() +
                              " -o " + (dir / "steel.csv").string());
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> header;
    const auto rows = readCsv(dir / "steel.csv", header);
    ASSERT_EQ(header[2], "sigma_xx");
    ASSERT_EQ(header[10], "plastic_strain");
    int checked = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        if (rows[i - 1][10] <= 0.0) continue;
        // Rows are 50 increments apart (output_every): one increment's Δε̄p is a 50th of theirs.
        const double increment = (rows[i][10] - rows[i - 1][10]) / 50.0;
        EXPECT_NEAR(rows[i][2], 350e6 + 1.5e9 * rows[i][10],
                    1.2 * 1.5e9 * increment + 1e-9 * rows[i][2])
            << "ε̄p " << rows[i][10];
        EXPECT_EQ(rows[i][11], 293.15) << "isothermal without taylor_quinney";
        ++checked;
    }
    EXPECT_GT(checked, 50);
    write(dir / "bad.toml", steel + "hardening_exponent = 0.3\n");
    try {
        solver::readMaterialFile(dir / "bad.toml");
        ADD_FAILURE() << "a Johnson–Cook key in a linear-hardening material was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "bad.toml:11: unknown key 'hardening_exponent' in material 'bad' (it "
                      "belongs to model = \"johnson_cook\")"),
                  std::string::npos)
            << e.what();
    }
}

TEST(MaterialPointCli, BadPathFilesGetOneLineMessages) {
    TempDir dir;
    const std::string material = (kLibrary / "ofhc_copper.toml").string();
    struct Bad {
        const char* name;
        const char* text;
        const char* message;
    };
    const std::vector<Bad> cases = {
        {"typo.toml", "loading = \"uniaxial_stress\"\nstrain_rate = 1.0\nfinal_strian = 0.1\n",
         "typo.toml:3: unknown key 'final_strian' in the path"},
        {"kind.toml", "loading = \"tension\"\nstrain_rate = 1.0\nfinal_strain = 0.1\n",
         "kind.toml:1: 'loading' must be"},
        {"sign.toml", "loading = \"simple_shear\"\nstrain_rate = 1.0\nfinal_strain = -0.1\n",
         "sign.toml:3: 'final_strain' must be non-zero, with the sign of strain_rate"},
        {"short.csv",
         "time,F_xx,F_xy,F_xz,F_yx,F_yy,F_yz,F_zx,F_zy,F_zz\n0,1,0,0,0,1,0,0,0,1\n1,1,0\n",
         "short.csv:3: expected 10 numbers"},
        {"start.csv", "0,2,0,0,0,1,0,0,0,1\n1,2,0,0,0,1,0,0,0,1\n",
         "start.csv: the first F of a path must be the identity"},
        {"path.txt", "loading = \"simple_shear\"\n", "a path file is .toml"},
    };
    for (const Bad& c : cases) {
        write(dir / c.name, c.text);
        const auto r = runCommand(kSolve + " --material-point " + material + " --path " +
                                  (dir / c.name).string());
        EXPECT_EQ(r.status, 1) << c.name;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.name << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.name << ": " << r.err;
        EXPECT_TRUE(r.out.empty()) << c.name;
    }
    // --path is required with --material-point, and a case file excludes it.
    EXPECT_NE(runCommand(kSolve + " --material-point " + material).status, 0);
    EXPECT_NE(runCommand(kSolve).status, 0);
}

}  // namespace
}  // namespace gsph
