// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// pgloss._core's gloss-bridge functions (pgloss/bridge.h) over flat numpy arrays; the typed,
// broadcasting API is pgloss.bridge (pgloss/bridge.py). Each element is one call of the core,
// with the GIL released; statuses are returned per element, never raised here. Registered from
// core.cpp by pgloss_py_bind_bridge(mod).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include "pgloss/pgloss.h"

#include "flat_arrays.h"

namespace py = pybind11;

namespace {

using pgloss_py::common_length;
using pgloss_py::darr;

pgloss_bridge_target target_of(int t) {
    if (t < 0 || t >= PGLOSS_BRIDGE_TARGET_COUNT)
        throw std::invalid_argument("pgloss._core: unknown bridge target " + std::to_string(t));
    return static_cast<pgloss_bridge_target>(t);
}

// Paints (L, a, b, c, d) -> parameters (base colour (n, 3), roughness, ior, specular), the paint
// they read as (n, 5) and the status.
py::tuple from_perceptual(int target, const darr &L, const darr &a, const darr &b, const darr &c, const darr &d) {
    const pgloss_bridge_target t = target_of(target);
    const py::ssize_t n = common_length({&L, &a, &b, &c, &d});
    py::array_t<double> base({n, py::ssize_t(3)}), rough(n), ior(n), spec(n), reached({n, py::ssize_t(5)});
    py::array_t<std::int8_t> st(n);
    const double *pL = L.data(), *pa = a.data(), *pb = b.data(), *pc = c.data(), *pd = d.data();
    double *ob = base.mutable_data(), *orr = rough.mutable_data(), *oi = ior.mutable_data(), *os = spec.mutable_data(),
           *oq = reached.mutable_data();
    std::int8_t *s = st.mutable_data();
    {
        py::gil_scoped_release nogil;
        for (py::ssize_t i = 0; i < n; ++i) {
            const pgloss_perceptual q = {pL[i], pa[i], pb[i], pc[i], pd[i]};
            pgloss_bridge_params p;
            pgloss_perceptual got;
            s[i] = static_cast<std::int8_t>(pgloss_bridge_from_perceptual(t, &q, &p, &got));
            for (int k = 0; k < 3; ++k) ob[i * 3 + k] = p.base_color[k];
            orr[i] = p.roughness;
            oi[i] = p.ior;
            os[i] = p.specular;
            const double g[5] = {got.L, got.a, got.b, got.c, got.d};
            for (int k = 0; k < 5; ++k) oq[i * 5 + k] = g[k];
        }
    }
    return py::make_tuple(base, rough, ior, spec, reached, st);
}

pgloss_bridge_params params_at(const double *r, const double *g, const double *b, const double *rough,
                               const double *ior, const double *spec, py::ssize_t i) {
    return pgloss_bridge_params{{r[i], g[i], b[i]}, rough[i], ior[i], spec[i]};
}

// Parameters -> the paint (n, 5), the residual and the status.
py::tuple to_perceptual(int target, const darr &r, const darr &g, const darr &b, const darr &rough, const darr &ior,
                        const darr &spec) {
    const pgloss_bridge_target t = target_of(target);
    const py::ssize_t n = common_length({&r, &g, &b, &rough, &ior, &spec});
    py::array_t<double> paint({n, py::ssize_t(5)}), residual(n);
    py::array_t<std::int8_t> st(n);
    double *op = paint.mutable_data(), *orr = residual.mutable_data();
    std::int8_t *s = st.mutable_data();
    {
        py::gil_scoped_release nogil;
        for (py::ssize_t i = 0; i < n; ++i) {
            const pgloss_bridge_params p = params_at(r.data(), g.data(), b.data(), rough.data(), ior.data(), spec.data(), i);
            pgloss_perceptual q;
            s[i] = static_cast<std::int8_t>(pgloss_bridge_to_perceptual(t, &p, &q, &orr[i]));
            const double v[5] = {q.L, q.a, q.b, q.c, q.d};
            for (int k = 0; k < 5; ++k) op[i * 5 + k] = v[k];
        }
    }
    return py::make_tuple(paint, residual, st);
}

// (β, F0, α) -> the reading (ρd, ρs, α, residual) (n, 4) and the status.
py::tuple reading(int target, const darr &beta, const darr &f0, const darr &alpha) {
    const pgloss_bridge_target t = target_of(target);
    const py::ssize_t n = common_length({&beta, &f0, &alpha});
    py::array_t<double> out({n, py::ssize_t(4)});
    py::array_t<std::int8_t> st(n);
    double *o = out.mutable_data();
    std::int8_t *s = st.mutable_data();
    {
        py::gil_scoped_release nogil;
        for (py::ssize_t i = 0; i < n; ++i)
            s[i] = static_cast<std::int8_t>(pgloss_bridge_read(t, beta.data()[i], f0.data()[i], alpha.data()[i], &o[i * 4]));
    }
    return py::make_tuple(out, st);
}

// Parameters -> (β, F0, α) of the target's model, and the status.
py::tuple model_inputs(int target, const darr &r, const darr &g, const darr &b, const darr &rough, const darr &ior,
                       const darr &spec) {
    const pgloss_bridge_target t = target_of(target);
    const py::ssize_t n = common_length({&r, &g, &b, &rough, &ior, &spec});
    py::array_t<double> beta(n), f0(n), alpha(n);
    py::array_t<std::int8_t> st(n);
    double *ob = beta.mutable_data(), *of = f0.mutable_data(), *oa = alpha.mutable_data();
    std::int8_t *s = st.mutable_data();
    {
        py::gil_scoped_release nogil;
        for (py::ssize_t i = 0; i < n; ++i) {
            const pgloss_bridge_params p = params_at(r.data(), g.data(), b.data(), rough.data(), ior.data(), spec.data(), i);
            s[i] = static_cast<std::int8_t>(pgloss_bridge_model_inputs(t, &p, &ob[i], &of[i], &oa[i]));
        }
    }
    return py::make_tuple(beta, f0, alpha, st);
}

// Base colour, F0, α -> the target's parameters, and the status.
py::tuple params_from_model(int target, const darr &r, const darr &g, const darr &b, const darr &f0, const darr &alpha) {
    const pgloss_bridge_target t = target_of(target);
    const py::ssize_t n = common_length({&r, &g, &b, &f0, &alpha});
    py::array_t<double> base({n, py::ssize_t(3)}), rough(n), ior(n), spec(n);
    py::array_t<std::int8_t> st(n);
    double *ob = base.mutable_data(), *orr = rough.mutable_data(), *oi = ior.mutable_data(), *os = spec.mutable_data();
    std::int8_t *s = st.mutable_data();
    {
        py::gil_scoped_release nogil;
        for (py::ssize_t i = 0; i < n; ++i) {
            const double rgb[3] = {r.data()[i], g.data()[i], b.data()[i]};
            pgloss_bridge_params p;
            s[i] = static_cast<std::int8_t>(pgloss_bridge_params_from_model(t, rgb, f0.data()[i], alpha.data()[i], &p));
            for (int k = 0; k < 3; ++k) ob[i * 3 + k] = p.base_color[k];
            orr[i] = p.roughness;
            oi[i] = p.ior;
            os[i] = p.specular;
        }
    }
    return py::make_tuple(base, rough, ior, spec, st);
}

}  // namespace

void pgloss_py_bind_bridge(py::module_ &mod) {
    mod.attr("BRIDGE_TARGET_COUNT") = PGLOSS_BRIDGE_TARGET_COUNT;
    mod.attr("ERR_BRIDGE_BASE") = static_cast<int>(PGLOSS_ERR_BRIDGE_BASE);
    mod.attr("ERR_BRIDGE_SPECULAR") = static_cast<int>(PGLOSS_ERR_BRIDGE_SPECULAR);
    mod.attr("ERR_BRIDGE_ROUGHNESS") = static_cast<int>(PGLOSS_ERR_BRIDGE_ROUGHNESS);
    mod.def("bridge_target_name", [](int t) { return std::string(pgloss_bridge_target_name(static_cast<pgloss_bridge_target>(t))); });
    mod.def("bridge_range", [](int t) {
        double f0_min, f0_max, a_min, a_max;
        const int s = pgloss_bridge_range(target_of(t), &f0_min, &f0_max, &a_min, &a_max);
        return py::make_tuple(f0_min, f0_max, a_min, a_max, s);
    });
    mod.def("bridge_from_perceptual", &from_perceptual);
    mod.def("bridge_to_perceptual", &to_perceptual);
    mod.def("bridge_read", &reading);
    mod.def("bridge_model_inputs", &model_inputs);
    mod.def("bridge_params_from_model", &params_from_model);
}
