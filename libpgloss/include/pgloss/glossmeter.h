// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/glossmeter.h — a virtual glossmeter: the instrument readings of a BRDF (specular gloss
 * at 20°, 60° and 85°, reflection haze, Hunter's distinctness-of-image and contrast gloss),
 * the inverse (readings → paint) and the paint trade's named finishes.
 *
 * The measurement equation. A reading integrates the BRDF over the instrument's source and
 * receptor apertures, every ray within them given equal weight (ASTM E179, "All incident rays
 * within the limits of the illuminator aperture angle, and all rays within the receiver aperture
 * angle, should reach the receiver and be given equal weight"). A collimated-beam instrument sends
 * equal flux along every source direction, so the flux into a receptor window W is
 *     Φ(W) = ∫_S dωi ∫_W f(ωi, ωo) cos θo dωo
 * (the 1/cos θi of the illuminated area cancels the cos θi of the irradiance). Specular gloss is
 * 100 Φ(sample)/Φ(standard) through the specular receptor, the standard being polished glass of
 * refractive index 1.567 at 587.6 nm with unpolarised Fresnel reflectance (ISO 2813:2014 §3.3:
 * "ratio multiplied by 100 of the luminous flux reflected from a specimen to that reflected by a
 * glass surface with a refractive index of 1,567 at a wavelength of 587,6 nm in specular
 * direction"). Luminous: f is the luminance Y of the BRDF (Rec. 709 weights, color.h).
 *
 * Windows. Every window is a rectangle in the focal plane of an ideal lens whose axis is the
 * nominal direction (source: towards the light at θ from the normal; receptor: the mirror
 * direction): directions ∝ axis + s·u + t·v, u in the plane of measurement pointing away from the
 * normal, v perpendicular to it. A window of in-plane centre δ, in-plane width w and height h is
 * s ∈ [tan(δ − w/2), tan(δ + w/2)], t ∈ [−tan(h/2), tan(h/2)] (the "angular dimensions" of a
 * glossmeter's field stops). The mirror of source point (s, t) is receptor point (s, −t).
 *
 * Where each number comes from (docs/glossmeter.md lists them all):
 *   θ = 20°, 60°, 85°                   ISO 2813 / ASTM D523 (D523-14 §4.1)
 *   standard n = 1.567 → 100 GU          ISO 2813:2014 §3.3
 *   20° receptor, 1.8° in plane          DIN EN ISO 13803:2014, abstract ("The aperture range of a
 *                                        20° gloss meter is 1,8°")
 *   source 0.75° × 2.5°; 20° receptor height 3.6°; 60° receptor 4.4° × 11.7°; 85° receptor
 *   4.0° × 6.0°                          ASSUMED: the values usually quoted from ASTM D523 Table 1 /
 *                                        ISO 2813 Table 1, not found in any stored public text
 *   haze windows centred 2° either side  Rhopoint Novo-Gloss IQ manual ("the haze component 2°
 *   of the 20° specular                  either side of the specular"); their size 1.0° × 3.6° is
 *                                        ASSUMED
 *   haze = 100 Φ(haze windows)/Φ(standard)   ASTM E430 / ISO 13803 as summarised by Rhopoint:
 *                                        "the ratio of luminous flux in off-specular regions to the
 *                                        flux from a specular gloss reference sample"
 *   haze index = G60 − G20               ASTM D4039 (Rhopoint Novo-Gloss manual: "H = G60 – G20")
 *   DOI at 30°, R0.3 at ±0.3°            ASTM E430 (test methods A and C at 30°), Hunter & Harold
 *                                        1987 p. 286; DOI = 100 (Rs − R0.3)/Rs is Hunter's form
 *                                        as commonly quoted (ASSUMED: not in stored text), R0.3 the
 *                                        mean of the two sides; the DOI source and windows
 *                                        (0.1° × 2.5°, 0.1° × 3.6°) are ASSUMED
 *   contrast gloss                       pgloss's operationalisation of Hunter's definition
 *                                        (paper §2: "perceived relative brightness of specularly
 *                                        and diffusely reflecting areas"): the specular luminance
 *                                        factor in the 60° receptor over the 45°:0° luminance
 *                                        factor; Hunter's own formula was not found (ASSUMED)
 *
 * The paper's Ward lobe (eq. 2) has no Fresnel term and reflects about ρs·cos θ in total for a
 * sharp lobe, so it reads about 100·ρs·cos θ/R_F(θ) GU: low at 60° and almost nothing at 85°
 * (docs/glossmeter.md). The inverse below inverts the readings of the Ward paint (the model
 * pgloss renders), not those of a real paint with Fresnel reflection.
 *
 * Quadrature. Product Gauss–Legendre in the window coordinates, with panels split at the mirror
 * point and graded geometrically from it at the lobe's width (and at the points where the mirror
 * of the source crosses a window's edge); the order rises (6, 10, 16, 24 points a panel) until
 * two successive orders agree within the tolerance, and the difference is returned as the error
 * estimate. An ideal mirror part (a delta lobe) is integrated exactly over the overlap of the
 * source's mirror image with the window. Double, no allocation, no global state.
 */
#ifndef PGLOSS_GLOSSMETER_H
#define PGLOSS_GLOSSMETER_H

#include <stddef.h>
#include "pgloss/brdf.h"
#include "pgloss/bridge.h"
#include "pgloss/perceptual.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Refractive index of the primary standard (ISO 2813:2014 §3.3). */
#define PGLOSS_GLOSS_STANDARD_INDEX 1.567
/* Default relative tolerance of a reading's quadrature when the caller passes tol <= 0. */
#define PGLOSS_GLOSSMETER_TOL 1e-6

/* A field stop's angular dimensions (degrees), see "Windows" above. */
typedef struct pgloss_glossmeter_window {
    double center_deg;   /* in-plane angle of the centre from the nominal axis, + away from the normal */
    double width_deg;    /* full angular width in the plane of measurement */
    double height_deg;   /* full angular width perpendicular to it */
} pgloss_glossmeter_window;

/* One instrument: an angle of incidence, a source, the specular receptor, and up to two
 * off-specular receptors (haze, DOI). */
typedef struct pgloss_glossmeter_geometry {
    double theta_deg;                   /* angle of incidence = nominal angle of reflection */
    pgloss_glossmeter_window source;
    pgloss_glossmeter_window specular;  /* the receptor of specular gloss and of the standard */
    pgloss_glossmeter_window off[2];    /* off-specular receptors; n_off of them are used */
    int n_off;
    double standard_index;              /* refractive index of the primary standard */
} pgloss_glossmeter_geometry;

/* The readings pgloss computes. */
typedef enum pgloss_glossmeter_kind {
    PGLOSS_GLOSS_20 = 0,        /* specular gloss, 20° geometry, GU (ISO 2813 / ASTM D523) */
    PGLOSS_GLOSS_60 = 1,        /* specular gloss, 60° geometry, GU */
    PGLOSS_GLOSS_85 = 2,        /* specular gloss, 85° geometry (sheen), GU */
    PGLOSS_HAZE_20 = 3,         /* reflection haze at 20° (ASTM E430 / ISO 13803 style), HU */
    PGLOSS_HAZE_INDEX = 4,      /* ASTM D4039 haze index G60 − G20, GU */
    PGLOSS_DOI_30 = 5,          /* Hunter's distinctness-of-image gloss at 30° (ASTM E430), 0..100 */
    PGLOSS_CONTRAST_60 = 6,     /* Hunter's contrast gloss as pgloss operationalises it (above) */
    PGLOSS_GLOSSMETER_KINDS = 7
} pgloss_glossmeter_kind;

/* A reading and its quadrature error estimate (same unit). */
typedef struct pgloss_gloss_reading {
    double value;
    double error;
} pgloss_gloss_reading;

/* Every kind at once, indexed by pgloss_glossmeter_kind. */
typedef struct pgloss_glossmeter_readings {
    pgloss_gloss_reading r[PGLOSS_GLOSSMETER_KINDS];
} pgloss_glossmeter_readings;

/*
 * A BRDF as functions, for BRDFs other than pgloss's (the gloss bridge's microfacet targets):
 *   eval(wo, wi, user)  the luminance Y of f(wo, wi) in 1/sr, no cosine; unit directions in the
 *                       local frame (normal +z, both pointing away from the surface); NULL: none
 *   mirror(cos_i, user) the reflectance of an ideal mirror part at incidence cosine cos_i; NULL: none
 *   lobe_width          the slope-space width (radians; Ward's or Beckmann's α) of the narrowest
 *                       lobe, where the quadrature grades its panels; 0: unknown (1e-3 is used,
 *                       which is slower)
 * eval must be finite and >= 0 for unit directions with positive z.
 */
typedef struct pgloss_glossmeter_brdf {
    double (*eval)(const double wo[3], const double wi[3], void *user);
    double (*mirror)(double cos_i, void *user);
    void *user;
    double lobe_width;
} pgloss_glossmeter_brdf;

/* The nominal geometry of a kind (the table above; HAZE_INDEX and CONTRAST_60 give the 60°
 * geometry). Errors: NULL, ARGUMENT (unknown kind; *g is zeroed). */
PGLOSS_API pgloss_status pgloss_glossmeter_geometry_of(pgloss_glossmeter_kind kind,
                                                       pgloss_glossmeter_geometry *g);

/* Unpolarised Fresnel reflectance of a dielectric of index n > 1 at incidence cosine c in [0, 1].
 * Errors: NULL, NONFINITE, ARGUMENT (n <= 1 or c outside [0, 1]; *r = 0). */
PGLOSS_API pgloss_status pgloss_fresnel_dielectric(double n, double c, double *r);

/*
 * Φ(W) of the measurement equation for window `window` of g (0: specular, 1 + k: off[k]), the
 * sample rotated by azimuth_deg about its normal (the angle from the plane of measurement to the
 * BRDF's x axis), to relative tolerance tol (<= 0: PGLOSS_GLOSSMETER_TOL) of the flux the standard
 * sends into the specular window. *flux in sr² (the standard's flux is ~R_F · solid angle of the
 * source); *err the estimate of its error. Errors: NULL, NONFINITE, ARGUMENT (a window or angle
 * outside 0 < θ < 90°, 0 < width, height < 30°, a window reaching the horizon, window index out of
 * range, standard_index <= 1); outputs 0. Warning: PGLOSS_WARN_QUADRATURE (tolerance not reached).
 */
PGLOSS_API pgloss_status pgloss_glossmeter_flux(const pgloss_glossmeter_geometry *g, int window,
                                                const pgloss_glossmeter_brdf *brdf, double azimuth_deg,
                                                double tol, double *flux, double *err);

/* Φ of the primary standard (a mirror of g->standard_index) through the specular window.
 * Errors as pgloss_glossmeter_flux. */
PGLOSS_API pgloss_status pgloss_glossmeter_standard_flux(const pgloss_glossmeter_geometry *g,
                                                         double *flux);

/* One reading of kind `kind` of a BRDF given as functions. Errors as pgloss_glossmeter_flux,
 * plus ARGUMENT for an unknown kind; warning QUADRATURE. */
PGLOSS_API pgloss_status pgloss_glossmeter_read(pgloss_glossmeter_kind kind,
                                                const pgloss_glossmeter_brdf *brdf, double azimuth_deg,
                                                double tol, pgloss_gloss_reading *out);

/* The same on a custom geometry (aperture sensitivity studies); kind selects the formula
 * (GLOSS_*: specular gloss; HAZE_20: haze; DOI_30: DOI; HAZE_INDEX and CONTRAST_60: ARGUMENT). */
PGLOSS_API pgloss_status pgloss_glossmeter_read_geometry(pgloss_glossmeter_kind kind,
                                                         const pgloss_glossmeter_geometry *g,
                                                         const pgloss_glossmeter_brdf *brdf,
                                                         double azimuth_deg, double tol,
                                                         pgloss_gloss_reading *out);

/* One reading of a pgloss paint (any normalisation, anisotropic lobes), evaluated in double from
 * the parameters. Errors: pgloss_check_physical's NULL, NONFINITE, NEGATIVE, ALPHA, NORMALIZATION
 * (energy is not checked), then as pgloss_glossmeter_read. */
PGLOSS_API pgloss_status pgloss_glossmeter_read_physical(pgloss_glossmeter_kind kind,
                                                         const pgloss_physical *p, double azimuth_deg,
                                                         double tol, pgloss_gloss_reading *out);

/* The same for an initialised material (its float constants, as pgloss_eval evaluates them). */
PGLOSS_API pgloss_status pgloss_glossmeter_read_material(pgloss_glossmeter_kind kind,
                                                         const pgloss_material *m, double azimuth_deg,
                                                         double tol, pgloss_gloss_reading *out);

/* Every kind for a paint. Errors as pgloss_glossmeter_read_physical (the first failing kind). */
PGLOSS_API pgloss_status pgloss_glossmeter_readings_physical(const pgloss_physical *p,
                                                             double azimuth_deg, double tol,
                                                             pgloss_glossmeter_readings *out);

/* Every kind for a BRDF given as functions (CONTRAST_60 is 0 where it has no diffuse at 45°:0°).
 * Errors as pgloss_glossmeter_read (the first failing kind; outputs 0). */
PGLOSS_API pgloss_status pgloss_glossmeter_readings_brdf(const pgloss_glossmeter_brdf *brdf, double azimuth_deg,
                                                    double tol, pgloss_glossmeter_readings *out);

/* Every kind for a gloss-bridge target with its parameters: its specular microfacet lobe (GGX or
 * Beckmann, α, F0 and base luminance as pgloss_bridge_model_inputs converts them) with the
 * target's energy compensation, plus its diffuse term as the target defines it
 * (docs/glossmeter.md, "Microfacet targets"); α < 1e-4 reads as an ideal mirror. Errors: those
 * of pgloss_bridge_model_inputs (NULL, ARGUMENT, NONFINITE, NEGATIVE), BRIDGE_BASE (a base
 * channel > 1), BRIDGE_SPECULAR (F0 = 1), BRIDGE_ROUGHNESS (α > 1), then as
 * pgloss_glossmeter_readings_brdf; outputs 0. */
PGLOSS_API pgloss_status pgloss_glossmeter_readings_bridge(pgloss_bridge_target target,
                                                           const pgloss_bridge_params *params,
                                                           double azimuth_deg, double tol,
                                                           pgloss_glossmeter_readings *out);

/* ---- inverse: readings → paint --------------------------------------------------------------- */

/* Which second reading accompanies the 60° gloss. */
typedef enum pgloss_gloss_second {
    PGLOSS_SECOND_NONE = 0,   /* 60° gloss alone: d is the caller's (or PGLOSS_ASSUMED_DOI_GLOSS) */
    PGLOSS_SECOND_GLOSS_20 = 1,
    PGLOSS_SECOND_HAZE_20 = 2,
    PGLOSS_SECOND_DOI_30 = 3
} pgloss_gloss_second;

/* The d assumed when only the 60° gloss is known: α = 0.07, the middle of the paper's stimuli,
 * which "span" the range of measured glossy paints Ward gives (§3.2.3.1: α = 0.04, 0.07, 0.10). */
#define PGLOSS_ASSUMED_DOI_GLOSS 0.93
/* The α range the inverse searches: [PGLOSS_INVERSE_ALPHA_MIN, PGLOSS_INVERSE_ALPHA_MAX]. */
#define PGLOSS_INVERSE_ALPHA_MIN 0.002
#define PGLOSS_INVERSE_ALPHA_MAX 0.5

/*
 * The isotropic paint of the pgloss model — eq. 2 with the given normalisation, ρd from the
 * CIELAB colour (L*, a*, b*) as pgloss_physical_from_perceptual — whose virtual readings are
 * gloss_60 and, per `second`, the second value (d_or_second: the 20° gloss, the haze, the DOI;
 * with PGLOSS_SECOND_NONE it is d itself, and a value outside (0, 1) means
 * PGLOSS_ASSUMED_DOI_GLOSS). The readings are luminous, so ρs follows from the luminance Y.
 * Returns q (c, d; L, a, b as given) and p. Errors: NULL, NONFINITE, LIGHTNESS, GAMUT,
 * NORMALIZATION, ARGUMENT (unknown `second`, negative readings), NO_FIT (no paint of the model
 * gives these readings: gloss_60 at or below the diffuse's own reading, or the pair outside what
 * α in [PGLOSS_INVERSE_ALPHA_MIN, PGLOSS_INVERSE_ALPHA_MAX] reaches; q and p then hold the paint
 * nearest in the second reading, so a caller can show how far out it is), ENVELOPE (ρd + ρs > 1:
 * values still written); warning ALPHA_UNTRUSTED (α > 0.2).
 */
PGLOSS_API pgloss_status pgloss_paint_from_gloss_units(double L, double a, double b,
                                                       pgloss_normalization normalization,
                                                       double gloss_60, pgloss_gloss_second second,
                                                       double d_or_second, pgloss_perceptual *q,
                                                       pgloss_physical *p);

/* ---- named finishes -------------------------------------------------------------------------- */

/* A finish of the paint trade and its gloss-unit ranges (NAN: no bound given). */
typedef struct pgloss_finish {
    const char *name;        /* "flat", "velvet", "eggshell", "satin", "semi-gloss", "gloss", "high-gloss" */
    const char *level;       /* "MPI G1" ... "MPI G7" */
    double gloss_60_min, gloss_60_max;   /* 60° gloss, GU */
    double sheen_85_min, sheen_85_max;   /* 85° gloss, GU */
    const char *source;      /* where the numbers were found */
} pgloss_finish;

/* The MPI gloss levels G1–G7 (Master Painters Institute, paintinfo.com/mpi/approved/sheen.shtml):
 * index 0..6. Returns NULL for other indices. G7's open upper bound is capped at 100 GU (the
 * primary standard) where a range is needed. */
PGLOSS_API const pgloss_finish *pgloss_finish_at(size_t index);

/* The finish of that name (or level "G4", "mpi-g4"; case-insensitive); NULL if none. */
PGLOSS_API const pgloss_finish *pgloss_finish_find(const char *name);

/*
 * A representative paint of a finish at a colour, and the (c, d) it spans: the paint whose 60°
 * gloss is the middle of the finish's 60° range, with d = PGLOSS_ASSUMED_DOI_GLOSS; the span is
 * c over the 60° range and d over [0.90, 0.96] (α from 0.10 to 0.04, the paper's stimulus range).
 * The 85° ranges are not used: a Ward paint reads almost nothing at 85° (above), and *sheen_ok
 * (may be NULL) says whether the representative paint meets the finish's 85° range.
 * Errors: NULL, ARGUMENT (f NULL), and those of pgloss_paint_from_gloss_units.
 */
PGLOSS_API pgloss_status pgloss_finish_paint(const pgloss_finish *f, double L, double a, double b,
                                             pgloss_normalization normalization,
                                             pgloss_perceptual *q, pgloss_physical *p,
                                             double c_range[2], double d_range[2], int *sheen_ok);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_GLOSSMETER_H */
