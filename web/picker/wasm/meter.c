// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * meter.c — the glossmeter calls whose arguments JS cannot build without function pointers or
 * a geometry struct: the readings of an ideal Fresnel mirror and of a Lambertian diffuser (the
 * shared vectors' glossmeter_read_fresnel / glossmeter_read_lambert) and the primary standard's
 * flux of a kind's geometry. The BRDFs are the closed forms the vectors' generator uses.
 */
#include <pgloss/pgloss.h>

pgloss_status pgloss_wasm_read_fresnel(int kind, double n, double tol, pgloss_gloss_reading *out);
pgloss_status pgloss_wasm_read_lambert(int kind, double rho, double tol, pgloss_gloss_reading *out);
pgloss_status pgloss_wasm_standard_flux(int kind, double *flux);

static double fresnel_mirror(double cos_i, void *user) {
    double r = 0.0;
    (void)pgloss_fresnel_dielectric(*(const double *)user, cos_i, &r);
    return r;
}

/* A perfect diffuser: f = ρ/π (no cosine; the measurement equation applies it). */
static double lambert(const double wo[3], const double wi[3], void *user) {
    (void)wo;
    (void)wi;
    return *(const double *)user * 0.31830988618379067154;
}

pgloss_status pgloss_wasm_read_fresnel(int kind, double n, double tol, pgloss_gloss_reading *out) {
    const pgloss_glossmeter_brdf b = {NULL, fresnel_mirror, &n, 0.0};
    return pgloss_glossmeter_read((pgloss_glossmeter_kind)kind, &b, 0.0, tol, out);
}

pgloss_status pgloss_wasm_read_lambert(int kind, double rho, double tol, pgloss_gloss_reading *out) {
    const pgloss_glossmeter_brdf b = {lambert, NULL, &rho, 1.0};
    return pgloss_glossmeter_read((pgloss_glossmeter_kind)kind, &b, 0.0, tol, out);
}

pgloss_status pgloss_wasm_standard_flux(int kind, double *flux) {
    pgloss_glossmeter_geometry g;
    const pgloss_status st = pgloss_glossmeter_geometry_of((pgloss_glossmeter_kind)kind, &g);
    if (st != PGLOSS_OK) {
        if (flux) *flux = 0.0;
        return st;
    }
    return pgloss_glossmeter_standard_flux(&g, flux);
}
