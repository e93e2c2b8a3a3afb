"""Executes the shared test vectors (tests/vectors/*.json) through glsl/pgloss.glsl.

One compute shader (GLSL 4.50 core) includes pgloss.glsl and dispatches every case of every
file to the function it names; inputs and outputs travel through SSBOs; the comparison
follows tests/test_vectors.cpp and the tolerance model of tests/vectors/README.md:

    |got - want| <= abs + rel*|want| + kappa_rel*sens            (the "float" column, always)
                  + (3 + 2|x|) * 2^-24 * |want|                   (BRDF outputs only)

The last term is the accuracy the GLSL 4.60 and Vulkan specifications allow for the
built-in exp(x) (3 + 2|x| ULP), through which eq. 2's exponential x = tan²δ/α² reaches f,
pdf and the sample weight. Files whose C precision is double are held to the float column
(rel 1e-5, kappa_rel 1e-6: float rounding of inputs and intermediates, amplified by the
case's sens, is what the port may add), with three documented exceptions for the status
(see classify()).

Environment:
  PGLOSS_GLSL_DEVICE=llvmpipe (default): Mesa llvmpipe through EGL, headless; the renderer
      string must say llvmpipe, else the run fails.
  PGLOSS_GLSL_DEVICE=gpu: the default EGL device (a GPU driver); the renderer must NOT be a
      software rasteriser.
"""
from __future__ import annotations

import json
import math
import os
import pathlib
import struct
from dataclasses import dataclass, field
from typing import Any, Callable, Iterable

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
VECTORS = ROOT / "tests" / "vectors"
GLSL = ROOT / "glsl" / "pgloss.glsl"

FLT_MAX = float(np.finfo(np.float32).max)
FLT_MIN = float(np.finfo(np.float32).tiny)
ULP = 2.0**-24

STATUS = {
    "PGLOSS_OK": 0, "PGLOSS_WARN_ALPHA_UNTRUSTED": 1, "PGLOSS_ERR_NULL": -1,
    "PGLOSS_ERR_NONFINITE": -2, "PGLOSS_ERR_NEGATIVE": -3, "PGLOSS_ERR_ALPHA": -4,
    "PGLOSS_ERR_ENERGY": -5, "PGLOSS_ERR_ENVELOPE": -6, "PGLOSS_ERR_LIGHTNESS": -7,
    "PGLOSS_ERR_GAMUT": -8, "PGLOSS_ERR_DIRECTION": -9, "PGLOSS_ERR_NORMALIZATION": -10,
    "PGLOSS_ERR_ARGUMENT": -11, "PGLOSS_ERR_RANDOM": -12,
}
STATUS_NAME = {v: k for k, v in STATUS.items()}
LOBE = {"PGLOSS_LOBE_NONE": 0, "PGLOSS_LOBE_DIFFUSE": 1, "PGLOSS_LOBE_SPECULAR": 2}

FILES = ["lightness.json", "gloss.json", "color.json", "validity.json",
         "perceptual_material.json", "material.json", "brdf_eval.json", "brdf_sample.json"]

# Function codes of the dispatcher below.
FN = {name: k for k, name in enumerate([
    "lightness_from_luminance", "luminance_from_lightness", "contrast_gloss",
    "specular_from_contrast", "gloss_from_physical", "physical_from_gloss", "gloss_distance",
    "envelope_contrast", "match_gloss", "isogloss_contour", "rgb_from_lab", "lab_from_rgb",
    "luminance", "check_physical", "check_perceptual", "physical_from_perceptual",
    "perceptual_from_physical", "material_init", "specular_probability", "eval_pdf", "sample"])}

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
# Numbers


def num(j: Any) -> float:
    if isinstance(j, str):
        return {"nan": math.nan, "inf": math.inf, "-inf": -math.inf}[j]
    return float(j)


def f32(x: float) -> float:
    with np.errstate(over="ignore"):
        return float(np.float32(x))


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
    return ([num(x) for x in p["rho_d"]] + [num(p["rho_s"]), num(p["alpha_x"]), num(p["alpha_y"])],
            u32(int(p["normalization"])))


def jobs_of(doc: dict, file: str) -> tuple[list[Job], int]:
    """Jobs for every case of a file; returns (jobs, number of null_pointer cases skipped)."""
    jobs: list[Job] = []
    skipped = 0
    mats = doc.get("materials", {})
    for c in doc["cases"]:
        inp = c["input"]
        if "null" in inp:  # README: ports without pointers skip null_pointer cases
            skipped += 1
            continue
        fn = c.get("function")
        if file == "brdf_eval.json":
            fn = "eval_pdf"
        elif file == "brdf_sample.json":
            fn = "sample"
        if fn in ("eval_pdf", "sample"):
            pf, norm = physical_floats(mats[inp["material"]])
            extra = inp["wi"] if fn == "eval_pdf" else inp["u"]
            fin = pf + [num(x) for x in inp["wo"]] + [num(x) for x in extra]
            jobs.append(Job(c, fn, fin, [FN[fn], norm, u32(int(inp["lobes"])), 0]))
        elif fn in ("material_init", "specular_probability", "check_physical", "perceptual_from_physical"):
            pf, norm = physical_floats(inp["p"])
            lobes = u32(int(inp.get("lobes", 0)))
            jobs.append(Job(c, fn, pf, [FN[fn], norm, lobes, 0]))
        elif fn in ("check_perceptual", "physical_from_perceptual"):
            q = inp["q"]
            fin = [num(q[k]) for k in "Labcd"]
            jobs.append(Job(c, fn, fin, [FN[fn], u32(int(inp.get("normalization", 0))), 0, 0]))
        elif fn == "isogloss_contour":
            fin = [num(inp["c0"]), num(inp["d0"]), num(inp["D"])]
            n = int(inp["n"])
            for k in range(max(n, 1)):
                jobs.append(Job(c, fn, fin, [FN[fn], 0, k, n], point=k))
        else:
            keys = {"lightness_from_luminance": ["Y"], "luminance_from_lightness": ["L"],
                    "contrast_gloss": ["rho_d", "rho_s"], "specular_from_contrast": ["rho_d", "c"],
                    "gloss_from_physical": ["rho_d", "rho_s", "alpha"],
                    "physical_from_gloss": ["L", "c", "d"],
                    "gloss_distance": ["c1", "d1", "c2", "d2"], "envelope_contrast": ["L"],
                    "match_gloss": ["rho_d", "rho_s", "L_target"]}
            if fn in keys:
                fin = [num(inp[k]) for k in keys[fn]]
            elif fn in ("rgb_from_lab", "lab_from_rgb", "luminance"):
                fin = [num(x) for x in inp["lab" if fn == "rgb_from_lab" else "rgb"]]
            else:
                raise ValueError(f"{c['id']}: unknown function {fn}")
            jobs.append(Job(c, fn, fin, [FN[fn], 0, 0, 0]))
    return jobs, skipped


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
# Comparison


@dataclass
class Stat:
    checks: int = 0
    regular: int = 0
    sanity: int = 0
    max_rel: float = 0.0
    max_ratio: float = 0.0
    worst_rel: str = ""
    worst_ratio: str = ""


@dataclass
class Report:
    stats: dict[str, Stat] = field(default_factory=dict)
    failures: list[str] = field(default_factory=list)
    waived: dict[str, list[str]] = field(default_factory=dict)
    skipped_null: int = 0
    cases: int = 0

    def fail(self, msg: str) -> None:
        self.failures.append(msg)

    def waive(self, why: str, cid: str) -> None:
        self.waived.setdefault(why, []).append(cid)

    def summary(self) -> str:
        lines = [f"{'function output':34s} {'checks':>7s} {'regular':>7s} {'sanity':>6s} "
                 f"{'max relerr':>11s} {'(case)':>8s} {'max e/tol':>9s} {'(case)':>8s}"]
        for k in sorted(self.stats):
            s = self.stats[k]
            lines.append(f"{k:34s} {s.checks:7d} {s.regular:7d} {s.sanity:6d} {s.max_rel:11.3e} "
                         f"{s.worst_rel:>8s} {s.max_ratio:9.3g} {s.worst_ratio:>8s}")
        lines.append(f"cases run: {self.cases}; null_pointer cases skipped (no pointers in GLSL): "
                     f"{self.skipped_null}")
        for why, ids in sorted(self.waived.items()):
            lines.append(f"status waived ({why}): {len(ids)}: {' '.join(sorted(set(ids))[:12])}"
                         + (" ..." if len(set(ids)) > 12 else ""))
        return "\n".join(lines)


def check(rep: Report, key: str, cid: str, got: float, want: Any, sens: float, tol: dict,
          extra_rel: float = 0.0, sanity: bool = False, nonneg: bool = False) -> None:
    st = rep.stats.setdefault(key, Stat())
    if not math.isfinite(got):
        rep.fail(f"{cid} {key}: output not finite: {got}")
        return
    if want is None:
        return
    w = num(want)
    if sanity:
        st.sanity += 1
        if nonneg and got < 0:
            rep.fail(f"{cid} {key}: negative {got!r}")
        return
    st.checks += 1
    err = abs(got - w)
    bound = tol["abs"] + (tol["rel"] + extra_rel) * abs(w) + tol["kappa_rel"] * sens
    rel = err / abs(w) if w != 0 else 0.0
    ratio = err / bound if bound > 0 else (0.0 if err == 0 else math.inf)
    if abs(w) >= 1e-30 and sens <= 10 * abs(w):
        st.regular += 1
        if rel > st.max_rel or not st.worst_rel:
            st.max_rel = max(st.max_rel, rel)
            st.worst_rel = cid
    if ratio > st.max_ratio or not st.worst_ratio:
        st.max_ratio = max(st.max_ratio, ratio)
        st.worst_ratio = cid
    if not err <= bound:
        rep.fail(f"{cid} {key}: got {got!r} want {w!r} |err| {err:.3g} > tol {bound:.3g} (sens {sens})")


def sens_at(c: dict, out: str, k: int = -1) -> float:
    s = c.get("sens", {}).get(out)
    if s is None:
        return 0.0
    if k >= 0:
        s = s[k]
    return 0.0 if s is None else float(s)


def float_key(job: Job) -> tuple:
    with np.errstate(over="ignore"):
        return (job.fn, tuple(np.array(job.fin, np.float64).astype(np.float32).tobytes()),
                tuple(job.uin))


def classify(job: Job, file_precision: str, groups: dict) -> str | None:
    """Why the float status may legitimately differ from the double one, or None.

    - "float-unresolvable": another case of the function has the same float32 inputs and a
      different status (e.g. α = 0.2 vs the next double, ρd + ρs = 1 + 2e-12), or an input
      that is not float-exact rounds exactly onto a boundary value of the headers (0, 1, 100,
      0.2, 0.8: e.g. L = 100.00000000000001 becomes 100): no float implementation can tell
      them apart; either status (of the siblings) is accepted.
    - "beyond float range": a finite input or an expected output exceeds FLT_MAX (the C double
      function returns OK; in float the input is Inf): NONFINITE or the C status is accepted.
    - "below float range": a non-zero input is smaller than FLT_MIN (rounds to 0 or a
      denormal, which GLSL allows to be flushed): any status is accepted, outputs must be
      finite.
    """
    c = job.case
    if job.fn in ("eval_pdf", "sample"):
        return None  # float API: inputs are float-exact
    vals = [x for x in job.fin if math.isfinite(x)]
    exp = c.get("expected", {})
    outs: list[float] = []
    for v in exp.values():
        for x in (v if isinstance(v, list) else [v]):
            if isinstance(x, (int, float)) and not isinstance(x, bool):
                outs.append(float(x))
    if any(abs(x) > FLT_MAX for x in vals + outs):
        return "beyond float range"
    if any(0 < abs(x) < FLT_MIN for x in vals):
        return "below float range"
    if len(groups.get(float_key(job), set())) > 1:
        return "float-unresolvable"
    bounds = (0.0, 1.0, 100.0, 0.2, 0.8)
    if any(math.isfinite(x) and x not in bounds and f32(x) in {f32(b) for b in bounds}
           for x in job.fin):
        return "float-unresolvable"
    return None


def compare_file(rep: Report, file: str, doc: dict, jobs: list[Job], fout: np.ndarray,
                 iout: np.ndarray) -> None:
    prec = doc["c_precision"]
    tolt = doc["tolerance"]

    def tol(fn: str, out: str) -> dict:
        return tolt[fn][out]["float"]

    groups: dict[tuple, set] = {}
    for j in jobs:
        groups.setdefault(float_key(j), set()).add(j.case["status"])

    seen: set[str] = set()
    for row, j in enumerate(jobs):
        c, fn, cid = j.case, j.fn, j.case["id"]
        if cid not in seen:
            seen.add(cid)
            rep.cases += 1
        o, io = fout[row], iout[row]
        exp = c.get("expected", {})
        want_status = STATUS[c["status"]]
        got_status = int(io[0])
        why = classify(j, prec, groups)
        if fn in ("eval_pdf", "sample", "specular_probability"):
            if int(io[3]) != 0:
                rep.fail(f"{cid}: material_init of the case's material returned {io[3]}")
                continue
        if fn in ("eval_pdf", "sample") and flushed_to_zero_direction(j):
            # GLSL lets the driver flush denormal inputs to 0 (GLSL 4.60 §4.7.1); a direction
            # made only of denormals then becomes the zero direction: ERR_DIRECTION and 0.
            statuses = [got_status] + ([int(io[1]), int(io[2])] if fn == "eval_pdf" else [])
            if all(x == STATUS["PGLOSS_ERR_DIRECTION"] for x in statuses):
                zeros = o[:8] if fn == "eval_pdf" else np.concatenate([o[3:4], o[4:7]])
                if np.all(zeros == 0):
                    rep.waive("denormal direction flushed to 0 by the driver", cid)
                else:
                    rep.fail(f"{cid} {fn}: flushed direction gave ERR_DIRECTION but non-zero outputs")
                continue
        if fn == "eval_pdf":
            names = [("eval", got_status), ("pdf", int(io[1])), ("eval_pdf", int(io[2]))]
            for name, s in names:
                if s != want_status:
                    rep.fail(f"{cid} {name}: status {STATUS_NAME.get(s, s)}, want {c['status']}")
            sanity = "ill_conditioned" in c.get("tags", [])
            x = float(c.get("info", {}).get("exponent", 0.0) or 0.0)
            extra = (3.0 + 2.0 * abs(x)) * ULP
            for name, fo, po in (("eval", 0, None), ("pdf", None, 3), ("eval_pdf", 4, 7)):
                if fo is not None:
                    for k in range(3):
                        check(rep, f"{name} f", cid, o[fo + k], exp["f"][k], sens_at(c, "f", k),
                              tol(name, "f"), extra, sanity, True)
                if po is not None:
                    check(rep, f"{name} pdf", cid, o[po], exp["pdf"], sens_at(c, "pdf"),
                          tol(name, "pdf"), extra, sanity, True)
            continue
        if fn == "sample":
            if got_status != want_status:
                rep.fail(f"{cid} sample: status {STATUS_NAME.get(got_status, got_status)}, want {c['status']}")
            x = sample_exponent(doc, c)
            extra = (3.0 + 2.0 * abs(x)) * ULP
            for k in range(3):
                check(rep, "sample wi", cid, o[k], None if exp["wi"] is None else exp["wi"][k],
                      sens_at(c, "wi", k), tol("sample", "wi"))
                check(rep, "sample weight", cid, o[4 + k], exp["weight"][k], sens_at(c, "weight", k),
                      tol("sample", "weight"), extra, False, True)
            check(rep, "sample pdf", cid, o[3], exp["pdf"], sens_at(c, "pdf"), tol("sample", "pdf"),
                  extra, False, True)
            if exp.get("lobe") is not None:
                rep.stats.setdefault("sample lobe", Stat()).checks += 1
                if int(io[1]) != LOBE[exp["lobe"]]:
                    rep.fail(f"{cid} sample lobe {io[1]}, want {exp['lobe']}")
            if num(exp["pdf"]) == 0:
                if not (o[3] == 0 and o[4] == 0 and o[5] == 0 and o[6] == 0):
                    rep.fail(f"{cid} sample: rejected sample must have pdf and weight exactly 0")
            elif exp["wi"] is not None:
                if abs(math.sqrt(o[0] ** 2 + o[1] ** 2 + o[2] ** 2) - 1) > 1e-5:
                    rep.fail(f"{cid} sample: wi not unit length")
            continue

        status_ok = got_status == want_status
        if not status_ok:
            if why == "float-unresolvable" and (len(groups[float_key(j)]) == 1 or
                                                STATUS_NAME.get(got_status) in groups[float_key(j)]):
                rep.waive(why, cid)
            elif why == "beyond float range" and got_status == STATUS["PGLOSS_ERR_NONFINITE"]:
                rep.waive(why, cid)
            elif why == "below float range":
                rep.waive(why, cid)
            else:
                rep.fail(f"{cid} {fn}: status {STATUS_NAME.get(got_status, got_status)}, want "
                         f"{c['status']} (input {c['input']})")
        # Values are compared whenever the status agrees, except where an input is outside
        # float range (there the float input is a different number altogether).
        compare_values = status_ok and why in (None, "float-unresolvable")

        def chk(out: str, got: float, want: Any, sens: float, t: dict | None = None) -> None:
            if not compare_values:
                if not math.isfinite(got):
                    rep.fail(f"{cid} {fn} {out}: not finite")
                return
            check(rep, f"{fn} {out}", cid, got, want, sens, t if t is not None else tol(fn, out))

        if fn in ("check_physical", "check_perceptual"):
            rep.stats.setdefault(f"{fn} status", Stat()).checks += 1
            continue
        if fn == "material_init":
            if "lobes" not in exp or not compare_values:
                continue
            if int(io[1]) != int(exp["lobes"]):
                rep.fail(f"{cid} material_init lobes {io[1]}, want {exp['lobes']}")
            if got_status != 0:
                if not (o[12] == 0 and o[13] == 0 and o[14] == 0):
                    rep.fail(f"{cid} material_init: a failed init must give a black material")
                continue
            if int(io[2]) != int(c["input"]["p"]["normalization"]):
                rep.fail(f"{cid} material_init normalization {io[2]}")
            for k in range(3):
                chk("rho_d", o[k], exp["rho_d"][k], sens_at(c, "rho_d", k))
            for k, name in enumerate(["rho_s", "alpha_x", "alpha_y", "inv_alpha_x", "inv_alpha_y",
                                      "spec_scale", "pdf_scale", "weight_diffuse", "weight_specular"]):
                chk(name, o[3 + k], exp[name], sens_at(c, name))
            continue
        outs: dict[str, list[tuple[int, int]]] = {
            "lightness_from_luminance": [("L", 0)], "luminance_from_lightness": [("Y", 0)],
            "contrast_gloss": [("c", 0)], "specular_from_contrast": [("rho_s", 0)],
            "gloss_from_physical": [("L", 0), ("c", 1), ("d", 2)],
            "physical_from_gloss": [("rho_d", 0), ("rho_s", 1), ("alpha", 2)],
            "gloss_distance": [("D", 0)], "envelope_contrast": [("c_max", 0)],
            "match_gloss": [("rho_d_out", 0), ("rho_s_out", 1)], "luminance": [("Y", 0)],
            "specular_probability": [("P", 0)],
            "perceptual_from_physical": [("L", 0), ("a", 1), ("b", 2), ("c", 3), ("d", 4)],
            "physical_from_perceptual": [("rho_s", 3), ("alpha_x", 4), ("alpha_y", 5)],
        }.get(fn, [])
        if fn == "isogloss_contour":
            k = j.point
            if int(c["input"]["n"]) == 0:
                continue
            chk("c", o[0], exp["c"][k], sens_at(c, "c", k))
            chk("d", o[1], exp["d"][k], sens_at(c, "d", k))
            continue
        if fn in ("rgb_from_lab", "lab_from_rgb"):
            out = "rgb" if fn == "rgb_from_lab" else "lab"
            for k in range(3):
                w = exp[out]
                chk(out, o[k], None if w is None else w[k], sens_at(c, out, k))
            continue
        if fn == "physical_from_perceptual":
            w = exp.get("rho_d")
            for k in range(3):
                chk("rho_d", o[k], None if w is None else w[k], sens_at(c, "rho_d", k))
            if exp.get("normalization") is not None and int(io[1]) != int(exp["normalization"]):
                rep.fail(f"{cid} physical_from_perceptual normalization {io[1]}")
        for name, k in outs:
            if name in exp:
                chk(name, o[k], exp[name], sens_at(c, name))


def flushed_to_zero_direction(job: Job) -> bool:
    """True if wo (or wi, for eval) has a denormal component and is all zero after flushing
    denormals to zero."""
    dirs = [job.fin[6:9]] + ([job.fin[9:12]] if job.fn == "eval_pdf" else [])
    for d in dirs:
        if any(0 < abs(x) < FLT_MIN for x in d) and all(abs(x) < FLT_MIN for x in d):
            return True
    return False


def sample_exponent(doc: dict, c: dict) -> float:
    """x = ((h.x/αx)² + (h.y/αy)²)/h.z² at the expected wi (only scales the exp ULP term)."""
    e = c["expected"]
    if e.get("wi") is None or num(e["pdf"]) == 0:
        return 0.0
    m = doc["materials"][c["input"]["material"]]
    wo = np.array([num(x) for x in c["input"]["wo"]])
    n = np.linalg.norm(wo)
    if not np.isfinite(n) or n == 0:
        return 0.0
    h = wo / n + np.array([num(x) for x in e["wi"]])
    ax, ay = max(num(m["alpha_x"]), 1e-4), max(num(m["alpha_y"]), 1e-4)
    if h[2] <= 0:
        return 0.0
    return float(((h[0] / ax) ** 2 + (h[1] / ay) ** 2) / h[2] ** 2)


def run_all(ctx, files: Iterable[str] = FILES, defines: Iterable[str] = (),
            select: Callable[[Job], bool] | None = None, stage: str = "comp") -> Report:
    rep = Report()
    for file in files:
        doc = json.loads((VECTORS / file).read_text())
        if doc.get("format") != "pgloss-vectors" or doc.get("version") != 1:
            rep.fail(f"{file}: not a pgloss-vectors version 1 file")
            continue
        jobs, skipped = jobs_of(doc, file)
        rep.skipped_null += skipped
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
    import sys
    r = run_all(ctx, stage=sys.argv[1] if len(sys.argv) > 1 else "comp")
    print(r.summary())
    print(f"{len(r.failures)} failures")
    for f in r.failures[:60]:
        print("  ", f)
