/* Importance sampling of the Ward BRDF: lobe selection by albedo, cosine-weighted diffuse
 * directions, and Walter's (2005) half-vector sampling of the specular lobe. */
#include "internal.h"

/* Largest float below 1: random numbers are clamped to [0, ONE_MINUS_EPS]. */
#define ONE_MINUS_EPS 0x1.fffffep-1f

static float clamp_u(float u)
{
    return u < 0.0f ? 0.0f : (u > ONE_MINUS_EPS ? ONE_MINUS_EPS : u);
}

/* Shirley & Chiu's concentric map of [0,1)² onto the unit disk, lifted to the hemisphere
 * (Malley's method): density cosθ/π. */
static void sample_cosine_hemisphere(double u1, double u2, double w[3])
{
    const double a = 2.0 * u1 - 1.0, b = 2.0 * u2 - 1.0;
    double r = 0.0, phi = 0.0;
    if (a != 0.0 || b != 0.0) {
        if (fabs(a) > fabs(b)) {
            r = a;
            phi = (PGLOSS_PI / 4.0) * (b / a);
        } else {
            r = b;
            phi = PGLOSS_PI / 2.0 - (PGLOSS_PI / 4.0) * (a / b);
        }
    }
    w[0] = r * cos(phi);
    w[1] = r * sin(phi);
    w[2] = sqrt(fmax(0.0, 1.0 - w[0] * w[0] - w[1] * w[1]));
}

/* Half vector with density exp(-tan²δ (cos²φ/αx² + sin²φ/αy²)) / (π αx αy cos³δ) (Walter 2005,
 * eq. 5–6 in the anisotropic form of Ward 1992). With t = 2πu2 and s = sqrt(-ln(1-u1)),
 * tanδ·(cosφ, sinφ) = s·(αx cos t, αy sin t): the isotropic case is φ = t, tan²δ = -α² ln(1-u1). */
static void sample_half_vector(const pgloss_material *m, double u1, double u2, double h[3])
{
    const double s = sqrt(-log1p(-u1));
    const double t = 2.0 * PGLOSS_PI * u2;
    double x = m->alpha_x * s * cos(t), y = m->alpha_y * s * sin(t), z = 1.0;
    /* Scale by the largest component before squaring, as pgloss__normalize does, and as the
     * float batch must (there (α s)² overflows for α ≳ 2e19): the same algorithm in both
     * paths keeps scalar and batch results together for every α the material accepts. */
    const double big = fmax(fmax(fabs(x), fabs(y)), 1.0);
    x /= big; y /= big; z /= big;
    const double inv = 1.0 / sqrt(x * x + y * y + z * z);
    h[0] = x * inv;
    h[1] = y * inv;
    h[2] = z * inv;
}

static void reject(pgloss_sample_record *s)
{
    s->pdf = 0.0f;
    s->weight.r = s->weight.g = s->weight.b = 0.0f;
}

pgloss_status pgloss_sample(const pgloss_material *m, pgloss_vec3 wo, const float u[3],
                            unsigned lobes, pgloss_sample_record *s)
{
    if (!s)
        return PGLOSS_ERR_NULL;
    s->wi.x = s->wi.y = 0.0f;
    s->wi.z = 1.0f;
    s->lobe = PGLOSS_LOBE_NONE;
    reject(s);
    if (!m || !u)
        return PGLOSS_ERR_NULL;
    if (isnan(u[0]) || isnan(u[1]) || isnan(u[2]))
        return PGLOSS_ERR_RANDOM;
    double o[3];
    if (!pgloss__normalize(wo, o))
        return PGLOSS_ERR_DIRECTION;

    const unsigned active = lobes & m->lobes & PGLOSS_LOBE_ALL;
    if (!active)
        return PGLOSS_OK;
    const double ps = pgloss__specular_probability_d(m, active);
    const double u0 = clamp_u(u[0]), u1 = clamp_u(u[1]), u2 = clamp_u(u[2]);

    double w[3];
    if (u0 < ps) {
        s->lobe = PGLOSS_LOBE_SPECULAR;
        double h[3];
        sample_half_vector(m, u1, u2, h);
        const double oh = o[0] * h[0] + o[1] * h[1] + o[2] * h[2];
        for (int k = 0; k < 3; ++k)
            w[k] = 2.0 * oh * h[k] - o[k];
        if (!(oh > 0.0)) {
            s->wi.x = (float)w[0]; s->wi.y = (float)w[1]; s->wi.z = (float)w[2];
            return PGLOSS_OK;
        }
    } else {
        s->lobe = PGLOSS_LOBE_DIFFUSE;
        sample_cosine_hemisphere(u1, u2, w);
    }
    s->wi.x = (float)w[0];
    s->wi.y = (float)w[1];
    s->wi.z = (float)w[2];
    if (!(o[2] > 0.0))
        return PGLOSS_OK;

    /* Density and weight at the float direction handed back, computed exactly as
     * pgloss_eval_pdf(wo, s->wi) computes them, so that they agree with pgloss_pdf and
     * pgloss_eval bit for bit. wi at or below the horizon gives p = 0 (rejected below). */
    double f[3], p, ci = 0.0;
    if (pgloss__eval_pdf_raw(m, active, wo, s->wi, f, &p, &ci) != PGLOSS_OK)
        return PGLOSS_OK;
    /* Decide rejection on the float pdf that is stored, not on the double one: a density in
     * (0, FLT_TRUE_MIN/2) rounds to 0, and a sample with pdf 0 must be a rejected sample
     * (weight 0), never one with a finite weight and a zero pdf (found by test_stress). */
    const float pf = pgloss__to_float(p);
    if (!(pf > 0.0f))
        return PGLOSS_OK;
    s->pdf = pf;
    const double ci_p = ci / p; /* weight = f cosθi / pdf */
    s->weight.r = pgloss__to_float(f[0] * ci_p);
    s->weight.g = pgloss__to_float(f[1] * ci_p);
    s->weight.b = pgloss__to_float(f[2] * ci_p);
    return PGLOSS_OK;
}
