// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * Quick start: one of the paper's paints (Fig. 4's grey, ρd 0.193, ρs 0.033, α 0.07) from
 * physical parameters to the perceptual ones (L*, c, d: eqs. 3, 4) and back (eqs. 6–8).
 * Built and run by scripts/docs.sh; its output must equal quickstart.out.
 */
#include <assert.h>
#include <math.h>
#include <stdio.h>

#include <pgloss/pgloss.h>

int main(void)
{
    const double rho_d = 0.193, rho_s = 0.033, alpha = 0.07;

    /* physical → perceptual: L* of ρd, c = ∛(ρs + ρd/2) − ∛(ρd/2), d = 1 − α */
    double L, c, d;
    pgloss_status st = pgloss_gloss_from_physical(rho_d, rho_s, alpha, &L, &c, &d);
    assert(st == PGLOSS_OK);
    assert(fabs(d - 0.93) < 1e-15);
    assert(c > 0.047 && c < 0.048);

    /* perceptual → physical: ρd = f⁻¹(L), ρs = (c + ∛(ρd/2))³ − ρd/2, α = 1 − d */
    double rho_d2, rho_s2, alpha2;
    st = pgloss_physical_from_gloss(L, c, d, &rho_d2, &rho_s2, &alpha2);
    assert(st == PGLOSS_OK);
    assert(fabs(rho_d2 - rho_d) < 1e-12 && fabs(rho_s2 - rho_s) < 1e-12 && fabs(alpha2 - alpha) < 1e-12);

    /* outside the range the paper trusts (α > 0.2): a warning, the values still computed */
    st = pgloss_gloss_from_physical(rho_d, rho_s, 0.3, &L, &c, &d);
    assert(st == PGLOSS_WARN_ALPHA_UNTRUSTED && st > 0);

    /* an error: a negative reflectance is rejected, and the outputs are 0 */
    st = pgloss_gloss_from_physical(-0.1, rho_s, alpha, &L, &c, &d);
    assert(st == PGLOSS_ERR_NEGATIVE && L == 0.0 && c == 0.0 && d == 0.0);

    st = pgloss_gloss_from_physical(rho_d, rho_s, alpha, &L, &c, &d);
    assert(st == PGLOSS_OK);
    printf("rho_d %.3f rho_s %.3f alpha %.2f -> L* %.2f c %.4f d %.2f -> rho_d %.3f rho_s %.3f alpha %.2f (%s)\n",
           rho_d, rho_s, alpha, L, c, d, rho_d2, rho_s2, alpha2, pgloss_status_name(st));
    return 0;
}
