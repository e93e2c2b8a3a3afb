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
 * 5 sizeof(pgloss_perceptual), 6 sizeof(pgloss_status), 7 sizeof(pgloss_bridge_params),
 * 8 offsetof roughness, 9 ior, 10 specular, 11 sizeof(pgloss_glossmeter_readings),
 * 12 sizeof(pgloss_finish), 13 offsetof level, 14 gloss_60_min, 15 source,
 * 16 sizeof(pgloss_bridge_shading), 17 offsetof alpha, 18 base_color, 19 diffuse_scale,
 * 20 specular_factor, 21 diffuse_factor; anything else: 0. */
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
    case 7: return sizeof(pgloss_bridge_params);
    case 8: return offsetof(pgloss_bridge_params, roughness);
    case 9: return offsetof(pgloss_bridge_params, ior);
    case 10: return offsetof(pgloss_bridge_params, specular);
    case 11: return sizeof(pgloss_glossmeter_readings);
    case 12: return sizeof(pgloss_finish);
    case 13: return offsetof(pgloss_finish, level);
    case 14: return offsetof(pgloss_finish, gloss_60_min);
    case 15: return offsetof(pgloss_finish, source);
    case 16: return sizeof(pgloss_bridge_shading);
    case 17: return offsetof(pgloss_bridge_shading, alpha);
    case 18: return offsetof(pgloss_bridge_shading, base_color);
    case 19: return offsetof(pgloss_bridge_shading, diffuse_scale);
    case 20: return offsetof(pgloss_bridge_shading, specular_factor);
    case 21: return offsetof(pgloss_bridge_shading, diffuse_factor);
    default: return 0;
    }
}
