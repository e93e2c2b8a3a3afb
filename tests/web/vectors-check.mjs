// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The WebAssembly build of libpgloss held to the shared vectors (tests/vectors/README.md):
// lightness, gloss, color, validity, perceptual_material and color_space, through the picker's own loader
// (web/picker/pgloss-wasm.js), with the C runner's double tolerances. The module has
// pointers, so the null_pointer cases run too (nothing is skipped). Then bridge.json (the gloss
// bridge's conventions, tests/test_bridge.cpp's bounds) and glossmeter.json (the virtual
// glossmeter, tests/test_glossmeter.cpp's rule: |got − value| <= got's error estimate + the
// vector's error bound + 1e-12 |value|, and the estimate itself below 1e-6 of the reading).
// vectors-check.mjs runs them on a loaded module (no imports: the browser test hands it the module
// and the files); vectors.mjs is its command line under Node:
//   node tests/web/vectors.mjs build-web/wasm/pgloss.wasm
// The files of tests/vectors/ this checks (the keys of `docs`).
export const FILES = ['lightness', 'gloss', 'color', 'validity', 'perceptual_material', 'color_space'];
export const ALL_FILES = [...FILES, 'bridge', 'glossmeter'];

// "nan", "inf", "-inf" → numbers, recursively (struct fields and arrays too).
const num = (v) => (v === 'nan' ? NaN : v === 'inf' ? Infinity : v === '-inf' ? -Infinity
  : Array.isArray(v) ? v.map(num) : v && typeof v === 'object' ? Object.fromEntries(Object.entries(v).map(([k, x]) => [k, num(x)])) : v);

function run(pg, fn, input) {
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

// pg: a Pgloss (web/picker/pgloss-wasm.js); docs: {file name: parsed JSON} for ALL_FILES;
// log: where failures are printed. Returns {total, failed, summary}.
export function checkVectors(pg, docs, log = console.log) {
  let total = 0, failed = 0, nullCases = 0, worst = { ratio: 0 };
  const perFn = {};
  for (const f of FILES) {
    const doc = docs[f];
    for (const c of doc.cases) {
      total++;
      perFn[c.function] = (perFn[c.function] ?? 0) + 1;
      if (c.input.null) nullCases++;
      const errs = [];
      let got;
      try { got = run(pg, c.function, c.input); } catch (e) { errs.push(`threw ${e.message}`); }
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
      if (errs.length) { failed++; if (failed <= 30) log(`FAIL ${c.id} ${c.function}: ${errs.join('; ')}`); }
    }
  }
  // bridge.json: pgloss_bridge_model_inputs and pgloss_bridge_params_from_model.
  let bridgeTotal = 0, bridgeWorst = 0;
  {
    const doc = docs.bridge;
    for (const c of doc.cases) {
      bridgeTotal++;
      const errs = [];
      const near = (what, got, want, tol) => {
        const e = Math.abs(got - want);
        bridgeWorst = Math.max(bridgeWorst, e / tol);
        if (!(e <= tol)) errs.push(`${what} = ${got}, want ${want} (|err| ${e.toExponential(2)} > ${tol})`);
      };
      const m = pg.bridgeModelInputs(c.target, c.params);
      if (m.name !== 'PGLOSS_OK') errs.push(`model_inputs status ${m.name}`);
      for (const k of ['beta', 'f0', 'alpha']) near(k, m[k], c[k], 1e-14);
      const back = pg.bridgeParamsFromModel(c.target, c.params.base_color, c.f0, c.alpha);
      if (back.name !== 'PGLOSS_OK') errs.push(`params_from_model status ${back.name}`);
      for (const k of ['roughness', 'ior', 'specular']) near(k, back.params[k], c.canonical[k], 1e-12);
      if (errs.length) { failed++; log(`FAIL ${c.id}: ${errs.join('; ')}`); }
    }
    total += bridgeTotal;
  }

  // glossmeter.json: Fresnel reflectance, the standard's flux and the readings.
  let meterTotal = 0, meterWorst = 0;
  {
    const doc = docs.glossmeter;
    for (const c of doc.cases) {
      meterTotal++;
      const i = num(c.input), want = c.expected.value ?? 0, errs = [];
      let got;
      const tol = 1e-9;  // the quadrature tolerance the C runner asks for
      switch (c.function) {
        case 'fresnel_dielectric': got = pg.fresnelDielectric(i.n, i.c); break;
        case 'glossmeter_standard_flux': got = pg.glossmeterStandardFlux(i.kind); break;
        case 'glossmeter_read_fresnel': got = pg.glossmeterReadFresnel(i.kind, i.n, tol); break;
        case 'glossmeter_read_lambert': got = pg.glossmeterReadLambert(i.kind, i.rho, tol); break;
        case 'glossmeter_read_physical': got = pg.glossmeterReadPhysical(i.kind, i.physical, i.azimuth_deg, tol); break;
        default: throw new Error(`no runner for ${c.function}`);
      }
      if (got.name !== c.status) errs.push(`status ${got.name}, want ${c.status}`);
      if (got.status >= 0) {
        let bound;
        if (c.function === 'fresnel_dielectric') bound = 1e-14 * Math.abs(want) + 1e-300;
        else if (c.function === 'glossmeter_standard_flux') bound = 1e-13 * want;
        else {
          bound = got.error + c.error + 1e-12 * Math.abs(want);
          if (!(got.error <= 1e-6 * Math.max(1, Math.abs(want)))) errs.push(`error estimate ${got.error} above its tolerance`);
        }
        const e = Math.abs(got.value - want);
        meterWorst = Math.max(meterWorst, e / bound);
        if (!(e <= bound)) errs.push(`${got.value}, want ${want} (|err| ${e.toExponential(2)} > ${bound.toExponential(2)})`);
      }
      if (errs.length) { failed++; log(`FAIL ${c.id} ${c.function}: ${errs.join('; ')}`); }
    }
    total += meterTotal;
  }

  const summary = `wasm vectors: ${total - failed}/${total} cases pass (${Object.keys(perFn).length} functions, ` +
    `${nullCases} null_pointer cases run, none skipped); worst error/bound ${worst.ratio.toExponential(2)}` +
    (worst.id ? ` (${worst.id} ${worst.out})` : '') +
    `; bridge.json ${bridgeTotal} cases, worst error/bound ${bridgeWorst.toExponential(2)}` +
    `; glossmeter.json ${meterTotal} cases, worst error/bound ${meterWorst.toExponential(2)}`;
  return { total, failed, summary };
}
