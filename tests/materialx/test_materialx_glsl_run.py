# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The GLSL that MaterialX's ShaderGen makes from materialx/pgloss, run on llvmpipe through
moderngl (EGL, the harness of tests/glsl), against the C core (libpgloss through ctypes,
tests/osl/cref.py).

The material is generated with one directional light bound (ND_directional_light) and the
environment light's intensity set to 0, so a pixel's colour is exactly f(wo, wi) cos θi of the BSDF node. Each
pixel is one (wo, wi) pair: the vertex shader puts the surface at -wo under a camera at the
origin with the normal +z, and the light (one draw per wi) shines along -wi.
"""
from __future__ import annotations

import ctypes as C
import math
import sys
from pathlib import Path

import numpy as np
import pytest

mx = pytest.importorskip("MaterialX", reason="the MaterialX package is what these tests exercise")
moderngl = pytest.importorskip("moderngl", reason="moderngl runs the generated GLSL on llvmpipe")
import MaterialX.PyMaterialXGenGlsl as mx_glsl  # noqa: E402
import MaterialX.PyMaterialXGenShader as mx_gen  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "osl"))
import cref  # noqa: E402  (the C core through ctypes)

from test_materialx import search_path  # noqa: E402

VERT = """#version 400
in vec3 i_wo;
uniform vec2 u_pixel;        // this draw's pixel row
uniform float u_count;
out VertexData { vec3 normalWorld; vec3 positionWorld; } vd;
void main() {
    vd.normalWorld = vec3(0.0, 0.0, 1.0);
    vd.positionWorld = -i_wo;  // V = normalize(u_viewPosition - P) = wo with u_viewPosition = 0
    float x = (float(gl_VertexID) + 0.5) / u_count * 2.0 - 1.0;
    gl_Position = vec4(x, u_pixel.y, 0.0, 1.0);
    gl_PointSize = 1.0;
}
"""


def _dir(theta: float, phi: float) -> tuple:
    return (math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta))


def _directions() -> tuple:
    wos = [_dir(t, p) for t in (0.05, 0.4, 0.9, 1.3) for p in (0.0, 2.0, 4.0)]
    wis = [_dir(t, p) for t in (0.1, 0.5, 1.1) for p in (0.3, 3.3)]
    # Near the mirror directions, where the specular lobe matters most.
    wis += [(-wo[0] * 0.999, -wo[1] * 0.999, math.sqrt(1 - 0.998001 * (wo[0] ** 2 + wo[1] ** 2))) for wo in wos[3:6]]
    return wos, wis


def _shader(doc, material: str):
    gen = mx_glsl.GlslShaderGenerator.create()
    ctx = mx_gen.GenContext(gen)
    ctx.registerSourceCodeSearchPath(search_path())
    ctx.getOptions().hwMaxActiveLightSources = 1
    mx_gen.HwShaderGenerator.bindLightShader(doc.getNodeDef("ND_directional_light"), 1, ctx)
    return gen.generate(material, doc.getChild(material), ctx).getSourceCode(mx_gen.PIXEL_STAGE)


def _doc(kind: str, values: dict):
    lib = mx.createDocument()
    mx.loadLibraries(["libraries", "pgloss"], search_path(), lib)
    doc = mx.createDocument()
    doc.importLibrary(lib)
    node = doc.addNode(kind, "SR", "surfaceshader")
    for k, v in values.items():
        node.setInputValue(k, mx.Color3(*v) if isinstance(v, tuple) else v)
    doc.addMaterialNode("M", node)
    return doc


def _reference(phys: "cref.Physical", wos, wis) -> np.ndarray:
    lib = cref.lib()
    m = cref.Material()
    assert lib.pgloss_material_init(C.byref(m), C.byref(phys)) >= 0

    class V3(C.Structure):
        _fields_ = [("x", C.c_float), ("y", C.c_float), ("z", C.c_float)]

    out = np.zeros((len(wis), len(wos), 3))
    for j, wi in enumerate(wis):
        for i, wo in enumerate(wos):
            f = V3()
            lib.pgloss_eval(C.byref(m), V3(*wo), V3(*wi), 3, C.byref(f))
            out[j, i] = np.array([f.x, f.y, f.z]) * wi[2]
    return out


def _perceptual_physical(q: tuple, space: int) -> "cref.Physical":
    p = cref.Physical()
    st = cref.lib().pgloss_physical_from_perceptual_ex(C.byref(cref.Perceptual(*q)), 0, space, C.byref(p))
    assert st >= 0, st
    return p


CASES = {
    "physical": ("pgloss_physical_surface", {"rho_d": (0.193, 0.3, 0.05), "rho_s": 0.066, "alpha": 0.07},
                 lambda: cref.Physical((C.c_double * 3)(0.193, 0.3, 0.05), 0.066, 0.07, 0.07, 0)),
    "fig14_rec709": ("pgloss_surface", {"lightness": 35.0, "a": 45.0, "b": 25.0, "c": 0.06, "d": 0.95},
                     lambda: _perceptual_physical((35.0, 45.0, 25.0, 0.06, 0.95), 0)),
    "acescg": ("pgloss_surface", {"lightness": 60.0, "a": -30.0, "b": 20.0, "c": 0.04, "d": 0.9, "color_space": 1},
               lambda: _perceptual_physical((60.0, -30.0, 20.0, 0.04, 0.9), 1)),
}


@pytest.mark.parametrize("name", list(CASES))
def test_generated_glsl_matches_the_c_core(gl, name: str) -> None:
    kind, values, phys = CASES[name]
    doc = _doc(kind, values)
    frag = _shader(doc, "M")
    wos, wis = _directions()
    prog = gl.program(vertex_shader=VERT, fragment_shader=frag)
    fbo = gl.framebuffer(color_attachments=[gl.texture((len(wos), len(wis)), 4, dtype="f4")])
    fbo.use()
    fbo.clear(-1.0, -1.0, -1.0, -1.0)
    vbo = gl.buffer(np.array(wos, dtype="f4").tobytes())
    vao = gl.vertex_array(prog, [(vbo, "3f", "i_wo")])
    prog["u_count"].value = float(len(wos))
    prog["u_numActiveLightSources"].value = 1
    prog["u_envLightIntensity"].value = 0.0
    prog["u_lightData[0].type"].value = 1
    prog["u_lightData[0].color"].value = (1.0, 1.0, 1.0)
    prog["u_lightData[0].intensity"].value = 1.0
    for j, wi in enumerate(wis):
        prog["u_lightData[0].direction"].value = tuple(-x for x in wi)
        prog["u_pixel"].value = (0.0, (j + 0.5) / len(wis) * 2.0 - 1.0)
        vao.render(moderngl.POINTS)
    got = np.frombuffer(fbo.read(components=4, dtype="f4"), dtype="f4").reshape(len(wis), len(wos), 4)[..., :3]
    want = _reference(phys(), wos, wis)
    assert np.all(want >= 0) and want.max() > 0.1, want.max()
    # float32 on both sides (the C core's eval is float); the GLSL port meets the vectors'
    # float tolerance, far below this.
    np.testing.assert_allclose(got, want, rtol=2e-5, atol=1e-6)
