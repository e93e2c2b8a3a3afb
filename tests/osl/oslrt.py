# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""A real OSL runtime for tests: OSL 1.14 inside Blender's Cycles (PyPI ``bpy==5.0.1``).

``compile_osl`` runs Cycles' OSL compiler on a file. ``render_shader`` executes a shader as
an emission closure on a plane that fills an orthographic camera exactly, one Cycles sample
per pixel, a box pixel filter 0.01 pixel wide (so no sample leaves its pixel), no bounces,
the Raw view transform, written to a 32-bit float OpenEXR and read back with OpenImageIO.
Pixel (x, y) (y = 0 at the top) sees the plane at P = (x + 0.5 - W/2, H/2 - y - 0.5, 0),
up to the sub-pixel jitter, so a shader finds its pixel with ``floor(P[0] + W/2)``.
Cycles replaces non-finite radiance by 0 (``ensure_finite``), so shaders must report
non-finiteness themselves; the readback is checked to be exact by ``tests/osl/test_osl.py``.
"""
from __future__ import annotations

import importlib.util
import os
import sys
from pathlib import Path

import numpy as np

_spec = importlib.util.find_spec("bpy")
if _spec is None or _spec.origin is None:
    raise ImportError("bpy (PyPI bpy==5.0.1) is not installed in this interpreter")
# The Cycles add-on imports oslquery, which bpy bundles outside the interpreter's sys.path.
_BUNDLED = Path(_spec.origin).parent / "5.0" / "python" / "lib" / "python3.11" / "site-packages"
if str(_BUNDLED) not in sys.path:
    sys.path.append(str(_BUNDLED))

import bpy  # noqa: E402
import OpenImageIO as oiio  # noqa: E402  (bundled with bpy)

REPO = Path(__file__).resolve().parents[2]
OSL_DIR = REPO / "osl"
WORK = REPO / "build-osl"


def compile_osl(src: Path, oso: Path) -> bool:
    """Compiles ``src`` with Cycles' OSL compiler into ``oso``; True on success."""
    import _cycles  # available once bpy is imported

    oso.parent.mkdir(parents=True, exist_ok=True)
    if oso.exists():
        oso.unlink()
    ok = bool(_cycles.osl_compile(str(src), str(oso)))
    return ok and oso.exists() and oso.stat().st_size > 0


def reset_scene() -> bpy.types.Scene:
    """An empty scene set up for Cycles + OSL on the CPU."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.device = "CPU"
    sc.cycles.shading_system = True
    sc.render.threads_mode = "FIXED"
    sc.render.threads = max(1, min(2, os.cpu_count() or 1))
    sc.view_settings.view_transform = "Raw"
    sc.view_settings.look = "None"
    sc.view_settings.exposure = 0.0
    sc.view_settings.gamma = 1.0
    sc.render.image_settings.file_format = "OPEN_EXR"
    sc.render.image_settings.color_depth = "32"
    sc.render.image_settings.exr_codec = "ZIP"
    sc.render.resolution_percentage = 100
    return sc


def empty_material(name: str):
    """A new material with no nodes but its output: (material, node tree, output node)."""
    mat = bpy.data.materials.new(name)
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    return mat, nt, nt.nodes.new("ShaderNodeOutputMaterial")


def osl_material(name: str, osl_path: Path):
    """A material with an external OSL script node (compiled by Cycles on assignment):
    (material, node tree, script node, output node). Raises if the shader did not compile."""
    mat, nt, out = empty_material(name)
    script = nt.nodes.new("ShaderNodeScript")
    script.mode = "EXTERNAL"
    script.filepath = str(osl_path)
    if not script.outputs:
        raise RuntimeError(f"OSL compilation of {osl_path} failed (see the log above)")
    return mat, nt, script, out


def emission_scene(width: int, height: int) -> bpy.types.Scene:
    """A reset scene for emission renders: 1 sample, box pixel filter, no bounces, fixed seed,
    ``width`` x ``height`` pixels seen by an orthographic camera of scale ``width`` at z = 10
    looking down -z (one pixel per unit), black world."""
    sc = reset_scene()
    sc.cycles.samples = 1
    sc.cycles.use_adaptive_sampling = False
    sc.cycles.use_denoising = False
    sc.cycles.pixel_filter_type = "BOX"
    sc.cycles.filter_width = 0.01
    sc.cycles.max_bounces = 0
    sc.cycles.seed = 0
    sc.render.resolution_x = width
    sc.render.resolution_y = height
    cam = bpy.data.cameras.new("cam")
    cam.type = "ORTHO"
    cam.ortho_scale = float(width)
    cam_obj = bpy.data.objects.new("cam", cam)
    sc.collection.objects.link(cam_obj)
    cam_obj.location = (0.0, 0.0, 10.0)
    sc.camera = cam_obj
    world = bpy.data.worlds.new("world")
    world.color = (0.0, 0.0, 0.0)
    sc.world = world
    return sc


def render_exr(sc: bpy.types.Scene, out_exr: Path) -> np.ndarray:
    """Renders ``sc`` to the EXR ``out_exr``; returns its RGB, float32 [H, W, 3]."""
    out_exr.parent.mkdir(parents=True, exist_ok=True)
    if out_exr.exists():
        out_exr.unlink()
    sc.render.filepath = str(out_exr)
    bpy.ops.render.render(write_still=True)
    buf = oiio.ImageBuf(str(out_exr))
    spec = buf.spec()
    if (spec.width, spec.height) != (sc.render.resolution_x, sc.render.resolution_y) or spec.format != oiio.FLOAT:
        raise RuntimeError(f"unexpected EXR {spec.width}x{spec.height} {spec.format}")
    px = np.asarray(buf.get_pixels(oiio.FLOAT), dtype=np.float32)
    return px[:, :, :3].copy()


def render_shader(osl_path: Path, width: int, height: int, out_exr: Path, wire=None) -> np.ndarray:
    """Renders the shader as emission on a camera-filling plane; returns float32 [H, W, 3].

    ``width`` must be even and >= ``height`` >= 4 (Blender's smallest height), so that the
    orthographic scale is the width and the plane's edges fall on pixel edges.
    ``wire(node_tree, script_node, output_node)``, if given, links the script's outputs to the
    material output itself (e.g. a pattern shader through an Emission node).
    """
    assert width % 2 == 0 and width >= height >= 4
    sc = emission_scene(width, height)
    mesh = bpy.data.meshes.new("plane")
    w2, h2 = width / 2, height / 2
    mesh.from_pydata([(-w2, -h2, 0), (w2, -h2, 0), (w2, h2, 0), (-w2, h2, 0)], [], [(0, 1, 2, 3)])
    plane = bpy.data.objects.new("plane", mesh)
    sc.collection.objects.link(plane)

    mat, nt, script, out = osl_material("shader", osl_path)
    if wire is None:
        nt.links.new(script.outputs[0], out.inputs["Surface"])
    else:
        wire(nt, script, out)
    mesh.materials.append(mat)
    return render_exr(sc, out_exr)


def furnace_setup(sc: bpy.types.Scene, samples: int, size: int, segments: int = 128, rings: int = 64):
    """Adds a white furnace to a reset scene: a smooth unit sphere seen head-on by an
    orthographic camera inside a uniform environment of radiance 1, one bounce, fixed seed,
    no denoising, ``size`` x ``size`` pixels. A pixel shows the directional albedo at its θo.
    Returns the sphere object (its material is the caller's)."""
    sc.cycles.samples = samples
    sc.cycles.use_denoising = False
    sc.cycles.max_bounces = 1
    sc.cycles.seed = 0
    sc.render.resolution_x = sc.render.resolution_y = size
    bpy.ops.mesh.primitive_uv_sphere_add(radius=1.0, segments=segments, ring_count=rings)
    bpy.ops.object.shade_smooth()
    sphere = bpy.context.object
    cam = bpy.data.cameras.new("c")
    cam.type = "ORTHO"
    cam.ortho_scale = 2.2
    co = bpy.data.objects.new("c", cam)
    sc.collection.objects.link(co)
    co.location = (0, 0, 5)
    sc.camera = co
    w = bpy.data.worlds.new("w")
    for n in w.node_tree.nodes:
        if n.type == "BACKGROUND":
            n.inputs["Color"].default_value = (1, 1, 1, 1)
            n.inputs["Strength"].default_value = 1.0
    sc.world = w
    return sphere


def render_centre(sc: bpy.types.Scene, path: Path, half: int = 4) -> np.ndarray:
    """Renders the scene to ``path``; the (2 half + 1)² pixels around the centre, RGB float64
    (at 64 px and half = 4, θo < 13° on the furnace's sphere)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    sc.render.filepath = str(path)
    bpy.ops.render.render(write_still=True)
    img = np.asarray(oiio.ImageBuf(str(path)).get_pixels(oiio.FLOAT))[:, :, :3]
    c = img.shape[0] // 2
    return img[c - half:c + half + 1, c - half:c + half + 1].astype(np.float64)
