// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// targets.js — the picker's render targets and their export formats. A target is the Ward paint
// itself or one of the gloss bridge's (pgloss/bridge.h) dielectric BRDFs; its parameters come
// from the C core (pgloss_bridge_from_perceptual), this file only names them as each target does
// (the names of `pgloss bridge` and of pgloss.bridge.Params.named; docs/bridge.md cites each
// convention) and writes them in each target's file format.

// Mitsuba 3's default exterior index, "air" (its `ext_ior` default; bridge.h).
export const MITSUBA_AIR = 1.000277;

// id: the picker's name (URL hash `target=`); bridge: the pgloss_bridge_target short name
// (null: the Ward paint); names: the target's own names of (base colour, roughness, IOR,
// specular) and its fixed inputs.
export const TARGETS = [
  { id: 'ward', label: 'Ward (the paint, eq. 2)', bridge: null },
  { id: 'openpbr', label: 'OpenPBR Surface', bridge: 'openpbr',
    names: ['base_color', 'specular_roughness', 'specular_ior', 'specular_weight'], fixed: { base_weight: 1 } },
  { id: 'standard_surface', label: 'Autodesk Standard Surface', bridge: 'standard_surface',
    names: ['base_color', 'specular_roughness', 'specular_IOR', 'specular'], fixed: { base: 1 } },
  { id: 'gltf', label: 'glTF 2.0 (KHR_materials_ior, _specular)', bridge: 'gltf',
    names: ['baseColorFactor', 'roughnessFactor', 'ior', 'specularFactor'], fixed: { metallicFactor: 0 } },
  { id: 'gltf_core', label: 'glTF 2.0 core (no extensions)', bridge: 'gltf_core',
    names: ['baseColorFactor', 'roughnessFactor', 'ior', 'specularFactor'], fixed: { metallicFactor: 0 } },
  { id: 'principled', label: 'Blender Principled BSDF', bridge: 'principled',
    names: ['Base Color', 'Roughness', 'IOR', 'Specular IOR Level'], fixed: { Metallic: 0 } },
  { id: 'roughplastic_ggx', label: 'Mitsuba 3 roughplastic (GGX)', bridge: 'roughplastic_ggx',
    names: ['diffuse_reflectance', 'alpha', 'int_ior', null], fixed: { distribution: 'ggx', ext_ior: MITSUBA_AIR, nonlinear: false } },
  { id: 'roughplastic_beckmann', label: 'Mitsuba 3 roughplastic (Beckmann)', bridge: 'roughplastic_beckmann',
    names: ['diffuse_reflectance', 'alpha', 'int_ior', null], fixed: { distribution: 'beckmann', ext_ior: MITSUBA_AIR, nonlinear: false } },
];
export const targetOf = (id) => TARGETS.find((t) => t.id === id);

// A bridge_params object under the target's own names, with its fixed inputs (glTF's
// baseColorFactor is RGBA: alpha 1).
export function namedParams(target, p) {
  const [base, rough, ior, spec] = target.names;
  const color = base === 'baseColorFactor' ? [...p.base_color, 1] : [...p.base_color];
  const out = { [base]: color, [rough]: p.roughness, [ior]: p.ior };
  if (spec) out[spec] = p.specular;
  return { ...out, ...target.fixed };
}

// ---- exports ----------------------------------------------------------------------------
// Each export takes the parameters the core wrote (for an out-of-reach paint: the nearest
// reachable paint's, which the export says) and `note`: {status, reason, requested, reached}.
// 9 significant digits: a relative rounding below 5e-9, far under any visible or measurable step.
const num = (x) => Number(x.toPrecision(9));
const paintNum = (q) => (q ? Object.fromEntries(Object.entries(q).map(([k, v]) => [k, num(v)])) : null);
const xmlEscape = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
const xmlComment = (s) => String(s).replace(/--/g, '- -');

function noteLines(note) {
  const q = (p) => `L*=${num(p.L)} a*=${num(p.a)} b*=${num(p.b)} c=${num(p.c)} d=${num(p.d)}`;
  const lines = [`pgloss paint ${q(note.requested)}`, `status ${note.name}: ${note.reason}`];
  if (note.status < 0 && note.reached) lines.push(`out of reach: these are the parameters of the nearest reachable paint ${q(note.reached)}`);
  return lines;
}

// glTF 2.0: one material, metallic 0; KHR_materials_ior only where the ior is not glTF's 1.5 and
// KHR_materials_specular only where specularFactor is not 1 (glTF 2.0 §3.9.2 and the two
// extensions' specifications: F0 = ((ior − 1)/(ior + 1))² · specularFactor for a dielectric).
export function gltfDocument(p, note) {
  const mat = {
    name: 'pgloss_paint',
    pbrMetallicRoughness: {
      baseColorFactor: [...p.base_color.map(num), 1], metallicFactor: 0, roughnessFactor: num(p.roughness),
    },
    extras: { pgloss: { status: note.name, reason: note.reason, requested: paintNum(note.requested), reached: paintNum(note.reached) } },
  };
  const ext = {};
  if (p.ior !== 1.5) ext.KHR_materials_ior = { ior: num(p.ior) };
  if (p.specular !== 1) ext.KHR_materials_specular = { specularFactor: num(p.specular) };
  const used = Object.keys(ext);
  if (used.length) mat.extensions = ext;
  const doc = { asset: { version: '2.0', generator: 'pgloss picker' }, materials: [mat] };
  if (used.length) doc.extensionsUsed = used;
  return JSON.stringify(doc, null, 2);
}

// MaterialX 1.39: a surfacematerial over open_pbr_surface or standard_surface (the nodes of
// MaterialX's standard library; input names as in their nodedefs).
export function materialxDocument(node, p, note) {
  const inputs = node === 'open_pbr_surface'
    ? [['base_weight', 'float', 1], ['base_color', 'color3', p.base_color], ['specular_weight', 'float', p.specular],
      ['specular_roughness', 'float', p.roughness], ['specular_ior', 'float', p.ior]]
    : [['base', 'float', 1], ['base_color', 'color3', p.base_color], ['specular', 'float', p.specular],
      ['specular_roughness', 'float', p.roughness], ['specular_IOR', 'float', p.ior]];
  const value = (v) => (Array.isArray(v) ? v.map(num).join(', ') : String(num(v)));
  return ['<?xml version="1.0"?>', '<materialx version="1.39">',
    ...noteLines(note).map((l) => `  <!-- ${xmlComment(l)} -->`),
    `  <${node} name="pgloss_surface" type="surfaceshader">`,
    ...inputs.map(([n, t, v]) => `    <input name="${n}" type="${t}" value="${value(v)}" />`),
    `  </${node}>`,
    '  <surfacematerial name="pgloss_material" type="material">',
    '    <input name="surfaceshader" type="surfaceshader" nodename="pgloss_surface" />',
    '  </surfacematerial>', '</materialx>'].join('\n');
}

// Blender's Principled BSDF inputs (by their UI names) and the lines of Python that set them.
export function blenderValues(p, note) {
  const v = { 'Base Color': [...p.base_color.map(num), 1], Metallic: 0, Roughness: num(p.roughness), IOR: num(p.ior),
    'Specular IOR Level': num(p.specular) };
  return [...noteLines(note).map((l) => `# ${l}`),
    'import bpy',
    'mat = bpy.data.materials.new("pgloss_paint")',
    'mat.use_nodes = True',
    'bsdf = mat.node_tree.nodes["Principled BSDF"]',
    ...Object.entries(v).map(([k, x]) => `bsdf.inputs["${k}"].default_value = ${Array.isArray(x) ? `(${x.join(', ')})` : x}`),
  ].join('\n');
}

// Mitsuba 3: a roughplastic <bsdf> (its plugin parameters; ext_ior is its default, air).
export function mitsubaBsdf(distribution, p, note) {
  return [...noteLines(note).map((l) => `<!-- ${xmlComment(l)} -->`),
    '<bsdf version="3.0.0" type="roughplastic" id="pgloss_paint">',
    `  <string name="distribution" value="${xmlEscape(distribution)}"/>`,
    `  <float name="alpha" value="${num(p.roughness)}"/>`,
    `  <float name="int_ior" value="${num(p.ior)}"/>`,
    `  <float name="ext_ior" value="${MITSUBA_AIR}"/>`,
    `  <rgb name="diffuse_reflectance" value="${p.base_color.map(num).join(', ')}"/>`,
    '  <boolean name="nonlinear" value="false"/>',
    '</bsdf>'].join('\n');
}
