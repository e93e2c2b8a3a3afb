// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Float kernels of the batched paths: branch-free, libm-free (so that loops vectorise without
 * -ffast-math or a vector math library), inlined into each specialised loop of batch.c.
 * Accuracy: expf/logf/sincosf below are within 2 ulp of the correctly rounded results on the
 * arguments used here (Taylor/atanh series past float precision, Cody–Waite reduction). */
#ifndef PGLOSS_KERNEL_FLOAT_H
#define PGLOSS_KERNEL_FLOAT_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#if defined(__GNUC__) || defined(__clang__)
#define PGLOSS_INLINE static inline __attribute__((always_inline))
#else
#define PGLOSS_INLINE static inline
#endif

#define PGLOSS_PI_F 3.14159265358979323846f
#define PGLOSS_INV_PI_F 0.31830988618379067154f

PGLOSS_INLINE float pgloss__bits_to_float(int32_t b) { float f; memcpy(&f, &b, sizeof f); return f; }
PGLOSS_INLINE int32_t pgloss__float_to_bits(float f) { int32_t b; memcpy(&b, &f, sizeof b); return b; }
PGLOSS_INLINE float pgloss__minf(float a, float b) { return a < b ? a : b; }
PGLOSS_INLINE float pgloss__maxf(float a, float b) { return a > b ? a : b; }
PGLOSS_INLINE float pgloss__absf(float a) { return a < 0.0f ? -a : a; }

/* Range reduction of exp(x), x <= 0: x = n ln2 + r, |r| <= ln2/2, with xc = max(x, ln FLT_MIN);
 * returns 2^n (the bits of the exponent field). */
PGLOSS_INLINE float pgloss__exp_reduce(float x, float *r)
{
    const float xc = x < -87.33654f ? -87.33654f : x;
    /* round(x / ln2) by the 1.5·2^23 trick: exact for |x| < 2^22, no rint() call. */
    const float shifter = 12582912.0f;
    const float n = (xc * 1.44269504088896341f + shifter) - shifter;
    *r = (xc - n * 0.693145751953125f) - n * 1.428606765330187e-06f; /* Cody–Waite */
    return pgloss__bits_to_float(((int32_t)n + 127) << 23);
}

/* exp(x) for x <= 0; 0 below ln(FLT_MIN) (results that would be subnormal flush to 0).
 * Degree-7 Taylor polynomial on the reduced argument: within 2 ulp. */
PGLOSS_INLINE float pgloss__exp_neg(float x)
{
    float r;
    const float scale = pgloss__exp_reduce(x, &r);
    float p = 1.0f / 5040.0f;
    p = p * r + 1.0f / 720.0f;
    p = p * r + 1.0f / 120.0f;
    p = p * r + 1.0f / 24.0f;
    p = p * r + 1.0f / 6.0f;
    p = p * r + 0.5f;
    p = p * r + 1.0f;
    p = p * r + 1.0f;
    return x < -87.33654f ? 0.0f : p * scale;
}

/* exp(x) for x <= 0 in the fast tier: a degree-5 polynomial with p(0) = 1, minimax in relative
 * error on [-ln2/2, ln2/2] (9.2e-8; 1.5e-7 as evaluated in float). */
PGLOSS_INLINE float pgloss__exp_neg_fast(float x)
{
    float r;
    const float scale = pgloss__exp_reduce(x, &r);
    float p = 8.290305734e-03f;
    p = p * r + 4.189792275e-02f;
    p = p * r + 1.666763574e-01f;
    p = p * r + 4.999915063e-01f;
    p = p * r + 9.999997020e-01f;
    p = p * r + 1.0f;
    return x < -87.33654f ? 0.0f : p * scale;
}

/* log(w) for normal w > 0. */
PGLOSS_INLINE float pgloss__log_pos(float w)
{
    const int32_t b = pgloss__float_to_bits(w);
    int32_t e = ((b >> 23) & 0xff) - 127;
    float m = pgloss__bits_to_float((b & 0x007fffff) | 0x3f800000); /* [1, 2) */
    const int big = m > 1.41421356f;
    m = big ? 0.5f * m : m;
    e = big ? e + 1 : e;
    /* log m = 2 atanh(s), s = (m-1)/(m+1) in [-0.1716, 0.1716]. */
    const float s = (m - 1.0f) / (m + 1.0f), s2 = s * s;
    float p = 2.0f / 11.0f;
    p = p * s2 + 2.0f / 9.0f;
    p = p * s2 + 2.0f / 7.0f;
    p = p * s2 + 2.0f / 5.0f;
    p = p * s2 + 2.0f / 3.0f;
    p = p * s2 + 2.0f;
    return (float)e * 0.693147180559945309f + s * p;
}

/* -log(1 - u) for u in [0, 1 - 2^-24], accurate also for tiny u (Kahan's log1p trick). */
PGLOSS_INLINE float pgloss__neg_log1m(float u)
{
    const float w = 1.0f - u;
    const float d = w - 1.0f;                 /* exact */
    const float safe_d = d == 0.0f ? -1.0f : d;
    const float v = pgloss__log_pos(w) * (-u / safe_d);
    return d == 0.0f ? u : -v;
}

/* sin and cos of θ in [-π/4, π/4] (Taylor to θ^11 / θ^10). */
PGLOSS_INLINE void pgloss__sincos_small(float t, float *s, float *c)
{
    const float t2 = t * t;
    float ps = -1.0f / 39916800.0f;
    ps = ps * t2 + 1.0f / 362880.0f;
    ps = ps * t2 - 1.0f / 5040.0f;
    ps = ps * t2 + 1.0f / 120.0f;
    ps = ps * t2 - 1.0f / 6.0f;
    ps = ps * t2 + 1.0f;
    float pc = 1.0f / 3628800.0f;
    pc = pc * t2 - 1.0f / 40320.0f;
    pc = pc * t2 + 1.0f / 720.0f;
    pc = pc * t2 - 1.0f / 24.0f;
    pc = pc * t2 + 0.5f;
    *s = ps * t;
    *c = 1.0f - pc * t2;
}

/* sin and cos of 2πu, u in [0, 1): quarter turns are taken exactly from u. */
PGLOSS_INLINE void pgloss__sincos_turn(float u, float *s, float *c)
{
    const float v = 4.0f * u;
    const float k = (float)(int32_t)(v + 0.5f);
    const float t = (v - k) * (0.5f * PGLOSS_PI_F);
    float st, ct;
    pgloss__sincos_small(t, &st, &ct);
    const int32_t q = ((int32_t)k) & 3;
    const float ss = q == 0 ? st : (q == 1 ? ct : (q == 2 ? -st : -ct));
    const float cc = q == 0 ? ct : (q == 1 ? -st : (q == 2 ? -ct : st));
    *s = ss;
    *c = cc;
}

/* 2^-e for the binary exponent e of m > 0 (2^127 for subnormal m, at most 2^-126): an exact
 * scale that brings the largest component of a vector to [1, 2) (or below 4 at the top of the
 * range) without a division, so that the squares neither overflow nor underflow. */
PGLOSS_INLINE float pgloss__pow2_scale(float m)
{
    const int32_t e = (pgloss__float_to_bits(m) >> 23) & 0xff;
    const int32_t s = 254 - e;
    return pgloss__bits_to_float((s < 1 ? 1 : s) << 23);
}

/* Whether x is finite, by its bits (robust under any floating-point flags). */
PGLOSS_INLINE int pgloss__finite_f(float x)
{
    return (pgloss__float_to_bits(x) & 0x7f800000) != 0x7f800000;
}

/* Normalises (x, y, z) in place after an exact power-of-two scaling by the largest component;
 * returns 0 (and leaves zeros) for a zero or non-finite vector. */
PGLOSS_INLINE int pgloss__normalize_f(float *x, float *y, float *z)
{
    const float m = pgloss__maxf(pgloss__absf(*x), pgloss__maxf(pgloss__absf(*y), pgloss__absf(*z)));
    const int finite = pgloss__finite_f(*x) & pgloss__finite_f(*y) & pgloss__finite_f(*z);
    const int ok = finite & (m > 0.0f);
    const float s = pgloss__pow2_scale(ok ? m : 1.0f);
    const float a = *x * s, b = *y * s, c = *z * s;
    const float inv = 1.0f / sqrtf(ok ? a * a + b * b + c * c : 1.0f);
    *x = ok ? a * inv : 0.0f;
    *y = ok ? b * inv : 0.0f;
    *z = ok ? c * inv : 0.0f;
    return ok;
}


#endif
