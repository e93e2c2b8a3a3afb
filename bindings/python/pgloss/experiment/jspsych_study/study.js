// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The jsPsych 8 study that `python -m pgloss experiment export-jspsych` writes: one of the paper's
// procedures (pairs §3.2.3.2, magnitude §3.3.3.2) with consent, full screen, the virtual chinrest
// (card size, then blind-spot distance: Li et al. 2020), the screen check, practice, breaks and
// the data saved through JATOS (jatos.appendResultData after every trial) or, outside JATOS,
// offered as a JSON or CSV download. The configuration is window.PGLOSS_STUDY (study-config.js);
// the trial order comes from design.js, the screens from display.js (both shared with the local
// server's page); every text from the study's texts (texts.json at export).
"use strict";
(function () {
  const S = window.PGLOSS_STUDY;
  const T = S.texts;
  const D = window.pglossDisplay;
  const PT = jsPsychModule.ParameterType;
  const ids = S.stimuli.map((s) => s.id);
  const files = Object.fromEntries(S.stimuli.map((s) => [s.id, s.file]));
  const state = { pixels: {}, size: null, screen: null };

  class PglossCheckPlugin {
    // The screen: chinrest measurements, sizes, the gamma and black-level check; prepares the
    // stimuli at the subject's device-pixel size.
    static info = { name: "pgloss-screen", version: "1", parameters: {}, data: {} };
    constructor(jsPsych) { this.jsPsych = jsPsych; }
    trial(display_element) {
      (async () => {
        const chin = this.jsPsych.data.get().filter({ trial_type: "virtual-chinrest" }).last(1).values()[0] || {};
        const dpr = window.devicePixelRatio || 1;
        const size = D.stimulusSize({ angleDeg: S.visual_angle_deg, distanceMm: chin.view_dist_mm, pxPerMm: chin.px2mm,
                                      dpr, imageWidth: S.image_width, imageHeight: S.image_height });
        const check = await D.displayCheck(display_element, T, dpr);
        display_element.replaceChildren();
        const masters = await Promise.all(ids.map((id) => D.decodeImage(files[id])));
        ids.forEach((id, k) => { state.pixels[id] = D.reduce(masters[k], size.width, size.height, S.display.gamma); });
        state.size = size;
        state.screen = {
          ...D.screenRecord(), px_per_mm: chin.px2mm ?? null, view_dist_mm: chin.view_dist_mm ?? null,
          image_device_width: size.width, image_device_height: size.height, image_wanted_width: size.wanted,
          image_size_limited: size.limited, visual_angle_stated: S.visual_angle_deg, visual_angle_deg: size.angleDeg,
          display_gamma_stated: S.display.gamma, ...check,
        };
        this.jsPsych.finishTrial({ ...state.screen });
      })();
    }
  }

  class PglossTrialPlugin {
    static info = {
      name: "pgloss-trial", version: "1",
      parameters: {
        stimuli: { type: PT.STRING, array: true, default: [] },
        phase: { type: PT.STRING, default: "main" },
        index: { type: PT.INT, default: 0 },
        progress: { type: PT.STRING, default: "" },
      },
      data: {},
    };
    constructor(jsPsych) { this.jsPsych = jsPsych; }
    trial(display_element, trial) {
      (async () => {
        const dpr = state.size.dpr;
        const canvases = trial.stimuli.map((id) => D.deviceCanvas(state.pixels[id], dpr, id));
        const pairs = S.procedure === "pairs";
        const answer = await D.runTrial(display_element, {
          canvases, low: pairs ? T.pairs_low : T.magnitude_low, high: pairs ? T.pairs_high : T.magnitude_high,
          next: T.next, progress: trial.progress, itiMs: S.iti_ms, label: pairs ? "difference in gloss" : "glossiness",
        });
        display_element.replaceChildren();
        this.jsPsych.finishTrial({
          phase: trial.phase, pgloss_trial: trial.index, stimuli: trial.stimuli.join(" "), rating: answer.rating,
          rt: answer.rt_ms, device_exact: answer.device_exact, time_iso: new Date().toISOString(),
        });
      })();
    }
  }

  class PglossEndPlugin {
    // The last screen: JATOS ends the study (and redirects, e.g. to Prolific); elsewhere the data
    // are offered as JSON and CSV downloads.
    static info = { name: "pgloss-end", version: "1", parameters: {}, data: {} };
    constructor(jsPsych) { this.jsPsych = jsPsych; }
    trial(display_element) {
      const code = S.completion_code ? D.fill(T.done_code, { code: S.completion_code }) : "";
      if (window.jatos) {
        display_element.innerHTML = T.done + code + T.saving;
        pending.then(() => {
          if (S.redirect_url) jatos.endStudyAndRedirect(S.redirect_url, true, "finished");
          else jatos.endStudy(true, "finished");
        });
        return;
      }
      const data = this.jsPsych.data.get();
      const name = `pgloss-${S.procedure}-${subject}`;
      const save = (text, ext, type) => {
        const a = D.el("a", { href: URL.createObjectURL(new Blob([text], { type })), download: `${name}.${ext}` });
        document.body.append(a);
        a.click();
        a.remove();
      };
      const json = D.el("button", { id: "pgloss-download-json", class: "jspsych-btn", type: "button", text: "JSON" });
      const csv = D.el("button", { id: "pgloss-download-csv", class: "jspsych-btn", type: "button", text: "CSV" });
      json.onclick = () => save(data.json(), "json", "application/json");
      csv.onclick = () => save(data.csv(), "csv", "text/csv");
      const parts = [D.el("div", { html: T.done + code + T.download }), D.el("div", { class: "pgloss-buttons" }, [json, csv])];
      if (S.redirect_url) parts.push(D.el("p", {}, [D.el("a", { id: "pgloss-redirect", href: S.redirect_url, text: T.continue })]));
      display_element.replaceChildren(...parts);
      document.body.dataset.pglossDone = "1";
    }
  }

  // Who: ?subject=, Prolific's PROLIFIC_PID, JATOS's worker, else a random id. Seed: ?seed= (to
  // reproduce a session) or a fresh one. Both are recorded on every row.
  const query = new URLSearchParams(window.location.search);
  let subject = "", source = "", pending = Promise.resolve();
  function pickSubject() {
    const jq = window.jatos && jatos.urlQueryParameters ? jatos.urlQueryParameters : {};
    const ok = (s) => typeof s === "string" && /^[A-Za-z0-9_-]{1,32}$/.test(s);
    if (ok(query.get("subject"))) return [query.get("subject"), "url"];
    if (ok(query.get("PROLIFIC_PID"))) return [query.get("PROLIFIC_PID"), "prolific"];
    if (ok(jq.PROLIFIC_PID)) return [jq.PROLIFIC_PID, "prolific"];
    if (window.jatos && jatos.workerId != null) return [`jatos-${jatos.workerId}`, "jatos"];
    return [`anon-${window.pglossDesign.randomSeed().toString(36)}`, "random"];
  }

  function run() {
    [subject, source] = pickSubject();
    const seedParam = query.get("seed");
    const seed = seedParam !== null && /^\d{1,16}$/.test(seedParam) && Number(seedParam) < 2 ** 53
      ? Number(seedParam) : window.pglossDesign.randomSeed();
    const main = window.pglossDesign.trials(ids, S.procedure, seed, S.repeats);
    const practice = window.pglossDesign.practice(ids, S.procedure, seed, S.practice);
    const jsPsych = initJsPsych({
      // JATOS keeps every row as it comes (one JSON object a line), so a run that breaks off
      // still has its answers; a failed append is logged and the next ones still go.
      on_data_update: (row) => {
        if (!window.jatos) return;
        const line = JSON.stringify(row) + "\n";
        pending = pending.then(() => jatos.appendResultData(line)).catch((e) => console.error("append failed", e));
      },
    });
    jsPsych.data.addProperties({ pgloss_study: S.study_id, pgloss_format: S.format_version, procedure: S.procedure,
                                 subject, subject_source: source, seed });
    const button = (html, label) => ({ type: jsPsychHtmlButtonResponse, stimulus: html, choices: [label] });
    const timeline = [];
    timeline.push({
      type: jsPsychHtmlButtonResponse, stimulus: T.consent, choices: [T.consent_agree, T.consent_decline],
      on_finish: (data) => {
        if (data.response !== 0) {
          if (window.jatos) pending.then(() => jatos.endStudy(false, "consent declined"));
          jsPsych.abortExperiment(T.consent_declined);
        }
      },
    });
    timeline.push({ type: jsPsychFullscreen, fullscreen_mode: true, message: T.fullscreen, button_label: T.fullscreen_button,
                    delay_after: 300 });
    timeline.push({ type: jsPsychVirtualChinrest, blindspot_reps: S.chinrest_reps, resize_units: "none" });
    timeline.push({ type: PglossCheckPlugin });
    timeline.push(button(S.procedure === "pairs" ? T.instructions_pairs : T.instructions_magnitude, T.begin));
    if (practice.length) {
      timeline.push(button(T.practice, T.begin));
      practice.forEach((stimuli, k) => timeline.push({ type: PglossTrialPlugin, stimuli, phase: "practice", index: k,
                                                       progress: `practice ${k + 1} of ${practice.length}` }));
      timeline.push(button(T.practice_done, T.continue));
    }
    main.forEach((stimuli, t) => {
      timeline.push({ type: PglossTrialPlugin, stimuli, phase: "main", index: t, progress: `${t + 1} of ${main.length}` });
      if (S.break_every > 0 && (t + 1) % S.break_every === 0 && t + 1 < main.length) {
        timeline.push(button(D.fill(T.break, { done: t + 1, total: main.length }), T.continue));
      }
    });
    timeline.push({ type: jsPsychFullscreen, fullscreen_mode: false, delay_after: 0 });
    timeline.push({ type: PglossEndPlugin });
    document.title = T.title;
    document.body.dataset.pglossSubject = subject;
    document.body.dataset.pglossSeed = String(seed);
    jsPsych.run(timeline);
  }

  if (window.jatos) jatos.onLoad(run);
  else run();
})();
