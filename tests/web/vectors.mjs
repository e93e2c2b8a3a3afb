// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The WebAssembly build of libpgloss held to the shared vectors (tests/vectors/README.md):
// lightness, gloss, color, validity, perceptual_material and color_space, through the picker's own loader
// (web/picker/pgloss-wasm.js), with the C runner's double tolerances. The module has
// pointers, so the null_pointer cases run too (nothing is skipped).
//   node tests/web/vectors.mjs build-wasm/pgloss.wasm
import { readFileSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { resolve, dirname } from 'node:path';
import { loadPgloss } from '../../web/picker/pgloss-wasm.js';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const wasmPath = resolve(process.argv[2] ?? `${root}/build-web/wasm/pgloss.wasm`);
const pg = await loadPgloss(pathToFileURL(wasmPath));

// "nan", "inf", "-inf" → numbers, recursively (struct fields and arrays too).
const num = (v) => (v === 'nan' ? NaN : v === 'inf' ? Infinity : v === '-inf' ? -Infinity
  : Array.isArray(v) ? v.map(num) : v && typeof v === 'object' ? Object.fromEntries(Object.entries(v).map(([k, x]) => [k, num(x)])) : v);

function run(fn, input) {
  const i = num(input), nulls = input.null ?? [];
  switch (fn) {
    case 'lightness_from_luminance': return pg.lightnessFromLuminance(i.Y, nulls);
    case 'luminance_from_lightness': return pg.luminanceFromLightness(i.L, nulls);
    case 'contrast_gloss': return pg.contrastGloss(i.rho_d, i.rho_s, nulls);
    case 'specular_from_contrast': return pg.specularFromContrast(i.rho_d, i.c, nulls);
    case 'gloss_from_physical': return pg.glossFromPhysical(i.rho_d, i.rho_s, i.alpha, nulls);
    case 'physical_from_gloss': return pg.physicalFromGloss(i.L, i.c, i.d, nulls);
    case 'gloss_distance': return pg.glossDistance(i.c1, i.d1, i.c2, i.d2, nulls);
    case 'envelope_contrast': return pg.envelopeContrast(i.L, nulls);
    case 'match_gloss': return pg.matchGloss(i.rho_d, i.rho_s, i.L_target, nulls);
    case 'isogloss_contour': return pg.isoglossContour(i.c0, i.d0, i.D, i.n, nulls);
    case 'rgb_from_lab': return pg.rgbFromLab(i.lab ?? [0, 0, 0], nulls);
    case 'lab_from_rgb': return pg.labFromRgb(i.rgb ?? [0, 0, 0], nulls);
    case 'luminance': return pg.luminance(i.rgb ?? [0, 0, 0], nulls);
    case 'check_physical': return pg.checkPhysical(i.p, nulls);
    case 'check_perceptual': return pg.checkPerceptual(i.q, nulls);
    case 'physical_from_perceptual': return pg.physicalFromPerceptual(i.q, i.normalization, nulls);
    case 'perceptual_from_physical': return pg.perceptualFromPhysical(i.p, nulls);
    case 'rgb_from_lab_ex': return pg.rgbFromLabEx(i.lab ?? [0, 0, 0], i.space, nulls);
    case 'lab_from_rgb_ex': return pg.labFromRgbEx(i.rgb ?? [0, 0, 0], i.space, nulls);
    case 'luminance_ex': return pg.luminanceEx(i.rgb ?? [0, 0, 0], i.space, nulls);
    case 'check_perceptual_ex': return pg.checkPerceptualEx(i.q, i.space, nulls);
    case 'physical_from_perceptual_ex': return pg.physicalFromPerceptualEx(i.q, i.normalization, i.space, nulls);
    case 'perceptual_from_physical_ex': return pg.perceptualFromPhysicalEx(i.p, i.space, nulls);
    default: throw new Error(`no runner for ${fn}`);
  }
}

const files = ['lightness', 'gloss', 'color', 'validity', 'perceptual_material', 'color_space'];
let total = 0, failed = 0, nullCases = 0, worst = { ratio: 0 };
const perFn = {};
for (const f of files) {
  const doc = JSON.parse(readFileSync(`${root}/tests/vectors/${f}.json`, 'utf8'));
  for (const c of doc.cases) {
    total++;
    perFn[c.function] = (perFn[c.function] ?? 0) + 1;
    if (c.input.null) nullCases++;
    const errs = [];
    let got;
    try { got = run(c.function, c.input); } catch (e) { errs.push(`threw ${e.message}`); }
    if (got && got.name !== c.status) errs.push(`status ${got.name}, want ${c.status}`);
    for (const [out, want] of Object.entries(c.expected ?? {})) {
      if (!got) break;
      const tol = doc.tolerance?.[c.function]?.[out]?.double;
      const g = got[out];
      const wants = Array.isArray(want) ? want : [want];
      const gots = Array.isArray(g) ? g : [g];
      const senses = Array.isArray(c.sens?.[out]) ? c.sens[out] : wants.map(() => c.sens?.[out] ?? 0);
      if (gots.length !== wants.length) { errs.push(`${out}: ${gots.length} values, want ${wants.length}`); continue; }
      wants.forEach((w, k) => {
        const gv = gots[k];
        if (typeof gv !== 'number' || !Number.isFinite(gv)) { errs.push(`${out}[${k}] = ${gv} not finite`); return; }
        if (w === null) return;  // unspecified by the header: finiteness only
        if (!tol) { if (gv !== w) errs.push(`${out}[${k}] = ${gv}, want exactly ${w}`); return; }
        const bound = tol.abs + tol.rel * Math.abs(w) + tol.kappa_rel * (senses[k] ?? 0);
        const err = Math.abs(gv - w);
        if (err / bound > worst.ratio) worst = { ratio: err / bound, id: c.id, out, err };
        if (!(err <= bound)) errs.push(`${out}[${k}] = ${gv}, want ${w} (|err| ${err.toExponential(2)} > ${bound.toExponential(2)})`);
      });
    }
    if (errs.length) { failed++; if (failed <= 30) console.log(`FAIL ${c.id} ${c.function}: ${errs.join('; ')}`); }
  }
}
console.log(`wasm vectors: ${total - failed}/${total} cases pass (${Object.keys(perFn).length} functions, ` +
  `${nullCases} null_pointer cases run, none skipped); worst error/bound ${worst.ratio.toExponential(2)}` +
  (worst.id ? ` (${worst.id} ${worst.out})` : ''));
process.exit(failed ? 1 : 0);
