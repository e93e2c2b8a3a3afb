# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""A MaterialX surface shader node (open_pbr_surface, standard_surface) with given inputs, as
OSL from MaterialX's own ShaderGen (genosl, PyPI MaterialX 1.39.5), ready for Cycles' Script
node (examples/bridge/harness_cycles.py, material type "osl"). MaterialX's genosl headers are
copied next to the shader so that Cycles' OSL compiler finds them.

    python examples/bridge/materialx_osl.py open_pbr_surface '{"base_color": 0.193,
        "specular_roughness": 0.3, "specular_ior": 1.5}' OUTDIR      # prints the .osl path
"""
from __future__ import annotations

import hashlib
import json
import shutil
import sys
from pathlib import Path
from typing import Optional

NODES = ("open_pbr_surface", "standard_surface")


def osl_shader(node: str, inputs: dict, folder: Path, library: Optional[Path] = None) -> Path:
    """Writes (once per node and inputs) the OSL of a material made of ``node`` with ``inputs``
    (MaterialX input names; a number for a color3 input is grey); returns its path. With
    ``library``, a .mtlx of node definitions read into the document first (e.g. materialx/pgloss/
    pgloss_bridge.mtlx), ``node`` may be any surface node it defines."""
    import MaterialX as mx  # noqa: PLC0415
    import MaterialX.PyMaterialXGenOsl as mx_osl  # noqa: PLC0415
    import MaterialX.PyMaterialXGenShader as mx_gen  # noqa: PLC0415

    if node not in NODES and library is None:
        raise ValueError(f"node must be one of {', '.join(NODES)}, not {node!r}")
    payload = [node, inputs, mx.getVersionString()] + ([library.read_text()] if library is not None else [])
    key = hashlib.sha256(json.dumps(payload, sort_keys=True).encode()).hexdigest()[:12]
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{node}_{key}.osl"
    if path.exists():
        return path
    root = Path(mx.__file__).resolve().parent
    search = mx.FileSearchPath(str(root))
    search.append(str(root / "libraries"))
    lib = mx.createDocument()
    mx.loadLibraries(["libraries"], search, lib)
    doc = mx.createDocument()
    if library is not None:
        mx.readFromXmlFile(doc, str(library), search)
    doc.importLibrary(lib)
    shader = doc.addNode(node, "paint", "surfaceshader")
    nodedef = doc.getNodeDef(f"ND_{node}_surfaceshader") or doc.getNodeDef(f"ND_{node}")
    if nodedef is None:
        raise ValueError(f"no node definition of {node!r}")
    for name, value in inputs.items():
        spec = nodedef.getActiveInput(name)
        if spec is None:
            raise ValueError(f"{node} has no input {name!r}")
        typ = spec.getType()
        if typ == "color3":
            v = [float(value)] * 3 if isinstance(value, (int, float)) else [float(x) for x in value]
            shader.setInputValue(name, mx.Color3(*v[:3]), typ)
        elif typ == "float":
            shader.setInputValue(name, float(value), typ)
        elif typ == "boolean":
            shader.setInputValue(name, bool(value), typ)
        else:
            raise ValueError(f"{node}.{name}: inputs of type {typ} are not supported here")
    material = doc.addMaterialNode("M_paint", shader)
    ok, msg = doc.validate()
    if not ok:
        raise ValueError(f"the MaterialX document does not validate: {msg}")
    gen = mx_osl.OslShaderGenerator.create()
    ctx = mx_gen.GenContext(gen)
    ctx.registerSourceCodeSearchPath(search)
    src = gen.generate("M_paint", material, ctx).getSourceCode(mx_gen.PIXEL_STAGE)
    for h in (root / "libraries" / "stdlib" / "genosl" / "include").glob("*.h"):
        shutil.copy(h, folder / h.name)
    tmp = path.with_suffix(".tmp")
    tmp.write_text(src)
    tmp.replace(path)
    return path


if __name__ == "__main__":
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    print(osl_shader(sys.argv[1], json.loads(sys.argv[2]), Path(sys.argv[3])))
