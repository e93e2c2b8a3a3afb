// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * layout.c — the struct layout of the public API as this wasm32 build sees it, so that the
 * JS loader (web/picker/pgloss-wasm.js) can refuse a module whose structs it would misread
 * instead of silently marshalling garbage.
 */
#include <stddef.h>
#include <pgloss/pgloss.h>

/* what: 0 sizeof(pgloss_physical), 1 offsetof rho_s, 2 alpha_x, 3 alpha_y, 4 normalization,
 * 5 sizeof(pgloss_perceptual), 6 sizeof(pgloss_status); anything else: 0. */
size_t pgloss_wasm_layout(int what);

size_t pgloss_wasm_layout(int what) {
    switch (what) {
    case 0: return sizeof(pgloss_physical);
    case 1: return offsetof(pgloss_physical, rho_s);
    case 2: return offsetof(pgloss_physical, alpha_x);
    case 3: return offsetof(pgloss_physical, alpha_y);
    case 4: return offsetof(pgloss_physical, normalization);
    case 5: return sizeof(pgloss_perceptual);
    case 6: return sizeof(pgloss_status);
    default: return 0;
    }
}
