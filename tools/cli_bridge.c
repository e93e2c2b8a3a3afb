// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* `pgloss bridge`: a paint → a target renderer's parameters as JSON, and back (pgloss/bridge.h,
 * docs/bridge.md). The JSON keys are each target's own parameter names. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pgloss/pgloss.h"

int pgloss_cli_bridge(int argc, char **argv);

/* The target's names for base colour, roughness, IOR, specular, and its fixed inputs. */
typedef struct {
    const char *base, *rough, *ior, *spec, *fixed;
    int base4; /* glTF's baseColorFactor has an alpha */
} names;
static names target_names(pgloss_bridge_target t)
{
    switch (t) {
    case PGLOSS_BRIDGE_OPENPBR:
        return (names){"base_color", "specular_roughness", "specular_ior", "specular_weight", "\"base_weight\": 1", 0};
    case PGLOSS_BRIDGE_STANDARD_SURFACE:
        return (names){"base_color", "specular_roughness", "specular_IOR", "specular", "\"base\": 1", 0};
    case PGLOSS_BRIDGE_GLTF:
    case PGLOSS_BRIDGE_GLTF_CORE:
        return (names){"baseColorFactor", "roughnessFactor", "ior", "specularFactor", "\"metallicFactor\": 0", 1};
    case PGLOSS_BRIDGE_PRINCIPLED:
        return (names){"Base Color", "Roughness", "IOR", "Specular IOR Level", "\"Metallic\": 0", 0};
    case PGLOSS_BRIDGE_ROUGHPLASTIC_GGX:
        return (names){"diffuse_reflectance", "alpha", "int_ior", NULL,
                       "\"distribution\": \"ggx\", \"ext_ior\": 1.000277, \"nonlinear\": false", 0};
    default:
        return (names){"diffuse_reflectance", "alpha", "int_ior", NULL,
                       "\"distribution\": \"beckmann\", \"ext_ior\": 1.000277, \"nonlinear\": false", 0};
    }
}

static void print_json(pgloss_bridge_target t, pgloss_status st, const pgloss_bridge_params *p,
                       const pgloss_perceptual *q, const double *residual)
{
    const names n = target_names(t);
    printf("{\n  \"target\": \"%s\",\n  \"status\": \"%s\",\n  \"reason\": \"%s\",\n", pgloss_bridge_target_name(t),
           st == PGLOSS_OK ? "ok" : pgloss_status_name(st), pgloss_status_string(st));
    printf("  \"parameters\": {\"%s\": [%.9g, %.9g, %.9g%s], \"%s\": %.9g, \"%s\": %.9g", n.base, p->base_color[0],
           p->base_color[1], p->base_color[2], n.base4 ? ", 1" : "", n.rough, p->roughness, n.ior, p->ior);
    if (n.spec)
        printf(", \"%s\": %.9g", n.spec, p->specular);
    printf(", %s},\n", n.fixed);
    printf("  \"paint\": {\"L\": %.9g, \"a\": %.9g, \"b\": %.9g, \"c\": %.9g, \"d\": %.9g}", q->L, q->a, q->b, q->c,
           q->d);
    if (residual)
        printf(",\n  \"residual\": %.6g", *residual);
    printf("\n}\n");
}

static int parse(const char *s, const char *name, double *out)
{
    char *end = NULL;
    errno = 0;
    *out = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE) {
        fprintf(stderr, "pgloss bridge: %s: '%s' is not a number\n", name, s);
        return 0;
    }
    return 1;
}

/* The value after "key": in text: a number, or the first n numbers of an array. */
static int json_find(const char *text, const char *key, double *v, int n)
{
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\"", key);
    const char *p = strstr(text, pat);
    if (!p)
        return 0;
    p += strlen(pat);
    while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r' || *p == ':') ++p;
    const int array = *p == '[';
    if (array) ++p;
    for (int k = 0; k < (array ? n : 1); ++k) {
        while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r' || *p == ',') ++p;
        char *end;
        v[k] = strtod(p, &end);
        if (end == p)
            return -1;
        p = end;
    }
    if (!array && n == 3)
        v[1] = v[2] = v[0];
    return 1;
}

static int from_file(pgloss_bridge_target t, const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "pgloss bridge: %s: %s\n", path, strerror(errno));
        return 2;
    }
    static char text[1 << 16];
    const size_t len = fread(text, 1, sizeof text - 1, f);
    const int too_long = !feof(f);
    fclose(f);
    text[len] = 0;
    if (too_long) {
        fprintf(stderr, "pgloss bridge: %s: larger than 64 KiB\n", path);
        return 2;
    }
    const names n = target_names(t);
    const char *params = strstr(text, "\"parameters\"");
    const char *body = params ? params : text;
    pgloss_bridge_params p = {{0, 0, 0}, 0, 0, 1};
    /* Defaults where a key is absent: each target's own default. */
    p.ior = (t == PGLOSS_BRIDGE_ROUGHPLASTIC_GGX || t == PGLOSS_BRIDGE_ROUGHPLASTIC_BECKMANN) ? 1.49 : 1.5;
    p.specular = t == PGLOSS_BRIDGE_PRINCIPLED ? 0.5 : 1;
    if (json_find(body, n.base, p.base_color, 3) != 1 || json_find(body, n.rough, &p.roughness, 1) != 1) {
        fprintf(stderr, "pgloss bridge: %s: needs \"%s\" and \"%s\" for %s\n", path, n.base, n.rough,
                pgloss_bridge_target_name(t));
        return 2;
    }
    if (json_find(body, n.ior, &p.ior, 1) < 0 || (n.spec && json_find(body, n.spec, &p.specular, 1) < 0)) {
        fprintf(stderr, "pgloss bridge: %s: \"%s\" or \"%s\" is not a number\n", path, n.ior, n.spec ? n.spec : "");
        return 2;
    }
    pgloss_perceptual q;
    double residual;
    const pgloss_status st = pgloss_bridge_to_perceptual(t, &p, &q, &residual);
    print_json(t, st, &p, &q, &residual);
    return st < 0 ? 1 : 0;
}

int pgloss_cli_bridge(int argc, char **argv)
{
    pgloss_bridge_target t;
    if (argc == 3 && !strcmp(argv[0], "--from")) {
        if (pgloss_bridge_target_from_name(argv[1], &t) != PGLOSS_OK) {
            fprintf(stderr, "pgloss bridge: unknown target '%s'\n", argv[1]);
            return 2;
        }
        return from_file(t, argv[2]);
    }
    if (argc != 6)
        return 2;
    if (pgloss_bridge_target_from_name(argv[0], &t) != PGLOSS_OK) {
        fprintf(stderr, "pgloss bridge: unknown target '%s' (openpbr, standard_surface, gltf, gltf_core, "
                        "principled, roughplastic_ggx, roughplastic_beckmann)\n", argv[0]);
        return 2;
    }
    static const char *const nm[] = {"L", "a", "b", "c", "d"};
    double v[5];
    for (int k = 0; k < 5; ++k)
        if (!parse(argv[1 + k], nm[k], &v[k]))
            return 2;
    const pgloss_perceptual q = {v[0], v[1], v[2], v[3], v[4]};
    pgloss_bridge_params p;
    pgloss_perceptual reached;
    const pgloss_status st = pgloss_bridge_from_perceptual(t, &q, &p, &reached);
    if (st < 0 && st != PGLOSS_ERR_BRIDGE_BASE && st != PGLOSS_ERR_BRIDGE_SPECULAR && st != PGLOSS_ERR_BRIDGE_ROUGHNESS) {
        printf("{\"target\": \"%s\", \"status\": \"%s\", \"reason\": \"%s\"}\n", pgloss_bridge_target_name(t),
               pgloss_status_name(st), pgloss_status_string(st));
        return 1;
    }
    print_json(t, st, &p, &reached, NULL);
    return st < 0 ? 1 : 0;
}
