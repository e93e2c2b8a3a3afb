// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* `pgloss bridge`: a paint -> a target renderer's parameters, and a material's parameters -> its
 * paint (pgloss/bridge.h, docs/bridge.md). The output is one JSON object whose keys are the
 * target's own parameter names, with the core's verdict in its "status" and "reason" (there is
 * no status line, so that the output stays JSON); the exit code is the tool's. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "cli_common.h"

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

static void print_json(FILE *out, pgloss_bridge_target t, pgloss_status st, const pgloss_bridge_params *p,
                       const pgloss_perceptual *q, const double *residual)
{
    const names n = target_names(t);
    fprintf(out, "{\n  \"target\": \"%s\",\n  \"status\": \"%s\",\n  \"reason\": \"%s\",\n",
            pgloss_bridge_target_name(t), st == PGLOSS_OK ? "ok" : pgloss_status_name(st), pgloss_status_string(st));
    fprintf(out, "  \"parameters\": {\"%s\": [%.9g, %.9g, %.9g%s], \"%s\": %.9g, \"%s\": %.9g", n.base,
            p->base_color[0], p->base_color[1], p->base_color[2], n.base4 ? ", 1" : "", n.rough, p->roughness, n.ior,
            p->ior);
    if (n.spec)
        fprintf(out, ", \"%s\": %.9g", n.spec, p->specular);
    fprintf(out, ", %s},\n", n.fixed);
    fprintf(out, "  \"paint\": {\"L\": %.9g, \"a\": %.9g, \"b\": %.9g, \"c\": %.9g, \"d\": %.9g}", q->L, q->a, q->b,
            q->c, q->d);
    if (residual)
        fprintf(out, ",\n  \"residual\": %.6g", *residual);
    fputs("\n}\n", out);
}

/* The target named `text`; 0 after the reason (naming every target) and the usage line. */
int pgloss_cli_bridge_target(pgloss_cli *cli, const char *text, pgloss_bridge_target *t)
{
    char q[PGLOSS_CLI_QUOTE_SIZE], all[256] = "";
    if (pgloss_bridge_target_from_name(text, t) == PGLOSS_OK)
        return 1;
    for (int k = 0; k < PGLOSS_BRIDGE_TARGET_COUNT; ++k) {
        const size_t used = strlen(all);
        snprintf(all + used, sizeof all - used, "%s%s", k ? ", " : "",
                 pgloss_bridge_target_name((pgloss_bridge_target)k));
    }
    pgloss_cli_usage_error(cli, "TARGET: %s is not one of %s", pgloss_cli_quote(text, q), all);
    return 0;
}

static int is_space(char ch) { return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r'; }

/* The value of "key" in the JSON text, read with the tool's grammar of numbers: a number, or the
 * first n numbers of an array (a number where 3 are wanted is a grey). Returns 1; 0 when the key
 * is absent; -1 after the reason (naming the file and the key) and the usage line. */
static int json_find(pgloss_cli *cli, const char *file, const char *text, const char *key, double *v, int n)
{
    char pat[64], name[PGLOSS_CLI_QUOTE_SIZE + 96], token[512];
    snprintf(pat, sizeof pat, "\"%s\"", key);
    const char *p = strstr(text, pat);
    if (!p)
        return 0;
    p += strlen(pat);
    while (is_space(*p))
        ++p;
    if (*p == ':')
        ++p;
    while (is_space(*p))
        ++p;
    const int array = *p == '[';
    p += array;
    for (int k = 0; k < (array ? n : 1); ++k) {
        while (is_space(*p) || (k && *p == ','))
            ++p;
        size_t len = strcspn(p, ",]} \t\r\n");
        if (len >= sizeof token)
            len = sizeof token - 1; /* still not a number: the grammar has no room for it */
        memcpy(token, p, len);
        token[len] = '\0';
        p += len;
        if (array)
            snprintf(name, sizeof name, "FILE.json: %s: \"%s\"[%d]", file, key, k);
        else
            snprintf(name, sizeof name, "FILE.json: %s: \"%s\"", file, key);
        if (!pgloss_cli_number(cli, name, token, &v[k]))
            return -1;
    }
    if (!array && n == 3)
        v[1] = v[2] = v[0];
    return 1;
}

enum { MAX_JSON = 1 << 16 };

int pgloss_cli_bridge_params_file(pgloss_cli *cli, pgloss_bridge_target t, const char *path,
                                  pgloss_bridge_params *p)
{
    char file[PGLOSS_CLI_QUOTE_SIZE];
    pgloss_cli_quote(path, file);
    FILE *f = fopen(path, "rb");
    if (!f)
        return pgloss_cli_usage_error(cli, "FILE.json: %s: %s", file, strerror(errno));
    char *text = malloc(MAX_JSON);
    if (!text) {
        fclose(f);
        return pgloss_cli_usage_error(cli, "FILE.json: %s: out of memory", file);
    }
    const size_t len = fread(text, 1, MAX_JSON - 1, f);
    const int failed = ferror(f), too_long = !failed && !feof(f);
    fclose(f);
    text[len] = '\0';
    int rc = PGLOSS_CLI_USAGE;
    const names n = target_names(t);
    const char *params = strstr(text, "\"parameters\"");
    const char *body = params ? params : text;
    *p = (pgloss_bridge_params){{0, 0, 0}, 0, 0, 1};
    /* Where a key is absent: the target's own default. */
    p->ior = (t == PGLOSS_BRIDGE_ROUGHPLASTIC_GGX || t == PGLOSS_BRIDGE_ROUGHPLASTIC_BECKMANN) ? 1.49 : 1.5;
    p->specular = t == PGLOSS_BRIDGE_PRINCIPLED ? 0.5 : 1;
    int base = 0, rough = 0, ior = 0, spec = 0;
    if (failed)
        pgloss_cli_usage_error(cli, "FILE.json: %s: cannot be read", file);
    else if (too_long)
        pgloss_cli_usage_error(cli, "FILE.json: %s: larger than 64 KiB", file);
    else if ((base = json_find(cli, file, body, n.base, p->base_color, 3)) < 0 ||
             (rough = json_find(cli, file, body, n.rough, &p->roughness, 1)) < 0 ||
             (ior = json_find(cli, file, body, n.ior, &p->ior, 1)) < 0 ||
             (n.spec && (spec = json_find(cli, file, body, n.spec, &p->specular, 1)) < 0)) {
        /* the reason is printed */
    } else if (!base || !rough) {
        pgloss_cli_usage_error(cli, "FILE.json: %s: needs \"%s\" and \"%s\" for %s", file, n.base, n.rough,
                               pgloss_bridge_target_name(t));
    } else {
        rc = PGLOSS_CLI_OK;
    }
    free(text);
    return rc;
}

static int from_file(pgloss_cli *cli, pgloss_bridge_target t, const char *path)
{
    pgloss_bridge_params p;
    const int rc = pgloss_cli_bridge_params_file(cli, t, path, &p);
    if (rc != PGLOSS_CLI_OK)
        return rc;
    pgloss_perceptual q;
    double residual;
    const pgloss_status st = pgloss_bridge_to_perceptual(t, &p, &q, &residual);
    print_json(cli->out, t, st, &p, &q, &residual);
    return st < 0 ? PGLOSS_CLI_ERROR : PGLOSS_CLI_OK;
}

static int bridge(pgloss_cli *cli, int argc, char **argv)
{
    pgloss_bridge_target t;
    if (argc >= 1 && !strcmp(argv[0], "--from")) {
        if (argc != 3)
            return pgloss_cli_usage_error(cli, "--from takes TARGET FILE.json, got %d argument%s", argc - 1,
                                          argc == 2 ? "" : "s");
        if (!pgloss_cli_bridge_target(cli, argv[1], &t))
            return PGLOSS_CLI_USAGE;
        return from_file(cli, t, argv[2]);
    }
    if (argc != 6)
        return pgloss_cli_usage_error(cli, "expected 6 arguments, got %d", argc);
    if (!pgloss_cli_bridge_target(cli, argv[0], &t))
        return PGLOSS_CLI_USAGE;
    static const char *const nm[5] = {"L", "a", "b", "c", "d"};
    double v[5];
    for (int k = 0; k < 5; ++k)
        if (!pgloss_cli_number(cli, nm[k], argv[1 + k], &v[k]))
            return PGLOSS_CLI_USAGE;
    const pgloss_perceptual q = {v[0], v[1], v[2], v[3], v[4]};
    pgloss_bridge_params p;
    pgloss_perceptual reached;
    const pgloss_status st = pgloss_bridge_from_perceptual(t, &q, &p, &reached);
    /* Out of the target's reach the parameters of the nearest reachable paint still come back. */
    if (st < 0 && st != PGLOSS_ERR_BRIDGE_BASE && st != PGLOSS_ERR_BRIDGE_SPECULAR && st != PGLOSS_ERR_BRIDGE_ROUGHNESS) {
        fprintf(cli->out, "{\"target\": \"%s\", \"status\": \"%s\", \"reason\": \"%s\"}\n",
                pgloss_bridge_target_name(t), pgloss_status_name(st), pgloss_status_string(st));
        return PGLOSS_CLI_ERROR;
    }
    print_json(cli->out, t, st, &p, &reached, NULL);
    return st < 0 ? PGLOSS_CLI_ERROR : PGLOSS_CLI_OK;
}

const pgloss_cli_command pgloss_cmd_bridge = {
    "bridge", "TARGET L a b c d | --from TARGET FILE.json",
    "paint <-> a renderer's parameters (OpenPBR, glTF, Principled, Mitsuba...), as JSON",
    bridge};
