# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Threads (pgloss.set_num_threads): every threaded array call gives, on 2, 3 and 7 threads
(7 is more than this host's CPUs), exactly what it gives on one thread — every output bit,
the status arrays, the first failing index of PglossError, the warnings — and the one-thread
path is itself held to the shared vectors by test_vectors.py and test_arrays.py.

The inputs: the shared vectors' inputs (tests/vectors), tiled to lengths that span several
threads' ranges and do not divide into them evenly, and random textures with failing
elements planted at the start, the middle and the end. The split threshold is lowered for
these tests (``_core._set_min_elements_per_thread(1)``) so that every array of two units or
more (1024 elements each) is split, as a texture is.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import warnings
from pathlib import Path
from typing import Any, Callable, Dict, List, Tuple

import numpy as np
import pytest

import pgloss
from pgloss import _core
from pgloss_vectors import load, num

THREADS = (2, 3, 7)
UNIT = 1024  # the elements of one C batch call (kUnit, core.cpp): the threads' unit
SLICE = CHUNK = UNIT
N_PAINTS = 5 * SLICE + 77  # 6 units: ranges of 3/3, 2/2/2, and 6 threads of 1 for 7
N_PAIRS = 9 * CHUNK + 5  # 10 units: uneven ranges for 3 and 7 threads


@pytest.fixture(autouse=True)
def split_everything():
    """Every array of two units or more is split; the thread count is restored afterwards."""
    old_min = _core._set_min_elements_per_thread(1)
    old_threads = pgloss.get_num_threads()
    yield
    _core._set_min_elements_per_thread(old_min)
    pgloss.set_num_threads(old_threads)


# ------------------------------------------------------------------------------------------------
# An outcome: everything a call shows its caller, as bytes, so that equality is bit for bit.

def _leaves(x: Any) -> List[Any]:
    if isinstance(x, np.ndarray):
        return [("array", x.dtype.str, x.shape, x.tobytes())]
    if isinstance(x, pgloss.Physical):
        return ["Physical"] + _leaves((x.rho_d, x.rho_s, x.alpha_x, x.alpha_y, int(x.normalization)))
    if isinstance(x, pgloss.Perceptual):
        return ["Perceptual"] + _leaves((x.L, x.a, x.b, x.c, x.d))
    if isinstance(x, (tuple, list)):
        return [type(x).__name__] + [leaf for v in x for leaf in _leaves(v)]
    if isinstance(x, (float, np.floating)):
        return [("float", np.float64(x).tobytes())]
    if isinstance(x, (int, np.integer)):
        return [("int", type(x).__name__, int(x))]
    if x is None:
        return [None]
    raise TypeError(f"no comparison for {type(x).__name__}")


def outcome(thunk: Callable[[], Any]) -> Tuple[Any, ...]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            res: Tuple[Any, ...] = ("returned", _leaves(thunk()))
        except pgloss.PglossError as e:
            res = ("raised", int(e.status), e.index, _leaves(e.status_array), _leaves(e.result), str(e))
    return res + (tuple((w.category.__name__, str(w.message)) for w in caught),)


def same_on_all_threads(thunk: Callable[[], Any]) -> Tuple[Any, ...]:
    """The call's outcome on one thread; asserts it is the same on every count of THREADS."""
    pgloss.set_num_threads(1)
    one = outcome(thunk)
    assert _core._last_threads() == 1
    split = False
    for n in THREADS:
        pgloss.set_num_threads(n)
        many = outcome(thunk)
        assert many == one, f"{n} threads differ from one thread"
        split = split or _core._last_threads() > 1
    assert split, "the call was not split"  # the inputs are long enough: else the test proves nothing
    return one


# ------------------------------------------------------------------------------------------------
# The shared vectors, tiled.

def tiled(values: List[Any], n: int) -> np.ndarray:
    a = np.asarray(values, dtype=np.float64)
    reps = -(-n // len(a))
    return np.concatenate([a] * reps)[:n]


def vector_inputs(file: str, function: str, names: List[str]) -> List[np.ndarray]:
    cases = [c for c in load(file)["cases"] if c.get("function") == function and
             all(k in c["input"] for k in names)]
    assert cases, (file, function)
    cols = [[num(c["input"][k]) if not isinstance(c["input"][k], list) else [num(v) for v in c["input"][k]]
             for c in cases] for k in names]
    return [tiled(col, N_PAINTS) for col in cols]


SCALAR_FUNCTIONS = [
    ("lightness.json", "lightness_from_luminance", ["Y"]),
    ("lightness.json", "luminance_from_lightness", ["L"]),
    ("gloss.json", "contrast_gloss", ["rho_d", "rho_s"]),
    ("gloss.json", "specular_from_contrast", ["rho_d", "c"]),
    ("gloss.json", "gloss_from_physical", ["rho_d", "rho_s", "alpha"]),
    ("gloss.json", "physical_from_gloss", ["L", "c", "d"]),
    ("gloss.json", "gloss_distance", ["c1", "d1", "c2", "d2"]),
    ("gloss.json", "envelope_contrast", ["L"]),
    ("gloss.json", "match_gloss", ["rho_d", "rho_s", "L_target"]),
]


@pytest.mark.parametrize("file,function,names", SCALAR_FUNCTIONS, ids=[f[1] for f in SCALAR_FUNCTIONS])
@pytest.mark.parametrize("errors", ["raise", "status"])
def test_vectors_element_wise(file: str, function: str, names: List[str], errors: str) -> None:
    args = vector_inputs(file, function, names)
    fn = getattr(pgloss, function)
    same_on_all_threads(lambda: fn(*args, errors=errors))
    # float32 input: the float32 results and their overflow check
    with np.errstate(over="ignore"):  # the vectors' huge values become inf, as a float32 user's would
        args32 = [a.astype(np.float32) for a in args]
    same_on_all_threads(lambda: fn(*args32, errors=errors))


@pytest.mark.parametrize("function", ["rgb_from_lab", "lab_from_rgb", "luminance"])
@pytest.mark.parametrize("space", list(pgloss.ColorSpace))
def test_vectors_colour(function: str, space: pgloss.ColorSpace) -> None:
    key = {"rgb_from_lab": "lab", "lab_from_rgb": "rgb", "luminance": "rgb"}[function]
    cases = [c for c in load("color.json")["cases"] if c["function"] == function]
    rows = np.array([[num(v) for v in c["input"][key]] for c in cases])
    x = np.concatenate([rows] * (-(-N_PAINTS // len(rows))))[:N_PAINTS]
    for errors in ("raise", "status"):
        same_on_all_threads(lambda: getattr(pgloss, function)(x, space, errors=errors))


def _physicals(ps: List[Dict[str, Any]]) -> pgloss.Physical:
    norm = int(ps[0]["normalization"])
    col = lambda f: tiled([num(p[f]) for p in ps], N_PAINTS)  # noqa: E731
    rho_d = np.stack([tiled([num(p["rho_d"][k]) for p in ps], N_PAINTS) for k in range(3)], axis=-1)
    return pgloss.Physical(rho_d, col("rho_s"), alpha_x=col("alpha_x"), alpha_y=col("alpha_y"), normalization=norm)


def _perceptuals(qs: List[Dict[str, Any]]) -> pgloss.Perceptual:
    return pgloss.Perceptual(*(tiled([num(q[f]) for q in qs], N_PAINTS) for f in "Labcd"))


def test_vectors_validity_and_conversions() -> None:
    val = load("validity.json")["cases"]
    pm = load("perceptual_material.json")["cases"]
    phys = [c["input"]["p"] for c in val if c["function"] == "check_physical"]
    phys += [c["input"]["p"] for c in pm if c["function"] == "perceptual_from_physical" and "p" in c["input"]]
    by_norm: Dict[int, List[Dict[str, Any]]] = {}
    for p in phys:
        by_norm.setdefault(int(p["normalization"]), []).append(p)
    percs = [c["input"]["q"] for c in val + pm if "q" in c["input"]]
    assert by_norm and percs
    q = _perceptuals(percs)
    for space in pgloss.ColorSpace:
        same_on_all_threads(lambda: pgloss.check_perceptual(q, space))
        for errors in ("raise", "status"):
            same_on_all_threads(lambda: pgloss.physical_from_perceptual(q, space=space, errors=errors))
            for norm in pgloss.Normalization:
                same_on_all_threads(lambda: pgloss.physical_from_perceptual(q, norm, space, errors=errors))
    for ps in by_norm.values():
        p = _physicals(ps)
        same_on_all_threads(lambda: pgloss.check_physical(p))
        for space in pgloss.ColorSpace:
            for errors in ("raise", "status"):
                same_on_all_threads(lambda: pgloss.perceptual_from_physical(p, space, errors=errors))


def _brdf_vectors(file: str) -> Tuple[dict, Dict[Tuple[str, int], List[dict]]]:
    doc = load(file)
    groups: Dict[Tuple[str, int], List[dict]] = {}
    for c in doc["cases"]:
        i = c["input"]
        if all(i.get(k) is not None for k in ("wo", "material")):
            groups.setdefault((i["material"], int(i["lobes"])), []).append(c)
    return doc, groups


def _physical_of(m: Dict[str, Any]) -> pgloss.Physical:
    return pgloss.Physical([num(x) for x in m["rho_d"]], num(m["rho_s"]), alpha_x=num(m["alpha_x"]),
                           alpha_y=num(m["alpha_y"]), normalization=int(m["normalization"]))


def _rows(cs: List[dict], key: str, n: int) -> np.ndarray:
    rows = np.array([[num(v) for v in c["input"][key]] for c in cs])
    return np.concatenate([rows] * (-(-n // len(rows))))[:n]


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_vectors_eval_one_material(dtype: str) -> None:
    doc, groups = _brdf_vectors("brdf_eval.json")
    n = 5 * CHUNK + 17
    for (mk, lobes), cs in groups.items():
        m = _physical_of(doc["materials"][mk])
        wo, wi = _rows(cs, "wo", n).astype(dtype), _rows(cs, "wi", n).astype(dtype)
        for fn in (pgloss.eval, pgloss.pdf, pgloss.eval_pdf):
            same_on_all_threads(lambda: fn(m, wo, wi, lobes))


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_vectors_eval_and_sample_per_element(dtype: str) -> None:
    """All the cases of one normalisation in one call, one material per pair."""
    for file in ("brdf_eval.json", "brdf_sample.json"):
        doc, groups = _brdf_vectors(file)
        by_norm: Dict[int, List[dict]] = {}
        for (mk, _), cs in groups.items():
            by_norm.setdefault(int(doc["materials"][mk]["normalization"]), []).extend(cs)
        for cs in by_norm.values():
            n = len(cs) if len(cs) > 2 * CHUNK else 3 * CHUNK + 1
            ms = [doc["materials"][c["input"]["material"]] for c in (cs * (n // len(cs) + 1))[:n]]
            mat = pgloss.Physical(np.array([[num(x) for x in m["rho_d"]] for m in ms]),
                                  np.array([num(m["rho_s"]) for m in ms]),
                                  alpha_x=np.array([num(m["alpha_x"]) for m in ms]),
                                  alpha_y=np.array([num(m["alpha_y"]) for m in ms]),
                                  normalization=int(ms[0]["normalization"]))
            wo = _rows(cs, "wo", n).astype(dtype)
            if file == "brdf_eval.json":
                wi = _rows(cs, "wi", n).astype(dtype)
                for fn in (pgloss.eval, pgloss.pdf, pgloss.eval_pdf):
                    same_on_all_threads(lambda: fn(mat, wo, wi))
            else:
                u = np.minimum(_rows(cs, "u", n), 1.0 - 2.0 ** -24).astype(dtype)
                same_on_all_threads(lambda: pgloss.sample(mat, wo, u))


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_vectors_sample_one_material(dtype: str) -> None:
    doc, groups = _brdf_vectors("brdf_sample.json")
    n = 5 * CHUNK + 17
    for (mk, lobes), cs in groups.items():
        m = _physical_of(doc["materials"][mk])
        wo = _rows(cs, "wo", n).astype(dtype)
        u = np.minimum(_rows(cs, "u", n), 1.0 - 2.0 ** -24).astype(dtype)
        same_on_all_threads(lambda: pgloss.sample(m, wo, u, lobes))


# ------------------------------------------------------------------------------------------------
# Random textures with failing elements planted at the start, the middle and the end.

PLANTS = {"none": [], "start": [0, 1], "middle": [None], "end": [-1], "start+middle+end": [0, None, -1]}


def planted(n: int, where: str) -> List[int]:
    return [n // 2 + 3 if k is None else k % n for k in PLANTS[where]]


@pytest.mark.parametrize("where", list(PLANTS))
@pytest.mark.parametrize("errors", ["raise", "status"])
def test_textures_element_wise(where: str, errors: str) -> None:
    rng = np.random.default_rng(18)
    n = N_PAINTS
    bad = planted(n, where)
    rd, rs = rng.uniform(0.0, 0.9, n), rng.uniform(0.0, 0.1, n)
    al = rng.uniform(0.02, 0.2, n)
    al[rng.integers(0, n, 50)] = 0.3  # AlphaUntrustedWarning
    # c under the envelope of L* <= 95 (0.066), so that the planted texels are the only errors
    L, c, d = rng.uniform(5.0, 95.0, n), rng.uniform(0.0, 0.06, n), rng.uniform(0.8, 0.99, n)
    rs[bad] = -0.1  # NEGATIVE
    L[bad] = 120.0  # LIGHTNESS
    calls = {
        "gloss_from_physical": lambda: pgloss.gloss_from_physical(rd, rs, al, errors=errors),
        "physical_from_gloss": lambda: pgloss.physical_from_gloss(L, c, d, errors=errors),
        "contrast_gloss": lambda: pgloss.contrast_gloss(rd, rs, errors=errors),
        "match_gloss": lambda: pgloss.match_gloss(rd, np.abs(rs), L, errors=errors),
        "envelope_contrast": lambda: pgloss.envelope_contrast(L, errors=errors),
        "lightness_from_luminance": lambda: pgloss.lightness_from_luminance(rs, errors=errors),
        "gloss_distance": lambda: pgloss.gloss_distance(c, d, rs, d, errors=errors),
    }
    for name, call in calls.items():
        res = same_on_all_threads(call)
        if bad and errors == "raise" and name in ("gloss_from_physical", "physical_from_gloss"):
            assert res[0] == "raised" and res[2] == (bad[0],), name  # the lowest failing index


@pytest.mark.parametrize("where", list(PLANTS))
def test_textures_conversions(where: str) -> None:
    rng = np.random.default_rng([18, 2])
    n = N_PAINTS
    bad = planted(n, where)
    q = [rng.uniform(40.0, 60.0, n), rng.uniform(-5.0, 5.0, n), rng.uniform(-5.0, 5.0, n),
         rng.uniform(0.0, 0.05, n), rng.uniform(0.85, 0.99, n)]  # inside the gamut but for the plants
    q[1][bad] = 180.0  # GAMUT
    q[4][rng.integers(0, n, 40)] = 0.7  # d < 0.8: AlphaUntrustedWarning
    tex = pgloss.Perceptual(*q)
    for errors in ("raise", "status"):
        res = same_on_all_threads(lambda: tex.to_physical(errors=errors))
        if errors == "raise":
            assert (res[0], res[2]) == (("raised", (bad[0],)) if bad else ("returned", res[2]))
    same_on_all_threads(lambda: tex.check())
    pgloss.set_num_threads(1)
    phys, _ = tex.to_physical(errors="status")
    rho_s = np.array(phys.rho_s)
    rho_s[bad] = -1.0
    phys = phys.replace(rho_s=rho_s)
    same_on_all_threads(lambda: phys.check())
    for errors in ("raise", "status"):
        same_on_all_threads(lambda: pgloss.perceptual_from_physical(phys, errors=errors))


def _directions(rng: np.random.Generator, n: int) -> np.ndarray:
    v = rng.normal(size=(n, 3))
    v[:, 2] = np.abs(v[:, 2]) + 0.05
    return v


@pytest.mark.parametrize("where", list(PLANTS))
@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize("per_element", [False, True], ids=["one-material", "per-element"])
def test_textures_brdf(where: str, dtype: str, per_element: bool) -> None:
    rng = np.random.default_rng([18, 3])
    n = N_PAIRS
    bad = planted(n, where)
    wo, wi = _directions(rng, n), _directions(rng, n)
    u = rng.random((n, 3))
    if per_element:
        rs = rng.uniform(0.0, 0.1, n)
        rs[bad] = -0.5  # NEGATIVE, element by element
        mat = pgloss.Physical(rng.uniform(0.0, 0.8, (n, 3)), rs, alpha_x=rng.uniform(0.03, 0.2, n),
                              alpha_y=rng.uniform(0.03, 0.2, n))
    else:
        mat = pgloss.Physical((0.5, 0.3, 0.1), 0.05, 0.1)
        wi[bad] = 0.0  # DIRECTION
        wo[[k for k in bad[1:]]] = np.nan  # DIRECTION, not the first
    wo, wi, u = wo.astype(dtype), wi.astype(dtype), u.astype(dtype)
    for fn in (pgloss.eval, pgloss.pdf, pgloss.eval_pdf):
        res = same_on_all_threads(lambda: fn(mat, wo, wi))
        if bad:
            assert res[0] == "raised" and res[2] == (bad[0],)
    res = same_on_all_threads(lambda: pgloss.sample(mat, wo if per_element else np.where(wi == 0, 0, wo), u))
    if bad:
        assert res[0] == "raised" and res[2] == (bad[0],)
    # out=: the caller's arrays, written the same
    f = np.empty((n, 3), dtype)
    if not bad:
        same_on_all_threads(lambda: pgloss.eval(mat, wo, wi, out=f))


def test_first_call_on_a_texture() -> None:
    """The first float32 call on a texture (its parameters rounded to float once, then kept) on many threads."""
    rng = np.random.default_rng([18, 4])
    n = 3 * SLICE + 5
    fields = (rng.uniform(0.0, 0.8, (n, 3)), rng.uniform(0.0, 0.1, n), rng.uniform(0.03, 0.2, n))
    wo, wi = _directions(rng, n).astype(np.float32), _directions(rng, n).astype(np.float32)
    fields[1][[0, n // 2, n - 1]] = 1e300  # beyond float: NONFINITE once rounded
    same_on_all_threads(lambda: pgloss.eval(pgloss.Physical(*fields), wo, wi))


def test_short_arrays_stay_on_the_calling_thread() -> None:
    """With the measured threshold: under 2 × MIN_ELEMENTS_PER_THREAD elements one thread, from
    there on several (the scalar element-wise functions count 4 × an element)."""
    _core._set_min_elements_per_thread(pgloss.MIN_ELEMENTS_PER_THREAD)
    pgloss.set_num_threads(7)
    k = pgloss.MIN_ELEMENTS_PER_THREAD
    pgloss.gloss_from_physical(np.full(2 * k - 1, 0.5), 0.05, 0.1)
    assert _core._last_threads() == 1
    pgloss.gloss_from_physical(np.full(2 * k, 0.5), 0.05, 0.1)
    assert _core._last_threads() == 2
    pgloss.contrast_gloss(np.full(k // 2, 0.5), 0.05)
    assert _core._last_threads() == 2
    pgloss.eval(pgloss.Physical(0.5, 0.05, 0.1), np.tile([0.0, 0.0, 1.0], (2 * k - 1, 1)), [0.0, 0.3, 1.0])
    assert _core._last_threads() == 1


def test_ranges_cover_every_unit_once_and_carry_exceptions() -> None:
    """parallel.h alone: every unit runs once, the results merge in index order, and an
    exception thrown in any thread (first, middle or last unit) reaches the caller."""
    for n in (1, 2, 3, 7, 16):
        pgloss.set_num_threads(n)
        for units in (1, 2, 5, 113, 1000):
            assert _core._test_ranges(units, -1) == list(range(units))
            for k in {0, units // 2, units - 1}:
                with pytest.raises(RuntimeError, match=f"unit {k}$"):
                    _core._test_ranges(units, k)
        assert pgloss.get_num_threads() == n


# ------------------------------------------------------------------------------------------------
# The setting.

def test_setting() -> None:
    cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    pgloss.set_num_threads(3)
    assert pgloss.get_num_threads() == 3
    assert pgloss.set_num_threads(np.int64(5)) == 3 and pgloss.get_num_threads() == 5
    assert pgloss.set_num_threads(None) == 5 and pgloss.get_num_threads() == cpus
    pgloss.set_num_threads(pgloss.MAX_THREADS)
    for bad, exc in ((0, ValueError), (-2, ValueError), (pgloss.MAX_THREADS + 1, ValueError), (2.0, TypeError),
                     ("4", TypeError), (True, TypeError), (np.bool_(True), TypeError)):
        with pytest.raises(exc, match="pgloss.set_num_threads: the thread count"):
            pgloss.set_num_threads(bad)
        assert pgloss.get_num_threads() == pgloss.MAX_THREADS  # unchanged
    with pytest.raises(ValueError):
        _core.set_num_threads(0)


def _import_with(value: str) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    if value is None:
        env.pop("PGLOSS_NUM_THREADS", None)
    else:
        env["PGLOSS_NUM_THREADS"] = value
    code = ("import json, os, pgloss; print(json.dumps([pgloss.get_num_threads(), "
            "len(os.sched_getaffinity(0))]))")
    return subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, cwd="/")


@pytest.mark.skipif(not hasattr(os, "sched_getaffinity"), reason="no os.sched_getaffinity on this platform")
def test_environment_variable() -> None:
    for value, want in (("1", 1), ("7", 7), (" 3 ", 3), ("", None), (None, None)):
        r = _import_with(value)
        assert r.returncode == 0, r.stderr
        got, cpus = json.loads(r.stdout)
        assert got == (cpus if want is None else want), value
    for value in ("0", "-1", "two", "2.5", str(pgloss.MAX_THREADS + 1)):
        r = _import_with(value)
        assert r.returncode != 0
        assert "PGLOSS_NUM_THREADS" in r.stderr and "ValueError" in r.stderr, r.stderr


def test_default_is_the_affinity_mask() -> None:
    """Under a narrower affinity mask (taskset) the default follows it."""
    if not hasattr(os, "sched_setaffinity") or len(os.sched_getaffinity(0)) < 2:
        pytest.skip("needs sched_setaffinity and two CPUs to narrow the mask")
    cpu = min(os.sched_getaffinity(0))
    code = (f"import os; os.sched_setaffinity(0, {{{cpu}}}); import pgloss; print(pgloss.get_num_threads())")
    env = {k: v for k, v in os.environ.items() if k != "PGLOSS_NUM_THREADS"}
    r = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, cwd="/")
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "1"


def test_interrupt_stops_a_threaded_call() -> None:
    """Ctrl-C (SIGINT) during a long threaded call raises KeyboardInterrupt promptly."""
    code = r"""
import os, signal, threading, time
import numpy as np, pgloss
# Python installs its Ctrl-C handler only where SIGINT is not ignored, and a CI job started in
# the background (`cmd &` in a script) inherits SIGINT ignored: install it, as test_arrays.py does.
signal.signal(signal.SIGINT, signal.default_int_handler)
pgloss.set_num_threads(3)
n = 1 << 24
rd = np.full(n, 0.5); rs = np.full(n, 0.05)
t0 = time.perf_counter(); pgloss.contrast_gloss(rd[: n // 16], rs[: n // 16]); one = (time.perf_counter() - t0) * 16
threading.Timer(0.05, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
t0 = time.perf_counter()
try:
    for _ in range(20):
        pgloss.contrast_gloss(rd, rs)
    print("not interrupted")
except KeyboardInterrupt:
    took = time.perf_counter() - t0
    print("interrupted", took < max(0.5 * one, 0.3), round(took, 3), round(one, 3))
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd="/", timeout=300)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("interrupted True"), r.stdout


def test_benchmarks_run() -> None:
    """The benchmarks are programs, not timed tests: only check that they run and print the
    single-thread and threaded rows."""
    bench = Path(__file__).resolve().parents[2] / "bindings" / "python" / "bench"
    r = subprocess.run([sys.executable, str(bench / "bench_textures.py"), "--size", "128", "--repeat", "1",
                        "--threads", "3"], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "| gloss_from_physical, 16,384 paints | gloss_from_physical (L, c, d + statuses, check=False) |" in r.stdout
    assert "| gloss_from_physical, 16,384 paints | on 3 threads |" in r.stdout
    r = subprocess.run([sys.executable, str(bench / "bench_calls.py"), "--n", "4096", "--repeat", "1"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "| eval, one material per pair, float64 |" in r.stdout
    r = subprocess.run([sys.executable, str(bench / "bench_threads.py"), "--repeat", "1", "--threads", "2"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "| eval float32, one material |" in r.stdout
