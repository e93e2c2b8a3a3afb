// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// scene.js — reads the tracer's stimulus scene (examples/tracer/scenes/stimulus.scene, copied
// next to the page by scripts/picker.sh) so that the page renders the very geometry, camera,
// light and tone map that pgloss-tracer renders. Only what the stimulus uses is accepted
// (the grammar is examples/tracer/src/scene.hpp's): one box with a checker of two diffuse
// materials, one sphere with the material `paint`, one area light; anything else is an error
// naming the line, never a silently different picture.

function parseLine(line, lineNo) {
  const words = line.trim().split(/\s+/);
  const kw = words.shift();
  const fields = {};
  const bare = [];
  for (const w of words) {
    const eq = w.indexOf('=');
    if (eq < 0) bare.push(w); else fields[w.slice(0, eq)] = w.slice(eq + 1);
  }
  return { kw, bare, fields, lineNo };
}

const vec = (s, what) => {
  const v = s.split(',').map(Number);
  if (v.length !== 3 || v.some((x) => !Number.isFinite(x))) throw new Error(`${what}: expected x,y,z, got '${s}'`);
  return v;
};
const numOf = (s, what) => {
  const x = Number(s);
  if (!Number.isFinite(x)) throw new Error(`${what}: expected a number, got '${s}'`);
  return x;
};

export function parseStimulusScene(text, name = 'stimulus.scene') {
  const sc = {
    image: { width: 256, height: 192 }, render: { max_depth: 8 },
    tonemap: { exposure: 1, limit: 1, sharpness: 2 }, materials: {},
  };
  text.split('\n').forEach((raw, i) => {
    const line = raw.replace(/#.*/, '').trim();
    if (!line) return;
    const { kw, bare, fields: f } = parseLine(line, i + 1);
    const at = `${name}:${i + 1}: ${kw}`;
    try {
      switch (kw) {
        case 'image': sc.image = { width: numOf(f.width, 'width'), height: numOf(f.height, 'height') }; break;
        case 'camera':
          sc.camera = { position: vec(f.position, 'position'), look_at: vec(f.look_at, 'look_at'),
            up: vec(f.up ?? '0,1,0', 'up'), fov: numOf(f.fov ?? '45', 'fov') };
          break;
        case 'render': sc.render.max_depth = numOf(f.max_depth ?? '8', 'max_depth'); break;
        case 'tonemap':
          for (const k of ['exposure', 'limit', 'sharpness']) if (f[k] !== undefined) sc.tonemap[k] = numOf(f[k], k);
          break;
        case 'material': {
          const mname = bare[0];
          if (bare[1] === 'checker') {
            sc.materials[mname] = { checker: true, a: f.a, b: f.b, size: numOf(f.size, 'size'),
              offset: f.offset ? vec(f.offset, 'offset') : [0, 0, 0] };
          } else if (f.diffuse !== undefined) {
            const v = f.diffuse.split(',').map(Number);
            sc.materials[mname] = { diffuse: v.length === 1 ? [v[0], v[0], v[0]] : v };
          } else {
            sc.materials[mname] = { other: true };  // the paint: the page sets it
          }
          break;
        }
        case 'box': sc.box = { min: vec(f.min, 'min'), max: vec(f.max, 'max'), material: f.material }; break;
        case 'sphere':
          if (sc.sphere) throw new Error('the page renders one sphere');
          sc.sphere = { center: vec(f.center, 'center'), radius: numOf(f.radius, 'radius'), material: f.material };
          break;
        case 'light':
          if (sc.light) throw new Error('the page renders one light');
          if ((f.emission ?? 'cosine') !== 'cosine') throw new Error('the page renders a cosine (Lambertian) emitter');
          sc.light = { corner: vec(f.corner, 'corner'), edge1: vec(f.edge1, 'edge1'), edge2: vec(f.edge2, 'edge2'),
            radiance: f.radiance.includes(',') ? vec(f.radiance, 'radiance') : Array(3).fill(numOf(f.radiance, 'radiance')) };
          break;
        default: throw new Error('not supported by the picker page');
      }
    } catch (e) { throw new Error(`${at}: ${e.message}`); }
  });
  for (const k of ['camera', 'box', 'sphere', 'light']) if (!sc[k]) throw new Error(`${name}: no ${k}`);
  const chk = sc.materials[sc.box.material];
  if (!chk?.checker) throw new Error(`${name}: the box's material must be a checker`);
  const a = sc.materials[chk.a], b = sc.materials[chk.b];
  if (!a?.diffuse || !b?.diffuse) throw new Error(`${name}: the checker's cells must be diffuse materials`);
  sc.checker = { a: a.diffuse, b: b.diffuse, size: chk.size, offset: chk.offset };
  if (sc.sphere.material !== 'paint') throw new Error(`${name}: the sphere's material must be called paint`);
  // render.cpp: rays are offset by 1e-4 × the scene's extent (largest |coordinate|, at least 1).
  const ext = Math.max(1, ...sc.box.min.map(Math.abs), ...sc.box.max.map(Math.abs),
    ...sc.sphere.center.map((x) => Math.abs(x) + sc.sphere.radius));
  sc.eps = 1e-4 * ext;
  return sc;
}
