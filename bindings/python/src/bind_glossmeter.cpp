// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// pgloss._core's glossmeter functions (pgloss/glossmeter.h) over flat numpy arrays; the typed,
// broadcasting API is pgloss.glossmeter. Each element is one call of the core, with the GIL
// released; statuses are returned per element, never raised here.
#include "bind_glossmeter.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" {
#include "pgloss/pgloss.h"
}

#include "flat_arrays.h"

namespace py = pybind11;

namespace {

using pgloss_py::common_length;
using pgloss_py::darr;

// Row i of the (n, 7) values and errors.
void store(const pgloss_glossmeter_readings &out, py::ssize_t i, double *v, double *e) {
    for (int k = 0; k < PGLOSS_GLOSSMETER_KINDS; ++k) {
        v[i * PGLOSS_GLOSSMETER_KINDS + k] = out.r[k].value;
        e[i * PGLOSS_GLOSSMETER_KINDS + k] = out.r[k].error;
    }
}

py::tuple readings(const darr &r, const darr &g, const darr &b, const darr &rs, const darr &ax, const darr &ay,
                   int norm, const darr &azimuth, double tol) {
    const py::ssize_t n = common_length({&r, &g, &b, &rs, &ax, &ay, &azimuth});
    py::array_t<double> values({n, py::ssize_t(PGLOSS_GLOSSMETER_KINDS)}), errors({n, py::ssize_t(PGLOSS_GLOSSMETER_KINDS)});
    py::array_t<std::int8_t> st(n);
    const double *pr = r.data(), *pg = g.data(), *pb = b.data(), *ps = rs.data(), *px = ax.data(), *py_ = ay.data(),
                 *pa = azimuth.data();
    double *v = values.mutable_data(), *e = errors.mutable_data();
    std::int8_t *s = st.mutable_data();
    {
        py::gil_scoped_release nogil;
        for (py::ssize_t i = 0; i < n; ++i) {
            const pgloss_physical p = {{pr[i], pg[i], pb[i]}, ps[i], px[i], py_[i], static_cast<pgloss_normalization>(norm)};
            pgloss_glossmeter_readings out;
            s[i] = static_cast<std::int8_t>(pgloss_glossmeter_readings_physical(&p, pa[i], tol, &out));
            store(out, i, v, e);
        }
    }
    return py::make_tuple(values, errors, st);
}

py::tuple readings_bridge(int target, const darr &r, const darr &g, const darr &b, const darr &rough,
                          const darr &ior, const darr &spec, double tol) {
    const py::ssize_t n = common_length({&r, &g, &b, &rough, &ior, &spec});
    py::array_t<double> values({n, py::ssize_t(PGLOSS_GLOSSMETER_KINDS)}), errors({n, py::ssize_t(PGLOSS_GLOSSMETER_KINDS)});
    py::array_t<std::int8_t> st(n);
    const double *pr = r.data(), *pg = g.data(), *pb = b.data(), *pro = rough.data(), *pi = ior.data(), *ps = spec.data();
    double *v = values.mutable_data(), *e = errors.mutable_data();
    std::int8_t *s = st.mutable_data();
    {
        py::gil_scoped_release nogil;
        for (py::ssize_t i = 0; i < n; ++i) {
            const pgloss_bridge_params p = {{pr[i], pg[i], pb[i]}, pro[i], pi[i], ps[i]};
            pgloss_glossmeter_readings out;
            s[i] = static_cast<std::int8_t>(
                pgloss_glossmeter_readings_bridge(static_cast<pgloss_bridge_target>(target), &p, 0.0, tol, &out));
            store(out, i, v, e);
        }
    }
    return py::make_tuple(values, errors, st);
}

py::tuple from_gloss_units(const darr &L, const darr &a, const darr &b, const darr &g60, const darr &x, int second,
                           int norm) {
    const py::ssize_t n = common_length({&L, &a, &b, &g60, &x});
    py::array_t<double> c(n), d(n);
    py::array_t<std::int8_t> st(n);
    const double *pL = L.data(), *pa = a.data(), *pb = b.data(), *pg = g60.data(), *px = x.data();
    double *pc = c.mutable_data(), *pd = d.mutable_data();
    std::int8_t *s = st.mutable_data();
    {
        py::gil_scoped_release nogil;
        for (py::ssize_t i = 0; i < n; ++i) {
            pgloss_perceptual q;
            pgloss_physical p;
            s[i] = static_cast<std::int8_t>(pgloss_paint_from_gloss_units(pL[i], pa[i], pb[i],
                                                                          static_cast<pgloss_normalization>(norm), pg[i],
                                                                          static_cast<pgloss_gloss_second>(second), px[i], &q, &p));
            pc[i] = q.c;
            pd[i] = q.d;
        }
    }
    return py::make_tuple(c, d, st);
}

}  // namespace

namespace pgloss_py {

void bind_glossmeter(py::module_ &mod) {
    mod.attr("GLOSSMETER_KINDS") = int(PGLOSS_GLOSSMETER_KINDS);
    mod.attr("GLOSS_STANDARD_INDEX") = PGLOSS_GLOSS_STANDARD_INDEX;
    mod.attr("GLOSSMETER_TOL") = PGLOSS_GLOSSMETER_TOL;
    mod.attr("ASSUMED_DOI_GLOSS") = PGLOSS_ASSUMED_DOI_GLOSS;
    mod.def("glossmeter_readings", &readings,
            "pgloss_glossmeter_readings_physical per element: (values (n, 7), errors (n, 7), status (n,)).");
    mod.def("glossmeter_readings_bridge", &readings_bridge,
            "pgloss_glossmeter_readings_bridge per element: (values (n, 7), errors (n, 7), status (n,)).");
    mod.def("paint_from_gloss_units", &from_gloss_units,
            "pgloss_paint_from_gloss_units per element: (c, d, status).");
    mod.def("fresnel_dielectric", [](double n, double c) {
        double r;
        const pgloss_status st = pgloss_fresnel_dielectric(n, c, &r);
        return py::make_tuple(r, int(st));
    });
    mod.def("finishes", [] {
        std::vector<py::tuple> out;
        for (size_t k = 0; pgloss_finish_at(k); ++k) {
            const pgloss_finish *f = pgloss_finish_at(k);
            out.push_back(py::make_tuple(f->name, f->level, f->gloss_60_min, f->gloss_60_max, f->sheen_85_min,
                                         f->sheen_85_max, f->source));
        }
        return out;
    });
    mod.def("finish_paint", [](const std::string &name, double L, double a, double b, int norm) {
        const pgloss_finish *f = pgloss_finish_find(name.c_str());
        if (!f) throw py::value_error("pgloss: '" + name + "' is not a finish (pgloss.glossmeter.FINISHES)");
        pgloss_perceptual q;
        pgloss_physical p;
        double c[2], d[2];
        int sheen = 0;
        pgloss_status st;
        {
            py::gil_scoped_release nogil;
            st = pgloss_finish_paint(f, L, a, b, static_cast<pgloss_normalization>(norm), &q, &p, c, d, &sheen);
        }
        return py::make_tuple(q.c, q.d, c[0], c[1], d[0], d[1], bool(sheen), int(st), std::string(f->name));
    });
}

}  // namespace pgloss_py
