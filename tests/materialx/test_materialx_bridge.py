# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The gloss bridge as MaterialX nodes (materialx/pgloss/pgloss_bridge.mtlx) against the C bridge
(libpgloss through ctypes: pgloss_bridge_from_perceptual, pgloss_bridge_to_perceptual).

- the nodes validate, and their graphs use MaterialX's standard nodes only: the sample document
  validates and generates code for every ShaderGen target of the package (GLSL, ESSL, Vulkan
  GLSL, MSL, MDL, Slang, OSL) with nothing of pgloss's code on the search path, and its GLSL and
  ESSL compile with glslangValidator;
- the GLSL that ShaderGen makes from <pgloss_bridge_from_perceptual>, run on llvmpipe, gives
  parameters that the C bridge reads back as the requested paint, within the errors stated in
  docs/materialx.md, at the paper's paints and at random reachable ones; out-of-reach and
  invalid inputs give finite parameters inside the targets' box.
"""
from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

mx = pytest.importorskip("MaterialX", reason="the MaterialX package is what these tests exercise")
moderngl = pytest.importorskip("moderngl", reason="moderngl runs the generated GLSL on llvmpipe")
import MaterialX.PyMaterialXGenGlsl as mx_glsl  # noqa: E402
import MaterialX.PyMaterialXGenOsl as mx_osl  # noqa: E402
import MaterialX.PyMaterialXGenShader as mx_gen  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
sys.path[:0] = [str(ROOT / "materialx"), str(Path(__file__).resolve().parent)]
import bridge_graph as bg  # noqa: E402  (the ctypes bindings of the C bridge; the graph's boxes)
import bridge_paints as bp  # noqa: E402

MX_ROOT = Path(mx.__file__).resolve().parent
LIBRARY = ROOT / "materialx" / "pgloss" / "pgloss_bridge.mtlx"
SAMPLE = ROOT / "materialx" / "examples" / "pgloss_bridge_paint.mtlx"
OUT = ROOT / "out" / "materialx"


def standard_search_path() -> "mx.FileSearchPath":
    """MaterialX's own libraries only: no pgloss folder, no pgloss source code."""
    sp = mx.FileSearchPath(str(MX_ROOT))
    sp.append(str(MX_ROOT / "libraries"))
    return sp


def standard_library() -> "mx.Document":
    lib = mx.createDocument()
    mx.loadLibraries(["libraries"], standard_search_path(), lib)
    return lib


def load(path: Path) -> "mx.Document":
    """A document read as a host without pgloss's search path would (XIncludes resolved), with
    MaterialX's standard libraries imported."""
    doc = mx.createDocument()
    mx.readFromXmlFile(doc, str(path), standard_search_path())
    doc.importLibrary(standard_library())
    return doc


def bridge_library() -> "mx.Document":
    return load(LIBRARY)


def test_bridge_nodes_validate_and_use_standard_nodes_only() -> None:
    doc = bridge_library()
    ok, msg = doc.validate()
    assert ok, msg
    std = standard_library()
    own = {nd.getName() for nd in doc.getNodeDefs() if nd.getName().startswith("ND_pgloss_")}
    assert own == {"ND_pgloss_bridge_from_perceptual", "ND_pgloss_open_pbr_surface", "ND_pgloss_standard_surface"}
    for ng in doc.getNodeGraphs():
        if not ng.getName().startswith("NG_pgloss_"):
            continue
        assert ng.getNodeDef() is not None and ng.getNodeDef().getName() in own
        for node in ng.getNodes():
            nd = node.getNodeDef()
            assert nd is not None, (ng.getName(), node.getName(), node.getCategory())
            assert nd.getName() in own or std.getNodeDef(nd.getName()) is not None, (ng.getName(), nd.getName())
    for nd in own:  # UI metadata on every input
        for inp in doc.getNodeDef(nd).getInputs():
            assert inp.getAttribute("uiname"), (nd, inp.getName())


def _generators() -> dict:
    """Every ShaderGen target of the MaterialX package: GLSL, ESSL, Vulkan GLSL, MSL, MDL, Slang, OSL."""
    import MaterialX.PyMaterialXGenMdl as mx_mdl  # noqa: PLC0415
    import MaterialX.PyMaterialXGenMsl as mx_msl  # noqa: PLC0415
    import MaterialX.PyMaterialXGenSlang as mx_slang  # noqa: PLC0415
    return {"frag": mx_glsl.GlslShaderGenerator.create(), "essl.frag": mx_glsl.EsslShaderGenerator.create(),
            "vk.frag": mx_glsl.VkShaderGenerator.create(), "metal": mx_msl.MslShaderGenerator.create(),
            "mdl": mx_mdl.MdlShaderGenerator.create(), "slang": mx_slang.SlangShaderGenerator.create(),
            "osl": mx_osl.OslShaderGenerator.create()}


def test_sample_generates_for_every_target_without_pgloss_code() -> None:
    doc = load(SAMPLE)  # with its XInclude of the library
    ok, msg = doc.validate()
    assert ok, msg
    OUT.mkdir(parents=True, exist_ok=True)
    materials = [m.getName() for m in doc.getMaterialNodes()]
    assert materials == ["M_fig14_red_openpbr", "M_fig14_red_standard_surface"]
    glslang = shutil.which("glslangValidator")
    if glslang is None:
        pytest.skip("glslangValidator (Debian glslang-tools) is missing")
    for ext, gen in _generators().items():
        for name in materials:
            ctx = mx_gen.GenContext(gen)
            ctx.registerSourceCodeSearchPath(standard_search_path())
            shader = gen.generate(name, doc.getChild(name), ctx)
            src = shader.getSourceCode(mx_gen.PIXEL_STAGE)
            assert "pgloss_material_init" not in src and "bridge_from_perceptual" in src, (ext, name)
            (OUT / f"{name}.{ext}").write_text(src)  # the Cycles test renders the .osl
            if ext in ("frag", "essl.frag"):  # both stages compile (desktop GLSL 4.0, OpenGL ES 3.0)
                (OUT / f"{name}.{ext[:-4]}vert").write_text(shader.getSourceCode(mx_gen.VERTEX_STAGE))
                for stage, path in (("frag", OUT / f"{name}.{ext}"), ("vert", OUT / f"{name}.{ext[:-4]}vert")):
                    r = subprocess.run([glslang, "-S", stage, str(path)], capture_output=True, text=True)
                    assert r.returncode == 0, (path, r.stdout + r.stderr)


# ---------------------------------------------------------------- the generated GLSL on llvmpipe

VERT = """#version 400
uniform float u_x;
void main() { gl_Position = vec4(u_x, 0.0, 0.0, 1.0); gl_PointSize = 1.0; }
"""


def _bridge_shaders(gen) -> dict:
    """Shaders of the bridge node's outputs: base_color, and (roughness, f0, 0)."""
    doc = bridge_library()
    node = doc.addNode("pgloss_bridge_from_perceptual", "BR", "multioutput")
    spec = doc.addNode("combine3", "spec", "vector3")
    for port, output in (("in1", "roughness"), ("in2", "f0")):
        inp = spec.addInput(port, "float")
        inp.setConnectedNode(node)
        inp.setOutputString(output)
    out_base = doc.addOutput("o_base", "color3")
    out_base.setConnectedNode(node)
    out_base.setOutputString("base_color")
    out_spec = doc.addOutput("o_spec", "vector3")
    out_spec.setConnectedNode(spec)
    for name in ("lightness", "a", "b", "c", "d"):
        node.setInputValue(name, 0.0)
    ok, msg = doc.validate()
    assert ok, msg
    shaders = {}
    for out in (out_base, out_spec):
        ctx = mx_gen.GenContext(gen)
        ctx.registerSourceCodeSearchPath(standard_search_path())
        shaders[out.getName()] = gen.generate(out.getName(), out, ctx).getSourceCode(mx_gen.PIXEL_STAGE)
    return shaders


def run_glsl(gl, paints: np.ndarray) -> np.ndarray:
    """The generated GLSL at each paint (one pixel per paint): rows (r, g, b, roughness, f0)."""
    shaders = _bridge_shaders(mx_glsl.GlslShaderGenerator.create())
    n = len(paints)
    got = []
    for name in ("o_base", "o_spec"):
        prog = gl.program(vertex_shader=VERT, fragment_shader=shaders[name])
        fbo = gl.framebuffer(color_attachments=[gl.texture((n, 1), 4, dtype="f4")])
        fbo.use()
        fbo.clear(-1.0, -1.0, -1.0, -1.0)
        vao = gl.vertex_array(prog, [])
        for i, p in enumerate(paints):
            for key, v in zip(("lightness", "a", "b", "c", "d"), p):
                prog[f"BR_{key}"].value = float(v)
            prog["u_x"].value = (i + 0.5) / n * 2.0 - 1.0
            vao.render(moderngl.POINTS, vertices=1)
        got.append(np.frombuffer(fbo.read(components=4, dtype="f4"), dtype="f4").reshape(n, 4)[:, :3])
    return np.concatenate([got[0], got[1][:, :2]], axis=1).astype(float)


def test_generated_glsl_against_the_c_bridge(gl) -> None:
    paints = bp.all_paints()
    print("\nbridge graph, GLSL on llvmpipe: " + bp.check_against_c(bg, paints, run_glsl(gl, paints)))


def test_genosl_for_cycles() -> None:
    """The OSL of the bridge node's outputs, and the sample's paint as open_pbr_surface /
    standard_surface with the C bridge's own parameters: tests/materialx/cycles renders them."""
    OUT.mkdir(parents=True, exist_ok=True)
    for name, src in _bridge_shaders(mx_osl.OslShaderGenerator.create()).items():
        (OUT / f"bridge_{name}.osl").write_text(src)
    lib = bg.bridge_lib()
    for target, node, names in ((0, "open_pbr_surface", ("base_color", "specular_roughness", "specular_ior",
                                                         "specular_weight")),
                                (1, "standard_surface", ("base_color", "specular_roughness", "specular_IOR",
                                                         "specular"))):
        st, p, _ = bg.from_paint(lib, bp.FIG14_RED, target)
        assert st == 0, st
        doc = mx.createDocument()
        doc.importLibrary(standard_library())
        shader = doc.addNode(node, "SR", "surfaceshader")
        shader.setInputValue(names[0], mx.Color3(*p.base_color))
        for key, v in zip(names[1:], (p.roughness, p.ior, p.specular)):
            shader.setInputValue(key, float(v))
        if node == "open_pbr_surface":
            shader.setInputValue("base_weight", 1.0)
        else:
            shader.setInputValue("base", 1.0)
        m = doc.addMaterialNode("M", shader)
        gen = mx_osl.OslShaderGenerator.create()
        ctx = mx_gen.GenContext(gen)
        ctx.registerSourceCodeSearchPath(standard_search_path())
        src = gen.generate(f"M_fig14_red_{target}_c", m, ctx).getSourceCode(mx_gen.PIXEL_STAGE)
        suffix = "openpbr" if target == 0 else "standard_surface"
        (OUT / f"M_fig14_red_{suffix}_c_bridge.osl").write_text(src)
