# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The MaterialX library (materialx/pgloss) with the MaterialX Python package (PyPI, 1.39.x).

- the library and the sample material validate against MaterialX's standard libraries;
- ShaderGen generates GLSL and OSL for materials that use every pgloss node;
- the generated GLSL (vertex and fragment stages) compiles with glslangValidator;
- the implementations are built on glsl/pgloss.glsl and osl/pgloss.h: the generated code holds
  those files' text, not another copy of the formulas.
"""
from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

mx = pytest.importorskip("MaterialX", reason="the MaterialX package is what these tests exercise")
import MaterialX.PyMaterialXGenGlsl as mx_glsl  # noqa: E402
import MaterialX.PyMaterialXGenOsl as mx_osl  # noqa: E402
import MaterialX.PyMaterialXGenShader as mx_gen  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
MX_ROOT = Path(mx.__file__).resolve().parent
SAMPLE = ROOT / "materialx" / "examples" / "pgloss_paint.mtlx"
OUT = ROOT / "out" / "materialx"


def search_path() -> "mx.FileSearchPath":
    """What a host application sets up: MaterialX's own libraries plus pgloss's folder."""
    sp = mx.FileSearchPath(str(MX_ROOT))
    sp.append(str(MX_ROOT / "libraries"))
    sp.append(str(ROOT / "materialx"))
    return sp


@pytest.fixture(scope="module")
def library() -> "mx.Document":
    lib = mx.createDocument()
    mx.loadLibraries(["libraries", "pgloss"], search_path(), lib)
    return lib


def test_library_validates(library) -> None:
    ok, msg = library.validate()
    assert ok, msg
    for nd in ("ND_pgloss_bsdf", "ND_pgloss_perceptual_bsdf", "ND_pgloss_surface", "ND_pgloss_physical_surface"):
        nodedef = library.getNodeDef(nd)
        assert nodedef is not None, nd
        for inp in nodedef.getInputs():  # UI metadata on every input
            assert inp.getAttribute("uiname"), (nd, inp.getName())
    for nd in ("ND_pgloss_bsdf", "ND_pgloss_perceptual_bsdf"):
        impls = {i.getTarget() for i in library.getImplementations() if i.getNodeDefString() == nd}
        assert impls == {"genglsl", "genosl"}, (nd, impls)
    for nd in ("ND_pgloss_surface", "ND_pgloss_physical_surface"):
        assert library.getNodeDef(nd).getImplementation() is not None, nd


def _physical_doc(library) -> "mx.Document":
    doc = mx.createDocument()
    doc.importLibrary(library)
    s = doc.addNode("pgloss_physical_surface", "SR_grey", "surfaceshader")
    s.setInputValue("rho_d", mx.Color3(0.193, 0.193, 0.193))
    s.setInputValue("rho_s", 0.066)
    s.setInputValue("alpha", 0.07)
    m = doc.addMaterialNode("M_grey", s)
    assert m is not None
    return doc


def _sample_doc(library) -> "mx.Document":
    doc = mx.createDocument()
    mx.readFromXmlFile(doc, str(SAMPLE))
    doc.importLibrary(library)
    return doc


def test_sample_document_validates(library) -> None:
    for doc in (_sample_doc(library), _physical_doc(library)):
        ok, msg = doc.validate()
        assert ok, msg


def _generate(generator, doc, material: str) -> "mx_gen.Shader":
    ctx = mx_gen.GenContext(generator)
    ctx.registerSourceCodeSearchPath(search_path())
    return generator.generate(material, doc.getChild(material), ctx)


CASES = [("sample", "M_fig14_red"), ("physical", "M_grey")]


def _doc(library, which: str):
    return _sample_doc(library) if which == "sample" else _physical_doc(library)


@pytest.mark.parametrize("which,material", CASES)
def test_genglsl_compiles(library, which: str, material: str, tmp_path: Path) -> None:
    glslang = shutil.which("glslangValidator")
    if glslang is None:
        pytest.skip("glslangValidator (Debian glslang-tools) is missing")
    shader = _generate(mx_glsl.GlslShaderGenerator.create(), _doc(library, which), material)
    OUT.mkdir(parents=True, exist_ok=True)
    for stage, ext in ((mx_gen.VERTEX_STAGE, "vert"), (mx_gen.PIXEL_STAGE, "frag")):
        src = shader.getSourceCode(stage)
        path = OUT / f"{material}.{ext}"
        path.write_text(src)
        r = subprocess.run([glslang, "-S", ext, str(path)], capture_output=True, text=True)
        assert r.returncode == 0, r.stdout + r.stderr
    frag = shader.getSourceCode(mx_gen.PIXEL_STAGE)
    # Built on glsl/pgloss.glsl: its code is in the shader (once), and the node calls it.
    port = (ROOT / "glsl" / "pgloss.glsl").read_text()
    body = port[port.index("#ifndef PGLOSS_GLSL"):]
    assert frag.count("int pgloss_material_init(") == 1
    assert body.splitlines()[40] in frag
    assert "mx_pgloss_bsdf(" in frag
    if which == "sample":
        assert "pgloss_physical_from_perceptual_ex(" in frag


@pytest.mark.parametrize("which,material", CASES)
def test_genosl_generates(library, which: str, material: str) -> None:
    shader = _generate(mx_osl.OslShaderGenerator.create(), _doc(library, which), material)
    src = shader.getSourceCode(mx_gen.PIXEL_STAGE)
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / f"{material}.osl").write_text(src)
    assert src.count("closure color pgloss_closure(") == 1  # osl/pgloss.h's closures, once
    assert "int pgloss_material_init(" in src
    assert "mx_pgloss_bsdf(" in src
    if which == "sample":
        assert "pgloss_physical_from_perceptual_ex(" in src
    assert "surface" in src.split("(")[0] or "shader" in src
