# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Render the stimulus scene in Blender Cycles (PyPI bpy 5.0.1, CPU) with a given sphere
material; write a linear EXR for the image gloss meter (pgloss.image_meter).

The scene is read from examples/tracer/scenes/stimulus.scene and built so that a Lambertian
sphere agrees with pgloss-tracer and Mitsuba 3 within noise (shared/reference facts, checked
by examples/bridge/validate.py --harnesses):

* the sphere is analytic (a Cycles point of the scene's radius, from a one-vertex mesh through
  geometry nodes' Mesh to Points); the box is six quads whose diffuse colour is the tracer's 3-D
  checker, parity of ⌊(x−o)/s⌋ + ⌊(y−o)/s⌋ + ⌊(z−o)/s⌋, computed from the shading position;
* the light is a one-sided emissive quad (Emission Strength = the scene's radiance; its back
  is black and is not sampled), no world light;
* pinhole camera of the scene's vertical fov, box pixel filter 1 px, max bounces = the tracer's
  max_depth − 1; off: denoiser, adaptive sampling, light tree, path guiding, clamps, filter
  glossy, the light threshold; view transform Standard, 32-bit float EXR (scene linear).

Materials (a JSON object, or a file holding one; a ``{"parameters": {...}}`` wrapper, as the
bridge tool prints, is unwrapped):

* ``{"type": "principled", "Base Color": 0.193, "Roughness": 0.3, "IOR": 1.5,
  "Specular IOR Level": 0.5, "distribution": "MULTI_GGX"}`` — Principled BSDF inputs by their
  Blender names (others keep Blender's defaults);
* ``{"type": "diffuse", "reflectance": 0.193}`` — Lambertian (Diffuse BSDF, roughness 0);
* ``{"type": "gltf", "material": {...glTF 2.0 material object...}}`` — written to a .gltf file
  (one triangle carrying it, with the extensions it uses) and read by Blender's own glTF
  importer (io_scene_gltf2); the material it makes goes on the sphere;
* ``{"type": "osl", "file": "shader.osl", "output": "out"}`` — an OSL shader (e.g. MaterialX's
  genosl output) in a Script node, Cycles' OSL shading system on.

From Python, :func:`build` also takes a function that makes each object's material from the
scene's material statement (a Blender add-on's material), and builds the scene's ``mesh`` lines
(OBJ through Blender's importer), so other scenes of the tracer's format render too (Fig. 14).

    .venv-bpy/bin/python examples/bridge/harness_cycles.py MATERIAL.json|'{…}' --out sphere.exr
        [--spp 1024] [--seed 1] [--size 160x120] [--crop x0,y0,w,h] [--threads 2]
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
from pathlib import Path
from typing import Any, Callable, Dict, List, Optional, Tuple, Union

import numpy as np

import harness_json  # examples/bridge, this script's folder

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "examples" / "tracer" / "scenes" / "stimulus.scene"


# ------------------------------------------------------------------------------ the scene file
def read_scene(path: Path) -> Dict[str, List[Dict[str, str]]]:
    """The scene file's statements: keyword → list of its key=value fields ('name' for the
    material's second word, 'kind' for its third)."""
    out: Dict[str, List[Dict[str, str]]] = {}
    for line in path.read_text().splitlines():
        words = line.split("#", 1)[0].split()
        if not words:
            continue
        f = dict(w.split("=", 1) for w in words[1:] if "=" in w)
        if words[0] == "material":
            f["name"] = words[1]
            f["kind"] = words[2] if len(words) > 2 and "=" not in words[2] else ""
            if "=" in words[2]:
                f["kind"] = words[2].split("=", 1)[0]
        out.setdefault(words[0], []).append(f)
    return out


def vec(s: str) -> Tuple[float, ...]:
    return tuple(float(v) for v in s.split(","))


# ---------------------------------------------------------------------------------- materials
def parameters(text: str) -> dict:
    """The material object (harness_json.parameters)."""
    return harness_json.parameters(text, "principled, diffuse, gltf, osl")


def _rgba(v) -> Tuple[float, float, float, float]:
    if isinstance(v, (int, float)):
        return (float(v), float(v), float(v), 1.0)
    v = [float(x) for x in v]
    return (v[0], v[1], v[2], v[3] if len(v) > 3 else 1.0)


def _material(bpy, name: str):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    return mat, nt, out


def sphere_material(bpy, p: dict, tmp: Path):
    kind = p["type"]
    if kind == "diffuse":
        mat, nt, out = _material(bpy, "sphere")
        n = nt.nodes.new("ShaderNodeBsdfDiffuse")
        n.inputs["Color"].default_value = _rgba(p["reflectance"])
        n.inputs["Roughness"].default_value = 0.0
        nt.links.new(n.outputs["BSDF"], out.inputs["Surface"])
        return mat
    if kind == "principled":
        mat, nt, out = _material(bpy, "sphere")
        n = nt.nodes.new("ShaderNodeBsdfPrincipled")
        n.distribution = p.get("distribution", "MULTI_GGX")
        for k, v in p.items():
            if k in ("type", "distribution"):
                continue
            if k not in n.inputs:
                raise ValueError(f"the Principled BSDF has no input {k!r}")
            sock = n.inputs[k]
            sock.default_value = _rgba(v) if sock.type == "RGBA" else float(v)
        nt.links.new(n.outputs["BSDF"], out.inputs["Surface"])
        return mat
    if kind == "gltf":
        return gltf_material(bpy, p["material"], tmp)
    if kind == "osl":
        mat, nt, out = _material(bpy, "sphere")
        n = nt.nodes.new("ShaderNodeScript")
        n.mode = "EXTERNAL"
        n.filepath = str(Path(p["file"]).resolve())  # compiled by Cycles on assignment
        outputs = [o.name for o in n.outputs]
        name = p.get("output", outputs[0] if outputs else "")
        if name not in outputs:
            raise ValueError(f"{p['file']}: the compiled shader has no output {name!r} (outputs: {outputs})")
        nt.links.new(n.outputs[name], out.inputs["Surface"])
        return mat
    raise ValueError(f"unknown material type {kind!r} (principled, diffuse, gltf, osl)")


def gltf_material(bpy, material: dict, tmp: Path):
    """Blender's glTF importer's material for ``material`` (a glTF 2.0 material object)."""
    import base64  # noqa: PLC0415
    import struct  # noqa: PLC0415

    pos = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    used = sorted(material.get("extensions", {}))
    doc = {
        "asset": {"version": "2.0", "generator": "pgloss examples/bridge/harness_cycles.py"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "carrier"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
        "materials": [dict(material, name=material.get("name", "paint"))],
        "buffers": [{"byteLength": len(pos),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(pos).decode()}],
        "bufferViews": [{"buffer": 0, "byteLength": len(pos)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}],
    }
    if used:
        doc["extensionsUsed"] = used
    path = tmp / "paint.gltf"
    path.write_text(json.dumps(doc))
    before = set(bpy.data.materials)
    bpy.ops.import_scene.gltf(filepath=str(path))
    new = [m for m in bpy.data.materials if m not in before]
    if len(new) != 1:
        raise RuntimeError(f"the glTF importer made {len(new)} materials from {path}, not one")
    for ob in list(bpy.context.scene.objects):
        if ob.name.startswith("carrier"):
            bpy.data.objects.remove(ob)
    return new[0]


# --------------------------------------------------------------------------------- the scene
def _quad(bpy, sc, name: str, corners, mat):
    me = bpy.data.meshes.new(name)
    me.from_pydata([tuple(c) for c in corners], [], [(0, 1, 2, 3)])
    me.materials.append(mat)
    ob = bpy.data.objects.new(name, me)
    sc.collection.objects.link(ob)
    return ob


def checker_material(bpy, a: float, b: float, size: float, offset: Tuple[float, float, float]):
    """Diffuse colour b where ⌊(x−o)/s⌋ + ⌊(y−o)/s⌋ + ⌊(z−o)/s⌋ is odd, else a (the tracer's)."""
    mat, nt, out = _material(bpy, "checks")
    geo = nt.nodes.new("ShaderNodeNewGeometry")
    sep = nt.nodes.new("ShaderNodeSeparateXYZ")
    nt.links.new(geo.outputs["Position"], sep.inputs[0])
    total = None
    for i, axis in enumerate("XYZ"):
        sub = nt.nodes.new("ShaderNodeMath")
        sub.operation = "SUBTRACT"
        nt.links.new(sep.outputs[axis], sub.inputs[0])
        sub.inputs[1].default_value = offset[i]
        div = nt.nodes.new("ShaderNodeMath")
        div.operation = "DIVIDE"
        nt.links.new(sub.outputs[0], div.inputs[0])
        div.inputs[1].default_value = size
        fl = nt.nodes.new("ShaderNodeMath")
        fl.operation = "FLOOR"
        nt.links.new(div.outputs[0], fl.inputs[0])
        if total is None:
            total = fl
        else:
            add = nt.nodes.new("ShaderNodeMath")
            add.operation = "ADD"
            nt.links.new(total.outputs[0], add.inputs[0])
            nt.links.new(fl.outputs[0], add.inputs[1])
            total = add
    # parity = n − 2⌊n/2⌋ (0 or 1 for negative n too, unlike a truncated modulo)
    half = nt.nodes.new("ShaderNodeMath")
    half.operation = "MULTIPLY"
    nt.links.new(total.outputs[0], half.inputs[0])
    half.inputs[1].default_value = 0.5
    fh = nt.nodes.new("ShaderNodeMath")
    fh.operation = "FLOOR"
    nt.links.new(half.outputs[0], fh.inputs[0])
    par = nt.nodes.new("ShaderNodeMath")
    par.operation = "MULTIPLY_ADD"  # −2⌊n/2⌋ + n
    nt.links.new(fh.outputs[0], par.inputs[0])
    par.inputs[1].default_value = -2.0
    nt.links.new(total.outputs[0], par.inputs[2])
    mix = nt.nodes.new("ShaderNodeMix")
    mix.data_type = "RGBA"
    nt.links.new(par.outputs[0], mix.inputs["Factor"])
    mix.inputs["A"].default_value = _rgba(a)
    mix.inputs["B"].default_value = _rgba(b)
    bsdf = nt.nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Roughness"].default_value = 0.0
    nt.links.new(mix.outputs["Result"], bsdf.inputs["Color"])
    nt.links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    return mat


def light_material(bpy, radiance: float):
    """Emission of ``radiance`` on the front (the normal's side) only; black elsewhere."""
    mat, nt, out = _material(bpy, "light")
    em = nt.nodes.new("ShaderNodeEmission")
    em.inputs["Strength"].default_value = radiance
    em.inputs["Color"].default_value = (1, 1, 1, 1)
    black = nt.nodes.new("ShaderNodeEmission")  # strength 0 and no BSDF: a black back
    black.inputs["Strength"].default_value = 0.0
    geo = nt.nodes.new("ShaderNodeNewGeometry")
    mix = nt.nodes.new("ShaderNodeMixShader")
    nt.links.new(geo.outputs["Backfacing"], mix.inputs["Fac"])
    nt.links.new(em.outputs[0], mix.inputs[1])
    nt.links.new(black.outputs[0], mix.inputs[2])
    nt.links.new(mix.outputs[0], out.inputs["Surface"])
    mat.cycles.emission_sampling = "FRONT"
    return mat


def analytic_sphere(bpy, sc, center, radius: float, mat):
    """A Cycles point (an exact sphere) at ``center``: one vertex through Mesh to Points."""
    me = bpy.data.meshes.new("sphere")
    me.from_pydata([tuple(center)], [], [])
    ob = bpy.data.objects.new("sphere", me)
    sc.collection.objects.link(ob)
    ng = bpy.data.node_groups.new("to_points", "GeometryNodeTree")
    ng.interface.new_socket("Geometry", in_out="INPUT", socket_type="NodeSocketGeometry")
    ng.interface.new_socket("Geometry", in_out="OUTPUT", socket_type="NodeSocketGeometry")
    gi, go = ng.nodes.new("NodeGroupInput"), ng.nodes.new("NodeGroupOutput")
    pts = ng.nodes.new("GeometryNodeMeshToPoints")
    pts.inputs["Radius"].default_value = radius
    sm = ng.nodes.new("GeometryNodeSetMaterial")
    sm.inputs["Material"].default_value = mat
    ng.links.new(gi.outputs[0], pts.inputs["Mesh"])
    ng.links.new(pts.outputs["Points"], sm.inputs["Geometry"])
    ng.links.new(sm.outputs["Geometry"], go.inputs[0])
    ob.modifiers.new("to_points", "NODES").node_group = ng
    return ob


def mesh_object(bpy, sc, path: Path, scale: float, translate, mat):
    """An OBJ of a scene's ``mesh`` line through Blender's own importer, in the scene's axes (no
    Y-up conversion), scaled then translated, flat shaded (the tracer's geometric normals)."""
    before = set(bpy.data.objects)
    bpy.ops.wm.obj_import(filepath=str(path), forward_axis="Y", up_axis="Z")
    new = [o for o in bpy.data.objects if o not in before]
    if len(new) != 1 or new[0].type != "MESH":
        raise RuntimeError(f"{path}: Blender's OBJ importer made {len(new)} objects, not one mesh")
    ob = new[0]
    for poly in ob.data.polygons:
        poly.use_smooth = False
    ob.data.materials.clear()
    ob.data.materials.append(mat)
    ob.scale = (scale, scale, scale)
    ob.location = tuple(translate)
    if ob.name not in sc.collection.objects:
        for c in list(ob.users_collection):
            c.objects.unlink(ob)
        sc.collection.objects.link(ob)
    return ob


#: What puts a material on the scene's paint objects: a harness material (one object for every
#: sphere and mesh), or a function (bpy, the scene's material statement) → a bpy Material, called
#: after the scene is reset (e.g. a Blender add-on's material made from the scene's paint).
PaintMaterial = Union[dict, Callable[[Any, Dict[str, str]], Any]]


def build(bpy, material: PaintMaterial, tmp: Path, *, spp: int, seed: int, size: Tuple[int, int],
          crop: Optional[Tuple[int, int, int, int]], threads: int, scene_path: Path = SCENE,
          keep_preferences: bool = False):
    """The scene in a reset Blender. ``keep_preferences``: reset with the home file (empty), which
    keeps the preferences and so the enabled add-ons, instead of the factory settings."""
    from mathutils import Matrix, Vector  # noqa: PLC0415

    st = read_scene(scene_path)
    if keep_preferences:
        bpy.ops.wm.read_homefile(use_empty=True)
    else:
        bpy.ops.wm.read_factory_settings(use_empty=True)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    cy = sc.cycles
    cy.device = "CPU"
    cy.shading_system = isinstance(material, dict) and material["type"] == "osl"
    cy.samples = spp
    cy.seed = seed
    cy.use_adaptive_sampling = False
    cy.use_denoising = False
    cy.pixel_filter_type = "BOX"
    cy.filter_width = 1.0
    depth = int(st["render"][0].get("max_depth", 8)) - 1
    cy.max_bounces = cy.diffuse_bounces = cy.glossy_bounces = cy.transmission_bounces = depth
    cy.transparent_max_bounces = depth
    cy.volume_bounces = 0
    cy.use_light_tree = False
    cy.use_guiding = False
    cy.sample_clamp_direct = cy.sample_clamp_indirect = 0.0
    cy.blur_glossy = 0.0
    cy.caustics_reflective = cy.caustics_refractive = True
    cy.light_sampling_threshold = 0.0
    sc.render.threads_mode = "FIXED"
    sc.render.threads = threads
    sc.render.resolution_x, sc.render.resolution_y = size
    sc.render.resolution_percentage = 100
    sc.render.pixel_aspect_x = sc.render.pixel_aspect_y = 1.0
    if crop is not None:
        x0, y0, w, h = crop
        W, H = size
        sc.render.use_border = sc.render.use_crop_to_border = True
        sc.render.border_min_x, sc.render.border_max_x = x0 / W, (x0 + w) / W
        sc.render.border_min_y, sc.render.border_max_y = (H - y0 - h) / H, (H - y0) / H
    sc.view_settings.view_transform = "Standard"
    sc.view_settings.look = "None"
    sc.view_settings.exposure = 0.0
    sc.view_settings.gamma = 1.0
    im = sc.render.image_settings
    im.file_format = "OPEN_EXR"
    im.color_depth = "32"
    im.exr_codec = "ZIP"
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    sc.world = world

    cam_f = st["camera"][0]
    pos, at, up = Vector(vec(cam_f["position"])), Vector(vec(cam_f["look_at"])), Vector(vec(cam_f.get("up", "0,1,0")))
    f = (at - pos).normalized()
    r = f.cross(up).normalized()
    u = r.cross(f)
    cam = bpy.data.cameras.new("camera")
    cam.sensor_fit = "VERTICAL"
    cam.angle_y = math.radians(float(cam_f["fov"]))
    cam.clip_start = 1e-3
    cam.clip_end = 1e3
    co = bpy.data.objects.new("camera", cam)
    co.matrix_world = Matrix(((r.x, u.x, -f.x, pos.x), (r.y, u.y, -f.y, pos.y), (r.z, u.z, -f.z, pos.z), (0, 0, 0, 1)))
    sc.collection.objects.link(co)
    sc.camera = co

    mats = {m["name"]: m for m in st["material"]}
    box, chk = st["box"][0], mats[st["box"][0]["material"]]
    checks = checker_material(bpy, float(mats[chk["a"]]["diffuse"]), float(mats[chk["b"]]["diffuse"]),
                              float(chk["size"]), vec(chk.get("offset", "0,0,0")))
    lo, hi = vec(box["min"]), vec(box["max"])
    for axis in range(3):
        for side in (lo[axis], hi[axis]):
            a, b = [k for k in range(3) if k != axis]
            corners = []
            for ua, ub in ((lo[a], lo[b]), (hi[a], lo[b]), (hi[a], hi[b]), (lo[a], hi[b])):
                p = [0.0, 0.0, 0.0]
                p[axis], p[a], p[b] = side, ua, ub
                corners.append(p)
            _quad(bpy, sc, f"wall{axis}{int(side == hi[axis])}", corners, checks)
    for i, lt in enumerate(st["light"]):
        c, e1, e2 = (np.array(vec(lt[k])) for k in ("corner", "edge1", "edge2"))
        # The tracer's light emits from the side of e1 × e2 (scene.hpp): this winding's normal.
        pts = [c, c + e1, c + e1 + e2, c + e2]
        _quad(bpy, sc, f"light{i}", pts, light_material(bpy, float(lt["radiance"])))

    def paint(fields: Dict[str, str]):
        if callable(material):
            return material(bpy, mats[fields["material"]])
        return sphere_material(bpy, material, tmp)

    for sph in st.get("sphere", []):
        analytic_sphere(bpy, sc, vec(sph["center"]), float(sph["radius"]), paint(sph))
    for m in st.get("mesh", []):
        mesh_object(bpy, sc, scene_path.parent / m["file"], float(m.get("scale", 1)),
                    vec(m.get("translate", "0,0,0")), paint(m))
    return sc


def install_extension(bpy, zip_path: Path, module: str):
    """Installs a Blender extension zip into the user repository and enables it (the user folder
    is $BLENDER_USER_RESOURCES: point it at a scratch folder); returns the add-on's module."""
    import os  # noqa: PLC0415

    if not os.environ.get("BLENDER_USER_RESOURCES"):
        raise RuntimeError("set BLENDER_USER_RESOURCES to a scratch folder: the extension installs there")
    r = bpy.ops.extensions.package_install_files(filepath=str(zip_path), repo="user_default", enable_on_install=True)
    if r != {"FINISHED"} or module not in bpy.context.preferences.addons.keys():
        raise RuntimeError(f"{zip_path}: the extension did not install and enable as {module} ({r})")
    return sys.modules[module]


def _bpy():
    """bpy, with the modules it bundles outside sys.path (oslquery for OSL Script nodes,
    OpenImageIO) reachable: tests/osl/oslrt.py's set-up."""
    sys.path.insert(0, str(ROOT / "tests" / "osl"))
    import oslrt  # noqa: PLC0415

    return oslrt.bpy


def render(material: dict, out: Path, **kw) -> np.ndarray:
    bpy = _bpy()
    import OpenImageIO as oiio  # noqa: PLC0415  (bundled with bpy)

    out.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="pgloss-cycles-") as tmp:
        sc = build(bpy, material, Path(tmp), **kw)
        sc.render.filepath = str(out)
        bpy.ops.render.render(write_still=True)
    buf = oiio.ImageBuf(str(out))
    img = np.asarray(buf.get_pixels(oiio.FLOAT), dtype=np.float64)[..., :3]
    want = kw["crop"][2:] if kw.get("crop") else kw["size"]
    if img.shape[:2] != (want[1], want[0]):
        raise RuntimeError(f"Cycles wrote {img.shape[1]}x{img.shape[0]}, not {want[0]}x{want[1]}")
    return img


def main(argv: Optional[List[str]] = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("material", nargs="?", help="JSON object (or a file holding one)")
    ap.add_argument("--out", type=Path)
    ap.add_argument("--jobs", type=Path, help="a JSON list of {material, out, spp, seed}: render them all in this "
                    "process (bpy starts once)")
    ap.add_argument("--spp", type=int, default=1024)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--size", default="160x120")
    ap.add_argument("--crop", help="x0,y0,w,h: render this window of the frame alone (the meter's sphere crop)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--scene", type=Path, default=SCENE)
    a = ap.parse_args(argv)
    size = tuple(int(v) for v in a.size.split("x"))
    crop = tuple(int(v) for v in a.crop.split(",")) if a.crop else None
    if a.jobs is not None:
        jobs = json.loads(a.jobs.read_text())
    elif a.material is not None and a.out is not None:
        jobs = [{"material": a.material, "out": str(a.out), "spp": a.spp, "seed": a.seed}]
    else:
        ap.error("give MATERIAL and --out, or --jobs")
    for job in jobs:
        try:
            mat = parameters(job["material"] if isinstance(job["material"], str) else json.dumps(job["material"]))
        except (ValueError, OSError) as e:
            print(f"harness_cycles: {e}", file=sys.stderr)
            return 2
        out = Path(job["out"])
        spp, seed = int(job.get("spp", a.spp)), int(job.get("seed", a.seed))
        img = render(mat, out, spp=spp, seed=seed, size=size, crop=crop, threads=a.threads, scene_path=a.scene)
        print(f"{out}: {img.shape[1]}x{img.shape[0]}, {spp} spp, Cycles (bpy 5.0.1), {json.dumps(mat)}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
