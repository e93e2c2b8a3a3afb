// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// render.js — the progressive WebGL2 path tracer of the view: trace.frag.glsl (with
// glsl/pgloss.glsl and microfacet.glsl inserted verbatim) adds samples into RGBA32F targets
// (ping-pong; needs EXT_color_buffer_float), display.frag.glsl tone-maps the running mean to the
// canvas. One view, or a grid of up to 6 views (the match-gloss rows of Fig. 12, or the Ward
// paint beside a bridge target's BRDF), one paint each. Every input is a uniform: a new paint
// or target never recompiles.

const VERT = `#version 300 es
void main() {  // one triangle covering the viewport
  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  gl_Position = vec4(p, 0.0, 1.0);
}`;

function compile(gl, type, src, what) {
  const sh = gl.createShader(type);
  gl.shaderSource(sh, src);
  gl.compileShader(sh);
  if (!gl.getShaderParameter(sh, gl.COMPILE_STATUS)) {
    throw new Error(`${what} does not compile:\n${gl.getShaderInfoLog(sh)}`);
  }
  return sh;
}

function program(gl, fragSrc, what) {
  const p = gl.createProgram();
  gl.attachShader(p, compile(gl, gl.VERTEX_SHADER, VERT, 'vertex shader'));
  gl.attachShader(p, compile(gl, gl.FRAGMENT_SHADER, fragSrc, what));
  gl.linkProgram(p);
  if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(`${what} does not link: ${gl.getProgramInfoLog(p)}`);
  const loc = {};
  const n = gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS);
  for (let i = 0; i < n; i++) {
    const name = gl.getActiveUniform(p, i).name.replace(/\[0\]$/, '');
    loc[name] = gl.getUniformLocation(p, name);
  }
  return { p, loc };
}

const sub = (a, b) => a.map((x, i) => x - b[i]);
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => { const l = Math.hypot(...a); return a.map((x) => x / l); };

export class Tracer {
  // sources: {pglossGlsl, microfacet, trace, display}; scene: parseStimulusScene's result.
  constructor(canvas, sources, scene) {
    const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true });
    if (!gl) throw new Error('WebGL2 is not available in this browser');
    if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('EXT_color_buffer_float is not available (float render targets)');
    this.gl = gl;
    this.canvas = canvas;
    this.scene = scene;
    const header = '#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n';
    this.trace = program(gl, `${header}${sources.pglossGlsl}\n#line 1 1\n${sources.microfacet}\n#line 1 2\n${sources.trace}`, 'trace.frag.glsl');
    this.display = program(gl, `${header}${sources.display}`, 'display.frag.glsl');
    this.vao = gl.createVertexArray();
    this.tilesX = 1; this.tilesY = 1;
    this.paints = [];
    this.count = 0;
    this.seed = 1;
    this.targets = null;
    this.shading = null;
  }

  _allocate() {
    const gl = this.gl, w = this.canvas.width, h = this.canvas.height;
    if (this.targets && this.targets.w === w && this.targets.h === h) return;
    if (this.targets) for (const t of this.targets.list) { gl.deleteTexture(t.tex); gl.deleteFramebuffer(t.fb); }
    const list = [0, 1].map(() => {
      const tex = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, tex);
      gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, w, h);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      const fb = gl.createFramebuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
      if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) throw new Error('RGBA32F render target is incomplete');
      return { tex, fb };
    });
    this.targets = { w, h, list, cur: 0 };
    this.reset();
  }

  // Restart accumulation (new paint, size or layout).
  reset() {
    const gl = this.gl;
    this.count = 0;
    if (!this.targets) return;
    for (const t of this.targets.list) {
      gl.bindFramebuffer(gl.FRAMEBUFFER, t.fb);
      gl.clearBufferfv(gl.COLOR, 0, [0, 0, 0, 0]);
    }
  }

  // An empty (black) canvas and no accumulation: for a paint that cannot be rendered.
  blank() {
    const gl = this.gl;
    this.reset();
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    gl.clearColor(0, 0, 0, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
  }

  // paints: up to 6 of {rho_d: [r,g,b], rho_s, alpha} (physical, from the C core), or
  // {target: true} for the bridge target's BRDF (setTarget), in reading order over a
  // tilesX × tilesY grid.
  setPaints(paints, tilesX = 1, tilesY = 1) {
    if (paints.length < 1 || paints.length > 6 || tilesX * tilesY !== paints.length) throw new Error('setPaints: 1..6 paints filling the grid');
    if (paints.some((p) => p.target) && !this.shading) throw new Error('setPaints: a target tile needs setTarget first');
    this.paints = paints.map((p) => (p.target ? { target: true, rho_d: [0, 0, 0], rho_s: 0, alpha: 1 }
      : { target: false, rho_d: p.rho_d.slice(), rho_s: p.rho_s, alpha: p.alpha }));
    this.tilesX = tilesX; this.tilesY = tilesY;
    this.reset();
  }

  // The bridge target's BRDF: a pgloss_bridge_shading as pgloss-wasm.js's bridgeShading reads it.
  setTarget(shading) {
    this.shading = shading ? {
      model: shading.model, diffuse_both: shading.diffuse_both, alpha: shading.alpha, eta: shading.eta,
      base_color: shading.base_color.slice(), diffuse_scale: shading.diffuse_scale,
      specular_factor: Float32Array.from(shading.specular_factor), diffuse_factor: Float32Array.from(shading.diffuse_factor),
    } : null;
    this.reset();
  }

  // One progressive pass of `spp` samples per pixel.
  step(spp = 1) {
    const gl = this.gl, sc = this.scene;
    this._allocate();
    const { list } = this.targets;
    const src = list[this.targets.cur], dst = list[1 - this.targets.cur];
    const { p, loc } = this.trace;
    gl.useProgram(p);
    gl.bindVertexArray(this.vao);
    gl.bindFramebuffer(gl.FRAMEBUFFER, dst.fb);
    gl.viewport(0, 0, this.targets.w, this.targets.h);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, src.tex);
    gl.uniform1i(loc.u_prev, 0);
    gl.uniform2f(loc.u_tile_size, this.targets.w / this.tilesX, this.targets.h / this.tilesY);
    gl.uniform1i(loc.u_tiles_x, this.tilesX);
    gl.uniform1i(loc.u_sample0, this.count);
    gl.uniform1i(loc.u_spp, spp);
    gl.uniform1i(loc.u_max_depth, sc.render.max_depth);
    gl.uniform1ui(loc.u_seed, this.seed);
    const cam = sc.camera;
    const f = norm(sub(cam.look_at, cam.position)), r = norm(cross(f, cam.up)), u = cross(r, f);
    gl.uniform3fv(loc.u_cam_pos, cam.position);
    gl.uniform3fv(loc.u_cam_f, f);
    gl.uniform3fv(loc.u_cam_r, r);
    gl.uniform3fv(loc.u_cam_u, u);
    gl.uniform1f(loc.u_cam_tan, Math.tan(0.5 * cam.fov * Math.PI / 180));
    gl.uniform3fv(loc.u_box_min, sc.box.min);
    gl.uniform3fv(loc.u_box_max, sc.box.max);
    gl.uniform3fv(loc.u_check_a, sc.checker.a);
    gl.uniform3fv(loc.u_check_b, sc.checker.b);
    gl.uniform1f(loc.u_check_size, sc.checker.size);
    gl.uniform3fv(loc.u_check_offset, sc.checker.offset);
    gl.uniform3fv(loc.u_sph_c, sc.sphere.center);
    gl.uniform1f(loc.u_sph_r, sc.sphere.radius);
    gl.uniform3fv(loc.u_light_corner, sc.light.corner);
    gl.uniform3fv(loc.u_light_e1, sc.light.edge1);
    gl.uniform3fv(loc.u_light_e2, sc.light.edge2);
    gl.uniform3fv(loc.u_light_radiance, sc.light.radiance);
    gl.uniform1f(loc.u_eps, sc.eps);
    const pad = (arr, n) => arr.concat(Array(Math.max(0, n - arr.length)).fill(arr[arr.length - 1] ?? 0));
    gl.uniform3fv(loc.u_rho_d, pad(this.paints.map((q) => q.rho_d), 6).flat());
    gl.uniform1fv(loc.u_rho_s, pad(this.paints.map((q) => q.rho_s), 6));
    gl.uniform1fv(loc.u_alpha, pad(this.paints.map((q) => q.alpha), 6));
    gl.uniform1iv(loc.u_kind, pad(this.paints.map((q) => (q.target ? 1 : 0)), 6));
    const t = this.shading;
    if (t) {
      gl.uniform1i(loc['u_target.model'], t.model);
      gl.uniform1i(loc['u_target.diffuse_both'], t.diffuse_both);
      gl.uniform1f(loc['u_target.alpha'], t.alpha);
      gl.uniform1f(loc['u_target.eta'], t.eta);
      gl.uniform3fv(loc['u_target.base_color'], t.base_color);
      gl.uniform1f(loc['u_target.diffuse_scale'], t.diffuse_scale);
      gl.uniform4fv(loc['u_target.specular_factor'], t.specular_factor);
      gl.uniform4fv(loc['u_target.diffuse_factor'], t.diffuse_factor);
    }
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    this.targets.cur = 1 - this.targets.cur;
    this.count += spp;
    this.present();
  }

  // Tone-map the running mean to the canvas.
  present() {
    const gl = this.gl, sc = this.scene;
    if (!this.targets) return;
    const { p, loc } = this.display;
    gl.useProgram(p);
    gl.bindVertexArray(this.vao);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, this.targets.w, this.targets.h);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.targets.list[this.targets.cur].tex);
    gl.uniform1i(loc.u_sum, 0);
    gl.uniform1f(loc.u_count, this.count);
    gl.uniform1f(loc.u_exposure, sc.tonemap.exposure);
    gl.uniform1f(loc.u_limit, sc.tonemap.limit);
    gl.uniform1f(loc.u_sharpness, sc.tonemap.sharpness);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  // The linear sums (RGBA32F: rgb = Σ radiance, a = Σ luminance²), rows from the top.
  readSums() {
    const gl = this.gl;
    this._allocate();
    const { w, h } = this.targets;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.targets.list[this.targets.cur].fb);
    const raw = new Float32Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.FLOAT, raw);
    const out = new Float32Array(w * h * 4);
    for (let y = 0; y < h; y++) out.set(raw.subarray((h - 1 - y) * w * 4, (h - y) * w * 4), y * w * 4);
    return { width: w, height: h, count: this.count, sums: out };
  }
}
