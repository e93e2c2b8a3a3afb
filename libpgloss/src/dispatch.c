// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The one dispatcher of the batched paths: which instruction sets this build and the running
 * CPU have, and the table of loops of each (batch_isa.c, batch_d_isa.c,
 * perceptual_batch_isa.c, compiled once per ISA: libpgloss/CMakeLists.txt). */
#include "batch_internal.h"

#if (defined(PGLOSS_HAVE_AVX2) || defined(PGLOSS_HAVE_AVX512)) && \
    (defined(__GNUC__) || defined(__clang__))
/* __builtin_cpu_supports reads the CPU model that libgcc fills in at start-up: a load and
 * a test, cheap enough to do on every call, and no state of ours. */
#define PGLOSS_CPU(feature) __builtin_cpu_supports(feature)
#else
#define PGLOSS_CPU(feature) 0
#endif

int pgloss_isa_supported(pgloss_isa isa)
{
    switch (isa) {
    case PGLOSS_ISA_AUTO:
    case PGLOSS_ISA_BASELINE: return 1;
#if defined(PGLOSS_HAVE_AVX2)
    case PGLOSS_ISA_AVX2: return PGLOSS_CPU("avx2") && PGLOSS_CPU("fma");
#endif
#if defined(PGLOSS_HAVE_AVX512)
    case PGLOSS_ISA_AVX512:
        return PGLOSS_CPU("avx512f") && PGLOSS_CPU("avx512vl") && PGLOSS_CPU("avx512dq") &&
               PGLOSS_CPU("avx512bw");
#endif
    default: return 0;
    }
}

pgloss_isa pgloss_isa_best(void)
{
    if (pgloss_isa_supported(PGLOSS_ISA_AVX512))
        return PGLOSS_ISA_AVX512;
    if (pgloss_isa_supported(PGLOSS_ISA_AVX2))
        return PGLOSS_ISA_AVX2;
    return PGLOSS_ISA_BASELINE;
}

const char *pgloss_isa_name(pgloss_isa isa)
{
    switch (isa) {
    case PGLOSS_ISA_AUTO: return "auto";
    case PGLOSS_ISA_BASELINE: return "baseline";
    case PGLOSS_ISA_AVX2: return "avx2";
    case PGLOSS_ISA_AVX512: return "avx512";
    default: return "unknown";
    }
}

/* The loops of one ISA: their declarations, and its table. */
#define PERCEPTUAL_DECL(name)                                                                      \
    void PGLOSS__CAT(pgloss__##name##_loop_, ISA)(size_t, const double *const *, double *const *, \
                                                  const pgloss__pargs *, signed char *);
#define PERCEPTUAL_ENTRY(name) PGLOSS__CAT(pgloss__##name##_loop_, ISA),
#define PGLOSS__CAT_(a, b) a##b
#define PGLOSS__CAT(a, b) PGLOSS__CAT_(a, b)
#define DECLARE_TIER(isa, tier)                                                                    \
    size_t pgloss__eval_pdf_##isa##_##tier(const pgloss__call_f *, size_t, pgloss__vec3_f,       \
                                           pgloss__vec3_f, pgloss__rgb_out_f, float *);          \
    size_t pgloss__sample_##isa##_##tier(const pgloss__call_f *, size_t, pgloss__vec3_f,         \
                                         const float *, const float *, const float *,            \
                                         pgloss__vec3_out_f, float *, pgloss__rgb_out_f,         \
                                         unsigned char *);
#define DECLARE_LOOPS(isa)                                                                         \
    DECLARE_TIER(isa, float)                                                                       \
    DECLARE_TIER(isa, fast)                                                                        \
    size_t pgloss__eval_pdf_batch_d_##isa(const struct pgloss__consts_d *,                       \
                                          const pgloss__materials_d *, unsigned, int, size_t,    \
                                          pgloss__vec3_d, pgloss__vec3_d, pgloss__rgb_out_d,     \
                                          double *);                                             \
    size_t pgloss__sample_batch_d_##isa(const struct pgloss__consts_d *,                           \
                                      const pgloss__materials_d *, unsigned, int, size_t,        \
                                      pgloss__vec3_d, const double *, const double *,            \
                                      const double *, pgloss__vec3_out_d, double *,              \
                                      pgloss__rgb_out_d, unsigned char *);                         \
    void pgloss__rows_in_##isa##_f(const void *, size_t, float *, float *, float *);               \
    void pgloss__rows_out_##isa##_f(const float *, const float *, const float *, size_t, void *);
#define TABLE(isa)                                                                                 \
    {{pgloss__eval_pdf_##isa##_float, pgloss__eval_pdf_##isa##_fast},                              \
     {pgloss__sample_##isa##_float, pgloss__sample_##isa##_fast},                                  \
     pgloss__eval_pdf_batch_d_##isa,                                                               \
     pgloss__sample_batch_d_##isa,                                                                 \
     pgloss__rows_in_##isa##_f,                                                                    \
     pgloss__rows_out_##isa##_f,                                                                   \
     PGLOSS__PERCEPTUAL_LOOPS(PERCEPTUAL_ENTRY)}
#define ISA baseline
DECLARE_LOOPS(baseline)
PGLOSS__PERCEPTUAL_LOOPS(PERCEPTUAL_DECL)
static const pgloss__loops loops_baseline = TABLE(baseline);
#undef ISA
#if defined(PGLOSS_HAVE_AVX2)
#define ISA avx2
DECLARE_LOOPS(avx2)
PGLOSS__PERCEPTUAL_LOOPS(PERCEPTUAL_DECL)
static const pgloss__loops loops_avx2 = TABLE(avx2);
#undef ISA
#endif
#if defined(PGLOSS_HAVE_AVX512)
#define ISA avx512
DECLARE_LOOPS(avx512)
PGLOSS__PERCEPTUAL_LOOPS(PERCEPTUAL_DECL)
static const pgloss__loops loops_avx512 = TABLE(avx512);
#undef ISA
#endif

const pgloss__loops *pgloss__dispatch(const pgloss_batch_options *opt,
                                      pgloss_batch_options *opt_out)
{
    static const pgloss_batch_options defaults = {PGLOSS_PRECISION_FLOAT, PGLOSS_ISA_AUTO,
                                                  PGLOSS_FLOAT32};
    pgloss_batch_options o = opt ? *opt : defaults;
    if (o.precision != PGLOSS_PRECISION_FLOAT && o.precision != PGLOSS_PRECISION_FAST &&
        o.precision != PGLOSS_PRECISION_REFERENCE)
        return NULL;
    if (o.scalar != PGLOSS_FLOAT32 && o.scalar != PGLOSS_FLOAT64)
        return NULL;
    if (!pgloss_isa_supported(o.isa))
        return NULL;
    if (o.isa == PGLOSS_ISA_AUTO)
        o.isa = pgloss_isa_best();
    if (opt_out)
        *opt_out = o;
    switch (o.isa) {
#if defined(PGLOSS_HAVE_AVX512)
    case PGLOSS_ISA_AVX512: return &loops_avx512;
#endif
#if defined(PGLOSS_HAVE_AVX2)
    case PGLOSS_ISA_AVX2: return &loops_avx2;
#endif
    default: return &loops_baseline;
    }
}
