// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// core.cpp — pgloss._core: the C core's functions over flat numpy arrays.
//
// This is the low layer of the Python package. It takes flat, C-contiguous arrays that
// pgloss/__init__.py has already broadcast and converted, loops in C++ over the core with
// the GIL released, and returns the outputs together with the core's status per element
// (perceptual functions) or the first failing element (BRDF functions). Turning statuses
// into exceptions and warnings, broadcasting, dtypes and docstrings for users live in
// pgloss/__init__.py.
//
// Threads: a long array call is split over pgloss.get_num_threads() threads, in contiguous
// ranges of whole chunks (parallel.h); the results are the same bits for any thread count.
//
// BRDF precision: float32 directions go through the vectorised batched entry points
// (pgloss/batch.h), de-interleaved chunk by chunk from the (n, 3) layout into
// structure-of-arrays buffers; float64 directions go through the scalar reference functions
// (pgloss/brdf.h: double arithmetic inside, one rounding to float), after rounding the
// inputs to float as the C API does.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

#include "pgloss/pgloss.h"
#include "parallel.h"
#include "shim.h"

namespace py = pybind11;

namespace {

using darr = py::array_t<double, py::array::c_style | py::array::forcecast>;
using farr = py::array_t<float, py::array::c_style>;  // no forcecast: the caller prepares them
using f64arr = py::array_t<double, py::array::c_style>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Rows of the (n, 3) direction arrays processed per batched call (measured: 128 beats 256,
// 1024 and 4096 rows by 5-25% on 10^6 pairs): small enough that the
// structure-of-arrays buffers stay in L1/L2, large enough to amortise the call.
constexpr size_t kChunk = 128;

// The array calls run over several threads (parallel.h); their loops go in units: 128 direction
// pairs (kChunk), or a slice of kSlice paints for the element-wise functions.
using pgloss_py::Interrupt;
using pgloss_py::run_ranges;
using pgloss_py::StopCheck;
constexpr size_t kSlice = size_t(1) << 13;

inline size_t units_of(size_t n, size_t unit) { return (n + unit - 1) / unit; }

// A status no core function returns: marks a status array the core left unwritten (a
// whole-call error, e.g. an unknown normalisation: nothing is written).
constexpr signed char kUnwritten = 127;

// ---------------------------------------------------------------------------------------
// Element-wise map over double functions: NI flat inputs of equal length, NO outputs, and
// the status of every element (int8). f(x, y) -> status; y is pre-filled with NaN so that
// an output the core failed to write is visible (the core always writes them).
template <size_t NI, size_t NO, class F>
py::tuple vmap(const std::array<darr, NI> &in, F f) {
    const py::ssize_t n = in[0].size();
    std::array<const double *, NI> ip{};
    for (size_t k = 0; k < NI; ++k) {
        if (in[k].ndim() != 1 || in[k].size() != n)
            throw std::invalid_argument("pgloss._core: inputs must be flat arrays of equal length");
        ip[k] = in[k].data();
    }
    std::array<darr, NO> out;
    std::array<double *, NO> op{};
    for (size_t k = 0; k < NO; ++k) {
        out[k] = darr(n);
        op[k] = out[k].mutable_data();
    }
    py::array_t<std::int8_t> st(n);
    std::int8_t *sp = st.mutable_data();
    const auto count = static_cast<size_t>(n);
    Interrupt I;
    {
        py::gil_scoped_release nogil;
        run_ranges<char>(count * pgloss_py::kScalarCost, units_of(count, kSlice), I, [&](size_t u0, size_t u1, StopCheck &stop) {
            for (size_t u = u0; u < u1; ++u) {
                if (stop((u - u0) * kSlice)) break;
                const size_t end = std::min(count, (u + 1) * kSlice);
                for (size_t i = u * kSlice; i < end; ++i) {
                    std::array<double, NI> x;
                    std::array<double, NO> y;
                    for (size_t k = 0; k < NI; ++k) x[k] = ip[k][i];
                    y.fill(kNaN);
                    const int s = f(x.data(), y.data());
                    for (size_t k = 0; k < NO; ++k) op[k][i] = y[k];
                    sp[i] = static_cast<std::int8_t>(s);
                }
            }
            return char(0);
        });
    }
    I.raise_if_signalled();
    py::tuple t(NO + 1);
    for (size_t k = 0; k < NO; ++k) t[k] = out[k];
    t[NO] = st;
    return t;
}

// ---------------------------------------------------------------------------------------
// Element-wise map over a batched core function (pgloss/perceptual_batch.h): NI flat
// inputs of equal length, NO outputs and the status of every element (int8), in slices of
// kSlice elements (Ctrl-C and the threads' ranges between slices). batch(m, x, y, st) runs one slice. A
// whole-call error of the batch (an unknown colour space or normalisation: nothing written)
// falls back to the scalar function, element by element, so that each element gets exactly
// the scalar function's status (the order of its checks) and outputs.
template <size_t NI, size_t NO, class Batch, class Scalar>
py::tuple bmap(const std::array<darr, NI> &in, Batch batch, Scalar scalar) {
    const py::ssize_t n = NI ? in[0].size() : 0;
    std::array<const double *, NI> ip{};
    for (size_t k = 0; k < NI; ++k) {
        if (in[k].ndim() != 1 || in[k].size() != n)
            throw std::invalid_argument("pgloss._core: inputs must be flat arrays of equal length");
        ip[k] = in[k].data();
    }
    // One (NO, n) block: each output a contiguous row (a conversion's rho_d r, g, b rows are
    // then one channel-first array for Python, without a copy).
    darr block(std::vector<py::ssize_t>{static_cast<py::ssize_t>(NO), n});
    std::array<double *, NO> op{};
    for (size_t k = 0; k < NO; ++k) op[k] = block.mutable_data() + k * static_cast<size_t>(n);
    py::array_t<std::int8_t> st(n);
    auto *sp = reinterpret_cast<signed char *>(st.mutable_data());
    const auto count = static_cast<size_t>(n);
    Interrupt I;
    {
        py::gil_scoped_release nogil;
        run_ranges<char>(count, units_of(count, kSlice), I, [&](size_t u0, size_t u1, StopCheck &stop) {
            for (size_t u = u0; u < u1; ++u) {
                if (stop((u - u0) * kSlice)) break;
                const size_t base = u * kSlice;
                const size_t m = std::min(kSlice, count - base);
                std::array<const double *, NI> x{};
                std::array<double *, NO> y{};
                for (size_t k = 0; k < NI; ++k) x[k] = ip[k] + base;
                for (size_t k = 0; k < NO; ++k) y[k] = op[k] + base;
                sp[base] = kUnwritten;
                const int s = batch(m, x.data(), y.data(), sp + base);
                if (s < 0 && sp[base] == kUnwritten) {
                    for (size_t j = 0; j < m; ++j) {
                        std::array<double, NI> xs;
                        std::array<double, NO> ys;
                        for (size_t k = 0; k < NI; ++k) xs[k] = x[k][j];
                        ys.fill(kNaN);
                        sp[base + j] = static_cast<signed char>(scalar(xs.data(), ys.data()));
                        for (size_t k = 0; k < NO; ++k) y[k][j] = ys[k];
                    }
                }
            }
            return char(0);
        });
    }
    I.raise_if_signalled();
    py::tuple t(NO + 2);  // the outputs (rows of the block), the statuses, the block
    for (size_t k = 0; k < NO; ++k) t[k] = block[py::int_(k)];
    t[NO] = st;
    t[NO + 1] = block;
    return t;
}

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
    const int st = pgloss_py_material_init(&M.m, v.data(), normalization);
    return {M, st};
}

py::tuple rgb_tuple(const float *c) { return py::make_tuple(c[0], c[1], c[2]); }

// Float conversion of a double input as the C API receives it: values beyond float range
// become ±Inf (the core then reports them); the C++ cast of such a value would be undefined.
// A select, not a branch: the per-element materials' columns go through it (six per element),
// and as a branch that loop stayed scalar (about 2 of the ~16 ns per pair of Python's eval with
// one material per pair; BENCHMARKS.md).
inline float to_float(double x) {
    const double c = std::fabs(x) > static_cast<double>(FLT_MAX) ? std::copysign(HUGE_VAL, x) : x;
    return static_cast<float>(c);
}

size_t rows_of(const py::array &a, const char *what) {
    if (a.ndim() != 1 || a.size() % 3 != 0)
        throw std::invalid_argument(std::string("pgloss._core: ") + what + " must be a flat array of n*3 values");
    return static_cast<size_t>(a.size() / 3);
}

struct FirstError {
    int status = PGLOSS_OK;
    py::ssize_t index = -1;
    void note(int st, py::ssize_t i) {
        if (st < 0 && status == PGLOSS_OK) {
            status = st;
            index = i;
        }
    }
};

// The first error of the call: the ranges are in index order, so the first range with one.
FirstError first_of(const std::vector<FirstError> &ranges) {
    for (const FirstError &e : ranges)
        if (e.status != PGLOSS_OK) return e;
    return FirstError{};
}

// Whether a chunk's input rows are read with the rows two chunks ahead prefetched. Where the
// C loop's work on a chunk is long (float64; one material per element; sampling), the
// hardware's stream prefetcher stops running ahead during it, and the next chunk's first loads
// wait on DRAM (perf: 57 % of the float64 copy's time at two loads); prefetching as the rows
// are read took float64 eval on 2^20 pairs from 12.5–12.8 to 10.7–11.0 ns a pair and float32
// per-element eval from 8.4–8.8 to 7.7–8.1. float32 with one material has the shortest chunk
// and is at the memory's speed already; it was 7 % slower with the prefetch, so it goes
// without (BENCHMARKS.md). Prefetches never fault, past the array's end included.
enum class Ahead : bool { no = false, yes = true };

// Rows j to m − 1 of (n, 3) rows <-> three arrays, one at a time: the SSE2 loops' tails below,
// and every other target.
template <class T>
inline void rows_to_arrays(size_t j, size_t m, const T *__restrict__ src, T *__restrict__ x, T *__restrict__ y,
                           T *__restrict__ z) {
    for (; j < m; ++j) {
        x[j] = src[3 * j];
        y[j] = src[3 * j + 1];
        z[j] = src[3 * j + 2];
    }
}

template <class T>
inline void arrays_to_rows(size_t j, size_t m, const T *__restrict__ x, const T *__restrict__ y,
                           const T *__restrict__ z, T *__restrict__ dst) {
    for (; j < m; ++j) {
        dst[3 * j] = x[j];
        dst[3 * j + 1] = y[j];
        dst[3 * j + 2] = z[j];
    }
}

// (n, 3) rows <-> three arrays, for one chunk. With SSE2 (every x86-64), four rows at a
// time by shuffles (GCC only vectorises the stride-3 accesses with 8-byte vectors); the
// portable loop does the rest and every other target.
inline void deinterleave(size_t m, const float *__restrict__ src, float *__restrict__ x, float *__restrict__ y,
                         float *__restrict__ z, Ahead prefetch = Ahead::yes) {
    size_t j = 0;
#if defined(__SSE2__)
    const char *ahead = reinterpret_cast<const char *>(src) + 2 * kChunk * 3 * sizeof(float);
    for (; j + 4 <= m; j += 4) {
        if (prefetch == Ahead::yes) _mm_prefetch(ahead + 3 * sizeof(float) * j, _MM_HINT_T0);
        const __m128 a = _mm_loadu_ps(src + 3 * j);      // x0 y0 z0 x1
        const __m128 b = _mm_loadu_ps(src + 3 * j + 4);  // y1 z1 x2 y2
        const __m128 c = _mm_loadu_ps(src + 3 * j + 8);  // z2 x3 y3 z3
        const __m128 bc = _mm_shuffle_ps(b, c, _MM_SHUFFLE(1, 1, 2, 2));       // x2 x2 x3 x3
        _mm_storeu_ps(x + j, _mm_shuffle_ps(a, bc, _MM_SHUFFLE(2, 0, 3, 0)));  // x0 x1 x2 x3
        const __m128 ab1 = _mm_shuffle_ps(a, b, _MM_SHUFFLE(0, 0, 1, 1));      // y0 y0 y1 y1
        const __m128 bc3 = _mm_shuffle_ps(b, c, _MM_SHUFFLE(2, 2, 3, 3));      // y2 y2 y3 y3
        _mm_storeu_ps(y + j, _mm_shuffle_ps(ab1, bc3, _MM_SHUFFLE(2, 0, 2, 0)));
        const __m128 ab2 = _mm_shuffle_ps(a, b, _MM_SHUFFLE(1, 1, 2, 2));      // z0 z0 z1 z1
        _mm_storeu_ps(z + j, _mm_shuffle_ps(ab2, c, _MM_SHUFFLE(3, 0, 2, 0)));  // z0 z1 z2 z3
    }
#endif
    rows_to_arrays(j, m, src, x, y, z);
}

inline void interleave(size_t m, const float *__restrict__ x, const float *__restrict__ y,
                       const float *__restrict__ z, float *__restrict__ dst) {
    size_t j = 0;
#if defined(__SSE2__)
    for (; j + 4 <= m; j += 4) {
        const __m128 X = _mm_loadu_ps(x + j), Y = _mm_loadu_ps(y + j), Z = _mm_loadu_ps(z + j);
        const __m128 lo = _mm_unpacklo_ps(X, Y);  // x0 y0 x1 y1
        const __m128 hi = _mm_unpackhi_ps(X, Y);  // x2 y2 x3 y3
        const __m128 zx = _mm_shuffle_ps(Z, X, _MM_SHUFFLE(1, 1, 0, 0));       // z0 z0 x1 x1
        _mm_storeu_ps(dst + 3 * j, _mm_shuffle_ps(lo, zx, _MM_SHUFFLE(2, 0, 1, 0)));      // x0 y0 z0 x1
        const __m128 yz = _mm_shuffle_ps(Y, Z, _MM_SHUFFLE(1, 1, 1, 1));       // y1 y1 z1 z1
        _mm_storeu_ps(dst + 3 * j + 4, _mm_shuffle_ps(yz, hi, _MM_SHUFFLE(1, 0, 2, 0)));  // y1 z1 x2 y2
        const __m128 u = _mm_shuffle_ps(hi, Z, _MM_SHUFFLE(3, 2, 3, 2));       // x3 y3 z2 z3
        _mm_storeu_ps(dst + 3 * j + 8, _mm_shuffle_ps(u, u, _MM_SHUFFLE(3, 1, 0, 2)));    // z2 x3 y3 z3
    }
#endif
    arrays_to_rows(j, m, x, y, z, dst);
}

// ---------------------------------------------------------------------------------------
// Outputs: a caller's out= array (checked again here: C-contiguous, writeable, the exact
// dtype and size) or a new one.

template <class T>
py::array_t<T> output(const py::object &given, py::ssize_t count, const std::vector<py::ssize_t> &shape,
                      const char *what) {
    if (given.is_none()) return py::array_t<T>(shape);
    if (!py::isinstance<py::array>(given)) throw std::invalid_argument(std::string("pgloss._core: out ") + what);
    py::array a = py::reinterpret_borrow<py::array>(given);
    if (!a.dtype().is(py::dtype::of<T>()) || !(a.flags() & py::array::c_style) || !a.writeable() ||
        a.size() != count)
        throw std::invalid_argument(std::string("pgloss._core: out ") + what +
                                    " must be a C-contiguous writeable array of the result's dtype and size");
    return py::reinterpret_borrow<py::array_t<T>>(given);
}

// The same for double rows, two at a time with SSE2: three loads or stores of two doubles
// and three shuffles for two rows, where GCC leaves the stride-3 loop scalar (six loads
// and six stores): a chunk's wo, wi and f cost 1.7–1.8 ns a pair instead of 2.6–2.9 in
// cache (BENCHMARKS.md).
inline void deinterleave(size_t m, const double *__restrict__ src, double *__restrict__ x,
                         double *__restrict__ y, double *__restrict__ z, Ahead prefetch = Ahead::yes) {
    size_t j = 0;
#if defined(__SSE2__)
    const char *ahead = reinterpret_cast<const char *>(src) + 2 * kChunk * 3 * sizeof(double);
    for (; j + 2 <= m; j += 2) {
        if (prefetch == Ahead::yes) _mm_prefetch(ahead + 3 * sizeof(double) * j, _MM_HINT_T0);
        const __m128d a = _mm_loadu_pd(src + 3 * j);      // x0 y0
        const __m128d b = _mm_loadu_pd(src + 3 * j + 2);  // z0 x1
        const __m128d c = _mm_loadu_pd(src + 3 * j + 4);  // y1 z1
        _mm_storeu_pd(x + j, _mm_shuffle_pd(a, b, 2));    // x0 x1
        _mm_storeu_pd(y + j, _mm_shuffle_pd(a, c, 1));    // y0 y1
        _mm_storeu_pd(z + j, _mm_shuffle_pd(b, c, 2));    // z0 z1
    }
#endif
    rows_to_arrays(j, m, src, x, y, z);
}

inline void interleave(size_t m, const double *__restrict__ x, const double *__restrict__ y,
                       const double *__restrict__ z, double *__restrict__ dst) {
    size_t j = 0;
#if defined(__SSE2__)
    for (; j + 2 <= m; j += 2) {
        const __m128d X = _mm_loadu_pd(x + j), Y = _mm_loadu_pd(y + j), Z = _mm_loadu_pd(z + j);
        _mm_storeu_pd(dst + 3 * j, _mm_unpacklo_pd(X, Y));      // x0 y0
        _mm_storeu_pd(dst + 3 * j + 2, _mm_shuffle_pd(Z, X, 2));  // z0 x1
        _mm_storeu_pd(dst + 3 * j + 4, _mm_unpackhi_pd(Y, Z));  // y1 z1
    }
#endif
    arrays_to_rows(j, m, x, y, z, dst);
}

// The C structs of one precision: float (pgloss/batch.h) or double (pgloss/batch_materials.h).
template <class T> struct Soa;
template <> struct Soa<float> {
    using in = pgloss_vec3_array;
    using out = pgloss_vec3_out;
    using rgb = pgloss_rgb_out;
};
template <> struct Soa<double> {
    using in = pgloss_vec3_array_d;
    using out = pgloss_vec3_out_d;
    using rgb = pgloss_rgb_out_d;
};

// One material for the batch: float → pgloss_*_batch (the FLOAT tier); double →
// pgloss_*_batch_d. The status of the first failing element is found, on the error path only,
// from the _ex form's status array (double) or the scalar pdf (float).
template <class T>
int eval_chunk(const Material &M, unsigned lobes, size_t m, typename Soa<T>::in a, typename Soa<T>::in b,
               typename Soa<T>::rgb fo, T *pd, bool want_f, bool want_pdf) {
    if constexpr (std::is_same_v<T, float>) {
        if (want_f && want_pdf) return pgloss_eval_pdf_batch(&M.m, lobes, m, a, b, fo, pd);
        if (want_f) return pgloss_eval_batch(&M.m, lobes, m, a, b, fo);
        return pgloss_pdf_batch(&M.m, lobes, m, a, b, pd);
    } else {
        if (want_f && want_pdf) return pgloss_eval_pdf_batch_d(&M.m, lobes, m, a, b, fo, pd);
        if (want_f) return pgloss_eval_batch_d(&M.m, lobes, m, a, b, fo);
        return pgloss_pdf_batch_d(&M.m, lobes, m, a, b, pd);
    }
}

template <class T>
py::ssize_t first_bad_eval(const Material &M, unsigned lobes, size_t m, typename Soa<T>::in a,
                           typename Soa<T>::in b) {
    if constexpr (std::is_same_v<T, float>) {
        for (size_t j = 0; j < m; ++j) {
            float p;
            if (pgloss_pdf(&M.m, pgloss_vec3{a.x[j], a.y[j], a.z[j]}, pgloss_vec3{b.x[j], b.y[j], b.z[j]}, lobes, &p) <
                0)
                return static_cast<py::ssize_t>(j);
        }
        return 0;
    } else {
        std::vector<double> scratch(4 * m);
        std::vector<signed char> st(m);
        pgloss_eval_pdf_batch_d_ex(nullptr, &M.m, lobes, m, a, b,
                                   pgloss_rgb_out_d{scratch.data(), scratch.data() + m, scratch.data() + 2 * m},
                                   scratch.data() + 3 * m, st.data());
        for (size_t j = 0; j < m; ++j)
            if (st[j] < 0) return static_cast<py::ssize_t>(j);
        return 0;
    }
}

template <class T>
py::tuple eval_uniform(const Material &M, unsigned lobes, const py::array_t<T, py::array::c_style> &wo,
                       const py::array_t<T, py::array::c_style> &wi, bool want_f, bool want_pdf,
                       const py::object &f_out, const py::object &p_out) {
    const size_t n = rows_of(wo, "wo");
    if (rows_of(wi, "wi") != n) throw std::invalid_argument("pgloss._core: wo and wi differ in length");
    const auto N = static_cast<py::ssize_t>(n);
    auto f = output<T>(want_f ? f_out : py::none(), want_f ? 3 * N : 0,
                       std::vector<py::ssize_t>{want_f ? N : 0, 3}, "f");
    auto pdf = output<T>(want_pdf ? p_out : py::none(), want_pdf ? N : 0, {want_pdf ? N : 0}, "pdf");
    const T *o = wo.data(), *i = wi.data();
    T *fp = want_f ? f.mutable_data() : nullptr, *pp = want_pdf ? pdf.mutable_data() : nullptr;
    Interrupt I;
    std::vector<FirstError> errs;
    {
        py::gil_scoped_release nogil;
        errs = run_ranges<FirstError>(n, units_of(n, kChunk), I, [&](size_t c0, size_t c1, StopCheck &stop) {
            FirstError err;
            std::vector<T> buf(10 * kChunk);
            T *ox = buf.data(), *oy = ox + kChunk, *oz = oy + kChunk, *ix = oz + kChunk, *iy = ix + kChunk,
              *iz = iy + kChunk, *fr = iz + kChunk, *fg = fr + kChunk, *fb = fg + kChunk, *pd = fb + kChunk;
            for (size_t base = c0 * kChunk; base < std::min(n, c1 * kChunk); base += kChunk) {
                if (stop(base - c0 * kChunk)) break;
                const size_t m = n - base < kChunk ? n - base : kChunk;
                constexpr Ahead ahead = std::is_same_v<T, float> ? Ahead::no : Ahead::yes;
                deinterleave(m, o + 3 * base, ox, oy, oz, ahead);
                deinterleave(m, i + 3 * base, ix, iy, iz, ahead);
                const typename Soa<T>::in a{ox, oy, oz}, b{ix, iy, iz};
                const int st = eval_chunk<T>(M, lobes, m, a, b, typename Soa<T>::rgb{fr, fg, fb}, pd, want_f, want_pdf);
                if (want_f) interleave(m, fr, fg, fb, fp + 3 * base);
                if (want_pdf) std::copy(pd, pd + m, pp + base);
                if (st < 0 && err.status == PGLOSS_OK)
                    err.note(st, static_cast<py::ssize_t>(base) + first_bad_eval<T>(M, lobes, m, a, b));
            }
            return err;
        });
    }
    I.raise_if_signalled();
    const FirstError err = first_of(errs);
    return py::make_tuple(f, pdf, err.status, err.index);
}

// One material per element: the (6, n) float32 block of the materials' parameters (rho_d r, g,
// b, rho_s, alpha_x, alpha_y), already rounded to float as the core's pgloss_material_array
// holds them (material_columns below; pgloss/__init__.py keeps it on the Physical). The float
// batch reads it in place; the double batch widens it chunk by chunk (exactly).
struct Columns {
    const float *p = nullptr;
    size_t n = 0;
};

Columns columns_of(const farr &block, size_t n) {
    if (block.ndim() != 2 || block.shape(0) != 6 || static_cast<size_t>(block.shape(1)) != n)
        throw std::invalid_argument("pgloss._core: the material block must be a (6, n) float32 array, n the batch's length");
    return Columns{block.data(), n};
}

// The material's six double columns rounded to float once, as the C API receives them (beyond
// float range they become ±Inf, which the core reports as NONFINITE, as pgloss_material_init
// does): the (6, n) float32 block that eval_materials and sample_any read. A material is a
// pgloss_material (float parameters, as every C caller's and the scalar double reference's),
// whatever the directions' precision.
py::array_t<float> material_columns(const std::array<darr, 6> &cols) {
    const py::ssize_t n = cols[0].size();
    std::array<const double *, 6> src{};
    for (size_t k = 0; k < 6; ++k) {
        if (cols[k].ndim() != 1 || cols[k].size() != n)
            throw std::invalid_argument("pgloss._core: material columns must be flat arrays of equal length");
        src[k] = cols[k].data();
    }
    const auto count = static_cast<size_t>(n);
    py::array_t<float> block(std::vector<py::ssize_t>{6, n});
    float *dst = block.mutable_data();
    Interrupt I;
    {
        py::gil_scoped_release nogil;
        run_ranges<char>(count, units_of(count, kSlice), I, [&](size_t u0, size_t u1, StopCheck &stop) {
            for (size_t u = u0; u < u1; ++u) {
                if (stop((u - u0) * kSlice)) break;
                const size_t base = u * kSlice, end = std::min(count, base + kSlice);
                for (size_t k = 0; k < 6; ++k)
                    for (size_t j = base; j < end; ++j) dst[k * count + j] = to_float(src[k][j]);
            }
            return char(0);
        });
    }
    I.raise_if_signalled();
    return block;
}

// One chunk of the material columns in the batch's precision: the block itself (float), or
// the chunk widened into buf (double).
template <class T>
std::array<const T *, 6> material_chunk(const Columns &C, size_t base, size_t m, T *buf) {
    std::array<const T *, 6> mc{};
    for (size_t k = 0; k < 6; ++k) {
        const float *src = C.p + k * C.n + base;
        if constexpr (std::is_same_v<T, float>) {
            (void)m;
            (void)buf;
            mc[k] = src;
        } else {
            T *dst = buf + k * kChunk;
            for (size_t j = 0; j < m; ++j) dst[j] = static_cast<T>(src[j]);
            mc[k] = dst;
        }
    }
    return mc;
}

// The per-element status array, allocated (all zeros) at the first chunk with an error, in
// whichever thread meets it first: every chunk without an error keeps its zeros, which are
// right. Writing statuses halves the loops' speed, and a texture without errors needs none;
// pgloss/__init__.py gets None then. The threads write disjoint ranges of it.
struct LazyStatus {
    std::vector<signed char> v;
    std::mutex mu;
    signed char *at(size_t n, size_t base) {  // GIL released: no Python objects
        std::lock_guard<std::mutex> lock(mu);
        if (v.empty()) v.assign(n, 0);
        return v.data() + base;
    }
    py::object array() const {  // GIL held
        if (v.empty()) return py::none();
        py::array_t<std::int8_t> a(static_cast<py::ssize_t>(v.size()));
        std::copy(v.begin(), v.end(), reinterpret_cast<signed char *>(a.mutable_data()));
        return std::move(a);
    }
};

template <class T>
py::tuple eval_materials(const farr &block, int normalization, unsigned lobes,
                         const py::array_t<T, py::array::c_style> &wo, const py::array_t<T, py::array::c_style> &wi,
                         bool want_f, bool want_pdf, const py::object &f_out, const py::object &p_out) {
    const size_t n = rows_of(wo, "wo");
    if (rows_of(wi, "wi") != n) throw std::invalid_argument("pgloss._core: wo and wi differ in length");
    const Columns C = columns_of(block, n);
    const auto N = static_cast<py::ssize_t>(n);
    auto f = output<T>(want_f ? f_out : py::none(), want_f ? 3 * N : 0,
                       std::vector<py::ssize_t>{want_f ? N : 0, 3}, "f");
    auto pdf = output<T>(want_pdf ? p_out : py::none(), want_pdf ? N : 0, {want_pdf ? N : 0}, "pdf");
    const T *o = wo.data(), *i = wi.data();
    T *fp = want_f ? f.mutable_data() : nullptr, *pp = want_pdf ? pdf.mutable_data() : nullptr;
    LazyStatus status;
    Interrupt I;
    std::vector<FirstError> errs;
    {
        py::gil_scoped_release nogil;
        errs = run_ranges<FirstError>(n, units_of(n, kChunk), I, [&](size_t c0, size_t c1, StopCheck &stop) {
            FirstError err;
            std::vector<T> buf(10 * kChunk);
            T *ox = buf.data(), *oy = ox + kChunk, *oz = oy + kChunk, *ix = oz + kChunk, *iy = ix + kChunk,
              *iz = iy + kChunk, *fr = iz + kChunk, *fg = fr + kChunk, *fb = fg + kChunk, *pd = fb + kChunk;
            std::vector<T> mbuf(std::is_same_v<T, float> ? 0 : 6 * kChunk);
            for (size_t base = c0 * kChunk; base < std::min(n, c1 * kChunk); base += kChunk) {
                if (stop(base - c0 * kChunk)) break;
                const size_t m = n - base < kChunk ? n - base : kChunk;
                deinterleave(m, o + 3 * base, ox, oy, oz);
                deinterleave(m, i + 3 * base, ix, iy, iz);
                const auto mc = material_chunk<T>(C, base, m, mbuf.data());
                auto call = [&](signed char *status_out) -> int {
                    if constexpr (std::is_same_v<T, float>)
                        return pgloss_py_eval_pdf_batch_materials(
                            mc.data(), normalization, lobes, m, pgloss_vec3_array{ox, oy, oz}, pgloss_vec3_array{ix, iy, iz},
                            want_f ? pgloss_rgb_out{fr, fg, fb} : pgloss_rgb_out{nullptr, nullptr, nullptr},
                            want_pdf ? pd : nullptr, status_out);
                    else
                        return pgloss_py_eval_pdf_batch_materials_d(
                            mc.data(), normalization, lobes, m, pgloss_vec3_array_d{ox, oy, oz},
                            pgloss_vec3_array_d{ix, iy, iz},
                            want_f ? pgloss_rgb_out_d{fr, fg, fb} : pgloss_rgb_out_d{nullptr, nullptr, nullptr},
                            want_pdf ? pd : nullptr, status_out);
                };
                // Without the status array first; a chunk with an error runs again with it, for
                // the statuses (the outputs are the same).
                int st = call(nullptr);
                if (st < 0) {
                    signed char *sp = status.at(n, base);
                    std::fill(sp, sp + m, kUnwritten);
                    st = call(sp);
                    if (st < 0 && m > 0 && sp[0] == kUnwritten) {
                        // A whole-call error (nothing written): every element gets it.
                        std::fill(sp, sp + m, static_cast<signed char>(st));
                        std::fill(fr, fr + 3 * kChunk + kChunk, T(0));
                    }
                    if (st < 0 && err.status == PGLOSS_OK)
                        for (size_t j = 0; j < m; ++j)
                            if (sp[j] < 0) {
                                err.note(sp[j], static_cast<py::ssize_t>(base + j));
                                break;
                            }
                }
                if (want_f) interleave(m, fr, fg, fb, fp + 3 * base);
                if (want_pdf) std::copy(pd, pd + m, pp + base);
            }
            return err;
        });
    }
    I.raise_if_signalled();
    const FirstError err = first_of(errs);
    return py::make_tuple(f, pdf, status.array(), err.status, err.index);
}

// ---------------------------------------------------------------------------------------
// sample.

template <class T>
py::tuple sample_any(const Material *M, const Columns *C, int normalization, unsigned lobes,
                     const py::array_t<T, py::array::c_style> &wo, const py::array_t<T, py::array::c_style> &u,
                     const py::object &wi_out, const py::object &pdf_out, const py::object &weight_out,
                     const py::object &lobe_out) {
    const size_t n = rows_of(wo, "wo");
    if (rows_of(u, "u") != n) throw std::invalid_argument("pgloss._core: wo and u differ in length");
    const auto N = static_cast<py::ssize_t>(n);
    auto wi = output<T>(wi_out, 3 * N, {N, 3}, "wi");
    auto weight = output<T>(weight_out, 3 * N, {N, 3}, "weight");
    auto pdf = output<T>(pdf_out, N, {N}, "pdf");
    auto lobe = output<std::uint8_t>(lobe_out, N, {N}, "lobe");
    LazyStatus status;  // per-element materials: the statuses, once a chunk has an error
    const T *o = wo.data(), *uu = u.data();
    T *wp = wi.mutable_data(), *gp = weight.mutable_data(), *pp = pdf.mutable_data();
    std::uint8_t *lp = lobe.mutable_data();
    Interrupt I;
    std::vector<FirstError> errs;
    {
        py::gil_scoped_release nogil;
        errs = run_ranges<FirstError>(n, units_of(n, kChunk), I, [&](size_t c0, size_t c1, StopCheck &stop) {
            FirstError err;
            std::vector<T> buf(13 * kChunk);
            T *ox = buf.data(), *oy = ox + kChunk, *oz = oy + kChunk, *u0 = oz + kChunk, *u1 = u0 + kChunk,
              *u2 = u1 + kChunk, *wx = u2 + kChunk, *wy = wx + kChunk, *wz = wy + kChunk, *pd = wz + kChunk,
              *gr = pd + kChunk, *gg = gr + kChunk, *gb = gg + kChunk;
            std::vector<T> mbuf(C && !std::is_same_v<T, float> ? 6 * kChunk : 0);
            std::vector<signed char> chunk_status(C ? 0 : kChunk);
            for (size_t base = c0 * kChunk; base < std::min(n, c1 * kChunk); base += kChunk) {
                if (stop(base - c0 * kChunk)) break;
                const size_t m = n - base < kChunk ? n - base : kChunk;
                deinterleave(m, o + 3 * base, ox, oy, oz);
                deinterleave(m, uu + 3 * base, u0, u1, u2);
                const T *uc[3] = {u0, u1, u2};
                std::array<const T *, 6> mc{};
                if (C) mc = material_chunk<T>(*C, base, m, mbuf.data());
                // As eval_materials: without the status array first, again with it on an error.
                auto call = [&](signed char *status_out) -> int {
                    if constexpr (std::is_same_v<T, float>) {
                        const pgloss_vec3_array a{ox, oy, oz};
                        const pgloss_vec3_out wo_{wx, wy, wz};
                        const pgloss_rgb_out go{gr, gg, gb};
                        if (C)
                            return pgloss_py_sample_batch_materials(mc.data(), normalization, lobes, m, a, uc, wo_, pd, go,
                                                                    lp + base, status_out);
                        const int r = pgloss_sample_batch(&M->m, lobes, m, a, u0, u1, u2, wo_, pd, go, lp + base);
                        if (r < 0 && status_out) {  // which element? the scalar function, on the error path only
                            std::fill(status_out, status_out + m, 0);
                            for (size_t j = 0; j < m; ++j) {
                                pgloss_sample_record rec;
                                const float uj[3] = {u0[j], u1[j], u2[j]};
                                status_out[j] = static_cast<signed char>(
                                    pgloss_sample(&M->m, pgloss_vec3{ox[j], oy[j], oz[j]}, uj, lobes, &rec));
                                if (status_out[j] < 0) break;
                            }
                        }
                        return r;
                    } else {
                        const pgloss_vec3_array_d a{ox, oy, oz};
                        const pgloss_vec3_out_d wo_{wx, wy, wz};
                        const pgloss_rgb_out_d go{gr, gg, gb};
                        if (C)
                            return pgloss_py_sample_batch_materials_d(mc.data(), normalization, lobes, m, a, uc, wo_, pd,
                                                                      go, lp + base, status_out);
                        if (!status_out) return pgloss_sample_batch_d(&M->m, lobes, m, a, u0, u1, u2, wo_, pd, go, lp + base);
                        return pgloss_sample_batch_d_ex(nullptr, &M->m, lobes, m, a, u0, u1, u2, wo_, pd, go, lp + base,
                                                        status_out);
                    }
                };
                int st = call(nullptr);
                signed char *cs = nullptr;  // this chunk's statuses, on an error only
                if (st < 0) {
                    cs = C ? status.at(n, base) : chunk_status.data();
                    std::fill(cs, cs + m, kUnwritten);
                    st = call(cs);
                }
                if (st < 0 && m > 0 && cs[0] == kUnwritten) {
                    std::fill(cs, cs + m, static_cast<signed char>(st));  // a whole-call error: nothing was written
                    std::fill(wx, wx + m, T(0));
                    std::fill(wy, wy + m, T(0));
                    std::fill(wz, wz + m, T(1));
                    std::fill(pd, pd + m, T(0));
                    std::fill(gr, gr + 3 * kChunk, T(0));
                    std::fill(lp + base, lp + base + m, std::uint8_t(0));
                }
                interleave(m, wx, wy, wz, wp + 3 * base);
                interleave(m, gr, gg, gb, gp + 3 * base);
                std::copy(pd, pd + m, pp + base);
                if (st < 0 && err.status == PGLOSS_OK)
                    for (size_t j = 0; j < m; ++j)
                        if (cs[j] < 0) {
                            err.note(cs[j], static_cast<py::ssize_t>(base + j));
                            break;
                        }
                if (st < 0 && err.status == PGLOSS_OK) err.note(st, static_cast<py::ssize_t>(base));
            }
            return err;
        });
    }
    I.raise_if_signalled();
    const FirstError err = first_of(errs);
    if (C) return py::make_tuple(wi, pdf, weight, lobe, status.array(), err.status, err.index);
    return py::make_tuple(wi, pdf, weight, lobe, err.status, err.index);
}

// ---------------------------------------------------------------------------------------
// Benchmark helper: the C batched path alone, on structure-of-arrays buffers that the
// caller preallocated (no conversion, no Python in the timed region). Returns the
// wall-clock seconds of each repetition.
std::vector<double> time_eval_batch(const Material &M, unsigned lobes, const farr &wo_soa, const farr &wi_soa,
                                    int repeats) {
    if (wo_soa.ndim() != 2 || wo_soa.shape(0) != 3 || wi_soa.ndim() != 2 || wi_soa.shape(0) != 3 ||
        wi_soa.shape(1) != wo_soa.shape(1))
        throw std::invalid_argument("time_eval_batch: wo_soa and wi_soa must be (3, n) float32 arrays");
    const size_t n = static_cast<size_t>(wo_soa.shape(1));
    std::vector<float> out(3 * n);
    const float *o = wo_soa.data(), *i = wi_soa.data();
    std::vector<double> times;
    {
        py::gil_scoped_release nogil;
        for (int r = 0; r < repeats; ++r) {
            const auto t0 = std::chrono::steady_clock::now();
            const pgloss_status st =
                pgloss_eval_batch(&M.m, lobes, n, pgloss_vec3_array{o, o + n, o + 2 * n},
                                  pgloss_vec3_array{i, i + n, i + 2 * n},
                                  pgloss_rgb_out{out.data(), out.data() + n, out.data() + 2 * n});
            const auto t1 = std::chrono::steady_clock::now();
            (void)st;
            times.push_back(std::chrono::duration<double>(t1 - t0).count());
        }
    }
    return times;
}

}  // namespace

PYBIND11_MODULE(_core, mod) {
    mod.doc() = "pgloss._core: the C core over flat numpy arrays (use the pgloss package, not this module).";

    mod.attr("VERSION") = pgloss_version();  // the linked library's (pgloss/version.h)
    mod.attr("ALPHA_MIN") = static_cast<double>(PGLOSS_ALPHA_MIN);
    mod.attr("COS_MIN") = static_cast<double>(PGLOSS_COS_MIN);
    mod.attr("CIE_EPSILON") = PGLOSS_CIE_EPSILON;
    mod.attr("CIE_KAPPA") = PGLOSS_CIE_KAPPA;
    mod.attr("D_WEIGHT") = PGLOSS_D_WEIGHT;
    mod.attr("ALPHA_TRUSTED_MAX") = PGLOSS_ALPHA_TRUSTED_MAX;
    mod.attr("BOUNDARY_TOLERANCE") = PGLOSS_BOUNDARY_TOLERANCE;
    mod.attr("LUMA") = py::make_tuple(PGLOSS_LUMA_R, PGLOSS_LUMA_G, PGLOSS_LUMA_B);
    { void pgloss_py_bind_bridge(py::module_ &); pgloss_py_bind_bridge(mod); }  // pgloss.bridge (bridge.cpp)

    // The thread count of the array calls; pgloss.set_num_threads validates it and reads
    // PGLOSS_NUM_THREADS at import (parallel.h).
    mod.def("set_num_threads", [](int n) {
        if (n < 1) throw py::value_error("pgloss._core.set_num_threads: n must be at least 1");
        return pgloss_py::num_threads().exchange(n);
    });
    mod.def("get_num_threads", [] { return pgloss_py::num_threads().load(); });
    mod.attr("MIN_ELEMENTS_PER_THREAD") = pgloss_py::kMinPerThread;
    // For the tests and the benchmark only: the threshold above (1 splits any array of two
    // chunks or more); returns the previous value.
    mod.def("_set_min_elements_per_thread", [](size_t n) {
        return pgloss_py::min_per_thread().exchange(std::max<size_t>(1, n));
    });
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
    });

    mod.def("status_string", [](int s) { return std::string(pgloss_status_string(static_cast<pgloss_status>(s))); });
    mod.def("status_name", [](int s) { return std::string(pgloss_status_name(static_cast<pgloss_status>(s))); });

    py::class_<Material>(mod, "Material",
                         "An evaluation-ready material (pgloss_material): the physical parameters rounded to float\n"
                         "and what eval/pdf/sample precompute. Build one with pgloss.material_init(physical) or\n"
                         "Physical.material(); the fields are read-only.")
        .def_property_readonly("rho_d", [](const Material &M) { return rgb_tuple(M.m.rho_d); },
                               "diffuse reflectance (r, g, b), rounded to float")
        .def_property_readonly("rho_s", [](const Material &M) { return M.m.rho_s; }, "specular energy ρs")
        .def_property_readonly("alpha_x", [](const Material &M) { return M.m.alpha_x; }, "αx (at least ALPHA_MIN)")
        .def_property_readonly("alpha_y", [](const Material &M) { return M.m.alpha_y; }, "αy (at least ALPHA_MIN)")
        .def_property_readonly("normalization", [](const Material &M) { return static_cast<int>(M.m.normalization); },
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
        .def("__eq__", [](const Material &a, const Material &b) { return a.v == b.v && a.normalization == b.normalization; })
        .def("__hash__", [](const Material &M) {
            return py::hash(py::make_tuple(M.v[0], M.v[1], M.v[2], M.v[3], M.v[4], M.v[5], M.normalization));
        })
        .def("__repr__", [](const Material &M) {
            char buf[320];
            std::snprintf(buf, sizeof buf,
                          "Material(rho_d=(%.9g, %.9g, %.9g), rho_s=%.9g, alpha_x=%.9g, alpha_y=%.9g, normalization=%d, lobes=%u)",
                          M.m.rho_d[0], M.m.rho_d[1], M.m.rho_d[2], M.m.rho_s, M.m.alpha_x, M.m.alpha_y,
                          static_cast<int>(M.m.normalization), M.m.lobes);
            return std::string(buf);
        })
        .def(py::pickle(
            [](const Material &M) { return py::make_tuple(M.v, M.normalization); },
            [](const py::tuple &t) {
                if (t.size() != 2) throw std::runtime_error("pgloss.Material: bad pickle state");
                auto r = material_init(t[0].cast<std::array<double, 6>>(), t[1].cast<int>());
                if (r.second < 0) throw py::value_error(pgloss_status_string(static_cast<pgloss_status>(r.second)));
                return r.first;
            }));

    mod.def("material_init", [](const std::array<double, 6> &v, int norm) {
        auto r = material_init(v, norm);
        return py::make_tuple(r.first, r.second);
    });
    mod.def("specular_probability",
            [](const Material &M, unsigned lobes) { return pgloss_specular_probability(&M.m, lobes); });

    mod.def("eval_f32", &eval_uniform<float>, py::arg("m"), py::arg("lobes"), py::arg("wo"), py::arg("wi"),
            py::arg("want_f"), py::arg("want_pdf"), py::arg("f_out") = py::none(), py::arg("pdf_out") = py::none());
    mod.def("eval_f64", &eval_uniform<double>, py::arg("m"), py::arg("lobes"), py::arg("wo"), py::arg("wi"),
            py::arg("want_f"), py::arg("want_pdf"), py::arg("f_out") = py::none(), py::arg("pdf_out") = py::none());
    mod.def("material_columns", [](darr r, darr g, darr b, darr rs, darr ax, darr ay) {
        return material_columns({r, g, b, rs, ax, ay});
    });
    mod.def("eval_materials_f32", &eval_materials<float>);
    mod.def("eval_materials_f64", &eval_materials<double>);
    mod.def(
        "sample_f32",
        [](const Material &M, unsigned lobes, const farr &wo, const farr &u, py::object a, py::object b, py::object c,
           py::object d) { return sample_any<float>(&M, nullptr, 0, lobes, wo, u, a, b, c, d); },
        py::arg("m"), py::arg("lobes"), py::arg("wo"), py::arg("u"), py::arg("wi_out") = py::none(),
        py::arg("pdf_out") = py::none(), py::arg("weight_out") = py::none(), py::arg("lobe_out") = py::none());
    mod.def(
        "sample_f64",
        [](const Material &M, unsigned lobes, const f64arr &wo, const f64arr &u, py::object a, py::object b,
           py::object c, py::object d) { return sample_any<double>(&M, nullptr, 0, lobes, wo, u, a, b, c, d); },
        py::arg("m"), py::arg("lobes"), py::arg("wo"), py::arg("u"), py::arg("wi_out") = py::none(),
        py::arg("pdf_out") = py::none(), py::arg("weight_out") = py::none(), py::arg("lobe_out") = py::none());
    mod.def("sample_materials_f32", [](const farr &block, int norm, unsigned lobes, const farr &wo, const farr &u,
                                       py::object a, py::object b, py::object c, py::object d) {
        const Columns C = columns_of(block, rows_of(wo, "wo"));
        return sample_any<float>(nullptr, &C, norm, lobes, wo, u, a, b, c, d);
    });
    mod.def("sample_materials_f64", [](const farr &block, int norm, unsigned lobes, const f64arr &wo,
                                       const f64arr &u, py::object a, py::object b, py::object c, py::object d) {
        const Columns C = columns_of(block, rows_of(wo, "wo"));
        return sample_any<double>(nullptr, &C, norm, lobes, wo, u, a, b, c, d);
    });
    // One pgloss_eval_pdf call (the scalar reference: float directions, double inside, float
    // results), as the C tool calls it: python -m pgloss eval / demo print exactly its numbers.
    mod.def("eval_pdf_reference", [](const Material &M, unsigned lobes, std::array<float, 3> wo,
                                     std::array<float, 3> wi) {
        pgloss_rgb f{0, 0, 0};
        float pdf = 0;
        const int st = pgloss_eval_pdf(&M.m, pgloss_vec3{wo[0], wo[1], wo[2]}, pgloss_vec3{wi[0], wi[1], wi[2]}, lobes,
                                       &f, &pdf);
        return py::make_tuple(py::make_tuple(f.r, f.g, f.b), pdf, st);
    });
    mod.def("time_eval_batch", &time_eval_batch,
            "Seconds per repetition of pgloss_eval_batch on (3, n) float32 SoA buffers (benchmark helper).");

    // Perceptual and colour functions (double), element-wise: the batched core functions
    // (pgloss/perceptual_batch.h) where the core has one, else the scalar function per element.
    mod.def("lightness_from_luminance", [](darr Y) {
        return vmap<1, 1>({Y}, [](const double *x, double *y) { return (int)pgloss_lightness_from_luminance(x[0], &y[0]); });
    });
    mod.def("luminance_from_lightness", [](darr L) {
        return vmap<1, 1>({L}, [](const double *x, double *y) { return (int)pgloss_luminance_from_lightness(x[0], &y[0]); });
    });
    mod.def("contrast_gloss", [](darr rd, darr rs) {
        return vmap<2, 1>({rd, rs}, [](const double *x, double *y) { return (int)pgloss_contrast_gloss(x[0], x[1], &y[0]); });
    });
    mod.def("specular_from_contrast", [](darr rd, darr c) {
        return vmap<2, 1>({rd, c}, [](const double *x, double *y) {
            return (int)pgloss_specular_from_contrast(x[0], x[1], &y[0]);
        });
    });
    mod.def("gloss_from_physical", [](darr rd, darr rs, darr a) {
        return bmap<3, 3>(
            {rd, rs, a},
            [](size_t m, const double *const *x, double *const *y, signed char *st) {
                return (int)pgloss_gloss_from_physical_batch(m, x[0], x[1], x[2], y[0], y[1], y[2], st);
            },
            [](const double *x, double *y) { return (int)pgloss_gloss_from_physical(x[0], x[1], x[2], &y[0], &y[1], &y[2]); });
    });
    mod.def("physical_from_gloss", [](darr L, darr c, darr d) {
        return bmap<3, 3>(
            {L, c, d},
            [](size_t m, const double *const *x, double *const *y, signed char *st) {
                return (int)pgloss_physical_from_gloss_batch(m, x[0], x[1], x[2], y[0], y[1], y[2], st);
            },
            [](const double *x, double *y) { return (int)pgloss_physical_from_gloss(x[0], x[1], x[2], &y[0], &y[1], &y[2]); });
    });
    mod.def("gloss_distance", [](darr c1, darr d1, darr c2, darr d2) {
        return vmap<4, 1>({c1, d1, c2, d2}, [](const double *x, double *y) {
            return (int)pgloss_gloss_distance(x[0], x[1], x[2], x[3], &y[0]);
        });
    });
    mod.def("envelope_contrast", [](darr L) {
        return bmap<1, 1>(
            {L},
            [](size_t m, const double *const *x, double *const *y, signed char *st) {
                return (int)pgloss_envelope_contrast_batch(m, x[0], y[0], st);
            },
            [](const double *x, double *y) { return (int)pgloss_envelope_contrast(x[0], &y[0]); });
    });
    mod.def("match_gloss", [](darr rd, darr rs, darr L) {
        return bmap<3, 2>(
            {rd, rs, L},
            [](size_t m, const double *const *x, double *const *y, signed char *st) {
                return (int)pgloss_match_gloss_batch(m, x[0], x[1], x[2], y[0], y[1], st);
            },
            [](const double *x, double *y) { return (int)pgloss_match_gloss(x[0], x[1], x[2], &y[0], &y[1]); });
    });
    mod.def("isogloss_contour", [](double c0, double d0, double D, size_t n) {
        darr c(static_cast<py::ssize_t>(n)), d(static_cast<py::ssize_t>(n));
        double *cp = c.mutable_data(), *dp = d.mutable_data();
        int st;
        {
            py::gil_scoped_release nogil;
            st = pgloss_isogloss_contour(c0, d0, D, n, cp, dp);
        }
        return py::make_tuple(c, d, st);
    });
    // The colour functions take the working space (pgloss_color_space) as an int.
    mod.def("rgb_from_lab", [](darr L, darr a, darr b, int space) {
        return bmap<3, 3>(
            {L, a, b},
            [space](size_t m, const double *const *x, double *const *y, signed char *st) {
                return pgloss_py_rgb_from_lab_batch(m, x, space, y, st);
            },
            [space](const double *x, double *y) { return pgloss_py_rgb_from_lab(x, space, y); });
    });
    mod.def("lab_from_rgb", [](darr r, darr g, darr b, int space) {
        return bmap<3, 3>(
            {r, g, b},
            [space](size_t m, const double *const *x, double *const *y, signed char *st) {
                return pgloss_py_lab_from_rgb_batch(m, x, space, y, st);
            },
            [space](const double *x, double *y) { return pgloss_py_lab_from_rgb(x, space, y); });
    });
    mod.def("luminance", [](darr r, darr g, darr b, int space) {
        return vmap<3, 1>({r, g, b}, [space](const double *x, double *y) { return pgloss_py_luminance(x, space, &y[0]); });
    });
    // Structs: physical = (rho_d r, g, b, rho_s, alpha_x, alpha_y) columns and the
    // normalisation; perceptual = (L, a, b, c, d) columns.
    mod.def("check_physical", [](darr r, darr g, darr b, darr rs, darr ax, darr ay, int norm) {
        return bmap<6, 0>(
            {r, g, b, rs, ax, ay},
            [norm](size_t m, const double *const *x, double *const *, signed char *st) {
                return pgloss_py_check_physical_batch(m, x, norm, st);
            },
            [norm](const double *x, double *) { return pgloss_py_check_physical(x, norm); });
    });
    mod.def("check_perceptual", [](darr L, darr a, darr b, darr c, darr d, int space) {
        return bmap<5, 0>(
            {L, a, b, c, d},
            [space](size_t m, const double *const *x, double *const *, signed char *st) {
                return pgloss_py_check_perceptual_batch(m, x, space, st);
            },
            [space](const double *x, double *) { return pgloss_py_check_perceptual(x, space); });
    });
    // Five outputs: rho_d r, g, b, rho_s and alpha (= alpha_x = alpha_y, isotropic: the core
    // is given no alpha_y array, and Python uses the one for both), one n-double row fewer to
    // allocate and write.
    mod.def("physical_from_perceptual", [](darr L, darr a, darr b, darr c, darr d, int norm, int space) {
        return bmap<5, 5>(
            {L, a, b, c, d},
            [norm, space](size_t m, const double *const *x, double *const *y, signed char *st) {
                double *const out[6] = {y[0], y[1], y[2], y[3], y[4], nullptr};
                return pgloss_py_physical_from_perceptual_batch(m, x, norm, space, out, st);
            },
            [norm, space](const double *x, double *y) {
                int n = 0;
                double out[6];
                const int s = pgloss_py_physical_from_perceptual(x, norm, space, out, &n);
                std::copy(out, out + 5, y);
                return s;
            });
    });
    mod.def("perceptual_from_physical", [](darr r, darr g, darr b, darr rs, darr ax, darr ay, int norm, int space) {
        return bmap<6, 5>(
            {r, g, b, rs, ax, ay},
            [norm, space](size_t m, const double *const *x, double *const *y, signed char *st) {
                return pgloss_py_perceptual_from_physical_batch(m, x, norm, space, y, st);
            },
            [norm, space](const double *x, double *y) { return pgloss_py_perceptual_from_physical(x, norm, space, y); });
    });
}
