"""Loading and checking the shared test vectors (tests/vectors/*.json) from Python.

The logic is that of the C runner tests/test_vectors.cpp and of tests/vectors/README.md:

    |got - want| <= abs + rel * |want| + kappa_rel * sens

with (rel, kappa_rel, abs) from the file's tolerance table for the file's ``c_precision``
(the Python package computes in the core's precision: double for the perceptual and colour
functions, float for the BRDF), and ``sens`` from the case. A missing file or field is a
failure, never a skip. The largest errors are collected in STATS and printed by conftest.py.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Dict, List, Optional

VECTORS_DIR = Path(__file__).resolve().parents[1] / "vectors"

FILES = ["lightness.json", "gloss.json", "color.json", "validity.json", "perceptual_material.json",
         "material.json", "brdf_eval.json", "brdf_sample.json"]

_cache: Dict[str, dict] = {}


def load(name: str) -> dict:
    """The parsed file (cached); raises (a failure) if absent or malformed."""
    if name not in _cache:
        path = VECTORS_DIR / name
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
        assert doc.get("format") == "pgloss-vectors" and doc.get("version") == 1, f"{path}: not a pgloss-vectors v1 file"
        assert isinstance(doc.get("cases"), list) and doc["cases"], f"{path}: no cases"
        _cache[name] = doc
    return _cache[name]


def num(v: Any) -> float:
    """JSON number, or "nan" / "inf" / "-inf"."""
    if isinstance(v, str):
        return {"nan": math.nan, "inf": math.inf, "-inf": -math.inf}[v]
    return float(v)


def cases(name: str, function: Optional[str] = None) -> List[dict]:
    doc = load(name)
    out = [c for c in doc["cases"] if function is None or c.get("function") == function]
    assert out, f"no cases for {function} in {name}"
    return out


def has_tag(c: dict, tag: str) -> bool:
    return tag in c.get("tags", [])


def is_null_case(c: dict) -> bool:
    """Cases that pass a NULL pointer: not expressible in Python (README: ports without
    pointers skip the cases tagged null_pointer). They are counted, not silently dropped."""
    return "null" in c["input"]


@dataclass
class Tol:
    rel: float
    kappa_rel: float
    abs: float


def tolerance(doc: dict, fn: str, out: str) -> Tol:
    t = doc["tolerance"][fn][out][doc["c_precision"]]
    return Tol(float(t["rel"]), float(t["kappa_rel"]), float(t["abs"]))


def sens_at(c: dict, out: str, k: int = -1) -> float:
    s = c.get("sens", {}).get(out)
    if s is None:
        return 0.0
    if k < 0:
        return 0.0 if s is None else float(s)
    v = s[k]
    return 0.0 if v is None else float(v)


@dataclass
class Stat:
    checks: int = 0
    regular: int = 0
    sanity_only: int = 0
    max_rel: float = 0.0
    max_ratio: float = 0.0
    worst_rel_id: str = ""
    worst_ratio_id: str = ""


STATS: Dict[str, Stat] = {}
SKIPPED_NULL: Dict[str, int] = {}


class Checker:
    """Collects failures of one test; ``finish()`` asserts there were none."""

    def __init__(self) -> None:
        self.failures: List[str] = []

    def fail(self, msg: str) -> None:
        self.failures.append(msg)

    def value(self, fn: str, out: str, c: dict, got: float, want: Any, sens: float, tol: Optional[Tol],
              sanity_only: bool = False, nonneg: bool = False) -> None:
        key = f"{fn} {out}"
        st = STATS.setdefault(key, Stat())
        cid = c.get("id", "?")
        got = float(got)
        if not math.isfinite(got):
            self.fail(f"{cid} {key}: output not finite: {got}")
            return
        if want is None:
            return
        w = num(want)
        if sanity_only:
            st.sanity_only += 1
            if nonneg and got < 0:
                self.fail(f"{cid} {key}: negative {got!r}")
            return
        assert tol is not None
        st.checks += 1
        err = abs(got - w)
        bound = tol.abs + tol.rel * abs(w) + tol.kappa_rel * sens
        rel = err / abs(w) if w != 0 else 0.0
        ratio = err / bound if bound > 0 else (0.0 if err == 0 else math.inf)
        if abs(w) >= 1e-30 and sens <= 10 * abs(w):
            st.regular += 1
            if rel > st.max_rel or not st.worst_rel_id:
                st.max_rel = max(st.max_rel, rel)
                st.worst_rel_id = cid
        if ratio > st.max_ratio or not st.worst_ratio_id:
            st.max_ratio = max(st.max_ratio, ratio)
            st.worst_ratio_id = cid
        if not err <= bound:
            self.fail(f"{cid} {key}: got {got!r} want {w!r} |err| {err!r} > tol {bound!r} (sens {sens}) "
                      f"tags {c.get('tags')}")

    def status(self, fn: str, c: dict, got_name: str) -> None:
        want = c["status"]
        if want != got_name:
            self.fail(f"{c.get('id')} {fn}: status {got_name}, want {want}; input {c['input']}")

    def finish(self, what: str) -> None:
        if self.failures:
            shown = "\n  ".join(self.failures[:40])
            more = f"\n  ... and {len(self.failures) - 40} more" if len(self.failures) > 40 else ""
            raise AssertionError(f"{what}: {len(self.failures)} failures\n  {shown}{more}")


def summary_lines() -> List[str]:
    lines = ["pgloss vectors (Python): largest error per function and output",
             "regular: |want| >= 1e-30 and sens/|want| <= 10; sanity: float-ill-conditioned, finiteness/sign only",
             f"{'function output':<44} {'checks':>7} {'regular':>7} {'sanity':>6} {'max relerr':>11} {'(case)':>8} "
             f"{'max e/tol':>9} {'(case)':>8}"]
    for key in sorted(STATS):
        s = STATS[key]
        lines.append(f"{key:<44} {s.checks:>7} {s.regular:>7} {s.sanity_only:>6} {s.max_rel:>11.3e} "
                     f"{s.worst_rel_id:>8} {s.max_ratio:>9.3g} {s.worst_ratio_id:>8}")
    if SKIPPED_NULL:
        lines.append("NULL-pointer cases (not expressible in Python, per tests/vectors/README.md): " +
                     ", ".join(f"{k} {v}" for k, v in sorted(SKIPPED_NULL.items())))
    return lines
