#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The picker's MaterialX and Mitsuba 3 exports read by their own libraries (run with the venv
.venv-web-export of scripts/test-web.sh: PyPI MaterialX 1.39, mitsuba 3, variant llvm_ad_rgb).

Reads a JSON list of {"kind": "materialx" | "mitsuba", "text": …, "want": {…}} on stdin and
writes, for each, {"ok": bool, "message": …, "values": {…}}:
  materialx  MaterialX's Document.validate() with the standard libraries imported (so that
             open_pbr_surface / standard_surface and their inputs' types are checked against the
             nodedefs), and the shader node's input values as MaterialX parsed them;
  mitsuba    mitsuba.load_string of the <bsdf>, and its parameters as the plugin holds them
             (mi.traverse: alpha, the IOR ratio eta, diffuse_reflectance).
"""
from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any, Dict


def materialx(text: str) -> Dict[str, Any]:
    import MaterialX as mx  # noqa: PLC0415

    search = mx.FileSearchPath(str(Path(mx.__file__).resolve().parent))
    lib = mx.createDocument()
    mx.loadLibraries(["libraries"], search, lib)
    doc = mx.createDocument()
    mx.readFromXmlString(doc, text)
    doc.importLibrary(lib)
    ok, message = doc.validate()
    values: Dict[str, Any] = {"version": doc.getVersionString()}
    for node in doc.getNodes():
        if node.getType() != "surfaceshader":
            continue
        values["node"] = node.getCategory()
        values["nodedef"] = node.getNodeDef().getName() if node.getNodeDef() else None
        for inp in node.getInputs():
            v = inp.getValue()
            values[inp.getName()] = list(v.asTuple()) if hasattr(v, "asTuple") else v
    materials = [n.getName() for n in doc.getMaterialNodes()]
    return {"ok": bool(ok) and bool(materials) and values.get("nodedef") is not None, "message": message,
            "values": values}


def mitsuba(text: str) -> Dict[str, Any]:
    import mitsuba as mi  # noqa: PLC0415
    import numpy as np  # noqa: PLC0415

    mi.set_variant("llvm_ad_rgb")
    bsdf = mi.load_string(text)
    params = mi.traverse(bsdf)
    values: Dict[str, Any] = {"class": bsdf.class_().name() if hasattr(bsdf, "class_") else type(bsdf).__name__}
    for key in params.keys():
        flat = np.asarray(params[key], dtype=np.float64).ravel()
        values[key] = [float(x) for x in flat] if flat.size > 1 else float(flat[0])
    return {"ok": True, "message": "", "values": values}


def main() -> None:
    out = []
    for item in json.load(sys.stdin):
        try:
            out.append(materialx(item["text"]) if item["kind"] == "materialx" else mitsuba(item["text"]))
        except Exception as e:  # noqa: BLE001  (reported to the test, which fails on it)
            out.append({"ok": False, "message": f"{type(e).__name__}: {e}", "values": {}})
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main()
