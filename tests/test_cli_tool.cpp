// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The pgloss tool (tools/), run in-process on a table of argument lists: its grammar of numbers,
// its messages on stderr, its exit codes, and the core's verdict as the status line. The
// expected values are the grammar and verdicts that tools/cli_common.h documents and eq. 5
// computed by hand; tests/python/test_cli.py runs the same kind of table through the built tool
// and `python -m pgloss`.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "cli_common.h"

namespace {

struct Result {
    int rc;
    std::string out, err;
};

std::string slurp(FILE *f) {
    std::string s;
    std::rewind(f);
    for (int ch; (ch = std::fgetc(f)) != EOF;) s += char(ch);
    std::fclose(f);
    return s;
}

Result run_tool(std::vector<std::string> args) {
    args.insert(args.begin(), "pgloss");
    std::vector<char *> argv;
    for (auto &a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    FILE *out = std::tmpfile(), *err = std::tmpfile();
    const int rc = pgloss_cli_main(int(args.size()), argv.data(), out, err);
    std::string o = slurp(out);
    return {rc, o, slurp(err)};
}

std::string joined(const std::vector<std::string> &args) {
    std::string s;
    for (const auto &a : args) s += (s.empty() ? "" : " ") + a;
    return s;
}

// A wrong argument: exit 2, the reason and the command's usage line on stderr, nothing on stdout.
void expect_usage_error(const std::vector<std::string> &args, const std::string &reason, const std::string &usage) {
    SCOPED_TRACE(joined(args));
    const Result r = run_tool(args);
    EXPECT_EQ(r.rc, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "pgloss " + args[0] + ": " + reason + "\nusage: pgloss " + usage + "\n");
}

const char *const DISTANCE = "distance c1 d1 c2 d2";

TEST(CliTool, NumbersOutOfRangeSaySo) {
    expect_usage_error({"distance", "1e400", "0.9", "0.1", "0.9"}, "c1: '1e400' is out of range (|x| > 1.8e308)",
                       DISTANCE);
    expect_usage_error({"distance", "0.1", "-1e309", "0.1", "0.9"}, "d1: '-1e309' is out of range (|x| > 1.8e308)",
                       DISTANCE);
    expect_usage_error({"distance", "0.1", "0.9", "1e-400", "0.9"},
                       "c2: '1e-400' is out of range (0 < |x| < 4.9e-324)", DISTANCE);
}

TEST(CliTool, SubnormalsAndZerosAreNumbers) {
    // 4.9e-324 is the smallest subnormal double; 2.2250738585072014e-308 the smallest normal.
    for (const char *tiny : {"4.9e-324", "-4.9e-324", "2.2250738585072014e-308", "0e999999", "-0", "0.000"}) {
        SCOPED_TRACE(tiny);
        const Result r = run_tool({"distance", tiny, "0.9", "0.1", "0.9"});
        const bool negative = tiny[0] == '-' && tiny[1] != '0';
        EXPECT_EQ(r.err, "");
        if (negative) {
            EXPECT_EQ(r.rc, 1);
            EXPECT_EQ(r.out.rfind("status: PGLOSS_ERR_NEGATIVE (", 0), 0u) << r.out;
        } else {
            EXPECT_EQ(r.rc, 0);
            EXPECT_EQ(r.out, "D = 0.100000\nstatus: ok\n");  // eq. 5: |0 - 0.1|
        }
    }
}

TEST(CliTool, OnlyDecimalAsciiNumbers) {
    expect_usage_error({"distance", "0x23", "0.9", "0.1", "0.9"}, "c1: '0x23' is not a decimal number", DISTANCE);
    expect_usage_error({"distance", "-0X1p3", "0.9", "0.1", "0.9"}, "c1: '-0X1p3' is not a decimal number", DISTANCE);
    for (const char *s : {"inf", "-inf", "+Infinity", "nan", "NaN", "-nan(1)"})
        expect_usage_error({"distance", "0.1", s, "0.1", "0.9"}, std::string("d1: '") + s + "' is not a finite number",
                           DISTANCE);
    // ARABIC-INDIC DIGIT ONE and FULLWIDTH DIGIT ONE, shown byte by byte.
    expect_usage_error({"distance", "0.1", "0.9", "\xd9\xa1", "0.9"},
                       "c2: '\\xd9\\xa1' is not a number (digits are ASCII 0-9)", DISTANCE);
    expect_usage_error({"distance", "0.1", "0.9", "\xef\xbc\x91", "0.9"},
                       "c2: '\\xef\\xbc\\x91' is not a number (digits are ASCII 0-9)", DISTANCE);
    for (const char *s : {"", " 1", "1 ", "1_0", ".", "e5", "1e", "1e+", "+", "1.2.3", "--1", "1,5", "0.5x"})
        expect_usage_error({"distance", "0.1", "0.9", "0.1", s}, std::string("d2: '") + s + "' is not a number",
                           DISTANCE);
    // Every accepted spelling of 0.05 and 0.9: D = 0.
    const Result r = run_tool({"distance", ".05", "9.E-1", "+5e-2", "0.90"});
    EXPECT_EQ(r.rc, 0);
    EXPECT_EQ(r.out, "D = 0.000000\nstatus: ok\n");
}

TEST(CliTool, MessagesShowBytesNotTerminalEscapes) {
    expect_usage_error({"envelope", "\x1b[31mred"}, "L: '\\x1b[31mred' is not a number", "envelope L");
    expect_usage_error({"envelope", std::string(100, '7') + "x"}, "L: '" + std::string(64, '7') + "'... is not a number",
                       "envelope L");
}

TEST(CliTool, WrongCountsSayWhatWasExpected) {
    expect_usage_error({"demo", "extra"}, "expected no arguments, got 1", "demo");
    expect_usage_error({"distance", "1", "2", "3"}, "expected 4 arguments, got 3", DISTANCE);
    expect_usage_error({"envelope"}, "expected 1 argument, got 0", "envelope L");
    expect_usage_error({"eval", "0.2", "0.05", "0.07", "30", "0", "30", "180", "ward", "x"},
                       "expected 7 or 8 arguments, got 9", "eval rho_d rho_s alpha theta_o phi_o theta_i phi_i [norm]");
    expect_usage_error({"check", "0.2", "0.05", "0.1", "Ward"}, "norm: 'Ward' is not one of ward, ward-dur, bounded",
                       "check rho_d rho_s alpha [norm]");
    const Result r = run_tool({"fit", "1"});
    EXPECT_EQ(r.rc, 2);
    EXPECT_EQ(r.err, "pgloss: unknown command 'fit' (pgloss --help lists the commands)\n");
}

// The status line's verdict and exit code.
void expect_verdict(const std::vector<std::string> &args, const std::string &status, int rc) {
    SCOPED_TRACE(joined(args));
    const Result r = run_tool(args);
    EXPECT_EQ(r.rc, rc);
    EXPECT_EQ(r.err, "");
    const size_t at = r.out.rfind("status: ");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_EQ(r.out.substr(at, 8 + status.size()), "status: " + status) << r.out;
}

TEST(CliTool, DistanceTakesGlossesOnly) {
    // d >= 1 is α <= 0 (eq. 3); c < 0 is no contrast gloss (eq. 4); c > 1 is outside the
    // envelope at every lightness (its widest point, L* = 0, is c = 1: Fig. 10).
    expect_verdict({"distance", "0.05", "1.5", "0.05", "0.95"}, "PGLOSS_ERR_ALPHA", 1);
    expect_verdict({"distance", "0.05", "0.95", "0.05", "1"}, "PGLOSS_ERR_ALPHA", 1);
    expect_verdict({"distance", "-0.1", "0.9", "0.1", "0.9"}, "PGLOSS_ERR_NEGATIVE", 1);
    expect_verdict({"distance", "0.1", "0.9", "-1e-300", "0.9"}, "PGLOSS_ERR_NEGATIVE", 1);
    expect_verdict({"distance", "1.2", "0.9", "0.1", "0.9"}, "PGLOSS_ERR_ENVELOPE", 1);
    const Result ok = run_tool({"distance", "0.087", "0.93", "0.1", "0.9"});  // hypot(0.013, 1.78 * 0.03)
    EXPECT_EQ(ok.out, "D = 0.054960\nstatus: ok\n");
    const Result warn = run_tool({"distance", "0.1", "0.7", "0.1", "0.9"});  // d < 0.8: α > 0.2 (§4)
    EXPECT_EQ(warn.rc, 0);
    EXPECT_EQ(warn.out.rfind("D = 0.356000\nstatus: PGLOSS_WARN_ALPHA_UNTRUSTED (", 0), 0u) << warn.out;
}

TEST(CliTool, EveryCommandJudgesItsPaint) {
    // match: the given paint reflects more than it receives (ρd + ρs = 1.2), so there is no match.
    const Result m = run_tool({"match", "0.9", "0.3", "50"});
    EXPECT_EQ(m.rc, 1);
    EXPECT_EQ(m.out.rfind("status: PGLOSS_ERR_ENERGY (", 0), 0u) << m.out;
    expect_verdict({"match", "0.767", "0.099", "20"}, "ok", 0);
    // eval evaluates the lobe, and says when the paint is not in the model.
    expect_verdict({"eval", "0.9", "0.5", "0.07", "30", "0", "30", "180"}, "PGLOSS_ERR_ENERGY", 1);
    expect_verdict({"eval", "0.2", "0.05", "0.3", "30", "0", "30", "180"}, "PGLOSS_WARN_ALPHA_UNTRUSTED", 0);
    expect_verdict({"eval", "0.2", "-0.05", "0.07", "30", "0", "30", "180"}, "PGLOSS_ERR_NEGATIVE", 1);
    expect_verdict({"check", "0.767", "0.3", "0.04"}, "PGLOSS_ERR_ENERGY", 1);
    expect_verdict({"to-physical", "50", "0", "0", "0.05", "1.2"}, "PGLOSS_ERR_ALPHA", 1);
    expect_verdict({"to-perceptual", "0.9", "0.3", "0.07"}, "PGLOSS_ERR_ENERGY", 1);
    expect_verdict({"envelope", "101"}, "PGLOSS_ERR_LIGHTNESS", 1);
}

const char *const GLOSSMETER =
    "glossmeter rho_d rho_s alpha [norm] [--alpha-y A] [--azimuth DEG] [--tol T] [--rgb R G B] | --target TARGET "
    "FILE.json [--azimuth DEG] [--tol T] | --fig4 [--markdown] | --bench";
const char *const FROM_GLOSS_UNITS =
    "from-gloss-units --L L --g60 G [--a A] [--b B] [--g20 G | --haze H | --doi D | --d D] [--norm N]";
const char *const FINISH = "finish NAME [--L L] [--a A] [--b B] [--norm N] | --list";
const char *const BRIDGE = "bridge TARGET L a b c d | --from TARGET FILE.json";

TEST(CliTool, GlossmeterCommandsShareTheGrammar) {
    // Numbers, options and normalisations of the glossmeter commands: one grammar, one message.
    expect_usage_error({"glossmeter", "0.5", "x", "0.1"}, "rho_s: 'x' is not a number", GLOSSMETER);
    expect_usage_error({"glossmeter", "0.5", "0", "0.1", "--tol", "inf"}, "--tol: 'inf' is not a finite number",
                       GLOSSMETER);
    expect_usage_error({"glossmeter", "0.5", "0", "0.1", "--rgb", "0.1", "0.2"}, "--rgb needs 3 numbers", GLOSSMETER);
    expect_usage_error({"glossmeter", "0.5", "0", "0.1", "Ward"}, "norm: 'Ward' is not one of ward, ward-dur, bounded",
                       GLOSSMETER);
    expect_usage_error({"glossmeter", "0.5", "0"}, "expected 3 or 4 arguments besides the options, got 2", GLOSSMETER);
    expect_usage_error({"glossmeter", "0.5", "0", "0.1", "--tolerance", "1e-6"}, "unknown option '--tolerance'",
                       GLOSSMETER);
    expect_usage_error({"glossmeter", "--fig4", "--html"}, "--fig4 takes only --markdown", GLOSSMETER);
    expect_usage_error({"from-gloss-units", "--L", "50", "--g60"}, "--g60 needs a number", FROM_GLOSS_UNITS);
    expect_usage_error({"from-gloss-units", "--L", "50", "--g60", "0x14"}, "--g60: '0x14' is not a decimal number",
                       FROM_GLOSS_UNITS);
    expect_usage_error({"from-gloss-units", "--g60", "20"}, "needs --L and --g60", FROM_GLOSS_UNITS);
    expect_usage_error({"from-gloss-units", "--L", "50", "--g60", "20", "--g20", "9", "--haze", "5"},
                       "takes at most one of --g20, --haze, --doi, --d", FROM_GLOSS_UNITS);
    expect_usage_error({"from-gloss-units", "--L", "50", "--L", "60", "--g60", "20"}, "--L given twice",
                       FROM_GLOSS_UNITS);
    expect_usage_error({"from-gloss-units", "--L", "50", "--g60", "20", "--norm", "phong"},
                       "norm: 'phong' is not one of ward, ward-dur, bounded", FROM_GLOSS_UNITS);
    expect_usage_error({"finish", "glosy"},
                       "NAME: 'glosy' is not a finish: one of flat, velvet, eggshell, satin, semi-gloss, gloss, "
                       "high-gloss, or its level G1-G7 (pgloss finish --list)",
                       FINISH);
    expect_usage_error({"finish", "satin", "--L", "ninety"}, "--L: 'ninety' is not a number", FINISH);
    expect_usage_error({"finish", "satin", "--L"}, "--L needs a number", FINISH);
    expect_usage_error({"finish", "satin", "90"}, "unexpected argument '90'", FINISH);
    // The core's verdicts as the status line (negative ρs: eq. 2 has no such paint).
    expect_verdict({"glossmeter", "0.5", "-0.1", "0.1"}, "PGLOSS_ERR_NEGATIVE", 1);
    expect_verdict({"glossmeter", "0.5", "0", "0.1", "bounded", "--azimuth", "-30"}, "ok", 0);
    expect_verdict({"from-gloss-units", "--L", "50", "--g60", "20", "--g20", "90"}, "PGLOSS_ERR_NO_FIT", 1);
    expect_verdict({"finish", "G4", "--L", "90"}, "ok", 0);
}

TEST(CliTool, BridgeSharesTheGrammar) {
    expect_usage_error({"bridge", "vray", "50", "0", "0", "0.057", "0.96"},
                       "TARGET: 'vray' is not one of openpbr, standard_surface, gltf, gltf_core, principled, "
                       "roughplastic_ggx, roughplastic_beckmann",
                       BRIDGE);
    expect_usage_error({"bridge", "openpbr", "50", "0", "0", "0.057", "nan"}, "d: 'nan' is not a finite number", BRIDGE);
    expect_usage_error({"bridge", "openpbr", "50", "0", "0", "0.057"}, "expected 6 arguments, got 5", BRIDGE);
    expect_usage_error({"bridge", "--from", "gltf"}, "--from takes TARGET FILE.json, got 1 argument", BRIDGE);
    expect_usage_error({"bridge", "--from", "blender", "m.json"},
                       "TARGET: 'blender' is not one of openpbr, standard_surface, gltf, gltf_core, principled, "
                       "roughplastic_ggx, roughplastic_beckmann",
                       BRIDGE);
    expect_usage_error({"bridge", "--from", "gltf", "/nonexistent/m.json"},
                       "FILE.json: '/nonexistent/m.json': No such file or directory", BRIDGE);
    // The verdict is the JSON's "status" (the output stays JSON): glTF without extensions has
    // F0 = 0.04, too little specular for c = 0.2 at L* = 20 (docs/bridge.md).
    const Result r = run_tool({"bridge", "gltf_core", "20", "0", "0", "0.2", "0.95"});
    EXPECT_EQ(r.rc, 1);
    EXPECT_EQ(r.err, "");
    EXPECT_NE(r.out.find("\"status\": \"PGLOSS_ERR_BRIDGE_SPECULAR\""), std::string::npos) << r.out;
}

// Writes text to path (the JSON files the bridge commands read).
void write_file(const std::string &path, const char *text) {
    FILE *g = std::fopen(path.c_str(), "w");
    ASSERT_NE(g, nullptr) << path;
    std::fputs(text, g);
    std::fclose(g);
}

TEST(CliTool, BridgeReadsAMaterialWithTheGrammar) {
    const std::string path = testing::TempDir() + "pgloss_cli_bridge.json";
    const auto write = [&](const char *text) { write_file(path, text); };
    write("{\"parameters\": {\"baseColorFactor\": [0.18, 0.18, Infinity, 1], \"roughnessFactor\": 0.17}}");
    expect_usage_error({"bridge", "--from", "gltf", path}, "FILE.json: '" + path +
                       "': \"baseColorFactor\"[2]: 'Infinity' is not a finite number", BRIDGE);
    write("{\"parameters\": {\"baseColorFactor\": [0.18, 0.18, 0.18, 1]}}");
    expect_usage_error({"bridge", "--from", "gltf", path}, "FILE.json: '" + path +
                       "': needs \"baseColorFactor\" and \"roughnessFactor\" for gltf", BRIDGE);
    write("{\"parameters\": {\"baseColorFactor\": [0.1851, 0.1851, 0.1851, 1], \"roughnessFactor\": 0.1684,"
          " \"ior\": 1.5, \"specularFactor\": 0.642}}");
    const Result r = run_tool({"bridge", "--from", "gltf", path});
    std::remove(path.c_str());
    EXPECT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(r.out.find("\"status\": \"ok\""), std::string::npos) << r.out;
}

TEST(CliTool, GlossmeterReadsABridgeMaterial) {
    // What `pgloss bridge` prints is what `pgloss glossmeter --target` reads; the verdict of a
    // material out of the model (a base channel above 1) is a status, the file's faults usage.
    const std::string path = testing::TempDir() + "pgloss_cli_glossmeter_target.json";
    const auto write = [&](const char *text) { write_file(path, text); };
    write("{\"parameters\": {\"base_color\": [0.18, 0.18, 0.18], \"specular_roughness\": 0.24,"
          " \"specular_ior\": 1.5, \"specular_weight\": 1.13, \"base_weight\": 1}}");
    expect_verdict({"glossmeter", "--target", "openpbr", path, "--tol", "1e-4"}, "ok", 0);
    expect_usage_error({"glossmeter", "--target", "blender", path},
                       "TARGET: 'blender' is not one of openpbr, standard_surface, gltf, gltf_core, principled, "
                       "roughplastic_ggx, roughplastic_beckmann", GLOSSMETER);
    expect_usage_error({"glossmeter", "--target", "openpbr"}, "--target takes TARGET FILE.json", GLOSSMETER);
    expect_usage_error({"glossmeter", "--target", "openpbr", path, "--alpha-y", "0.1"}, "unknown option '--alpha-y'",
                       GLOSSMETER);
    write("{\"parameters\": {\"base_color\": [1.2, 0.18, 0.18], \"specular_roughness\": 0.24}}");
    expect_verdict({"glossmeter", "--target", "openpbr", path}, "PGLOSS_ERR_BRIDGE_BASE", 1);
    std::remove(path.c_str());
}

TEST(CliTool, DemoSpellsGrey) {
    const Result r = run_tool({"demo"});
    EXPECT_EQ(r.rc, 0);
    EXPECT_NE(r.out.find("\n  grey    0.193  0.066  0.07 |"), std::string::npos);
    EXPECT_EQ(r.out.find("gray"), std::string::npos);
}

TEST(CliTool, HelpAndUsage) {
    const Result h = run_tool({"--help"});
    EXPECT_EQ(h.rc, 0);
    EXPECT_EQ(h.out.rfind("usage: pgloss <command> [args]\n", 0), 0u);
    const Result none = run_tool({});
    EXPECT_EQ(none.rc, 2);
    EXPECT_EQ(none.err, h.out);
    const Result d = run_tool({"distance", "--help"});
    EXPECT_EQ(d.rc, 0);
    EXPECT_EQ(d.out.rfind("usage: pgloss distance c1 d1 c2 d2\n", 0), 0u);
}

#ifdef __linux__
TEST(CliTool, WriteErrorsAreErrors) {
    FILE *full = std::fopen("/dev/full", "w");
    ASSERT_NE(full, nullptr);
    FILE *err = std::tmpfile();
    std::vector<std::string> args = {"pgloss", "demo"};
    char *argv[] = {args[0].data(), args[1].data(), nullptr};
    const int rc = pgloss_cli_finish(full, err, pgloss_cli_main(2, argv, full, err));
    std::fclose(full);
    EXPECT_EQ(rc, 3);
    EXPECT_EQ(slurp(err), "pgloss: cannot write the output: No space left on device\n");
}
#endif

}  // namespace
