// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The BRDF batches (pgloss/batch.h): argument checks, then chunk by chunk the strided arrays
 * as contiguous columns (strided.h), the loops of the call's tier and scalar type on the
 * dispatched ISA (dispatch.c), the outputs written back, and the chunk's statuses: OK for
 * every element where the loops met no invalid one, else each element's reason. */
#include "batch_internal.h"
#include "internal.h"
#include "lobe_d.h"
#include "rows3.h"
#include "strided.h"

#define B PGLOSS__BLOCK

/* ---- arguments ----------------------------------------------------------------------------- */

static int in3_ok(pgloss_strided3 v) { return v.ptr[0] && v.ptr[1] && v.ptr[2]; }
static int out3_ok(pgloss_strided3_out v) { return v.ptr[0] && v.ptr[1] && v.ptr[2]; }
static int physical_ok(const pgloss_physical_array *p)
{
    return in3_ok(p->rho_d) && p->rho_s.ptr && p->alpha_x.ptr;
}
/* An output's stride: 0 (every element to one place) only for one element. */
static int stride_ok(ptrdiff_t stride, size_t n) { return stride != 0 || n == 1; }

/* ---- per-element statuses ------------------------------------------------------------------ */

/* pgloss_material_init's first failing check (NONFINITE, NEGATIVE, ALPHA), in double. */
static pgloss_status material_status(const double v[6])
{
    for (int k = 0; k < 6; ++k)
        if (!(fabs(v[k]) <= (double)FLT_MAX))
            return PGLOSS_ERR_NONFINITE;
    if (v[0] < 0.0 || v[1] < 0.0 || v[2] < 0.0 || v[3] < 0.0)
        return PGLOSS_ERR_NEGATIVE;
    if (!(v[4] > 0.0) || !(v[5] > 0.0))
        return PGLOSS_ERR_ALPHA;
    return PGLOSS_OK;
}

/* A direction's validity as the scalar functions decide it: not zero-length, finite. */
static int direction_ok(double x, double y, double z)
{
    if (!isfinite(x) || !isfinite(y) || !isfinite(z))
        return 0;
    return x != 0.0 || y != 0.0 || z != 0.0;
}

/* The inputs of a call, as the statuses read them (pointers to the arguments: copies of them
 * would cost every call a reload that misses store forwarding). */
typedef struct inputs {
    size_t size; /* bytes per value */
    const pgloss_physical_array *ms;
    const pgloss_strided3 *wo, *second; /* wi (eval) or u (sample) */
    int sample;
} inputs;

static double at1(pgloss_strided s, size_t j, size_t size)
{
    return pgloss__value_at(s.ptr, s.stride, j, size);
}
static double at3(const pgloss_strided3 *s, int c, size_t j, size_t size)
{
    return pgloss__value_at(s->ptr[c], s->stride, j, size);
}

static pgloss_status elem_status(const inputs *a, size_t j)
{
    const size_t sz = a->size;
    if (a->ms) {
        const pgloss_physical_array *p = a->ms;
        const double v[6] = {at3(&p->rho_d, 0, j, sz), at3(&p->rho_d, 1, j, sz),
                             at3(&p->rho_d, 2, j, sz), at1(p->rho_s, j, sz),
                             at1(p->alpha_x, j, sz),
                             at1(p->alpha_y.ptr ? p->alpha_y : p->alpha_x, j, sz)};
        const pgloss_status s = material_status(v);
        if (s != PGLOSS_OK)
            return s;
    }
    if (a->sample && (isnan(at3(a->second, 0, j, sz)) || isnan(at3(a->second, 1, j, sz)) ||
                      isnan(at3(a->second, 2, j, sz))))
        return PGLOSS_ERR_RANDOM;
    if (!direction_ok(at3(a->wo, 0, j, sz), at3(a->wo, 1, j, sz), at3(a->wo, 2, j, sz)))
        return PGLOSS_ERR_DIRECTION;
    if (!a->sample &&
        !direction_ok(at3(a->second, 0, j, sz), at3(a->second, 1, j, sz), at3(a->second, 2, j, sz)))
        return PGLOSS_ERR_DIRECTION;
    return PGLOSS_OK;
}

/* The statuses of elements [base, base + m), a chunk in which the loops met an invalid
 * element: written to status (if wanted); returns `first` or, while it is OK, the chunk's
 * first non-OK status. A chunk without an invalid element costs a memset (chunk_done). */
static pgloss_status chunk_statuses(const inputs *a, size_t base, size_t m, signed char *status,
                                    pgloss_status first)
{
    for (size_t j = base; j < base + m; ++j) {
        if (!status && first != PGLOSS_OK)
            break;
        const pgloss_status st = elem_status(a, j);
        if (status)
            status[j] = (signed char)st;
        if (first == PGLOSS_OK)
            first = st;
    }
    return first;
}

static pgloss_status chunk_done(const inputs *a, size_t base, size_t m, size_t bad,
                                signed char *status, pgloss_status first)
{
    if (bad)
        return chunk_statuses(a, base, m, status, first);
    if (status)
        memset(status + base, PGLOSS_OK, m);
    return first;
}

/* ---- columns of a chunk ------------------------------------------------------------------- */

/* A chunk's input and output columns: in place where contiguous, else in these buffers. */
typedef struct chunk {
    double in[12][B], out[7][B];
    const void *o[3], *x[3], *mat[6]; /* wo; wi or u; ρd r g b, ρs, αx, αy */
    void *y[7];                       /* f or wi (3), pdf, weight (3) */
} chunk;

/* (n, 3) rows: x y z of an element adjacent, one element every 3 size bytes. */
static int rows3(const void *const *p, ptrdiff_t stride, size_t size)
{
    const char *x = (const char *)p[0];
    return stride == 3 * (ptrdiff_t)size && (const char *)p[1] == x + size &&
           (const char *)p[2] == x + 2 * size;
}

/* Asks for the next chunk's rows [from, min(from + B, n)) (to write: rw 1) while the loops
 * compute this one: the copies of rows otherwise wait for memory with nothing to overlap,
 * where the loops on columns in place overlap their loads with the lobe's arithmetic. */
static void prefetch_rows(const void *const *ptr, ptrdiff_t stride, size_t size, size_t from,
                          size_t n, int rw)
{
#if defined(__GNUC__) || defined(__clang__)
    if (from >= n || !rows3(ptr, stride, size))
        return;
    const char *p = (const char *)ptr[0] + 3 * size * from;
    const size_t bytes = 3 * size * (n - from < B ? n - from : B);
    for (size_t k = 0; k < bytes; k += 64) {
        if (rw)
            __builtin_prefetch(p + k, 1);
        else
            __builtin_prefetch(p + k, 0);
    }
#else
    (void)ptr, (void)stride, (void)size, (void)from, (void)n, (void)rw;
#endif
}

/* Whether every value of a strided array is where the loops take it (a contiguous, aligned
 * column); the chunk step of a call all of whose arrays are: one chunk, no per-chunk cost. */
static int in_place3(const void *const *p, ptrdiff_t stride, size_t size)
{
    return pgloss__in_place(p[0], stride, size) && pgloss__in_place(p[1], stride, size) &&
           pgloss__in_place(p[2], stride, size);
}
static int materials_in_place(const pgloss_physical_array *p, size_t size)
{
    return !p || (in_place3(p->rho_d.ptr, p->rho_d.stride, size) &&
                  pgloss__in_place(p->rho_s.ptr, p->rho_s.stride, size) &&
                  pgloss__in_place(p->alpha_x.ptr, p->alpha_x.stride, size) &&
                  (!p->alpha_y.ptr || pgloss__in_place(p->alpha_y.ptr, p->alpha_y.stride, size)));
}

/* The strided arrays pass by pointer: by value, the copies' 16-byte reloads of 8-byte stores
 * miss store forwarding, which costs a small call more than the copying itself. */
static void gather3(const pgloss__loops *L, const pgloss_strided3 *sp, size_t size, size_t base,
                    size_t m, double (*buf)[B], const void **col)
{
    const pgloss_strided3 s = *sp;
    if (rows3(s.ptr, s.stride, size)) {
        if (size == 4)
            L->rows_in((const char *)s.ptr[0] + 12 * base, m, (float *)buf[0], (float *)buf[1],
                       (float *)buf[2]);
        else
            pgloss__rows3d_to_columns((const char *)s.ptr[0] + 24 * base, m, buf[0], buf[1], buf[2]);
        for (int c = 0; c < 3; ++c)
            col[c] = buf[c];
        return;
    }
    for (int c = 0; c < 3; ++c)
        col[c] = pgloss__gather(s.ptr[c], s.stride, size, base, m, buf[c]);
}

/* The input columns of a call whose arrays are all in place: the arrays themselves. */
static void columns_in_place(const pgloss_strided3 *a, const pgloss_strided3 *b,
                             const pgloss_physical_array *ms, chunk *c)
{
    for (int k = 0; k < 3; ++k) {
        c->o[k] = a->ptr[k];
        c->x[k] = b->ptr[k];
    }
    if (ms) {
        for (int k = 0; k < 3; ++k)
            c->mat[k] = ms->rho_d.ptr[k];
        c->mat[3] = ms->rho_s.ptr;
        c->mat[4] = ms->alpha_x.ptr;
        c->mat[5] = ms->alpha_y.ptr ? ms->alpha_y.ptr : ms->alpha_x.ptr;
    }
}

static void gather_materials(const pgloss__loops *L, const pgloss_physical_array *p, size_t size,
                             size_t base, size_t m, chunk *c)
{
    gather3(L, &p->rho_d, size, base, m, &c->in[6], c->mat);
    c->mat[3] = pgloss__gather(p->rho_s.ptr, p->rho_s.stride, size, base, m, c->in[9]);
    c->mat[4] = pgloss__gather(p->alpha_x.ptr, p->alpha_x.stride, size, base, m, c->in[10]);
    c->mat[5] = p->alpha_y.ptr
                    ? pgloss__gather(p->alpha_y.ptr, p->alpha_y.stride, size, base, m, c->in[11])
                    : c->mat[4];
}

/* A chunk's inputs (directions, and u or the materials) as columns: a call whose arrays are
 * all in place (whole) takes them as they are; any other gathers them and asks for the next
 * chunk's rows. */
static void chunk_inputs(const pgloss__loops *L, int whole, const pgloss_strided3 *a,
                         const pgloss_strided3 *b, const pgloss_physical_array *ms, size_t size,
                         size_t base, size_t m, size_t n, chunk *c)
{
    if (whole) {
        columns_in_place(a, b, ms, c);
        return;
    }
    gather3(L, a, size, base, m, &c->in[0], c->o);
    gather3(L, b, size, base, m, &c->in[3], c->x);
    prefetch_rows(a->ptr, a->stride, size, base + m, n, 0);
    prefetch_rows(b->ptr, b->stride, size, base + m, n, 0);
    if (ms)
        gather_materials(L, ms, size, base, m, c);
}

static void out3(const pgloss_strided3_out *sp, size_t size, size_t base, double (*buf)[B],
                 void **col)
{
    const pgloss_strided3_out s = *sp;
    for (int c = 0; c < 3; ++c)
        col[c] = pgloss__out(s.ptr[c], s.stride, size, base, buf[c]);
}

static void scatter3(const pgloss__loops *L, const pgloss_strided3_out *sp, size_t size,
                     size_t base, size_t m, void *const *col)
{
    const pgloss_strided3_out s = *sp;
    if (rows3((const void *const *)s.ptr, s.stride, size)) {
        if (size == 4)
            L->rows_out(col[0], col[1], col[2], m, (char *)s.ptr[0] + 12 * base);
        else
            pgloss__columns_to_rows3d(col[0], col[1], col[2], m, (char *)s.ptr[0] + 24 * base);
        return;
    }
    for (int c = 0; c < 3; ++c)
        pgloss__scatter(s.ptr[c], s.stride, size, base, m, col[c]);
}

static pgloss__materials_f materials_f(const chunk *c, int norm)
{
    const pgloss__materials_f r = {c->mat[0], c->mat[1], c->mat[2], c->mat[3],
                                   c->mat[4], c->mat[5], (pgloss_normalization)norm};
    return r;
}

static pgloss__materials_d materials_d(const chunk *c, int norm)
{
    const pgloss__materials_d r = {c->mat[0], c->mat[1], c->mat[2], c->mat[3],
                                   c->mat[4], c->mat[5], (pgloss_normalization)norm};
    return r;
}

/* Element j's pgloss_material of a float chunk (black where invalid: pgloss_material_init,
 * whose status it returns). */
static pgloss_status material_at(const chunk *c, size_t j, int norm, pgloss_material *out)
{
    pgloss_physical p;
    for (int k = 0; k < 3; ++k)
        p.rho_d[k] = ((const float *)c->mat[k])[j];
    p.rho_s = ((const float *)c->mat[3])[j];
    p.alpha_x = ((const float *)c->mat[4])[j];
    p.alpha_y = ((const float *)c->mat[5])[j];
    p.normalization = (pgloss_normalization)norm;
    return pgloss_material_init(out, &p);
}

/* Whether a material's float f or pdf can exceed FLT_MAX anywhere (then the loops clamp them):
 * bounds of the lobe's steps with cosines raised to COS_MIN, e <= 1, |ô + î| <= 2 (so
 * hhs <= 4/hzc², hzc >= 2 COS_MIN), and a margin of 4 for rounding and the FAST estimates. */
static int may_exceed_flt_max(const pgloss_material *m)
{
    const double c = 2.0 * PGLOSS_COS_MIN; /* the least hzc */
    double n = 1.0 / PGLOSS_COS_MIN;       /* WARD: 1/sqrt(ci' co') */
    if (m->normalization == PGLOSS_NORM_WARD_DUR)
        n = n * n;
    else if (m->normalization == PGLOSS_NORM_BOUNDED)
        n = 4.0 / (c * c * c * c); /* hhs/hzc² */
    const double fd = ((double)m->rho_d[0] + m->rho_d[1] + m->rho_d[2]) / 3.14159265358979323846;
    const double f = fd + (double)m->spec_scale * n;
    const double pdf = (double)m->pdf_diffuse + 0.31830988618379067154 +
                       2.0 * (double)m->pdf_scale * 4.0 / (c * c * c);
    return !(f <= 0.25 * FLT_MAX && pdf <= 0.25 * FLT_MAX);
}

/* A call's set-up, once: the lobes the loops are specialised on and the normalisation, and
 * for one material in float64 its constants formed again in double (its parameters widened
 * exactly). */
typedef struct setup {
    pgloss__call_f c;
    pgloss__consts_d kd;
} setup;

static void set_up(const pgloss_material *m, const pgloss_physical_array *ms, unsigned lobes,
                   int f64, setup *s)
{
    s->c.m = m;
    s->c.ms = NULL;
    s->c.active = lobes & PGLOSS_LOBE_ALL;
    if (!m) {
        s->c.norm = (int)ms->normalization;
        s->c.clamp = 1;
        return;
    }
    s->c.norm = (int)m->normalization;
    s->c.clamp = may_exceed_flt_max(m);
    if (f64) {
        s->kd = pgloss__consts_d_of(m->rho_d[0], m->rho_d[1], m->rho_d[2], m->rho_s, m->alpha_x,
                                    m->alpha_y, s->c.norm, s->c.active);
        s->c.active = s->kd.active;
    } else {
        s->c.active &= m->lobes;
    }
}

/* ---- eval / pdf ------------------------------------------------------------------------------ */

/* The REFERENCE tier on float32 columns: the scalar function element by element. */
static size_t eval_reference(const pgloss_material *m, const chunk *c, int norm, unsigned lobes,
                             size_t count, int want_f, int want_p)
{
    size_t bad = 0;
    for (size_t j = 0; j < count; ++j) {
        pgloss_material mj;
        if (!m)
            bad += material_at(c, j, norm, &mj) != PGLOSS_OK;
        const float *const *o = (const float *const *)c->o, *const *i = (const float *const *)c->x;
        const pgloss_vec3 vo = {o[0][j], o[1][j], o[2][j]}, vi = {i[0][j], i[1][j], i[2][j]};
        pgloss_rgb v;
        float p;
        bad += pgloss_eval_pdf(m ? m : &mj, vo, vi, lobes, want_f ? &v : NULL,
                               want_p ? &p : NULL) != PGLOSS_OK;
        if (want_f) {
            ((float *)c->y[0])[j] = v.r;
            ((float *)c->y[1])[j] = v.g;
            ((float *)c->y[2])[j] = v.b;
        }
        if (want_p)
            ((float *)c->y[3])[j] = p;
    }
    return bad; /* nonzero where an element is invalid (chunk_done finds which) */
}

pgloss_status pgloss_eval_pdf_batch(const pgloss_batch_options *options,
                                    const pgloss_material *m, const pgloss_physical_array *ms,
                                    unsigned lobes, size_t n, pgloss_strided3 wo,
                                    pgloss_strided3 wi, pgloss_strided3_out f,
                                    pgloss_strided_out pdf, signed char *status)
{
    pgloss_batch_options o;
    const pgloss__loops *L = pgloss__dispatch(options, &o);
    if (!L)
        return PGLOSS_ERR_ARGUMENT;
    if (n == 0)
        return PGLOSS_OK;
    const int want_f = f.ptr[0] != NULL, want_p = pdf.ptr != NULL;
    if ((!m && !ms) || !in3_ok(wo) || !in3_ok(wi) || (want_f && !out3_ok(f)) ||
        !(want_f || want_p) || (ms && !physical_ok(ms)))
        return PGLOSS_ERR_NULL;
    if ((m && ms) || (want_f && !stride_ok(f.stride, n)) || (want_p && !stride_ok(pdf.stride, n)))
        return PGLOSS_ERR_ARGUMENT;
    if (ms && !pgloss__valid_normalization(ms->normalization))
        return PGLOSS_ERR_NORMALIZATION;
    const int f64 = o.scalar == PGLOSS_FLOAT64;
    const size_t size = f64 ? 8 : 4;
    setup s;
    set_up(m, ms, lobes, f64, &s);
    const inputs a = {size, ms, &wo, &wi, 0};
    const int whole = in_place3(wo.ptr, wo.stride, size) && in_place3(wi.ptr, wi.stride, size) &&
                      (!want_f || in_place3((const void *const *)f.ptr, f.stride, size)) &&
                      (!want_p || pgloss__in_place(pdf.ptr, pdf.stride, size)) &&
                      materials_in_place(ms, size);
    const size_t step = whole ? n : B;
    pgloss_status first = PGLOSS_OK;
    chunk c;
    for (size_t base = 0; base < n; base += step) {
        const size_t cnt = n - base < step ? n - base : step;
        size_t bad;
        chunk_inputs(L, whole, &wo, &wi, ms, size, base, cnt, n, &c);
        if (want_f && !whole)
            prefetch_rows((const void *const *)f.ptr, f.stride, size, base + cnt, n, 1);
        c.y[0] = c.y[1] = c.y[2] = c.y[3] = NULL;
        if (want_f)
            out3(&f, size, base, &c.out[0], c.y);
        if (want_p)
            c.y[3] = pgloss__out(pdf.ptr, pdf.stride, size, base, c.out[3]);
        if (f64) {
            const pgloss__vec3_d vo = {c.o[0], c.o[1], c.o[2]}, vi = {c.x[0], c.x[1], c.x[2]};
            const pgloss__rgb_out_d vf = {c.y[0], c.y[1], c.y[2]};
            const pgloss__materials_d md = materials_d(&c, s.c.norm);
            bad = L->eval_pdf_d(m ? &s.kd : NULL, m ? NULL : &md, s.c.active, s.c.norm, cnt, vo,
                                vi, vf, c.y[3]);
        } else if (o.precision == PGLOSS_PRECISION_REFERENCE) {
            bad = eval_reference(m, &c, s.c.norm, lobes, cnt, want_f, want_p);
        } else {
            const pgloss__vec3_f vo = {c.o[0], c.o[1], c.o[2]}, vi = {c.x[0], c.x[1], c.x[2]};
            const pgloss__rgb_out_f vf = {c.y[0], c.y[1], c.y[2]};
            const pgloss__materials_f mf = materials_f(&c, s.c.norm);
            s.c.ms = m ? NULL : &mf;
            bad = L->eval_pdf[o.precision == PGLOSS_PRECISION_FAST](&s.c, cnt, vo, vi, vf, c.y[3]);
        }
        if (want_f && !whole)
            scatter3(L, &f, size, base, cnt, c.y);
        if (want_p)
            pgloss__scatter(pdf.ptr, pdf.stride, size, base, cnt, c.y[3]);
        first = chunk_done(&a, base, cnt, bad, status, first);
    }
    return first;
}

/* ---- sampling -------------------------------------------------------------------------------- */

/* The REFERENCE tier on float32 columns: pgloss_sample element by element (an invalid
 * material is black: no lobe, wi = (0, 0, 1), 0 outputs); nonzero where one is invalid. */
static size_t sample_reference(const pgloss_material *m, const chunk *c, int norm, unsigned lobes,
                             size_t count, unsigned char *lobe)
{
    const float *const *o = (const float *const *)c->o, *const *u = (const float *const *)c->x;
    float *const *y = (float *const *)c->y;
    size_t bad = 0;
    for (size_t j = 0; j < count; ++j) {
        pgloss_material mj;
        if (!m)
            bad += material_at(c, j, norm, &mj) != PGLOSS_OK;
        const pgloss_vec3 vo = {o[0][j], o[1][j], o[2][j]};
        const float uj[3] = {u[0][j], u[1][j], u[2][j]};
        pgloss_sample_record r;
        bad += pgloss_sample(m ? m : &mj, vo, uj, lobes, &r) != PGLOSS_OK;
        y[0][j] = r.wi.x;
        y[1][j] = r.wi.y;
        y[2][j] = r.wi.z;
        y[3][j] = r.pdf;
        y[4][j] = r.weight.r;
        y[5][j] = r.weight.g;
        y[6][j] = r.weight.b;
        if (lobe)
            lobe[j] = (unsigned char)r.lobe;
    }
    return bad;
}

pgloss_status pgloss_sample_batch(const pgloss_batch_options *options, const pgloss_material *m,
                                  const pgloss_physical_array *ms, unsigned lobes, size_t n,
                                  pgloss_strided3 wo, pgloss_strided3 u, pgloss_strided3_out wi,
                                  pgloss_strided_out pdf, pgloss_strided3_out weight,
                                  unsigned char *lobe, signed char *status)
{
    pgloss_batch_options o;
    const pgloss__loops *L = pgloss__dispatch(options, &o);
    if (!L)
        return PGLOSS_ERR_ARGUMENT;
    if (n == 0)
        return PGLOSS_OK;
    if ((!m && !ms) || !in3_ok(wo) || !in3_ok(u) || !out3_ok(wi) || !pdf.ptr ||
        !out3_ok(weight) || (ms && !physical_ok(ms)))
        return PGLOSS_ERR_NULL;
    if ((m && ms) || !stride_ok(wi.stride, n) || !stride_ok(pdf.stride, n) ||
        !stride_ok(weight.stride, n))
        return PGLOSS_ERR_ARGUMENT;
    if (ms && !pgloss__valid_normalization(ms->normalization))
        return PGLOSS_ERR_NORMALIZATION;
    const int f64 = o.scalar == PGLOSS_FLOAT64;
    const size_t size = f64 ? 8 : 4;
    setup s;
    set_up(m, ms, lobes, f64, &s);
    const inputs a = {size, ms, &wo, &u, 1};
    const int whole = in_place3(wo.ptr, wo.stride, size) && in_place3(u.ptr, u.stride, size) &&
                      in_place3((const void *const *)wi.ptr, wi.stride, size) &&
                      pgloss__in_place(pdf.ptr, pdf.stride, size) &&
                      in_place3((const void *const *)weight.ptr, weight.stride, size) &&
                      materials_in_place(ms, size);
    const size_t step = whole ? n : B;
    pgloss_status first = PGLOSS_OK;
    chunk c;
    for (size_t base = 0; base < n; base += step) {
        const size_t cnt = n - base < step ? n - base : step;
        size_t bad;
        unsigned char *lb = lobe ? lobe + base : NULL;
        chunk_inputs(L, whole, &wo, &u, ms, size, base, cnt, n, &c);
        if (!whole) {
            prefetch_rows((const void *const *)wi.ptr, wi.stride, size, base + cnt, n, 1);
            prefetch_rows((const void *const *)weight.ptr, weight.stride, size, base + cnt, n, 1);
        }
        out3(&wi, size, base, &c.out[0], c.y);
        c.y[3] = pgloss__out(pdf.ptr, pdf.stride, size, base, c.out[3]);
        out3(&weight, size, base, &c.out[4], c.y + 4);
        if (f64) {
            const pgloss__vec3_d vo = {c.o[0], c.o[1], c.o[2]};
            const pgloss__vec3_out_d vw = {c.y[0], c.y[1], c.y[2]};
            const pgloss__rgb_out_d vg = {c.y[4], c.y[5], c.y[6]};
            const pgloss__materials_d md = materials_d(&c, s.c.norm);
            bad = L->sample_d(m ? &s.kd : NULL, m ? NULL : &md, s.c.active, s.c.norm, cnt, vo,
                              c.x[0], c.x[1], c.x[2], vw, c.y[3], vg, lb);
        } else if (o.precision == PGLOSS_PRECISION_REFERENCE) {
            bad = sample_reference(m, &c, s.c.norm, lobes, cnt, lb);
        } else {
            const pgloss__vec3_f vo = {c.o[0], c.o[1], c.o[2]};
            const pgloss__vec3_out_f vw = {c.y[0], c.y[1], c.y[2]};
            const pgloss__rgb_out_f vg = {c.y[4], c.y[5], c.y[6]};
            const pgloss__materials_f mf = materials_f(&c, s.c.norm);
            s.c.ms = m ? NULL : &mf;
            bad = L->sample[o.precision == PGLOSS_PRECISION_FAST](&s.c, cnt, vo, c.x[0], c.x[1],
                                                                   c.x[2], vw, c.y[3], vg, lb);
        }
        if (!whole) {
            scatter3(L, &wi, size, base, cnt, c.y);
            scatter3(L, &weight, size, base, cnt, c.y + 4);
        }
        pgloss__scatter(pdf.ptr, pdf.stride, size, base, cnt, c.y[3]);
        first = chunk_done(&a, base, cnt, bad, status, first);
    }
    return first;
}
