// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// Each subject's trials from a recorded seed: the algorithm of pgloss/experiment/design.py (its
// docstring is the specification), in BigInt so that every 64-bit step is exact. The jsPsych
// study draws its subject's seed and order here; the import recomputes them in Python.
"use strict";
(function (root) {
  const MASK = (1n << 64n) - 1n;
  const GAMMA = 0x9e3779b97f4a7c15n;
  const PROCEDURES = ["pairs", "magnitude"];
  const SEED_LIMIT = 2 ** 53;

  // SplitMix64 (the generator of java.util.SplittableRandom): the mix of state + k·γ.
  function splitmix64(state) {
    return function next() {
      state = (state + GAMMA) & MASK;
      let z = state;
      z = ((z ^ (z >> 30n)) * 0xbf58476d1ce4e5b9n) & MASK;
      z = ((z ^ (z >> 27n)) * 0x94d049bb133111ebn) & MASK;
      return z ^ (z >> 31n);
    };
  }

  function stream(procedure, seed, practice) {
    const k = PROCEDURES.indexOf(procedure);
    if (k < 0) throw new Error(`procedure ${procedure}: want one of ${PROCEDURES}`);
    if (!Number.isSafeInteger(seed) || seed < 0 || seed >= SEED_LIMIT) throw new Error(`seed ${seed}: want 0 ≤ seed < 2^53`);
    const next = splitmix64(4n * BigInt(seed) + BigInt(k + (practice ? 2 : 0)));
    const below = (n) => {
      const N = BigInt(n), limit = (1n << 64n) - ((1n << 64n) % N);
      for (;;) {
        const z = next();
        if (z < limit) return Number(z % N);
      }
    };
    const shuffle = (a) => {
      for (let i = a.length - 1; i > 0; i--) {
        const j = below(i + 1);
        [a[i], a[j]] = [a[j], a[i]];
      }
    };
    return { next, below, shuffle };
  }

  // The main trials, in presentation order: arrays of stimulus ids, left to right.
  function trials(ids, procedure, seed, repeats = 3) {
    const rng = stream(procedure, seed, false);
    if (procedure === "pairs") {
      const pairs = [];
      for (let i = 0; i < ids.length; i++) for (let j = i + 1; j < ids.length; j++) pairs.push([ids[i], ids[j]]);
      rng.shuffle(pairs);
      return pairs.map(([a, b]) => ((rng.next() >> 63n) ? [b, a] : [a, b]));
    }
    const out = [];
    for (let r = 0; r < repeats; r++) {
      const seq = ids.slice();
      rng.shuffle(seq);
      for (const s of seq) out.push([s]);
    }
    return out;
  }

  // Practice trials (not data): random pairs or single images from the same seed.
  function practice(ids, procedure, seed, n = 3) {
    const rng = stream(procedure, seed, true);
    const k = procedure === "pairs" ? 2 : 1;
    const out = [];
    for (let p = 0; p < n; p++) {
      const pool = ids.slice();
      for (let t = 0; t < k; t++) {
        const j = t + rng.below(pool.length - t);
        [pool[t], pool[j]] = [pool[j], pool[t]];
      }
      out.push(pool.slice(0, k));
    }
    return out;
  }

  // A fresh seed from the browser's CSPRNG (53 bits).
  function randomSeed() {
    const u = new Uint32Array(2);
    (root.crypto || globalThis.crypto).getRandomValues(u);
    return (u[0] & 0x1fffff) * 2 ** 32 + u[1];
  }

  const api = { PROCEDURES, SEED_LIMIT, splitmix64, trials, practice, randomSeed };
  if (typeof module !== "undefined" && module.exports) module.exports = api;
  else root.pglossDesign = api;
})(typeof window !== "undefined" ? window : globalThis);
