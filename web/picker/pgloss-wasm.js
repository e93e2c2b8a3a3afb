// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// pgloss-wasm.js — loads libpgloss compiled to WebAssembly (a WASI reactor, built by
// scripts/picker.sh from web/picker/wasm) and marshals arguments to its pgloss_* functions.
// It computes nothing itself: every number comes from the C core. Works in browsers and
// in Node (ES module, no dependencies, no emscripten).
//
// Every method returns {status, name, ...outputs}: `status` is the C pgloss_status,
// `name` its enumerator name (pgloss_status_name); outputs are what the C function wrote,
// also on errors (the headers document those fallbacks). Struct and array arguments are
// plain JS objects/arrays. `nulls` (optional, a list of C parameter names) passes NULL for
// those pointers instead, so that tests can reach PGLOSS_ERR_NULL.

const WASI_ENOSYS = 52;

// The core does no I/O and needs no WASI call; should a libc start-up import one anyway,
// it gets ENOSYS (proc_exit throws), so that a module never silently depends on a host.
function wasiStubs(module) {
  const imports = {};
  for (const imp of WebAssembly.Module.imports(module)) {
    if (imp.kind !== 'function') throw new Error(`pgloss.wasm imports ${imp.module}.${imp.name} (${imp.kind}); only WASI functions can be stubbed`);
    imports[imp.module] ??= {};
    imports[imp.module][imp.name] = imp.name === 'proc_exit'
      ? (code) => { throw new Error(`pgloss.wasm called proc_exit(${code})`); }
      : () => WASI_ENOSYS;
  }
  return imports;
}

async function bytesOf(source) {
  if (source instanceof ArrayBuffer || ArrayBuffer.isView(source)) return source;
  if (typeof source === 'string' || source instanceof URL) {
    const url = source instanceof URL ? source : new URL(source, globalThis.location?.href ?? import.meta.url);
    if (url.protocol === 'file:') {  // Node
      const { readFile } = await import('node:fs/promises');
      return readFile(url);
    }
    const resp = await fetch(url);
    if (!resp.ok) throw new Error(`cannot load ${url}: HTTP ${resp.status}`);
    return resp.arrayBuffer();
  }
  throw new TypeError('loadPgloss: give a URL, a path URL or the module bytes');
}

export async function loadPgloss(source = new URL('./pgloss.wasm', import.meta.url)) {
  const module = await WebAssembly.compile(await bytesOf(source));
  const instance = await WebAssembly.instantiate(module, wasiStubs(module));
  if (instance.exports._initialize) instance.exports._initialize();
  return new Pgloss(instance);
}

// Layout of the public structs on wasm32 (checked against the module at load time).
const PHYS = { size: 56, rho_d: 0, rho_s: 24, alpha_x: 32, alpha_y: 40, normalization: 48 };
const PERC = { size: 40, fields: ['L', 'a', 'b', 'c', 'd'] };
const BRIDGE = { size: 48, base_color: 0, roughness: 24, ior: 32, specular: 40 };
const READINGS = { size: 112 };  // pgloss_glossmeter_readings: 7 × {value, error}
const FINISH = { size: 48, name: 0, level: 4, gloss_60_min: 8, source: 40 };
// pgloss_bridge_shading: model, distribution, diffuse_both (int32), then doubles; 64-node tables.
const SHADING = { size: 1096, model: 0, distribution: 4, diffuse_both: 8, alpha: 16, f0: 24, eta: 32,
  base_color: 40, diffuse_scale: 64, specular_factor: 72, diffuse_factor: 584, nmu: 64 };

// The bridge's targets (pgloss_bridge_target) and the glossmeter's kinds (pgloss_glossmeter_kind),
// in enum order, under the names of their C enumerators without the prefix.
export const BRIDGE_TARGETS = ['openpbr', 'standard_surface', 'gltf', 'gltf_core', 'principled',
  'roughplastic_ggx', 'roughplastic_beckmann'];
export const GLOSSMETER_KINDS = ['GLOSS_20', 'GLOSS_60', 'GLOSS_85', 'HAZE_20', 'HAZE_INDEX', 'DOI_30',
  'CONTRAST_60'];
// pgloss_gloss_second: which reading accompanies the 60° gloss.
export const GLOSS_SECOND = { none: 0, gloss_20: 1, haze_20: 2, doi_30: 3 };

export class Pgloss {
  constructor(instance) {
    this.x = instance.exports;
    const lay = (i) => this.x.pgloss_wasm_layout(i) >>> 0;
    const got = Array.from({ length: 22 }, (_, i) => lay(i));
    const want = [PHYS.size, PHYS.rho_s, PHYS.alpha_x, PHYS.alpha_y, PHYS.normalization, PERC.size, 4,
      BRIDGE.size, BRIDGE.roughness, BRIDGE.ior, BRIDGE.specular, READINGS.size,
      FINISH.size, FINISH.level, FINISH.gloss_60_min, FINISH.source,
      SHADING.size, SHADING.alpha, SHADING.base_color, SHADING.diffuse_scale, SHADING.specular_factor, SHADING.diffuse_factor];
    if (got.join() !== want.join()) throw new Error(`pgloss.wasm struct layout ${got} is not the loader's ${want}`);
    this.scratchSize = 16384;  // bytes: room for a 1000-point isogloss contour
    this.scratch = this.x.malloc(this.scratchSize);
    if (!this.scratch) throw new Error('pgloss.wasm: malloc failed');
    this._names = new Map();
  }

  // --- memory helpers -------------------------------------------------------------------
  get f64() { return new Float64Array(this.x.memory.buffer); }
  get i32() { return new Int32Array(this.x.memory.buffer); }
  cstring(ptr) {
    const u8 = new Uint8Array(this.x.memory.buffer);
    let end = ptr;
    while (u8[end]) end++;
    return new TextDecoder().decode(u8.subarray(ptr, end));
  }
  // A bump allocator over the scratch block, reset per call (calls are not re-entrant).
  _arena() {
    let top = this.scratch;
    const limit = this.scratch + this.scratchSize;
    return (bytes) => {
      const p = (top + 7) & ~7;
      top = p + bytes;
      if (top > limit) throw new Error('pgloss.wasm: scratch block too small');
      this.f64.fill(0, p / 8, (p + bytes + 7) / 8 | 0);
      return p;
    };
  }
  _result(st, out) {
    return { status: st, name: this.statusName(st), ...out };
  }
  _writePhysical(ptr, p) {
    const f = this.f64;
    const rd = Array.isArray(p.rho_d) ? p.rho_d : [p.rho_d, p.rho_d, p.rho_d];
    f.set(rd.map(Number), (ptr + PHYS.rho_d) / 8);
    f[(ptr + PHYS.rho_s) / 8] = p.rho_s;
    f[(ptr + PHYS.alpha_x) / 8] = p.alpha_x ?? p.alpha;
    f[(ptr + PHYS.alpha_y) / 8] = p.alpha_y ?? p.alpha_x ?? p.alpha;
    this.i32[(ptr + PHYS.normalization) / 4] = p.normalization ?? 0;
  }
  _readPhysical(ptr) {
    const f = this.f64;
    return {
      rho_d: Array.from(f.subarray((ptr + PHYS.rho_d) / 8, (ptr + PHYS.rho_d) / 8 + 3)),
      rho_s: f[(ptr + PHYS.rho_s) / 8], alpha_x: f[(ptr + PHYS.alpha_x) / 8],
      alpha_y: f[(ptr + PHYS.alpha_y) / 8], normalization: this.i32[(ptr + PHYS.normalization) / 4],
    };
  }
  _writePerceptual(ptr, q) { this.f64.set(PERC.fields.map((k) => q[k]), ptr / 8); }
  _readPerceptual(ptr) {
    const f = this.f64;
    return Object.fromEntries(PERC.fields.map((k, i) => [k, f[ptr / 8 + i]]));
  }
  // Scalar-in, doubles-out functions: fn(inputs…, double *out…).
  _scalar(cname, inputs, outNames, nulls = []) {
    const alloc = this._arena();
    const ptrs = outNames.map((n) => (nulls.includes(n) ? 0 : alloc(8)));
    const st = this.x[cname](...inputs, ...ptrs);
    const out = {};
    outNames.forEach((n, i) => { if (ptrs[i]) out[n] = this.f64[ptrs[i] / 8]; });
    return this._result(st, out);
  }

  // --- status.h ---------------------------------------------------------------------------
  statusName(st) {
    if (!this._names.has(st)) this._names.set(st, this.cstring(this.x.pgloss_status_name(st)));
    return this._names.get(st);
  }
  statusString(st) { return this.cstring(this.x.pgloss_status_string(st)); }

  // --- perceptual.h -----------------------------------------------------------------------
  lightnessFromLuminance(Y, nulls) { return this._scalar('pgloss_lightness_from_luminance', [Y], ['L'], nulls); }
  luminanceFromLightness(L, nulls) { return this._scalar('pgloss_luminance_from_lightness', [L], ['Y'], nulls); }
  contrastGloss(rho_d, rho_s, nulls) { return this._scalar('pgloss_contrast_gloss', [rho_d, rho_s], ['c'], nulls); }
  specularFromContrast(rho_d, c, nulls) { return this._scalar('pgloss_specular_from_contrast', [rho_d, c], ['rho_s'], nulls); }
  glossFromPhysical(rho_d, rho_s, alpha, nulls) {
    return this._scalar('pgloss_gloss_from_physical', [rho_d, rho_s, alpha], ['L', 'c', 'd'], nulls);
  }
  physicalFromGloss(L, c, d, nulls) {
    return this._scalar('pgloss_physical_from_gloss', [L, c, d], ['rho_d', 'rho_s', 'alpha'], nulls);
  }
  glossDistance(c1, d1, c2, d2, nulls) { return this._scalar('pgloss_gloss_distance', [c1, d1, c2, d2], ['D'], nulls); }
  envelopeContrast(L, nulls) { return this._scalar('pgloss_envelope_contrast', [L], ['c_max'], nulls); }
  matchGloss(rho_d, rho_s, L_target, nulls) {
    return this._scalar('pgloss_match_gloss', [rho_d, rho_s, L_target], ['rho_d_out', 'rho_s_out'], nulls);
  }
  isoglossContour(c0, d0, D, n, nulls = []) {
    const alloc = this._arena();
    const bytes = 8 * Math.max(n, 1);
    const pc = nulls.includes('c') ? 0 : alloc(bytes), pd = nulls.includes('d') ? 0 : alloc(bytes);
    const st = this.x.pgloss_isogloss_contour(c0, d0, D, n >>> 0, pc, pd);
    const out = {};
    if (pc) out.c = Array.from(this.f64.subarray(pc / 8, pc / 8 + n));
    if (pd) out.d = Array.from(this.f64.subarray(pd / 8, pd / 8 + n));
    return this._result(st, out);
  }
  checkPhysical(p, nulls = []) {
    const alloc = this._arena();
    let pp = 0;
    if (!nulls.includes('p')) { pp = alloc(PHYS.size); this._writePhysical(pp, p); }
    return this._result(this.x.pgloss_check_physical(pp), {});
  }
  checkPerceptual(q, nulls = []) {
    const alloc = this._arena();
    let pq = 0;
    if (!nulls.includes('q')) { pq = alloc(PERC.size); this._writePerceptual(pq, q); }
    return this._result(this.x.pgloss_check_perceptual(pq), {});
  }
  physicalFromPerceptual(q, normalization = 0, nulls = []) {
    const alloc = this._arena();
    let pq = 0, pp = 0;
    if (!nulls.includes('q')) { pq = alloc(PERC.size); this._writePerceptual(pq, q); }
    if (!nulls.includes('p')) pp = alloc(PHYS.size);
    const st = this.x.pgloss_physical_from_perceptual(pq, normalization, pp);
    return this._result(st, pp ? this._readPhysical(pp) : {});
  }
  perceptualFromPhysical(p, nulls = []) {
    const alloc = this._arena();
    let pp = 0, pq = 0;
    if (!nulls.includes('p')) { pp = alloc(PHYS.size); this._writePhysical(pp, p); }
    if (!nulls.includes('q')) pq = alloc(PERC.size);
    const st = this.x.pgloss_perceptual_from_physical(pp, pq);
    return this._result(st, pq ? this._readPerceptual(pq) : {});
  }
  // The _ex forms: the same in a working colour space (pgloss_color_space: 0 linear Rec. 709,
  // 1 ACEScg, 2 linear Display P3), as perceptual.h's *_ex.
  checkPerceptualEx(q, space, nulls = []) {
    const alloc = this._arena();
    let pq = 0;
    if (!nulls.includes('q')) { pq = alloc(PERC.size); this._writePerceptual(pq, q); }
    return this._result(this.x.pgloss_check_perceptual_ex(pq, space), {});
  }
  physicalFromPerceptualEx(q, normalization, space, nulls = []) {
    const alloc = this._arena();
    let pq = 0, pp = 0;
    if (!nulls.includes('q')) { pq = alloc(PERC.size); this._writePerceptual(pq, q); }
    if (!nulls.includes('p')) pp = alloc(PHYS.size);
    const st = this.x.pgloss_physical_from_perceptual_ex(pq, normalization, space, pp);
    return this._result(st, pp ? this._readPhysical(pp) : {});
  }
  perceptualFromPhysicalEx(p, space, nulls = []) {
    const alloc = this._arena();
    let pp = 0, pq = 0;
    if (!nulls.includes('p')) { pp = alloc(PHYS.size); this._writePhysical(pp, p); }
    if (!nulls.includes('q')) pq = alloc(PERC.size);
    const st = this.x.pgloss_perceptual_from_physical_ex(pp, space, pq);
    return this._result(st, pq ? this._readPerceptual(pq) : {});
  }

  // --- color.h ----------------------------------------------------------------------------
  // space: undefined for the functions without _ex, else the pgloss_color_space of *_ex.
  _vec3(cname, inName, v, outName, outLen, nulls = [], space = undefined) {
    const alloc = this._arena();
    let pin = 0;
    if (!nulls.includes(inName)) { pin = alloc(24); this.f64.set(v.map(Number), pin / 8); }
    const pout = nulls.includes(outName) ? 0 : alloc(8 * outLen);
    const st = space === undefined ? this.x[cname](pin, pout) : this.x[cname](pin, space, pout);
    const out = {};
    if (pout) out[outName] = outLen === 1 ? this.f64[pout / 8] : Array.from(this.f64.subarray(pout / 8, pout / 8 + outLen));
    return this._result(st, out);
  }
  rgbFromLab(lab, nulls) { return this._vec3('pgloss_rgb_from_lab', 'lab', lab, 'rgb', 3, nulls); }
  labFromRgb(rgb, nulls) { return this._vec3('pgloss_lab_from_rgb', 'rgb', rgb, 'lab', 3, nulls); }
  luminance(rgb, nulls) { return this._vec3('pgloss_luminance', 'rgb', rgb, 'Y', 1, nulls); }
  rgbFromLabEx(lab, space, nulls) { return this._vec3('pgloss_rgb_from_lab_ex', 'lab', lab, 'rgb', 3, nulls, space); }
  labFromRgbEx(rgb, space, nulls) { return this._vec3('pgloss_lab_from_rgb_ex', 'rgb', rgb, 'lab', 3, nulls, space); }
  luminanceEx(rgb, space, nulls) { return this._vec3('pgloss_luminance_ex', 'rgb', rgb, 'Y', 1, nulls, space); }

  // --- bridge.h ---------------------------------------------------------------------------
  // target: a pgloss_bridge_target number or its short name (BRIDGE_TARGETS).
  _target(t) {
    if (typeof t === 'number') return t;
    const i = BRIDGE_TARGETS.indexOf(t);
    return i >= 0 ? i : 99;  // an unknown name reaches the core as an unknown target: ARGUMENT
  }
  _writeBridge(ptr, p) {
    const f = this.f64;
    f.set(p.base_color.map(Number), (ptr + BRIDGE.base_color) / 8);
    f[(ptr + BRIDGE.roughness) / 8] = p.roughness;
    f[(ptr + BRIDGE.ior) / 8] = p.ior;
    f[(ptr + BRIDGE.specular) / 8] = p.specular;
  }
  _readBridge(ptr) {
    const f = this.f64;
    return {
      base_color: Array.from(f.subarray(ptr / 8, ptr / 8 + 3)), roughness: f[(ptr + BRIDGE.roughness) / 8],
      ior: f[(ptr + BRIDGE.ior) / 8], specular: f[(ptr + BRIDGE.specular) / 8],
    };
  }
  bridgeTargetName(t) { return this.cstring(this.x.pgloss_bridge_target_name(this._target(t))); }
  // Paint → the target's parameters (`params`) and the paint they reach (`reached`: the paint, or
  // the nearest reachable one when the status is BRIDGE_BASE / _SPECULAR / _ROUGHNESS).
  bridgeFromPerceptual(target, q) {
    const alloc = this._arena();
    const pq = alloc(PERC.size), pp = alloc(BRIDGE.size), pr = alloc(PERC.size);
    this._writePerceptual(pq, q);
    const st = this.x.pgloss_bridge_from_perceptual(this._target(target), pq, pp, pr);
    return this._result(st, { params: this._readBridge(pp), reached: this._readPerceptual(pr) });
  }
  bridgeToPerceptual(target, params) {
    const alloc = this._arena();
    const pp = alloc(BRIDGE.size), pq = alloc(PERC.size), pres = alloc(8);
    this._writeBridge(pp, params);
    const st = this.x.pgloss_bridge_to_perceptual(this._target(target), pp, pq, pres);
    return this._result(st, { paint: this._readPerceptual(pq), residual: this.f64[pres / 8] });
  }
  bridgeModelInputs(target, params) {
    const alloc = this._arena();
    const pp = alloc(BRIDGE.size), o = alloc(24);
    this._writeBridge(pp, params);
    const st = this.x.pgloss_bridge_model_inputs(this._target(target), pp, o, o + 8, o + 16);
    const f = this.f64;
    return this._result(st, { beta: f[o / 8], f0: f[o / 8 + 1], alpha: f[o / 8 + 2] });
  }
  bridgeParamsFromModel(target, base_color, f0, alpha) {
    const alloc = this._arena();
    const pb = alloc(24), pp = alloc(BRIDGE.size);
    this.f64.set(base_color.map(Number), pb / 8);
    const st = this.x.pgloss_bridge_params_from_model(this._target(target), pb, f0, alpha, pp);
    return this._result(st, { params: this._readBridge(pp) });
  }
  bridgeRange(target) {
    const o = this._arena()(32);
    const st = this.x.pgloss_bridge_range(this._target(target), o, o + 8, o + 16, o + 24);
    const f = this.f64;
    return this._result(st, { f0_min: f[o / 8], f0_max: f[o / 8 + 1], alpha_min: f[o / 8 + 2], alpha_max: f[o / 8 + 3] });
  }

  // --- bridge_model.h ---------------------------------------------------------------------
  _readShading(ptr) {
    const f = this.f64, i = this.i32, d = (o) => f[(ptr + o) / 8], tab = (o) => Array.from(f.subarray((ptr + o) / 8, (ptr + o) / 8 + SHADING.nmu));
    return {
      model: i[(ptr + SHADING.model) / 4], distribution: i[(ptr + SHADING.distribution) / 4],
      diffuse_both: i[(ptr + SHADING.diffuse_both) / 4], alpha: d(SHADING.alpha), f0: d(SHADING.f0), eta: d(SHADING.eta),
      base_color: Array.from(f.subarray((ptr + SHADING.base_color) / 8, (ptr + SHADING.base_color) / 8 + 3)),
      diffuse_scale: d(SHADING.diffuse_scale), specular_factor: tab(SHADING.specular_factor), diffuse_factor: tab(SHADING.diffuse_factor),
    };
  }
  _writeShading(ptr, s) {
    const f = this.f64, i = this.i32;
    i[(ptr + SHADING.model) / 4] = s.model; i[(ptr + SHADING.distribution) / 4] = s.distribution;
    i[(ptr + SHADING.diffuse_both) / 4] = s.diffuse_both;
    for (const k of ['alpha', 'f0', 'eta', 'diffuse_scale']) f[(ptr + SHADING[k]) / 8] = s[k];
    f.set(s.base_color, (ptr + SHADING.base_color) / 8);
    f.set(s.specular_factor, (ptr + SHADING.specular_factor) / 8);
    f.set(s.diffuse_factor, (ptr + SHADING.diffuse_factor) / 8);
  }
  // A target's BRDF as the renderer draws it: {shading: {model, distribution, diffuse_both, alpha,
  // f0, eta, base_color, diffuse_scale, specular_factor[64], diffuse_factor[64]}}.
  bridgeShading(target, params) {
    const alloc = this._arena();
    const pp = alloc(BRIDGE.size), ps = alloc(SHADING.size);
    this._writeBridge(pp, params);
    const st = this.x.pgloss_bridge_shading_init(this._target(target), pp, ps);
    return this._result(st, { shading: this._readShading(ps) });
  }
  // f = specular + diffuse · base_color at unit local directions wo, wi (normal +z).
  bridgeShadingEval(shading, wo, wi) {
    const alloc = this._arena();
    const ps = alloc(SHADING.size), po = alloc(24), pi = alloc(24), o = alloc(16);
    this._writeShading(ps, shading);
    this.f64.set(wo, po / 8);
    this.f64.set(wi, pi / 8);
    const st = this.x.pgloss_bridge_shading_eval(ps, po, pi, o, o + 8);
    return this._result(st, { specular: this.f64[o / 8], diffuse: this.f64[o / 8 + 1] });
  }

  // --- glossmeter.h -----------------------------------------------------------------------
  // kind: a pgloss_glossmeter_kind number or its name (GLOSSMETER_KINDS, with or without PGLOSS_).
  _kind(k) {
    if (typeof k === 'number') return k;
    const i = GLOSSMETER_KINDS.indexOf(String(k).replace(/^PGLOSS_/, ''));
    return i >= 0 ? i : 99;
  }
  _reading(cname, args) {
    const o = this._arena()(16);
    const st = this.x[cname](...args, o);
    return this._result(st, { value: this.f64[o / 8], error: this.f64[o / 8 + 1] });
  }
  _readings(ptr) {
    const f = this.f64;
    return Object.fromEntries(GLOSSMETER_KINDS.map((k, i) => [k, { value: f[ptr / 8 + 2 * i], error: f[ptr / 8 + 2 * i + 1] }]));
  }
  fresnelDielectric(n, c) { return this._scalar('pgloss_fresnel_dielectric', [n, c], ['value']); }
  glossmeterStandardFlux(kind) { return this._scalar('pgloss_wasm_standard_flux', [this._kind(kind)], ['value']); }
  // An ideal dielectric mirror of index n, and a perfect diffuser of albedo rho (meter.c).
  glossmeterReadFresnel(kind, n, tol = 0) { return this._reading('pgloss_wasm_read_fresnel', [this._kind(kind), n, tol]); }
  glossmeterReadLambert(kind, rho, tol = 0) { return this._reading('pgloss_wasm_read_lambert', [this._kind(kind), rho, tol]); }
  glossmeterReadPhysical(kind, p, azimuth_deg = 0, tol = 0) {
    const alloc = this._arena();
    const pp = alloc(PHYS.size), o = alloc(16);
    this._writePhysical(pp, p);
    const st = this.x.pgloss_glossmeter_read_physical(this._kind(kind), pp, azimuth_deg, tol, o);
    return this._result(st, { value: this.f64[o / 8], error: this.f64[o / 8 + 1] });
  }
  // Every reading at once: {readings: {GLOSS_60: {value, error}, …}}.
  glossmeterReadingsPhysical(p, azimuth_deg = 0, tol = 0) {
    const alloc = this._arena();
    const pp = alloc(PHYS.size), o = alloc(READINGS.size);
    this._writePhysical(pp, p);
    const st = this.x.pgloss_glossmeter_readings_physical(pp, azimuth_deg, tol, o);
    return this._result(st, { readings: this._readings(o) });
  }
  glossmeterReadingsBridge(target, params, azimuth_deg = 0, tol = 0) {
    const alloc = this._arena();
    const pp = alloc(BRIDGE.size), o = alloc(READINGS.size);
    this._writeBridge(pp, params);
    const st = this.x.pgloss_glossmeter_readings_bridge(this._target(target), pp, azimuth_deg, tol, o);
    return this._result(st, { readings: this._readings(o) });
  }
  // The Ward paint of colour (L*, a*, b*) whose 60° gloss is gloss_60 GU; `second` (GLOSS_SECOND)
  // names the other reading, or with `none` d itself (outside (0, 1): the assumed d).
  paintFromGlossUnits(L, a, b, normalization, gloss_60, second = 'none', d_or_second = 0) {
    const alloc = this._arena();
    const pq = alloc(PERC.size), pp = alloc(PHYS.size);
    const sec = typeof second === 'number' ? second : (GLOSS_SECOND[second] ?? 99);
    const st = this.x.pgloss_paint_from_gloss_units(L, a, b, normalization, gloss_60, sec, d_or_second, pq, pp);
    return this._result(st, { q: this._readPerceptual(pq), p: this._readPhysical(pp) });
  }
  _finish(ptr) {
    if (!ptr) return null;
    const f = this.f64, u32 = new Uint32Array(this.x.memory.buffer);
    const g = (ptr + FINISH.gloss_60_min) / 8;
    return {
      ptr, name: this.cstring(u32[(ptr + FINISH.name) / 4]), level: this.cstring(u32[(ptr + FINISH.level) / 4]),
      gloss_60_min: f[g], gloss_60_max: f[g + 1], sheen_85_min: f[g + 2], sheen_85_max: f[g + 3],
      source: this.cstring(u32[(ptr + FINISH.source) / 4]),
    };
  }
  // The MPI finishes G1–G7, in order.
  finishes() {
    const out = [];
    for (let i = 0; ; i++) {
      const f = this._finish(this.x.pgloss_finish_at(i));
      if (!f) return out;
      out.push(f);
    }
  }
  finishFind(name) {
    const bytes = new TextEncoder().encode(String(name));
    const p = this._arena()(bytes.length + 1);
    new Uint8Array(this.x.memory.buffer).set([...bytes, 0], p);
    return this._finish(this.x.pgloss_finish_find(p));
  }
  // A finish's representative paint at a colour, and the (c, d) it spans.
  finishPaint(name, L, a, b, normalization = 0) {
    const f = this.finishFind(name);
    const alloc = this._arena();
    const pq = alloc(PERC.size), pp = alloc(PHYS.size), pc = alloc(16), pd = alloc(16), ps = alloc(4);
    const st = this.x.pgloss_finish_paint(f ? f.ptr : 0, L, a, b, normalization, pq, pp, pc, pd, ps);
    const fl = this.f64;
    return this._result(st, {
      finish: f, q: this._readPerceptual(pq), p: this._readPhysical(pp),
      c_range: [fl[pc / 8], fl[pc / 8 + 1]], d_range: [fl[pd / 8], fl[pd / 8 + 1]], sheen_ok: this.i32[ps / 4] !== 0,
    });
  }
}
