# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The shared test vectors (tests/vectors/*.json) for the Python-driven test layers.

One module for the three layers that judge the vectors from Python — tests/python (the
pybind11 package), tests/glsl (glsl/pgloss.glsl in a compute or fragment shader) and tests/osl
(osl/pgloss.h in Cycles): loading and iterating the cases, the tolerance model of
tests/vectors/README.md and the report (failures, error statistics, summary). A layer keeps
only what is its own: how it runs its implementation on the cases, and the float-precision
allowances it documents (named there, e.g. the GLSL built-in exp's ULP term).

The logic is that of the C runner tests/test_vectors.cpp. For every checked number (each
component of a vector):

    |got - want| <= abs + (rel + extra_rel) * |want| + kappa_rel * sens

with (rel, kappa_rel, abs) from the file's ``tolerance[function][output][precision]`` — the
file's ``c_precision`` for an implementation with the C core's precision (the Python
package), ``"float"`` for a float32 port (GLSL, OSL) — ``sens`` from the case (0 if absent),
and ``extra_rel`` 0 unless a layer names an allowance of its own. A ``null`` expected value
is checked for finiteness only; a case tagged ``ill_conditioned`` is checked, in float
precision, for finiteness and sign only; cases that pass a NULL pointer (tag
``null_pointer``) are not expressible without pointers and are counted as skipped, never
dropped silently. A missing file or field is a failure, never a skip.

Standard library only: it is imported by three venvs (numpy 2 in .venv-py and .venv-glsl,
CPython 3.11 with numpy < 2 in .venv-bpy). Numbers the layers pass in may be Python or numpy
scalars and sequences.
"""

from __future__ import annotations

import json
import math
import struct
from collections import OrderedDict
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple

VECTORS_DIR = Path(__file__).resolve().parent

# Every file, and the functions each must cover (the C runner's FilesPresentAndCovered).
FUNCTIONS: "OrderedDict[str, List[str]]" = OrderedDict([
    ("lightness.json", ["lightness_from_luminance", "luminance_from_lightness"]),
    ("gloss.json", ["contrast_gloss", "specular_from_contrast", "gloss_from_physical", "physical_from_gloss",
                    "gloss_distance", "envelope_contrast", "match_gloss", "isogloss_contour"]),
    ("color.json", ["rgb_from_lab", "lab_from_rgb", "luminance"]),
    ("validity.json", ["check_physical", "check_perceptual"]),
    ("perceptual_material.json", ["physical_from_perceptual", "perceptual_from_physical"]),
    ("color_space.json", ["rgb_from_lab_ex", "lab_from_rgb_ex", "luminance_ex", "check_perceptual_ex",
                          "physical_from_perceptual_ex", "perceptual_from_physical_ex"]),
    ("material.json", ["material_init", "specular_probability"]),
    ("brdf_eval.json", ["eval", "pdf", "eval_pdf", "eval_batch", "pdf_batch", "eval_pdf_batch"]),
    ("brdf_sample.json", ["sample", "sample_batch"]),
])
FILES: List[str] = list(FUNCTIONS)

# The cases of brdf_*.json name no function: each is run through several (eval, pdf,
# eval_pdf / sample and their batched forms). These labels name them as one.
BRDF_EVAL = "brdf_eval"
BRDF_SAMPLE = "brdf_sample"

# pgloss/status.h and pgloss/brdf.h.
STATUS: Dict[str, int] = {
    "PGLOSS_OK": 0, "PGLOSS_WARN_ALPHA_UNTRUSTED": 1, "PGLOSS_ERR_NULL": -1,
    "PGLOSS_ERR_NONFINITE": -2, "PGLOSS_ERR_NEGATIVE": -3, "PGLOSS_ERR_ALPHA": -4,
    "PGLOSS_ERR_ENERGY": -5, "PGLOSS_ERR_ENVELOPE": -6, "PGLOSS_ERR_LIGHTNESS": -7,
    "PGLOSS_ERR_GAMUT": -8, "PGLOSS_ERR_DIRECTION": -9, "PGLOSS_ERR_NORMALIZATION": -10,
    "PGLOSS_ERR_ARGUMENT": -11, "PGLOSS_ERR_RANDOM": -12,
}
STATUS_NAME: Dict[int, str] = {v: k for k, v in STATUS.items()}
LOBE: Dict[str, int] = {"PGLOSS_LOBE_NONE": 0, "PGLOSS_LOBE_DIFFUSE": 1, "PGLOSS_LOBE_SPECULAR": 2}

# Functions whose only output is their status (validity.json).
STATUS_ONLY = ("check_physical", "check_perceptual")

# float32 (IEEE binary32) facts, without numpy.
FLT_MAX = 3.4028234663852886e38
FLT_MIN = 2.0 ** -126  # smallest normal
ULP = 2.0 ** -24  # unit roundoff u of float32

# The "regular range" of the statistics: |want| >= REGULAR_MIN_ABS and sens <= REGULAR_KAPPA |want|.
REGULAR_MIN_ABS = 1e-30
REGULAR_KAPPA = 10.0
# |wi| of a non-rejected sample must be 1 within this (the C runner's EXPECT_NEAR).
UNIT_LENGTH_TOL = 1e-5


# ------------------------------------------------------------------------------------------
# Numbers


def num(v: Any) -> float:
    """A JSON number, or one of the strings "nan", "inf", "-inf" (non-finite inputs)."""
    if isinstance(v, str):
        return {"nan": math.nan, "inf": math.inf, "-inf": -math.inf}[v]
    return float(v)


def f32(x: float) -> float:
    """x rounded to float32 (round to nearest even), as a Python float; ±inf past FLT_MAX."""
    try:
        return struct.unpack("<f", struct.pack("<f", x))[0]
    except OverflowError:
        return math.copysign(math.inf, x)


def status_name(code: Any) -> str:
    """The enumerator name of a status code (the code itself, as text, if it is none)."""
    return STATUS_NAME.get(int(code), str(int(code)))


# ------------------------------------------------------------------------------------------
# Loading and iterating


class VectorsError(AssertionError):
    """A vector file is missing or malformed (a test failure, never a skip)."""


_cache: Dict[str, dict] = {}


def load(name: str) -> dict:
    """The parsed file (cached); raises VectorsError if it is absent or malformed."""
    if name not in _cache:
        path = VECTORS_DIR / name
        try:
            with open(path, encoding="utf-8") as fh:
                doc = json.load(fh)
        except (OSError, ValueError) as e:
            raise VectorsError(f"cannot read {path}: {e}") from e
        if not (isinstance(doc, dict) and doc.get("format") == "pgloss-vectors" and doc.get("version") == 1
                and isinstance(doc.get("cases"), list) and doc["cases"] and "tolerance" in doc
                and "c_precision" in doc):
            raise VectorsError(f"{path}: not a pgloss-vectors version 1 file with cases, tolerance and c_precision")
        _cache[name] = doc
    return _cache[name]


def case_function(file: str, c: dict) -> str:
    """The function a case is run through: its "function", or BRDF_EVAL / BRDF_SAMPLE."""
    if file == "brdf_eval.json":
        return BRDF_EVAL
    if file == "brdf_sample.json":
        return BRDF_SAMPLE
    return c["function"]


def has_tag(c: dict, tag: str) -> bool:
    return tag in c.get("tags", [])


def is_null_case(c: dict) -> bool:
    """A case that passes a NULL pointer (input "null", tag null_pointer): the README lets
    ports without pointers skip it; the report counts it (Report.skip_null)."""
    return "null" in c["input"] or has_tag(c, "null_pointer")


def cases(name: str, function: Optional[str] = None) -> List[dict]:
    """Every case of a file, or those of one function; raises VectorsError if there is none."""
    doc = load(name)
    out = [c for c in doc["cases"] if function is None or case_function(name, c) == function]
    if not out:
        raise VectorsError(f"no cases for {function} in {name}")
    return out


def runnable(name: str, report: "Report", function: Optional[str] = None) -> Iterator[Tuple[str, dict]]:
    """(function, case) for every case of a file (or of one function) that a port without
    pointers can run; null_pointer cases are counted on the report as skipped."""
    for c in cases(name, function):
        fn = case_function(name, c)
        if is_null_case(c):
            report.skip_null(fn)
            continue
        yield fn, c


def check_coverage(report: "Report") -> None:
    """The C runner's FilesPresentAndCovered: every file lists the functions it must cover,
    every case names a function of its file, and case ids are unique."""
    for name, want in FUNCTIONS.items():
        try:
            doc = load(name)
        except VectorsError as e:
            report.fail(str(e))
            continue
        fns = doc.get("functions", [])
        for fn in want:
            if fn not in fns:
                report.fail(f"{name} lacks {fn}")
        seen: Dict[str, int] = {}
        for c in doc["cases"]:
            cid = c.get("id", "?")
            seen[cid] = seen.get(cid, 0) + 1
            if seen[cid] == 2:
                report.fail(f"{name}: duplicate id {cid}")
            if "function" in c and c["function"] not in fns:
                report.fail(f"{cid}: unknown function {c['function']}")


def groups_of(doc: dict) -> "OrderedDict[Tuple[str, int], List[dict]]":
    """brdf_*.json cases without NULL pointers grouped by (material, lobes), in file order:
    the calls of the batched functions."""
    g: "OrderedDict[Tuple[str, int], List[dict]]" = OrderedDict()
    for c in doc["cases"]:
        if is_null_case(c):
            continue
        g.setdefault((c["input"]["material"], int(c["input"]["lobes"])), []).append(c)
    return g


def first_error(cs: Sequence[dict]) -> Tuple[str, int]:
    """The status a batched call over the group must return (its first non-OK status) and the
    index of that case; ("PGLOSS_OK", -1) if there is none."""
    for k, c in enumerate(cs):
        if c["status"] != "PGLOSS_OK":
            return c["status"], k
    return "PGLOSS_OK", -1


# ------------------------------------------------------------------------------------------
# Tolerance model


@dataclass(frozen=True)
class Tol:
    rel: float
    kappa_rel: float
    abs: float


def precision_of(doc: dict, precision: Optional[str]) -> str:
    """The tolerance column: `precision` if given ("float" for a float32 port), else the
    file's c_precision."""
    p = precision if precision is not None else doc["c_precision"]
    if p not in ("float", "double"):
        raise VectorsError(f"unknown precision {p!r}")
    return p


def tolerance(doc: dict, fn: str, out: str, precision: Optional[str] = None) -> Tol:
    t = doc["tolerance"][fn][out][precision_of(doc, precision)]
    return Tol(float(t["rel"]), float(t["kappa_rel"]), float(t["abs"]))


def sens_at(c: dict, out: str, k: int = -1) -> float:
    """The case's sensitivity of output `out` (component k of a vector output), 0 if absent."""
    s = c.get("sens", {}).get(out)
    if s is not None and k >= 0:
        s = s[k]
    return 0.0 if s is None else float(s)


def sanity_only(doc: dict, c: dict, precision: Optional[str] = None) -> bool:
    """README: a float-ill-conditioned case is only checked for finiteness and sign in float."""
    return has_tag(c, "ill_conditioned") and precision_of(doc, precision) == "float"


def bound(tol: Tol, want: float, sens: float, extra_rel: float = 0.0) -> float:
    """The allowed |got - want|."""
    return tol.abs + (tol.rel + extra_rel) * abs(want) + tol.kappa_rel * sens


def _is_seq(x: Any) -> bool:
    return hasattr(x, "__len__") and not isinstance(x, (str, bytes, dict))


# ------------------------------------------------------------------------------------------
# Report


@dataclass
class Stat:
    """Per "function output": values compared against the tolerance (checks), of which in
    the regular range (regular), checked for finiteness/sign only (sanity), and the largest
    relative error (regular range) and err/tol, with the cases they occur in. Exact checks
    (status-only functions, lobes, normalization) count as checks with no error."""
    checks: int = 0
    regular: int = 0
    sanity: int = 0
    max_rel: float = 0.0
    max_ratio: float = 0.0
    worst_rel: str = ""
    worst_ratio: str = ""


@dataclass
class Report:
    """Failures and statistics of one run. ``child()`` gives a report with its own failures
    that adds to this one's statistics and counts (one pytest test of a session)."""
    stats: Dict[str, Stat] = field(default_factory=dict)
    failures: List[str] = field(default_factory=list)
    cases: Dict[str, int] = field(default_factory=dict)  # cases run, per function
    skipped_null: Dict[str, int] = field(default_factory=dict)  # null_pointer cases, per function
    waived: Dict[str, List[str]] = field(default_factory=dict)  # why -> case ids (layer allowances)
    notes: List[str] = field(default_factory=list)

    def child(self) -> "Report":
        return Report(self.stats, [], self.cases, self.skipped_null, self.waived, self.notes)

    # -- bookkeeping

    def fail(self, msg: str) -> None:
        self.failures.append(msg)

    def waive(self, why: str, cid: str) -> None:
        """A documented allowance of the layer applied to a case (listed in the summary)."""
        self.waived.setdefault(why, []).append(cid)

    def ran(self, fn: str, n: int = 1) -> None:
        self.cases[fn] = self.cases.get(fn, 0) + n

    def skip_null(self, fn: str) -> None:
        self.skipped_null[fn] = self.skipped_null.get(fn, 0) + 1

    def stat(self, key: str) -> Stat:
        return self.stats.setdefault(key, Stat())

    @property
    def n_cases(self) -> int:
        return sum(self.cases.values())

    @property
    def n_checks(self) -> int:
        return sum(s.checks for s in self.stats.values())

    # -- checks

    def value(self, key: str, c: dict, got: Any, want: Any, sens: float, tol: Optional[Tol],
              extra_rel: float = 0.0, sanity: bool = False, nonneg: bool = False) -> None:
        """One number. want None: finiteness only (the header leaves it unspecified).
        sanity: float-ill-conditioned case: finite, and >= 0 for a non-negative quantity."""
        st = self.stat(key)
        cid = c.get("id", "?")
        got = float(got)
        if not math.isfinite(got):
            self.fail(f"{cid} {key}: output not finite: {got}")
            return
        if want is None:
            return
        w = num(want)
        if sanity:
            st.sanity += 1
            if nonneg and got < 0:
                self.fail(f"{cid} {key}: negative {got!r}")
            return
        if tol is None:
            raise VectorsError(f"{cid} {key}: no tolerance")
        st.checks += 1
        err = abs(got - w)
        lim = bound(tol, w, sens, extra_rel)
        rel = err / abs(w) if w != 0 else 0.0
        ratio = err / lim if lim > 0 else (0.0 if err == 0 else math.inf)
        if abs(w) >= REGULAR_MIN_ABS and sens <= REGULAR_KAPPA * abs(w):
            st.regular += 1
            if rel > st.max_rel or not st.worst_rel:
                st.max_rel = max(st.max_rel, rel)
                st.worst_rel = cid
        if ratio > st.max_ratio or not st.worst_ratio:
            st.max_ratio = max(st.max_ratio, ratio)
            st.worst_ratio = cid
        if not err <= lim:
            self.fail(f"{cid} {key}: got {got!r} want {w!r} |err| {err:.3g} > tol {lim:.3g} (sens {sens}) "
                      f"tags {c.get('tags')}")

    def exact(self, key: str, c: dict, got: Any, want: Any) -> None:
        """An integer output (lobe, lobes, normalization) that must be exactly `want`."""
        self.stat(key).checks += 1
        if int(got) != int(want):
            self.fail(f"{c.get('id', '?')} {key}: {int(got)} want {want}")

    def status(self, fn: str, c: dict, got: str) -> bool:
        """The status (enumerator name) against the case's; True if it agrees."""
        if got == c["status"]:
            return True
        self.fail(f"{c.get('id', '?')} {fn}: status {got}, want {c['status']}; input {json.dumps(c['input'])}")
        return False

    def outputs(self, doc: dict, fn: str, c: dict, got: Mapping[str, Any], precision: Optional[str] = None,
                values: bool = True) -> None:
        """Every expected output of a double-API function (lightness, gloss, colour,
        perceptual/physical, specular_probability) from `got` (output name -> number or
        sequence). values=False (a layer's documented allowance: its input is a different
        number, or its status legitimately differs): floats are checked for finiteness only;
        an integer output (normalization) is exact either way."""
        if fn in STATUS_ONLY:
            self.stat(f"{fn} status").checks += 1
            return
        if fn == "material_init":
            raise VectorsError("material_init: use Report.material_init")
        cid = c.get("id", "?")
        for out, want in c["expected"].items():
            if out not in got:
                self.fail(f"{cid} {fn}: no output {out}")
                continue
            g = got[out]
            key = f"{fn} {out}"
            if out == "normalization":  # an integer, exact
                if want is not None:
                    self.exact(key, c, g, want)
                continue
            if not values:
                want = None
            tol = tolerance(doc, fn, out, precision) if want is not None else None
            if _is_seq(g) or isinstance(want, list):
                g = list(g) if _is_seq(g) else [g]
                if want is not None and len(g) != len(want):
                    self.fail(f"{cid} {key}: {len(g)} values, want {len(want)}")
                    continue
                for k in range(len(g)):
                    self.value(key, c, g[k], None if want is None else want[k], sens_at(c, out, k), tol)
            else:
                self.value(key, c, g, want, sens_at(c, out), tol)

    def material_init(self, doc: dict, c: dict, got_status: str, got: Mapping[str, Any],
                      precision: Optional[str] = None, values: bool = True) -> None:
        """material.json's material_init: `got` has lobes, normalization, black (eval at
        normal incidence is 0) and the stored fields. On error only lobes == 0 is specified,
        and the material must be black; on success every stored field is compared."""
        fn = "material_init"
        e = c["expected"]
        if "lobes" not in e:  # a NULL-pointer case: status only
            return
        if not values:
            for out in e:
                if out != "lobes":
                    g = got[out]
                    for x in (list(g) if _is_seq(g) else [g]):
                        self.value(f"{fn} {out}", c, x, None, 0.0, None)
            return
        self.exact(f"{fn} lobes", c, got["lobes"], e["lobes"])
        if got_status != "PGLOSS_OK":
            if not got["black"]:
                self.fail(f"{c.get('id', '?')} {fn}: a failed init must give a black material")
            return
        for out, want in e.items():
            if out == "lobes":
                continue
            g = got[out]
            tol = tolerance(doc, fn, out, precision)
            if isinstance(want, list):
                for k in range(len(want)):
                    self.value(f"{fn} {out}", c, g[k], want[k], sens_at(c, out, k), tol)
            else:
                self.value(f"{fn} {out}", c, g, want, sens_at(c, out), tol)
        self.exact(f"{fn} normalization", c, got["normalization"], c["input"]["p"]["normalization"])

    def brdf_eval(self, doc: dict, fn: str, c: dict, f: Optional[Sequence[Any]] = None, pdf: Any = None,
                  precision: Optional[str] = None, tol_fn: Optional[str] = None, extra_rel: float = 0.0) -> None:
        """brdf_eval.json: the rgb value f and/or the pdf that function `fn` (eval, pdf,
        eval_pdf, a batched or array form, named as the statistics should show it) returned for
        case c, with the tolerance of tol_fn (default fn). extra_rel: a layer's allowance for
        the outputs that go through eq. 2's exponential."""
        tf = tol_fn or fn
        e = c["expected"]
        s = sanity_only(doc, c, precision)
        if f is not None:
            t = tolerance(doc, tf, "f", precision)
            for k in range(3):
                self.value(f"{fn} f", c, f[k], e["f"][k], sens_at(c, "f", k), t, extra_rel, s, True)
        if pdf is not None:
            self.value(f"{fn} pdf", c, pdf, e["pdf"], sens_at(c, "pdf"), tolerance(doc, tf, "pdf", precision),
                       extra_rel, s, True)

    def sample(self, doc: dict, fn: str, c: dict, wi: Sequence[Any], pdf: Any, weight: Sequence[Any], lobe: Any,
               precision: Optional[str] = None, extra_rel: float = 0.0) -> None:
        """brdf_sample.json: one sample record (wi, pdf, weight, lobe) that function `fn`
        returned for case c. A rejected sample (expected pdf 0) must have pdf and weight
        exactly 0; an accepted one a unit wi. extra_rel: a layer's allowance for the outputs
        that go through eq. 2's exponential (pdf and weight)."""
        e = c["expected"]
        cid = c.get("id", "?")
        s = sanity_only(doc, c, precision)
        twi, tpdf, tw = (tolerance(doc, "sample", out, precision) for out in ("wi", "pdf", "weight"))
        for k in range(3):
            self.value(f"{fn} wi", c, wi[k], None if e["wi"] is None else e["wi"][k], sens_at(c, "wi", k), twi, 0.0, s)
            self.value(f"{fn} weight", c, weight[k], e["weight"][k], sens_at(c, "weight", k), tw, extra_rel, s, True)
        self.value(f"{fn} pdf", c, pdf, e["pdf"], sens_at(c, "pdf"), tpdf, extra_rel, s, True)
        if e["lobe"] is not None:
            self.exact(f"{fn} lobe", c, lobe, LOBE[e["lobe"]])
        if e["pdf"] is not None and num(e["pdf"]) == 0:
            if float(pdf) != 0 or any(float(w) != 0 for w in weight):
                self.fail(f"{cid} {fn}: rejected sample must have pdf and weight exactly 0")
        elif e["wi"] is not None:
            if abs(math.sqrt(sum(float(x) ** 2 for x in wi)) - 1.0) > UNIT_LENGTH_TOL:
                self.fail(f"{cid} {fn}: wi not unit length")

    # -- output

    def summary_lines(self, title: str, full: bool = True) -> List[str]:
        """The summary every layer prints: per function and output the checks and the largest
        errors, then the cases run per function, the skipped null_pointer cases, the layer's
        waivers and notes, and the number of failures."""
        if not full:
            worst = max(self.stats.items(), key=lambda kv: kv[1].max_ratio, default=("-", Stat()))
            return [f"{title}: {self.n_cases} cases, {self.n_checks} checks, largest err/tol "
                    f"{worst[1].max_ratio:.3g} ({worst[0]}, {worst[1].worst_ratio}), failures: {len(self.failures)}"]
        w = max([34] + [len(k) for k in self.stats])
        lines = [f"{title}: largest error per function and output",
                 f"regular: |want| >= {REGULAR_MIN_ABS:g} and sens/|want| <= {REGULAR_KAPPA:g}; "
                 "sanity: float-ill-conditioned, finiteness/sign only",
                 f"{'function output':<{w}} {'checks':>7} {'regular':>7} {'sanity':>6} {'max relerr':>11} "
                 f"{'(case)':>8} {'max e/tol':>9} {'(case)':>8}"]
        for key in sorted(self.stats):
            s = self.stats[key]
            lines.append(f"{key:<{w}} {s.checks:>7} {s.regular:>7} {s.sanity:>6} {s.max_rel:>11.3e} "
                         f"{s.worst_rel:>8} {s.max_ratio:>9.3g} {s.worst_ratio:>8}")
        lines.append(f"cases run: {self.n_cases} (" + ", ".join(f"{k} {v}" for k, v in self.cases.items()) + ")")
        lines.append(f"null_pointer cases skipped (no pointers; tests/vectors/README.md allows it): "
                     f"{sum(self.skipped_null.values())} ("
                     + ", ".join(f"{k} {v}" for k, v in sorted(self.skipped_null.items())) + ")")
        for why, ids in sorted(self.waived.items()):
            u = sorted(set(ids))
            lines.append(f"waived ({why}): {len(u)}: {' '.join(u[:12])}" + (" ..." if len(u) > 12 else ""))
        lines.extend(self.notes)
        lines.append(f"failures: {len(self.failures)}")
        return lines

    def summary(self, title: str, full: bool = True) -> str:
        return "\n".join(self.summary_lines(title, full))

    def finish(self, what: str, shown: int = 40) -> None:
        """Raises AssertionError listing the failures, if any."""
        if self.failures:
            more = f"\n  ... and {len(self.failures) - shown} more" if len(self.failures) > shown else ""
            raise AssertionError(f"{what}: {len(self.failures)} failures\n  " + "\n  ".join(self.failures[:shown])
                                 + more)
