/*
 * pgloss/batch.h — batched entry points over structure-of-arrays inputs.
 *
 * Same semantics as the scalar functions of pgloss/brdf.h (normalisation of inputs,
 * one-sided BRDF, rejected samples, lobe masks), element by element, in float
 * arithmetic written so that the compiler vectorises the loops (no branches in the
 * loop bodies, restrict-qualified arrays, an inlined float exp). They agree with the
 * scalar reference within a few float ulps times the conditioning of exp (tests assert it).
 *
 * Arrays may be any alignment. Input and output arrays must not overlap.
 * The status is PGLOSS_OK if every element was valid, else the error of the first
 * invalid element (PGLOSS_ERR_DIRECTION, PGLOSS_ERR_RANDOM); invalid elements get 0
 * outputs and the others are computed normally.
 */
#ifndef PGLOSS_BATCH_H
#define PGLOSS_BATCH_H

#include <stddef.h>
#include "pgloss/brdf.h"

#ifdef __cplusplus
extern "C" {
#endif

/* n directions as three arrays (read-only). */
typedef struct pgloss_vec3_array { const float *x, *y, *z; } pgloss_vec3_array;
/* n directions as three arrays (written). */
typedef struct pgloss_vec3_out { float *x, *y, *z; } pgloss_vec3_out;
/* n RGB values as three arrays (written). */
typedef struct pgloss_rgb_out { float *r, *g, *b; } pgloss_rgb_out;

pgloss_status pgloss_eval_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                pgloss_vec3_array wo, pgloss_vec3_array wi, pgloss_rgb_out f);

pgloss_status pgloss_pdf_batch(const pgloss_material *m, unsigned lobes, size_t n,
                               pgloss_vec3_array wo, pgloss_vec3_array wi, float *pdf);

pgloss_status pgloss_eval_pdf_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                    pgloss_vec3_array wo, pgloss_vec3_array wi,
                                    pgloss_rgb_out f, float *pdf);

/* u0, u1, u2: the three random numbers of pgloss_sample, one array each.
 * lobe may be NULL; otherwise it receives the pgloss_lobe chosen per element. */
pgloss_status pgloss_sample_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                  pgloss_vec3_array wo, const float *u0, const float *u1,
                                  const float *u2, pgloss_vec3_out wi, float *pdf,
                                  pgloss_rgb_out weight, unsigned char *lobe);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_BATCH_H */
