# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The colour/gloss picker (web/picker) in a real browser: Debian's Chromium, headless, WebGL2 on
SwiftShader, driven by Playwright (no browser download). Run by scripts/test-web.sh, which builds
the site, the Python binding (expected values) and pgloss-tracer (reference image) first.

Environment (set by scripts/test-web.sh): PGLOSS_WEB_SITE (the built site), PGLOSS_WEB_PY (a Python
with the pgloss binding), PGLOSS_TRACER (the pgloss-tracer binary), PGLOSS_CHROMIUM.
"""
from __future__ import annotations

import json
import math
import os
import re
import subprocess
import time
from pathlib import Path
from typing import Any, Dict, List, Tuple

import numpy as np
import pytest
from playwright.sync_api import Browser, Page

ROOT = Path(__file__).resolve().parents[2]
SITE = Path(os.environ.get("PGLOSS_WEB_SITE", ROOT / "build-web/site"))
OUT = ROOT / "out/web"
SCENE = ROOT / "examples/tracer/scenes/stimulus.scene"

# Paints set through the controls (L*, a*, b*, c, d): the stimulus grey (≈ Fig. 11's reference),
# the README's dark red, a light blue, an untrusted spread (d < 0.8), one beyond the envelope
# (the envelope at L* 90 is c ≈ 0.129) and one outside the Rec. 709 gamut.
PAINTS: List[Dict[str, float]] = [
    {"L": 51.04, "a": 0.0, "b": 0.0, "c": 0.087, "d": 0.93},
    {"L": 35.0, "a": 45.0, "b": 25.0, "c": 0.06, "d": 0.95},
    {"L": 70.0, "a": -10.0, "b": -30.0, "c": 0.04, "d": 0.97},
    {"L": 60.0, "a": 0.0, "b": 0.0, "c": 0.05, "d": 0.75},
    {"L": 90.0, "a": 5.0, "b": 10.0, "c": 0.2, "d": 0.96},
    {"L": 50.0, "a": 0.0, "b": -120.0, "c": 0.05, "d": 0.95},
]


def open_page(browser: Browser, url: str, viewport: Tuple[int, int] = (1100, 820)) -> Page:
    page = browser.new_page(viewport={"width": viewport[0], "height": viewport[1]})
    errors: List[str] = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" and "favicon" not in m.text
            and "404" not in m.text else None)
    page.goto(url)
    page.evaluate("window.picker.ready")
    assert page.locator("#error").is_hidden(), page.locator("#error").inner_text()
    page.errors = errors  # type: ignore[attr-defined]
    return page


def python_expected(paints: List[Dict[str, float]]) -> List[Dict[str, Any]]:
    py = os.environ.get("PGLOSS_WEB_PY", str(ROOT / ".venv-py/bin/python"))
    if not Path(py).is_file():
        pytest.fail(f"no Python with the pgloss binding at {py} (PGLOSS_PY_SETUP_ONLY=1 bash scripts/test-python.sh)")
    r = subprocess.run([py, str(ROOT / "tests/web/expected_python.py")], input=json.dumps(paints),
                       capture_output=True, text=True, check=True, cwd="/")
    return json.loads(r.stdout)


def close(a: float, b: float) -> bool:
    """Same double up to the last bits: wasi-libc's and glibc's cbrt/pow may differ by an ulp;
    the shared vectors allow the C core 1e-12 relative."""
    return abs(a - b) <= 1e-12 * max(abs(a), abs(b)) + 1e-300


def fmt6(x: float) -> str:
    """The page's read-out format: 6 significant digits, shortest form (JS Number(x.toPrecision(6)))."""
    s = f"{float(f'{x:.6g}')!r}"
    return s[:-2] if s.endswith(".0") else s


def set_control(page: Page, key: str, value: float) -> None:
    page.fill(f"#num-{key}", repr(value))  # fires `input`, as typing does


# ---- (a) the WebAssembly core in the browser meets the shared vectors ----------------------

def test_shared_vectors_in_the_browser(browser: Browser, base_url: str) -> None:
    """Every case of tests/vectors' double-precision files, the gloss bridge's (bridge.json) and
    the glossmeter's (glossmeter.json) included, on the module the page loads, in Chromium:
    tests/web/vectors-check.mjs, the checks vectors.mjs runs under Node."""
    files = ["lightness", "gloss", "color", "validity", "perceptual_material", "color_space", "bridge",
             "glossmeter"]
    docs = {f: json.loads((ROOT / f"tests/vectors/{f}.json").read_text(encoding="utf-8")) for f in files}
    cases = sum(len(d["cases"]) for d in docs.values())
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    res = page.evaluate("""async ([src, docs]) => {
        const url = URL.createObjectURL(new Blob([src], { type: 'text/javascript' }));
        const { ALL_FILES, checkVectors } = await import(url);
        const { loadPgloss } = await import(new URL('pgloss-wasm.js', location.href).href);
        const pg = await loadPgloss(new URL('pgloss.wasm', location.href));
        const log = [];
        const r = checkVectors(pg, docs, (line) => log.push(line));
        return { ...r, files: ALL_FILES, log };
    }""", [(ROOT / "tests/web/vectors-check.mjs").read_text(encoding="utf-8"), docs])
    print(f"\n  chromium: {res['summary']}")
    assert sorted(res["files"]) == sorted(files)
    assert res["total"] == cases and res["failed"] == 0, res["log"][:20]


# ---- (b) the displayed numbers are the binding's ------------------------------------------

def test_readout_equals_python_binding(browser: Browser, base_url: str) -> None:
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    want = python_expected(PAINTS)
    seen_status = set()
    for paint, exp in zip(PAINTS, want):
        for k in ("L", "a", "b", "c", "d"):
            set_control(page, k, paint[k])
        rd = json.loads(page.get_attribute("#out-rho-d", "data-value") or "null")
        rs = json.loads(page.get_attribute("#out-rho-s", "data-value") or "null")
        al = json.loads(page.get_attribute("#out-alpha", "data-value") or "null")
        status = page.inner_text("#out-status")
        reason = page.inner_text("#out-reason")
        label = f"paint {paint}"
        assert status == exp["status"], label
        assert reason == exp["reason"], label
        assert all(close(g, w) for g, w in zip(rd, exp["rho_d"])), (label, rd, exp["rho_d"])
        assert close(rs, exp["rho_s"]) and close(al, exp["alpha"]), (label, rs, al, exp)
        # what a person reads: the same numbers at 6 digits
        assert page.inner_text("#out-rho-d") == ", ".join(fmt6(x) for x in exp["rho_d"]), label
        assert page.inner_text("#out-rho-s") == fmt6(exp["rho_s"]), label
        assert page.inner_text("#out-alpha") == fmt6(exp["alpha"]), label
        seen_status.add(status)
        # Out-of-model values are shown as such: the c row is marked, the view says why.
        if exp["status"] == "PGLOSS_ERR_ENVELOPE":
            assert page.locator(".ctl[data-key=c].out").count() == 1, label
            assert page.locator("#view-note").is_visible()
            assert "PGLOSS_ERR_ENVELOPE" in page.inner_text("#view-note")
            assert page.input_value("#num-c") == "0.2"  # not clamped to the envelope
        # Fig. 12 match: the paints the match view renders are pgloss_match_gloss's.
        page.check("input[name=view][value=match]")
        paints = page.evaluate("window.picker.tracer.paints")
        for i, m in enumerate(exp["match"]):
            got = paints[3 + i]
            assert close(got["rho_d"][0], m["rho_d"]) and close(got["rho_s"], m["rho_s"]), (label, i, got, m)
            assert page.locator("#match-labels div").nth(3 + i).locator("span").inner_text() == m["status"]
        page.check("input[name=view][value=single]")
    assert {"PGLOSS_OK", "PGLOSS_WARN_ALPHA_UNTRUSTED", "PGLOSS_ERR_ENVELOPE", "PGLOSS_ERR_GAMUT"} <= seen_status
    assert not page.errors, page.errors  # type: ignore[attr-defined]
    print(f"\n(b) {len(PAINTS)} paints: ρd, ρs, α, status and reason equal the Python binding "
          f"(statuses {sorted(seen_status)})")


TARGET_IDS = ["openpbr", "standard_surface", "gltf", "gltf_core", "principled", "roughplastic_ggx",
              "roughplastic_beckmann"]
READ_TARGET = """() => {
    const v = (id) => { const d = document.getElementById(id).dataset.value; return d === undefined ? null : JSON.parse(d); };
    const meter = (who) => Object.fromEntries([['GLOSS_60', 'gloss60'], ['HAZE_20', 'haze'], ['DOI_30', 'doi']]
        .map(([k, id]) => [k, v(`meter-${who}-${id}`)]));
    return {
        hidden: document.getElementById('target-readout').hidden,
        status: document.getElementById('target-status').textContent,
        reason: document.getElementById('target-reason').textContent,
        named: Object.fromEntries([...document.querySelectorAll('#target-params td')]
            .map((td) => [td.dataset.name, JSON.parse(td.dataset.value)])),
        reachedShown: !document.getElementById('target-reached-row').hidden,
        reached: v('target-reached'),
        ward: meter('ward'), target: meter('target'),
    };
}"""


def _same(got: Any, want: Any) -> bool:
    if isinstance(want, list):
        return isinstance(got, list) and len(got) == len(want) and all(_same(g, w) for g, w in zip(got, want))
    if isinstance(want, (bool, str)) or want is None:
        return got == want
    return isinstance(got, (int, float)) and close(float(got), float(want))


def _meter_close(got: Dict[str, Any], want: Dict[str, Dict[str, float]]) -> bool:
    """The same quadrature at the same tolerance: equal within the two error estimates (wasi-libc's
    and glibc's libm may differ in the last bits, which can move a panel's order)."""
    return all(got[k] is not None and abs(got[k] - w["value"]) <= 2 * w["error"] + 1e-9 * abs(w["value"])
               for k, w in want.items())


def test_targets_read_out_the_binding(browser: Browser, base_url: str) -> None:
    """For each paint and each gloss-bridge target: the target's parameters under its own names,
    the bridge's status and reason, the nearest reachable paint when out of reach (never a silent
    clamp), and the glossmeter's 60° gloss, haze and DOI of the Ward paint and of the target's
    material, all equal to the Python binding's (the native C core)."""
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    want = python_expected(PAINTS)
    seen: set = set()
    worst = {"params": 0.0, "readings": 0.0}
    for paint, exp in zip(PAINTS, want):
        for k in ("L", "a", "b", "c", "d"):
            set_control(page, k, paint[k])
        page.select_option("#target", "ward")
        got = page.evaluate(READ_TARGET)
        assert got["hidden"]
        if exp["readings"] is None:
            assert all(v is None for v in got["ward"].values()), (paint, got["ward"])
        else:
            assert _meter_close(got["ward"], exp["readings"]), (paint, got["ward"], exp["readings"])
        for t in TARGET_IDS:
            page.select_option("#target", t)
            got = page.evaluate(READ_TARGET)
            e = exp["targets"][t]
            label = (paint, t)
            seen.add(e["status"])
            assert not got["hidden"] and got["status"] == e["status"] and got["reason"] == e["reason"], (label, got, e)
            if e["named"] is None:
                assert got["named"] == {} and not got["reachedShown"], label
                assert all(v is None for v in got["target"].values()), label
                continue
            assert got["named"].keys() == e["named"].keys(), (label, got["named"], e["named"])
            assert all(_same(got["named"][k], w) for k, w in e["named"].items()), (label, got["named"], e["named"])
            for k, w in e["named"].items():
                for g, x in zip(np.ravel(got["named"][k]), np.ravel(w)):
                    if isinstance(x, (int, float)) and not isinstance(x, bool) and x != 0:
                        worst["params"] = max(worst["params"], abs(float(g) - float(x)) / abs(float(x)))
            out_of_reach = e["status"].startswith("PGLOSS_ERR_BRIDGE_")
            assert got["reachedShown"] == out_of_reach, label
            if out_of_reach:
                assert all(abs(g - w) <= 1e-9 * max(1.0, abs(w)) for g, w in
                           zip([got["reached"][k] for k in ("L", "a", "b", "c", "d")], e["reached"])), (label, got, e)
            assert _meter_close(got["target"], e["readings"]), (label, got["target"], e["readings"])
            for k, w in e["readings"].items():
                worst["readings"] = max(worst["readings"], abs(got["target"][k] - w["value"]) / max(abs(w["value"]), 1e-30))
            assert "target=" + t in page.evaluate("location.href")
    print(f"\n  targets: WebAssembly vs the native core, worst relative difference: parameters "
          f"{worst['params']:.1e}, glossmeter readings {worst['readings']:.1e}")
    # The paints reach every kind of answer: reachable, out of reach, outside the model.
    assert "PGLOSS_OK" in seen and "PGLOSS_ERR_BRIDGE_SPECULAR" in seen and "PGLOSS_ERR_ENVELOPE" in seen, seen


def test_paint_from_gloss_units_and_finish(browser: Browser, base_url: str) -> None:
    """A 60° gloss in GU (with d as set) and a named finish set c and d as the binding's
    from_gloss_units and finish do; a reading no paint gives (NO_FIT: 0 GU, below the diffuse's
    own reading) sets the nearest paint and says so; one beyond the envelope sets the paint with
    its status (ENVELOPE), as the sliders would."""
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    colour = {"L": 35.0, "a": 45.0, "b": 25.0, "d": 0.95}
    for k, v in colour.items():
        set_control(page, k, v)
    spec = {"gloss_units": [[35.0, 45.0, 25.0, 12.0, 0.95], [35.0, 45.0, 25.0, 0.0, 0.95],
                            [35.0, 45.0, 25.0, 400.0, 0.95]],
            "finishes": [["satin", 35.0, 45.0, 25.0], ["semi-gloss", 35.0, 45.0, 25.0]]}
    py = os.environ.get("PGLOSS_WEB_PY", str(ROOT / ".venv-py/bin/python"))
    want = json.loads(subprocess.run([py, str(ROOT / "tests/web/expected_python.py")], input=json.dumps(spec),
                                     capture_output=True, text=True, check=True, cwd="/").stdout)
    state = lambda: page.evaluate("({...window.picker.state})")  # noqa: E731
    before = state()
    page.fill("#gu60", "")  # an empty box is not 0 GU: the paint stays, the page says why
    page.click("#gu-set")
    assert state() == before and "Enter a number" in page.inner_text("#entry-reason")
    for (_, _, _, g60, d), w in zip(spec["gloss_units"], want["gloss_units"]):
        set_control(page, "d", d)
        page.fill("#gu60", repr(g60))
        page.click("#gu-set")
        st = state()
        assert page.inner_text("#entry-name") == w["status"], (g60, w)
        assert close(st["c"], w["c"]) and close(st["d"], w["d"]), (g60, st, w)
        if w["status"] == "PGLOSS_ERR_NO_FIT":
            assert "nearest paint" in page.inner_text("#entry-reason")
    assert [w["status"] for w in want["gloss_units"]] == ["PGLOSS_OK", "PGLOSS_ERR_NO_FIT", "PGLOSS_ERR_ENVELOPE"]
    for (name, *_), w in zip(spec["finishes"], want["finishes"]):
        page.select_option("#finish", name)
        st = state()
        assert close(st["c"], w["c"]) and close(st["d"], w["d"]), (name, st, w)
        assert page.inner_text("#entry-name") == w["status"]
        assert ("not met" in page.inner_text("#finish-span")) == (not w["sheen_ok"])


THREE = ROOT / "tests/web/node_modules/three"  # npm ci --prefix tests/web (scripts/test-web.sh)
EXPORT_PY = os.environ.get("PGLOSS_WEB_EXPORT_PY", str(ROOT / ".venv-bridge/bin/python"))
EXPORTS = [("gltf", "gltf"), ("gltf", "gltf_core"), ("materialx", "openpbr"), ("materialx", "standard_surface"),
           ("blender", "principled"), ("mitsuba", "roughplastic_ggx"), ("mitsuba", "roughplastic_beckmann")]


def _rel(a: float, b: float, r: float) -> bool:
    return abs(a - b) <= r * max(abs(a), abs(b), 1e-30)


def _three_page(browser: Browser, base_url: str) -> Page:
    """A page with an import map to three.js (the npm package, served by a route: no CDN)."""
    if not (THREE / "examples/jsm/loaders/GLTFLoader.js").is_file():
        pytest.fail(f"no three.js at {THREE} (npm ci --prefix tests/web; scripts/test-web.sh does)")
    page = browser.new_page()
    html = ('<!DOCTYPE html><script type="importmap">{"imports": {"three": "/__three/build/three.module.js", '
            '"three/addons/": "/__three/examples/jsm/"}}</script><p>three</p>')

    def serve(route: Any) -> None:
        rel = route.request.url.split("/__three/", 1)[1].split("?")[0]
        if rel == "index.html":
            route.fulfill(body=html, content_type="text/html")
            return
        f = (THREE / rel).resolve()
        if THREE.resolve() not in f.parents or not f.is_file():
            route.fulfill(status=404, body="")
            return
        route.fulfill(body=f.read_bytes(), content_type="text/javascript")

    page.route(f"{base_url}/__three/**", serve)
    page.goto(f"{base_url}/__three/index.html")
    return page


def test_target_exports_load_in_their_own_libraries(browser: Browser, base_url: str) -> None:
    """Each bridge target's export, for a reachable paint and one out of glTF core's reach: the
    glTF material loads in three.js's GLTFLoader (MeshPhysicalMaterial with the extensions' ior
    and specularIntensity where present), the MaterialX document passes MaterialX's own
    validation against the open_pbr_surface / standard_surface nodedefs, the Mitsuba <bsdf> loads
    with mitsuba.load_string, and the Blender lines set the Principled inputs; every value each
    library reads back is the binding's parameter to the export's 9 digits (MaterialX and Mitsuba
    hold float32)."""
    paints = [PAINTS[0], PAINTS[1]]
    want = python_expected(paints)
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    texts: List[Tuple[int, str, str, str]] = []
    for i, paint in enumerate(paints):
        for k in ("L", "a", "b", "c", "d"):
            set_control(page, k, paint[k])
        for kind, target in EXPORTS:
            page.select_option("#target", target)
            page.check(f"input[name=export][value={kind}]")
            texts.append((i, kind, target, page.input_value("#export")))
    statuses = {want[i]["targets"][t]["status"] for i, _, t, _ in texts}
    assert "PGLOSS_OK" in statuses and "PGLOSS_ERR_BRIDGE_SPECULAR" in statuses, statuses
    for i, kind, target, text in texts:  # the status and reason travel with every export
        e = want[i]["targets"][target]
        assert e["status"] in text and (e["status"] == "PGLOSS_OK" or e["reason"] in text), (kind, target, text)

    # glTF → three.js GLTFLoader
    gltf = [(i, t, json.loads(x)) for i, k, t, x in texts if k == "gltf"]
    three = _three_page(browser, base_url)
    got = three.evaluate("""async (docs) => {
        const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
        const out = [];
        for (const d of docs) {
            const gltf = await new GLTFLoader().parseAsync(JSON.stringify(d), '');
            const m = await gltf.parser.getDependency('material', 0);
            out.push({ type: m.type, color: m.color.toArray(), roughness: m.roughness, metalness: m.metalness,
                       ior: m.ior ?? null, specularIntensity: m.specularIntensity ?? null });
        }
        return out;
    }""", [d for _, _, d in gltf])
    for (i, t, doc), m in zip(gltf, got):
        n = want[i]["targets"][t]["named"]
        ext = doc["materials"][0].get("extensions", {})
        label = (i, t, m)
        assert m["metalness"] == 0 and _rel(m["roughness"], n["roughnessFactor"], 1e-8), label
        assert all(_rel(g, w, 1e-8) for g, w in zip(m["color"], n["baseColorFactor"][:3])), label
        assert set(ext) == ({"KHR_materials_ior"} if n["ior"] != 1.5 else set()) | \
            ({"KHR_materials_specular"} if n["specularFactor"] != 1 else set()), label
        if ext:
            assert m["type"] == "MeshPhysicalMaterial" and _rel(m["ior"], n["ior"], 1e-8), label
            assert _rel(m["specularIntensity"], n["specularFactor"], 1e-8), label
        else:
            assert m["type"] == "MeshStandardMaterial" and t == "gltf_core", label
    three.close()

    # MaterialX and Mitsuba 3 → their Python packages; one deliberately broken document first,
    # so that a validator that accepts anything fails this test.
    mtlx = next(x for _, k, _, x in texts if k == "materialx")
    broken = mtlx.replace('name="base_color" type="color3"', 'name="base_color" type="float"', 1)
    assert broken != mtlx
    items = [{"kind": k, "text": x} for _, k, _, x in texts if k in ("materialx", "mitsuba")]
    if not Path(EXPORT_PY).is_file():
        pytest.fail(f"no Python with MaterialX and mitsuba at {EXPORT_PY} (scripts/test-web.sh makes .venv-bridge)")
    r = subprocess.run([EXPORT_PY, str(ROOT / "tests/web/validate_exports.py")],
                       input=json.dumps([{"kind": "materialx", "text": broken}] + items),
                       capture_output=True, text=True, cwd="/", timeout=300)
    assert r.returncode == 0, r.stderr[-3000:]
    results = json.loads(r.stdout)
    assert not results[0]["ok"], "MaterialX accepted base_color typed float"
    checked = [(i, k, t) for i, k, t, _ in texts if k in ("materialx", "mitsuba")]
    for (i, kind, target), res in zip(checked, results[1:]):
        n, v = want[i]["targets"][target]["named"], res["values"]
        label = (i, target, res)
        assert res["ok"], label
        if kind == "materialx":
            assert v["node"] == ("open_pbr_surface" if target == "openpbr" else "standard_surface"), label
            for key, w in n.items():
                if isinstance(w, list):
                    assert all(_rel(g, x, 1e-6) for g, x in zip(v[key], w)), (key, label)
                else:
                    assert _rel(float(v[key]), float(w), 1e-6), (key, label)
        else:
            assert _rel(v["alpha"], n["alpha"], 1e-6) and _rel(v["eta"], n["int_ior"] / n["ext_ior"], 1e-6), label
            assert all(_rel(g, x, 1e-6) for g, x in zip(v["diffuse_reflectance.value"], n["diffuse_reflectance"])), label

    # Blender: the lines that set the Principled BSDF's inputs
    for i, kind, target, text in texts:
        if kind != "blender":
            continue
        n = want[i]["targets"][target]["named"]
        sets = dict(re.findall(r'^bsdf\.inputs\["([^"]+)"\]\.default_value = (.+)$', text, re.M))
        assert set(sets) == {"Base Color", "Metallic", "Roughness", "IOR", "Specular IOR Level"}, text
        colour = [float(x) for x in sets["Base Color"].strip("()").split(",")]
        assert colour[3] == 1 and all(_rel(g, w, 1e-8) for g, w in zip(colour, n["Base Color"])), text
        for key in ("Metallic", "Roughness", "IOR", "Specular IOR Level"):
            assert _rel(float(sets[key]), float(n[key]), 1e-8), (key, text)


# A fragment shader over web/picker/microfacet.glsl in the page's WebGL2 (float32): `body` sets
# `o` at pixel `px` (ivec2) from the input rows (texelFetch(u_in, ivec2(i, row), 0)); each job
# draws width n × `height` pixels with its own inputs and, where given, the uniform u_target from
# a pgloss_bridge_shading (pgloss-wasm.js's bridgeShading). Returns each job's RGBA floats, rows
# from the bottom.
GLSL_RUN = """async ({ body, jobs }) => {
    const src = await (await fetch('microfacet.glsl')).text();
    const gl = document.createElement('canvas').getContext('webgl2');
    if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('no EXT_color_buffer_float');
    const sh = (type, text) => { const s = gl.createShader(type); gl.shaderSource(s, text); gl.compileShader(s);
        if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s)); return s; };
    const prog = gl.createProgram();
    gl.attachShader(prog, sh(gl.VERTEX_SHADER, '#version 300 es\\nvoid main() { vec2 p = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 4.0 - 1.0; gl_Position = vec4(p, 0, 1); }'));
    gl.attachShader(prog, sh(gl.FRAGMENT_SHADER, '#version 300 es\\nprecision highp float;\\nprecision highp int;\\n' + src +
        '\\nuniform highp sampler2D u_in;\\nuniform pgloss_bridge_shading u_target;\\nout vec4 o;\\n' +
        'void main() { ivec2 px = ivec2(gl_FragCoord.xy); o = vec4(0.0);\\n' + body + '\\n}'));
    gl.linkProgram(prog);
    if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(prog));
    gl.useProgram(prog);
    const U = (name) => gl.getUniformLocation(prog, name);
    const results = [];
    for (const { inputs, n, height, shading: t } of jobs) {
        const data = new Float32Array(n * inputs.length * 4);
        inputs.forEach((row, r) => data.set(row, 4 * n * r));
        const tex = gl.createTexture();
        gl.activeTexture(gl.TEXTURE0);
        gl.bindTexture(gl.TEXTURE_2D, tex);
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, n, inputs.length, 0, gl.RGBA, gl.FLOAT, data);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
        const out = gl.createTexture();
        gl.bindTexture(gl.TEXTURE_2D, out);
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, n, height, 0, gl.RGBA, gl.FLOAT, null);
        const fb = gl.createFramebuffer();
        gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
        gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, out, 0);
        gl.viewport(0, 0, n, height);
        gl.bindTexture(gl.TEXTURE_2D, tex);
        gl.uniform1i(U('u_in'), 0);
        if (t) {
            gl.uniform1i(U('u_target.model'), t.model);
            gl.uniform1i(U('u_target.diffuse_both'), t.diffuse_both);
            gl.uniform1f(U('u_target.alpha'), t.alpha);
            gl.uniform1f(U('u_target.eta'), t.eta);
            gl.uniform3fv(U('u_target.base_color'), t.base_color);
            gl.uniform1f(U('u_target.diffuse_scale'), t.diffuse_scale);
            gl.uniform4fv(U('u_target.specular_factor'), Float32Array.from(t.specular_factor));
            gl.uniform4fv(U('u_target.diffuse_factor'), Float32Array.from(t.diffuse_factor));
        }
        gl.drawArrays(gl.TRIANGLES, 0, 3);
        const px = new Float32Array(4 * n * height);
        gl.readPixels(0, 0, n, height, gl.RGBA, gl.FLOAT, px);
        results.push(Array.from(px));
        gl.deleteTexture(tex); gl.deleteTexture(out); gl.deleteFramebuffer(fb);
    }
    return results;
}"""


# ---- the bridge targets' specular lobe in GLSL (web/picker/microfacet.glsl) ---------------

def _mf_reference(model: int, eta: float, a: float, wo: np.ndarray, wi: np.ndarray) -> np.ndarray:
    """D G F / (4 μi μo) in double from the published forms, written here in angles (not the
    shader's component form): GGX D and G1 (Walter et al. 2007, eqs. 33, 34), height-correlated
    Smith G2 = 1/(1 + Λ(i) + Λ(o)) (Heitz 2014, eq. 99), Beckmann D and the rational G1 (Walter
    eqs. 25, 27), the exact unpolarised dielectric Fresnel term (Walter eq. 22)."""
    wo = wo / np.linalg.norm(wo, axis=1)[:, None]
    wi = wi / np.linalg.norm(wi, axis=1)[:, None]
    h = wo + wi
    h /= np.linalg.norm(h, axis=1)[:, None]
    ch, co, ci = h[:, 2], wo[:, 2], wi[:, 2]
    tan2 = lambda c: np.sin(np.arccos(np.clip(c, -1, 1))) ** 2 / c ** 2  # noqa: E731
    if model == 3:
        D = np.exp(-tan2(ch) / a ** 2) / (np.pi * a ** 2 * ch ** 4)

        def g1(c: np.ndarray) -> np.ndarray:
            t = np.sqrt(tan2(c))
            x = np.divide(1.0, a * t, out=np.full_like(t, np.inf), where=t > 0)
            return np.where(x >= 1.6, 1.0, (3.535 * x + 2.181 * x ** 2) / (1 + 2.276 * x + 2.577 * x ** 2))

        G = g1(ci) * g1(co)
    else:
        D = a ** 2 / (np.pi * ch ** 4 * (a ** 2 + tan2(ch)) ** 2)
        lam = lambda c: (-1 + np.sqrt(1 + a ** 2 * tan2(c))) / 2  # noqa: E731
        G = 1 / ((1 + lam(ci)) * (1 + lam(co))) if model == 2 else 1 / (1 + lam(ci) + lam(co))
    c = np.sum(wo * h, axis=1)
    g = np.sqrt(eta ** 2 - 1 + c ** 2)
    F = 0.5 * (g - c) ** 2 / (g + c) ** 2 * (1 + ((c * (g + c) - 1) / (c * (g - c) + 1)) ** 2)
    return D * G * F / (4 * ci * co)


def test_microfacet_glsl_matches_the_reference(browser: Browser, base_url: str) -> None:
    """web/picker/microfacet.glsl in WebGL2 (Chromium, SwiftShader; float32) against the double
    reference above: 4 models × 4 roughnesses × 3 F0, random directions and directions near the
    mirror, on float32 inputs. Measured worst relative error is printed; the bound 2e-4 is float32's
    rounding through D's (a² + tan²)² and the Fresnel term, with margin."""
    rng = np.random.default_rng(7)
    rows = []
    for model in range(4):
        for a in (0.01, 0.05, 0.2, 0.6):
            for f0 in (0.02, 0.04, 0.1):
                eta = (1 + np.sqrt(f0)) / (1 - np.sqrt(f0))
                n = 24
                wo = rng.normal(size=(n, 3))
                wo[:, 2] = np.abs(wo[:, 2]) + 0.1
                wi = rng.normal(size=(n, 3))
                wi[:, 2] = np.abs(wi[:, 2]) + 0.1
                # near the mirror: wi = reflect(wo) tilted by about α
                m = n // 2
                wi[:m] = np.c_[-wo[:m, 0], -wo[:m, 1], wo[:m, 2]] + a * rng.normal(size=(m, 3)) * np.linalg.norm(wo[:m], axis=1)[:, None]
                wi[:m, 2] = np.abs(wi[:m, 2]) + 0.05
                wo = (wo / np.linalg.norm(wo, axis=1)[:, None]).astype(np.float32)
                wi = (wi / np.linalg.norm(wi, axis=1)[:, None]).astype(np.float32)
                for k in range(n):
                    rows.append((model, np.float32(eta), np.float32(a), wo[k], wi[k]))
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    n = len(rows)
    inputs = [[v for r in rows for v in (*map(float, r[3]), 0.0)], [v for r in rows for v in (*map(float, r[4]), 0.0)],
              [v for r in rows for v in (float(r[0]), float(r[1]), float(r[2]), 0.0)]]
    body = """vec4 a = texelFetch(u_in, ivec2(px.x, 0), 0), b = texelFetch(u_in, ivec2(px.x, 1), 0),
              c = texelFetch(u_in, ivec2(px.x, 2), 0);
              o = vec4(pgloss_mf_specular(int(c.x), c.y, c.z, a.xyz, b.xyz), 0, 0, 1);"""
    got = page.evaluate(GLSL_RUN, {"body": body, "jobs": [{"inputs": inputs, "n": n, "height": 1}]})[0][0::4]
    got = np.asarray(got)
    worst = {}
    for model in range(4):
        idx = [i for i, r in enumerate(rows) if r[0] == model]
        ref = np.concatenate([_mf_reference(model, float(rows[i][1]), float(rows[i][2]),
                                            rows[i][3][None].astype(np.float64), rows[i][4][None].astype(np.float64)) for i in idx])
        rel = np.abs(got[idx] - ref) / np.maximum(ref, 1e-30)
        worst[model] = float(rel.max())
        assert np.all(np.isfinite(got[idx])) and np.all(rel <= 2e-4), (model, float(rel.max()), int(np.argmax(rel)))
    print(f"\n  microfacet.glsl vs reference ({len(rows)} cases): worst relative error per model {worst}")


def test_envelope_mark(browser: Browser, base_url: str) -> None:
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    set_control(page, "L", 70.0)
    env = json.loads(page.get_attribute("#out-envelope", "data-value") or "null")
    want = python_envelope(70.0)
    assert close(env, want)
    box = page.locator("#rng-c").bounding_box()
    mark = page.locator("#envelope-mark").bounding_box()
    assert box and mark
    frac = (mark["x"] + mark["width"] / 2 - box["x"]) / box["width"]
    assert abs(frac - want / 0.6) < 0.02, (frac, want)


def test_plot_click_picks(browser: Browser, base_url: str) -> None:
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48#mode=perceptual&L=60&a=0&b=0&c=0.05&d=0.95")
    x, y = page.evaluate("window.picker.plotXY(0.12, 0.9)")
    box = page.locator("#plot").bounding_box()
    assert box
    page.mouse.click(box["x"] + x, box["y"] + y)
    c, d = float(page.input_value("#num-c")), float(page.input_value("#num-d"))
    assert abs(c - 0.12) < 0.004 and abs(d - 0.9) < 0.004, (c, d)
    assert "c=" + page.input_value("#num-c") in page.evaluate("location.href")


def python_envelope(L: float) -> float:
    py = os.environ.get("PGLOSS_WEB_PY", str(ROOT / ".venv-py/bin/python"))
    r = subprocess.run([py, "-c", f"import pgloss; print(repr(pgloss.envelope_contrast({L!r})))"],
                       capture_output=True, text=True, check=True, cwd="/")
    return float(r.stdout)


# ---- (d) the URL hash holds the state -----------------------------------------------------

def test_url_hash_reproduces_state(browser: Browser, base_url: str) -> None:
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    set_control(page, "L", 42.5)
    set_control(page, "a", 12.25)
    set_control(page, "c", 0.071)
    page.check("input[name=view][value=match]")
    url = page.evaluate("location.href")  # (page.url follows replaceState only asynchronously)
    assert re.search(r"L=42\.5", url) and "view=match" in url, url
    before = {k: page.inner_text(f"#out-{k}") for k in ("rho-d", "rho-s", "alpha", "status", "lab", "cd")}
    paints_before = page.evaluate("window.picker.tracer.paints")
    other = open_page(browser, url.replace("autorun=0", "autorun=0"))
    after = {k: other.inner_text(f"#out-{k}") for k in ("rho-d", "rho-s", "alpha", "status", "lab", "cd")}
    assert after == before
    assert other.evaluate("window.picker.tracer.paints") == paints_before
    assert other.input_value("#num-a") == "12.25"
    assert other.is_checked("input[name=view][value=match]")
    # Physical mode round-trips too.
    other.check("input[name=mode][value=physical]")
    set_control(other, "rho_s", 0.05)
    third = open_page(browser, other.evaluate("location.href"))
    assert third.is_checked("input[name=mode][value=physical]")
    assert third.input_value("#num-rho_s") == "0.05"
    assert third.inner_text("#out-cd") == other.inner_text("#out-cd")
    print("\n(d) URL hash: perceptual and physical state, view, read-outs and rendered paints reproduced")


# ---- export -------------------------------------------------------------------------------

def test_export_formats(browser: Browser, base_url: str, tmp_path: Path) -> None:
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48#mode=perceptual&L=35&a=45&b=25&c=0.06&d=0.95")
    j = json.loads(page.input_value("#export"))
    assert j["perceptual"] == {"L": 35, "a": 45, "b": 25, "c": 0.06, "d": 0.95}
    assert j["status"] == "PGLOSS_OK"
    page.check("input[name=export][value=scene]")
    scene_text = page.input_value("#export")
    assert "material paint perceptual L=35 a=45 b=25 c=0.06 d=0.95" in scene_text
    assert re.search(r"material paint physical rho_d=[0-9.e-]+,[0-9.e-]+,[0-9.e-]+ rho_s=[0-9.e-]+ alpha=0.05", scene_text)
    page.check("input[name=export][value=osl]")
    osl = page.input_value("#export")
    for name in ("Lightness", "a_star", "b_star", "contrast_gloss", "distinctness_gloss", "rho_d", "rho_s", "alpha"):
        assert re.search(rf"^param \w+ {name} ", osl, re.M), name
        assert re.search(rf"\b{name}\b", (ROOT / "osl/pgloss_material.osl").read_text()), name
    page.check("input[name=export][value=glsl]")
    snippet = page.input_value("#export")
    assert "pgloss_perceptual(35.0, 45.0, 25.0, 0.06, 0.95)" in snippet
    # The GLSL snippet compiles (ESSL 3.00, this browser's WebGL2) after glsl/pgloss.glsl.
    log = page.evaluate("""async (snippet) => {
        const glsl = await (await fetch('pgloss.glsl')).text();
        const gl = document.createElement('canvas').getContext('webgl2');
        const sh = gl.createShader(gl.FRAGMENT_SHADER);
        gl.shaderSource(sh, `#version 300 es\n${glsl}\nout vec4 o;\nvoid main() {\n${snippet}\n` +
                            `o = vec4(m.rho_d, float(st));\n}\n`);
        gl.compileShader(sh);
        return gl.getShaderParameter(sh, gl.COMPILE_STATUS) ? 'ok' : gl.getShaderInfoLog(sh);
    }""", snippet)
    assert log == "ok", log
    # Both scene lines are accepted by pgloss-tracer's parser (a 1-spp render of a tiny image).
    tracer = os.environ.get("PGLOSS_TRACER", str(ROOT / "build-tracer-test/examples/tracer/pgloss-tracer"))
    # the active line, and the physical equivalent given as a comment
    lines = re.findall(r"(material paint (?:perceptual|physical) .*)$", scene_text, re.M)
    assert len(lines) == 2
    for i, ln in enumerate(lines):
        sc = tmp_path / f"export{i}.scene"
        sc.write_text(re.sub(r"^material paint .*$", ln, SCENE.read_text(), flags=re.M))
        r = subprocess.run([tracer, "render", str(sc), "--size", "8x6", "--spp", "1", "--quiet",
                            "--out", str(tmp_path / f"export{i}")], capture_output=True, text=True)
        assert r.returncode == 0, (ln, r.stderr)


# ---- (c) the render agrees with pgloss-tracer ---------------------------------------------

W, H = 64, 48
RENDER_PAINT = {"L": 40.0, "a": 20.0, "b": -10.0, "c": 0.08, "d": 0.94}
PAGE_FRAMES, PAGE_SPP = 256, 2       # 512 samples per pixel, in 256 accumulated frames
TRACER_SPP = 2048


def regions(scene_text: str) -> np.ndarray:
    """Region of each pixel centre's first hit (render.cpp's camera and Renderer::regions):
    1 walls, 2 floor, 3 ceiling, 4 sphere, 5 light. Independent of the page's code."""
    kv = {}
    for line in scene_text.splitlines():
        line = line.split("#")[0].split()
        if line:
            kv.setdefault(line[0], dict(w.split("=", 1) for w in line[1:] if "=" in w))
    v = lambda s: np.array([float(x) for x in s.split(",")])  # noqa: E731
    cam = kv["camera"]
    pos, look, up, fov = v(cam["position"]), v(cam["look_at"]), v(cam["up"]), float(cam["fov"])
    f = (look - pos) / np.linalg.norm(look - pos)
    r = np.cross(f, up); r /= np.linalg.norm(r)
    u = np.cross(r, f)
    th = math.tan(0.5 * math.radians(fov))
    ys, xs = np.mgrid[0:H, 0:W] + 0.5
    sx = (2 * xs / W - 1) * (W / H) * th
    sy = (1 - 2 * ys / H) * th
    d = f[None, None] + sx[..., None] * r + sy[..., None] * u
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    lo, hi = v(kv["box"]["min"]), v(kv["box"]["max"])
    t_hi = np.maximum((lo - pos) / d, (hi - pos) / d)
    t_box = t_hi.min(axis=-1)
    axis = t_hi.argmin(axis=-1)
    p = pos + t_box[..., None] * d
    reg = np.where(axis == 1, np.where(p[..., 1] < 0.5 * (lo[1] + hi[1]), 2, 3), 1)
    c, rad = v(kv["sphere"]["center"]), float(kv["sphere"]["radius"])
    oc = pos - c
    b = (d * oc).sum(-1)
    disc = b * b - (oc @ oc - rad * rad)
    t_s = np.where(disc > 0, -b - np.sqrt(np.maximum(disc, 0)), np.inf)
    reg = np.where((t_s > 0) & (t_s < t_box), 4, reg)
    return reg


def read_exr(path: Path) -> np.ndarray:
    """Linear RGB of the tracer's EXR, as OpenImageIO (which wrote it) prints it: `oiiotool --dumpdata`
    (9 significant digits, far below the noise compared here)."""
    r = subprocess.run(["oiiotool", "--info", "-v", "--dumpdata", str(path)], check=True, capture_output=True, text=True)
    img = np.full((H, W, 3), np.nan)
    for m in re.finditer(r"Pixel \((\d+), (\d+)\): (\S+) (\S+) (\S+)", r.stdout):
        x, y = int(m.group(1)), int(m.group(2))
        img[y, x] = [float(m.group(k)) for k in (3, 4, 5)]
    assert np.isfinite(img).all(), f"{path}: not every pixel was read"
    return img


def render_sums(page: Page, frames: int) -> Tuple[np.ndarray, int, float]:
    """The page's tracer restarted and run for `frames` passes of PAGE_SPP: its running sums
    (rows, columns, RGB + Σ Y²), the samples per pixel and the seconds it took."""
    t0 = time.time()
    res = page.evaluate(f"""() => {{
        const t = window.picker.tracer;
        t.reset();
        for (let i = 0; i < {frames}; i++) t.step({PAGE_SPP});
        const s = t.readSums();
        return {{w: s.width, h: s.height, n: s.count, sums: Array.from(s.sums)}};
    }}""")
    sums = np.array(res["sums"], dtype=np.float64).reshape(res["h"], res["w"], 4)
    return sums, int(res["n"]), time.time() - t0


def test_render_matches_tracer(browser: Browser, base_url: str, tmp_path: Path) -> None:
    tracer = os.environ.get("PGLOSS_TRACER", str(ROOT / "build-tracer-test/examples/tracer/pgloss-tracer"))
    if not Path(tracer).is_file():
        pytest.fail(f"no pgloss-tracer at {tracer} (scripts/test-web.sh builds it)")
    q = RENDER_PAINT
    scene_text = SCENE.read_text()
    line = f"material paint perceptual L={q['L']} a={q['a']} b={q['b']} c={q['c']} d={q['d']}"
    ref_scene = re.sub(r"^material paint .*$", line, scene_text, flags=re.M)
    assert line in ref_scene
    (tmp_path / "ref.scene").write_text(ref_scene)
    t0 = time.time()
    subprocess.run([tracer, "render", str(tmp_path / "ref.scene"), "--size", f"{W}x{H}", "--spp", str(TRACER_SPP),
                    "--out", str(tmp_path / "ref"), "--quiet"], check=True, capture_output=True)
    t_tracer = time.time() - t0
    ref = read_exr(tmp_path / "ref.exr")

    hash_ = "#mode=perceptual&" + "&".join(f"{k}={v}" for k, v in q.items()) + "&view=single"
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size={W}x{H}{hash_}")
    assert page.inner_text("#out-status") == "PGLOSS_OK"
    sums, n, t_page = render_sums(page, PAGE_FRAMES)
    assert sums.shape == (H, W, 4) and n == PAGE_FRAMES * PAGE_SPP
    mean = sums[..., :3] / n
    lum_w = np.array([0.2126, 0.7152, 0.0722])
    Y_page = mean @ lum_w
    # Per pixel: variance of the mean of n samples, from the accumulated Σ Y².
    var_pix = np.maximum(sums[..., 3] / n - Y_page ** 2, 0) * n / (n - 1) / n
    Y_ref = ref @ lum_w
    reg = regions(scene_text)
    lines, worst = [], 0.0
    for name, code in (("sphere", 4), ("walls", 1), ("floor", 2)):
        m = reg == code
        k = int(m.sum())
        assert k > 50, (name, k)
        mp, mr = Y_page[m].mean(), Y_ref[m].mean()
        se_page = math.sqrt(var_pix[m].sum()) / k
        # The tracer runs the same estimator (MIS, same strategies per vertex), so its per-sample
        # variance is the page's: its standard error is the page's scaled by √(n / spp).
        se_ref = se_page * math.sqrt(n / TRACER_SPP)
        z = (mp - mr) / math.hypot(se_page, se_ref)
        worst = max(worst, abs(z))
        rel = (mp - mr) / mr
        lines.append(f"  {name:6s} {k:5d} px  page {mp:.5f}  tracer {mr:.5f}  diff {rel:+.3%}  "
                     f"σ {math.hypot(se_page, se_ref) / mr:.3%}  z {z:+.2f}")
        # Per channel, the colour of the paint: the same test on each of R, G, B with the luminance σ
        # scaled by the channel/luminance ratio (a loose proxy; reported, and bounded at 5σ).
        for ch in range(3):
            cp, cr = mean[..., ch][m].mean(), ref[..., ch][m].mean()
            zc = (cp - cr) / (math.hypot(se_page, se_ref) * max(cr / max(mr, 1e-12), 0.2))
            lines.append(f"           channel {'RGB'[ch]}: page {cp:.5f} tracer {cr:.5f} z {zc:+.2f}")
            assert abs(zc) < 5.0, (name, ch, cp, cr, zc)
        assert abs(z) < 4.0, (name, mp, mr, z)
    print(f"\n(c) {W}x{H}, page {n} spp in {PAGE_FRAMES} frames ({t_page:.1f} s on SwiftShader), "
          f"pgloss-tracer {TRACER_SPP} spp ({t_tracer:.1f} s); paint {q}; mean luminance per region:\n" + "\n".join(lines))
    assert not page.errors, page.errors  # type: ignore[attr-defined]


# ---- (e) a screenshot -----------------------------------------------------------------------

def test_screenshot(browser: Browser, base_url: str) -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    page = open_page(browser, f"{base_url}/index.html?size=240x180&maxspp=96"
                     "#mode=perceptual&L=35&a=45&b=25&c=0.06&d=0.95&view=single")
    t0 = time.time()
    page.wait_for_function("window.picker.tracer.count >= 96", timeout=240_000)
    dt = time.time() - t0
    page.screenshot(path=str(OUT / "picker.png"), full_page=True)
    print(f"\n(e) interactive loop at 240x180: 96 spp in {dt:.1f} s ({96 * 240 * 180 / dt / 1e6:.2f} Msamples/s on SwiftShader)")
    page.check("input[name=view][value=match]")
    page.wait_for_function("window.picker.tracer.count >= 48", timeout=240_000)
    page.locator("#view-panel").screenshot(path=str(OUT / "picker-match.png"))
    # A target out of the paint's reach (glTF core: F0 fixed at 0.04), with the glTF export.
    page.check("input[name=view][value=single]")
    page.select_option("#target", "gltf_core")
    page.check("input[name=export][value=gltf]")
    page.locator("#controls").screenshot(path=str(OUT / "picker-target.png"))
    # A reachable target beside the paint (Blender Principled), rendered to the end (maxspp) first:
    # a frame of the two tiles at many samples per frame outlasts the screenshot's wait.
    page.close()
    page = open_page(browser, f"{base_url}/index.html?size=128x96&maxspp=32"
                     "#mode=perceptual&L=35&a=45&b=25&c=0.06&d=0.95&view=single&target=principled")
    page.wait_for_function("window.picker.tracer.count >= 32 && window.picker.tracer.tilesX === 2", timeout=240_000)
    page.locator("#view-panel").screenshot(path=str(OUT / "picker-target-view.png"))
    assert (OUT / "picker.png").stat().st_size > 10_000
    print(f"\n(e) screenshots: {OUT / 'picker.png'}, {OUT / 'picker-match.png'}, {OUT / 'picker-target.png'}, "
          f"{OUT / 'picker-target-view.png'}")


# ---- defects found by a new user (each test failed before its fix) ------------------------

CANVAS_MAX = """() => {  // the brightest 8-bit channel on the view canvas (WebGL, preserveDrawingBuffer)
    const v = document.getElementById('view'), c = document.createElement('canvas');
    c.width = v.width; c.height = v.height;
    const g = c.getContext('2d');
    g.drawImage(v, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let m = 0;
    for (let i = 0; i < d.length; i += 4) m = Math.max(m, d[i], d[i + 1], d[i + 2]);
    return m;
}"""


def test_match_labels_hidden_in_paint_view(browser: Browser, base_url: str) -> None:
    """Back from "match gloss" to "paint", the six match labels go: `#match-labels { display:
    grid }` overrode the `hidden` attribute, and they stayed with stale values. Nothing on the
    page with `hidden` may show."""
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    page.check("input[name=view][value=match]")
    assert page.locator("#match-labels").is_visible()
    assert page.locator("#match-labels div").count() == 6
    page.check("input[name=view][value=single]")
    assert page.locator("#match-labels").is_hidden()
    shown = page.evaluate("[...document.querySelectorAll('[hidden]')].filter((e) => getComputedStyle(e).display "
                          "!== 'none').map((e) => e.id || e.tagName)")
    assert shown == [], shown


def test_export_link_follows_every_change(browser: Browser, base_url: str) -> None:
    """The JSON export's "link" is the page's address after the change, not before it
    (exportText read location.href before writeHash updated it)."""
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48#mode=perceptual&L=50&a=0&b=0&c=0.05&d=0.95")
    for key, value in (("c", 0.071), ("L", 42.5), ("d", 0.91)):
        set_control(page, key, value)
        link = json.loads(page.input_value("#export"))["link"]
        assert link == page.evaluate("location.href") and f"{key}={value}" in link, (key, link)
    page.check("input[name=view][value=match]")
    assert "view=match" in json.loads(page.input_value("#export"))["link"]
    page.check("input[name=mode][value=physical]")
    assert "mode=physical" in json.loads(page.input_value("#export"))["link"]


def test_out_of_gamut_paint_is_not_shown_as_rendered(browser: Browser, base_url: str) -> None:
    """An out-of-gamut paint: the note under the view gives the status the status line gives
    (it said PGLOSS_ERR_NEGATIVE under PGLOSS_ERR_GAMUT), and the canvas is emptied (it kept the
    previous paint's image). In the match view a tile whose paint the core refuses is black, not
    a black sphere in a lit room."""
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48#mode=perceptual&L=51.04&a=0&b=0&c=0.087&d=0.93")
    page.evaluate("() => { for (let i = 0; i < 4; i++) window.picker.tracer.step(1); }")
    assert page.evaluate(CANVAS_MAX) > 40  # the grey paint is on the canvas
    set_control(page, "b", -120.0)
    status, reason = page.inner_text("#out-status"), page.inner_text("#out-reason")
    assert status == "PGLOSS_ERR_GAMUT"
    note = page.inner_text("#view-note")
    assert note.startswith(f"Not rendered — {status}: {reason}"), note
    assert "PGLOSS_ERR_NEGATIVE" not in note
    assert page.evaluate(CANVAS_MAX) == 0
    set_control(page, "b", 0.0)  # a valid paint renders again
    page.evaluate("() => window.picker.tracer.step(2)")
    assert page.locator("#view-note").is_hidden() and page.evaluate(CANVAS_MAX) > 40
    # Physical mode, α = 0 (PGLOSS_ERR_ALPHA): every match tile's paint is refused.
    page.check("input[name=mode][value=physical]")
    set_control(page, "alpha", 0.0)
    page.check("input[name=view][value=match]")
    page.evaluate("() => { for (let i = 0; i < 4; i++) window.picker.tracer.step(1); }")
    assert page.evaluate(CANVAS_MAX) == 0
    assert not page.errors, page.errors  # type: ignore[attr-defined]


def _significant(number: str) -> int:
    mantissa = re.sub(r"[eE].*$", "", number).lstrip("-").replace(".", "").lstrip("0")
    return len(mantissa)


def test_numbers_shown_and_exported_without_float_noise(browser: Browser, base_url: str) -> None:
    """Number boxes and exports show at most 6 significant digits (0.050000000000000044 was shown
    for α = 1 − 0.95, 0.08699999999999998 exported for c); the URL hash keeps the exact doubles,
    so that the link reproduces the state bit for bit."""
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48#mode=perceptual&L=51.04&a=0&b=0&c=0.087&d=0.95")
    page.check("input[name=mode][value=physical]")
    assert page.input_value("#num-alpha") == "0.05"
    for key in ("rd_r", "rd_g", "rd_b", "rho_s", "alpha"):
        assert _significant(page.input_value(f"#num-{key}")) <= 6, (key, page.input_value(f"#num-{key}"))
    page.check("input[name=mode][value=perceptual]")
    assert page.input_value("#num-c") == "0.087" and page.input_value("#num-d") == "0.95"
    exact = page.evaluate("({...window.picker.state})")
    for kind in ("json", "scene", "osl", "glsl"):
        page.check(f"input[name=export][value={kind}]")
        text = page.input_value("#export")
        if kind == "json":
            j = json.loads(text)
            assert j["perceptual"]["c"] == 0.087 and j["perceptual"]["d"] == 0.95 and j["physical"]["alpha"] == 0.05
            text = text.replace(j["link"], "")
        noisy = [n for n in re.findall(r"-?\d+\.\d+(?:[eE][-+]?\d+)?", text) if _significant(n) > 6]
        assert not noisy, (kind, noisy)
    # The link is exact: the state it opens is the same doubles.
    again = open_page(browser, json.loads(page.evaluate("JSON.stringify({l: location.href})"))["l"])
    state = again.evaluate("({...window.picker.state})")
    assert all(state[k] == exact[k] for k in ("L", "a", "b", "c", "d")), (state, exact)


def test_guide_states_the_wasm_size() -> None:
    """docs/guide/picker.md's "a WASI reactor of about N kB" is the built module's size to ±10 %
    (the README once said 38 kB of a 48 kB file)."""
    guide = (ROOT / "docs" / "guide" / "picker.md").read_text(encoding="utf-8")
    m = re.search(r"WASI reactor of about (\d+) kB", guide)
    assert m, "docs/guide/picker.md no longer states the module's size"
    size = (SITE / "pgloss.wasm").stat().st_size / 1000
    assert abs(size - int(m.group(1))) <= 0.1 * size, (m.group(1), size)


# ---- the targets' whole BRDF in GLSL (microfacet.glsl's pgloss_bridge_shading_*) -----------------

# One parameter set per model (bridge.h's conventions): MaterialX, Principled, roughplastic GGX
# and Beckmann, a coloured base, the roughness of a glossy paint and of a satin one.
SHADING_CASES = [("openpbr", 0.25, 1.5, 1.0), ("openpbr", 0.5, 1.6, 0.7), ("principled", 0.25, 1.5, 0.5),
                 ("principled", 0.5, 1.45, 0.5), ("roughplastic_ggx", 0.06, 1.5, 1.0),
                 ("roughplastic_ggx", 0.25, 1.55, 1.0), ("roughplastic_beckmann", 0.06, 1.5, 1.0),
                 ("roughplastic_beckmann", 0.25, 1.45, 1.0)]
SHADINGS = """(cases) => cases.map(([t, r, ior, spec]) => {
    const s = window.picker.pg.bridgeShading(t, { base_color: [0.8, 0.45, 0.1], roughness: r, ior, specular: spec });
    if (s.status !== 0) throw new Error(`${t}: ${s.name}`);
    return s.shading;
})"""


def test_target_brdf_glsl_matches_the_core(browser: Browser, base_url: str) -> None:
    """GLSL pgloss_bridge_shading_eval (float32, WebGL2 on SwiftShader, f in RGB) against the C core's
    pgloss_bridge_shading_eval in double (WebAssembly) at the same float32 directions: random
    pairs and pairs near the mirror direction, 8 targets. Measured 7e-7 relative; bound 2e-4, the
    float32 allowance of the lobe alone (the test above), which the tables' lerp in μ·63 and the
    diffuse term only dilute."""
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    shadings = page.evaluate(SHADINGS, SHADING_CASES)
    rng = np.random.default_rng(33)
    n = 96
    jobs, dirs = [], []
    for s in shadings:
        wo = rng.normal(size=(n, 3)); wo[:, 2] = np.abs(wo[:, 2]) + 0.05
        wi = rng.normal(size=(n, 3)); wi[:, 2] = np.abs(wi[:, 2]) + 0.05
        m = n // 2
        wi[:m] = np.c_[-wo[:m, 0], -wo[:m, 1], wo[:m, 2]] + math.sqrt(s["alpha"]) * rng.normal(size=(m, 3)) * np.linalg.norm(wo[:m], axis=1)[:, None]
        wi[:m, 2] = np.abs(wi[:m, 2]) + 0.02
        wo = (wo / np.linalg.norm(wo, axis=1)[:, None]).astype(np.float32).astype(np.float64)
        wi = (wi / np.linalg.norm(wi, axis=1)[:, None]).astype(np.float32).astype(np.float64)
        dirs.append((wo, wi))
        jobs.append({"inputs": [np.c_[wo, np.zeros(n)].ravel().tolist(), np.c_[wi, np.zeros(n)].ravel().tolist()],
                     "n": n, "height": 1, "shading": s})
    body = """vec3 wo = texelFetch(u_in, ivec2(px.x, 0), 0).xyz, wi = texelFetch(u_in, ivec2(px.x, 1), 0).xyz;
              o = vec4(pgloss_bridge_shading_eval(u_target, wo, wi), pgloss_bridge_shading_pdf(u_target, wo, wi));"""
    got = page.evaluate(GLSL_RUN, {"body": body, "jobs": jobs})
    want = page.evaluate("""(cases) => cases.map(([s, wo, wi]) => wo.map((o, k) => {
        const r = window.picker.pg.bridgeShadingEval(s, o, wi[k]);
        return s.base_color.map((b) => r.specular + r.diffuse * b);
    }))""", [[s, d[0].tolist(), d[1].tolist()] for s, d in zip(shadings, dirs)])
    worst = {}
    for (t, *_), g, w in zip(SHADING_CASES, got, want):
        g = np.asarray(g).reshape(n, 4)
        w = np.asarray(w)
        assert np.all(np.isfinite(g)) and np.all(g[:, 3] > 0), t
        rel = np.abs(g[:, :3] - w) / np.maximum(w, 1e-30)
        worst[t] = max(worst.get(t, 0.0), float(rel.max()))
        assert rel.max() <= 2e-4, (t, float(rel.max()), int(np.argmax(rel.max(axis=1))))
    print(f"\n  target BRDF GLSL vs C core ({len(SHADING_CASES)} targets × {n} direction pairs): worst relative error {worst}")


def test_target_sampling_is_consistent(browser: Browser, base_url: str) -> None:
    """The target's importance sampling (pgloss_bridge_shading_sample: visible normals / Beckmann D,
    cosine, their mixture pdf) against a deterministic quadrature of its BRDF on the hemisphere
    (1024 rings in cos θi × 512 azimuths): the sampled estimate of the directional albedo,
    E[f cos θi / pdf] over 2^17 samples, equals ∫ f cos θi dωi within 4 standard errors plus 0.3%
    (the quadrature's own error at α 0.06, measured ≤ 0.19% in all), and the pdf integrates to at
    most 1 (to the quadrature error; below 1 by the specular samples that fall under the horizon:
    Beckmann's D sampling loses 15% at μo 0.15). A sample drawn from a density other than the pdf
    its weight divides by moves the estimate (the VNDF pdf without its G1(ωo): 31σ off at μo 0.15)."""
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    shadings = page.evaluate(SHADINGS, SHADING_CASES)
    mus = [0.95, 0.7, 0.4, 0.15]
    NT, NP, NS, SPP = 1024, 512, 1024, 128
    wos = [[math.sqrt(1 - m * m), 0.0, m] for m in mus]
    row = [v for w in wos for v in (*w, 0.0)]
    quad = page.evaluate(GLSL_RUN, {"body": f"""
        vec3 wo = texelFetch(u_in, ivec2(px.y, 0), 0).xyz;
        float c0 = 1.0 - float(px.x) / {NT}.0, c1 = 1.0 - float(px.x + 1) / {NT}.0, ci = 0.5 * (c0 + c1);
        float si = sqrt(1.0 - ci * ci), dw = (c0 - c1) * 2.0 * PGLOSS_MF_PI / {NP}.0;
        for (int j = 0; j < {NP}; ++j) {{
            float ph = 2.0 * PGLOSS_MF_PI * (float(j) + 0.5) / {NP}.0;
            vec3 wi = vec3(si * cos(ph), si * sin(ph), ci);
            o += vec4(pgloss_bridge_shading_eval(u_target, wo, wi) * ci, pgloss_bridge_shading_pdf(u_target, wo, wi)) * dw;
        }}""", "jobs": [{"inputs": [row + [0.0] * 4 * (NT - len(mus))], "n": NT, "height": len(mus), "shading": s}
                        for s in shadings]})
    mc = page.evaluate(GLSL_RUN, {"body": f"""
        vec3 wo = texelFetch(u_in, ivec2(px.y, 0), 0).xyz;
        uint h = uint(px.x) * 2654435761u ^ uint(px.y) * 40503u;
        for (int j = 0; j < {SPP}; ++j) {{
            vec3 u;
            for (int k = 0; k < 3; ++k) {{  // xorshift-multiply hash (Wang/Jenkins style), 24 bits
                h ^= h >> 16; h *= 0x7feb352du; h ^= h >> 15; h *= 0x846ca68bu; h ^= h >> 16;
                u[k] = float(h >> 8) / 16777216.0;
            }}
            vec3 wi; float pdf;
            vec3 w = pgloss_bridge_shading_sample(u_target, wo, u, wi, pdf);
            o += vec4(w.r, w.r * w.r, w.g, 1.0);
        }}""", "jobs": [{"inputs": [row + [0.0] * 4 * (NS - len(mus))], "n": NS, "height": len(mus), "shading": s}
                        for s in shadings]})
    lines, worst_z = [], 0.0
    for (t, r, *_), q, m in zip(SHADING_CASES, quad, mc):
        q = np.asarray(q).reshape(len(mus), NT, 4).sum(axis=1)
        m = np.asarray(m).reshape(len(mus), NS, 4).sum(axis=1)
        for k, mu in enumerate(mus):
            N = m[k, 3]
            est = m[k, 0] / N
            se = math.sqrt(max(m[k, 1] / N - est * est, 0) / N)
            ref, pdf_mass = q[k, 0], q[k, 3]
            z = (est - ref) / se if se > 0 else 0.0
            worst_z = max(worst_z, abs(z))
            lines.append(f"  {t:22s} r {r:.2f} μo {mu:.2f}: albedo (R) sampled {est:.5f} ± {se:.5f}, "
                         f"quadrature {ref:.5f} ({(est - ref) / ref:+.3%}), ∫pdf {pdf_mass:.5f}")
            assert abs(est - ref) <= 4 * se + 3e-3 * ref, lines[-1]
            assert 0.8 <= pdf_mass <= 1.005, lines[-1]
    print(f"\n  target sampling vs quadrature ({NS * SPP} samples per direction), worst |z| {worst_z:.2f}:\n" + "\n".join(lines))


# ---- the target beside the paint, against Mitsuba 3 --------------------------------------------

MITSUBA_SPP = 1024
TARGET_FRAMES = 128  # × PAGE_SPP: 256 samples per pixel on both tiles (seconds on SwiftShader)


def test_target_view_matches_mitsuba(browser: Browser, base_url: str, tmp_path: Path) -> None:
    """The paint view with a Mitsuba 3 roughplastic target: the right-hand tile (the target's BRDF
    in the page's tracer) against Mitsuba 3 itself rendering the same scene with its own
    roughplastic at the parameters the page shows (examples/bridge/harness_mitsuba.py, the tracer's
    scene in Mitsuba). Mean luminance and channels per region, as test_render_matches_tracer. The
    σ assumes Mitsuba's per-sample variance is the page's (both: light sampling + BSDF sampling,
    MIS); 0.5% is added for what the two models share only to their quadratures (t(μ), R_int agree
    with Mitsuba's to 1e-3, test_bridge_shading) and Mitsuba's float32."""
    q = RENDER_PAINT
    hash_ = "#mode=perceptual&" + "&".join(f"{k}={v}" for k, v in q.items()) + "&view=single&target=roughplastic_ggx"
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size={W}x{H}{hash_}")
    assert page.inner_text("#target-status") == "PGLOSS_OK"
    assert "Right: Mitsuba 3 roughplastic (GGX)" in page.inner_text("#view-what")
    params = page.evaluate("window.picker.model.target.params")
    bsdf = {"type": "roughplastic", "distribution": "ggx", "alpha": params["roughness"], "int_ior": params["ior"],
            "diffuse_reflectance": params["base_color"], "nonlinear": False}
    t0 = time.time()
    subprocess.run([EXPORT_PY, str(ROOT / "examples/bridge/harness_mitsuba.py"), json.dumps(bsdf), "--out",
                    str(tmp_path / "mi.exr"), "--spp", str(MITSUBA_SPP), "--size", f"{W}x{H}"], check=True,
                   capture_output=True)
    t_mi = time.time() - t0
    ref = read_exr(tmp_path / "mi.exr")
    sums, n, t_page = render_sums(page, TARGET_FRAMES)
    assert sums.shape == (H, 2 * W, 4)
    sums = sums[:, W:]  # the target's tile
    mean = sums[..., :3] / n
    lum_w = np.array([0.2126, 0.7152, 0.0722])
    Y_page, Y_ref = mean @ lum_w, ref @ lum_w
    var_pix = np.maximum(sums[..., 3] / n - Y_page ** 2, 0) / (n - 1)
    reg = regions(SCENE.read_text())
    lines = []
    sphere = reg == 4
    bright = sphere & (Y_ref >= np.quantile(Y_ref[sphere], 0.9))  # the highlight: the sphere's top decile
    for name, m in (("sphere", sphere), ("highlight", bright), ("walls", reg == 1), ("floor", reg == 2)):
        k = int(m.sum())
        mp, mr = Y_page[m].mean(), Y_ref[m].mean()
        se = math.sqrt(var_pix[m].sum()) / k * math.sqrt(1 + n / MITSUBA_SPP)
        tol = 4 * se + 5e-3 * mr
        lines.append(f"  {name:9s} {k:5d} px  page {mp:.5f}  Mitsuba {mr:.5f}  diff {(mp - mr) / mr:+.3%}  σ {se / mr:.3%}")
        for ch in range(3):
            cp, cr = mean[..., ch][m].mean(), ref[..., ch][m].mean()
            lines.append(f"            channel {'RGB'[ch]}: page {cp:.5f} Mitsuba {cr:.5f} diff {(cp - cr) / cr:+.3%}")
            assert abs(cp - cr) <= 5 * se * max(cr / mr, 0.2) + 5e-3 * cr, lines[-1]
        assert abs(mp - mr) <= tol, lines
    print(f"\n  target view vs Mitsuba 3 roughplastic (GGX), {W}x{H}: page {n} spp ({t_page:.1f} s, both tiles), "
          f"Mitsuba {MITSUBA_SPP} spp ({t_mi:.1f} s); params {params}:\n" + "\n".join(lines))
    assert not page.errors, page.errors  # type: ignore[attr-defined]


def test_target_view_layout_follows_the_bridge(browser: Browser, base_url: str) -> None:
    """Ward alone: one tile. A reachable target: the paint and the target side by side. Out of the
    target's reach: the nearest reachable paint's BRDF, said so. Outside the model (no parameters):
    the Ward paint alone, with the bridge's status named; never a stale target tile."""
    page = open_page(browser, f"{base_url}/index.html?autorun=0&size=64x48")
    tiles = "() => [window.picker.tracer.tilesX, document.getElementById('view').width]"
    assert page.evaluate(tiles) == [1, 64]
    page.select_option("#target", "openpbr")
    assert page.evaluate(tiles) == [2, 128]
    assert page.inner_text("#view-what").startswith("Left: the Ward paint (eq. 2). Right: OpenPBR Surface")
    for k, v in (("L", 10.0), ("c", 0.2)):  # a black paint of c 0.2: out of glTF core's reach
        set_control(page, k, v)
    page.select_option("#target", "gltf_core")
    assert page.inner_text("#target-status").startswith("PGLOSS_ERR_BRIDGE_")
    assert page.evaluate(tiles) == [2, 128] and "the nearest reachable paint's" in page.inner_text("#view-what")
    set_control(page, "L", 90.0)  # c 0.2 is beyond the envelope at L* 90: no parameters
    assert page.inner_text("#target-status") == "PGLOSS_ERR_ENVELOPE"
    assert page.evaluate(tiles) == [1, 64] and "alone" in page.inner_text("#view-what")
    assert not page.errors, page.errors  # type: ignore[attr-defined]
