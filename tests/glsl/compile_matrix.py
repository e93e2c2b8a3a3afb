# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Compile matrix of glsl/pgloss.glsl with glslangValidator, and SPIR-V size of feature builds.

Targets x stages x feature builds. Each source is "#version ..." + the build's #defines +
pgloss.glsl (pasted, as a shader writer would; the Vulkan targets #include it through
GL_GOOGLE_include_directive instead) + a probe main() that calls every function the build
has, with inputs from a uniform block / buffer (so that nothing is constant-folded away).

    python tests/glsl/compile_matrix.py          # run the matrix, print the SPIR-V size table
"""
from __future__ import annotations

import itertools
import os
import pathlib
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass

ROOT = pathlib.Path(__file__).resolve().parents[2]
GLSL_DIR = ROOT / "glsl"
GLSL = GLSL_DIR / "pgloss.glsl"


@dataclass(frozen=True)
class Target:
    name: str
    version: str          # the #version line's argument
    stages: tuple[str, ...]
    vulkan: bool = False
    target_env: str = ""  # glslangValidator --target-env for Vulkan


TARGETS = [
    Target("glsl330", "330 core", ("vert", "frag")),
    Target("glsl450", "450 core", ("vert", "frag", "comp")),
    Target("essl300", "300 es", ("vert", "frag")),
    Target("essl310", "310 es", ("comp",)),
    Target("vulkan450", "450", ("vert", "frag", "comp"), True, "vulkan1.0"),
    # GL_EXT_ray_tracing needs #version 460 and SPIR-V 1.4 (Vulkan 1.2).
    Target("vulkan460-rt", "460", ("rgen", "rchit", "rmiss", "rcall"), True, "vulkan1.2"),
]

ALL_SWITCHES = ["PGLOSS_NO_DIFFUSE", "PGLOSS_NO_SPECULAR", "PGLOSS_NO_ANISOTROPY",
                "PGLOSS_NO_NORM_WARD_DUR", "PGLOSS_NO_NORM_BOUNDED", "PGLOSS_NO_SAMPLING",
                "PGLOSS_NO_PERCEPTUAL", "PGLOSS_NO_CONVERSIONS"]

BUILDS: dict[str, tuple[str, ...]] = {
    "full": (),
    "diffuse-only": ("PGLOSS_NO_SPECULAR",),
    "specular-only": ("PGLOSS_NO_DIFFUSE",),
    "isotropic": ("PGLOSS_NO_ANISOTROPY",),
    "no-ward-dur": ("PGLOSS_NO_NORM_WARD_DUR",),
    "no-bounded": ("PGLOSS_NO_NORM_BOUNDED",),
    "eq2-only": ("PGLOSS_NO_NORM_WARD_DUR", "PGLOSS_NO_NORM_BOUNDED"),
    "no-sampling": ("PGLOSS_NO_SAMPLING",),
    "no-perceptual": ("PGLOSS_NO_PERCEPTUAL",),
    "no-conversions": ("PGLOSS_NO_CONVERSIONS",),
    "specular-minimal": ("PGLOSS_NO_DIFFUSE", "PGLOSS_NO_ANISOTROPY", "PGLOSS_NO_NORM_WARD_DUR",
                         "PGLOSS_NO_NORM_BOUNDED", "PGLOSS_NO_PERCEPTUAL"),
    "diffuse-minimal": ("PGLOSS_NO_SPECULAR", "PGLOSS_NO_PERCEPTUAL"),
    "minimal": ("PGLOSS_NO_ANISOTROPY", "PGLOSS_NO_NORM_WARD_DUR", "PGLOSS_NO_NORM_BOUNDED",
                "PGLOSS_NO_PERCEPTUAL", "PGLOSS_NO_SAMPLING"),
}

# The probe: every function the build has. IN0..IN3 are vec4 inputs the stage provides.
PROBE = r"""
vec4 pgloss_probe(vec4 in0, vec4 in1, vec4 in2, vec4 in3)
{
    pgloss_physical p = pgloss_physical(in0.xyz, in0.w, in1.x, in1.y, int(in1.z));
    pgloss_material m;
    int st = pgloss_material_init(m, p);
    uint lobes = uint(in1.w);
    vec3 f;
    float pdf;
    st += pgloss_eval(m, in2.xyz, in3.xyz, lobes, f);
    vec4 acc = vec4(f, 0.0);
    st += pgloss_pdf(m, in2.xyz, in3.xyz, lobes, pdf);
    acc.w += pdf;
    st += pgloss_eval_pdf(m, in2.xyz, in3.xyz, lobes, f, pdf);
    acc += vec4(f, pdf);
    acc.w += pgloss_specular_probability(m, lobes);
#ifndef PGLOSS_NO_SAMPLING
    pgloss_sample_record r;
    st += pgloss_sample(m, in2.xyz, in3.xyz, lobes, r);
    acc += vec4(r.wi + r.weight, r.pdf + float(r.lobe));
#endif
#ifndef PGLOSS_NO_PERCEPTUAL
    float a, b, c;
    vec3 v;
    st += pgloss_lightness_from_luminance(in0.x, a); acc.x += a;
    st += pgloss_luminance_from_lightness(in0.y, a); acc.y += a;
    st += pgloss_contrast_gloss(in0.x, in0.w, a); acc.z += a;
    st += pgloss_specular_from_contrast(in0.x, in0.y, a); acc.w += a;
    st += pgloss_gloss_from_physical(in0.x, in0.y, in0.z, a, b, c); acc.xyz += vec3(a, b, c);
    st += pgloss_physical_from_gloss(in1.x, in1.y, in1.z, a, b, c); acc.xyz += vec3(a, b, c);
    st += pgloss_gloss_distance(in0.x, in0.y, in0.z, in0.w, a); acc.x += a;
    st += pgloss_envelope_contrast(in1.x, a); acc.y += a;
    st += pgloss_match_gloss(in0.x, in0.y, in0.z, a, b); acc.xy += vec2(a, b);
    st += pgloss_isogloss_contour(in0.x, in0.y, in0.z, uint(in1.x), uint(in1.y), a, b); acc.xy += vec2(a, b);
    st += pgloss_rgb_from_lab(in2.xyz, v); acc.xyz += v;
    st += pgloss_lab_from_rgb(in3.xyz, v); acc.xyz += v;
    st += pgloss_luminance(in3.xyz, a); acc.x += a;
    st += pgloss_check_physical(p);
    pgloss_perceptual q = pgloss_perceptual(in2.x, in2.y, in2.z, in2.w, in3.w);
    st += pgloss_check_perceptual(q);
    pgloss_physical p2;
    st += pgloss_physical_from_perceptual(q, int(in1.z), p2); acc += vec4(p2.rho_d, p2.rho_s);
    st += pgloss_perceptual_from_physical(p, q); acc += vec4(q.L, q.a, q.b, q.c + q.d);
    int sp = int(in1.w);
    st += pgloss_rgb_from_lab_ex(in2.xyz, sp, v); acc.xyz += v;
    st += pgloss_lab_from_rgb_ex(in3.xyz, sp, v); acc.xyz += v;
    st += pgloss_luminance_ex(in3.xyz, sp, a); acc.x += a;
    st += pgloss_check_perceptual_ex(q, sp);
    st += pgloss_physical_from_perceptual_ex(q, int(in1.z), sp, p2); acc += vec4(p2.rho_d, p2.rho_s);
    st += pgloss_perceptual_from_physical_ex(p, sp, q); acc += vec4(q.L, q.a, q.b, q.c + q.d);
#endif
    return acc + vec4(float(st));
}
"""

# The "shade" probe: what a path tracer's hit shader does (init, eval_pdf, sample).
SHADE = r"""
vec4 pgloss_probe(vec4 in0, vec4 in1, vec4 in2, vec4 in3)
{
    pgloss_physical p = pgloss_physical(in0.xyz, in0.w, in1.x, in1.y, int(in1.z));
    pgloss_material m;
    int st = pgloss_material_init(m, p);
    vec3 f;
    float pdf;
    st += pgloss_eval_pdf(m, in2.xyz, in3.xyz, PGLOSS_LOBE_ALL, f, pdf);
    vec4 acc = vec4(f, pdf);
#ifndef PGLOSS_NO_SAMPLING
    pgloss_sample_record r;
    st += pgloss_sample(m, in2.xyz, in3.xyz, PGLOSS_LOBE_ALL, r);
    acc += vec4(r.wi + r.weight, r.pdf);
#endif
    return acc + vec4(float(st));
}
"""


def stage_main(target: Target, stage: str) -> str:
    """Declarations + main() feeding the probe from non-constant inputs."""
    binding = "binding = 0, " if target.vulkan else ""
    ubo = (f"layout(std140, {binding.rstrip(', ')}) uniform PglossProbeIn {{ vec4 in0; vec4 in1; vec4 in2; vec4 in3; }} pin;\n"
           if binding else "layout(std140) uniform PglossProbeIn { vec4 in0; vec4 in1; vec4 in2; vec4 in3; } pin;\n")
    call = "pgloss_probe(pin.in0, pin.in1, pin.in2, pin.in3)"
    loc = "layout(location = 0) " if (target.vulkan or target.version == "300 es") else ""
    if stage == "vert":
        return ubo + f"void main() {{ gl_Position = {call}; }}\n"
    if stage == "frag":
        return ubo + f"{loc}out vec4 pgloss_probe_out;\nvoid main() {{ pgloss_probe_out = {call}; }}\n"
    if stage == "comp":
        ssbo_binding = "binding = 1, " if target.vulkan or target.version in ("450 core", "310 es") else ""
        return (ubo + "layout(local_size_x = 64) in;\n"
                f"layout({ssbo_binding}std430) buffer PglossProbeOut {{ vec4 o[]; }} pout;\n"
                f"void main() {{ pout.o[gl_GlobalInvocationID.x] = {call}; }}\n")
    rt = "#extension GL_EXT_ray_tracing : require\n"
    if stage == "rgen":
        return (rt + ubo + "layout(binding = 1, std430) buffer PglossProbeOut { vec4 o[]; } pout;\n"
                f"void main() {{ pout.o[gl_LaunchIDEXT.x] = {call}; }}\n")
    if stage == "rchit":
        return (rt + ubo + "layout(location = 0) rayPayloadInEXT vec4 payload;\n"
                "hitAttributeEXT vec2 bary;\n"
                f"void main() {{ payload = {call} + vec4(bary, 0.0, 0.0); }}\n")
    if stage == "rmiss":
        return (rt + ubo + "layout(location = 0) rayPayloadInEXT vec4 payload;\n"
                f"void main() {{ payload = {call}; }}\n")
    if stage == "rcall":
        return (rt + ubo + "layout(location = 0) callableDataInEXT vec4 data;\n"
                f"void main() {{ data = {call}; }}\n")
    raise ValueError(stage)


def source(target: Target, stage: str, defines: tuple[str, ...], probe: str = PROBE,
           twice: bool = False) -> str:
    head = f"#version {target.version}\n"
    rt_ext = stage in ("rgen", "rchit", "rmiss", "rcall")
    if target.vulkan:
        head += "#extension GL_GOOGLE_include_directive : require\n"
    head += "".join(f"#define {d} 1\n" for d in defines)
    lib = '#include "pgloss.glsl"\n' if target.vulkan else GLSL.read_text()
    body = lib + (lib if twice else "")  # twice: the include guard must make this harmless
    main = stage_main(target, stage)
    if rt_ext:  # #extension must precede any non-preprocessor token
        head = head.replace("\n", "\n#extension GL_EXT_ray_tracing : require\n", 1)
        main = main.replace("#extension GL_EXT_ray_tracing : require\n", "")
    return head + body + probe + main


def glslang() -> str:
    exe = shutil.which("glslangValidator")
    if not exe:
        raise RuntimeError("glslangValidator not found (Debian package glslang-tools)")
    return exe


def compile_one(target: Target, stage: str, defines: tuple[str, ...], probe: str = PROBE,
                spv_out: pathlib.Path | None = None, twice: bool = False) -> subprocess.CompletedProcess:
    src = source(target, stage, defines, probe, twice)
    with tempfile.TemporaryDirectory() as tmp:
        path = pathlib.Path(tmp) / f"probe.{stage}"
        path.write_text(src)
        cmd = [glslang(), "-I" + str(GLSL_DIR)]
        if target.vulkan:
            cmd += ["-V", "--target-env", target.target_env]
            cmd += ["-o", str(spv_out) if spv_out else os.path.join(tmp, "probe.spv")]
        cmd.append(str(path))
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode == 0 and target.vulkan:  # and the SPIR-V must validate
            spv = cmd[cmd.index("-o") + 1]
            v = subprocess.run(["spirv-val", "--target-env", target.target_env, spv],
                               capture_output=True, text=True)
            if v.returncode:
                return subprocess.CompletedProcess(cmd + ["&& spirv-val"], v.returncode,
                                                   r.stdout + v.stdout, r.stderr + v.stderr)
        return r


def matrix() -> list[tuple[Target, str, str]]:
    return [(t, s, b) for t in TARGETS for s in t.stages for b in BUILDS]


# ---------------------------------------------------------------------------------------
# SPIR-V size


# Debug-information instructions (names, source text, line info): not counted as code.
DEBUG_OPS = {"OpName", "OpMemberName", "OpSource", "OpSourceExtension", "OpSourceContinued",
             "OpString", "OpLine", "OpNoLine", "OpModuleProcessed"}


def spirv_instructions(spv: pathlib.Path, optimise: bool) -> int:
    """Number of SPIR-V instructions other than debug information (spirv-dis lines, without
    comments and DEBUG_OPS), after spirv-opt -O when optimise."""
    path = spv
    if optimise:
        opt = spv.with_suffix(".opt.spv")
        r = subprocess.run(["spirv-opt", "-O", str(spv), "-o", str(opt)], capture_output=True, text=True)
        if r.returncode:
            raise RuntimeError(r.stderr)
        path = opt
    r = subprocess.run(["spirv-dis", "--no-header", "--raw-id", str(path)], capture_output=True, text=True)
    if r.returncode:
        raise RuntimeError(r.stderr)
    count = 0
    for line in r.stdout.splitlines():
        line = line.strip()
        if not line or line.startswith(";"):
            continue
        # "%5 = OpTypeFloat 32" or "OpStore %a %b"
        op = line.split(" = ", 1)[1].split()[0] if line.startswith("%") else line.split()[0]
        if op not in DEBUG_OPS:
            count += 1
    return count


def size_table() -> str:
    """SPIR-V instruction counts (Vulkan 4.50 compute) per build, for both probes."""
    target = next(t for t in TARGETS if t.name == "vulkan450")
    rows = []
    base: dict[str, int] = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, defines in BUILDS.items():
            counts = []
            for probe_name, probe in (("all", PROBE), ("shade", SHADE)):
                spv = pathlib.Path(tmp) / f"{name}-{probe_name}.spv"
                r = compile_one(target, "comp", defines, probe, spv)
                if r.returncode:
                    raise RuntimeError(f"{name}: {r.stdout}{r.stderr}")
                for optimise in (False, True):
                    counts.append(spirv_instructions(spv, optimise))
            if name == "full":
                base = dict(zip(["a", "ao", "s", "so"], counts))
            rows.append((name, defines, counts))
    out = ["SPIR-V instructions, Vulkan GLSL 4.50 compute shader (glslangValidator -V; "
           "'-O' = after spirv-opt -O)",
           "  probe 'all' calls every function the build has; 'shade' = material_init + eval_pdf + sample",
           f"{'build':18s} {'all':>6s} {'all -O':>7s} {'shade':>6s} {'shade -O':>9s}  (vs full, shade -O)  switches"]
    for name, defines, c in rows:
        pct = 100.0 * (c[3] - base["so"]) / base["so"]
        out.append(f"{name:18s} {c[0]:6d} {c[1]:7d} {c[2]:6d} {c[3]:9d}  ({pct:+6.1f}%)  {' '.join(d.replace('PGLOSS_', '') for d in defines) or '-'}")
    return "\n".join(out)


if __name__ == "__main__":
    fails = 0
    cells = matrix()
    for t, s, b in cells:
        r = compile_one(t, s, BUILDS[b])
        if r.returncode:
            fails += 1
            print(f"FAIL {t.name} {s} {b}\n{r.stdout}{r.stderr}")
    print(f"compile matrix: {len(cells)} compilations ({len(TARGETS)} targets, "
          f"{sum(len(t.stages) for t in TARGETS)} target x stage pairs, {len(BUILDS)} feature builds), "
          f"{fails} failures")
    print(size_table())
