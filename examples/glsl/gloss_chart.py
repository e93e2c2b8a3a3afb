# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Renders a gloss chart with glsl/pgloss.glsl: spheres shaded by the Pellacini–Ferwerda–
Greenberg model, rows of contrast gloss c, columns of distinctness-of-image gloss d, one
panel per CIELAB lightness L* (the paper's three perceptual parameters, eqs. 3–8).

Everything happens in one GLSL 3.30 fragment shader that pastes pgloss.glsl: per pixel,
pgloss_check_perceptual / pgloss_physical_from_perceptual / pgloss_material_init turn
(L*, c, d) into a material, and pgloss_sample importance-samples the BRDF against a small
studio environment (a soft box over a grey gradient sky). Spheres whose (L*, c) lies beyond
the envelope of gloss space (Fig. 10: ρd + ρs > 1) are drawn over a red backdrop.

Headless: an OpenGL context through EGL (Mesa llvmpipe on the CPU works; no display needed).

    .venv-glsl/bin/python examples/glsl/gloss_chart.py [--out out/glsl/gloss_chart.png] [--spp 64]
"""
from __future__ import annotations

import argparse
import os
import pathlib

import moderngl
import numpy as np
from PIL import Image, ImageDraw

ROOT = pathlib.Path(__file__).resolve().parents[2]
GLSL = ROOT / "glsl" / "pgloss.glsl"

LIGHTNESS = [30.0, 60.0, 90.0]
CONTRAST = [0.02, 0.05, 0.08, 0.11, 0.14]      # rows (top: most contrast gloss)
DISTINCTNESS = [0.80, 0.86, 0.90, 0.94, 0.97]  # columns (right: sharpest reflection)

VERTEX = """
#version 330 core
in vec2 pos;
void main() { gl_Position = vec4(pos, 0.0, 1.0); }
"""

FRAGMENT_MAIN = """
uniform float cell;          // cell size in pixels
uniform float margin;        // left/top margin for labels, pixels
uniform float panel_gap;     // pixels between lightness panels
uniform vec2 size;           // image size
uniform int spp;
uniform float Ls[3];
uniform float cs[5];
uniform float ds[5];
out vec4 color;

// A small studio: grey gradient sky, dark floor, and a bright soft box up and to the left.
vec3 environment(vec3 w)
{
    vec3 box_dir = normalize(vec3(-0.45, 0.65, 0.6));
    vec3 c = mix(vec3(0.02), vec3(0.35, 0.38, 0.42), clamp(0.5 + 0.7 * w.y, 0.0, 1.0));
    if (dot(w, box_dir) > 0.94)
        c += vec3(5.0);
    return c;
}

float hash(vec2 p)
{
    p = fract(p * vec2(443.897, 441.423));
    p += dot(p, p.yx + 19.19);
    return fract((p.x + p.y) * p.x);
}

vec3 tonemap(vec3 x)
{
    x = x / (1.0 + x);                      // Reinhard
    return pow(clamp(x, 0.0, 1.0), vec3(1.0 / 2.2));
}

void main()
{
    vec2 px = vec2(gl_FragCoord.x, size.y - gl_FragCoord.y);  // origin top-left
    float panel_w = 5.0 * cell + panel_gap;
    float x = px.x - margin;
    float y = px.y - margin;
    int panel = int(floor(x / panel_w));
    float xp = x - float(panel) * panel_w;
    int col = int(floor(xp / cell));
    int row = int(floor(y / cell));
    if (x < 0.0 || y < 0.0 || panel > 2 || col > 4 || row > 4) {
        color = vec4(vec3(0.93), 1.0);
        return;
    }
    vec2 uv = (vec2(xp, y) - cell * (vec2(col, row) + 0.5)) / (0.46 * cell);
    uv.y = -uv.y;
    pgloss_perceptual q = pgloss_perceptual(Ls[panel], 0.0, 0.0, cs[row], ds[col]);
    int valid = pgloss_check_perceptual(q);
    float r2 = dot(uv, uv);
    if (r2 >= 1.0) {
        color = vec4(valid < 0 ? vec3(0.75, 0.25, 0.2) : vec3(0.18), 1.0);
        return;
    }
    pgloss_physical p;
    pgloss_physical_from_perceptual(q, PGLOSS_NORM_WARD, p);
    pgloss_material m;
    pgloss_material_init(m, p);

    // World: y up, z towards the (orthographic) viewer. Shading frame around the normal.
    vec3 n = vec3(uv, sqrt(1.0 - r2));
    vec3 t = normalize(cross(abs(n.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), n));
    vec3 b = cross(n, t);
    vec3 v = vec3(0.0, 0.0, 1.0);
    vec3 wo = vec3(dot(v, t), dot(v, b), dot(v, n));

    vec3 sum = vec3(0.0);
    vec3 rot = vec3(hash(px), hash(px + 17.0), hash(px + 41.0));
    for (int s = 0; s < spp; ++s) {
        // Roberts' R3 low-discrepancy sequence, randomly rotated per pixel.
        vec3 u = fract(rot + float(s) * vec3(0.8191725134, 0.6710436067, 0.5497004779));
        pgloss_sample_record rec;
        pgloss_sample(m, wo, u, PGLOSS_LOBE_ALL, rec);
        if (rec.pdf > 0.0) {
            vec3 wi = rec.wi.x * t + rec.wi.y * b + rec.wi.z * n;
            sum += rec.weight * environment(wi);
        }
    }
    color = vec4(tonemap(sum / float(spp)), 1.0);
}
"""


def render(out: pathlib.Path, spp: int, cell: int) -> pathlib.Path:
    if os.environ.get("PGLOSS_GLSL_DEVICE", "llvmpipe") == "llvmpipe":
        os.environ.setdefault("LIBGL_ALWAYS_SOFTWARE", "1")
    ctx = moderngl.create_context(standalone=True, backend="egl", require=330)
    margin, gap = 70, 30
    width = margin + 3 * (5 * cell + gap)
    height = margin + 5 * cell + 20
    frag = "#version 330 core\n" + GLSL.read_text() + FRAGMENT_MAIN
    prog = ctx.program(vertex_shader=VERTEX, fragment_shader=frag)
    prog["cell"].value = float(cell)
    prog["margin"].value = float(margin)
    prog["panel_gap"].value = float(gap)
    prog["size"].value = (float(width), float(height))
    prog["spp"].value = spp
    prog["Ls"].value = LIGHTNESS
    prog["cs"].value = CONTRAST[::-1]
    prog["ds"].value = DISTINCTNESS
    quad = ctx.buffer(np.array([-1, -1, 1, -1, -1, 1, 1, 1], np.float32).tobytes())
    vao = ctx.vertex_array(prog, [(quad, "2f", "pos")])
    fbo = ctx.simple_framebuffer((width, height), components=4)
    fbo.use()
    vao.render(moderngl.TRIANGLE_STRIP)
    img = Image.frombytes("RGBA", (width, height), fbo.read(components=4)).transpose(Image.FLIP_TOP_BOTTOM)
    renderer = ctx.info["GL_RENDERER"]
    ctx.release()

    draw = ImageDraw.Draw(img)
    ink = (20, 20, 20, 255)
    for k, L in enumerate(LIGHTNESS):
        x0 = margin + k * (5 * cell + gap)
        draw.text((x0 + 2, 8), f"L* = {L:g}", fill=ink)
        for j, d in enumerate(DISTINCTNESS):
            draw.text((x0 + j * cell + cell // 2 - 14, margin - 18), f"d={d:.2f}", fill=ink)
    for i, c in enumerate(CONTRAST[::-1]):
        draw.text((6, margin + i * cell + cell // 2 - 6), f"c={c:.2f}", fill=ink)
    draw.text((6, height - 16), f"pgloss.glsl, {spp} BRDF samples/pixel, {renderer}", fill=ink)
    out.parent.mkdir(parents=True, exist_ok=True)
    img.convert("RGB").save(out)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", type=pathlib.Path, default=ROOT / "out" / "glsl" / "gloss_chart.png")
    ap.add_argument("--spp", type=int, default=1024, help="BRDF samples per pixel")
    ap.add_argument("--cell", type=int, default=96, help="sphere cell size in pixels")
    a = ap.parse_args()
    print(render(a.out, a.spp, a.cell))


if __name__ == "__main__":
    main()
