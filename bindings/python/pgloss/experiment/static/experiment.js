// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The subject's page: instructions, practice, trials, resume. A trial advances only once the
// server has committed its response; if the server cannot be reached the answer is kept and sent
// again (the server treats a repeat of the same answer as a no-op), so nothing is lost.
"use strict";

const $ = (id) => document.getElementById(id);
const LABELS = {
  pairs: ["0, small difference", "100, large difference"],
  magnitude: ["0, not glossy", "100, very glossy"],
};
const RETRY_MS = 1000;
let config = null;
let run = null; // {subject, procedure, sitting, trials, practice, done:Set}

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
      await new Promise((ok) => setTimeout(ok, RETRY_MS));
    }
  }
}

// Loads one stimulus; like persist(), waits out a server that is down instead of failing the trial.
async function loadImage(id) {
  for (;;) {
    const img = new Image(config.width, config.height);
    img.alt = "";
    img.dataset.stimulus = id;
    img.src = `/stimuli/${encodeURIComponent(id)}`;
    try {
      await img.decode();
      $("connection").classList.add("hidden");
      return img;
    } catch (e) {
      $("connection").classList.remove("hidden");
      await new Promise((ok) => setTimeout(ok, RETRY_MS));
    }
  }
}

// One trial: shows the images, waits for a slider movement and Next; resolves to {rating, rt_ms}.
async function present(stimuli, label) {
  const imgs = await Promise.all(stimuli.map(loadImage));
  const slider = $("slider"), next = $("next"), readout = $("readout");
  slider.value = "50";
  readout.textContent = "–";
  next.disabled = true;
  slider.disabled = false;
  $("progress").textContent = label;
  $("images").replaceChildren(...imgs);
  show("trial");
  document.body.dataset.trialLabel = label;
  document.body.dataset.stimuli = stimuli.join(",");
  const t0 = performance.now();
  return new Promise((resolve) => {
    slider.oninput = () => { readout.textContent = slider.value; next.disabled = false; };
    next.onclick = () => {
      next.disabled = true;
      slider.disabled = true;
      slider.oninput = next.onclick = null;
      resolve({ rating: Number(slider.value), rt_ms: Math.round(performance.now() - t0) });
    };
  });
}

async function practice() {
  for (let i = 0; i < run.practice.length; i++) await present(run.practice[i], `practice ${i + 1} of ${run.practice.length}`);
  show("interlude");
  await new Promise((ok) => { $("interlude-button").onclick = ok; });
}

async function main() {
  const n = run.trials.length;
  for (let t = 0; t < n; t++) {
    if (run.done.has(t)) continue;
    const stimuli = run.trials[t];
    const answer = await present(stimuli, `${run.done.size + 1} of ${n}`);
    document.body.dataset.pending = String(t);
    await persist("/api/response", { sitting: run.sitting, subject: run.subject, procedure: run.procedure,
                                     trial: t, stimuli, rating: answer.rating, rt_ms: answer.rt_ms });
    run.done.add(t);
    document.body.dataset.acked = String(run.done.size);
    delete document.body.dataset.pending;
  }
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
  [$("label-low").textContent, $("label-high").textContent] = LABELS[procedure];
  $("slider").setAttribute("aria-label", procedure === "pairs" ? "difference in gloss" : "glossiness");
  const resuming = run.done.size > 0;
  $("instructions-pairs").classList.toggle("hidden", procedure !== "pairs");
  $("instructions-magnitude").classList.toggle("hidden", procedure !== "magnitude");
  $("instructions-practice").classList.toggle("hidden", resuming);
  $("instructions-resume").classList.toggle("hidden", !resuming);
  $("resume-done").textContent = String(run.done.size);
  $("resume-total").textContent = String(run.trials.length);
  $("instructions-button").textContent = resuming ? "Continue" : "Begin the practice";
  show("instructions");
  await new Promise((ok) => { $("instructions-button").onclick = ok; });
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
  const q = new URLSearchParams(location.search);
  if (q.get("subject")) $("subject").value = q.get("subject");
  if (config.procedures.includes(q.get("procedure"))) $("procedure").value = q.get("procedure");
  $("start-form").addEventListener("submit", start);
  show("start");
  document.body.dataset.ready = "1";
}

init();
