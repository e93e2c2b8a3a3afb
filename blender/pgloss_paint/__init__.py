# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pgloss paint: a Cycles material driven by the perceptual parameters of Pellacini, Ferwerda &
Greenberg (SIGGRAPH 2000) — CIELAB lightness L*, a*, b*, contrast gloss c and
distinctness-of-image gloss d (Fig. 13) — through the OSL shader of the pgloss project.

"New pgloss Paint" in the material properties' "pgloss paint" panel (the operator
``material.pgloss_paint_new``) makes a material whose node group "pgloss paint" has the five sliders and the working colour
space; it drives an Internal OSL script (the self-contained pgloss_material.osl, so the .blend
carries it). The panel shows the derived ρd, ρs, α and the validity reason, computed by the
bundled pgloss package (the C library), and flags paints outside the model.
"""
from __future__ import annotations

import os
from typing import Any, Dict, Optional

import bpy

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


def new_material(name: str = "pgloss paint") -> bpy.types.Material:
    """A material with the node group wired to its output (Cycles with OSL renders it)."""
    mat = bpy.data.materials.new(name)
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    grp = nt.nodes.new("ShaderNodeGroup")
    grp.node_tree = node_group()
    grp.location, out.location = (-300, 0), (0, 0)
    nt.links.new(grp.outputs["BSDF"], out.inputs["Surface"])
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


class PGLOSS_OT_paint_new(bpy.types.Operator):
    """Add a pgloss paint material to the active object"""
    bl_idname = "material.pgloss_paint_new"
    bl_label = "New pgloss Paint"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        mat = new_material()
        ob = context.object
        if ob is not None and ob.type == "MESH":
            if ob.data.materials:
                ob.data.materials[ob.active_material_index] = mat
            else:
                ob.data.materials.append(mat)
        context.scene.render.engine = "CYCLES"
        context.scene.cycles.shading_system = True   # OSL
        return {"FINISHED"}


class PGLOSS_PT_paint(bpy.types.Panel):
    bl_label = "pgloss paint"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "material"

    def draw(self, context):
        layout = self.layout
        mat = context.material
        node = paint_node(mat)
        if node is None:
            layout.operator(PGLOSS_OT_paint_new.bl_idname, icon="MATERIAL")
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


CLASSES = (PGLOSS_OT_paint_new, PGLOSS_PT_paint)


def register():
    for c in CLASSES:
        bpy.utils.register_class(c)


def unregister():
    for c in reversed(CLASSES):
        bpy.utils.unregister_class(c)
