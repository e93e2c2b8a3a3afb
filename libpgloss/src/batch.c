/* Batched entry points. Each public function dispatches once, outside the loop, to a loop
 * specialised for (active lobes, normalisation, outputs wanted): absent lobes and unused
 * normalisations cost nothing, and each loop body is branch-free float code that the
 * compiler vectorises. Semantics mirror the scalar functions of brdf.c / sample.c. */
#include "pgloss/batch.h"
#include "internal.h"
#include "kernel_float.h"

#define ONE_MINUS_EPS_F 0x1.fffffep-1f
#define COS_MIN_F PGLOSS_COS_MIN

typedef struct consts {
    float fd[3];          /* ρd/π */
    float spec_scale, pdf2; /* 2 × pdf_scale */
    float inv_ax, inv_ay;
    float ax_s, ay_s;     /* αx, αy divided by amax = max(αx, αy, 1) (sampling) */
    float inv_amax;       /* 1 / amax: never 0, since α <= FLT_MAX */
    float ps, pd;         /* lobe probabilities */
} consts;

static consts make_consts(const pgloss_material *m, unsigned active)
{
    consts k;
    for (int c = 0; c < 3; ++c)
        k.fd[c] = m->rho_d[c] * PGLOSS_INV_PI_F;
    k.spec_scale = m->spec_scale;
    k.pdf2 = 2.0f * m->pdf_scale;
    k.inv_ax = m->inv_alpha_x;
    k.inv_ay = m->inv_alpha_y;
    const double amax = fmax(fmax((double)m->alpha_x, (double)m->alpha_y), 1.0);
    k.ax_s = (float)(m->alpha_x / amax);
    k.ay_s = (float)(m->alpha_y / amax);
    k.inv_amax = (float)(1.0 / amax);
    k.ps = (float)pgloss__specular_probability_d(m, active);
    k.pd = 1.0f - k.ps;
    return k;
}

/* f and pdf at unit o, i (float); the float twin of pgloss__eval_pdf_d. */
PGLOSS_INLINE void kernel_eval_pdf(const consts *k, const unsigned active, const int norm,
                                   float ox, float oy, float oz, float ix, float iy, float iz,
                                   int valid, float f[3], float *pdf)
{
    const int upper = valid & (oz > 0.0f) & (iz > 0.0f);
    float fr = 0.0f, fg = 0.0f, fb = 0.0f, p = 0.0f;
    if (active & PGLOSS_LOBE_DIFFUSE) {
        fr = k->fd[0];
        fg = k->fd[1];
        fb = k->fd[2];
        p = k->pd * iz * PGLOSS_INV_PI_F;
    }
    if (active & PGLOSS_LOBE_SPECULAR) {
        const float hx = ox + ix, hy = oy + iy, hz = oz + iz;
        const float ex = hx * k->inv_ax, ey = hy * k->inv_ay;
        const float hz2 = pgloss__maxf(hz * hz, FLT_MIN);
        const float e = pgloss__exp_neg(-(ex * ex + ey * ey) / hz2); /* eq. 2's exponential */
        const float ci = pgloss__maxf(iz, COS_MIN_F), co = pgloss__maxf(oz, COS_MIN_F);
        const float hzc = ci + co;
        const float hh = hx * hx + hy * hy + hz * hz;
        float n;
        if (norm == PGLOSS_NORM_WARD_DUR)
            n = 1.0f / (ci * co);
        else if (norm == PGLOSS_NORM_BOUNDED)
            n = hh / ((hzc * hzc) * (hzc * hzc));
        else
            n = 1.0f / sqrtf(ci * co);
        const float fs = pgloss__minf(k->spec_scale * e * n, FLT_MAX);
        fr += fs;
        fg += fs;
        fb += fs;
        p += k->ps * (k->pdf2 * e * hh / (hzc * hzc * hzc));
    }
    f[0] = upper ? pgloss__minf(fr, FLT_MAX) : 0.0f;
    f[1] = upper ? pgloss__minf(fg, FLT_MAX) : 0.0f;
    f[2] = upper ? pgloss__minf(fb, FLT_MAX) : 0.0f;
    *pdf = upper ? pgloss__minf(p, FLT_MAX) : 0.0f;
}

/* Directions are normalised chunk by chunk into the stack, then the BRDF loop runs over the
 * chunk: two simple loops vectorise where one fused loop defeats GCC's if-conversion. */
#define PGLOSS_CHUNK 256

PGLOSS_INLINE size_t normalize_chunk(size_t n, const float *restrict xs, const float *restrict ys,
                                     const float *restrict zs, float *restrict nx,
                                     float *restrict ny, float *restrict nz, int *restrict ok)
{
    size_t bad = 0;
    for (size_t j = 0; j < n; ++j) {
        float x = xs[j], y = ys[j], z = zs[j];
        const int v = pgloss__normalize_f(&x, &y, &z);
        nx[j] = x;
        ny[j] = y;
        nz[j] = z;
        ok[j] &= v;
        bad += !v;
    }
    return bad;
}

PGLOSS_INLINE size_t eval_pdf_loop(const consts *restrict k, const unsigned active, const int norm,
                                   size_t n, const float *restrict oxs, const float *restrict oys,
                                   const float *restrict ozs, const float *restrict ixs,
                                   const float *restrict iys, const float *restrict izs,
                                   float *restrict fr, float *restrict fg, float *restrict fb,
                                   float *restrict pdf, const int want_f, const int want_pdf)
{
    size_t bad = 0;
    float ox[PGLOSS_CHUNK], oy[PGLOSS_CHUNK], oz[PGLOSS_CHUNK];
    float ix[PGLOSS_CHUNK], iy[PGLOSS_CHUNK], iz[PGLOSS_CHUNK];
    int ok[PGLOSS_CHUNK];
    for (size_t base = 0; base < n; base += PGLOSS_CHUNK) {
        const size_t m = n - base < PGLOSS_CHUNK ? n - base : PGLOSS_CHUNK;
        for (size_t j = 0; j < m; ++j)
            ok[j] = 1;
        const size_t bo = normalize_chunk(m, oxs + base, oys + base, ozs + base, ox, oy, oz, ok);
        const size_t bi = normalize_chunk(m, ixs + base, iys + base, izs + base, ix, iy, iz, ok);
        bad += bo + bi;
        for (size_t j = 0; j < m; ++j) {
            float f[3], p;
            kernel_eval_pdf(k, active, norm, ox[j], oy[j], oz[j], ix[j], iy[j], iz[j], ok[j], f, &p);
            if (want_f) {
                fr[base + j] = f[0];
                fg[base + j] = f[1];
                fb[base + j] = f[2];
            }
            if (want_pdf)
                pdf[base + j] = p;
        }
    }
    return bad;
}

/* Instantiates the loop for every (active, norm) with constant arguments. */
static size_t eval_pdf_dispatch(const pgloss_material *m, unsigned active, size_t n,
                                pgloss_vec3_array wo, pgloss_vec3_array wi, pgloss_rgb_out f,
                                float *pdf, int want_f, int want_pdf)
{
    const consts k = make_consts(m, active);
#define PGLOSS_LOOP(A, N, WF, WP)                                                                  \
    eval_pdf_loop(&k, A, N, n, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, f.r, f.g, f.b, pdf, WF, WP)
#define PGLOSS_BY_WANT(A, N)                                                                       \
    (want_f && want_pdf ? PGLOSS_LOOP(A, N, 1, 1)                                                  \
                        : (want_f ? PGLOSS_LOOP(A, N, 1, 0) : PGLOSS_LOOP(A, N, 0, 1)))
#define PGLOSS_BY_NORM(A)                                                                          \
    (m->normalization == PGLOSS_NORM_WARD_DUR                                                      \
         ? PGLOSS_BY_WANT(A, PGLOSS_NORM_WARD_DUR)                                                 \
         : (m->normalization == PGLOSS_NORM_BOUNDED ? PGLOSS_BY_WANT(A, PGLOSS_NORM_BOUNDED)       \
                                                    : PGLOSS_BY_WANT(A, PGLOSS_NORM_WARD)))
    switch (active) {
    case PGLOSS_LOBE_DIFFUSE: return PGLOSS_BY_WANT(PGLOSS_LOBE_DIFFUSE, PGLOSS_NORM_WARD);
    case PGLOSS_LOBE_SPECULAR: return PGLOSS_BY_NORM(PGLOSS_LOBE_SPECULAR);
    case PGLOSS_LOBE_ALL: return PGLOSS_BY_NORM(PGLOSS_LOBE_ALL);
    default: return PGLOSS_BY_WANT(PGLOSS_LOBE_NONE, PGLOSS_NORM_WARD);
    }
#undef PGLOSS_BY_NORM
#undef PGLOSS_BY_WANT
#undef PGLOSS_LOOP
}

static int arrays_ok(pgloss_vec3_array v)
{
    return v.x && v.y && v.z;
}

static pgloss_status eval_pdf_common(const pgloss_material *m, unsigned lobes, size_t n,
                                     pgloss_vec3_array wo, pgloss_vec3_array wi, pgloss_rgb_out f,
                                     float *pdf, int want_f, int want_pdf)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!m || !arrays_ok(wo) || !arrays_ok(wi) || (want_f && (!f.r || !f.g || !f.b)) ||
        (want_pdf && !pdf))
        return PGLOSS_ERR_NULL;
    const unsigned active = lobes & m->lobes & PGLOSS_LOBE_ALL;
    const size_t bad = eval_pdf_dispatch(m, active, n, wo, wi, f, pdf, want_f, want_pdf);
    return bad ? PGLOSS_ERR_DIRECTION : PGLOSS_OK;
}

pgloss_status pgloss_eval_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                pgloss_vec3_array wo, pgloss_vec3_array wi, pgloss_rgb_out f)
{
    return eval_pdf_common(m, lobes, n, wo, wi, f, NULL, 1, 0);
}

pgloss_status pgloss_pdf_batch(const pgloss_material *m, unsigned lobes, size_t n,
                               pgloss_vec3_array wo, pgloss_vec3_array wi, float *pdf)
{
    const pgloss_rgb_out none = {NULL, NULL, NULL};
    return eval_pdf_common(m, lobes, n, wo, wi, none, pdf, 0, 1);
}

pgloss_status pgloss_eval_pdf_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                    pgloss_vec3_array wo, pgloss_vec3_array wi,
                                    pgloss_rgb_out f, float *pdf)
{
    return eval_pdf_common(m, lobes, n, wo, wi, f, pdf, 1, 1);
}

/* ---- sampling ---------------------------------------------------------------------- */

PGLOSS_INLINE float clamp_u(float u)
{
    const float a = u > 0.0f ? u : 0.0f; /* also maps NaN to 0; NaN is reported separately */
    return a < ONE_MINUS_EPS_F ? a : ONE_MINUS_EPS_F;
}

PGLOSS_INLINE void sample_loop(const consts *restrict k, const unsigned active, const int norm,
                               size_t n, const float *restrict oxs, const float *restrict oys,
                               const float *restrict ozs, const float *restrict u0s,
                               const float *restrict u1s, const float *restrict u2s,
                               float *restrict wx, float *restrict wy, float *restrict wz,
                               float *restrict pdfs, float *restrict wr, float *restrict wg,
                               float *restrict wb, unsigned char *restrict lobe_out,
                               const int want_lobe)
{
    for (size_t j = 0; j < n; ++j) {
        float ox = oxs[j], oy = oys[j], oz = ozs[j];
        const float r0 = u0s[j], r1 = u1s[j], r2 = u2s[j];
        const int nan_u = (r0 != r0) | (r1 != r1) | (r2 != r2);
        const int valid = pgloss__normalize_f(&ox, &oy, &oz) & !nan_u;
        const float u0 = clamp_u(r0), u1 = clamp_u(r1), u2 = clamp_u(r2);
        const int spec = (active == PGLOSS_LOBE_SPECULAR) |
                         ((active == PGLOSS_LOBE_ALL) & (u0 < k->ps));

        /* Diffuse: concentric disk (Shirley–Chiu), lifted to the hemisphere. */
        const float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
        const int first = pgloss__absf(a) > pgloss__absf(b);
        const float num = first ? b : a, den = first ? a : b;
        const float t = (den != 0.0f ? num / den : 0.0f) * (0.25f * PGLOSS_PI_F);
        float st, ct;
        pgloss__sincos_small(t, &st, &ct);
        const float r = first ? a : b;
        /* first: φ = t; else φ = π/2 - t, so cos φ = sin t, sin φ = cos t. */
        const float dx = r * (first ? ct : st), dy = r * (first ? st : ct);
        const float dz = sqrtf(pgloss__maxf(0.0f, 1.0f - dx * dx - dy * dy));

        /* Specular: Walter's half-vector sampling, stretched by (αx, αy). */
        float sn, cs;
        pgloss__sincos_turn(u2, &sn, &cs);
        const float s = sqrtf(pgloss__neg_log1m(u1));
        /* h ∝ (αx s cos t, αy s sin t, 1). αx s overflows float for α near FLT_MAX, and its
         * square for α ≳ 2e19 (giving NaN or wi = -wo): first divide by the per-material
         * amax = max(αx, αy, 1), then by the largest component, as the scalar path does. */
        const float hx0 = k->ax_s * (s * cs), hy0 = k->ay_s * (s * sn), hz0 = k->inv_amax;
        const float hm = pgloss__maxf(pgloss__maxf(pgloss__absf(hx0), pgloss__absf(hy0)), hz0);
        const float hx1 = hx0 / hm, hy1 = hy0 / hm, hz1 = hz0 / hm;
        const float hinv = 1.0f / sqrtf(hx1 * hx1 + hy1 * hy1 + hz1 * hz1);
        const float hx = hx1 * hinv, hy = hy1 * hinv, hz = hz1 * hinv;
        const float oh = ox * hx + oy * hy + oz * hz;
        const float sx = 2.0f * oh * hx - ox, sy = 2.0f * oh * hy - oy, sz = 2.0f * oh * hz - oz;

        const int has_lobe = active != PGLOSS_LOBE_NONE;
        float ix = spec ? sx : dx, iy = spec ? sy : dy, iz = spec ? sz : dz;
        const int drawn = valid & has_lobe;
        ix = drawn ? ix : 0.0f;
        iy = drawn ? iy : 0.0f;
        iz = drawn ? iz : 1.0f;
        wx[j] = ix;
        wy[j] = iy;
        wz[j] = iz;

        float nx = ix, ny = iy, nz = iz;
        const int ok_i = pgloss__normalize_f(&nx, &ny, &nz);
        const int accepted = drawn & ok_i & ((!spec) | (oh > 0.0f));
        float f[3], p;
        kernel_eval_pdf(k, active, norm, ox, oy, oz, nx, ny, nz, accepted, f, &p);
        const int good = accepted & (p > 0.0f);
        const float inv_p = nz / (good ? p : 1.0f);
        pdfs[j] = good ? p : 0.0f;
        wr[j] = good ? pgloss__minf(f[0] * inv_p, FLT_MAX) : 0.0f;
        wg[j] = good ? pgloss__minf(f[1] * inv_p, FLT_MAX) : 0.0f;
        wb[j] = good ? pgloss__minf(f[2] * inv_p, FLT_MAX) : 0.0f;
        if (want_lobe)
            lobe_out[j] = (unsigned char)(!drawn ? PGLOSS_LOBE_NONE
                                          : (spec ? PGLOSS_LOBE_SPECULAR : PGLOSS_LOBE_DIFFUSE));
    }
}

pgloss_status pgloss_sample_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                  pgloss_vec3_array wo, const float *u0, const float *u1,
                                  const float *u2, pgloss_vec3_out wi, float *pdf,
                                  pgloss_rgb_out weight, unsigned char *lobe)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!m || !arrays_ok(wo) || !u0 || !u1 || !u2 || !wi.x || !wi.y || !wi.z || !pdf ||
        !weight.r || !weight.g || !weight.b)
        return PGLOSS_ERR_NULL;
    const unsigned active = lobes & m->lobes & PGLOSS_LOBE_ALL;
    const consts k = make_consts(m, active);
#define PGLOSS_LOOP(A, N, WL)                                                                      \
    sample_loop(&k, A, N, n, wo.x, wo.y, wo.z, u0, u1, u2, wi.x, wi.y, wi.z, pdf, weight.r,        \
                weight.g, weight.b, lobe, WL)
#define PGLOSS_BY_LOBE(A, N) (lobe ? PGLOSS_LOOP(A, N, 1) : PGLOSS_LOOP(A, N, 0))
#define PGLOSS_BY_NORM(A)                                                                          \
    (m->normalization == PGLOSS_NORM_WARD_DUR                                                      \
         ? PGLOSS_BY_LOBE(A, PGLOSS_NORM_WARD_DUR)                                                 \
         : (m->normalization == PGLOSS_NORM_BOUNDED ? PGLOSS_BY_LOBE(A, PGLOSS_NORM_BOUNDED)       \
                                                    : PGLOSS_BY_LOBE(A, PGLOSS_NORM_WARD)))
    switch (active) {
    case PGLOSS_LOBE_DIFFUSE: PGLOSS_BY_LOBE(PGLOSS_LOBE_DIFFUSE, PGLOSS_NORM_WARD); break;
    case PGLOSS_LOBE_SPECULAR: PGLOSS_BY_NORM(PGLOSS_LOBE_SPECULAR); break;
    case PGLOSS_LOBE_ALL: PGLOSS_BY_NORM(PGLOSS_LOBE_ALL); break;
    default: PGLOSS_BY_LOBE(PGLOSS_LOBE_NONE, PGLOSS_NORM_WARD); break;
    }
#undef PGLOSS_BY_NORM
#undef PGLOSS_BY_LOBE
#undef PGLOSS_LOOP

    /* Report the first invalid element's reason, in the scalar function's order. */
    for (size_t j = 0; j < n; ++j) {
        if (isnan(u0[j]) || isnan(u1[j]) || isnan(u2[j]))
            return PGLOSS_ERR_RANDOM;
        const pgloss_vec3 v = {wo.x[j], wo.y[j], wo.z[j]};
        double o[3];
        if (!pgloss__normalize(v, o))
            return PGLOSS_ERR_DIRECTION;
    }
    return PGLOSS_OK;
}
