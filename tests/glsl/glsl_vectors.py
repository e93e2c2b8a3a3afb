# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Executes the shared test vectors (tests/vectors/*.json) through glsl/pgloss.glsl.

One compute shader (GLSL 4.50 core) includes pgloss.glsl and dispatches every case of every
file to the function it names; inputs and outputs travel through SSBOs (or, for the GLSL 3.30
and ESSL 3.00 fragment stages, an RGBA32UI texture in and a render target out). Loading the
cases, the tolerance model of tests/vectors/README.md and the report are the shared module
tests/vectors/pgloss_vectors.py (the logic of tests/test_vectors.cpp); what is this layer's:

    |got - want| <= abs + rel*|want| + kappa_rel*sens            (the "float" column, always)
                  + exp_ulp_rel(x) * |want|                       (BRDF f, pdf, sample weight)

* PRECISION = "float": GLSL floats are 32-bit. Files whose C precision is double are held to
  the float column (rel 1e-5, kappa_rel 1e-6: float rounding of inputs and intermediates,
  amplified by the case's sens, is what the port may add), with three documented exceptions
  for the status (see classify()).
* exp_ulp_rel(x) = (3 + 2|x|) * 2^-24: the accuracy the GLSL 4.60 and Vulkan specifications
  allow for the built-in exp(x), through which eq. 2's exponential x = tan²δ/α² reaches f,
  pdf and the sample weight.
* Denormal directions a driver flushes to zero (GLSL 4.60 §4.7.1): see compare_file().

Environment:
  PGLOSS_GLSL_DEVICE=llvmpipe (default): Mesa llvmpipe through EGL, headless; the renderer
      string must say llvmpipe, else the run fails.
  PGLOSS_GLSL_DEVICE=gpu: the default EGL device (a GPU driver); the renderer must NOT be a
      software rasteriser.
"""
from __future__ import annotations

import math
import os
import pathlib
import sys
from collections import OrderedDict
from dataclasses import dataclass, field
from typing import Callable, Iterable

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "vectors"))
import pgloss_vectors as pv  # noqa: E402

GLSL = ROOT / "glsl" / "pgloss.glsl"

# GLSL floats are 32-bit: every file is held to the vectors' float tolerance column.
PRECISION = "float"


def exp_ulp_rel(x: float) -> float:
    """The relative error the GLSL 4.60 / Vulkan specifications allow the built-in exp(x):
    3 + 2|x| ULP. Eq. 2's exponential (x = tan²δ/α²) reaches f, pdf and the sample weight."""
    return (3.0 + 2.0 * abs(x)) * pv.ULP


# Function codes of the dispatcher below.
FN = {name: k for k, name in enumerate([
    "lightness_from_luminance", "luminance_from_lightness", "contrast_gloss",
    "specular_from_contrast", "gloss_from_physical", "physical_from_gloss", "gloss_distance",
    "envelope_contrast", "match_gloss", "isogloss_contour", "rgb_from_lab", "lab_from_rgb",
    "luminance", "check_physical", "check_perceptual", "physical_from_perceptual",
    "perceptual_from_physical", "material_init", "specular_probability", pv.BRDF_EVAL,
    pv.BRDF_SAMPLE, "rgb_from_lab_ex", "lab_from_rgb_ex", "luminance_ex", "check_perceptual_ex",
    "physical_from_perceptual_ex", "perceptual_from_physical_ex"])}

NF_IN, NU_IN, NF_OUT, NI_OUT = 16, 4, 16, 4

# Stage-specific accessors: F (float input k of job j), U (uint input), O (float output), I (int output).
COMPUTE_PRELUDE = r"""
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer FIn { float fin[]; };
layout(std430, binding = 1) readonly buffer UIn { uint uin[]; };
layout(std430, binding = 2) writeonly buffer FOut { float fout[]; };
layout(std430, binding = 3) writeonly buffer IOut { int iout[]; };
uniform uint n_jobs;
float F(uint j, uint k) { return fin[j * 16u + k]; }
uint U(uint j, uint k) { return uin[j * 4u + k]; }
void O(uint j, uint k, float v) { fout[j * 16u + k] = v; }
void I(uint j, uint k, int v) { iout[j * 4u + k] = v; }
"""

COMPUTE_MAIN = r"""
void main() {
    uint j = gl_GlobalInvocationID.x;
    if (j < n_jobs) pgloss_run(j);
}
"""

# GLSL 3.30 fragment stage: one row of 5 RGBA32UI texels per job, in and out (float bits).
FRAGMENT_PRELUDE = r"""
uniform usampler2D inp;
out uvec4 outp;
float res[16];
int ires[4];
float F(uint j, uint k) { return uintBitsToFloat(texelFetch(inp, ivec2(int(k / 4u), int(j)), 0)[int(k % 4u)]); }
uint U(uint j, uint k) { return texelFetch(inp, ivec2(4, int(j)), 0)[int(k)]; }
void O(uint j, uint k, float v) { res[k] = v; }
void I(uint j, uint k, int v) { ires[k] = v; }
"""

FRAGMENT_MAIN = r"""
void main() {
    uint j = uint(gl_FragCoord.y);
    int part = int(gl_FragCoord.x);
    pgloss_run(j);
    if (part < 4)
        outp = floatBitsToUint(vec4(res[4 * part], res[4 * part + 1], res[4 * part + 2], res[4 * part + 3]));
    else
        outp = uvec4(ivec4(ires[0], ires[1], ires[2], ires[3]));
}
"""

DISPATCHER = r"""
vec3 F3(uint j, uint k) { return vec3(F(j, k), F(j, k + 1u), F(j, k + 2u)); }
void O3(uint j, uint k, vec3 v) { O(j, k, v.x); O(j, k + 1u, v.y); O(j, k + 2u, v.z); }
pgloss_physical P(uint j) { return pgloss_physical(F3(j, 0u), F(j, 3u), F(j, 4u), F(j, 5u), int(U(j, 1u))); }

void pgloss_run(uint j) {
    uint fn = U(j, 0u);
    for (uint k = 0u; k < 16u; ++k) O(j, k, -12345.0);
    for (uint k = 1u; k < 4u; ++k) I(j, k, -12345);
    int st = -12345;
    float a, b, c, d, e;
    vec3 v;
    if (fn == 0xFFFFFFFFu) { /* chain head (the perceptual block may be compiled out) */ }
#ifndef PGLOSS_NO_PERCEPTUAL
    else if (fn == 0u) { st = pgloss_lightness_from_luminance(F(j, 0u), a); O(j, 0u, a); }
    else if (fn == 1u) { st = pgloss_luminance_from_lightness(F(j, 0u), a); O(j, 0u, a); }
    else if (fn == 2u) { st = pgloss_contrast_gloss(F(j, 0u), F(j, 1u), a); O(j, 0u, a); }
    else if (fn == 3u) { st = pgloss_specular_from_contrast(F(j, 0u), F(j, 1u), a); O(j, 0u, a); }
    else if (fn == 4u) { st = pgloss_gloss_from_physical(F(j, 0u), F(j, 1u), F(j, 2u), a, b, c); O(j, 0u, a); O(j, 1u, b); O(j, 2u, c); }
    else if (fn == 5u) { st = pgloss_physical_from_gloss(F(j, 0u), F(j, 1u), F(j, 2u), a, b, c); O(j, 0u, a); O(j, 1u, b); O(j, 2u, c); }
    else if (fn == 6u) { st = pgloss_gloss_distance(F(j, 0u), F(j, 1u), F(j, 2u), F(j, 3u), a); O(j, 0u, a); }
    else if (fn == 7u) { st = pgloss_envelope_contrast(F(j, 0u), a); O(j, 0u, a); }
    else if (fn == 8u) { st = pgloss_match_gloss(F(j, 0u), F(j, 1u), F(j, 2u), a, b); O(j, 0u, a); O(j, 1u, b); }
    else if (fn == 9u) { st = pgloss_isogloss_contour(F(j, 0u), F(j, 1u), F(j, 2u), U(j, 2u), U(j, 3u), a, b); O(j, 0u, a); O(j, 1u, b); }
    else if (fn == 10u) { st = pgloss_rgb_from_lab(F3(j, 0u), v); O3(j, 0u, v); }
    else if (fn == 11u) { st = pgloss_lab_from_rgb(F3(j, 0u), v); O3(j, 0u, v); }
    else if (fn == 12u) { st = pgloss_luminance(F3(j, 0u), a); O(j, 0u, a); }
    else if (fn == 13u) { st = pgloss_check_physical(P(j)); }
    else if (fn == 14u) { st = pgloss_check_perceptual(pgloss_perceptual(F(j, 0u), F(j, 1u), F(j, 2u), F(j, 3u), F(j, 4u))); }
    else if (fn == 15u) {
        pgloss_physical p;
        st = pgloss_physical_from_perceptual(pgloss_perceptual(F(j, 0u), F(j, 1u), F(j, 2u), F(j, 3u), F(j, 4u)), int(U(j, 1u)), p);
        O3(j, 0u, p.rho_d); O(j, 3u, p.rho_s); O(j, 4u, p.alpha_x); O(j, 5u, p.alpha_y); I(j, 1u, p.normalization);
    }
    else if (fn == 16u) {
        pgloss_perceptual q;
        st = pgloss_perceptual_from_physical(P(j), q);
        O(j, 0u, q.L); O(j, 1u, q.a); O(j, 2u, q.b); O(j, 3u, q.c); O(j, 4u, q.d);
    }
    /* The _ex functions: the working colour space is U(j, 3u). */
    else if (fn == 21u) { st = pgloss_rgb_from_lab_ex(F3(j, 0u), int(U(j, 3u)), v); O3(j, 0u, v); }
    else if (fn == 22u) { st = pgloss_lab_from_rgb_ex(F3(j, 0u), int(U(j, 3u)), v); O3(j, 0u, v); }
    else if (fn == 23u) { st = pgloss_luminance_ex(F3(j, 0u), int(U(j, 3u)), a); O(j, 0u, a); }
    else if (fn == 24u) { st = pgloss_check_perceptual_ex(pgloss_perceptual(F(j, 0u), F(j, 1u), F(j, 2u), F(j, 3u), F(j, 4u)), int(U(j, 3u))); }
    else if (fn == 25u) {
        pgloss_physical p;
        st = pgloss_physical_from_perceptual_ex(pgloss_perceptual(F(j, 0u), F(j, 1u), F(j, 2u), F(j, 3u), F(j, 4u)), int(U(j, 1u)), int(U(j, 3u)), p);
        O3(j, 0u, p.rho_d); O(j, 3u, p.rho_s); O(j, 4u, p.alpha_x); O(j, 5u, p.alpha_y); I(j, 1u, p.normalization);
    }
    else if (fn == 26u) {
        pgloss_perceptual q;
        st = pgloss_perceptual_from_physical_ex(P(j), int(U(j, 3u)), q);
        O(j, 0u, q.L); O(j, 1u, q.a); O(j, 2u, q.b); O(j, 3u, q.c); O(j, 4u, q.d);
    }
#endif
    else if (fn == 17u) {
        pgloss_material m;
        st = pgloss_material_init(m, P(j));
        O3(j, 0u, m.rho_d); O(j, 3u, m.rho_s); O(j, 4u, m.alpha_x); O(j, 5u, m.alpha_y);
        O(j, 6u, m.inv_alpha_x); O(j, 7u, m.inv_alpha_y); O(j, 8u, m.spec_scale); O(j, 9u, m.pdf_scale);
        O(j, 10u, m.weight_diffuse); O(j, 11u, m.weight_specular);
        vec3 f; pgloss_eval(m, vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), PGLOSS_LOBE_ALL, f); O3(j, 12u, f);
        I(j, 1u, int(m.lobes)); I(j, 2u, m.normalization);
    }
    else if (fn == 18u) {
        pgloss_material m;
        I(j, 3u, pgloss_material_init(m, P(j)));
        O(j, 0u, pgloss_specular_probability(m, U(j, 2u))); st = 0;
    }
    else if (fn == 19u) {
        pgloss_material m;
        I(j, 3u, pgloss_material_init(m, P(j)));
        uint lobes = U(j, 2u);
        vec3 wo = F3(j, 6u), wi = F3(j, 9u), f;
        float pdf;
        st = pgloss_eval(m, wo, wi, lobes, f); O3(j, 0u, f);
        I(j, 1u, pgloss_pdf(m, wo, wi, lobes, pdf)); O(j, 3u, pdf);
        I(j, 2u, pgloss_eval_pdf(m, wo, wi, lobes, f, pdf)); O3(j, 4u, f); O(j, 7u, pdf);
    }
#ifndef PGLOSS_NO_SAMPLING
    else if (fn == 20u) {
        pgloss_material m;
        I(j, 3u, pgloss_material_init(m, P(j)));
        pgloss_sample_record r;
        st = pgloss_sample(m, F3(j, 6u), F3(j, 9u), U(j, 2u), r);
        O3(j, 0u, r.wi); O(j, 3u, r.pdf); O3(j, 4u, r.weight); I(j, 1u, int(r.lobe));
    }
#endif
    I(j, 0u, st);
}
"""


STAGES = {"comp": "450 core", "frag": "330 core", "frag_es": "300 es"}


def shader_source(defines: Iterable[str] = (), stage: str = "comp") -> str:
    """comp: GLSL 4.50 compute; frag: GLSL 3.30 fragment; frag_es: GLSL ES 3.00 (WebGL2's
    language) fragment, which a desktop GL >= 4.3 context runs through ARB_ES3_compatibility."""
    head = f"#version {STAGES[stage]}\n" + "".join(f"#define {d} 1\n" for d in defines)
    if stage == "comp":
        return head + GLSL.read_text() + COMPUTE_PRELUDE + DISPATCHER + COMPUTE_MAIN
    prelude = FRAGMENT_PRELUDE
    if stage == "frag_es":  # ES has no default precision for integer samplers
        prelude = prelude.replace("uniform usampler2D inp;", "uniform highp usampler2D inp;")
    return head + GLSL.read_text() + prelude + DISPATCHER + FRAGMENT_MAIN



# ---------------------------------------------------------------------------------------
# Jobs: one per case (one per point of an isogloss contour)


def u32(x: int) -> int:
    return x & 0xFFFFFFFF


@dataclass
class Job:
    case: dict
    fn: str
    fin: list[float] = field(default_factory=list)
    uin: list[int] = field(default_factory=list)
    point: int = -1  # isogloss: the point index


def physical_floats(p: dict) -> tuple[list[float], int]:
    num = pv.num
    return ([num(x) for x in p["rho_d"]] + [num(p["rho_s"]), num(p["alpha_x"]), num(p["alpha_y"])],
            u32(int(p["normalization"])))


# Scalar inputs of the simple double-API functions, in argument order.
SCALAR_INPUTS = {"lightness_from_luminance": ["Y"], "luminance_from_lightness": ["L"],
                 "contrast_gloss": ["rho_d", "rho_s"], "specular_from_contrast": ["rho_d", "c"],
                 "gloss_from_physical": ["rho_d", "rho_s", "alpha"], "physical_from_gloss": ["L", "c", "d"],
                 "gloss_distance": ["c1", "d1", "c2", "d2"], "envelope_contrast": ["L"],
                 "match_gloss": ["rho_d", "rho_s", "L_target"]}


def jobs_of(file: str, rep: pv.Report) -> list[Job]:
    """Jobs for every case of a file; null_pointer cases are counted on rep as skipped."""
    num = pv.num
    jobs: list[Job] = []
    doc = pv.load(file)
    mats = doc.get("materials", {})
    for fn, c in pv.runnable(file, rep):
        inp = c["input"]
        if fn in (pv.BRDF_EVAL, pv.BRDF_SAMPLE):
            pf, norm = physical_floats(mats[inp["material"]])
            extra = inp["wi"] if fn == pv.BRDF_EVAL else inp["u"]
            fin = pf + [num(x) for x in inp["wo"]] + [num(x) for x in extra]
            jobs.append(Job(c, fn, fin, [FN[fn], norm, u32(int(inp["lobes"])), 0]))
        elif fn in ("material_init", "specular_probability", "check_physical", "perceptual_from_physical",
                    "perceptual_from_physical_ex"):
            pf, norm = physical_floats(inp["p"])
            lobes = u32(int(inp.get("lobes", 0)))
            jobs.append(Job(c, fn, pf, [FN[fn], norm, lobes, u32(int(inp.get("space", 0)))]))
        elif fn in ("check_perceptual", "physical_from_perceptual", "check_perceptual_ex",
                    "physical_from_perceptual_ex"):
            q = inp["q"]
            fin = [num(q[k]) for k in "Labcd"]
            jobs.append(Job(c, fn, fin, [FN[fn], u32(int(inp.get("normalization", 0))), 0,
                                         u32(int(inp.get("space", 0)))]))
        elif fn == "isogloss_contour":
            fin = [num(inp["c0"]), num(inp["d0"]), num(inp["D"])]
            n = int(inp["n"])
            for k in range(max(n, 1)):
                jobs.append(Job(c, fn, fin, [FN[fn], 0, k, n], point=k))
        elif fn in SCALAR_INPUTS:
            jobs.append(Job(c, fn, [num(inp[k]) for k in SCALAR_INPUTS[fn]], [FN[fn], 0, 0, 0]))
        elif fn in ("rgb_from_lab", "lab_from_rgb", "luminance", "rgb_from_lab_ex", "lab_from_rgb_ex",
                    "luminance_ex"):
            fin = [num(x) for x in inp["lab" if fn.startswith("rgb_from_lab") else "rgb"]]
            jobs.append(Job(c, fn, fin, [FN[fn], 0, 0, u32(int(inp.get("space", 0)))]))
        else:
            raise ValueError(f"{c['id']}: unknown function {fn}")
    return jobs

# ---------------------------------------------------------------------------------------
# Execution


def create_context():
    """EGL headless context; enforces the device asked for by PGLOSS_GLSL_DEVICE."""
    import moderngl

    device = os.environ.get("PGLOSS_GLSL_DEVICE", "llvmpipe")
    if device not in ("llvmpipe", "gpu"):
        raise RuntimeError(f"PGLOSS_GLSL_DEVICE={device!r}: expected 'llvmpipe' or 'gpu'")
    if device == "llvmpipe":
        os.environ["LIBGL_ALWAYS_SOFTWARE"] = "1"
        os.environ.setdefault("GALLIUM_DRIVER", "llvmpipe")
    ctx = moderngl.create_context(standalone=True, backend="egl", require=450)
    renderer = ctx.info["GL_RENDERER"]
    software = any(s in renderer.lower() for s in ("llvmpipe", "softpipe", "swrast", "lavapipe"))
    if device == "llvmpipe" and "llvmpipe" not in renderer:
        raise RuntimeError(f"asked for llvmpipe, got renderer {renderer!r}")
    if device == "gpu" and software:
        raise RuntimeError(f"PGLOSS_GLSL_DEVICE=gpu but the renderer is {renderer!r}")
    return ctx


def run_jobs(ctx, jobs: list[Job], defines: Iterable[str] = (),
             stage: str = "comp") -> tuple[np.ndarray, np.ndarray]:
    """Runs the jobs in a compute shader (GLSL 4.50, SSBOs) or a fragment shader (GLSL 3.30,
    RGBA32UI texture in and render target out, float bits carried exactly)."""
    n = len(jobs)
    fin = np.zeros((n, NF_IN), np.float32)
    uin = np.zeros((n, NU_IN), np.uint32)
    with np.errstate(over="ignore"):
        for k, j in enumerate(jobs):
            fin[k, : len(j.fin)] = np.array(j.fin, np.float64).astype(np.float32)
            uin[k, :] = j.uin
    if stage in ("frag", "frag_es"):
        return _run_fragment(ctx, fin, uin, defines, stage)
    prog = ctx.compute_shader(shader_source(defines))
    bufs = [ctx.buffer(fin.tobytes()), ctx.buffer(uin.tobytes()),
            ctx.buffer(reserve=n * NF_OUT * 4), ctx.buffer(reserve=n * NI_OUT * 4)]
    for b, buf in enumerate(bufs):
        buf.bind_to_storage_buffer(b)
    prog["n_jobs"].value = n
    prog.run(group_x=(n + 63) // 64)
    ctx.finish()
    fout = np.frombuffer(bufs[2].read(), np.float32).reshape(n, NF_OUT).astype(np.float64)
    iout = np.frombuffer(bufs[3].read(), np.int32).reshape(n, NI_OUT)
    for buf in bufs:
        buf.release()
    prog.release()
    return fout, iout


_VERTEX = """
in vec2 pos;
void main() { gl_Position = vec4(pos, 0.0, 1.0); }
"""


def _run_fragment(ctx, fin: np.ndarray, uin: np.ndarray, defines: Iterable[str],
                  stage: str) -> tuple[np.ndarray, np.ndarray]:
    import moderngl

    n = fin.shape[0]
    texels = np.concatenate([fin.view(np.uint32), uin], axis=1)  # n x 20 uints = 5 RGBA texels
    tex = ctx.texture((5, n), 4, texels.tobytes(), dtype="u4")
    tex.filter = (moderngl.NEAREST, moderngl.NEAREST)
    prog = ctx.program(vertex_shader=f"#version {STAGES[stage]}\n" + _VERTEX,
                       fragment_shader=shader_source(defines, stage))
    tex.use(0)
    prog["inp"].value = 0
    quad = ctx.buffer(np.array([-1, -1, 1, -1, -1, 1, 1, 1], np.float32).tobytes())
    vao = ctx.vertex_array(prog, [(quad, "2f", "pos")])
    target = ctx.texture((5, n), 4, dtype="u4")
    fbo = ctx.framebuffer(color_attachments=[target])
    fbo.use()
    fbo.viewport = (0, 0, 5, n)
    vao.render(moderngl.TRIANGLE_STRIP)
    ctx.finish()
    raw = np.frombuffer(fbo.read(components=4, dtype="u4"), np.uint32).reshape(n, 20)
    fout = raw[:, :16].copy().view(np.float32).astype(np.float64)
    iout = raw[:, 16:].copy().view(np.int32)
    for obj in (fbo, target, vao, quad, prog, tex):
        obj.release()
    return fout, iout



# ---------------------------------------------------------------------------------------
# Comparison (the checks are pgloss_vectors.Report's; what follows reads the shader's slots
# and applies this layer's float allowances)

def float_key(job: Job) -> tuple:
    with np.errstate(over="ignore"):
        return (job.fn, tuple(np.array(job.fin, np.float64).astype(np.float32).tobytes()),
                tuple(job.uin))


def classify(job: Job, groups: dict) -> str | None:
    """Why the float status may legitimately differ from the double one, or None.

    - "float-unresolvable": another case of the function has the same float32 inputs and a
      different status (e.g. α = 0.2 vs the next double, ρd + ρs = 1 + 2e-12), or an input
      that is not float-exact rounds exactly onto a boundary value of the headers (0, 1, 100,
      0.2, 0.8: e.g. L = 100.00000000000001 becomes 100): no float implementation can tell
      them apart; either status (of the siblings) is accepted.
    - "beyond float range": a finite input or an expected output exceeds pv.FLT_MAX (the C double
      function returns OK; in float the input is Inf): NONFINITE or the C status is accepted.
    - "below float range": a non-zero input is smaller than pv.FLT_MIN (rounds to 0 or a
      denormal, which GLSL allows to be flushed): any status is accepted, outputs must be
      finite.
    """
    c = job.case
    if job.fn in (pv.BRDF_EVAL, pv.BRDF_SAMPLE):
        return None  # float API: inputs are float-exact
    vals = [x for x in job.fin if math.isfinite(x)]
    exp = c.get("expected", {})
    outs: list[float] = []
    for v in exp.values():
        for x in (v if isinstance(v, list) else [v]):
            if isinstance(x, (int, float)) and not isinstance(x, bool):
                outs.append(float(x))
    if any(abs(x) > pv.FLT_MAX for x in vals + outs):
        return "beyond float range"
    if any(0 < abs(x) < pv.FLT_MIN for x in vals):
        return "below float range"
    if len(groups.get(float_key(job), set())) > 1:
        return "float-unresolvable"
    bounds = (0.0, 1.0, 100.0, 0.2, 0.8)
    if any(math.isfinite(x) and x not in bounds and pv.f32(x) in {pv.f32(b) for b in bounds}
           for x in job.fin):
        return "float-unresolvable"
    return None


# Output slots (fout columns) of the double-API functions in the dispatcher: a slot, or
# (first slot, component count) for a vector.
OUTPUT_SLOTS: dict[str, dict[str, int | tuple[int, int]]] = {
    "lightness_from_luminance": {"L": 0}, "luminance_from_lightness": {"Y": 0},
    "contrast_gloss": {"c": 0}, "specular_from_contrast": {"rho_s": 0},
    "gloss_from_physical": {"L": 0, "c": 1, "d": 2},
    "physical_from_gloss": {"rho_d": 0, "rho_s": 1, "alpha": 2},
    "gloss_distance": {"D": 0}, "envelope_contrast": {"c_max": 0},
    "match_gloss": {"rho_d_out": 0, "rho_s_out": 1}, "luminance": {"Y": 0},
    "rgb_from_lab": {"rgb": (0, 3)}, "lab_from_rgb": {"lab": (0, 3)},
    "specular_probability": {"P": 0},
    "perceptual_from_physical": {"L": 0, "a": 1, "b": 2, "c": 3, "d": 4},
    "physical_from_perceptual": {"rho_d": (0, 3), "rho_s": 3, "alpha_x": 4, "alpha_y": 5},
    "check_physical": {}, "check_perceptual": {},
}
OUTPUT_SLOTS.update({f + "_ex": OUTPUT_SLOTS[f] for f in (
    "rgb_from_lab", "lab_from_rgb", "luminance", "check_perceptual", "physical_from_perceptual",
    "perceptual_from_physical")})
MATERIAL_SLOTS = {"rho_d": (0, 3), "rho_s": 3, "alpha_x": 4, "alpha_y": 5, "inv_alpha_x": 6, "inv_alpha_y": 7,
                  "spec_scale": 8, "pdf_scale": 9, "weight_diffuse": 10, "weight_specular": 11}


def _read(o: np.ndarray, slots: dict) -> dict:
    return {k: (list(o[v[0]:v[0] + v[1]]) if isinstance(v, tuple) else o[v]) for k, v in slots.items()}


def compare_file(rep: pv.Report, file: str, doc: dict, jobs: list[Job], fout: np.ndarray,
                 iout: np.ndarray) -> None:
    groups: dict[tuple, set] = {}
    for j in jobs:
        groups.setdefault(float_key(j), set()).add(j.case["status"])
    rows_of: OrderedDict[str, list[int]] = OrderedDict()
    for row, j in enumerate(jobs):
        rows_of.setdefault(j.case["id"], []).append(row)

    for cid, rows in rows_of.items():
        j = jobs[rows[0]]
        c, fn = j.case, j.fn
        rep.ran(fn)
        o, io = fout[rows[0]], iout[rows[0]]
        got_status = int(io[0])
        if len({int(iout[r, 0]) for r in rows}) > 1:  # the points of one isogloss call
            rep.fail(f"{cid} {fn}: the points disagree on the status: {[int(iout[r, 0]) for r in rows]}")
        if fn in (pv.BRDF_EVAL, pv.BRDF_SAMPLE, "specular_probability") and int(io[3]) != 0:
            rep.fail(f"{cid}: material_init of the case's material returned {io[3]}")
            continue
        if fn in (pv.BRDF_EVAL, pv.BRDF_SAMPLE) and flushed_to_zero_direction(j):
            # GLSL lets the driver flush denormal inputs to 0 (GLSL 4.60 §4.7.1); a direction
            # made only of denormals then becomes the zero direction: ERR_DIRECTION and 0.
            statuses = [got_status] + ([int(io[1]), int(io[2])] if fn == pv.BRDF_EVAL else [])
            if all(x == pv.STATUS["PGLOSS_ERR_DIRECTION"] for x in statuses):
                zeros = o[:8] if fn == pv.BRDF_EVAL else np.concatenate([o[3:4], o[4:7]])
                if np.all(zeros == 0):
                    rep.waive("denormal direction flushed to 0 by the driver", cid)
                else:
                    rep.fail(f"{cid} {fn}: flushed direction gave ERR_DIRECTION but non-zero outputs")
                continue
        if fn == pv.BRDF_EVAL:
            for name, s in (("eval", got_status), ("pdf", int(io[1])), ("eval_pdf", int(io[2]))):
                rep.status(name, c, pv.status_name(s))
            extra = exp_ulp_rel(float(c.get("info", {}).get("exponent", 0.0) or 0.0))
            rep.brdf_eval(doc, "eval", c, f=o[0:3], precision=PRECISION, extra_rel=extra)
            rep.brdf_eval(doc, "pdf", c, pdf=o[3], precision=PRECISION, extra_rel=extra)
            rep.brdf_eval(doc, "eval_pdf", c, f=o[4:7], pdf=o[7], precision=PRECISION, extra_rel=extra)
            continue
        if fn == pv.BRDF_SAMPLE:
            rep.status("sample", c, pv.status_name(got_status))
            rep.sample(doc, "sample", c, o[0:3], o[3], o[4:7], io[1], PRECISION,
                       exp_ulp_rel(sample_exponent(doc, c)))
            continue

        # A double-API function: the status decided in float may legitimately differ.
        why = classify(j, groups)
        got_name = pv.status_name(got_status)
        status_ok = got_name == c["status"]
        if not status_ok:
            siblings = groups[float_key(j)]
            if why == "float-unresolvable" and (len(siblings) == 1 or got_name in siblings):
                rep.waive(f"status: {why}", cid)
            elif why == "beyond float range" and got_name == "PGLOSS_ERR_NONFINITE":
                rep.waive(f"status: {why}", cid)
            elif why == "below float range":
                rep.waive(f"status: {why}", cid)
            else:
                rep.status(fn, c, got_name)
        # Values are compared whenever the status agrees, except where an input is outside
        # float range (there the float input is a different number altogether); elsewhere
        # they must be finite.
        values = status_ok and why in (None, "float-unresolvable")
        if fn == "material_init":
            got = _read(o, MATERIAL_SLOTS)
            got.update(lobes=int(io[1]), normalization=int(io[2]), black=bool(np.all(o[12:15] == 0)))
            rep.material_init(doc, c, got_name, got, PRECISION, values)
            continue
        if fn == "isogloss_contour":
            n = int(c["input"]["n"])  # one job per point (one, unused, for n = 0)
            got = {"c": [fout[r, 0] for r in rows[:n]], "d": [fout[r, 1] for r in rows[:n]]}
        else:
            got = _read(o, OUTPUT_SLOTS[fn])
            if fn in ("physical_from_perceptual", "physical_from_perceptual_ex"):
                got["normalization"] = int(io[1])
        rep.outputs(doc, fn, c, got, PRECISION, values)


def flushed_to_zero_direction(job: Job) -> bool:
    """True if wo (or wi, for eval) has a denormal component and is all zero after flushing
    denormals to zero."""
    dirs = [job.fin[6:9]] + ([job.fin[9:12]] if job.fn == pv.BRDF_EVAL else [])
    for d in dirs:
        if any(0 < abs(x) < pv.FLT_MIN for x in d) and all(abs(x) < pv.FLT_MIN for x in d):
            return True
    return False


def sample_exponent(doc: dict, c: dict) -> float:
    """x = ((h.x/αx)² + (h.y/αy)²)/h.z² at the expected wi (only scales the exp ULP term)."""
    e = c["expected"]
    if e.get("wi") is None or pv.num(e["pdf"]) == 0:
        return 0.0
    m = doc["materials"][c["input"]["material"]]
    wo = np.array([pv.num(x) for x in c["input"]["wo"]])
    n = np.linalg.norm(wo)
    if not np.isfinite(n) or n == 0:
        return 0.0
    h = wo / n + np.array([pv.num(x) for x in e["wi"]])
    ax, ay = max(pv.num(m["alpha_x"]), 1e-4), max(pv.num(m["alpha_y"]), 1e-4)
    if h[2] <= 0:
        return 0.0
    return float(((h[0] / ax) ** 2 + (h[1] / ay) ** 2) / h[2] ** 2)


def run_all(ctx, files: Iterable[str] = pv.FILES, defines: Iterable[str] = (),
            select: Callable[[Job], bool] | None = None, stage: str = "comp") -> pv.Report:
    rep = pv.Report()
    for file in files:
        try:
            doc = pv.load(file)
            jobs = jobs_of(file, rep)
        except pv.VectorsError as e:
            rep.fail(str(e))
            continue
        if select is not None:
            jobs = [j for j in jobs if select(j)]
        if not jobs:
            rep.fail(f"{file}: no cases")
            continue
        fout, iout = run_jobs(ctx, jobs, defines, stage)
        compare_file(rep, file, doc, jobs, fout, iout)
    return rep


if __name__ == "__main__":
    ctx = create_context()
    print("renderer:", ctx.info["GL_RENDERER"], "|", ctx.info["GL_VERSION"])
    stage = sys.argv[1] if len(sys.argv) > 1 else "comp"
    r = run_all(ctx, stage=stage)
    print(r.summary(f"pgloss vectors (GLSL, {STAGES[stage]} {'compute' if stage == 'comp' else 'fragment'} stage)"))
    for f in r.failures[:60]:
        print("  ", f)
