// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Batched BRDF entry points with per-element materials and the double path
 * (pgloss/batch_materials.h): argument checks, ISA dispatch (once per call) to the loops of
 * batch_isa.c (float, per element) and batch_d_isa.c (double), and the per-element statuses,
 * found in a pass of their own only when asked for or when the loops met an invalid element. */
#include "batch_internal.h"
#include "internal.h"
#include "pgloss/batch_materials.h"
#include "lobe_d.h"

/* ---- dispatch ---------------------------------------------------------------------------- */

static int valid_norm(pgloss_normalization n)
{
    return n == PGLOSS_NORM_WARD || n == PGLOSS_NORM_WARD_DUR || n == PGLOSS_NORM_BOUNDED;
}

/* The checks every entry point makes first, in the order of the error contract (brdf.h,
 * batch.h): the options (ARGUMENT), nothing to do (OK), the pointers (NULL), the
 * normalisation *norm (NORMALIZATION; read only once the pointers are known good). Returns 1
 * to go on, with the ISA and whether the tier is REFERENCE, or 0 to return *st. */
static int prepare(const pgloss_batch_options *options, size_t n, int pointers_ok,
                   const pgloss_normalization *norm, pgloss_isa *isa, int *reference,
                   pgloss_status *st)
{
    pgloss_precision prec;
    if (!pgloss__batch_options_resolve(options, &prec, isa))
        *st = PGLOSS_ERR_ARGUMENT;
    else if (n == 0)
        *st = PGLOSS_OK;
    else if (!pointers_ok)
        *st = PGLOSS_ERR_NULL;
    else if (!valid_norm(*norm))
        *st = PGLOSS_ERR_NORMALIZATION;
    else {
        *reference = prec == PGLOSS_PRECISION_REFERENCE;
        return 1;
    }
    return 0;
}

#define PICK(var, name, isa)                                                                       \
    do {                                                                                           \
        switch (isa) {                                                                             \
        PICK_AVX512(var, name)                                                                     \
        PICK_AVX2(var, name)                                                                       \
        default: var = name##_baseline; break;                                                     \
        }                                                                                          \
    } while (0)
#if defined(PGLOSS_HAVE_AVX512)
#define PICK_AVX512(var, name) case PGLOSS_ISA_AVX512: var = name##_avx512; break;
#else
#define PICK_AVX512(var, name)
#endif
#if defined(PGLOSS_HAVE_AVX2)
#define PICK_AVX2(var, name) case PGLOSS_ISA_AVX2: var = name##_avx2; break;
#else
#define PICK_AVX2(var, name)
#endif

/* ---- per-element statuses ---------------------------------------------------------------- */

/* pgloss_material_init's first failing check (NONFINITE, NEGATIVE, ALPHA), in double. */
static pgloss_status material_status(double r, double g, double b, double s, double ax, double ay)
{
    const double v[6] = {r, g, b, s, ax, ay};
    for (int k = 0; k < 6; ++k)
        if (!(fabs(v[k]) <= (double)FLT_MAX))
            return PGLOSS_ERR_NONFINITE;
    if (r < 0.0 || g < 0.0 || b < 0.0 || s < 0.0)
        return PGLOSS_ERR_NEGATIVE;
    if (!(ax > 0.0) || !(ay > 0.0))
        return PGLOSS_ERR_ALPHA;
    return PGLOSS_OK;
}

/* A direction's validity as the scalar functions decide it: zero-length or non-finite. */
static int direction_ok(double x, double y, double z)
{
    if (!isfinite(x) || !isfinite(y) || !isfinite(z))
        return 0;
    return x != 0.0 || y != 0.0 || z != 0.0;
}

/* Inputs of the per-element status of element j, in any precision. */
typedef struct elem {
    double mat[6];  /* ρd r, g, b, ρs, αx, αy (has_mat) */
    int has_mat;
    double o[3], i[3];
    int has_i;      /* eval: wi; sample: the random numbers instead */
    double u[3];
} elem;

static pgloss_status elem_status(const elem *e)
{
    if (e->has_mat) {
        const pgloss_status m = material_status(e->mat[0], e->mat[1], e->mat[2], e->mat[3],
                                                e->mat[4], e->mat[5]);
        if (m != PGLOSS_OK)
            return m;
    }
    if (!e->has_i && (isnan(e->u[0]) || isnan(e->u[1]) || isnan(e->u[2])))
        return PGLOSS_ERR_RANDOM;
    if (!direction_ok(e->o[0], e->o[1], e->o[2]))
        return PGLOSS_ERR_DIRECTION;
    if (e->has_i && !direction_ok(e->i[0], e->i[1], e->i[2]))
        return PGLOSS_ERR_DIRECTION;
    return PGLOSS_OK;
}

/* Fills status (if wanted) and returns the first non-OK status. `get` reads element j. */
typedef void (*elem_fn)(const void *ctx, size_t j, elem *e);

static pgloss_status statuses(size_t n, elem_fn get, const void *ctx, signed char *status)
{
    pgloss_status first = PGLOSS_OK;
    for (size_t j = 0; j < n; ++j) {
        elem e;
        memset(&e, 0, sizeof e); /* the fields get() leaves unset are never read */
        get(ctx, j, &e);
        const pgloss_status st = elem_status(&e);
        if (status)
            status[j] = (signed char)st;
        else if (st != PGLOSS_OK)
            return st;
        if (first == PGLOSS_OK)
            first = st;
    }
    return first;
}

/* The argument sets, for elem_fn. */
typedef struct ctx_f {
    const pgloss_material_array *m;
    const float *ox, *oy, *oz, *ix, *iy, *iz, *u0, *u1, *u2;
} ctx_f;

typedef struct ctx_d {
    const pgloss_physical_array *m;
    const double *ox, *oy, *oz, *ix, *iy, *iz, *u0, *u1, *u2;
} ctx_d;

#define FILL_ELEM(c, j, e)                                                                         \
    do {                                                                                           \
        (e)->has_mat = (c)->m != NULL;                                                             \
        if ((c)->m) {                                                                              \
            (e)->mat[0] = (c)->m->rho_d_r[j];                                                      \
            (e)->mat[1] = (c)->m->rho_d_g[j];                                                      \
            (e)->mat[2] = (c)->m->rho_d_b[j];                                                      \
            (e)->mat[3] = (c)->m->rho_s[j];                                                        \
            (e)->mat[4] = (c)->m->alpha_x[j];                                                      \
            (e)->mat[5] = (c)->m->alpha_y ? (c)->m->alpha_y[j] : (c)->m->alpha_x[j];               \
        }                                                                                          \
        (e)->o[0] = (c)->ox[j];                                                                    \
        (e)->o[1] = (c)->oy[j];                                                                    \
        (e)->o[2] = (c)->oz[j];                                                                    \
        (e)->has_i = (c)->ix != NULL;                                                              \
        if ((c)->ix) {                                                                             \
            (e)->i[0] = (c)->ix[j];                                                                \
            (e)->i[1] = (c)->iy[j];                                                                \
            (e)->i[2] = (c)->iz[j];                                                                \
        } else {                                                                                   \
            (e)->u[0] = (c)->u0[j];                                                                \
            (e)->u[1] = (c)->u1[j];                                                                \
            (e)->u[2] = (c)->u2[j];                                                                \
        }                                                                                          \
    } while (0)

static void get_f(const void *ctx, size_t j, elem *e)
{
    const ctx_f *c = (const ctx_f *)ctx;
    FILL_ELEM(c, j, e);
}

static void get_d(const void *ctx, size_t j, elem *e)
{
    const ctx_d *c = (const ctx_d *)ctx;
    FILL_ELEM(c, j, e);
}

static int material_array_ok(const pgloss_material_array *m)
{
    return m && m->rho_d_r && m->rho_d_g && m->rho_d_b && m->rho_s && m->alpha_x;
}

static int physical_array_ok(const pgloss_physical_array *m)
{
    return m && m->rho_d_r && m->rho_d_g && m->rho_d_b && m->rho_s && m->alpha_x;
}

static int vec_ok(pgloss_vec3_array v) { return v.x && v.y && v.z; }
static int vec_ok_d(pgloss_vec3_array_d v) { return v.x && v.y && v.z; }

/* Element j's pgloss_material (pgloss_material_init of the arrays' values). */
static void material_at(const pgloss_material_array *m, size_t j, pgloss_material *out)
{
    pgloss_physical p;
    p.rho_d[0] = m->rho_d_r[j];
    p.rho_d[1] = m->rho_d_g[j];
    p.rho_d[2] = m->rho_d_b[j];
    p.rho_s = m->rho_s[j];
    p.alpha_x = m->alpha_x[j];
    p.alpha_y = m->alpha_y[j];
    p.normalization = m->normalization;
    (void)pgloss_material_init(out, &p);
}

/* ---- float, one material per element ----------------------------------------------------- */

pgloss_status pgloss_eval_pdf_batch_materials_ex(const pgloss_batch_options *options,
                                                 const pgloss_material_array *m, unsigned lobes,
                                                 size_t n, pgloss_vec3_array wo,
                                                 pgloss_vec3_array wi, pgloss_rgb_out f,
                                                 float *pdf, signed char *status)
{
    pgloss_isa isa;
    int reference;
    pgloss_status st;
    const int pointers_ok = !(f.r && (!f.g || !f.b)) && material_array_ok(m) && vec_ok(wo) &&
                            vec_ok(wi) && (f.r || pdf);
    if (!prepare(options, n, pointers_ok, m ? &m->normalization : NULL, &isa, &reference, &st))
        return st;
    pgloss_material_array ma = *m;
    if (!ma.alpha_y)
        ma.alpha_y = ma.alpha_x;
    size_t bad = 0;
    if (reference) {
        for (size_t j = 0; j < n; ++j) {
            pgloss_material mj;
            material_at(&ma, j, &mj);
            const pgloss_vec3 o = {wo.x[j], wo.y[j], wo.z[j]}, i = {wi.x[j], wi.y[j], wi.z[j]};
            pgloss_rgb v;
            float p;
            (void)pgloss_eval_pdf(&mj, o, i, lobes, f.r ? &v : NULL, pdf ? &p : NULL);
            if (f.r) {
                f.r[j] = v.r;
                f.g[j] = v.g;
                f.b[j] = v.b;
            }
            if (pdf)
                pdf[j] = p;
        }
        /* an invalid material is black (0 outputs), and its status comes from the pass below */
        bad = 1;
    } else {
        if (!f.r)
            f.g = f.b = NULL;
        size_t (*fn)(const pgloss_material_array *, unsigned, size_t, pgloss_vec3_array,
                     pgloss_vec3_array, pgloss_rgb_out, float *);
        PICK(fn, pgloss__eval_pdf_materials, isa);
        /* the FLOAT kernels for both FLOAT and FAST (batch_materials.h) */
        bad = fn(&ma, lobes & PGLOSS_LOBE_ALL, n, wo, wi, f, pdf);
    }
    if (!bad && !status)
        return PGLOSS_OK;
    const ctx_f c = {&ma, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, NULL, NULL, NULL};
    return statuses(n, get_f, &c, status);
}

pgloss_status pgloss_sample_batch_materials_ex(const pgloss_batch_options *options,
                                               const pgloss_material_array *m, unsigned lobes,
                                               size_t n, pgloss_vec3_array wo, const float *u0,
                                               const float *u1, const float *u2,
                                               pgloss_vec3_out wi, float *pdf,
                                               pgloss_rgb_out weight, unsigned char *lobe,
                                               signed char *status)
{
    pgloss_isa isa;
    int reference;
    pgloss_status st;
    const int pointers_ok = material_array_ok(m) && vec_ok(wo) && u0 && u1 && u2 && wi.x &&
                            wi.y && wi.z && pdf && weight.r && weight.g && weight.b;
    if (!prepare(options, n, pointers_ok, m ? &m->normalization : NULL, &isa, &reference, &st))
        return st;
    pgloss_material_array ma = *m;
    if (!ma.alpha_y)
        ma.alpha_y = ma.alpha_x;
    if (reference) {
        for (size_t j = 0; j < n; ++j) {
            pgloss_material mj;
            material_at(&ma, j, &mj);
            const pgloss_vec3 o = {wo.x[j], wo.y[j], wo.z[j]};
            const float u[3] = {u0[j], u1[j], u2[j]};
            pgloss_sample_record s;
            /* an invalid material is black: no lobe, wi = (0, 0, 1), 0 outputs */
            (void)pgloss_sample(&mj, o, u, lobes, &s);
            pgloss__put_sample_record(&s, j, wi, pdf, weight, lobe);
        }
    } else {
        void (*fn)(const pgloss_material_array *, unsigned, size_t, pgloss_vec3_array,
                   const float *, const float *, const float *, pgloss_vec3_out, float *,
                   pgloss_rgb_out, unsigned char *);
        PICK(fn, pgloss__sample_materials, isa);
        fn(&ma, lobes & PGLOSS_LOBE_ALL, n, wo, u0, u1, u2, wi, pdf, weight, lobe);
    }
    const ctx_f c = {&ma, wo.x, wo.y, wo.z, NULL, NULL, NULL, u0, u1, u2};
    return statuses(n, get_f, &c, status);
}

/* ---- double -------------------------------------------------------------------------------- */

/* One material (m: its constants in double, *k) or one per element (pa: the arrays, alpha_y
 * defaulted, *a), and the normalisation. */
static void setup_d(const pgloss_material *m, const pgloss_physical_array *pa, unsigned lobes,
                    pgloss__consts_d *k, pgloss_physical_array *a, int *norm)
{
    if (m) {
        *k = pgloss__consts_d_of(m->rho_d[0], m->rho_d[1], m->rho_d[2], m->rho_s, m->alpha_x,
                                 m->alpha_y, (int)m->normalization, lobes & PGLOSS_LOBE_ALL);
        *norm = (int)m->normalization;
    } else {
        *a = *pa;
        if (!a->alpha_y)
            a->alpha_y = a->alpha_x;
        *norm = (int)a->normalization;
    }
}

/* The normalisation of a double call's material(s), NULL while a pointer is missing. */
static const pgloss_normalization *norm_of_d(const pgloss_material *m,
                                             const pgloss_physical_array *pa)
{
    return m ? &m->normalization : (pa ? &pa->normalization : NULL);
}

static pgloss_status eval_pdf_d(const pgloss_batch_options *options, const pgloss_material *m,
                                const pgloss_physical_array *pa, unsigned lobes, size_t n,
                                pgloss_vec3_array_d wo, pgloss_vec3_array_d wi,
                                pgloss_rgb_out_d f, double *pdf, signed char *status)
{
    pgloss_isa isa;
    int reference; /* the double loops serve every tier */
    pgloss_status st;
    const int pointers_ok = !(f.r && (!f.g || !f.b)) && (m || physical_array_ok(pa)) &&
                            vec_ok_d(wo) && vec_ok_d(wi) && (f.r || pdf);
    if (!prepare(options, n, pointers_ok, norm_of_d(m, pa), &isa, &reference, &st))
        return st;
    if (!f.r)
        f.g = f.b = NULL;
    pgloss_physical_array a;
    pgloss__consts_d k;
    int norm;
    setup_d(m, pa, lobes, &k, &a, &norm);
    size_t (*fn)(const pgloss__consts_d *, const pgloss_physical_array *, unsigned, int, size_t,
                 pgloss_vec3_array_d, pgloss_vec3_array_d, pgloss_rgb_out_d, double *);
    PICK(fn, pgloss__eval_pdf_batch_d, isa);
    /* one material: the loops are specialised on its active lobes; per element: on the mask */
    const size_t bad = m ? fn(&k, NULL, k.active, norm, n, wo, wi, f, pdf)
                         : fn(NULL, &a, lobes & PGLOSS_LOBE_ALL, norm, n, wo, wi, f, pdf);
    if (!bad && !status)
        return PGLOSS_OK;
    const ctx_d c = {m ? NULL : &a, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, NULL, NULL, NULL};
    return statuses(n, get_d, &c, status);
}

static pgloss_status sample_d(const pgloss_batch_options *options, const pgloss_material *m,
                              const pgloss_physical_array *pa, unsigned lobes, size_t n,
                              pgloss_vec3_array_d wo, const double *u0, const double *u1,
                              const double *u2, pgloss_vec3_out_d wi, double *pdf,
                              pgloss_rgb_out_d weight, unsigned char *lobe, signed char *status)
{
    pgloss_isa isa;
    int reference; /* the double loops serve every tier */
    pgloss_status st;
    const int pointers_ok = (m || physical_array_ok(pa)) && vec_ok_d(wo) && u0 && u1 && u2 &&
                            wi.x && wi.y && wi.z && pdf && weight.r && weight.g && weight.b;
    if (!prepare(options, n, pointers_ok, norm_of_d(m, pa), &isa, &reference, &st))
        return st;
    pgloss_physical_array a;
    pgloss__consts_d k;
    int norm;
    setup_d(m, pa, lobes, &k, &a, &norm);
    void (*fn)(const pgloss__consts_d *, const pgloss_physical_array *, unsigned, int, size_t,
               pgloss_vec3_array_d, const double *, const double *, const double *,
               pgloss_vec3_out_d, double *, pgloss_rgb_out_d, unsigned char *);
    PICK(fn, pgloss__sample_batch_d, isa);
    if (m)
        fn(&k, NULL, k.active, norm, n, wo, u0, u1, u2, wi, pdf, weight, lobe);
    else
        fn(NULL, &a, lobes & PGLOSS_LOBE_ALL, norm, n, wo, u0, u1, u2, wi, pdf, weight, lobe);
    const ctx_d c = {m ? NULL : &a, wo.x, wo.y, wo.z, NULL, NULL, NULL, u0, u1, u2};
    return statuses(n, get_d, &c, status);
}

pgloss_status pgloss_eval_pdf_batch_d_ex(const pgloss_batch_options *options,
                                         const pgloss_material *m, unsigned lobes, size_t n,
                                         pgloss_vec3_array_d wo, pgloss_vec3_array_d wi,
                                         pgloss_rgb_out_d f, double *pdf, signed char *status)
{
    return eval_pdf_d(options, m, NULL, lobes, n, wo, wi, f, pdf, status);
}

pgloss_status pgloss_sample_batch_d_ex(const pgloss_batch_options *options,
                                       const pgloss_material *m, unsigned lobes, size_t n,
                                       pgloss_vec3_array_d wo, const double *u0,
                                       const double *u1, const double *u2, pgloss_vec3_out_d wi,
                                       double *pdf, pgloss_rgb_out_d weight, unsigned char *lobe,
                                       signed char *status)
{
    return sample_d(options, m, NULL, lobes, n, wo, u0, u1, u2, wi, pdf, weight, lobe, status);
}

pgloss_status pgloss_eval_pdf_batch_materials_d_ex(const pgloss_batch_options *options,
                                                   const pgloss_physical_array *m, unsigned lobes,
                                                   size_t n, pgloss_vec3_array_d wo,
                                                   pgloss_vec3_array_d wi, pgloss_rgb_out_d f,
                                                   double *pdf, signed char *status)
{
    return eval_pdf_d(options, NULL, m, lobes, n, wo, wi, f, pdf, status);
}

pgloss_status pgloss_sample_batch_materials_d_ex(const pgloss_batch_options *options,
                                                 const pgloss_physical_array *m, unsigned lobes,
                                                 size_t n, pgloss_vec3_array_d wo,
                                                 const double *u0, const double *u1,
                                                 const double *u2, pgloss_vec3_out_d wi,
                                                 double *pdf, pgloss_rgb_out_d weight,
                                                 unsigned char *lobe, signed char *status)
{
    return sample_d(options, NULL, m, lobes, n, wo, u0, u1, u2, wi, pdf, weight, lobe, status);
}

/* ---- the convenience forms: default options, no status array ------------------------- */

pgloss_status pgloss_eval_batch_materials(const pgloss_material_array *m, unsigned lobes,
                                          size_t n, pgloss_vec3_array wo, pgloss_vec3_array wi,
                                          pgloss_rgb_out f)
{
    if (n && !f.r)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_ex(NULL, m, lobes, n, wo, wi, f, NULL, NULL);
}

pgloss_status pgloss_pdf_batch_materials(const pgloss_material_array *m, unsigned lobes,
                                         size_t n, pgloss_vec3_array wo, pgloss_vec3_array wi,
                                         float *pdf)
{
    const pgloss_rgb_out none = {NULL, NULL, NULL};
    if (n && !pdf)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_ex(NULL, m, lobes, n, wo, wi, none, pdf, NULL);
}

pgloss_status pgloss_eval_pdf_batch_materials(const pgloss_material_array *m, unsigned lobes,
                                              size_t n, pgloss_vec3_array wo,
                                              pgloss_vec3_array wi, pgloss_rgb_out f, float *pdf)
{
    if (n && (!f.r || !pdf))
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_ex(NULL, m, lobes, n, wo, wi, f, pdf, NULL);
}

pgloss_status pgloss_sample_batch_materials(const pgloss_material_array *m, unsigned lobes,
                                            size_t n, pgloss_vec3_array wo, const float *u0,
                                            const float *u1, const float *u2,
                                            pgloss_vec3_out wi, float *pdf,
                                            pgloss_rgb_out weight, unsigned char *lobe)
{
    return pgloss_sample_batch_materials_ex(NULL, m, lobes, n, wo, u0, u1, u2, wi, pdf, weight,
                                            lobe, NULL);
}

pgloss_status pgloss_eval_batch_d(const pgloss_material *m, unsigned lobes, size_t n,
                                  pgloss_vec3_array_d wo, pgloss_vec3_array_d wi,
                                  pgloss_rgb_out_d f)
{
    if (n && !f.r)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_d_ex(NULL, m, lobes, n, wo, wi, f, NULL, NULL);
}

pgloss_status pgloss_pdf_batch_d(const pgloss_material *m, unsigned lobes, size_t n,
                                 pgloss_vec3_array_d wo, pgloss_vec3_array_d wi, double *pdf)
{
    const pgloss_rgb_out_d none = {NULL, NULL, NULL};
    if (n && !pdf)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_d_ex(NULL, m, lobes, n, wo, wi, none, pdf, NULL);
}

pgloss_status pgloss_eval_pdf_batch_d(const pgloss_material *m, unsigned lobes, size_t n,
                                      pgloss_vec3_array_d wo, pgloss_vec3_array_d wi,
                                      pgloss_rgb_out_d f, double *pdf)
{
    if (n && (!f.r || !pdf))
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_d_ex(NULL, m, lobes, n, wo, wi, f, pdf, NULL);
}

pgloss_status pgloss_sample_batch_d(const pgloss_material *m, unsigned lobes, size_t n,
                                    pgloss_vec3_array_d wo, const double *u0, const double *u1,
                                    const double *u2, pgloss_vec3_out_d wi, double *pdf,
                                    pgloss_rgb_out_d weight, unsigned char *lobe)
{
    return pgloss_sample_batch_d_ex(NULL, m, lobes, n, wo, u0, u1, u2, wi, pdf, weight, lobe,
                                    NULL);
}

pgloss_status pgloss_eval_batch_materials_d(const pgloss_physical_array *m, unsigned lobes,
                                            size_t n, pgloss_vec3_array_d wo,
                                            pgloss_vec3_array_d wi, pgloss_rgb_out_d f)
{
    if (n && !f.r)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_d_ex(NULL, m, lobes, n, wo, wi, f, NULL, NULL);
}

pgloss_status pgloss_pdf_batch_materials_d(const pgloss_physical_array *m, unsigned lobes,
                                           size_t n, pgloss_vec3_array_d wo,
                                           pgloss_vec3_array_d wi, double *pdf)
{
    const pgloss_rgb_out_d none = {NULL, NULL, NULL};
    if (n && !pdf)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_d_ex(NULL, m, lobes, n, wo, wi, none, pdf, NULL);
}

pgloss_status pgloss_eval_pdf_batch_materials_d(const pgloss_physical_array *m, unsigned lobes,
                                                size_t n, pgloss_vec3_array_d wo,
                                                pgloss_vec3_array_d wi, pgloss_rgb_out_d f,
                                                double *pdf)
{
    if (n && (!f.r || !pdf))
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_d_ex(NULL, m, lobes, n, wo, wi, f, pdf, NULL);
}

pgloss_status pgloss_sample_batch_materials_d(const pgloss_physical_array *m, unsigned lobes,
                                              size_t n, pgloss_vec3_array_d wo, const double *u0,
                                              const double *u1, const double *u2,
                                              pgloss_vec3_out_d wi, double *pdf,
                                              pgloss_rgb_out_d weight, unsigned char *lobe)
{
    return pgloss_sample_batch_materials_d_ex(NULL, m, lobes, n, wo, u0, u1, u2, wi, pdf, weight,
                                              lobe, NULL);
}
