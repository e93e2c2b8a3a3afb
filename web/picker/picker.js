// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// picker.js — the colour/gloss picker of Fig. 13: controls, read-outs, the c–d plot,
// match-gloss view, render targets, glossmeter readings, export and URL-hash state. Every
// conversion (eqs. 3–8, Lab → RGB, validity, envelope, matching, isogloss contours, the gloss
// bridge to each target, the glossmeter, gloss units and finishes) is a call into libpgloss
// (pgloss.wasm); this file only moves numbers between the controls, the C core and the renderer.
//
// Query options (for tests and slow GPUs): ?autorun=0 (no render loop: call
// picker.tracer.step()), ?size=WxH (canvas size of the single view), ?maxspp=N.
import { loadPgloss } from './pgloss-wasm.js';
import { parseStimulusScene } from './scene.js';
import { Tracer } from './render.js';
import { TARGETS, targetOf, namedParams, gltfDocument, materialxDocument, blenderValues, mitsubaBsdf } from './targets.js';

const $ = (id) => document.getElementById(id);
const query = new URLSearchParams(location.search);
const AUTORUN = query.get('autorun') !== '0';
const MAX_SPP = Number(query.get('maxspp') ?? 4096);
const SIZE = (query.get('size') ?? '480x360').split('x').map(Number);

// Fig. 12's three lightnesses: the stimulus scene's white, grey and black paints (ρd).
const MATCH_RHO_D = [0.767, 0.193, 0.03];
const MATCH_NAMES = ['white', 'grey', 'black'];
const PERCEPTUAL_KEYS = ['L', 'a', 'b', 'c', 'd'];
const PHYSICAL_KEYS = ['rd_r', 'rd_g', 'rd_b', 'rho_s', 'alpha'];
// The default paint: the stimulus scene's grey (ρd .193, ρs .066, α .07) ≈ Fig. 11's reference.
const DEFAULT = { mode: 'perceptual', view: 'single', L: 51.04, a: 0, b: 0, c: 0.087, d: 0.93,
  rd_r: 0.193, rd_g: 0.193, rd_b: 0.193, rho_s: 0.066, alpha: 0.07, export: 'json', target: 'ward' };
// The bridge's out-of-reach statuses: the parameters written are the nearest reachable paint's.
const REACH = ['PGLOSS_ERR_BRIDGE_BASE', 'PGLOSS_ERR_BRIDGE_SPECULAR', 'PGLOSS_ERR_BRIDGE_ROUGHNESS'];
// The glossmeter's quadrature tolerance for the read-outs (relative; 4 digits are shown).
const METER_TOL = 1e-5;

let pg;            // the C core
let tracer = null; // null when WebGL2 is missing (the page still converts)
const state = { ...DEFAULT };
let model = null;  // the last conversion: what is displayed and rendered

// ---- formatting -------------------------------------------------------------------------
// What a person reads and what the exports carry: 6 significant digits. A step of 1e-6
// relative moves L* by < 1e-4 and c, d by < 1e-6 — far below a just-noticeable difference and
// the ΔD 0.04 isogloss step — and hides a double's rounding noise (1 − 0.95 =
// 0.050000000000000044, c = 0.08699999999999998 after a round trip through ρs). The state and
// the URL hash keep the exact doubles, so that a link reproduces the paint bit for bit.
const fmt = (x, digits = 6) => (Number.isFinite(x) ? Number(x.toPrecision(digits)).toString() : String(x));
const exact = (x) => String(x);  // shortest round-trip decimal of the double
const glslFloat = (x) => { const s = fmt(x); return /[.eE]/.test(s) ? s : `${s}.0`; };
// A number for the JSON export: rounded as shown, not-finite values as null (JSON has no NaN).
const jsonNum = (x) => (Number.isFinite(x) ? Number(x.toPrecision(6)) : null);
const statusClass = (st) => (st === 0 ? 'ok' : st > 0 ? 'warn' : 'bad');

// ---- the model: state → numbers from the C core ---------------------------------------
function convert() {
  const m = {};
  if (state.mode === 'perceptual') {
    const q = { L: state.L, a: state.a, b: state.b, c: state.c, d: state.d };
    const conv = pg.physicalFromPerceptual(q, 0);
    const check = pg.checkPerceptual(q);
    m.perceptual = q;
    m.physical = { rho_d: conv.rho_d, rho_s: conv.rho_s, alpha: conv.alpha_x };
    m.convStatus = conv.status;
    // The status shown is pgloss_check_perceptual's: the first reason the paint is outside
    // the model (envelope, energy, gamut, …); the conversion alone does not test the
    // envelope (perceptual.h), and its values are shown as computed, never clamped.
    m.status = check.status;
  } else {
    const p = { rho_d: [state.rd_r, state.rd_g, state.rd_b], rho_s: state.rho_s, alpha: state.alpha };
    const back = pg.perceptualFromPhysical(p);
    const check = pg.checkPhysical(p);
    m.physical = p;
    m.perceptual = { L: back.L, a: back.a, b: back.b, c: back.c, d: back.d };
    m.convStatus = back.status;
    m.status = check.status;
  }
  m.name = pg.statusName(m.status);
  m.reason = pg.statusString(m.status);
  const env = pg.envelopeContrast(m.perceptual.L);
  m.envelope = env.status === 0 ? env.c_max : NaN;
  m.envelopeStatus = env.status;
  const Y = pg.luminance(m.physical.rho_d);
  m.Y = Y.Y;
  // Renderable: what pgloss_material_init accepts (finite, non-negative ρ, α > 0). An
  // energy-violating paint (beyond the envelope) renders, flagged; the others do not.
  const phys = pg.checkPhysical({ ...m.physical });
  m.renderable = ![-2, -3, -4].includes(phys.status);
  m.physicalCheck = phys;
  m.target = state.target === 'ward' ? null : bridgeOf(m.perceptual, state.target);
  m.shading = m.target && m.target.params ? shadingOf(m.target) : null;
  m.meter = meterReadings(m);
  return m;
}

// The paint in a bridge target: its parameters, the status and the core's reason. Out of the
// target's reach the core writes the nearest reachable paint's parameters (`reached`); for a
// paint outside the model (ENVELOPE, GAMUT, …) it writes nothing usable: params null.
function bridgeOf(q, id) {
  const def = targetOf(id);
  const r = pg.bridgeFromPerceptual(def.bridge, q);
  const written = r.status >= 0 || REACH.includes(r.name);
  return { def, status: r.status, name: r.name, reason: pg.statusString(r.status), requested: { ...q },
    params: written ? r.params : null, reached: written ? r.reached : null };
}

// The target's BRDF as the tracer renders it (pgloss_bridge_shading_init; tens of milliseconds
// in WebAssembly, so cached like the meter's readings). Null where the core refuses it.
const shadingCache = new Map();
function shadingOf(t) {
  const key = JSON.stringify([t.def.bridge, t.params]);
  if (!shadingCache.has(key)) {
    if (shadingCache.size > 64) shadingCache.clear();
    const r = pg.bridgeShading(t.def.bridge, t.params);
    shadingCache.set(key, r.status === 0 ? r.shading : null);
  }
  return shadingCache.get(key);
}

// The virtual glossmeter (glossmeter.h) on the Ward paint and on the target's material,
// recomputed only when the material changes (a reading takes tens of milliseconds).
const meterCache = new Map();
function cachedReadings(key, fn) {
  if (!meterCache.has(key)) {
    if (meterCache.size > 64) meterCache.clear();
    meterCache.set(key, fn());
  }
  return meterCache.get(key);
}
function meterReadings(m) {
  const p = m.physical;
  // Every paint the view renders is measured, one beyond the envelope too (flagged by its status).
  const ward = m.renderable
    ? cachedReadings(JSON.stringify(['ward', p]), () => pg.glossmeterReadingsPhysical({ ...p }, 0, METER_TOL)) : null;
  const t = m.target;
  const target = t && t.params
    ? cachedReadings(JSON.stringify([t.def.bridge, t.params]), () => pg.glossmeterReadingsBridge(t.def.bridge, t.params, 0, METER_TOL)) : null;
  return { ward, target };
}

// Fig. 12: top row, the paint's physical ρs and α on white, grey and black; bottom row,
// the paint's c and d moved to those lightnesses by pgloss_match_gloss.
function matchPaints(m) {
  const top = [], bottom = [];
  for (const rd of MATCH_RHO_D) {
    const L = pg.lightnessFromLuminance(rd).L;
    const same = { rho_d: [rd, rd, rd], rho_s: m.physical.rho_s, alpha: m.physical.alpha };
    const sp = pg.perceptualFromPhysical(same);
    const chk = pg.checkPhysical(same);
    top.push({ ...same, label: `ρs ${fmt(same.rho_s, 4)} α ${fmt(same.alpha, 4)} → c ${fmt(sp.c, 4)}`, status: chk.status, L });
    const mt = pg.matchGloss(m.Y, m.physical.rho_s, L);
    const matched = { rho_d: [mt.rho_d_out, mt.rho_d_out, mt.rho_d_out], rho_s: mt.rho_s_out, alpha: m.physical.alpha };
    bottom.push({ ...matched, label: `c ${fmt(m.perceptual.c, 4)} d ${fmt(m.perceptual.d, 4)} → ρs ${fmt(mt.rho_s_out, 4)}`, status: mt.status, L });
  }
  return [...top, ...bottom];
}

// ---- URL hash ---------------------------------------------------------------------------
function writeHash() {
  const keys = state.mode === 'perceptual' ? PERCEPTUAL_KEYS : PHYSICAL_KEYS;
  const h = new URLSearchParams();
  h.set('mode', state.mode);
  for (const k of keys) h.set(k, exact(state[k]));
  h.set('view', state.view);
  h.set('target', state.target);
  const s = `#${h.toString()}`;
  if (location.hash !== s) history.replaceState(null, '', s);
}
function readHash() {
  const h = new URLSearchParams(location.hash.slice(1));
  if (h.get('mode') === 'physical' || h.get('mode') === 'perceptual') state.mode = h.get('mode');
  if (h.get('view') === 'match' || h.get('view') === 'single') state.view = h.get('view');
  if (targetOf(h.get('target'))) state.target = h.get('target');
  for (const k of [...PERCEPTUAL_KEYS, ...PHYSICAL_KEYS]) {
    if (h.has(k) && h.get(k).trim() !== '' && Number.isFinite(Number(h.get(k)))) state[k] = Number(h.get(k));
  }
}

// ---- controls ---------------------------------------------------------------------------
function bindControl(key) {
  const rng = $(`rng-${key}`), num = $(`num-${key}`);
  rng.addEventListener('input', () => { state[key] = Number(rng.value); update(); });
  num.addEventListener('input', () => {
    if (num.value.trim() === '' || !Number.isFinite(Number(num.value))) return;
    state[key] = Number(num.value);
    update({ keepNumber: key });
  });
}

function showControl(key, outOfModel) {
  const rng = $(`rng-${key}`), num = $(`num-${key}`);
  rng.value = state[key];  // the slider shows the nearest end; the number box the exact value
  if (document.activeElement !== num) num.value = fmt(state[key]);  // the exact value stays in state
  const lo = Number(rng.min), hi = Number(rng.max);
  const row = rng.closest('.ctl');
  row.classList.toggle('out', outOfModel || state[key] < lo || state[key] > hi);
  num.title = state[key] < lo || state[key] > hi ? `beyond the slider's range [${lo}, ${hi}]; not clamped` : '';
}

function syncFromModelForModeSwitch(newMode) {
  // Switching keeps the paint: the other description comes from the C core.
  if (!model) return;
  if (newMode === 'physical') {
    [state.rd_r, state.rd_g, state.rd_b] = model.physical.rho_d;
    state.rho_s = model.physical.rho_s;
    state.alpha = model.physical.alpha;
  } else {
    Object.assign(state, model.perceptual);
  }
  state.mode = newMode;
}

// ---- read-outs --------------------------------------------------------------------------
function setText(id, text, value) {
  const el = $(id);
  el.textContent = text;
  if (value !== undefined) el.dataset.value = JSON.stringify(value);
}

function showReadout(m) {
  const rd = m.physical.rho_d;
  setText('out-rho-d', rd.map((x) => fmt(x)).join(', '), rd);
  setText('out-rho-s', fmt(m.physical.rho_s), m.physical.rho_s);
  setText('out-alpha', fmt(m.physical.alpha), m.physical.alpha);
  const q = m.perceptual;
  setText('out-lab', [q.L, q.a, q.b].map((x) => fmt(x)).join(', '), [q.L, q.a, q.b]);
  setText('out-cd', `${fmt(q.c)}, ${fmt(q.d)}`, [q.c, q.d]);
  setText('out-envelope', Number.isFinite(m.envelope)
    ? `c ≤ ${fmt(m.envelope)}${q.c > m.envelope ? `  (c is ${fmt(q.c - m.envelope, 3)} beyond)` : ''}`
    : pg.statusName(m.envelopeStatus), m.envelope);
  const st = $('out-status');
  st.textContent = m.name;
  st.className = statusClass(m.status);
  st.dataset.value = m.status;
  $('out-reason').textContent = m.reason;  // pgloss_status_string, as the library words it
  $('out-reason').className = statusClass(m.status);

  showTarget(m);
  showMeter(m);

  // The envelope on the c slider.
  const mark = $('envelope-mark'), rng = $('rng-c');
  const lo = Number(rng.min), hi = Number(rng.max);
  const pos = Math.min(Math.max((m.envelope - lo) / (hi - lo), 0), 1);
  mark.style.left = `calc(${(pos * 100).toFixed(3)}% - 1px)`;
  mark.classList.toggle('off', !(m.envelope <= hi));
  mark.title = `envelope at L* ${fmt(q.L, 4)}: c ≤ ${fmt(m.envelope, 4)}${m.envelope > hi ? ' (beyond the slider)' : ''}`;
}

function showTarget(m) {
  const t = m.target;
  $('target-readout').hidden = !t;
  $('view-what').hidden = !t;
  $('meter-target-head').textContent = t ? t.def.label : 'target';
  if (!t) return;
  $('target-title').textContent = t.def.label;
  const rows = $('target-params');
  rows.innerHTML = '';
  const named = t.params ? namedParams(t.def, t.params) : {};
  for (const [k, v] of Object.entries(named)) {
    const tr = document.createElement('tr'), th = document.createElement('th'), td = document.createElement('td');
    th.textContent = k;
    td.textContent = Array.isArray(v) ? v.map((x) => fmt(x)).join(', ') : typeof v === 'number' ? fmt(v) : String(v);
    td.dataset.value = JSON.stringify(v);
    td.dataset.name = k;
    tr.append(th, td);
    rows.appendChild(tr);
  }
  const st = $('target-status');
  st.textContent = t.name;
  st.className = statusClass(t.status);
  st.dataset.value = t.status;
  $('target-reason').textContent = t.reason;
  $('target-reason').className = statusClass(t.status);
  // Out of reach: the parameters above are the nearest reachable paint's; never a silent clamp.
  const out = t.status < 0 && t.reached;
  $('target-reached-row').hidden = !out;
  if (out) {
    const r = t.reached;
    setText('target-reached', `L* ${fmt(r.L)}, a* ${fmt(r.a)}, b* ${fmt(r.b)}, c ${fmt(r.c)}, d ${fmt(r.d)}`, r);
  }
}

function showMeter(m) {
  const cells = [['gloss60', 'GLOSS_60'], ['haze', 'HAZE_20'], ['doi', 'DOI_30']];
  for (const [who, r] of [['ward', m.meter.ward], ['target', m.meter.target]]) {
    for (const [id, kind] of cells) {
      const el = $(`meter-${who}-${id}`);
      if (!r) { setText(`meter-${who}-${id}`, '—', null); el.title = ''; continue; }
      if (r.status < 0) { setText(`meter-${who}-${id}`, r.name, null); el.title = pg.statusString(r.status); continue; }
      setText(`meter-${who}-${id}`, fmt(r.readings[kind].value, 4), r.readings[kind].value);
      el.title = `± ${fmt(r.readings[kind].error, 2)} (quadrature)`;
    }
  }
}

// ---- paint entry by gloss units or finish ----------------------------------------------
function showEntry(r, extra = '') {
  $('entry-name').textContent = r.name;
  $('entry-name').className = statusClass(r.status);
  $('entry-name').dataset.value = r.status;
  $('entry-reason').textContent = r.status === 0 ? extra : `${pg.statusString(r.status)}${extra ? ` ${extra}` : ''}`;
}
// Sets c and d of the current colour from a result of pgloss_paint_from_gloss_units or
// pgloss_finish_paint. NO_FIT: the core wrote the nearest paint, which is set and said so.
function applyEntry(r, extra) {
  const usable = r.status >= 0 || r.name === 'PGLOSS_ERR_NO_FIT' || r.name === 'PGLOSS_ERR_ENVELOPE';
  const nearest = r.name === 'PGLOSS_ERR_NO_FIT' ? ` Set to the nearest paint: c ${fmt(r.q.c)}, d ${fmt(r.q.d)}.` : '';
  showEntry(r, `${extra}${nearest}`);
  if (!usable) return;
  if (state.mode !== 'perceptual') { syncFromModelForModeSwitch('perceptual'); applyModeUI(); }
  state.c = r.q.c;
  state.d = r.q.d;
  update({ all: true });
}
function enterGlossUnits() {
  const q = model.perceptual, second = $('gu-second').value;
  const missing = [['gu60', '60° gloss'], ...(second === 'none' ? [] : [['gu-second-value', 'second reading']])]
    .filter(([id]) => $(id).value.trim() === '' || !Number.isFinite(Number($(id).value)));
  if (missing.length) {  // an empty box is not 0 GU: nothing is set
    $('entry-name').textContent = 'no paint set';
    $('entry-name').className = 'bad';
    delete $('entry-name').dataset.value;
    $('entry-reason').textContent = `Enter a number for the ${missing.map(([, n]) => n).join(' and the ')}.`;
    return;
  }
  const x = second === 'none' ? q.d : Number($('gu-second-value').value);
  const r = pg.paintFromGlossUnits(q.L, q.a, q.b, 0, Number($('gu60').value), second, x);
  $('finish').value = '';
  $('finish-span').textContent = '';
  applyEntry(r, '');
}
function enterFinish() {
  const name = $('finish').value;
  if (!name) return;
  const q = model.perceptual;
  const r = pg.finishPaint(name, q.L, q.a, q.b, 0);
  const f = r.finish;
  const range = (lo, hi) => (Number.isFinite(lo) ? (Number.isFinite(hi) ? `${lo}–${hi}` : `≥ ${lo}`) : `≤ ${hi}`);
  $('finish-span').textContent = f ? `${f.level}: 60° ${range(f.gloss_60_min, f.gloss_60_max)} GU → c ${fmt(r.c_range[0], 3)}–${fmt(r.c_range[1], 3)}, ` +
    `d ${fmt(r.d_range[0], 3)}–${fmt(r.d_range[1], 3)}; 85° sheen ${range(f.sheen_85_min, f.sheen_85_max)} GU ${r.sheen_ok ? 'met' : 'not met (a Ward paint reads little at 85°)'}` : '';
  applyEntry(r, '');
}

// ---- the c–d plot -----------------------------------------------------------------------
const PLOT = { c0: 0, c1: 0.3, d0: 0.7, d1: 1.0, ml: 40, mr: 10, mt: 10, mb: 32 };
function plotXY(canvas, c, d) {
  const w = canvas.width - PLOT.ml - PLOT.mr, h = canvas.height - PLOT.mt - PLOT.mb;
  return [PLOT.ml + (c - PLOT.c0) / (PLOT.c1 - PLOT.c0) * w, PLOT.mt + (PLOT.d1 - d) / (PLOT.d1 - PLOT.d0) * h];
}
function plotCD(canvas, x, y) {
  const w = canvas.width - PLOT.ml - PLOT.mr, h = canvas.height - PLOT.mt - PLOT.mb;
  return [PLOT.c0 + (x - PLOT.ml) / w * (PLOT.c1 - PLOT.c0), PLOT.d1 - (y - PLOT.mt) / h * (PLOT.d1 - PLOT.d0)];
}
function drawPlot(m) {
  const cv = $('plot'), g = cv.getContext('2d');
  // c axis: wide enough to show the envelope at this L* (0.3 at least, as Figs. 9-11).
  PLOT.c1 = Number.isFinite(m.envelope) ? Math.min(1.05, Math.max(0.3, Math.ceil(m.envelope * 1.15 / 0.05) * 0.05)) : 0.3;
  g.clearRect(0, 0, cv.width, cv.height);
  const [x0, y0] = plotXY(cv, PLOT.c0, PLOT.d1), [x1, y1] = plotXY(cv, PLOT.c1, PLOT.d0);
  g.save();
  g.beginPath(); g.rect(x0, y0, x1 - x0, y1 - y0); g.clip();
  // untrusted d < 0.8 (α > 0.2)
  const [, yu] = plotXY(cv, 0, 0.8);
  g.fillStyle = 'rgba(255,200,80,0.10)'; g.fillRect(x0, yu, x1 - x0, y1 - yu);
  // beyond the envelope
  if (Number.isFinite(m.envelope)) {
    const [xe] = plotXY(cv, m.envelope, 0);
    g.fillStyle = 'rgba(220,50,50,0.18)'; g.fillRect(xe, y0, x1 - xe, y1 - y0);
    g.strokeStyle = '#e44'; g.lineWidth = 2;
    g.beginPath(); g.moveTo(xe, y0); g.lineTo(xe, y1); g.stroke();
  }
  // isogloss contours of eq. 5
  for (const [D, dash] of [[0.04, []], [0.08, [4, 3]]]) {
    const iso = pg.isoglossContour(m.perceptual.c, m.perceptual.d, D, 96);
    if (iso.status !== 0) continue;
    g.strokeStyle = '#8ab'; g.lineWidth = 1; g.setLineDash(dash);
    g.beginPath();
    iso.c.forEach((c, i) => { const [x, y] = plotXY(cv, c, iso.d[i]); if (i) g.lineTo(x, y); else g.moveTo(x, y); });
    g.closePath(); g.stroke();
  }
  g.setLineDash([]);
  const [px, py] = plotXY(cv, m.perceptual.c, m.perceptual.d);
  g.fillStyle = m.status < 0 ? '#f66' : '#fff';
  g.beginPath(); g.arc(px, py, 4, 0, 2 * Math.PI); g.fill();
  g.restore();
  // axes
  g.strokeStyle = '#666'; g.strokeRect(x0, y0, x1 - x0, y1 - y0);
  g.fillStyle = '#aaa'; g.font = '11px sans-serif'; g.textAlign = 'center';
  for (let c = 0, step = PLOT.c1 > 0.6 ? 0.2 : 0.1; c <= PLOT.c1 + 1e-9; c += step) { const [x] = plotXY(cv, c, 0); g.fillText(c.toFixed(2), x, y1 + 13); }
  g.fillText('contrast gloss c', (x0 + x1) / 2, y1 + 27);
  g.textAlign = 'right';
  for (let d = PLOT.d0; d <= PLOT.d1 + 1e-9; d += 0.05) { const [, y] = plotXY(cv, 0, d); g.fillText(d.toFixed(2), x0 - 4, y + 4); }
  g.save(); g.translate(10, (y0 + y1) / 2); g.rotate(-Math.PI / 2); g.textAlign = 'center'; g.fillText('DOI gloss d', 0, 0); g.restore();
  if (Number.isFinite(m.envelope) && m.envelope > PLOT.c1) {
    g.textAlign = 'right'; g.fillStyle = '#e88';
    g.fillText(`envelope c = ${fmt(m.envelope, 3)} →`, x1 - 4, y0 + 12);
  }
}

function pickFromPlot(ev) {
  const cv = $('plot'), r = cv.getBoundingClientRect();
  const [c, d] = plotCD(cv, (ev.clientX - r.left) * cv.width / r.width, (ev.clientY - r.top) * cv.height / r.height);
  if (state.mode === 'perceptual') {
    state.c = Number(c.toFixed(4)); state.d = Number(d.toFixed(4));
  } else {  // keep ρd; ρs and α from eqs. 7, 8 at its lightness
    const g = pg.physicalFromGloss(model.perceptual.L, Number(c.toFixed(4)), Number(d.toFixed(4)));
    if (g.status < 0) return;
    state.rho_s = g.rho_s; state.alpha = g.alpha;
  }
  update();
}

// ---- export -----------------------------------------------------------------------------
function exportText(m, kind) {
  const q = m.perceptual, p = m.physical, rd = p.rho_d;
  if (kind === 'json') {
    // Rounded as shown; `link` (the URL hash) carries the exact doubles for a bit-exact round trip.
    const perceptual = Object.fromEntries(PERCEPTUAL_KEYS.map((k) => [k, jsonNum(q[k])]));
    return JSON.stringify({ perceptual, physical: { rho_d: rd.map(jsonNum), rho_s: jsonNum(p.rho_s), alpha: jsonNum(p.alpha),
      normalization: 'ward' }, status: m.name, reason: m.status === 0 ? null : m.reason, envelope_c: jsonNum(m.envelope),
      link: location.href }, null, 2);
  }
  if (kind === 'scene') {
    return [`# examples/tracer scene line (replace the stimulus scene's \`material paint\`)`,
      state.mode === 'perceptual'
        ? `material paint perceptual L=${fmt(q.L)} a=${fmt(q.a)} b=${fmt(q.b)} c=${fmt(q.c)} d=${fmt(q.d)}`
        : `# perceptual: L=${fmt(q.L)} a=${fmt(q.a)} b=${fmt(q.b)} c=${fmt(q.c)} d=${fmt(q.d)}`,
      `${state.mode === 'perceptual' ? '# the same paint, physical: ' : ''}material paint physical rho_d=${rd.map((x) => fmt(x)).join(',')} rho_s=${fmt(p.rho_s)} alpha=${fmt(p.alpha)}`,
      m.status < 0 ? `# ${m.name}: ${m.reason} (the tracer refuses a perceptual paint outside the model)` : ''].filter(Boolean).join('\n');
  }
  if (kind === 'osl') {
    return [`// osl/pgloss_material.osl parameters (OSL shader-group syntax)`,
      `param int use_physical ${state.mode === 'physical' ? 1 : 0} ;`,
      `param float Lightness ${fmt(q.L)} ;`, `param float a_star ${fmt(q.a)} ;`, `param float b_star ${fmt(q.b)} ;`,
      `param float contrast_gloss ${fmt(q.c)} ;`, `param float distinctness_gloss ${fmt(q.d)} ;`,
      `param color rho_d ${rd.map((x) => fmt(x)).join(' ')} ;`, `param float rho_s ${fmt(p.rho_s)} ;`,
      `param float alpha ${fmt(p.alpha)} ;`].join('\n');
  }
  if (kind === 'gltf' || kind === 'materialx' || kind === 'blender' || kind === 'mitsuba') return targetExport(m, kind);
  return [`// glsl/pgloss.glsl (after #include "pgloss.glsl")`,
    `pgloss_perceptual q = pgloss_perceptual(${[q.L, q.a, q.b, q.c, q.d].map(glslFloat).join(', ')});`,
    `pgloss_physical p;`,
    `int st = pgloss_physical_from_perceptual(q, PGLOSS_NORM_WARD, p);  // libpgloss: ${m.name}`,
    `// or the physical parameters as computed by libpgloss (double):`,
    `// pgloss_physical p = pgloss_physical(vec3(${rd.map(glslFloat).join(', ')}), ${glslFloat(p.rho_s)}, ${glslFloat(p.alpha)}, ${glslFloat(p.alpha)}, PGLOSS_NORM_WARD);`,
    `pgloss_material m;`,
    `st = pgloss_material_init(m, p);`].join('\n');
}

// The exports of the bridge's targets: the chosen target where it is of the format's kind,
// else the format's default target (glTF with extensions, OpenPBR, Mitsuba GGX).
const EXPORT_TARGETS = { gltf: ['gltf', 'gltf_core'], materialx: ['openpbr', 'standard_surface'],
  blender: ['principled'], mitsuba: ['roughplastic_ggx', 'roughplastic_beckmann'] };
function targetExport(m, kind) {
  const ids = EXPORT_TARGETS[kind];
  const id = ids.includes(state.target) ? state.target : ids[0];
  const t = bridgeOf(m.perceptual, id);
  const comment = kind === 'gltf' || kind === 'blender' ? '#' : '<!--';
  if (!t.params) {
    const line = `${t.def.label}: no parameters — ${t.name}: ${t.reason}`;
    return kind === 'gltf' ? JSON.stringify({ error: { status: t.name, reason: t.reason, target: id } }, null, 2)
      : comment === '#' ? `# ${line}` : `<!-- ${line.replace(/--/g, '- -')} -->`;
  }
  if (kind === 'gltf') return gltfDocument(t.params, t);
  if (kind === 'materialx') return materialxDocument(id === 'openpbr' ? 'open_pbr_surface' : 'standard_surface', t.params, t);
  if (kind === 'blender') return blenderValues(t.params, t);
  return mitsubaBsdf(id === 'roughplastic_ggx' ? 'ggx' : 'beckmann', t.params, t);
}

// ---- render loop ------------------------------------------------------------------------
let matchInfo = [];
function updateRender(m) {
  const note = $('view-note');
  if (!tracer) return;
  const canvas = $('view');
  if (state.view === 'match') {
    matchInfo = matchPaints(m);
    // Three columns × two rows of tiles, each half the single view's size.
    canvas.width = 3 * Math.round(SIZE[0] / 2); canvas.height = 2 * Math.round(SIZE[1] / 2);
    tracer.setPaints(matchInfo.map((x) => ({ rho_d: x.rho_d, rho_s: x.rho_s, alpha: x.alpha })), 3, 2);
    const labels = $('match-labels');
    labels.hidden = false;
    labels.style.width = `${canvas.width}px`;
    labels.innerHTML = '';
    matchInfo.forEach((x, i) => {
      const div = document.createElement('div');
      const row = i < 3 ? 'same ρs, α' : 'same c, d (match)';
      div.innerHTML = `<b>${MATCH_NAMES[i % 3]}</b> L* ${fmt(x.L, 4)} · ${row}<br>${x.label}<br>`;
      const s = document.createElement('span');
      s.className = statusClass(x.status);
      s.textContent = pg.statusName(x.status);
      s.title = pg.statusString(x.status);
      div.appendChild(s);
      labels.appendChild(div);
    });
    note.hidden = true;
    $('view-what').textContent = m.target ? 'The match-gloss view renders Ward paints; the paint view shows the target beside its paint.' : '';
  } else {
    $('match-labels').hidden = true;
    // With a target: the Ward paint (left) beside the target's own BRDF (right), each at full size.
    const side = m.shading !== null;
    canvas.width = (side ? 2 : 1) * SIZE[0]; canvas.height = SIZE[1];
    if (side) {
      tracer.setTarget(m.shading);
      tracer.setPaints([m.physical, { target: true }], 2, 1);
    } else {
      tracer.setPaints([m.physical], 1, 1);
    }
    const what = $('view-what');
    what.textContent = !m.target ? '' : side
      ? `Left: the Ward paint (eq. 2). Right: ${m.target.def.label}, its own BRDF (${['GGX', 'Beckmann'][m.shading.distribution]}, ` +
        `α ${fmt(m.shading.alpha, 4)}, F0 ${fmt(m.shading.f0, 4)}) at the parameters in the table` +
        `${m.target.status < 0 ? ' — the nearest reachable paint\'s' : ''}.`
      : `The view renders the Ward paint (eq. 2) alone: ${m.target.def.label} has no parameters for this paint (${m.target.name}).`;
    note.hidden = m.status >= 0;
    note.style.maxWidth = `${Math.max(canvas.width, 240)}px`;
    // The paint's own status, as the status line shows it; the physical check's reason (a
    // negative ρd for an out-of-gamut colour) says why it cannot be rendered.
    note.textContent = m.renderable
      ? `Outside the model — ${m.name}: ${m.reason}. Rendered as computed, not clamped.`
      : `Not rendered — ${m.name}: ${m.reason}` +
        (m.physicalCheck.status !== m.status ? ` (its physical parameters: ${pg.statusString(m.physicalCheck.status)})` : '');
    // Nothing of the previous paint may stay on the canvas as if it were this one's render.
    if (!m.renderable) tracer.blank();
  }
}

// Samples per pixel per frame adapt to the frame interval (which the GPU's throughput sets):
// more while frames come faster than 20 ms, fewer above 40 ms, so a fast GPU converges in
// seconds and a slow one stays responsive.
let loopRunning = false, sppPerFrame = 1, lastFrame = 0;
function loop(now) {
  if (!tracer || !AUTORUN) return;
  if (tracer.count < MAX_SPP && (state.view === 'match' || model.renderable)) {
    if (lastFrame) {
      const dt = now - lastFrame;
      if (dt < 20 && sppPerFrame < 32) sppPerFrame++;
      else if (dt > 40 && sppPerFrame > 1) sppPerFrame--;
    }
    lastFrame = now;
    tracer.step(Math.min(sppPerFrame, MAX_SPP - tracer.count));
    $('spp').textContent = `${tracer.count} spp`;
  } else {
    lastFrame = 0;
  }
  requestAnimationFrame(loop);
}

// ---- update -----------------------------------------------------------------------------
function update(opts = {}) {
  model = convert();
  for (const k of PERCEPTUAL_KEYS) if (state.mode === 'perceptual' || opts.all) showControl(k, false);
  if (state.mode === 'physical') {
    // Mark the rows the check's reason names (pgloss_check_physical's order).
    const st = model.status, neg = (k) => state[k] < 0;
    const out = {
      rd_r: (st === -3 && neg('rd_r')) || st === -5, rd_g: (st === -3 && neg('rd_g')) || st === -5,
      rd_b: (st === -3 && neg('rd_b')) || st === -5, rho_s: (st === -3 && neg('rho_s')) || st === -5,
      alpha: st === -4 || st === 1,
    };
    for (const k of PHYSICAL_KEYS) showControl(k, out[k]);
  }
  if (state.mode === 'perceptual') $('rng-c').closest('.ctl').classList.toggle('out', model.status === -6 || model.status === -5 || state.c > Number($('rng-c').max));
  showReadout(model);
  drawPlot(model);
  writeHash();  // before the export, whose `link` is the hash just written
  $('export').value = exportText(model, state.export);
  updateRender(model);
}

function applyModeUI() {
  $('perceptual-controls').hidden = state.mode !== 'perceptual';
  $('physical-controls').hidden = state.mode !== 'physical';
  document.querySelector(`input[name=mode][value=${state.mode}]`).checked = true;
  document.querySelector(`input[name=view][value=${state.view}]`).checked = true;
  $('target').value = state.target;
}

async function fetchText(url) {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`cannot load ${url}: HTTP ${r.status}`);
  return r.text();
}

async function main() {
  pg = await loadPgloss(new URL('./pgloss.wasm', import.meta.url));
  readHash();
  for (const k of [...PERCEPTUAL_KEYS, ...PHYSICAL_KEYS]) bindControl(k);
  document.querySelectorAll('input[name=mode]').forEach((r) => r.addEventListener('change', () => {
    syncFromModelForModeSwitch(r.value); applyModeUI(); update();
  }));
  document.querySelectorAll('input[name=view]').forEach((r) => r.addEventListener('change', () => {
    state.view = r.value; update();
  }));
  document.querySelectorAll('input[name=export]').forEach((r) => r.addEventListener('change', () => {
    state.export = r.value; $('export').value = exportText(model, state.export);
  }));
  $('copy').addEventListener('click', () => navigator.clipboard?.writeText($('export').value));
  $('link').addEventListener('click', () => navigator.clipboard?.writeText(location.href));
  $('plot').addEventListener('click', pickFromPlot);
  const sel = $('target');
  for (const t of TARGETS) sel.add(new Option(t.label, t.id));
  sel.value = state.target;
  sel.addEventListener('change', () => { state.target = sel.value; update(); });
  for (const f of pg.finishes()) $('finish').add(new Option(`${f.name} (${f.level})`, f.name));
  $('finish').addEventListener('change', enterFinish);
  $('gu-set').addEventListener('click', enterGlossUnits);
  $('gu-second').addEventListener('change', () => { $('gu-second-value').hidden = $('gu-second').value === 'none'; });
  window.addEventListener('hashchange', () => { readHash(); applyModeUI(); update(); });
  applyModeUI();
  try {
    const [pglossGlsl, microfacet, trace, display, sceneText] = await Promise.all(
      ['pgloss.glsl', 'microfacet.glsl', 'trace.frag.glsl', 'display.frag.glsl', 'stimulus.scene'].map((f) => fetchText(new URL(`./${f}`, import.meta.url))));
    const scene = parseStimulusScene(sceneText);
    tracer = new Tracer($('view'), { pglossGlsl, microfacet, trace, display }, scene);
  } catch (e) {
    const err = $('error');
    err.hidden = false;
    err.textContent = `The view cannot render: ${e.message}`;
    console.error(e);
  }
  update();
  if (!loopRunning) { loopRunning = true; requestAnimationFrame(loop); }
}

// For tests and the console: the live objects.
window.picker = { state, get model() { return model; }, get tracer() { return tracer; }, get pg() { return pg; },
  update, plotXY: (c, d) => plotXY($('plot'), c, d), ready: main().then(() => true, (e) => {
    const err = $('error'); err.hidden = false; err.textContent = `The picker failed to start: ${e.message}`; throw e;
  }) };
