// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The subject's page of the local server: consent, full screen, the screen check, instructions,
// practice, trials with breaks, resume. The screens are display.js's (shared with the jsPsych
// study) and the texts texts.json's. A trial advances only once the server has committed its
// response; if the server cannot be reached the answer is kept and sent again (the server treats
// a repeat of the same answer as a no-op), so nothing is lost.
"use strict";

const $ = (id) => document.getElementById(id);
const D = window.pglossDisplay;
const RETRY_MS = 1000;
let config = null;
let run = null; // {subject, procedure, sitting, trials, practice, done:Set}
let pixels = {}; // stimulus id → ImageData at this screen's device-pixel size

function show(id) {
  for (const s of document.querySelectorAll(".screen")) s.classList.toggle("hidden", s.id !== id);
  document.body.dataset.screen = id;
}

async function api(path, body) {
  const r = await fetch(path, {
    method: body === undefined ? "GET" : "POST",
    headers: body === undefined ? {} : { "Content-Type": "application/json" },
    body: body === undefined ? undefined : JSON.stringify(body),
    cache: "no-store",
  });
  let data = null;
  try { data = await r.json(); } catch (e) { data = { error: `HTTP ${r.status}` }; }
  if (!r.ok) { const e = new Error(data.error || `HTTP ${r.status}`); e.status = r.status; throw e; }
  return data;
}

// Retries while the server is unreachable (network error or 5xx); a 4xx is final.
async function persist(path, body) {
  for (;;) {
    try {
      const data = await api(path, body);
      $("connection").classList.add("hidden");
      return data;
    } catch (e) {
      if (e.status && e.status < 500) throw e;
      $("connection").classList.remove("hidden");
      await D.wait(RETRY_MS);
    }
  }
}

// Every stimulus, decoded once; like persist(), waits out a server that is down.
async function loadImages() {
  const dpr = window.devicePixelRatio || 1;
  // The on-screen width asked for (serve --display-size, CSS pixels) on display.js's pixel grid,
  // never above the rendered size (no enlarging, so no resampling blur).
  const size = D.stimulusSize({ cssWidth: config.width, dpr, imageWidth: config.image_width, imageHeight: config.image_height });
  for (const id of config.stimuli) {
    for (;;) {
      try {
        const image = await D.decodeImage(`/stimuli/${encodeURIComponent(id)}`);
        pixels[id] = D.reduce(image, size.width, size.height, config.gamma);
        $("connection").classList.add("hidden");
        break;
      } catch (e) {
        $("connection").classList.remove("hidden");
        await D.wait(RETRY_MS);
      }
    }
  }
  return size;
}

const texts = () => config.texts;
const labels = (p) => (p === "pairs" ? [texts().pairs_low, texts().pairs_high] : [texts().magnitude_low, texts().magnitude_high]);

async function present(stimuli, label) {
  const dpr = window.devicePixelRatio || 1;
  const canvases = stimuli.map((id) => D.deviceCanvas(pixels[id], dpr, id));
  const [low, high] = labels(run.procedure);
  show("trial");
  document.body.dataset.trialLabel = label;
  document.body.dataset.stimuli = stimuli.join(",");
  return D.runTrial($("trial"), { canvases, low, high, next: texts().next, progress: label, itiMs: config.iti_ms,
                                   label: run.procedure === "pairs" ? "difference in gloss" : "glossiness" });
}

async function clicked(id) {
  await new Promise((ok) => $(id).addEventListener("click", ok, { once: true }));
}

async function practice() {
  for (let i = 0; i < run.practice.length; i++) await present(run.practice[i], `practice ${i + 1} of ${run.practice.length}`);
  show("interlude");
  await clicked("interlude-button");
}

async function main() {
  const n = run.trials.length;
  let sinceBreak = 0;
  for (let t = 0; t < n; t++) {
    if (run.done.has(t)) continue;
    if (config.break_every > 0 && sinceBreak === config.break_every) {
      $("pause-text").innerHTML = D.fill(texts().break, { done: run.done.size, total: n });
      show("pause");
      await clicked("pause-button");
      sinceBreak = 0;
    }
    const stimuli = run.trials[t];
    const answer = await present(stimuli, `${run.done.size + 1} of ${n}`);
    document.body.dataset.pending = String(t);
    await persist("/api/response", { sitting: run.sitting, subject: run.subject, procedure: run.procedure,
                                     trial: t, stimuli, rating: answer.rating, rt_ms: answer.rt_ms });
    run.done.add(t);
    sinceBreak++;
    document.body.dataset.acked = String(run.done.size);
    delete document.body.dataset.pending;
  }
  if (document.fullscreenElement) document.exitFullscreen().catch(() => {});
  show("done");
}

async function start(ev) {
  ev.preventDefault();
  const subject = $("subject").value.trim(), procedure = $("procedure").value;
  $("start-message").textContent = "";
  $("start-button").disabled = true;
  try {
    run = await persist("/api/session", { subject, procedure });
  } catch (e) {
    $("start-message").textContent = e.message;
    $("start-button").disabled = false;
    return;
  }
  run.done = new Set(run.done);
  document.body.dataset.acked = String(run.done.size);
  const resuming = run.done.size > 0;
  if (!resuming) {
    show("consent");
    const agreed = await Promise.race([clicked("consent-agree").then(() => true), clicked("consent-decline").then(() => false)]);
    if (!agreed) return show("declined");
  }
  show("fullscreen");
  await clicked("fullscreen-button");
  await document.documentElement.requestFullscreen?.().catch(() => {});
  show("check");
  const dpr = window.devicePixelRatio || 1;
  const check = await D.displayCheck($("check"), texts(), dpr);
  const size = await loadImages();
  await persist("/api/screen", { sitting: run.sitting, subject: run.subject, procedure: run.procedure, screen: {
    ...D.screenRecord(), image_device_width: size.width, image_device_height: size.height, image_size_limited: size.limited,
    display_gamma_stated: config.gamma, ...check } });
  $("instructions-pairs").classList.toggle("hidden", procedure !== "pairs");
  $("instructions-magnitude").classList.toggle("hidden", procedure !== "magnitude");
  $("instructions-practice").classList.toggle("hidden", resuming);
  $("instructions-resume").classList.toggle("hidden", !resuming);
  $("instructions-resume").innerHTML = D.fill(texts().resume, { done: run.done.size, total: run.trials.length });
  $("instructions-resume").dataset.done = String(run.done.size);
  $("instructions-button").innerHTML = resuming ? texts().continue : texts().begin;
  show("instructions");
  await clicked("instructions-button");
  try {
    if (!resuming && run.done.size < run.trials.length) await practice();
    await main();
  } catch (e) {
    show("start");
    $("start-message").textContent = `The server refused an answer: ${e.message}. Please tell the experimenter.`;
  }
}

async function init() {
  config = await persist("/api/config");
  for (const e of document.querySelectorAll("[data-text]")) {
    if (config.texts[e.dataset.text] !== undefined) e.innerHTML = config.texts[e.dataset.text];
  }
  const q = new URLSearchParams(location.search);
  if (q.get("subject")) $("subject").value = q.get("subject");
  if (config.procedures.includes(q.get("procedure"))) $("procedure").value = q.get("procedure");
  $("start-form").addEventListener("submit", start);
  show("start");
  document.body.dataset.ready = "1";
}

init();
