// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// test_vectors.cpp — runs the shared test vectors (tests/vectors/*.json) through the C API.
//
// Every case of every file is run through the scalar function it names; the BRDF cases
// (eval / pdf / eval_pdf / sample) are also run through the batched functions of batch.h,
// grouped by (material, lobe mask), with the same tolerance. The tolerance model is the
// one of tests/vectors/README.md:
//
//     |got - want| <= abs + rel * |want| + kappa_rel * sens
//
// with (rel, kappa_rel, abs) from the file's "tolerance" table for the file's "c_precision",
// and sens from the case. A summary of the largest errors per function and output is
// printed to stdout at the end of the run.
//
// The BRDF cases also run through the header-only functions of pgloss/inline.h, compiled here
// as C++ and in test_inline_c99.c as C99, with the tolerance of the file's float precision.
//
// A missing vectors directory, file or field is a failure, never a skip.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "batch_util.h"
#include "pgloss/inline.h"

extern "C" {
#include "pgloss/pgloss.h"
#include "test_inline_c99.h"
// test_vectors_shim.c: pgloss_physical_from_perceptual with the normalization as an int.
pgloss_status pgloss_test_physical_from_perceptual(const pgloss_perceptual *q, int normalization,
                                                   pgloss_physical *p);
// ... and the _ex functions with the working colour space as an int.
pgloss_status pgloss_test_rgb_from_lab_ex(const double lab[3], int space, double rgb[3]);
pgloss_status pgloss_test_lab_from_rgb_ex(const double rgb[3], int space, double lab[3]);
pgloss_status pgloss_test_luminance_ex(const double rgb[3], int space, double *Y);
pgloss_status pgloss_test_check_perceptual_ex(const pgloss_perceptual *q, int space);
pgloss_status pgloss_test_physical_from_perceptual_ex(const pgloss_perceptual *q, int normalization, int space,
                                                      pgloss_physical *p);
pgloss_status pgloss_test_perceptual_from_physical_ex(const pgloss_physical *p, int space, pgloss_perceptual *q);
}

#ifndef PGLOSS_VECTORS_DIR
#error "PGLOSS_VECTORS_DIR must be defined (tests/CMakeLists.txt does it)"
#endif

using json = nlohmann::json;

namespace {

static_assert(sizeof(pgloss_normalization) == sizeof(int), "normalization is stored through an int");

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const float kNaNf = std::numeric_limits<float>::quiet_NaN();

// ------------------------------------------------------------------------------------------
// Loading.

struct LoadedFile {
    bool ok = false;
    std::string error;
    json doc;
};

const char *const kFiles[] = {"lightness.json", "gloss.json", "color.json", "validity.json",
                              "perceptual_material.json", "color_space.json", "material.json",
                              "brdf_eval.json", "brdf_sample.json"};

const LoadedFile &load_file(const std::string &name) {
    static std::map<std::string, LoadedFile> cache;
    auto it = cache.find(name);
    if (it != cache.end()) return it->second;
    LoadedFile &f = cache[name];
    const std::string path = std::string(PGLOSS_VECTORS_DIR) + "/" + name;
    std::ifstream in(path);
    if (!in) {
        f.error = "cannot open " + path;
        return f;
    }
    try {
        in >> f.doc;
    } catch (const std::exception &e) {
        f.error = "cannot parse " + path + ": " + e.what();
        return f;
    }
    if (!f.doc.is_object() || f.doc.value("format", "") != "pgloss-vectors" || f.doc.value("version", 0) != 1 ||
        !f.doc.contains("cases") || !f.doc["cases"].is_array() || f.doc["cases"].empty() ||
        !f.doc.contains("tolerance") || !f.doc.contains("c_precision")) {
        f.error = path + ": not a pgloss-vectors version 1 file with cases, tolerance and c_precision";
        return f;
    }
    f.ok = true;
    return f;
}

// Returns the document or records a failure (never skips).
const json *doc_or_fail(const std::string &name) {
    const LoadedFile &f = load_file(name);
    if (!f.ok) {
        ADD_FAILURE() << f.error;
        return nullptr;
    }
    return &f.doc;
}

// Numbers: JSON numbers, or the strings "nan", "inf", "-inf" for non-finite inputs.
double num(const json &j) {
    if (j.is_string()) {
        const std::string s = j.get<std::string>();
        if (s == "nan") return kNaN;
        if (s == "inf") return std::numeric_limits<double>::infinity();
        if (s == "-inf") return -std::numeric_limits<double>::infinity();
        throw std::runtime_error("bad number string: " + s);
    }
    return j.get<double>();
}

float numf(const json &j) {
    const double d = num(j);
    const float f = static_cast<float>(d);
    if (!std::isnan(d) && static_cast<double>(f) != d) throw std::runtime_error("input is not float-exact");
    return f;
}

std::string fmt(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

bool has_tag(const json &c, const char *tag) {
    if (!c.contains("tags")) return false;
    for (const auto &t : c["tags"])
        if (t.get<std::string>() == tag) return true;
    return false;
}

bool is_null_arg(const json &c, const char *arg) {
    const json &in = c["input"];
    if (!in.contains("null")) return false;
    for (const auto &a : in["null"])
        if (a.get<std::string>() == arg) return true;
    return false;
}

std::string case_id(const json &c) { return c.value("id", std::string("?")); }

// ------------------------------------------------------------------------------------------
// Tolerances and error statistics.

struct Tol {
    double rel = 0, kappa_rel = 0, abs = 0;
};

Tol tolerance(const json &doc, const std::string &fn, const std::string &out) {
    const std::string prec = doc["c_precision"].get<std::string>();
    const json &t = doc["tolerance"].at(fn).at(out).at(prec);
    Tol r;
    r.rel = t.at("rel").get<double>();
    r.kappa_rel = t.at("kappa_rel").get<double>();
    r.abs = t.at("abs").get<double>();
    return r;
}

// max_rel is over the "regular range": |want| >= 1e-30 and condition number sens/|want| <= 10
// (elsewhere the relative error says little; err/tol covers every check).
struct Stat {
    long checks = 0, regular = 0, sanity_only = 0;
    double max_rel = 0, max_ratio = 0;
    std::string worst_rel_id, worst_ratio_id;
};

std::map<std::string, Stat> &stats() {
    static std::map<std::string, Stat> s;
    return s;
}

double sens_at(const json &c, const std::string &out, int k) {
    if (!c.contains("sens") || !c["sens"].contains(out)) return 0.0;
    const json &s = c["sens"][out];
    if (k < 0) return s.is_null() ? 0.0 : s.get<double>();
    return s.at(static_cast<size_t>(k)).is_null() ? 0.0 : s.at(static_cast<size_t>(k)).get<double>();
}

// Compares one output. want == null: only finiteness (the header leaves the value unspecified).
// sanity_only: float-ill-conditioned case (README): finite, and >= 0 for a non-negative quantity.
void check(const std::string &fn, const std::string &out, const json &c, double got, const json &want,
           double sens, const Tol &t, bool sanity_only = false, bool nonneg = false) {
    const std::string key = fn + " " + out;
    Stat &st = stats()[key];
    const std::string id = case_id(c);
    if (!std::isfinite(got)) {
        ADD_FAILURE() << id << " " << key << ": output not finite: " << got;
        return;
    }
    if (want.is_null()) return;
    const double w = num(want);
    if (sanity_only) {
        ++st.sanity_only;
        if (nonneg && got < 0) ADD_FAILURE() << id << " " << key << ": negative " << fmt(got);
        return;
    }
    ++st.checks;
    const double err = std::fabs(got - w);
    const double tol = t.abs + t.rel * std::fabs(w) + t.kappa_rel * sens;
    const double rel = w != 0 ? err / std::fabs(w) : 0.0;
    const double ratio = tol > 0 ? err / tol : (err == 0 ? 0.0 : std::numeric_limits<double>::infinity());
    if (std::fabs(w) >= 1e-30 && sens <= 10 * std::fabs(w)) {
        ++st.regular;
        if (rel > st.max_rel || st.worst_rel_id.empty()) {
            st.max_rel = std::max(st.max_rel, rel);
            st.worst_rel_id = id;
        }
    }
    if (ratio > st.max_ratio || st.worst_ratio_id.empty()) {
        st.max_ratio = std::max(st.max_ratio, ratio);
        st.worst_ratio_id = id;
    }
    if (!(err <= tol))
        ADD_FAILURE() << id << " " << key << ": got " << fmt(got) << " want " << fmt(w) << " |err| " << fmt(err)
                      << " > tol " << fmt(tol) << " (sens " << sens << ") tags " << c["tags"].dump();
}

void check_status(const std::string &fn, const json &c, pgloss_status got) {
    const std::string want = c.at("status").get<std::string>();
    const char *name = pgloss_status_name(got);
    if (want != name)
        ADD_FAILURE() << case_id(c) << " " << fn << ": status " << name << " (" << static_cast<int>(got)
                      << "), want " << want << "; input " << c["input"].dump();
}

// Runs body(case) for every case of `file` whose "function" is fn; fails if there is none.
template <class F>
void for_cases(const char *file, const char *fn, F body) {
    const json *doc = doc_or_fail(file);
    if (!doc) return;
    int n = 0;
    for (const auto &c : (*doc)["cases"]) {
        if (c.value("function", std::string()) != fn) continue;
        ++n;
        try {
            body(*doc, c);
        } catch (const std::exception &e) {
            ADD_FAILURE() << case_id(c) << " " << fn << ": malformed case: " << e.what();
        }
    }
    EXPECT_GT(n, 0) << "no cases for " << fn << " in " << file;
}

// Scalar double output of a perceptual / colour function.
void check_d(const json &doc, const std::string &fn, const std::string &out, const json &c, double got) {
    const json &e = c.at("expected");
    if (!e.contains(out)) return;  // NULL case: status only
    check(fn, out, c, got, e[out], sens_at(c, out, -1), tolerance(doc, fn, out));
}

void check_d3(const json &doc, const std::string &fn, const std::string &out, const json &c, const double *got,
              int n = 3) {
    const json &e = c.at("expected");
    if (!e.contains(out)) return;
    if (e[out].is_null()) {
        for (int k = 0; k < n; ++k) check(fn, out, c, got[k], json(), 0, Tol());
        return;
    }
    const Tol t = tolerance(doc, fn, out);
    ASSERT_EQ(e[out].size(), static_cast<size_t>(n)) << case_id(c);
    for (int k = 0; k < n; ++k) check(fn, out, c, got[k], e[out][static_cast<size_t>(k)], sens_at(c, out, k), t);
}

pgloss_physical physical_from(const json &p) {
    pgloss_physical r;
    std::memset(&r, 0, sizeof r);
    for (int k = 0; k < 3; ++k) r.rho_d[k] = num(p.at("rho_d").at(static_cast<size_t>(k)));
    r.rho_s = num(p.at("rho_s"));
    r.alpha_x = num(p.at("alpha_x"));
    r.alpha_y = num(p.at("alpha_y"));
    const int norm = p.at("normalization").get<int>();
    std::memcpy(&r.normalization, &norm, sizeof norm);  // unknown values are tested too
    return r;
}

pgloss_perceptual perceptual_from(const json &q) {
    pgloss_perceptual r;
    r.L = num(q.at("L"));
    r.a = num(q.at("a"));
    r.b = num(q.at("b"));
    r.c = num(q.at("c"));
    r.d = num(q.at("d"));
    return r;
}

pgloss_vec3 vec3(const json &v) { return pgloss_vec3{numf(v.at(0)), numf(v.at(1)), numf(v.at(2))}; }

// ------------------------------------------------------------------------------------------
// Summary.

class SummaryPrinter : public ::testing::Environment {
public:
    void TearDown() override {
        if (stats().empty()) return;
        std::printf("\npgloss vectors: largest error per function and output (checks against %s)\n",
                    PGLOSS_VECTORS_DIR);
        std::printf("regular: |want| >= 1e-30 and sens/|want| <= 10; sanity: float-ill-conditioned, finiteness/sign only\n");
        std::printf("%-34s %7s %7s %6s %11s %8s %9s %8s\n", "function output", "checks", "regular", "sanity",
                    "max relerr", "(case)", "max e/tol", "(case)");
        for (const auto &kv : stats()) {
            const Stat &s = kv.second;
            std::printf("%-34s %7ld %7ld %6ld %11.3e %8s %9.3g %8s\n", kv.first.c_str(), s.checks, s.regular,
                        s.sanity_only, s.max_rel, s.worst_rel_id.c_str(), s.max_ratio, s.worst_ratio_id.c_str());
        }
        std::fflush(stdout);
    }
};

[[maybe_unused]] const ::testing::Environment *const kSummary = ::testing::AddGlobalTestEnvironment(new SummaryPrinter);

// ------------------------------------------------------------------------------------------
// Files.

TEST(Vectors, FilesPresentAndCovered) {
    const std::map<std::string, std::vector<std::string>> want = {
        {"lightness.json", {"lightness_from_luminance", "luminance_from_lightness"}},
        {"gloss.json",
         {"contrast_gloss", "specular_from_contrast", "gloss_from_physical", "physical_from_gloss", "gloss_distance",
          "envelope_contrast", "match_gloss", "isogloss_contour"}},
        {"color.json", {"rgb_from_lab", "lab_from_rgb", "luminance"}},
        {"validity.json", {"check_physical", "check_perceptual"}},
        {"perceptual_material.json", {"physical_from_perceptual", "perceptual_from_physical"}},
        {"color_space.json",
         {"rgb_from_lab_ex", "lab_from_rgb_ex", "luminance_ex", "check_perceptual_ex", "physical_from_perceptual_ex",
          "perceptual_from_physical_ex"}},
        {"material.json", {"material_init", "specular_probability"}},
        {"brdf_eval.json", {"eval", "pdf", "eval_pdf", "eval_batch", "pdf_batch", "eval_pdf_batch"}},
        {"brdf_sample.json", {"sample", "sample_batch"}},
    };
    for (const char *name : kFiles) {
        const json *doc = doc_or_fail(name);
        if (!doc) continue;
        std::vector<std::string> fns;
        for (const auto &f : (*doc)["functions"]) fns.push_back(f.get<std::string>());
        for (const auto &f : want.at(name))
            EXPECT_NE(std::find(fns.begin(), fns.end(), f), fns.end()) << name << " lacks " << f;
        // Every case names a function the runner knows, and ids are unique.
        std::map<std::string, int> ids;
        for (const auto &c : (*doc)["cases"]) {
            EXPECT_EQ(ids[case_id(c)]++, 0) << name << ": duplicate id " << case_id(c);
            if (c.contains("function")) {
                const std::string f = c["function"].get<std::string>();
                EXPECT_NE(std::find(fns.begin(), fns.end(), f), fns.end()) << case_id(c) << ": unknown function " << f;
            }
        }
    }
}

// ------------------------------------------------------------------------------------------
// lightness.json

TEST(Vectors, lightness_from_luminance) {
    for_cases("lightness.json", "lightness_from_luminance", [](const json &doc, const json &c) {
        double L = kNaN;
        const pgloss_status st = pgloss_lightness_from_luminance(num(c["input"]["Y"]), is_null_arg(c, "L") ? nullptr : &L);
        check_status("lightness_from_luminance", c, st);
        check_d(doc, "lightness_from_luminance", "L", c, L);
    });
}

TEST(Vectors, luminance_from_lightness) {
    for_cases("lightness.json", "luminance_from_lightness", [](const json &doc, const json &c) {
        double Y = kNaN;
        const pgloss_status st = pgloss_luminance_from_lightness(num(c["input"]["L"]), is_null_arg(c, "Y") ? nullptr : &Y);
        check_status("luminance_from_lightness", c, st);
        check_d(doc, "luminance_from_lightness", "Y", c, Y);
    });
}

// ------------------------------------------------------------------------------------------
// gloss.json

TEST(Vectors, contrast_gloss) {
    for_cases("gloss.json", "contrast_gloss", [](const json &doc, const json &c) {
        double v = kNaN;
        const json &in = c["input"];
        const pgloss_status st = pgloss_contrast_gloss(num(in["rho_d"]), num(in["rho_s"]), is_null_arg(c, "c") ? nullptr : &v);
        check_status("contrast_gloss", c, st);
        check_d(doc, "contrast_gloss", "c", c, v);
    });
}

TEST(Vectors, specular_from_contrast) {
    for_cases("gloss.json", "specular_from_contrast", [](const json &doc, const json &c) {
        double v = kNaN;
        const json &in = c["input"];
        const pgloss_status st =
            pgloss_specular_from_contrast(num(in["rho_d"]), num(in["c"]), is_null_arg(c, "rho_s") ? nullptr : &v);
        check_status("specular_from_contrast", c, st);
        check_d(doc, "specular_from_contrast", "rho_s", c, v);
    });
}

TEST(Vectors, gloss_from_physical) {
    for_cases("gloss.json", "gloss_from_physical", [](const json &doc, const json &c) {
        double L = kNaN, cc = kNaN, d = kNaN;
        const json &in = c["input"];
        const pgloss_status st = pgloss_gloss_from_physical(
            num(in["rho_d"]), num(in["rho_s"]), num(in["alpha"]), is_null_arg(c, "L") ? nullptr : &L,
            is_null_arg(c, "c") ? nullptr : &cc, is_null_arg(c, "d") ? nullptr : &d);
        check_status("gloss_from_physical", c, st);
        check_d(doc, "gloss_from_physical", "L", c, L);
        check_d(doc, "gloss_from_physical", "c", c, cc);
        check_d(doc, "gloss_from_physical", "d", c, d);
    });
}

TEST(Vectors, physical_from_gloss) {
    for_cases("gloss.json", "physical_from_gloss", [](const json &doc, const json &c) {
        double rd = kNaN, rs = kNaN, al = kNaN;
        const json &in = c["input"];
        const pgloss_status st = pgloss_physical_from_gloss(
            num(in["L"]), num(in["c"]), num(in["d"]), is_null_arg(c, "rho_d") ? nullptr : &rd,
            is_null_arg(c, "rho_s") ? nullptr : &rs, is_null_arg(c, "alpha") ? nullptr : &al);
        check_status("physical_from_gloss", c, st);
        check_d(doc, "physical_from_gloss", "rho_d", c, rd);
        check_d(doc, "physical_from_gloss", "rho_s", c, rs);
        check_d(doc, "physical_from_gloss", "alpha", c, al);
    });
}

TEST(Vectors, gloss_distance) {
    for_cases("gloss.json", "gloss_distance", [](const json &doc, const json &c) {
        double D = kNaN;
        const json &in = c["input"];
        const pgloss_status st = pgloss_gloss_distance(num(in["c1"]), num(in["d1"]), num(in["c2"]), num(in["d2"]),
                                                       is_null_arg(c, "D") ? nullptr : &D);
        check_status("gloss_distance", c, st);
        check_d(doc, "gloss_distance", "D", c, D);
    });
}

TEST(Vectors, envelope_contrast) {
    for_cases("gloss.json", "envelope_contrast", [](const json &doc, const json &c) {
        double v = kNaN;
        const pgloss_status st = pgloss_envelope_contrast(num(c["input"]["L"]), is_null_arg(c, "c_max") ? nullptr : &v);
        check_status("envelope_contrast", c, st);
        check_d(doc, "envelope_contrast", "c_max", c, v);
    });
}

TEST(Vectors, match_gloss) {
    for_cases("gloss.json", "match_gloss", [](const json &doc, const json &c) {
        double rd = kNaN, rs = kNaN;
        const json &in = c["input"];
        const pgloss_status st =
            pgloss_match_gloss(num(in["rho_d"]), num(in["rho_s"]), num(in["L_target"]),
                               is_null_arg(c, "rho_d_out") ? nullptr : &rd, is_null_arg(c, "rho_s_out") ? nullptr : &rs);
        check_status("match_gloss", c, st);
        check_d(doc, "match_gloss", "rho_d_out", c, rd);
        check_d(doc, "match_gloss", "rho_s_out", c, rs);
    });
}

TEST(Vectors, isogloss_contour) {
    for_cases("gloss.json", "isogloss_contour", [](const json &doc, const json &c) {
        const json &in = c["input"];
        const size_t n = in["n"].get<size_t>();
        std::vector<double> cc(n + 1, kNaN), dd(n + 1, kNaN);  // one guard element past the end
        const pgloss_status st =
            pgloss_isogloss_contour(num(in["c0"]), num(in["d0"]), num(in["D"]), n,
                                    is_null_arg(c, "c") ? nullptr : cc.data(), is_null_arg(c, "d") ? nullptr : dd.data());
        check_status("isogloss_contour", c, st);
        const json &e = c["expected"];
        if (!e.contains("c")) return;
        ASSERT_EQ(e["c"].size(), n) << case_id(c);
        const Tol tc = tolerance(doc, "isogloss_contour", "c"), td = tolerance(doc, "isogloss_contour", "d");
        for (size_t k = 0; k < n; ++k) {
            check("isogloss_contour", "c", c, cc[k], e["c"][k], sens_at(c, "c", static_cast<int>(k)), tc);
            check("isogloss_contour", "d", c, dd[k], e["d"][k], sens_at(c, "d", static_cast<int>(k)), td);
        }
        EXPECT_TRUE(std::isnan(cc[n]) && std::isnan(dd[n])) << case_id(c) << ": wrote past n";
    });
}

// ------------------------------------------------------------------------------------------
// color.json

TEST(Vectors, rgb_from_lab) {
    for_cases("color.json", "rgb_from_lab", [](const json &doc, const json &c) {
        double lab[3], rgb[3] = {kNaN, kNaN, kNaN};
        for (int k = 0; k < 3; ++k) lab[k] = num(c["input"]["lab"][static_cast<size_t>(k)]);
        const pgloss_status st =
            pgloss_rgb_from_lab(is_null_arg(c, "lab") ? nullptr : lab, is_null_arg(c, "rgb") ? nullptr : rgb);
        check_status("rgb_from_lab", c, st);
        check_d3(doc, "rgb_from_lab", "rgb", c, rgb);
    });
}

TEST(Vectors, lab_from_rgb) {
    for_cases("color.json", "lab_from_rgb", [](const json &doc, const json &c) {
        double rgb[3], lab[3] = {kNaN, kNaN, kNaN};
        for (int k = 0; k < 3; ++k) rgb[k] = num(c["input"]["rgb"][static_cast<size_t>(k)]);
        const pgloss_status st =
            pgloss_lab_from_rgb(is_null_arg(c, "rgb") ? nullptr : rgb, is_null_arg(c, "lab") ? nullptr : lab);
        check_status("lab_from_rgb", c, st);
        check_d3(doc, "lab_from_rgb", "lab", c, lab);
    });
}

TEST(Vectors, luminance) {
    for_cases("color.json", "luminance", [](const json &doc, const json &c) {
        double rgb[3], Y = kNaN;
        for (int k = 0; k < 3; ++k) rgb[k] = num(c["input"]["rgb"][static_cast<size_t>(k)]);
        const pgloss_status st =
            pgloss_luminance(is_null_arg(c, "rgb") ? nullptr : rgb, is_null_arg(c, "Y") ? nullptr : &Y);
        check_status("luminance", c, st);
        check_d(doc, "luminance", "Y", c, Y);
    });
}

// ------------------------------------------------------------------------------------------
// validity.json

TEST(Vectors, check_physical) {
    for_cases("validity.json", "check_physical", [](const json &, const json &c) {
        const pgloss_physical p = physical_from(c["input"]["p"]);
        check_status("check_physical", c, pgloss_check_physical(is_null_arg(c, "p") ? nullptr : &p));
    });
}

TEST(Vectors, check_perceptual) {
    for_cases("validity.json", "check_perceptual", [](const json &, const json &c) {
        const pgloss_perceptual q = perceptual_from(c["input"]["q"]);
        check_status("check_perceptual", c, pgloss_check_perceptual(is_null_arg(c, "q") ? nullptr : &q));
    });
}

// ------------------------------------------------------------------------------------------
// perceptual_material.json

TEST(Vectors, physical_from_perceptual) {
    for_cases("perceptual_material.json", "physical_from_perceptual", [](const json &doc, const json &c) {
        const char *fn = "physical_from_perceptual";
        const pgloss_perceptual q = perceptual_from(c["input"]["q"]);
        const int norm = c["input"]["normalization"].get<int>();
        pgloss_physical p;
        p.rho_d[0] = p.rho_d[1] = p.rho_d[2] = p.rho_s = p.alpha_x = p.alpha_y = kNaN;
        const int garbage = 0x7eadbeef;
        std::memcpy(&p.normalization, &garbage, sizeof garbage);
        const pgloss_status st = pgloss_test_physical_from_perceptual(is_null_arg(c, "q") ? nullptr : &q, norm,
                                                                      is_null_arg(c, "p") ? nullptr : &p);
        check_status(fn, c, st);
        const json &e = c["expected"];
        if (!e.contains("rho_d")) return;
        check_d3(doc, fn, "rho_d", c, p.rho_d);
        check_d(doc, fn, "rho_s", c, p.rho_s);
        check_d(doc, fn, "alpha_x", c, p.alpha_x);
        check_d(doc, fn, "alpha_y", c, p.alpha_y);
        if (!e["normalization"].is_null()) {
            int got;
            std::memcpy(&got, &p.normalization, sizeof got);
            EXPECT_EQ(got, e["normalization"].get<int>()) << case_id(c);
        }
    });
}

TEST(Vectors, perceptual_from_physical) {
    for_cases("perceptual_material.json", "perceptual_from_physical", [](const json &doc, const json &c) {
        const char *fn = "perceptual_from_physical";
        const pgloss_physical p = physical_from(c["input"]["p"]);
        pgloss_perceptual q{kNaN, kNaN, kNaN, kNaN, kNaN};
        const pgloss_status st =
            pgloss_perceptual_from_physical(is_null_arg(c, "p") ? nullptr : &p, is_null_arg(c, "q") ? nullptr : &q);
        check_status(fn, c, st);
        check_d(doc, fn, "L", c, q.L);
        check_d(doc, fn, "a", c, q.a);
        check_d(doc, fn, "b", c, q.b);
        check_d(doc, fn, "c", c, q.c);
        check_d(doc, fn, "d", c, q.d);
    });
}

// ------------------------------------------------------------------------------------------
// color_space.json: the _ex functions in every working colour space.

int space_of(const json &c) { return c["input"]["space"].get<int>(); }

TEST(Vectors, rgb_from_lab_ex) {
    for_cases("color_space.json", "rgb_from_lab_ex", [](const json &doc, const json &c) {
        double lab[3], rgb[3] = {kNaN, kNaN, kNaN};
        for (int k = 0; k < 3; ++k) lab[k] = num(c["input"]["lab"][static_cast<size_t>(k)]);
        const pgloss_status st = pgloss_test_rgb_from_lab_ex(is_null_arg(c, "lab") ? nullptr : lab, space_of(c),
                                                             is_null_arg(c, "rgb") ? nullptr : rgb);
        check_status("rgb_from_lab_ex", c, st);
        check_d3(doc, "rgb_from_lab_ex", "rgb", c, rgb);
    });
}

TEST(Vectors, lab_from_rgb_ex) {
    for_cases("color_space.json", "lab_from_rgb_ex", [](const json &doc, const json &c) {
        double rgb[3], lab[3] = {kNaN, kNaN, kNaN};
        for (int k = 0; k < 3; ++k) rgb[k] = num(c["input"]["rgb"][static_cast<size_t>(k)]);
        const pgloss_status st = pgloss_test_lab_from_rgb_ex(is_null_arg(c, "rgb") ? nullptr : rgb, space_of(c),
                                                             is_null_arg(c, "lab") ? nullptr : lab);
        check_status("lab_from_rgb_ex", c, st);
        check_d3(doc, "lab_from_rgb_ex", "lab", c, lab);
    });
}

TEST(Vectors, luminance_ex) {
    for_cases("color_space.json", "luminance_ex", [](const json &doc, const json &c) {
        double rgb[3], Y = kNaN;
        for (int k = 0; k < 3; ++k) rgb[k] = num(c["input"]["rgb"][static_cast<size_t>(k)]);
        const pgloss_status st = pgloss_test_luminance_ex(is_null_arg(c, "rgb") ? nullptr : rgb, space_of(c),
                                                          is_null_arg(c, "Y") ? nullptr : &Y);
        check_status("luminance_ex", c, st);
        check_d(doc, "luminance_ex", "Y", c, Y);
    });
}

TEST(Vectors, check_perceptual_ex) {
    for_cases("color_space.json", "check_perceptual_ex", [](const json &, const json &c) {
        const pgloss_perceptual q = perceptual_from(c["input"]["q"]);
        check_status("check_perceptual_ex", c,
                     pgloss_test_check_perceptual_ex(is_null_arg(c, "q") ? nullptr : &q, space_of(c)));
    });
}

TEST(Vectors, physical_from_perceptual_ex) {
    for_cases("color_space.json", "physical_from_perceptual_ex", [](const json &doc, const json &c) {
        const char *fn = "physical_from_perceptual_ex";
        const pgloss_perceptual q = perceptual_from(c["input"]["q"]);
        const int norm = c["input"]["normalization"].get<int>();
        pgloss_physical p;
        p.rho_d[0] = p.rho_d[1] = p.rho_d[2] = p.rho_s = p.alpha_x = p.alpha_y = kNaN;
        const pgloss_status st = pgloss_test_physical_from_perceptual_ex(
            is_null_arg(c, "q") ? nullptr : &q, norm, space_of(c), is_null_arg(c, "p") ? nullptr : &p);
        check_status(fn, c, st);
        const json &e = c["expected"];
        if (!e.contains("rho_d")) return;
        check_d3(doc, fn, "rho_d", c, p.rho_d);
        check_d(doc, fn, "rho_s", c, p.rho_s);
        check_d(doc, fn, "alpha_x", c, p.alpha_x);
        check_d(doc, fn, "alpha_y", c, p.alpha_y);
        if (!e["normalization"].is_null()) {
            int got;
            std::memcpy(&got, &p.normalization, sizeof got);
            EXPECT_EQ(got, e["normalization"].get<int>()) << case_id(c);
        }
    });
}

TEST(Vectors, perceptual_from_physical_ex) {
    for_cases("color_space.json", "perceptual_from_physical_ex", [](const json &doc, const json &c) {
        const char *fn = "perceptual_from_physical_ex";
        const pgloss_physical p = physical_from(c["input"]["p"]);
        pgloss_perceptual q{kNaN, kNaN, kNaN, kNaN, kNaN};
        const pgloss_status st = pgloss_test_perceptual_from_physical_ex(is_null_arg(c, "p") ? nullptr : &p,
                                                                         space_of(c), is_null_arg(c, "q") ? nullptr : &q);
        check_status(fn, c, st);
        check_d(doc, fn, "L", c, q.L);
        check_d(doc, fn, "a", c, q.a);
        check_d(doc, fn, "b", c, q.b);
        check_d(doc, fn, "c", c, q.c);
        check_d(doc, fn, "d", c, q.d);
    });
}

// ------------------------------------------------------------------------------------------
// material.json

bool material_is_black(const pgloss_material &m) {
    pgloss_rgb f{1, 1, 1};
    const pgloss_vec3 n{0, 0, 1};
    pgloss_eval(&m, n, n, PGLOSS_LOBE_ALL, &f);
    return f.r == 0 && f.g == 0 && f.b == 0;
}

TEST(Vectors, material_init) {
    for_cases("material.json", "material_init", [](const json &doc, const json &c) {
        const char *fn = "material_init";
        const pgloss_physical p = physical_from(c["input"]["p"]);
        pgloss_material m;
        std::memset(&m, 0x5a, sizeof m);  // garbage: init must write everything it documents
        const pgloss_status st =
            pgloss_material_init(is_null_arg(c, "m") ? nullptr : &m, is_null_arg(c, "p") ? nullptr : &p);
        check_status(fn, c, st);
        const json &e = c["expected"];
        if (!e.contains("lobes")) return;
        EXPECT_EQ(m.lobes, e["lobes"].get<unsigned>()) << case_id(c);
        if (st != PGLOSS_OK) {
            EXPECT_TRUE(material_is_black(m)) << case_id(c) << ": a failed init must give a black material";
            return;
        }
        const double rd[3] = {m.rho_d[0], m.rho_d[1], m.rho_d[2]};
        check_d3(doc, fn, "rho_d", c, rd);
        check_d(doc, fn, "rho_s", c, m.rho_s);
        check_d(doc, fn, "alpha_x", c, m.alpha_x);
        check_d(doc, fn, "alpha_y", c, m.alpha_y);
        check_d(doc, fn, "inv_alpha_x", c, m.inv_alpha_x);
        check_d(doc, fn, "inv_alpha_y", c, m.inv_alpha_y);
        check_d(doc, fn, "spec_scale", c, m.spec_scale);
        check_d(doc, fn, "pdf_scale", c, m.pdf_scale);
        check_d(doc, fn, "weight_diffuse", c, m.weight_diffuse);
        check_d(doc, fn, "weight_specular", c, m.weight_specular);
        int norm;
        std::memcpy(&norm, &m.normalization, sizeof norm);
        EXPECT_EQ(norm, c["input"]["p"]["normalization"].get<int>()) << case_id(c);
    });
}

TEST(Vectors, specular_probability) {
    for_cases("material.json", "specular_probability", [](const json &doc, const json &c) {
        const pgloss_physical p = physical_from(c["input"]["p"]);
        pgloss_material m;
        ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK) << case_id(c);
        const float P = pgloss_specular_probability(&m, c["input"]["lobes"].get<unsigned>());
        check_d(doc, "specular_probability", "P", c, P);
    });
}

// ------------------------------------------------------------------------------------------
// BRDF: materials table shared by brdf_eval.json and brdf_sample.json.

std::map<std::string, pgloss_material> materials_of(const json &doc) {
    std::map<std::string, pgloss_material> mats;
    for (const auto &kv : doc.at("materials").items()) {
        const pgloss_physical p = physical_from(kv.value());
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(static_cast<double>(static_cast<float>(p.rho_d[k])), p.rho_d[k]) << kv.key() << " not float-exact";
        pgloss_material m;
        const pgloss_status st = pgloss_material_init(&m, &p);
        EXPECT_EQ(st, PGLOSS_OK) << "material " << kv.key() << ": " << pgloss_status_name(st);
        mats[kv.key()] = m;
    }
    return mats;
}

const pgloss_material &material_of(const std::map<std::string, pgloss_material> &mats, const json &c) {
    return mats.at(c["input"]["material"].get<std::string>());
}

bool sanity_float(const json &doc, const json &c) {
    // README: a float-ill-conditioned case is only checked for finiteness and sign in float.
    return has_tag(c, "ill_conditioned") && doc["c_precision"].get<std::string>() == "float";
}

void check_f(const json &doc, const std::string &fn, const json &c, const pgloss_rgb &f) {
    const Tol t = tolerance(doc, fn, "f");
    const double got[3] = {f.r, f.g, f.b};
    const bool s = sanity_float(doc, c);
    for (int k = 0; k < 3; ++k)
        check(fn, "f", c, got[k], c["expected"]["f"][static_cast<size_t>(k)], sens_at(c, "f", k), t, s, true);
}

void check_pdf(const json &doc, const std::string &fn, const json &c, double pdf) {
    check(fn, "pdf", c, pdf, c["expected"]["pdf"], sens_at(c, "pdf", -1), tolerance(doc, fn, "pdf"),
          sanity_float(doc, c), true);
}

// ------------------------------------------------------------------------------------------
// brdf_eval.json

TEST(Vectors, eval_pdf_scalar) {
    const json *doc = doc_or_fail("brdf_eval.json");
    if (!doc) return;
    const auto mats = materials_of(*doc);
    for (const auto &c : (*doc)["cases"]) {
        try {
            const pgloss_material &m = material_of(mats, c);
            const pgloss_vec3 wo = vec3(c["input"]["wo"]), wi = vec3(c["input"]["wi"]);
            const unsigned lobes = c["input"]["lobes"].get<unsigned>();
            pgloss_rgb f{-1, -1, -1};
            float pdf = -1;
            check_status("eval", c, pgloss_eval(&m, wo, wi, lobes, &f));
            check_f(*doc, "eval", c, f);
            check_status("pdf", c, pgloss_pdf(&m, wo, wi, lobes, &pdf));
            check_pdf(*doc, "pdf", c, pdf);
            f = pgloss_rgb{-1, -1, -1};
            pdf = -1;
            check_status("eval_pdf", c, pgloss_eval_pdf(&m, wo, wi, lobes, &f, &pdf));
            check_f(*doc, "eval_pdf", c, f);
            check_pdf(*doc, "eval_pdf", c, pdf);
        } catch (const std::exception &e) {
            ADD_FAILURE() << case_id(c) << ": malformed case: " << e.what();
        }
    }
}

// pgloss/inline.h as C++ and as C99: eval, pdf and eval_pdf of every case.
TEST(Vectors, eval_pdf_inline) {
    const json *doc = doc_or_fail("brdf_eval.json");
    if (!doc) return;
    const auto mats = materials_of(*doc);
    for (int lang = 0; lang < 2; ++lang) {
        const std::string sfx = lang == 0 ? "_inline" : "_inline (C99)";
        for (const auto &c : (*doc)["cases"]) {
            try {
                const pgloss_material &m = material_of(mats, c);
                const pgloss_vec3 wo = vec3(c["input"]["wo"]), wi = vec3(c["input"]["wi"]);
                const unsigned lobes = c["input"]["lobes"].get<unsigned>();
                pgloss_rgb f{-1, -1, -1};
                float pdf = -1;
                check_status("eval" + sfx, c, lang == 0 ? pgloss_eval_inline(&m, wo, wi, lobes, &f)
                                                        : pgloss_test_eval_inline_c99(&m, wo, wi, lobes, &f));
                const Tol tf = tolerance(*doc, "eval", "f"), tp = tolerance(*doc, "pdf", "pdf");
                const bool s = sanity_float(*doc, c);
                auto check_rgb = [&](const std::string &fn, const pgloss_rgb &v) {
                    const double got[3] = {v.r, v.g, v.b};
                    for (int k = 0; k < 3; ++k)
                        check(fn, "f", c, got[k], c["expected"]["f"][static_cast<size_t>(k)],
                              sens_at(c, "f", k), tf, s, true);
                };
                check_rgb("eval" + sfx, f);
                check_status("pdf" + sfx, c, lang == 0 ? pgloss_pdf_inline(&m, wo, wi, lobes, &pdf)
                                                       : pgloss_test_pdf_inline_c99(&m, wo, wi, lobes, &pdf));
                check("pdf" + sfx, "pdf", c, pdf, c["expected"]["pdf"], sens_at(c, "pdf", -1), tp, s, true);
                f = pgloss_rgb{-1, -1, -1};
                pdf = -1;
                check_status("eval_pdf" + sfx, c,
                             lang == 0 ? pgloss_eval_pdf_inline(&m, wo, wi, lobes, &f, &pdf)
                                       : pgloss_test_eval_pdf_inline_c99(&m, wo, wi, lobes, &f, &pdf));
                check_rgb("eval_pdf" + sfx, f);
                check("eval_pdf" + sfx, "pdf", c, pdf, c["expected"]["pdf"], sens_at(c, "pdf", -1), tp, s, true);
            } catch (const std::exception &e) {
                ADD_FAILURE() << case_id(c) << ": malformed case: " << e.what();
            }
        }
    }
}

// Cases grouped by (material, lobes), in file order; expected batch status: first non-OK.
std::map<std::pair<std::string, unsigned>, std::vector<const json *>> groups_of(const json &doc) {
    std::map<std::pair<std::string, unsigned>, std::vector<const json *>> g;
    for (const auto &c : doc["cases"]) {
        if (c["input"].contains("null")) continue;
        g[{c["input"]["material"].get<std::string>(), c["input"]["lobes"].get<unsigned>()}].push_back(&c);
    }
    return g;
}

std::string first_error(const std::vector<const json *> &cs) {
    for (const json *c : cs)
        if ((*c)["status"].get<std::string>() != "PGLOSS_OK") return (*c)["status"].get<std::string>();
    return "PGLOSS_OK";
}

// SoA arrays deliberately misaligned by one float (the header allows any alignment).
struct SoA {
    std::vector<float> buf;
    size_t n;
    explicit SoA(size_t n_, float fill) : buf(n_ + 1, fill), n(n_) {}
    float *p() { return buf.data() + 1; }
};

TEST(Vectors, eval_pdf_batch) {
    const json *doc = doc_or_fail("brdf_eval.json");
    if (!doc) return;
    const auto mats = materials_of(*doc);
    int groups = 0;
    for (const auto &kv : groups_of(*doc)) {
        const std::vector<const json *> &cs = kv.second;
        const size_t n = cs.size();
        const pgloss_material &m = mats.at(kv.first.first);
        const unsigned lobes = kv.first.second;
        SoA ox(n, 0), oy(n, 0), oz(n, 0), ix(n, 0), iy(n, 0), iz(n, 0);
        for (size_t k = 0; k < n; ++k) {
            const pgloss_vec3 wo = vec3((*cs[k])["input"]["wo"]), wi = vec3((*cs[k])["input"]["wi"]);
            ox.p()[k] = wo.x, oy.p()[k] = wo.y, oz.p()[k] = wo.z;
            ix.p()[k] = wi.x, iy.p()[k] = wi.y, iz.p()[k] = wi.z;
        }
        const pgloss_strided3 wo = soa(ox.p(), oy.p(), oz.p()), wi = soa(ix.p(), iy.p(), iz.p());
        // (n, 3) rows of the same directions: the strided path (gathered, not in place)
        std::vector<float> wo_rows(3 * n), wi_rows(3 * n);
        for (size_t k = 0; k < n; ++k)
            for (int c = 0; c < 3; ++c) {
                wo_rows[3 * k + c] = (c == 0 ? ox : c == 1 ? oy : oz).p()[k];
                wi_rows[3 * k + c] = (c == 0 ? ix : c == 1 ? iy : iz).p()[k];
            }
        const std::string want = first_error(cs);
        for (int variant = 0; variant < 4; ++variant) {
            // f only, pdf only, both; both from and into (n, 3) rows
            const char *fn = variant == 0 ? "eval_batch" : variant == 1 ? "pdf_batch"
                           : variant == 2 ? "eval_pdf_batch" : "eval_pdf_batch (rows)";
            const char *tolfn = variant == 0 ? "eval" : variant == 1 ? "pdf" : "eval_pdf";
            SoA fr(n, -1), fg(n, -1), fb(n, -1), pdf(n, -1);
            std::vector<float> f_rows(3 * n + 1, -1);
            const pgloss_strided3_out f = variant == 1 ? no_out3() : soa_out(fr.p(), fg.p(), fb.p());
            const pgloss_strided_out p = variant == 0 ? no_out() : col_out(pdf.p());
            pgloss_status st;
            if (variant < 3) {
                st = pgloss_eval_pdf_batch(nullptr, &m, nullptr, lobes, n, wo, wi, f, p, nullptr);
            } else {
                st = pgloss_eval_pdf_batch(nullptr, &m, nullptr, lobes, n, pgloss_strided3_rows(wo_rows.data(), 4),
                                           pgloss_strided3_rows(wi_rows.data(), 4),
                                           pgloss_strided3_out_rows(f_rows.data() + 1, 4), p, nullptr);
                for (size_t k = 0; k < n; ++k) {
                    fr.p()[k] = f_rows[3 * k + 1];
                    fg.p()[k] = f_rows[3 * k + 2];
                    fb.p()[k] = f_rows[3 * k + 3];
                }
            }
            EXPECT_EQ(std::string(pgloss_status_name(st)), want) << fn << " group " << kv.first.first << "/" << lobes;
            for (size_t k = 0; k < n; ++k) {
                const json &c = *cs[k];
                const bool s = sanity_float(*doc, c);
                if (variant != 1) {
                    const Tol t = tolerance(*doc, tolfn, "f");
                    const double got[3] = {fr.p()[k], fg.p()[k], fb.p()[k]};
                    for (int j = 0; j < 3; ++j)
                        check(fn, "f", c, got[j], c["expected"]["f"][static_cast<size_t>(j)], sens_at(c, "f", j), t, s,
                              true);
                }
                if (variant != 0)
                    check(fn, "pdf", c, pdf.p()[k], c["expected"]["pdf"], sens_at(c, "pdf", -1),
                          tolerance(*doc, tolfn, "pdf"), s, true);
            }
            EXPECT_EQ(fr.buf[0], -1.0f) << fn << ": wrote before the array";
        }
        // One case per call: a chunk whose directions are all of moderate length takes the
        // loops' short normalisation, one with an extreme direction the careful one; grouped
        // calls above mostly meet the latter, single calls meet each case's own path.
        for (size_t k = 0; k < n; ++k) {
            const json &c = *cs[k];
            float r = -1, g = -1, b = -1, p1 = -1;
            const pgloss_status st =
                pgloss_eval_pdf_batch(nullptr, &m, nullptr, lobes, 1, soa(ox.p() + k, oy.p() + k, oz.p() + k),
                                      soa(ix.p() + k, iy.p() + k, iz.p() + k), soa_out(&r, &g, &b), col_out(&p1), nullptr);
            EXPECT_EQ(std::string(pgloss_status_name(st)), c["status"].get<std::string>()) << case_id(c) << " n=1";
            const bool s = sanity_float(*doc, c);
            const double got[3] = {r, g, b};
            for (int j = 0; j < 3; ++j)
                check("eval_pdf_batch (n=1)", "f", c, got[j], c["expected"]["f"][static_cast<size_t>(j)],
                      sens_at(c, "f", j), tolerance(*doc, "eval_pdf", "f"), s, true);
            check("eval_pdf_batch (n=1)", "pdf", c, p1, c["expected"]["pdf"], sens_at(c, "pdf", -1),
                  tolerance(*doc, "eval_pdf", "pdf"), s, true);
        }
        ++groups;
    }
    EXPECT_GT(groups, 0);
}

// ------------------------------------------------------------------------------------------
// brdf_sample.json

unsigned lobe_value(const std::string &name) {
    if (name == "PGLOSS_LOBE_NONE") return PGLOSS_LOBE_NONE;
    if (name == "PGLOSS_LOBE_DIFFUSE") return PGLOSS_LOBE_DIFFUSE;
    if (name == "PGLOSS_LOBE_SPECULAR") return PGLOSS_LOBE_SPECULAR;
    throw std::runtime_error("bad lobe name " + name);
}

void check_sample(const json &doc, const std::string &fn, const json &c, const double wi[3], double pdf,
                  const double weight[3], unsigned lobe) {
    const json &e = c["expected"];
    const bool s = sanity_float(doc, c);
    const Tol twi = tolerance(doc, "sample", "wi"), tpdf = tolerance(doc, "sample", "pdf"),
              tw = tolerance(doc, "sample", "weight");
    for (int k = 0; k < 3; ++k) {
        const size_t kk = static_cast<size_t>(k);
        check(fn, "wi", c, wi[k], e["wi"].is_null() ? json() : e["wi"][kk], sens_at(c, "wi", k), twi, s);
        check(fn, "weight", c, weight[k], e["weight"][kk], sens_at(c, "weight", k), tw, s, true);
    }
    check(fn, "pdf", c, pdf, e["pdf"], sens_at(c, "pdf", -1), tpdf, s, true);
    if (!e["lobe"].is_null()) {
        ++stats()[fn + " lobe"].checks;
        EXPECT_EQ(lobe, lobe_value(e["lobe"].get<std::string>())) << case_id(c) << " " << fn << " lobe";
    }
    if (num(e["pdf"]) == 0) {  // a rejected sample: exactly 0
        EXPECT_EQ(pdf, 0.0) << case_id(c) << " " << fn << ": rejected sample must have pdf 0";
        EXPECT_TRUE(weight[0] == 0 && weight[1] == 0 && weight[2] == 0)
            << case_id(c) << " " << fn << ": rejected sample must have weight 0";
    } else if (!e["wi"].is_null()) {
        const double len = std::sqrt(wi[0] * wi[0] + wi[1] * wi[1] + wi[2] * wi[2]);
        EXPECT_NEAR(len, 1.0, 1e-5) << case_id(c) << " " << fn << ": wi not unit length";
    }
}

using sample_fn = pgloss_status (*)(const pgloss_material *, pgloss_vec3, const float[3], unsigned,
                                     pgloss_sample_record *);

// Every case of brdf_sample.json through one per-point sampler.
void sample_cases(const char *fn, sample_fn call) {
    const json *doc = doc_or_fail("brdf_sample.json");
    if (!doc) return;
    const auto mats = materials_of(*doc);
    for (const auto &c : (*doc)["cases"]) {
        try {
            const pgloss_material &m = material_of(mats, c);
            const pgloss_vec3 wo = vec3(c["input"]["wo"]);
            const float u[3] = {numf(c["input"]["u"][0]), numf(c["input"]["u"][1]), numf(c["input"]["u"][2])};
            pgloss_sample_record r;
            r.wi = pgloss_vec3{kNaNf, kNaNf, kNaNf};
            r.pdf = -1;
            r.weight = pgloss_rgb{-1, -1, -1};
            r.lobe = 77;
            const pgloss_status st = call(&m, wo, u, c["input"]["lobes"].get<unsigned>(), &r);
            check_status(fn, c, st);
            const double wi[3] = {r.wi.x, r.wi.y, r.wi.z}, w[3] = {r.weight.r, r.weight.g, r.weight.b};
            check_sample(*doc, fn, c, wi, r.pdf, w, r.lobe);
        } catch (const std::exception &e) {
            ADD_FAILURE() << case_id(c) << ": malformed case: " << e.what();
        }
    }
}

TEST(Vectors, sample_scalar) { sample_cases("sample", pgloss_sample); }

// pgloss/inline.h's sampler as C++ and as C99.
TEST(Vectors, sample_inline) {
    sample_cases("sample_inline", [](const pgloss_material *m, pgloss_vec3 wo, const float u[3], unsigned lobes,
                                     pgloss_sample_record *s) { return pgloss_sample_inline(m, wo, u, lobes, s); });
    sample_cases("sample_inline (C99)", pgloss_test_sample_inline_c99);
}

TEST(Vectors, sample_batch) {
    const json *doc = doc_or_fail("brdf_sample.json");
    if (!doc) return;
    const auto mats = materials_of(*doc);
    int groups = 0;
    for (const auto &kv : groups_of(*doc)) {
        const std::vector<const json *> &cs = kv.second;
        const size_t n = cs.size();
        const pgloss_material &m = mats.at(kv.first.first);
        const unsigned lobes = kv.first.second;
        SoA ox(n, 0), oy(n, 0), oz(n, 0), u0(n, 0), u1(n, 0), u2(n, 0);
        for (size_t k = 0; k < n; ++k) {
            const json &in = (*cs[k])["input"];
            const pgloss_vec3 wo = vec3(in["wo"]);
            ox.p()[k] = wo.x, oy.p()[k] = wo.y, oz.p()[k] = wo.z;
            u0.p()[k] = numf(in["u"][0]), u1.p()[k] = numf(in["u"][1]), u2.p()[k] = numf(in["u"][2]);
        }
        const std::string want = first_error(cs);
        for (int with_lobe = 0; with_lobe < 2; ++with_lobe) {
            SoA wx(n, kNaN), wy(n, kNaN), wz(n, kNaN), pdf(n, -1), gr(n, -1), gg(n, -1), gb(n, -1);
            std::vector<unsigned char> lobe(n + 1, 77);
            const pgloss_status st = pgloss_sample_batch(
                nullptr, &m, nullptr, lobes, n, soa(ox.p(), oy.p(), oz.p()), soa(u0.p(), u1.p(), u2.p()),
                soa_out(wx.p(), wy.p(), wz.p()), col_out(pdf.p()), soa_out(gr.p(), gg.p(), gb.p()),
                with_lobe ? lobe.data() + 1 : nullptr, nullptr);
            EXPECT_EQ(std::string(pgloss_status_name(st)), want) << "sample_batch group " << kv.first.first << "/" << lobes;
            if (!with_lobe) continue;  // the NULL-lobe call only has to run; values are checked below
            for (size_t k = 0; k < n; ++k) {
                const double wi[3] = {wx.p()[k], wy.p()[k], wz.p()[k]}, w[3] = {gr.p()[k], gg.p()[k], gb.p()[k]};
                check_sample(*doc, "sample_batch", *cs[k], wi, pdf.p()[k], w, lobe[k + 1]);
            }
            EXPECT_EQ(lobe[0], 77) << "sample_batch wrote before the lobe array";
        }
        // One case per call, as in eval_pdf_batch: each case meets its own normalisation path.
        for (size_t k = 0; k < n; ++k) {
            float x = kNaN, y = kNaN, z = kNaN, p1 = -1, r = -1, g = -1, b = -1;
            unsigned char lb = 77;
            const pgloss_status st = pgloss_sample_batch(
                nullptr, &m, nullptr, lobes, 1, soa(ox.p() + k, oy.p() + k, oz.p() + k),
                soa(u0.p() + k, u1.p() + k, u2.p() + k), soa_out(&x, &y, &z), col_out(&p1), soa_out(&r, &g, &b), &lb,
                nullptr);
            EXPECT_EQ(std::string(pgloss_status_name(st)), (*cs[k])["status"].get<std::string>()) << case_id(*cs[k]) << " n=1";
            const double wi[3] = {x, y, z}, w[3] = {r, g, b};
            check_sample(*doc, "sample_batch (n=1)", *cs[k], wi, p1, w, lb);
        }
        ++groups;
    }
    EXPECT_GT(groups, 0);
}


// ------------------------------------------------------------------------------------------
// Per-element materials and the double path (pgloss/batch.h): every non-NULL case of
// brdf_eval.json / brdf_sample.json grouped by lobes only, so that one call holds many
// materials; float entry points at the file's float tolerance, the double ones at its double
// tolerance (relative 1e-12, the header's bound).

Tol tolerance_at(const json &doc, const std::string &fn, const std::string &out, const char *prec) {
    const json &t = doc["tolerance"].at(fn).at(out).at(prec);
    Tol r;
    r.rel = t.at("rel").get<double>();
    r.kappa_rel = t.at("kappa_rel").get<double>();
    r.abs = t.at("abs").get<double>();
    return r;
}

std::map<unsigned, std::vector<const json *>> lobe_groups_of(const json &doc) {
    std::map<unsigned, std::vector<const json *>> g;
    for (const auto &c : doc["cases"]) {
        if (c["input"].contains("null")) continue;
        g[c["input"]["lobes"].get<unsigned>()].push_back(&c);
    }
    return g;
}

// SoA material arrays (float and double) of the cases' materials, misaligned by one element.
struct MatArrays {
    std::vector<float> f[6];
    std::vector<double> d[6];
    int norm = 0;
    bool one_norm = true;
    MatArrays(const json &doc, const std::vector<const json *> &cs) {
        for (auto &v : f) v.push_back(0);
        for (auto &v : d) v.push_back(0);
        bool first = true;
        for (const json *c : cs) {
            const pgloss_physical p = physical_from(doc["materials"].at((*c)["input"]["material"].get<std::string>()));
            const double v[6] = {p.rho_d[0], p.rho_d[1], p.rho_d[2], p.rho_s, p.alpha_x, p.alpha_y};
            for (int k = 0; k < 6; ++k) {
                f[k].push_back(static_cast<float>(v[k]));
                d[k].push_back(v[k]);
            }
            if (first) norm = static_cast<int>(p.normalization);
            one_norm = one_norm && static_cast<int>(p.normalization) == norm;
            first = false;
        }
    }
    pgloss_physical_array fa(int nm) const {
        return physical_cols(f[0].data() + 1, f[1].data() + 1, f[2].data() + 1, f[3].data() + 1, f[4].data() + 1,
                             f[5].data() + 1, static_cast<pgloss_normalization>(nm));
    }
    pgloss_physical_array da(int nm) const {
        return physical_cols(d[0].data() + 1, d[1].data() + 1, d[2].data() + 1, d[3].data() + 1, d[4].data() + 1,
                             d[5].data() + 1, static_cast<pgloss_normalization>(nm));
    }
};

// Cases of one (lobes, normalisation): the arrays hold one normalisation per call.
std::map<std::pair<unsigned, int>, std::vector<const json *>> lobe_norm_groups_of(const json &doc) {
    std::map<std::pair<unsigned, int>, std::vector<const json *>> g;
    for (const auto &kv : lobe_groups_of(doc))
        for (const json *c : kv.second) {
            const int nm = doc["materials"].at((*c)["input"]["material"].get<std::string>()).at("normalization").get<int>();
            g[{kv.first, nm}].push_back(c);
        }
    return g;
}

TEST(Vectors, eval_pdf_batch_materials_and_double) {
    const json *doc = doc_or_fail("brdf_eval.json");
    if (!doc) return;
    int groups = 0;
    for (const auto &kv : lobe_norm_groups_of(*doc)) {
        const std::vector<const json *> &cs = kv.second;
        const size_t n = cs.size();
        const unsigned lobes = kv.first.first;
        const MatArrays ma(*doc, cs);
        SoA ox(n, 0), oy(n, 0), oz(n, 0), ix(n, 0), iy(n, 0), iz(n, 0);
        std::vector<double> dox(n + 1), doy(n + 1), doz(n + 1), dix(n + 1), diy(n + 1), diz(n + 1);
        for (size_t k = 0; k < n; ++k) {
            const pgloss_vec3 wo = vec3((*cs[k])["input"]["wo"]), wi = vec3((*cs[k])["input"]["wi"]);
            ox.p()[k] = wo.x, oy.p()[k] = wo.y, oz.p()[k] = wo.z;
            ix.p()[k] = wi.x, iy.p()[k] = wi.y, iz.p()[k] = wi.z;
            dox[k + 1] = wo.x, doy[k + 1] = wo.y, doz[k + 1] = wo.z;
            dix[k + 1] = wi.x, diy[k + 1] = wi.y, diz[k + 1] = wi.z;
        }
        const pgloss_strided3 wo = soa(ox.p(), oy.p(), oz.p()), wi = soa(ix.p(), iy.p(), iz.p());
        const double *dwo[3] = {dox.data() + 1, doy.data() + 1, doz.data() + 1},
                     *dwi[3] = {dix.data() + 1, diy.data() + 1, diz.data() + 1};
        const std::string want = first_error(cs);
        // float, per element
        {
            SoA fr(n, -1), fg(n, -1), fb(n, -1), pdf(n, -1);
            std::vector<signed char> st(n, 99);
            const pgloss_physical_array m = ma.fa(kv.first.second);
            const pgloss_status r = pgloss_eval_pdf_batch(nullptr, nullptr, &m, lobes, n, wo, wi,
                                                          soa_out(fr.p(), fg.p(), fb.p()), col_out(pdf.p()), st.data());
            EXPECT_EQ(std::string(pgloss_status_name(r)), want) << "eval_pdf_batch_materials lobes " << lobes;
            for (size_t k = 0; k < n; ++k) {
                const json &c = *cs[k];
                check_status("eval_pdf_batch_materials", c, static_cast<pgloss_status>(st[k]));
                const bool s = sanity_float(*doc, c);
                const double got[3] = {fr.p()[k], fg.p()[k], fb.p()[k]};
                for (int j = 0; j < 3; ++j)
                    check("eval_pdf_batch_materials", "f", c, got[j], c["expected"]["f"][static_cast<size_t>(j)],
                          sens_at(c, "f", j), tolerance(*doc, "eval_pdf", "f"), s, true);
                check("eval_pdf_batch_materials", "pdf", c, pdf.p()[k], c["expected"]["pdf"], sens_at(c, "pdf", -1),
                      tolerance(*doc, "eval_pdf", "pdf"), s, true);
            }
        }
        // double: one material per call (each case's own), and per element
        for (int per_element = 0; per_element < 2; ++per_element) {
            const char *fn = per_element ? "eval_pdf_batch_materials_d" : "eval_pdf_batch_d";
            std::vector<double> fr(n, -1), fg(n, -1), fb(n, -1), pdf(n, -1);
            std::vector<signed char> st(n, 99);
            if (per_element) {
                const pgloss_physical_array m = ma.da(kv.first.second);
                const pgloss_status r = pgloss_eval_pdf_batch(
                    f64_options(), nullptr, &m, lobes, n, soa(dwo[0], dwo[1], dwo[2]), soa(dwi[0], dwi[1], dwi[2]),
                    soa_out(fr.data(), fg.data(), fb.data()), col_out(pdf.data()), st.data());
                EXPECT_EQ(std::string(pgloss_status_name(r)), want) << fn << " lobes " << lobes;
            } else {
                for (size_t k = 0; k < n; ++k) {
                    pgloss_material m;
                    const pgloss_physical p = physical_from((*doc)["materials"].at((*cs[k])["input"]["material"].get<std::string>()));
                    ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
                    const pgloss_status r = pgloss_eval_pdf_batch(
                        f64_options(), &m, nullptr, lobes, 1, soa(dwo[0] + k, dwo[1] + k, dwo[2] + k),
                        soa(dwi[0] + k, dwi[1] + k, dwi[2] + k), soa_out(&fr[k], &fg[k], &fb[k]), col_out(&pdf[k]),
                        &st[k]);
                    EXPECT_EQ(r, static_cast<pgloss_status>(st[k]));
                }
            }
            for (size_t k = 0; k < n; ++k) {
                const json &c = *cs[k];
                check_status(fn, c, static_cast<pgloss_status>(st[k]));
                const double got[3] = {fr[k], fg[k], fb[k]};
                for (int j = 0; j < 3; ++j)
                    check(fn, "f", c, got[j], c["expected"]["f"][static_cast<size_t>(j)], sens_at(c, "f", j),
                          tolerance_at(*doc, "eval_pdf", "f", "double"), false, true);
                check(fn, "pdf", c, pdf[k], c["expected"]["pdf"], sens_at(c, "pdf", -1),
                      tolerance_at(*doc, "eval_pdf", "pdf", "double"), false, true);
            }
        }
        ++groups;
    }
    EXPECT_GT(groups, 0);
}

TEST(Vectors, sample_batch_materials_and_double) {
    const json *doc = doc_or_fail("brdf_sample.json");
    if (!doc) return;
    int groups = 0;
    for (const auto &kv : lobe_norm_groups_of(*doc)) {
        const std::vector<const json *> &cs = kv.second;
        const size_t n = cs.size();
        const unsigned lobes = kv.first.first;
        const MatArrays ma(*doc, cs);
        SoA ox(n, 0), oy(n, 0), oz(n, 0), u0(n, 0), u1(n, 0), u2(n, 0);
        std::vector<double> d[6];
        for (auto &v : d) v.assign(n + 1, 0.0);
        for (size_t k = 0; k < n; ++k) {
            const json &in = (*cs[k])["input"];
            const pgloss_vec3 wo = vec3(in["wo"]);
            ox.p()[k] = wo.x, oy.p()[k] = wo.y, oz.p()[k] = wo.z;
            u0.p()[k] = numf(in["u"][0]), u1.p()[k] = numf(in["u"][1]), u2.p()[k] = numf(in["u"][2]);
            d[0][k + 1] = wo.x, d[1][k + 1] = wo.y, d[2][k + 1] = wo.z;
            d[3][k + 1] = u0.p()[k], d[4][k + 1] = u1.p()[k], d[5][k + 1] = u2.p()[k];
        }
        const std::string want = first_error(cs);
        {
            SoA wx(n, kNaN), wy(n, kNaN), wz(n, kNaN), pdf(n, -1), gr(n, -1), gg(n, -1), gb(n, -1);
            std::vector<unsigned char> lobe(n, 77);
            std::vector<signed char> st(n, 99);
            const pgloss_physical_array m = ma.fa(kv.first.second);
            const pgloss_status r = pgloss_sample_batch(
                nullptr, nullptr, &m, lobes, n, soa(ox.p(), oy.p(), oz.p()), soa(u0.p(), u1.p(), u2.p()),
                soa_out(wx.p(), wy.p(), wz.p()), col_out(pdf.p()), soa_out(gr.p(), gg.p(), gb.p()), lobe.data(),
                st.data());
            EXPECT_EQ(std::string(pgloss_status_name(r)), want) << "sample_batch_materials lobes " << lobes;
            for (size_t k = 0; k < n; ++k) {
                check_status("sample_batch_materials", *cs[k], static_cast<pgloss_status>(st[k]));
                const double wi[3] = {wx.p()[k], wy.p()[k], wz.p()[k]}, w[3] = {gr.p()[k], gg.p()[k], gb.p()[k]};
                check_sample(*doc, "sample_batch_materials", *cs[k], wi, pdf.p()[k], w, lobe[k]);
            }
        }
        {
            std::vector<double> wx(n, kNaN), wy(n, kNaN), wz(n, kNaN), pdf(n, -1), gr(n, -1), gg(n, -1), gb(n, -1);
            std::vector<unsigned char> lobe(n, 77);
            std::vector<signed char> st(n, 99);
            const pgloss_physical_array m = ma.da(kv.first.second);
            const pgloss_status r = pgloss_sample_batch(
                f64_options(), nullptr, &m, lobes, n, soa(d[0].data() + 1, d[1].data() + 1, d[2].data() + 1),
                soa(d[3].data() + 1, d[4].data() + 1, d[5].data() + 1), soa_out(wx.data(), wy.data(), wz.data()),
                col_out(pdf.data()), soa_out(gr.data(), gg.data(), gb.data()), lobe.data(), st.data());
            EXPECT_EQ(std::string(pgloss_status_name(r)), want) << "sample_batch_materials_d lobes " << lobes;
            for (size_t k = 0; k < n; ++k) {
                const json &c = *cs[k];
                check_status("sample_batch_materials_d", c, static_cast<pgloss_status>(st[k]));
                const json &e = c["expected"];
                const char *fn = "sample_batch_materials_d";
                for (int j = 0; j < 3; ++j) {
                    const size_t jj = static_cast<size_t>(j);
                    const double wi[3] = {wx[k], wy[k], wz[k]}, w[3] = {gr[k], gg[k], gb[k]};
                    check(fn, "wi", c, wi[j], e["wi"].is_null() ? json() : e["wi"][jj], sens_at(c, "wi", j),
                          tolerance_at(*doc, "sample", "wi", "double"));
                    check(fn, "weight", c, w[j], e["weight"][jj], sens_at(c, "weight", j),
                          tolerance_at(*doc, "sample", "weight", "double"), false, true);
                }
                check(fn, "pdf", c, pdf[k], e["pdf"], sens_at(c, "pdf", -1), tolerance_at(*doc, "sample", "pdf", "double"),
                      false, true);
                if (!e["lobe"].is_null()) {
                    EXPECT_EQ(lobe[k], lobe_value(e["lobe"].get<std::string>())) << case_id(c) << " " << fn << " lobe";
                }
            }
        }
        ++groups;
    }
    EXPECT_GT(groups, 0);
}


// ------------------------------------------------------------------------------------------
// The batched perceptual and colour functions (pgloss/perceptual_batch.h): all non-NULL cases
// of a function in one call (per colour space / normalisation where the function takes one,
// arrays misaligned by one element), each element's status and outputs against the vectors at
// the scalar functions' tolerance; the returned status is the first error, else the first
// warning.

std::string batch_summary(const std::vector<const json *> &cs) {
    std::string warn;
    for (const json *c : cs) {
        const std::string st = (*c)["status"].get<std::string>();
        const pgloss_status v = st == "PGLOSS_OK" ? PGLOSS_OK : st == "PGLOSS_WARN_ALPHA_UNTRUSTED" ? PGLOSS_WARN_ALPHA_UNTRUSTED : PGLOSS_ERR_NULL;
        if (v == PGLOSS_ERR_NULL) return st;
        if (v > 0 && warn.empty()) warn = st;
    }
    return warn.empty() ? "PGLOSS_OK" : warn;
}

// Cases of fn in file, without NULL arguments, grouped by key(c).
template <class K>
std::map<int, std::vector<const json *>> batch_groups(const json &doc, const char *fn, K key) {
    std::map<int, std::vector<const json *>> g;
    for (const auto &c : doc["cases"])
        if (c.value("function", std::string()) == fn && !c["input"].contains("null") && key(c) >= 0)
            g[key(c)].push_back(&c);
    return g;
}

// n doubles (one element of padding in front).
struct Col {
    std::vector<double> v;
    explicit Col(size_t n, double fill = kNaN) : v(n + 1, fill) {}
    double *p() { return v.data() + 1; }
};

template <class Run>
void batch_cases(const char *file, const char *fn, int (*key)(const json &), Run run) {
    const json *doc = doc_or_fail(file);
    if (!doc) return;
    int groups = 0;
    for (const auto &kv : batch_groups(*doc, fn, key)) {
        const auto &cs = kv.second;
        std::vector<signed char> st(cs.size(), 99);
        const pgloss_status r = run(*doc, kv.first, cs, st.data());
        const std::string want = batch_summary(cs);
        EXPECT_EQ(std::string(pgloss_status_name(r)), want) << fn << "_batch group " << kv.first;
        for (size_t k = 0; k < cs.size(); ++k)
            check_status(std::string(fn) + "_batch", *cs[k], static_cast<pgloss_status>(st[k]));
        ++groups;
    }
    EXPECT_GT(groups, 0) << fn;
}

int no_key(const json &) { return 0; }
bool known_space(int s) { return s >= 0 && s <= 3; }
bool known_norm(int n) { return n >= 0 && n <= 2; }
// Unknown colour spaces are errors of the whole call (header): -1 leaves those cases out of
// the groups; PerceptualBatch.EmptyAndWholeCallErrors covers them. An unknown normalisation
// is an element's status, as in the scalar function (one group for all of them).
int space_key(const json &c) {
    const int s = c["input"]["space"].get<int>();
    return known_space(s) ? s : -1;
}
int norm_key(const json &c) {
    const int n = c["input"]["normalization"].get<int>();
    return known_norm(n) ? n : 3;
}
int space_norm_key(const json &c) {
    const int s = space_key(c), n = norm_key(c);
    return s < 0 || n < 0 ? -1 : 16 * s + n;
}

TEST(Vectors, gloss_batches) {
    batch_cases("gloss.json", "gloss_from_physical", no_key, [](const json &doc, int, const std::vector<const json *> &cs, signed char *st) {
        const size_t n = cs.size();
        Col rd(n), rs(n), al(n), L(n), c(n), d(n);
        for (size_t k = 0; k < n; ++k) {
            const json &in = (*cs[k])["input"];
            rd.p()[k] = num(in["rho_d"]), rs.p()[k] = num(in["rho_s"]), al.p()[k] = num(in["alpha"]);
        }
        const pgloss_status r = pgloss_gloss_from_physical_batch(n, col(rd.p()), col(rs.p()), col(al.p()), col_out(L.p()),
                                                                 col_out(c.p()), col_out(d.p()), st);
        for (size_t k = 0; k < n; ++k) {
            check_d(doc, "gloss_from_physical", "L", *cs[k], L.p()[k]);
            check_d(doc, "gloss_from_physical", "c", *cs[k], c.p()[k]);
            check_d(doc, "gloss_from_physical", "d", *cs[k], d.p()[k]);
        }
        return r;
    });
    batch_cases("gloss.json", "physical_from_gloss", no_key, [](const json &doc, int, const std::vector<const json *> &cs, signed char *st) {
        const size_t n = cs.size();
        Col L(n), c(n), d(n), rd(n), rs(n), al(n);
        for (size_t k = 0; k < n; ++k) {
            const json &in = (*cs[k])["input"];
            L.p()[k] = num(in["L"]), c.p()[k] = num(in["c"]), d.p()[k] = num(in["d"]);
        }
        const pgloss_status r = pgloss_physical_from_gloss_batch(n, col(L.p()), col(c.p()), col(d.p()), col_out(rd.p()),
                                                                 col_out(rs.p()), col_out(al.p()), st);
        for (size_t k = 0; k < n; ++k) {
            check_d(doc, "physical_from_gloss", "rho_d", *cs[k], rd.p()[k]);
            check_d(doc, "physical_from_gloss", "rho_s", *cs[k], rs.p()[k]);
            check_d(doc, "physical_from_gloss", "alpha", *cs[k], al.p()[k]);
        }
        return r;
    });
    batch_cases("gloss.json", "envelope_contrast", no_key, [](const json &doc, int, const std::vector<const json *> &cs, signed char *st) {
        const size_t n = cs.size();
        Col L(n), cm(n);
        for (size_t k = 0; k < n; ++k) L.p()[k] = num((*cs[k])["input"]["L"]);
        const pgloss_status r = pgloss_envelope_contrast_batch(n, col(L.p()), col_out(cm.p()), st);
        for (size_t k = 0; k < n; ++k) check_d(doc, "envelope_contrast", "c_max", *cs[k], cm.p()[k]);
        return r;
    });
    batch_cases("gloss.json", "match_gloss", no_key, [](const json &doc, int, const std::vector<const json *> &cs, signed char *st) {
        const size_t n = cs.size();
        Col rd(n), rs(n), L(n), od(n), os(n);
        for (size_t k = 0; k < n; ++k) {
            const json &in = (*cs[k])["input"];
            rd.p()[k] = num(in["rho_d"]), rs.p()[k] = num(in["rho_s"]), L.p()[k] = num(in["L_target"]);
        }
        const pgloss_status r = pgloss_match_gloss_batch(n, col(rd.p()), col(rs.p()), col(L.p()), col_out(od.p()),
                                                         col_out(os.p()), st);
        for (size_t k = 0; k < n; ++k) {
            check_d(doc, "match_gloss", "rho_d_out", *cs[k], od.p()[k]);
            check_d(doc, "match_gloss", "rho_s_out", *cs[k], os.p()[k]);
        }
        return r;
    });
}

template <bool Ex>
pgloss_status rgb_from_lab_run(const json &doc, int space, const std::vector<const json *> &cs, signed char *st) {
    const size_t n = cs.size();
    Col L(n), a(n), b(n), R(n), G(n), B(n);
    for (size_t k = 0; k < n; ++k) {
        const json &in = (*cs[k])["input"]["lab"];
        L.p()[k] = num(in[0]), a.p()[k] = num(in[1]), b.p()[k] = num(in[2]);
    }
    const pgloss_status r = pgloss_rgb_from_lab_batch(n, soa(L.p(), a.p(), b.p()), static_cast<pgloss_color_space>(space),
                                                      soa_out(R.p(), G.p(), B.p()), st);
    const char *fn = Ex ? "rgb_from_lab_ex" : "rgb_from_lab";
    for (size_t k = 0; k < n; ++k) {
        const double got[3] = {R.p()[k], G.p()[k], B.p()[k]};
        check_d3(doc, fn, "rgb", *cs[k], got);
    }
    return r;
}

template <bool Ex>
pgloss_status lab_from_rgb_run(const json &doc, int space, const std::vector<const json *> &cs, signed char *st) {
    const size_t n = cs.size();
    Col R(n), G(n), B(n), L(n), a(n), b(n);
    for (size_t k = 0; k < n; ++k) {
        const json &in = (*cs[k])["input"]["rgb"];
        R.p()[k] = num(in[0]), G.p()[k] = num(in[1]), B.p()[k] = num(in[2]);
    }
    const pgloss_status r = pgloss_lab_from_rgb_batch(n, soa(R.p(), G.p(), B.p()), static_cast<pgloss_color_space>(space),
                                                      soa_out(L.p(), a.p(), b.p()), st);
    const char *fn = Ex ? "lab_from_rgb_ex" : "lab_from_rgb";
    for (size_t k = 0; k < n; ++k) {
        const double got[3] = {L.p()[k], a.p()[k], b.p()[k]};
        check_d3(doc, fn, "lab", *cs[k], got);
    }
    return r;
}

TEST(Vectors, color_batches) {
    batch_cases("color.json", "rgb_from_lab", no_key, rgb_from_lab_run<false>);
    batch_cases("color.json", "lab_from_rgb", no_key, lab_from_rgb_run<false>);
    batch_cases("color_space.json", "rgb_from_lab_ex", space_key, rgb_from_lab_run<true>);
    batch_cases("color_space.json", "lab_from_rgb_ex", space_key, lab_from_rgb_run<true>);
    double x = 50, y = 0;
    double o = kNaN;
    EXPECT_EQ(pgloss_rgb_from_lab_batch(1, soa(&x, &y, &y), static_cast<pgloss_color_space>(9), soa_out(&o, &o, &o),
                                        nullptr),
              PGLOSS_ERR_ARGUMENT);
    EXPECT_TRUE(std::isnan(o)) << "nothing written for an unknown space";
}

pgloss_physical_array physical_array_of(const std::vector<const json *> &cs, Col *cols, int norm) {
    for (size_t k = 0; k < cs.size(); ++k) {
        const pgloss_physical p = physical_from((*cs[k])["input"]["p"]);
        const double v[6] = {p.rho_d[0], p.rho_d[1], p.rho_d[2], p.rho_s, p.alpha_x, p.alpha_y};
        for (int j = 0; j < 6; ++j) cols[j].p()[k] = v[j];
    }
    return physical_cols(cols[0].p(), cols[1].p(), cols[2].p(), cols[3].p(), cols[4].p(), cols[5].p(),
                         static_cast<pgloss_normalization>(norm));
}

int physical_norm_key(const json &c) { return c["input"]["p"]["normalization"].get<int>(); }

template <bool Ex>
pgloss_status perceptual_from_physical_run(const json &doc, int key, const std::vector<const json *> &cs, signed char *st) {
    const size_t n = cs.size();
    std::vector<Col> cols(6, Col(n));
    const pgloss_physical_array pa = physical_array_of(cs, cols.data(), key % 16);
    Col L(n), a(n), b(n), c(n), d(n);
    const pgloss_perceptual_array_out q = perceptual_cols_out(L.p(), a.p(), b.p(), c.p(), d.p());
    const int space = key / 16;
    const pgloss_status r = pgloss_perceptual_from_physical_batch(n, &pa, static_cast<pgloss_color_space>(space), &q, st);
    const char *fn = Ex ? "perceptual_from_physical_ex" : "perceptual_from_physical";
    for (size_t k = 0; k < n; ++k) {
        check_d(doc, fn, "L", *cs[k], L.p()[k]);
        check_d(doc, fn, "a", *cs[k], a.p()[k]);
        check_d(doc, fn, "b", *cs[k], b.p()[k]);
        check_d(doc, fn, "c", *cs[k], c.p()[k]);
        check_d(doc, fn, "d", *cs[k], d.p()[k]);
    }
    return r;
}

template <bool Ex>
pgloss_status physical_from_perceptual_run(const json &doc, int key, const std::vector<const json *> &cs, signed char *st) {
    const size_t n = cs.size();
    Col L(n), a(n), b(n), c(n), d(n);
    for (size_t k = 0; k < n; ++k) {
        const pgloss_perceptual q = perceptual_from((*cs[k])["input"]["q"]);
        L.p()[k] = q.L, a.p()[k] = q.a, b.p()[k] = q.b, c.p()[k] = q.c, d.p()[k] = q.d;
    }
    Col R(n), G(n), B(n), S(n), AX(n), AY(n);
    const pgloss_physical_array_out p = physical_cols_out(R.p(), G.p(), B.p(), S.p(), AX.p(), AY.p());
    const int space = key / 16, norm = key % 16 == 3 ? 7 : key % 16;  // 3: unknown
    const pgloss_perceptual_array q = perceptual_cols(L.p(), a.p(), b.p(), c.p(), d.p());
    const pgloss_status r = pgloss_physical_from_perceptual_batch(n, &q, static_cast<pgloss_normalization>(norm),
                                                                  static_cast<pgloss_color_space>(space), &p, st);
    const char *fn = Ex ? "physical_from_perceptual_ex" : "physical_from_perceptual";
    for (size_t k = 0; k < n; ++k) {
        const json &e = (*cs[k])["expected"];
        if (!e.contains("rho_d")) continue;
        const double rd[3] = {R.p()[k], G.p()[k], B.p()[k]};
        check_d3(doc, fn, "rho_d", *cs[k], rd);
        check_d(doc, fn, "rho_s", *cs[k], S.p()[k]);
        check_d(doc, fn, "alpha_x", *cs[k], AX.p()[k]);
        check_d(doc, fn, "alpha_y", *cs[k], AY.p()[k]);
    }
    return r;
}

TEST(Vectors, validity_and_material_batches) {
    batch_cases("validity.json", "check_physical", physical_norm_key,
                [](const json &, int norm, const std::vector<const json *> &cs, signed char *st) {
                    std::vector<Col> cols(6, Col(cs.size()));
                    const pgloss_physical_array pa = physical_array_of(cs, cols.data(), norm);
                    return pgloss_check_physical_batch(cs.size(), &pa, st);
                });
    batch_cases("validity.json", "check_perceptual", no_key,
                [](const json &, int, const std::vector<const json *> &cs, signed char *st) {
                    const size_t n = cs.size();
                    Col L(n), a(n), b(n), c(n), d(n);
                    for (size_t k = 0; k < n; ++k) {
                        const pgloss_perceptual q = perceptual_from((*cs[k])["input"]["q"]);
                        L.p()[k] = q.L, a.p()[k] = q.a, b.p()[k] = q.b, c.p()[k] = q.c, d.p()[k] = q.d;
                    }
                    const pgloss_perceptual_array q = perceptual_cols(L.p(), a.p(), b.p(), c.p(), d.p());
                    return pgloss_check_perceptual_batch(n, &q, PGLOSS_COLOR_SPACE_LINEAR_REC709, st);
                });
    batch_cases("perceptual_material.json", "perceptual_from_physical", physical_norm_key,
                perceptual_from_physical_run<false>);
    batch_cases("perceptual_material.json", "physical_from_perceptual", norm_key,
                physical_from_perceptual_run<false>);
    batch_cases("color_space.json", "physical_from_perceptual_ex", space_norm_key, physical_from_perceptual_run<true>);
    batch_cases("color_space.json", "perceptual_from_physical_ex",
                [](const json &c) {
                    const int s = space_key(c);
                    return s < 0 ? -1 : 16 * s + c["input"]["p"]["normalization"].get<int>();
                },
                perceptual_from_physical_run<true>);
    batch_cases("color_space.json", "check_perceptual_ex", space_key,
                [](const json &, int space, const std::vector<const json *> &cs, signed char *st) {
                    const size_t n = cs.size();
                    Col L(n), a(n), b(n), c(n), d(n);
                    for (size_t k = 0; k < n; ++k) {
                        const pgloss_perceptual q = perceptual_from((*cs[k])["input"]["q"]);
                        L.p()[k] = q.L, a.p()[k] = q.a, b.p()[k] = q.b, c.p()[k] = q.c, d.p()[k] = q.d;
                    }
                    const pgloss_perceptual_array q = perceptual_cols(L.p(), a.p(), b.p(), c.p(), d.p());
                    return pgloss_check_perceptual_batch(n, &q, static_cast<pgloss_color_space>(space), st);
                });
}

// Scalar and batch agree bit for bit (perceptual_batch.h): the batches run the scalar
// functions' per-element code (libpgloss/src/perceptual_d.h), vectorised on the best ISA of
// this CPU; every case of the vector files goes through both, in one batch per file and
// function, and every output and status must be identical, not merely within tolerance.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::vector<const json *> cases_of(const json &doc, const char *fn) {
    std::vector<const json *> out;
    for (const json &c : doc["cases"])
        if (c["function"] == fn) out.push_back(&c);
    return out;
}

TEST(Vectors, batch_equals_scalar_bit_for_bit) {
    int compared = 0;
    if (const json *doc = doc_or_fail("gloss.json")) {
        const auto cs = cases_of(*doc, "gloss_from_physical");
        const size_t n = cs.size();
        Col rd(n), rs(n), al(n), L(n), c(n), d(n);
        std::vector<signed char> st(n);
        for (size_t k = 0; k < n; ++k) {
            const json &in = (*cs[k])["input"];
            rd.p()[k] = num(in["rho_d"]), rs.p()[k] = num(in["rho_s"]), al.p()[k] = num(in["alpha"]);
        }
        pgloss_gloss_from_physical_batch(n, col(rd.p()), col(rs.p()), col(al.p()), col_out(L.p()), col_out(c.p()),
                                         col_out(d.p()), st.data());
        for (size_t k = 0; k < n; ++k, ++compared) {
            double l, cc, dd;
            const pgloss_status want = pgloss_gloss_from_physical(rd.p()[k], rs.p()[k], al.p()[k], &l, &cc, &dd);
            EXPECT_EQ(int(st[k]), int(want)) << case_id(*cs[k]);
            EXPECT_TRUE(same_bits(L.p()[k], l) && same_bits(c.p()[k], cc) && same_bits(d.p()[k], dd))
                << case_id(*cs[k]);
        }
    }
    // physical_from_perceptual(_ex): both files, every known space and normalisation.
    for (const char *file : {"perceptual_material.json", "color_space.json"}) {
        const json *doc = doc_or_fail(file);
        if (!doc) continue;
        const bool ex = std::string(file) == "color_space.json";
        for (const json *cp : cases_of(*doc, ex ? "physical_from_perceptual_ex" : "physical_from_perceptual")) {
            const json &in = (*cp)["input"];
            const int norm = in["normalization"].get<int>(), space = ex ? in["space"].get<int>() : 0;
            if (!known_space(space)) continue;  // a whole-call error
            const pgloss_perceptual v = perceptual_from(in["q"]);
            double r, g, b, s, ax, ay;
            signed char st = 99;
            const pgloss_perceptual_array q = perceptual_cols(&v.L, &v.a, &v.b, &v.c, &v.d);
            const pgloss_physical_array_out p = physical_cols_out(&r, &g, &b, &s, &ax, &ay);
            pgloss_physical_from_perceptual_batch(1, &q, static_cast<pgloss_normalization>(norm),
                                                  static_cast<pgloss_color_space>(space), &p, &st);
            pgloss_physical o;
            const pgloss_status want = pgloss_physical_from_perceptual_ex(
                &v, static_cast<pgloss_normalization>(norm), static_cast<pgloss_color_space>(space), &o);
            EXPECT_EQ(int(st), int(want)) << case_id(*cp);
            EXPECT_TRUE(same_bits(r, o.rho_d[0]) && same_bits(g, o.rho_d[1]) && same_bits(b, o.rho_d[2]) &&
                        same_bits(s, o.rho_s) && same_bits(ax, o.alpha_x) && same_bits(ay, o.alpha_y))
                << case_id(*cp);
            ++compared;
        }
    }
    // rgb_from_lab: the same per-element code as physical_from_perceptual's colour.
    if (const json *doc = doc_or_fail("color.json")) {
        for (const json *cp : cases_of(*doc, "rgb_from_lab")) {
            const json &lab = (*cp)["input"]["lab"];
            const double in[3] = {num(lab[0]), num(lab[1]), num(lab[2])};
            double r, g, b, want_rgb[3];
            signed char st = 99;
            pgloss_rgb_from_lab_batch(1, soa(&in[0], &in[1], &in[2]), PGLOSS_COLOR_SPACE_LINEAR_REC709,
                                      soa_out(&r, &g, &b), &st);
            const pgloss_status want = pgloss_rgb_from_lab(in, want_rgb);
            EXPECT_EQ(int(st), int(want)) << case_id(*cp);
            EXPECT_TRUE(same_bits(r, want_rgb[0]) && same_bits(g, want_rgb[1]) && same_bits(b, want_rgb[2]))
                << case_id(*cp);
            ++compared;
        }
    }
    // The other batches, one case per call (each its own normalisation / space).
    if (const json *doc = doc_or_fail("gloss.json")) {
        for (const json *cp : cases_of(*doc, "physical_from_gloss")) {
            const json &in = (*cp)["input"];
            if (in.contains("null")) continue;
            const double L = num(in["L"]), c = num(in["c"]), d = num(in["d"]);
            double o[3], w[3];
            signed char st = 99;
            pgloss_physical_from_gloss_batch(1, col(&L), col(&c), col(&d), col_out(&o[0]), col_out(&o[1]),
                                             col_out(&o[2]), &st);
            EXPECT_EQ(int(st), int(pgloss_physical_from_gloss(L, c, d, &w[0], &w[1], &w[2]))) << case_id(*cp);
            EXPECT_TRUE(same_bits(o[0], w[0]) && same_bits(o[1], w[1]) && same_bits(o[2], w[2])) << case_id(*cp);
            ++compared;
        }
        for (const json *cp : cases_of(*doc, "envelope_contrast")) {
            const json &in = (*cp)["input"];
            if (in.contains("null")) continue;
            const double L = num(in["L"]);
            double o, w;
            signed char st = 99;
            pgloss_envelope_contrast_batch(1, col(&L), col_out(&o), &st);
            EXPECT_EQ(int(st), int(pgloss_envelope_contrast(L, &w))) << case_id(*cp);
            EXPECT_TRUE(same_bits(o, w)) << case_id(*cp);
            ++compared;
        }
        for (const json *cp : cases_of(*doc, "match_gloss")) {
            const json &in = (*cp)["input"];
            if (in.contains("null")) continue;
            const double rd = num(in["rho_d"]), rs = num(in["rho_s"]), L = num(in["L_target"]);
            double o[2], w[2];
            signed char st = 99;
            pgloss_match_gloss_batch(1, col(&rd), col(&rs), col(&L), col_out(&o[0]), col_out(&o[1]), &st);
            EXPECT_EQ(int(st), int(pgloss_match_gloss(rd, rs, L, &w[0], &w[1]))) << case_id(*cp);
            EXPECT_TRUE(same_bits(o[0], w[0]) && same_bits(o[1], w[1])) << case_id(*cp);
            ++compared;
        }
    }
    if (const json *doc = doc_or_fail("validity.json")) {
        for (const json *cp : cases_of(*doc, "check_physical")) {
            const json &in = (*cp)["input"];
            if (in.contains("null")) continue;
            const pgloss_physical p = physical_from(in["p"]);
            // the normalisation from the int (an unknown one read back as the enum is UB in C++)
            const pgloss_physical_array pa =
                physical_cols(&p.rho_d[0], &p.rho_d[1], &p.rho_d[2], &p.rho_s, &p.alpha_x, &p.alpha_y,
                              static_cast<pgloss_normalization>(in["p"]["normalization"].get<int>()));
            signed char st = 99;
            pgloss_check_physical_batch(1, &pa, &st);
            EXPECT_EQ(int(st), int(pgloss_check_physical(&p))) << case_id(*cp);
            ++compared;
        }
    }
    for (const char *file : {"validity.json", "color_space.json"}) {
        const json *doc = doc_or_fail(file);
        if (!doc) continue;
        const bool ex = std::string(file) == "color_space.json";
        for (const json *cp : cases_of(*doc, ex ? "check_perceptual_ex" : "check_perceptual")) {
            const json &in = (*cp)["input"];
            const int space = ex ? in["space"].get<int>() : 0;
            if (in.contains("null") || !known_space(space)) continue;
            const pgloss_perceptual v = perceptual_from(in["q"]);
            signed char st = 99;
            const auto sp = static_cast<pgloss_color_space>(space);
            const pgloss_perceptual_array q = perceptual_cols(&v.L, &v.a, &v.b, &v.c, &v.d);
            pgloss_check_perceptual_batch(1, &q, sp, &st);
            EXPECT_EQ(int(st), int(pgloss_check_perceptual_ex(&v, sp))) << case_id(*cp);
            ++compared;
        }
    }
    for (const char *file : {"perceptual_material.json", "color_space.json"}) {
        const json *doc = doc_or_fail(file);
        if (!doc) continue;
        const bool ex = std::string(file) == "color_space.json";
        for (const json *cp : cases_of(*doc, ex ? "perceptual_from_physical_ex" : "perceptual_from_physical")) {
            const json &in = (*cp)["input"];
            const int space = ex ? in["space"].get<int>() : 0;
            if (in.contains("null") || !known_space(space)) continue;
            const pgloss_physical p = physical_from(in["p"]);
            // the normalisation from the int (an unknown one read back as the enum is UB in C++)
            const pgloss_physical_array pa =
                physical_cols(&p.rho_d[0], &p.rho_d[1], &p.rho_d[2], &p.rho_s, &p.alpha_x, &p.alpha_y,
                              static_cast<pgloss_normalization>(in["p"]["normalization"].get<int>()));
            double L, a, b, c, d;
            signed char st = 99;
            const auto sp = static_cast<pgloss_color_space>(space);
            const pgloss_perceptual_array_out q = perceptual_cols_out(&L, &a, &b, &c, &d);
            pgloss_perceptual_from_physical_batch(1, &pa, sp, &q, &st);
            pgloss_perceptual o;
            EXPECT_EQ(int(st), int(pgloss_perceptual_from_physical_ex(&p, sp, &o))) << case_id(*cp);
            EXPECT_TRUE(same_bits(L, o.L) && same_bits(a, o.a) && same_bits(b, o.b) && same_bits(c, o.c) &&
                        same_bits(d, o.d))
                << case_id(*cp);
            ++compared;
        }
    }
    if (const json *doc = doc_or_fail("color.json")) {
        for (const json *cp : cases_of(*doc, "lab_from_rgb")) {
            const json &in = (*cp)["input"];
            if (in.contains("null")) continue;
            const double rgb[3] = {num(in["rgb"][0]), num(in["rgb"][1]), num(in["rgb"][2])};
            double L, a, b, w[3];
            signed char st = 99;
            pgloss_lab_from_rgb_batch(1, soa(&rgb[0], &rgb[1], &rgb[2]), PGLOSS_COLOR_SPACE_LINEAR_REC709,
                                      soa_out(&L, &a, &b), &st);
            EXPECT_EQ(int(st), int(pgloss_lab_from_rgb(rgb, w))) << case_id(*cp);
            EXPECT_TRUE(same_bits(L, w[0]) && same_bits(a, w[1]) && same_bits(b, w[2])) << case_id(*cp);
            ++compared;
        }
    }
    EXPECT_GT(compared, 200);
}

}  // namespace
