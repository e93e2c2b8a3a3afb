/* Scalar evaluation of the Ward BRDF (paper eq. 2 and its two later normalisations) and of
 * the sampling density. Double internally: this is the reference the float batches and the
 * shader ports are held to. */
#include "internal.h"

void pgloss__eval_pdf_d(const pgloss_material *m, unsigned active, const double o[3],
                        const double i[3], double f[3], double *pdf)
{
    double fd[3] = {0.0, 0.0, 0.0}, fs = 0.0, p = 0.0;
    if (o[2] > 0.0 && i[2] > 0.0 && active) {
        /* The lobe-selection probability only matters to the pdf: skip it for eval alone. */
        const double ps = pdf ? pgloss__specular_probability_d(m, active) : 0.0;
        if (active & PGLOSS_LOBE_DIFFUSE) {
            for (int k = 0; k < 3; ++k)
                fd[k] = m->rho_d[k] * PGLOSS_INV_PI;
            p += (1.0 - ps) * i[2] * PGLOSS_INV_PI;
        }
        if (active & PGLOSS_LOBE_SPECULAR) {
            const double hx = o[0] + i[0], hy = o[1] + i[1], hz = o[2] + i[2];
            const double ex = hx * m->inv_alpha_x, ey = hy * m->inv_alpha_y;
            /* exp(-tan²δ/α²) of eq. 2, anisotropic form (Ward 1992). */
            const double e = exp(-(ex * ex + ey * ey) / (hz * hz));
            const double ci = fmax(i[2], (double)PGLOSS_COS_MIN);
            const double co = fmax(o[2], (double)PGLOSS_COS_MIN);
            const double hzc = ci + co;
            const double hh = hx * hx + hy * hy + hz * hz;
            if (f) {
                double norm;
                switch (m->normalization) {
                case PGLOSS_NORM_WARD_DUR: norm = 1.0 / (ci * co); break;          /* Dür 2006 */
                case PGLOSS_NORM_BOUNDED: norm = hh / ((hzc * hzc) * (hzc * hzc)); break; /* GM&D 2010 */
                default: norm = 1.0 / sqrt(ci * co); break;                         /* eq. 2 */
                }
                fs = m->spec_scale * e * norm;
            }
            /* Walter 2005: p(wi) = D(h) / (4 (wo·h)), and for unit wo, wi: wo·ĥ ĥz³ = hz³ / (2 h·h). */
            if (pdf)
                p += ps * 2.0 * m->pdf_scale * e * hh / (hzc * hzc * hzc);
        }
    }
    if (f)
        for (int k = 0; k < 3; ++k)
            f[k] = fd[k] + fs;
    if (pdf)
        *pdf = p;
}

static pgloss_status prepare(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi,
                             double o[3], double i[3])
{
    const int ok_o = pgloss__normalize(wo, o);
    const int ok_i = pgloss__normalize(wi, i);
    (void)m;
    return (ok_o && ok_i) ? PGLOSS_OK : PGLOSS_ERR_DIRECTION;
}

static void store_rgb(pgloss_rgb *out, const double f[3])
{
    out->r = pgloss__to_float(f[0]);
    out->g = pgloss__to_float(f[1]);
    out->b = pgloss__to_float(f[2]);
}

pgloss_status pgloss_eval_pdf(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi,
                              unsigned lobes, pgloss_rgb *f, float *pdf)
{
    if (f) f->r = f->g = f->b = 0.0f;
    if (pdf) *pdf = 0.0f;
    if (!m || (!f && !pdf))
        return PGLOSS_ERR_NULL;
    double o[3], i[3], fv[3], p;
    const pgloss_status st = prepare(m, wo, wi, o, i);
    if (st != PGLOSS_OK)
        return st;
    pgloss__eval_pdf_d(m, lobes & m->lobes & PGLOSS_LOBE_ALL, o, i, f ? fv : NULL, pdf ? &p : NULL);
    if (f) store_rgb(f, fv);
    if (pdf) *pdf = pgloss__to_float(p);
    return PGLOSS_OK;
}

pgloss_status pgloss_eval(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi,
                          unsigned lobes, pgloss_rgb *f)
{
    if (!f)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf(m, wo, wi, lobes, f, NULL);
}

pgloss_status pgloss_pdf(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi,
                         unsigned lobes, float *pdf)
{
    if (!pdf)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf(m, wo, wi, lobes, NULL, pdf);
}
