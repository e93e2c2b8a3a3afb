// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// What the subject sees, shared by the local server's page (experiment.js) and the jsPsych study
// (study.js): the stimuli drawn in device pixels, a trial (images, the paper's slider with its
// labels and read-out, an inter-trial interval) and the screen check (gamma, black level).
//
// Device pixels, no resampling blur. A stimulus is shown on a canvas whose backing store has
// exactly the device pixels it covers, so the browser does not rescale it. Its size and corner lie
// on the grid where whole CSS pixels are whole device pixels (pixelGrid): an edge between device
// pixels (e.g. 33 device pixels = 16.5 CSS pixels at ratio 2) is snapped by the browser one way
// or the other, and the image is then shifted or cut. When the wanted size is below the
// rendered image's, the image is reduced here by an exact box filter in linear light: each device
// pixel gets the mean luminance of the image area it covers, which is what a display with that
// pixel grid would show of the image (code values are decoded with the stated display's gamma,
// L − black ∝ V^γ, averaged and encoded again). An image is never enlarged: above its rendered
// size it is shown 1:1 and the visual angle achieved is recorded (render the stimuli larger to
// reach the stated angle).
"use strict";
(function (root) {
  const doc = root.document;

  function el(tag, attrs = {}, children = []) {
    const e = doc.createElement(tag);
    for (const [k, v] of Object.entries(attrs)) {
      if (k === "text") e.textContent = v;
      else if (k === "html") e.innerHTML = v;
      else e.setAttribute(k, v);
    }
    for (const c of children) e.append(c);
    return e;
  }

  function fill(template, values) {
    return String(template).replace(/\{(\w+)\}/g, (m, k) => (k in values ? String(values[k]) : m));
  }

  // The image's code values as stored (no colour conversion): {width, height, data: RGBA bytes}.
  async function decodeImage(url) {
    const r = await fetch(url, { cache: "force-cache" });
    if (!r.ok) throw new Error(`${url}: HTTP ${r.status}`);
    const bitmap = await createImageBitmap(await r.blob(), { colorSpaceConversion: "none", premultiplyAlpha: "none" });
    const c = el("canvas", { width: bitmap.width, height: bitmap.height });
    const g = c.getContext("2d", { willReadFrequently: true });
    g.drawImage(bitmap, 0, 0);
    const img = g.getImageData(0, 0, bitmap.width, bitmap.height);
    return { width: img.width, height: img.height, data: img.data };
  }

  // For each of n destination cells, the source cells it covers with their area fractions.
  function boxWeights(nSrc, nDst) {
    const out = [];
    for (let i = 0; i < nDst; i++) {
      const a = (i * nSrc) / nDst, b = ((i + 1) * nSrc) / nDst, list = [];
      for (let s = Math.floor(a); s < Math.min(nSrc, Math.ceil(b)); s++) {
        const w = Math.min(b, s + 1) - Math.max(a, s);
        if (w > 1e-9) list.push([s, (w * nDst) / nSrc]);
      }
      out.push(list);
    }
    return out;
  }

  // The image reduced to w × h device pixels by the box filter in linear light (gamma γ).
  function reduce(image, w, h, gamma) {
    if (w === image.width && h === image.height) return new ImageData(new Uint8ClampedArray(image.data), w, h);
    const lut = new Float64Array(256);
    for (let v = 0; v < 256; v++) lut[v] = Math.pow(v / 255, gamma);
    const wx = boxWeights(image.width, w), wy = boxWeights(image.height, h);
    const tmp = new Float64Array(image.height * w * 3);  // rows reduced horizontally
    for (let y = 0; y < image.height; y++) {
      for (let x = 0; x < w; x++) {
        let r = 0, g = 0, b = 0;
        for (const [s, f] of wx[x]) {
          const o = 4 * (y * image.width + s);
          r += f * lut[image.data[o]]; g += f * lut[image.data[o + 1]]; b += f * lut[image.data[o + 2]];
        }
        const t = 3 * (y * w + x);
        tmp[t] = r; tmp[t + 1] = g; tmp[t + 2] = b;
      }
    }
    const out = new ImageData(w, h), inv = 1 / gamma;
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < w; x++) {
        const o = 4 * (y * w + x);
        for (let c = 0; c < 3; c++) {
          let sum = 0;
          for (const [s, f] of wy[y]) sum += f * tmp[3 * (s * w + x) + c];
          out.data[o + c] = Math.round(255 * Math.pow(Math.min(1, Math.max(0, sum)), inv));
        }
        out.data[o + 3] = 255;
      }
    }
    return out;
  }

  // The device pixel ratio as p/q with the smallest q ≤ 16 (browser zoom times the system's scale:
  // 2 = 2/1, 1.25 = 5/4, 1.5 = 3/2, 1.1 = 11/10): k·q CSS pixels are exactly k·p device pixels. A
  // ratio with no such fraction gets the device-pixel grid (exact: false): sizes in device pixels
  // whose CSS lengths are fractions.
  function pixelGrid(dpr) {
    const r = dpr > 0 ? dpr : 1;
    for (let q = 1; q <= 16; q++) {
      const p = Math.round(r * q);
      if (p >= 1 && Math.abs(r * q - p) <= 1e-5 * q) return { p, q, exact: true };
    }
    return { p: 1, q: 1 / r, exact: false };
  }

  // A length in device pixels as CSS pixels, exact on the grid (no 11 / 1.1000000238 = 9.9999998).
  function cssLength(devicePx, dpr) {
    const g = pixelGrid(dpr);
    return g.exact && devicePx % g.p === 0 ? (devicePx / g.p) * g.q : devicePx / (dpr || 1);
  }

  // The device-pixel size of a stimulus, on the grid (whole multiples of p device pixels = q CSS
  // pixels), never above the rendered size: its width the grid's nearest to the stated visual
  // angle at the measured viewing distance (mm) and CSS pixels per mm, or to cssWidth; without
  // either, the largest that fits the image. The height is the grid's nearest to the image's
  // aspect (halves up; integer arithmetic). angleDeg is the visual angle shown.
  function stimulusSize({ angleDeg, distanceMm, pxPerMm, cssWidth, dpr, imageWidth, imageHeight }) {
    const dev = dpr || 1;
    let g = pixelGrid(dev);
    if (imageWidth < g.p || imageHeight < g.p) g = { p: 1, q: 1 / dev, exact: false };  // never enlarged
    const p = g.p;
    let want = null;
    if (angleDeg > 0 && distanceMm > 0 && pxPerMm > 0) want = 2 * distanceMm * Math.tan((angleDeg * Math.PI) / 360) * pxPerMm * dev;
    else if (cssWidth > 0) want = cssWidth * dev;
    const maxW = Math.floor(imageWidth / p), maxH = Math.floor(imageHeight / p);
    const units = want === null ? maxW : Math.round(want / p);
    const w = p * Math.max(1, Math.min(maxW, units));
    const h = p * Math.max(1, Math.min(maxH, Math.floor((2 * w * imageHeight + imageWidth * p) / (2 * imageWidth * p))));
    const achieved = distanceMm > 0 && pxPerMm > 0 ? (360 / Math.PI) * Math.atan(w / dev / pxPerMm / 2 / distanceMm) : null;
    return { width: w, height: h, wanted: want === null ? null : Math.round(want), limited: want !== null && units > maxW,
             angleDeg: achieved, dpr: dev, grid: `${p}/${g.exact ? g.q : "device"}` };
  }

  // A canvas showing `pixels` (ImageData) in device pixels; data-device-exact says whether the
  // browser reports exactly that many device pixels for it (devicePixelContentBoxSize).
  function deviceCanvas(pixels, dpr, stimulus) {
    const c = el("canvas", { width: pixels.width, height: pixels.height, class: "pgloss-stimulus" });
    c.style.width = `${cssLength(pixels.width, dpr)}px`;
    c.style.height = `${cssLength(pixels.height, dpr)}px`;
    if (stimulus) c.dataset.stimulus = stimulus;
    c.getContext("2d").putImageData(pixels, 0, 0);
    if (root.ResizeObserver) {
      const ro = new ResizeObserver((entries) => {
        const box = entries[0].devicePixelContentBoxSize && entries[0].devicePixelContentBoxSize[0];
        if (box) c.dataset.deviceExact = String(box.inlineSize === pixels.width && box.blockSize === pixels.height);
      });
      try { ro.observe(c, { box: "device-pixel-content-box" }); } catch (e) { /* older browsers: not recorded */ }
    }
    return c;
  }

  // Moves each canvas (by less than a grid step) so that its corner lies on the grid of the page
  // (the document; the browser scrolls by whole device pixels): layout centres it at fractions of
  // a CSS pixel (e.g. (40 − 17) / 2), which would put its edges between device pixels.
  function alignToDevicePixels(canvases, dpr) {
    const step = pixelGrid(dpr).q;
    for (const c of canvases) {
      c.style.position = "relative";
      c.style.left = c.style.top = "0px";
      const r = c.getBoundingClientRect(), x = r.left + root.scrollX, y = r.top + root.scrollY;
      c.style.left = `${Math.round(x / step) * step - x}px`;
      c.style.top = `${Math.round(y / step) * step - y}px`;
    }
  }

  const wait = (ms) => new Promise((ok) => setTimeout(ok, ms));
  const frame = () => new Promise((ok) => requestAnimationFrame(() => ok()));

  // One trial in `container`: after itiMs of black, the canvases side by side, the slider (no
  // thumb until it is first touched, so nothing anchors the answer), the read-out and Next.
  // Resolves to {rating, rt_ms, device_exact}.
  async function runTrial(container, { canvases, low, high, next, progress, itiMs = 0, label = "" }) {
    container.replaceChildren();
    delete doc.body.dataset.pglossTrial;
    if (itiMs > 0) await wait(itiMs);
    const slider = el("input", { id: "pgloss-slider", type: "range", min: "0", max: "100", step: "1", value: "50",
                                 class: "pgloss-slider pgloss-untouched", "aria-label": label });
    const readout = el("output", { id: "pgloss-readout", class: "pgloss-readout", text: "–" });
    const button = el("button", { id: "pgloss-next", class: "pgloss-next jspsych-btn", type: "button", text: next });
    button.disabled = true;
    const block = el("div", { class: "pgloss-trial" }, [
      el("div", { id: "pgloss-images", class: "pgloss-images" }, canvases),
      el("div", { class: "pgloss-response" }, [
        el("div", { class: "pgloss-scale" }, [
          el("span", { id: "pgloss-label-low", class: "pgloss-end pgloss-low", html: low }), slider,
          el("span", { id: "pgloss-label-high", class: "pgloss-end pgloss-high", html: high })]),
        readout, button, el("div", { id: "pgloss-progress", class: "pgloss-progress", text: progress || "" })]),
    ]);
    container.append(block);
    // Aligned whenever the layout changes, before it is painted (ResizeObserver): the page centres
    // the trial, so text or a window that changes size moves the canvases by fractions of a pixel.
    const align = () => alignToDevicePixels(canvases, root.devicePixelRatio || 1);
    const watch = root.ResizeObserver ? new ResizeObserver(align) : null;
    if (watch) for (const e of [block, container, doc.documentElement]) watch.observe(e);
    align();
    if (doc.fonts) await doc.fonts.ready;
    align();
    await frame();
    await frame();  // the images are on screen from the second frame on
    const t0 = performance.now();
    doc.body.dataset.pglossTrial = progress || "";  // for scripts (the tests): this trial is up
    return new Promise((resolve) => {
      const touched = () => {
        slider.classList.remove("pgloss-untouched");
        readout.textContent = slider.value;
        button.disabled = false;
      };
      slider.addEventListener("pointerdown", () => setTimeout(touched, 0));
      slider.addEventListener("input", touched);
      slider.addEventListener("keydown", () => setTimeout(touched, 0));
      button.addEventListener("click", () => {
        if (watch) watch.disconnect();
        button.disabled = true;
        slider.disabled = true;
        resolve({ rating: Number(slider.value), rt_ms: Math.round(performance.now() - t0),
                  device_exact: canvases.every((c) => c.dataset.deviceExact !== "false") });
      }, { once: true });
    });
  }

  // The screen check: (1) the subject matches a uniform grey to alternating black and white lines
  // one device pixel high, whose mean luminance is halfway between black and white; the matched
  // code value V gives the display's gamma, ln 0.5 / ln(V/255). (2) The darkest of eight squares
  // (code values 1–16 on 0) that the subject can see. Resolves to the record of both.
  const BLACK_CODES = [1, 2, 3, 4, 6, 8, 12, 16];
  async function displayCheck(container, texts, dpr) {
    const g = pixelGrid(dpr), dev = g.exact ? Math.round(160 / g.q) * g.p : Math.round(160 * dpr);
    const stripes = new ImageData(dev, dev);
    for (let y = 0; y < dev; y++) for (let x = 0; x < dev; x++) {
      const o = 4 * (y * dev + x), v = y % 2 ? 255 : 0;
      stripes.data[o] = stripes.data[o + 1] = stripes.data[o + 2] = v;
      stripes.data[o + 3] = 255;
    }
    const striped = deviceCanvas(stripes, dpr);
    striped.id = "pgloss-gamma-stripes";
    const patch = el("div", { id: "pgloss-gamma-patch", class: "pgloss-patch" });
    patch.style.width = patch.style.height = `${cssLength(dev, dpr)}px`;
    const slider = el("input", { id: "pgloss-gamma-slider", type: "range", min: "0", max: "255", step: "1", value: "128",
                                 class: "pgloss-slider" });
    const paint = () => { patch.style.background = `rgb(${slider.value},${slider.value},${slider.value})`; };
    slider.addEventListener("input", paint);
    paint();
    const button = el("button", { id: "pgloss-gamma-done", class: "jspsych-btn", type: "button", text: texts.continue });
    container.replaceChildren(el("div", { class: "pgloss-check" }, [
      el("div", { html: texts.display_check }), el("div", { class: "pgloss-pair" }, [striped, patch]), slider, button]));
    alignToDevicePixels([striped], dpr);
    const t0 = performance.now();
    await new Promise((ok) => button.addEventListener("click", ok, { once: true }));
    const v = Number(slider.value);
    const squares = BLACK_CODES.map((code) => {
      const s = el("button", { class: "pgloss-black", type: "button", "data-code": String(code), "aria-label": `square ${code}` });
      s.style.background = `rgb(${code},${code},${code})`;
      return s;
    });
    const none = el("button", { id: "pgloss-black-none", class: "jspsych-btn", type: "button", text: texts.display_check_none });
    container.replaceChildren(el("div", { class: "pgloss-check" }, [
      el("div", { html: texts.display_check_black }), el("div", { class: "pgloss-blacks" }, squares), none]));
    const black = await new Promise((ok) => {
      for (const s of squares) s.addEventListener("click", () => ok(Number(s.dataset.code)), { once: true });
      none.addEventListener("click", () => ok(0), { once: true });
    });
    return {
      gamma_code: v,
      gamma_estimate: v > 0 && v < 255 ? Math.round((Math.log(0.5) / Math.log(v / 255)) * 1000) / 1000 : null,
      black_code: black,
      check_rt_ms: Math.round(performance.now() - t0),
    };
  }

  // The subject's screen, for the record.
  function screenRecord() {
    const s = root.screen || {};
    return {
      screen_width: s.width, screen_height: s.height, window_width: root.innerWidth, window_height: root.innerHeight,
      dpr: root.devicePixelRatio || 1, user_agent: root.navigator ? root.navigator.userAgent.slice(0, 300) : "",
    };
  }

  root.pglossDisplay = { el, fill, decodeImage, boxWeights, reduce, pixelGrid, cssLength, stimulusSize, deviceCanvas, alignToDevicePixels, runTrial, displayCheck,
                         screenRecord, wait, BLACK_CODES };
})(window);
