# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pgloss paint: materials driven by the perceptual parameters of Pellacini, Ferwerda &
Greenberg (SIGGRAPH 2000) — CIELAB lightness L*, a*, b*, contrast gloss c and
distinctness-of-image gloss d (Fig. 13) — in two modes:

* **Ward (OSL)**, the exact one: "New pgloss Paint" (``material.pgloss_paint_new``) makes a
  material whose node group "pgloss paint" has the five sliders and the working colour space; it
  drives an Internal OSL script (the self-contained pgloss_material.osl, so the .blend carries
  it): Cycles with OSL, on the CPU.
* **Principled**: ``material.pgloss_paint_new(mode="PRINCIPLED")`` makes a material of one
  Principled BSDF whose inputs the gloss bridge writes from the paint, from a 60° gloss in GU or
  from a finish name (principled.py). It renders in EEVEE and in Cycles on any device.

The panel ("pgloss paint", material properties) shows the derived values and the status computed
by the bundled pgloss package (the C library): ρd, ρs, α for Ward; for Principled the inputs
written, the glossmeter's readings of the material, and for a paint out of the bridge's reach the
nearest reachable paint it renders instead, with the status and its reason.
"""
from __future__ import annotations

import os
from typing import Any, Dict, Optional

import bpy

from . import principled as pr

GROUP = "pgloss paint"
TEXT = "pgloss_material.osl"
SHADER = os.path.join(os.path.dirname(__file__), "pgloss_material.osl")
# Group input socket -> shader parameter, default, (min, max).
SLIDERS = (
    ("L*", "Lightness", 50.0, (0.0, 100.0)),
    ("a*", "a_star", 0.0, (-128.0, 128.0)),
    ("b*", "b_star", 0.0, (-128.0, 128.0)),
    ("c", "contrast_gloss", 0.057, (0.0, 1.0)),
    ("d", "distinctness_gloss", 0.96, (0.0, 1.0)),
)
SPACES = (("0", "Linear Rec. 709", "Rec. 709 / sRGB primaries, D65"),
          ("1", "ACEScg", "AP1 primaries, ACES white (Bradford from D65)"),
          ("2", "Linear Display P3", "Display P3 primaries, D65"),
          ("3", "Linear Rec. 2020", "BT.2020 primaries, D65"))


def shader_text() -> bpy.types.Text:
    """The shader as a text datablock (an Internal script lives in the .blend)."""
    txt = bpy.data.texts.get(TEXT)
    if txt is None:
        txt = bpy.data.texts.new(TEXT)
        with open(SHADER, encoding="utf-8") as fh:
            txt.from_string(fh.read())
    return txt


def node_group() -> bpy.types.ShaderNodeTree:
    """The "pgloss paint" node group: sliders in, the shader's BSDF out."""
    ng = bpy.data.node_groups.get(GROUP)
    if ng is not None:
        return ng
    ng = bpy.data.node_groups.new(GROUP, "ShaderNodeTree")
    for label, _, default, (lo, hi) in SLIDERS:
        s = ng.interface.new_socket(label, in_out="INPUT", socket_type="NodeSocketFloat")
        s.default_value, s.min_value, s.max_value = default, lo, hi
    s = ng.interface.new_socket("Colour space", in_out="INPUT", socket_type="NodeSocketInt")
    s.default_value, s.min_value, s.max_value = 0, 0, 3
    ng.interface.new_socket("BSDF", in_out="OUTPUT", socket_type="NodeSocketShader")
    gin = ng.nodes.new("NodeGroupInput")
    gout = ng.nodes.new("NodeGroupOutput")
    scr = ng.nodes.new("ShaderNodeScript")
    scr.mode = "INTERNAL"
    scr.script = shader_text()
    if not scr.outputs:
        raise RuntimeError("pgloss paint: the OSL shader did not compile (is Cycles' OSL available?)")
    gin.location, scr.location, gout.location = (-400, 0), (0, 0), (400, 0)
    for label, param, _, _ in SLIDERS:
        ng.links.new(gin.outputs[label], scr.inputs[param])
    ng.links.new(gin.outputs["Colour space"], scr.inputs["color_space"])
    ng.links.new(scr.outputs["BSDF"], gout.inputs["BSDF"])
    return ng


def paint_node(mat: Optional[bpy.types.Material]) -> Optional[bpy.types.Node]:
    if mat is None or mat.node_tree is None:
        return None
    for n in mat.node_tree.nodes:
        if n.type == "GROUP" and n.node_tree is not None and n.node_tree.name.startswith(GROUP):
            return n
    return None


def _material(name: str, node_type: str):
    """A new material whose only node of type ``node_type`` drives its output: (material, node)."""
    mat = bpy.data.materials.new(name)
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    node = nt.nodes.new(node_type)
    node.location, out.location = (-300, 0), (0, 0)
    return mat, node


def new_material(name: str = "pgloss paint") -> bpy.types.Material:
    """A material with the node group wired to its output (Cycles with OSL renders it)."""
    mat, grp = _material(name, "ShaderNodeGroup")
    grp.node_tree = node_group()
    mat.node_tree.links.new(grp.outputs["BSDF"], mat.node_tree.nodes["Material Output"].inputs["Surface"])
    return mat


def set_paint(mat: bpy.types.Material, **values: float) -> None:
    """Sets sliders by name: L, a, b, c, d, space."""
    node = paint_node(mat)
    keys = {"L": "L*", "a": "a*", "b": "b*", "c": "c", "d": "d", "space": "Colour space"}
    for k, v in values.items():
        node.inputs[keys[k]].default_value = v


def derived(mat: bpy.types.Material) -> Optional[Dict[str, Any]]:
    """ρd, ρs, α and the validity of the material's paint, from the pgloss library."""
    import pgloss

    node = paint_node(mat)
    if node is None:
        return None
    v = {k: float(node.inputs[k].default_value) for k in ("L*", "a*", "b*", "c", "d")}
    space = int(node.inputs["Colour space"].default_value)
    q = pgloss.Perceptual(v["L*"], v["a*"], v["b*"], v["c"], v["d"])
    check = pgloss.check_perceptual(q, space=space)
    out: Dict[str, Any] = {"status": check, "reason": pgloss.status_string(check), "inside": check.value >= 0}
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            p = pgloss.physical_from_perceptual(q, space=space)
        except pgloss.PglossError as e:
            p = e.result if isinstance(e.result, pgloss.Physical) else None
    if p is not None:
        out.update(rho_d=tuple(p.rho_d), rho_s=p.rho_s, alpha=p.alpha_x)
    return out


# ------------------------------------------------------------------------- the Principled mode
SOURCES = (("PAINT", "Paint", "L*, a*, b*, c, d"),
           ("GLOSS_UNITS", "Gloss units", "L*, a*, b*, the 60° gloss in GU and d"),
           ("FINISH", "Finish", "L*, a*, b*, a trade finish (MPI G1–G7) and d"))


def _finish_items() -> tuple:
    from pgloss import glossmeter

    def rng(lo: float, hi: float) -> str:
        return f"{'' if lo != lo else f'{lo:g}'}–{'' if hi != hi else f'{hi:g}'}"
    return tuple((f.name, f"{f.level.split()[-1]} {f.name}", f"MPI {f.level}: 60° {rng(f.gloss_60_min, f.gloss_60_max)} GU, "
                  f"85° {rng(f.sheen_85_min, f.sheen_85_max)} GU") for f in glossmeter.FINISHES)


# Static items (a dynamic items callback must keep its strings alive itself).
FINISH_ITEMS = _finish_items()


def _changed(self, context) -> None:
    mat = self.id_data
    if self.mode == "PRINCIPLED" and not self.batch:
        apply_principled(mat)


class PglossPaintSettings(bpy.types.PropertyGroup):
    """The Principled mode's paint (Material.pgloss); the Ward mode keeps its node group's sliders."""
    mode: bpy.props.EnumProperty(name="Mode", items=(("NONE", "None", ""), ("PRINCIPLED", "Principled", "")),
                                 default="NONE")
    source: bpy.props.EnumProperty(name="Input", items=SOURCES, default="PAINT", update=_changed)
    L: bpy.props.FloatProperty(name="L*", default=50.0, min=0.0, max=100.0, update=_changed)
    a: bpy.props.FloatProperty(name="a*", default=0.0, min=-128.0, max=128.0, update=_changed)
    b: bpy.props.FloatProperty(name="b*", default=0.0, min=-128.0, max=128.0, update=_changed)
    c: bpy.props.FloatProperty(name="c", default=0.057, min=0.0, max=1.0, precision=4, update=_changed)
    d: bpy.props.FloatProperty(name="d", default=0.96, min=0.0, max=1.0, precision=4, update=_changed)
    gloss_60: bpy.props.FloatProperty(name="60° gloss (GU)", default=30.0, min=0.0, max=200.0, update=_changed)
    finish: bpy.props.EnumProperty(name="Finish", items=FINISH_ITEMS, default="satin", update=_changed)
    batch: bpy.props.BoolProperty(default=False, options={"HIDDEN", "SKIP_SAVE"})
    # What the last mapping gave (shown in the panel).
    status: bpy.props.IntProperty(default=0)
    status_name: bpy.props.StringProperty()
    reason: bpy.props.StringProperty()
    note: bpy.props.StringProperty()
    nearest: bpy.props.BoolProperty()  # out of reach: the node holds the nearest paint's inputs
    reached: bpy.props.FloatVectorProperty(size=5)
    readings: bpy.props.FloatVectorProperty(size=3)  # 20°, 60°, 85° gloss (GU)


def principled_node(mat: Optional[bpy.types.Material]) -> Optional[bpy.types.Node]:
    if mat is None or mat.node_tree is None or mat.pgloss.mode != "PRINCIPLED":
        return None
    return mat.node_tree.nodes.get(pr.NODE)


def working_space() -> str:
    """The .blend's working colour space (Blender 5; Linear Rec. 709 before it)."""
    cs = getattr(bpy.data, "colorspace", None)
    return cs.working_space if cs is not None else "Linear Rec.709"


def mapping(mat: bpy.types.Material) -> pr.Principled:
    """The bridge's mapping of the material's paint (its source: paint, gloss units or finish)."""
    s = mat.pgloss
    if s.source == "GLOSS_UNITS":
        return pr.from_gloss_60(s.L, s.a, s.b, s.gloss_60, s.d)
    if s.source == "FINISH":
        return pr.from_finish(s.L, s.a, s.b, s.finish, s.d)
    return pr.from_paint(s.L, s.a, s.b, s.c, s.d)


def apply_principled(mat: bpy.types.Material) -> pr.Principled:
    """Maps the paint and writes the Principled node; the status, reason and reached paint go to
    the settings (the panel). An invalid paint leaves the node as it was and says why."""
    p = mapping(mat)
    s = mat.pgloss
    node = principled_node(mat)
    if node is not None:
        pr.write(node, p, working_space())
    s.status, s.status_name, s.reason, s.note = p.status, p.status_name, p.reason, p.note
    s.nearest = p.nearest
    if not p.renderable:
        s.note = "The paint is outside the model: the material keeps its previous inputs"
    s.reached = p.reached
    if p.renderable:
        s.readings = tuple(p.readings[k] for k in ("gloss_20", "gloss_60", "gloss_85"))
    return p


def new_principled_material(name: str = "pgloss paint") -> bpy.types.Material:
    """A material of one Principled BSDF (multiscatter GGX, the bridge's model) driven by the paint
    in Material.pgloss; renders in EEVEE and in Cycles on any device."""
    mat, node = _material(name, "ShaderNodeBsdfPrincipled")
    node.name = node.label = pr.NODE
    node.distribution = "MULTI_GGX"
    mat.node_tree.links.new(node.outputs["BSDF"], mat.node_tree.nodes["Material Output"].inputs["Surface"])
    mat.pgloss.mode = "PRINCIPLED"
    apply_principled(mat)
    return mat


def set_principled(mat: bpy.types.Material, **values: Any) -> pr.Principled:
    """Sets the Principled mode's inputs by name (source, L, a, b, c, d, gloss_60, finish) and maps
    once."""
    s = mat.pgloss
    s.batch = True
    try:
        for k, v in values.items():
            if k not in ("source", "L", "a", "b", "c", "d", "gloss_60", "finish"):
                raise KeyError(f"pgloss paint: no Principled input {k!r}")
            setattr(s, k, v)
    finally:
        s.batch = False
    return apply_principled(mat)


class PGLOSS_OT_paint_new(bpy.types.Operator):
    """Add a pgloss paint material to the active object"""
    bl_idname = "material.pgloss_paint_new"
    bl_label = "New pgloss Paint"
    bl_options = {"REGISTER", "UNDO"}

    mode: bpy.props.EnumProperty(
        name="Mode", default="WARD_OSL",
        items=(("WARD_OSL", "Ward (OSL, exact)", "The paper's Ward BRDF in an OSL shader: Cycles, CPU"),
               ("PRINCIPLED", "Principled BSDF", "The gloss bridge's Principled BSDF: EEVEE, Cycles on any device")))

    def execute(self, context):
        mat = new_principled_material() if self.mode == "PRINCIPLED" else new_material()
        ob = context.object
        if ob is not None and ob.type == "MESH":
            if ob.data.materials:
                ob.data.materials[ob.active_material_index] = mat
            else:
                ob.data.materials.append(mat)
        if self.mode == "WARD_OSL":
            context.scene.render.engine = "CYCLES"
            context.scene.cycles.shading_system = True   # OSL
        return {"FINISHED"}


def _draw_principled(layout, mat: bpy.types.Material) -> None:
    s = mat.pgloss
    layout.prop(s, "source", expand=True)
    col = layout.column(align=True)
    for k in ("L", "a", "b"):
        col.prop(s, k)
    if s.source == "PAINT":
        col.prop(s, "c")
    elif s.source == "GLOSS_UNITS":
        col.prop(s, "gloss_60")
    else:
        col.prop(s, "finish")
    col.prop(s, "d")
    box = layout.box()
    node = principled_node(mat)
    if node is not None:
        bc = node.inputs["Base Color"].default_value
        box.label(text=f"Base Color ({bc[0]:.4f}, {bc[1]:.4f}, {bc[2]:.4f}), {working_space()}")
        box.label(text=f"Roughness {node.inputs['Roughness'].default_value:.4f}    "
                       f"IOR {node.inputs['IOR'].default_value:.4f}    "
                       f"Specular IOR Level {node.inputs['Specular IOR Level'].default_value:.3f}")
        g = s.readings
        box.label(text=f"Glossmeter: 20° {g[0]:.1f}  60° {g[1]:.1f}  85° {g[2]:.1f} GU")
    row = box.row()
    row.alert = s.status < 0
    row.label(text="Reaches the paint" if s.status == 0 else f"{s.status_name}: {s.reason}",
              icon="CHECKMARK" if s.status >= 0 else "ERROR")
    r = s.reached
    if s.nearest:
        box.label(text=f"Renders the nearest reachable paint: L* {r[0]:.2f}  a* {r[1]:.2f}  b* {r[2]:.2f}  "
                       f"c {r[3]:.4f}  d {r[4]:.4f}", icon="INFO")
    elif s.source != "PAINT":
        box.label(text=f"Paint: L* {r[0]:.2f}  c {r[3]:.4f}  d {r[4]:.4f}")
    if s.note:
        box.label(text=s.note, icon="INFO")


class PGLOSS_PT_paint(bpy.types.Panel):
    bl_label = "pgloss paint"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "material"

    def draw(self, context):
        layout = self.layout
        mat = context.material
        if principled_node(mat) is not None:
            _draw_principled(layout, mat)
            return
        node = paint_node(mat)
        if node is None:
            layout.operator(PGLOSS_OT_paint_new.bl_idname, text="New pgloss Paint (Ward, OSL)",
                            icon="MATERIAL").mode = "WARD_OSL"
            layout.operator(PGLOSS_OT_paint_new.bl_idname, text="New pgloss Paint (Principled)",
                            icon="MATERIAL").mode = "PRINCIPLED"
            return
        col = layout.column(align=True)
        for label, _, _, _ in SLIDERS:
            col.prop(node.inputs[label], "default_value", text=label)
        col.prop(node.inputs["Colour space"], "default_value", text="Colour space (0 709, 1 ACEScg, 2 P3, 3 2020)")
        info = derived(mat)
        box = layout.box()
        if "rho_d" in info:
            r = info["rho_d"]
            box.label(text=f"ρd = ({r[0]:.4f}, {r[1]:.4f}, {r[2]:.4f})")
            box.label(text=f"ρs = {info['rho_s']:.4f}    α = {info['alpha']:.4f}")
        row = box.row()
        row.alert = not info["inside"]
        row.label(text=("In the model" if info["status"].value == 0 else info["reason"]),
                  icon="CHECKMARK" if info["inside"] else "ERROR")
        if not context.scene.cycles.shading_system:
            layout.label(text="Enable Open Shading Language (Cycles, CPU) to render it", icon="INFO")


CLASSES = (PglossPaintSettings, PGLOSS_OT_paint_new, PGLOSS_PT_paint)


def register():
    for c in CLASSES:
        bpy.utils.register_class(c)
    bpy.types.Material.pgloss = bpy.props.PointerProperty(type=PglossPaintSettings)


def unregister():
    del bpy.types.Material.pgloss
    for c in reversed(CLASSES):
        bpy.utils.unregister_class(c)
