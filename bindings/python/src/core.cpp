// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// core.cpp — pgloss._core: the C core's batches over numpy arrays, as they are.
//
// The low layer of the Python package. pgloss/*.py checks, broadcasts and allocates; this file
// hands the arrays to the strided batches of pgloss/batch.h and pgloss/perceptual_batch.h —
// a base pointer and a byte stride per array, so that (n, 3) rows, columns and broadcast
// (stride 0) values pass without a copy — with the GIL released, and splits a long call over
// threads (parallel.h). Arrays come as (3, n) or (n,) views of any strides (a direction array's
// transpose is (3, n)), and the call's outputs and statuses are written where Python says.
// The perceptual functions without a batch (contrast_gloss, gloss_distance, …) run the scalar
// function per element.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "bind_glossmeter.h"
#include "parallel.h"
#include "pgloss/pgloss.h"

namespace py = pybind11;

namespace {

using pgloss_py::Interrupt;
using pgloss_py::run_ranges;
using pgloss_py::StopCheck;

// Elements per call of the C batch: the unit of Ctrl-C checks and of the threads' blocks.
constexpr size_t kUnit = 1024;

inline size_t units_of(size_t n) { return (n + kUnit - 1) / kUnit; }

// A status no core function returns: marks a status the core left unwritten (an error of the
// whole call, such as an unknown normalisation, writes nothing).
constexpr signed char kUnwritten = 127;

// The C enums from Python ints. Unknown values must reach the core (which reports them), and a
// C++ conversion of an int outside an enum's range is undefined: the bytes are copied instead.
template <class E>
E enum_of(int v) {
    static_assert(sizeof(E) == sizeof(int), "a C enum is an int here");
    E e;
    std::memcpy(&e, &v, sizeof e);
    return e;
}

// ---------------------------------------------------------------------------------------
// Arrays: a (3, n) or (n,) view of any strides, of the call's scalar type.

void check_array(const py::array &a, py::ssize_t rows, size_t n, const py::dtype &dt, const char *what) {
    const bool ok = rows ? (a.ndim() == 2 && a.shape(0) == rows && static_cast<size_t>(a.shape(1)) == n)
                         : (a.ndim() == 1 && static_cast<size_t>(a.shape(0)) == n);
    if (!ok || !a.dtype().is(dt))
        throw std::invalid_argument(std::string("pgloss._core: ") + what + " must be a " + (rows ? "(3, n)" : "(n,)") +
                                    " array of dtype " + std::string(py::str(dt)) + " with n = " + std::to_string(n));
}

const char *in_ptr(const py::array &a) { return static_cast<const char *>(a.data()); }
char *out_ptr(py::array &a) {
    if (!a.writeable()) throw std::invalid_argument("pgloss._core: an output array is read-only");
    return static_cast<char *>(a.mutable_data());
}

// Element `base` on of a (3, n) input / output, and of an (n,) one.
struct In3 {
    const char *p = nullptr;
    ptrdiff_t comp = 0, stride = 0;
    pgloss_strided3 at(size_t base) const {
        const char *q = p + static_cast<ptrdiff_t>(base) * stride;
        return pgloss_strided3{{q, q + comp, q + 2 * comp}, stride};
    }
};
struct Out3 {
    char *p = nullptr;
    ptrdiff_t comp = 0, stride = 0;
    pgloss_strided3_out at(size_t base) const {
        if (!p) return pgloss_strided3_out{{nullptr, nullptr, nullptr}, 0};
        char *q = p + static_cast<ptrdiff_t>(base) * stride;
        return pgloss_strided3_out{{q, q + comp, q + 2 * comp}, stride};
    }
};
struct In1 {
    const char *p = nullptr;
    ptrdiff_t stride = 0;
    pgloss_strided at(size_t base) const { return pgloss_strided{p + static_cast<ptrdiff_t>(base) * stride, stride}; }
};
struct Out1 {
    char *p = nullptr;
    ptrdiff_t stride = 0;
    pgloss_strided_out at(size_t base) const {
        return pgloss_strided_out{p ? p + static_cast<ptrdiff_t>(base) * stride : nullptr, stride};
    }
};

In3 in3(const py::array &a, size_t n, const py::dtype &dt, const char *what) {
    check_array(a, 3, n, dt, what);
    return In3{in_ptr(a), a.strides(0), a.strides(1)};
}
py::array output(const py::object &o, const char *what) {
    if (!py::isinstance<py::array>(o)) throw std::invalid_argument(std::string("pgloss._core: ") + what + " is not an array");
    return py::reinterpret_borrow<py::array>(o);
}

Out3 out3(const py::object &o, size_t n, const py::dtype &dt, const char *what) {
    if (o.is_none()) return Out3{};
    py::array a = output(o, what);
    check_array(a, 3, n, dt, what);
    return Out3{out_ptr(a), a.strides(0), a.strides(1)};
}
In1 in1(const py::array &a, size_t n, const py::dtype &dt, const char *what) {
    check_array(a, 0, n, dt, what);
    return In1{in_ptr(a), a.strides(0)};
}
Out1 out1(const py::object &o, size_t n, const py::dtype &dt, const char *what) {
    if (o.is_none()) return Out1{};
    py::array a = output(o, what);
    check_array(a, 0, n, dt, what);
    return Out1{out_ptr(a), a.strides(0)};
}

// The per-element statuses (and the sampler's lobes): contiguous bytes that Python allocated.
template <class T>
T *bytes(py::array &a, size_t n, const char *what) {
    if (a.ndim() != 1 || static_cast<size_t>(a.shape(0)) != n || a.itemsize() != 1 ||
        !(a.flags() & py::array::c_style))
        throw std::invalid_argument(std::string("pgloss._core: ") + what + " must be n contiguous bytes");
    return reinterpret_cast<T *>(out_ptr(a));
}

// One parameter set per element (pgloss_physical_array): rho_d (3, n), rho_s, alpha_x, alpha_y
// (n,), of the call's scalar type, and the normalisation.
struct Physicals {
    In3 rho_d;
    In1 rho_s, alpha_x, alpha_y;
    int normalization = 0;
    pgloss_physical_array at(size_t base) const {
        pgloss_physical_array p;
        p.rho_d = rho_d.at(base);
        p.rho_s = rho_s.at(base);
        p.alpha_x = alpha_x.at(base);
        p.alpha_y = alpha_y.at(base);
        p.normalization = enum_of<pgloss_normalization>(normalization);
        return p;
    }
};

// Five-parameter descriptions per element (pgloss_perceptual_array): L, a, b, c, d, each (n,)
// float64 of its own strides.
struct Perceptuals {
    std::array<In1, 5> f;
    pgloss_perceptual_array at(size_t base) const {
        return pgloss_perceptual_array{f[0].at(base), f[1].at(base), f[2].at(base), f[3].at(base), f[4].at(base)};
    }
};

Perceptuals perceptuals(const std::array<py::array, 5> &a, size_t n) {
    const char *names[5] = {"L", "a", "b", "c", "d"};
    Perceptuals q;
    for (size_t k = 0; k < 5; ++k) q.f[k] = in1(a[k], n, py::dtype::of<double>(), names[k]);
    return q;
}

Physicals physicals(const py::tuple &t, size_t n, const py::dtype &dt) {
    if (t.size() != 5) throw std::invalid_argument("pgloss._core: materials = (rho_d, rho_s, alpha_x, alpha_y, normalization)");
    return Physicals{in3(t[0].cast<py::array>(), n, dt, "rho_d"), in1(t[1].cast<py::array>(), n, dt, "rho_s"),
                     in1(t[2].cast<py::array>(), n, dt, "alpha_x"), in1(t[3].cast<py::array>(), n, dt, "alpha_y"),
                     t[4].cast<int>()};
}

// ---------------------------------------------------------------------------------------
// Runs batch(base, m, status + base) -> status over [0, n) in units of kUnit, on the threads of
// parallel.h, with the GIL released. A unit whose call fails as a whole (nothing written) gets
// that status for each of its elements. Returns the first error in index order: its status, its
// index, and whether the call failed as a whole.

struct FirstError {
    int status = PGLOSS_OK;
    py::ssize_t index = -1;
    bool whole = false;
};

template <class Batch>
FirstError run_batch(size_t n, std::size_t cost, signed char *status, Batch batch) {
    Interrupt I;
    std::vector<FirstError> blocks;
    {
        py::gil_scoped_release nogil;
        blocks = run_ranges<FirstError>(n * cost, units_of(n), I, [&](size_t u0, size_t u1, StopCheck &stop) {
            FirstError err;
            for (size_t u = u0; u < u1; ++u) {
                if (stop((u - u0) * kUnit)) break;
                const size_t base = u * kUnit, m = std::min(kUnit, n - base);
                signed char *st = status + base;
                st[0] = kUnwritten;
                const int r = batch(base, m, st);
                if (r >= 0) continue;
                const bool whole = st[0] == kUnwritten;
                if (whole) std::memset(st, static_cast<signed char>(r), m);
                if (err.status != PGLOSS_OK) continue;
                const auto j = static_cast<size_t>(std::find_if(st, st + m, [](signed char s) { return s < 0; }) - st);
                err = FirstError{st[j], static_cast<py::ssize_t>(base + j), whole};
            }
            return err;
        });
    }
    I.raise_if_signalled();
    for (const FirstError &e : blocks)
        if (e.status != PGLOSS_OK) return e;
    return FirstError{};
}

py::tuple result(const FirstError &e) { return py::make_tuple(e.status, e.index, e.whole); }

// ---------------------------------------------------------------------------------------
// Materials.

struct Material {
    pgloss_material m{};
    std::array<double, 6> v{};  // the physical parameters it was built from
    int normalization = 0;
};

// Builds a material; returns it with the core's status (on error it is the core's black material).
std::pair<Material, int> material_init(const std::array<double, 6> &v, int normalization) {
    Material M;
    M.v = v;
    M.normalization = normalization;
    pgloss_physical p{};
    std::copy(v.begin(), v.begin() + 3, p.rho_d);
    p.rho_s = v[3];
    p.alpha_x = v[4];
    p.alpha_y = v[5];
    p.normalization = enum_of<pgloss_normalization>(normalization);
    const int st = pgloss_material_init(&M.m, &p);
    return {M, st};
}

py::dtype scalar_dtype(const py::array &a) {
    if (a.dtype().is(py::dtype::of<float>())) return py::dtype::of<float>();
    if (a.dtype().is(py::dtype::of<double>())) return py::dtype::of<double>();
    throw std::invalid_argument("pgloss._core: directions must be float32 or float64");
}

pgloss_batch_options options_of(const py::dtype &dt, int precision) {
    pgloss_batch_options o{};
    o.precision = enum_of<pgloss_precision>(precision);
    o.scalar = dt.is(py::dtype::of<float>()) ? PGLOSS_FLOAT32 : PGLOSS_FLOAT64;
    return o;
}

// What eval_pdf and sample share: the scalar type (wo's), n, the options, and one Material or
// per-element parameters (a tuple, physicals above).
struct BrdfCall {
    py::dtype dt;
    size_t n;
    pgloss_batch_options opt;
    const pgloss_material *m = nullptr;
    Physicals ms;
    BrdfCall(const py::object &material, const py::object &materials, const py::array &wo, int precision)
        : dt(scalar_dtype(wo)), n(static_cast<size_t>(wo.ndim() == 2 ? wo.shape(1) : 0)), opt(options_of(dt, precision)) {
        if (!material.is_none())
            m = &material.cast<const Material &>().m;
        else
            ms = physicals(materials.cast<py::tuple>(), n, dt);
    }
    // The C call's per-element parameters for the elements from base on (NULL with one Material).
    const pgloss_physical_array *at(size_t base, pgloss_physical_array &p) const {
        if (m) return nullptr;
        p = ms.at(base);
        return &p;
    }
};

py::tuple eval_pdf(const py::object &material, const py::object &materials, unsigned lobes, const py::array &wo,
                   const py::array &wi, const py::object &f, const py::object &pdf, py::array status, int precision) {
    const BrdfCall c(material, materials, wo, precision);
    const In3 o = in3(wo, c.n, c.dt, "wo"), i = in3(wi, c.n, c.dt, "wi");
    const Out3 fo = out3(f, c.n, c.dt, "f");
    const Out1 po = out1(pdf, c.n, c.dt, "pdf");
    return result(run_batch(c.n, 1, bytes<signed char>(status, c.n, "status"), [&](size_t base, size_t k, signed char *s) {
        pgloss_physical_array p;
        return static_cast<int>(pgloss_eval_pdf_batch(&c.opt, c.m, c.at(base, p), lobes, k, o.at(base), i.at(base),
                                                      fo.at(base), po.at(base), s));
    }));
}

py::tuple sample(const py::object &material, const py::object &materials, unsigned lobes, const py::array &wo,
                 const py::array &u, const py::object &wi, const py::object &pdf, const py::object &weight,
                 py::array lobe, py::array status, int precision) {
    const BrdfCall c(material, materials, wo, precision);
    const In3 o = in3(wo, c.n, c.dt, "wo"), uu = in3(u, c.n, c.dt, "u");
    const Out3 wio = out3(wi, c.n, c.dt, "wi"), go = out3(weight, c.n, c.dt, "weight");
    const Out1 po = out1(pdf, c.n, c.dt, "pdf");
    auto *lp = bytes<unsigned char>(lobe, c.n, "lobe");
    return result(run_batch(c.n, 1, bytes<signed char>(status, c.n, "status"), [&](size_t base, size_t k, signed char *s) {
        pgloss_physical_array p;
        return static_cast<int>(pgloss_sample_batch(&c.opt, c.m, c.at(base, p), lobes, k, o.at(base), uu.at(base),
                                                    wio.at(base), po.at(base), go.at(base), lp + base, s));
    }));
}

// ---------------------------------------------------------------------------------------
// Perceptual and colour functions (float64). Inputs (n,) or (3, n) of any strides; outputs
// and statuses where Python allocated them.

const py::dtype &f64() {
    static const py::dtype d = py::dtype::of<double>();
    return d;
}

size_t length(const py::array &status) { return static_cast<size_t>(status.ndim() == 1 ? status.shape(0) : 0); }

// The scalar functions without a batch, element by element (about 40 ns an element: they count
// kScalarCost elements each for the threads): f(inputs, outputs) -> status.
template <size_t NI, size_t NO, class F>
void vmap(const std::array<py::array, NI> &in, const std::array<py::array, NO> &out, py::array status, F f) {
    const size_t n = length(status);
    std::array<In1, NI> x;
    std::array<Out1, NO> y;
    for (size_t k = 0; k < NI; ++k) x[k] = in1(in[k], n, f64(), "an input");
    for (size_t k = 0; k < NO; ++k) y[k] = out1(out[k], n, f64(), "an output");
    run_batch(n, pgloss_py::kScalarCost, bytes<signed char>(status, n, "status"),
              [&](size_t base, size_t m, signed char *s) {
                  int first = PGLOSS_OK;
                  for (size_t j = base; j < base + m; ++j) {
                      std::array<double, NI> a;
                      std::array<double, NO> b{};
                      for (size_t k = 0; k < NI; ++k) std::memcpy(&a[k], x[k].p + static_cast<ptrdiff_t>(j) * x[k].stride, 8);
                      const int r = f(a.data(), b.data());
                      for (size_t k = 0; k < NO; ++k) std::memcpy(y[k].p + static_cast<ptrdiff_t>(j) * y[k].stride, &b[k], 8);
                      s[j - base] = static_cast<signed char>(r);
                      if (r < 0 && first == PGLOSS_OK) first = r;
                  }
                  return first;
              });
}

// A batch of pgloss/perceptual_batch.h over the units; batch(base, m, status) -> status.
template <class Batch>
void bmap(py::array status, Batch batch) {
    const size_t n = length(status);
    run_batch(n, 1, bytes<signed char>(status, n, "status"), batch);
}

pgloss_color_space space_of(int s) { return enum_of<pgloss_color_space>(s); }

// A batch of three (n,) inputs and three (n,) outputs (gloss_from_physical, physical_from_gloss).
using ThreeToThree = pgloss_status (*)(size_t, pgloss_strided, pgloss_strided, pgloss_strided, pgloss_strided_out,
                                       pgloss_strided_out, pgloss_strided_out, signed char *);
auto three_to_three(ThreeToThree batch) {
    return [batch](py::array a, py::array b, py::array c, py::array x, py::array y, py::array z, py::array status) {
        const size_t n = length(status);
        const In1 i0 = in1(a, n, f64(), "an input"), i1 = in1(b, n, f64(), "an input"), i2 = in1(c, n, f64(), "an input");
        const Out1 o0 = out1(x, n, f64(), "an output"), o1 = out1(y, n, f64(), "an output"),
                   o2 = out1(z, n, f64(), "an output");
        bmap(status, [&](size_t k, size_t m, signed char *s) {
            return static_cast<int>(batch(m, i0.at(k), i1.at(k), i2.at(k), o0.at(k), o1.at(k), o2.at(k), s));
        });
    };
}

// A colour conversion: (3, n) in, (3, n) out, in a working space (rgb_from_lab, lab_from_rgb).
using ColourConversion = pgloss_status (*)(size_t, pgloss_strided3, pgloss_color_space, pgloss_strided3_out,
                                           signed char *);
auto colour_conversion(ColourConversion batch) {
    return [batch](py::array from, int space, py::array to, py::array status) {
        const size_t n = length(status);
        const In3 x = in3(from, n, f64(), "the input");
        const Out3 y = out3(to, n, f64(), "the output");
        bmap(status, [&](size_t b, size_t m, signed char *s) {
            return static_cast<int>(batch(m, x.at(b), space_of(space), y.at(b), s));
        });
    };
}

}  // namespace

PYBIND11_MODULE(_core, mod) {
    mod.doc() = "pgloss._core: the C core's batches over numpy arrays (use the pgloss package, not this module).";

    mod.attr("VERSION") = pgloss_version();  // the linked library's (pgloss/version.h)
    mod.attr("ALPHA_MIN") = static_cast<double>(PGLOSS_ALPHA_MIN);
    mod.attr("COS_MIN") = static_cast<double>(PGLOSS_COS_MIN);
    mod.attr("CIE_EPSILON") = PGLOSS_CIE_EPSILON;
    mod.attr("CIE_KAPPA") = PGLOSS_CIE_KAPPA;
    mod.attr("D_WEIGHT") = PGLOSS_D_WEIGHT;
    mod.attr("ALPHA_TRUSTED_MAX") = PGLOSS_ALPHA_TRUSTED_MAX;
    mod.attr("BOUNDARY_TOLERANCE") = PGLOSS_BOUNDARY_TOLERANCE;
    mod.attr("LUMA") = py::make_tuple(PGLOSS_LUMA_R, PGLOSS_LUMA_G, PGLOSS_LUMA_B);
    pgloss_py::bind_glossmeter(mod);  // pgloss.glossmeter (bind_glossmeter.cpp)
    { void pgloss_py_bind_bridge(py::module_ &); pgloss_py_bind_bridge(mod); }  // pgloss.bridge (bridge.cpp)

    // The thread count of the array calls; pgloss.set_num_threads validates it and reads
    // PGLOSS_NUM_THREADS at import (parallel.h).
    mod.def("set_num_threads", [](int n) {
        if (n < 1) throw py::value_error("pgloss._core.set_num_threads: n must be at least 1");
        return pgloss_py::num_threads().exchange(n);
    }, py::arg("n"));
    mod.def("get_num_threads", [] { return pgloss_py::num_threads().load(); });
    mod.attr("MIN_ELEMENTS_PER_THREAD") = pgloss_py::kMinPerThread;
    // For the tests and the benchmark only: the threshold above (1 splits any array of two
    // units or more); returns the previous value.
    mod.def("_set_min_elements_per_thread", [](size_t n) {
        return pgloss_py::min_per_thread().exchange(std::max<size_t>(1, n));
    }, py::arg("n"));
    mod.def("_last_threads", [] { return pgloss_py::last_threads().load(); },
            "The threads the latest array call used (for the tests).");
    // For the tests of parallel.h alone: runs `units` units of one element each and returns the
    // units in the order of the merged results (each exactly once, ascending); a unit equal to
    // throw_at throws std::runtime_error in whichever thread runs it.
    mod.def("_test_ranges", [](size_t units, long long throw_at) {
        Interrupt I;
        std::vector<std::vector<size_t>> blocks;
        {
            py::gil_scoped_release nogil;
            blocks = run_ranges<std::vector<size_t>>(units, units, I, [&](size_t u0, size_t u1, StopCheck &stop) {
                std::vector<size_t> seen;
                for (size_t u = u0; u < u1; ++u) {
                    if (stop(u - u0)) break;
                    if (static_cast<long long>(u) == throw_at)
                        throw std::runtime_error("pgloss._core._test_ranges: unit " + std::to_string(u));
                    seen.push_back(u);
                }
                return seen;
            });
        }
        I.raise_if_signalled();
        std::vector<size_t> all;
        for (const auto &b : blocks) all.insert(all.end(), b.begin(), b.end());
        return all;
    }, py::arg("units"), py::arg("throw_at"));

    mod.def("status_string", [](int s) { return std::string(pgloss_status_string(enum_of<pgloss_status>(s))); },
            py::arg("status"));
    mod.def("status_name", [](int s) { return std::string(pgloss_status_name(enum_of<pgloss_status>(s))); },
            py::arg("status"));

    py::class_<Material>(mod, "Material",
                         "An evaluation-ready material (pgloss_material): the physical parameters rounded to float\n"
                         "and what eval/pdf/sample precompute. Build one with pgloss.material_init(physical) or\n"
                         "Physical.material(); the fields are read-only.")
        .def_property_readonly("rho_d", [](const Material &M) { return py::make_tuple(M.m.rho_d[0], M.m.rho_d[1], M.m.rho_d[2]); },
                               "diffuse reflectance (r, g, b), rounded to float")
        .def_property_readonly("rho_s", [](const Material &M) { return M.m.rho_s; }, "specular energy ρs")
        .def_property_readonly("alpha_x", [](const Material &M) { return M.m.alpha_x; }, "αx (at least ALPHA_MIN)")
        .def_property_readonly("alpha_y", [](const Material &M) { return M.m.alpha_y; }, "αy (at least ALPHA_MIN)")
        .def_property_readonly("normalization", [](const Material &M) { return M.normalization; },
                               "normalisation of the specular lobe (pgloss.Normalization value)")
        .def_property_readonly("lobes", [](const Material &M) { return M.m.lobes; },
                               "lobes present: DIFFUSE if any ρd > 0, SPECULAR if ρs > 0")
        .def_property_readonly("inv_alpha_x", [](const Material &M) { return M.m.inv_alpha_x; }, "1/αx")
        .def_property_readonly("inv_alpha_y", [](const Material &M) { return M.m.inv_alpha_y; }, "1/αy")
        .def_property_readonly("spec_scale", [](const Material &M) { return M.m.spec_scale; },
                               "ρs/(4π αx αy) (WARD, WARD_DUR) or ρs/(π αx αy) (BOUNDED)")
        .def_property_readonly("pdf_scale", [](const Material &M) { return M.m.pdf_scale; },
                               "1/(4π αx αy), the specular pdf's constant")
        .def_property_readonly("weight_diffuse", [](const Material &M) { return M.m.weight_diffuse; },
                               "lobe-selection weight of the diffuse lobe (luminance of ρd)")
        .def_property_readonly("weight_specular", [](const Material &M) { return M.m.weight_specular; },
                               "lobe-selection weight of the specular lobe (ρs)")
        .def_property_readonly("parameters", [](const Material &M) { return py::make_tuple(M.v, M.normalization); },
                               "the (rho_d r, g, b, rho_s, alpha_x, alpha_y) doubles and the normalisation it was built from")
        .def("__eq__", [](const Material &a, const Material &b) { return a.v == b.v && a.normalization == b.normalization; },
             py::arg("other"))
        .def("__hash__", [](const Material &M) {
            return py::hash(py::make_tuple(M.v[0], M.v[1], M.v[2], M.v[3], M.v[4], M.v[5], M.normalization));
        })
        .def("__repr__", [](const Material &M) {
            char buf[320];
            std::snprintf(buf, sizeof buf,
                          "Material(rho_d=(%.9g, %.9g, %.9g), rho_s=%.9g, alpha_x=%.9g, alpha_y=%.9g, normalization=%d, lobes=%u)",
                          M.m.rho_d[0], M.m.rho_d[1], M.m.rho_d[2], M.m.rho_s, M.m.alpha_x, M.m.alpha_y, M.normalization,
                          M.m.lobes);
            return std::string(buf);
        })
        .def(py::pickle(
            [](const Material &M) { return py::make_tuple(M.v, M.normalization); },
            [](const py::tuple &t) {
                if (t.size() != 2) throw std::runtime_error("pgloss.Material: bad pickle state");
                auto r = material_init(t[0].cast<std::array<double, 6>>(), t[1].cast<int>());
                if (r.second < 0) throw py::value_error(pgloss_status_string(enum_of<pgloss_status>(r.second)));
                return r.first;
            }));

    mod.def("material_init", [](const std::array<double, 6> &v, int normalization) {
        auto r = material_init(v, normalization);
        return py::make_tuple(r.first, r.second);
    }, py::arg("v"), py::arg("normalization"));
    mod.def("specular_probability",
            [](const Material &M, unsigned lobes) { return pgloss_specular_probability(&M.m, lobes); },
            py::arg("material"), py::arg("lobes"));

    // The BRDF batches (pgloss/batch.h). Returns (status, index, whole): the first failing
    // element's status and index (status 0, index -1: none), and whether that call failed as a
    // whole (nothing written: every element has its status, the outputs are as allocated).
    mod.def("eval_pdf", &eval_pdf, py::arg("material"), py::arg("materials"), py::arg("lobes"), py::arg("wo"),
            py::arg("wi"), py::arg("f"), py::arg("pdf"), py::arg("status"), py::arg("precision") = 0,
            "pgloss_eval_pdf_batch: material (a Material) or materials ((rho_d, rho_s, alpha_x, alpha_y,\n"
            "normalization), one per element); wo, wi, f: (3, n); pdf, status: (n,); f or pdf may be None.");
    mod.def("sample", &sample, py::arg("material"), py::arg("materials"), py::arg("lobes"), py::arg("wo"),
            py::arg("u"), py::arg("wi"), py::arg("pdf"), py::arg("weight"), py::arg("lobe"), py::arg("status"),
            py::arg("precision") = 0, "pgloss_sample_batch, with the arrays of eval_pdf; u, wi, weight: (3, n).");
    // One pgloss_eval_pdf call (the scalar reference: float directions, double inside, float
    // results), as the C tool calls it.
    mod.def("eval_pdf_reference", [](const Material &M, unsigned lobes, std::array<float, 3> wo, std::array<float, 3> wi) {
        pgloss_rgb f{0, 0, 0};
        float pdf = 0;
        const int st = pgloss_eval_pdf(&M.m, pgloss_vec3{wo[0], wo[1], wo[2]}, pgloss_vec3{wi[0], wi[1], wi[2]}, lobes, &f, &pdf);
        return py::make_tuple(py::make_tuple(f.r, f.g, f.b), pdf, st);
    }, py::arg("material"), py::arg("lobes"), py::arg("wo"), py::arg("wi"));

    // The scalar functions without a batch: (inputs), (outputs), status; element by element.
    using A = py::array;
    mod.def("lightness_from_luminance", [](A Y, A L, A st) {
        vmap<1, 1>({Y}, {L}, st, [](const double *x, double *y) { return (int)pgloss_lightness_from_luminance(x[0], &y[0]); });
    }, py::arg("Y"), py::arg("L"), py::arg("status"));
    mod.def("luminance_from_lightness", [](A L, A Y, A st) {
        vmap<1, 1>({L}, {Y}, st, [](const double *x, double *y) { return (int)pgloss_luminance_from_lightness(x[0], &y[0]); });
    }, py::arg("L"), py::arg("Y"), py::arg("status"));
    mod.def("contrast_gloss", [](A rd, A rs, A c, A st) {
        vmap<2, 1>({rd, rs}, {c}, st, [](const double *x, double *y) { return (int)pgloss_contrast_gloss(x[0], x[1], &y[0]); });
    }, py::arg("rho_d"), py::arg("rho_s"), py::arg("c"), py::arg("status"));
    mod.def("specular_from_contrast", [](A rd, A c, A rs, A st) {
        vmap<2, 1>({rd, c}, {rs}, st,
                   [](const double *x, double *y) { return (int)pgloss_specular_from_contrast(x[0], x[1], &y[0]); });
    }, py::arg("rho_d"), py::arg("c"), py::arg("rho_s"), py::arg("status"));
    mod.def("gloss_distance", [](A c1, A d1, A c2, A d2, A D, A st) {
        vmap<4, 1>({c1, d1, c2, d2}, {D}, st,
                   [](const double *x, double *y) { return (int)pgloss_gloss_distance(x[0], x[1], x[2], x[3], &y[0]); });
    }, py::arg("c1"), py::arg("d1"), py::arg("c2"), py::arg("d2"), py::arg("D"), py::arg("status"));
    mod.def("luminance", [](A r, A g, A b, int space, A Y, A st) {
        vmap<3, 1>({r, g, b}, {Y}, st, [space](const double *x, double *y) {
            return (int)pgloss_luminance_ex(x, space_of(space), &y[0]);
        });
    }, py::arg("r"), py::arg("g"), py::arg("b"), py::arg("space"), py::arg("Y"), py::arg("status"));
    mod.def("isogloss_contour", [](double c0, double d0, double D, A c, A d) {
        const auto n = static_cast<size_t>(c.size());
        check_array(c, 0, n, f64(), "c");
        check_array(d, 0, n, f64(), "d");
        if (!(c.flags() & d.flags() & py::array::c_style)) throw std::invalid_argument("pgloss._core: c, d must be contiguous");
        double *cp = reinterpret_cast<double *>(out_ptr(c)), *dp = reinterpret_cast<double *>(out_ptr(d));
        py::gil_scoped_release nogil;
        return static_cast<int>(pgloss_isogloss_contour(c0, d0, D, n, cp, dp));
    }, py::arg("c0"), py::arg("d0"), py::arg("D"), py::arg("c"), py::arg("d"));

    // The batches of pgloss/perceptual_batch.h: (inputs), (outputs), status.
    mod.def("gloss_from_physical", three_to_three(pgloss_gloss_from_physical_batch), py::arg("rho_d"), py::arg("rho_s"),
            py::arg("alpha"), py::arg("L"), py::arg("c"), py::arg("d"), py::arg("status"));
    mod.def("physical_from_gloss", three_to_three(pgloss_physical_from_gloss_batch), py::arg("L"), py::arg("c"),
            py::arg("d"), py::arg("rho_d"), py::arg("rho_s"), py::arg("alpha"), py::arg("status"));
    mod.def("envelope_contrast", [](A L, A c_max, A st) {
        const size_t n = length(st);
        const In1 x = in1(L, n, f64(), "L");
        const Out1 y = out1(c_max, n, f64(), "c_max");
        bmap(st, [&](size_t b, size_t m, signed char *s) { return (int)pgloss_envelope_contrast_batch(m, x.at(b), y.at(b), s); });
    }, py::arg("L"), py::arg("c_max"), py::arg("status"));
    mod.def("match_gloss", [](A rd, A rs, A Lt, A rd_out, A rs_out, A st) {
        const size_t n = length(st);
        const In1 x0 = in1(rd, n, f64(), "rho_d"), x1 = in1(rs, n, f64(), "rho_s"), x2 = in1(Lt, n, f64(), "L_target");
        const Out1 y0 = out1(rd_out, n, f64(), "rho_d_out"), y1 = out1(rs_out, n, f64(), "rho_s_out");
        bmap(st, [&](size_t b, size_t m, signed char *s) {
            return (int)pgloss_match_gloss_batch(m, x0.at(b), x1.at(b), x2.at(b), y0.at(b), y1.at(b), s);
        });
    }, py::arg("rho_d"), py::arg("rho_s"), py::arg("L_target"), py::arg("rho_d_out"), py::arg("rho_s_out"),
       py::arg("status"));
    mod.def("rgb_from_lab", colour_conversion(pgloss_rgb_from_lab_batch), py::arg("lab"), py::arg("space"),
            py::arg("rgb"), py::arg("status"));
    mod.def("lab_from_rgb", colour_conversion(pgloss_lab_from_rgb_batch), py::arg("rgb"), py::arg("space"),
            py::arg("lab"), py::arg("status"));
    // Paints: physical = (rho_d (3, n), rho_s, alpha_x, alpha_y, normalization) as for eval_pdf;
    // perceptual = L, a, b, c, d, each (n,).
    mod.def("check_physical", [](py::tuple p, A st) {
        const size_t n = length(st);
        const Physicals ps = physicals(p, n, f64());
        bmap(st, [&](size_t b, size_t m, signed char *s) {
            const pgloss_physical_array a = ps.at(b);
            return (int)pgloss_check_physical_batch(m, &a, s);
        });
    }, py::arg("physical"), py::arg("status"));
    mod.def("check_perceptual", [](A L, A a, A b, A c, A d, int space, A st) {
        const Perceptuals q = perceptuals({L, a, b, c, d}, length(st));
        bmap(st, [&](size_t k, size_t m, signed char *s) {
            const pgloss_perceptual_array qa = q.at(k);
            return (int)pgloss_check_perceptual_batch(m, &qa, space_of(space), s);
        });
    }, py::arg("L"), py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"), py::arg("space"), py::arg("status"));
    // Outputs rho_d (3, n), rho_s, alpha (= alpha_x = alpha_y: eq. 8 is isotropic; alpha_y is not written).
    mod.def("physical_from_perceptual", [](A L, A a, A b, A c, A d, int norm, int space, A rd, A rs, A al, A st) {
        const size_t n = length(st);
        const Perceptuals q = perceptuals({L, a, b, c, d}, n);
        const Out3 y = out3(rd, n, f64(), "rho_d");
        const Out1 ys = out1(rs, n, f64(), "rho_s"), ya = out1(al, n, f64(), "alpha");
        bmap(st, [&](size_t k, size_t m, signed char *s) {
            const pgloss_perceptual_array qa = q.at(k);
            const pgloss_physical_array_out p{y.at(k), ys.at(k), ya.at(k), pgloss_strided_out{nullptr, 0}};
            return (int)pgloss_physical_from_perceptual_batch(m, &qa, enum_of<pgloss_normalization>(norm), space_of(space),
                                                              &p, s);
        });
    }, py::arg("L"), py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"), py::arg("normalization"), py::arg("space"),
       py::arg("rho_d"), py::arg("rho_s"), py::arg("alpha"), py::arg("status"));
    mod.def("perceptual_from_physical", [](py::tuple p, int space, A L, A a, A b, A c, A d, A st) {
        const size_t n = length(st);
        const Physicals ps = physicals(p, n, f64());
        std::array<Out1, 5> y;
        const char *names[5] = {"L", "a", "b", "c", "d"};
        const A outs[5] = {L, a, b, c, d};
        for (size_t k = 0; k < 5; ++k) y[k] = out1(outs[k], n, f64(), names[k]);
        bmap(st, [&](size_t k, size_t m, signed char *s) {
            const pgloss_physical_array pa = ps.at(k);
            const pgloss_perceptual_array_out q{y[0].at(k), y[1].at(k), y[2].at(k), y[3].at(k), y[4].at(k)};
            return (int)pgloss_perceptual_from_physical_batch(m, &pa, space_of(space), &q, s);
        });
    }, py::arg("physical"), py::arg("space"), py::arg("L"), py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"),
       py::arg("status"));
}
