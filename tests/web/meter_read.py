# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The image gloss meter (pgloss.image_meter) for tests/web/test_picker_meter.py, run with the
Python that has pgloss and OpenImageIO (.venv-bridge). JSON on stdin, JSON on stdout:

  {"cmd": "view"}  -> the meter's sphere crop: {"width", "height", "fov"} (View.crop, crop_fov_deg)
  {"cmd": "fit", "tracer", "basis_dir", "spp", "alphas", "images": [{"npy", "exr", "rho_d"}]}
      -> each image written as a linear float EXR (OpenImageIO), read back by the meter's own
         reader (image_meter.read_linear) and fitted against the pgloss-tracer basis at its ρd
         (primary setup, ρd known): [{"rho_d", "rho_s", "alpha", "L", "c", "d", "residual", "status"}],
         and the meter's expected noise at each of "spp": {"noise": {spp: [Δc, Δd]}}.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import OpenImageIO as oiio
from pgloss import image_meter as im

SCENE = Path(__file__).resolve().parents[2] / "examples/tracer/scenes/stimulus.scene"


def main() -> None:
    req = json.load(sys.stdin)
    view = im.View.from_scene(SCENE.read_text())
    if req["cmd"] == "view":
        _, _, w, h = view.crop()
        json.dump({"width": w, "height": h, "fov": view.crop_fov_deg()}, sys.stdout)
        return
    fits = []
    for item in req["images"]:
        img = np.load(item["npy"]).astype(np.float32)
        out = oiio.ImageOutput.create(item["exr"])
        out.open(item["exr"], oiio.ImageSpec(img.shape[1], img.shape[0], 3, oiio.FLOAT))
        out.write_image(img)
        out.close()
        basis = im.render_basis(Path(req["tracer"]), SCENE, item["rho_d"], alphas=req["alphas"], spp=req["basis_spp"],
                                threads=2, cache=Path(req["basis_dir"]))
        f = im.fit(im.read_linear(Path(item["exr"])), basis)
        fits.append({k: getattr(f, k) for k in ("rho_d", "rho_s", "alpha", "L", "c", "d", "residual", "status")})
    json.dump({"fits": fits, "noise": {n: im.expected_noise(n) for n in req["spp"]}}, sys.stdout)


if __name__ == "__main__":
    main()
