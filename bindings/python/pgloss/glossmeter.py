# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The virtual glossmeter (``pgloss/glossmeter.h``) for numpy: instrument readings of paints,
paints from readings, and the paint trade's named finishes.

* :func:`readings` — specular gloss at 20°, 60°, 85° (ISO 2813 / ASTM D523), reflection haze at
  20° (ASTM E430 / ISO 13803 style), the ASTM D4039 haze index, Hunter's DOI at 30° and contrast
  gloss, of one :class:`pgloss.Physical` or an array of them, each with its quadrature error;
* :func:`from_gloss_units` — the paint of the pgloss model (eq. 2, no Fresnel term) whose
  readings are a 60° gloss and one of the 20° gloss, the haze or the DOI (or, with the 60° gloss
  alone, a given or the assumed d);
* :data:`FINISHES` and :func:`finish` — the MPI gloss levels G1–G7 as 60° / 85° gloss ranges,
  and a finish's representative paint with the range of c and d it spans.

Where each aperture number comes from, and which are assumed, is in ``docs/glossmeter.md``. A
sharp Ward lobe reads about 100 ρs cos θ / R_F(θ) GU, so the paper's paints read low at 60° and
almost nothing at 85°: the inverse inverts what pgloss renders, not a real paint's readings.

Example:

    >>> import pgloss
    >>> from pgloss import glossmeter
    >>> r = glossmeter.readings(pgloss.Physical(0.193, 0.066, 0.04))
    >>> round(float(r.values[glossmeter.GLOSS_60]), 2)
    16.99
"""

from __future__ import annotations

from typing import Any, List, NamedTuple, Optional, Tuple, Union

import numpy as np

from . import _core
from ._status import PglossError

# Indices of the last axis of Readings.values / .errors (pgloss_glossmeter_kind).
GLOSS_20, GLOSS_60, GLOSS_85, HAZE_20, HAZE_INDEX, DOI_30, CONTRAST_60 = range(7)
KINDS: Tuple[str, ...] = ("gloss_20", "gloss_60", "gloss_85", "haze_20", "haze_index", "doi_30", "contrast_60")
STANDARD_INDEX: float = _core.GLOSS_STANDARD_INDEX
ASSUMED_DOI_GLOSS: float = _core.ASSUMED_DOI_GLOSS

_WARN_QUADRATURE = 2
_ERR_NO_FIT = -16


class Readings(NamedTuple):
    """Readings of a paint or an array of paints: ``values`` and ``errors`` of shape
    ``paint.shape + (7,)``, the last axis indexed by GLOSS_20 … CONTRAST_60 (:data:`KINDS`), and
    the core's ``status`` per paint (0 ok, 2 a quadrature tolerance missed: see ``errors``)."""

    values: np.ndarray
    errors: np.ndarray
    status: np.ndarray

    def __getattr__(self, name: str) -> Any:  # r.gloss_60 etc.
        if name in KINDS:
            return self.values[..., KINDS.index(name)]
        raise AttributeError(name)


def _raise_first(function: str, st: np.ndarray, shape: Tuple[int, ...], result: Any = None) -> None:
    bad = np.flatnonzero(st < 0)
    if bad.size:
        i = int(bad[0])
        index = tuple(int(x) for x in np.unravel_index(i, shape)) if shape else None
        raise PglossError(int(st.flat[i]), f"glossmeter.{function}", index, result, st.reshape(shape) if shape else None)


def readings(paint: Any, *, azimuth: Union[float, np.ndarray] = 0.0, tol: float = 0.0) -> Readings:
    """The virtual glossmeter's readings of ``paint`` (a :class:`pgloss.Physical`, one or an array,
    any normalisation, anisotropic lobes) rotated by ``azimuth`` degrees about its normal (broadcast
    against the paints), each to relative tolerance ``tol`` (0: 1e-6) of its flux. Raises
    :class:`pgloss.PglossError` for a paint the core rejects (NaN, negative, α <= 0)."""
    from . import Physical  # the package's class (pgloss/__init__.py)
    if not isinstance(paint, Physical):
        raise TypeError(f"pgloss.glossmeter.readings: expected a pgloss.Physical, not {type(paint).__name__}")
    shape = np.broadcast_shapes(paint.shape, np.shape(azimuth))
    rd, rs, ax, ay, _ = paint._core_arrays(shape)
    cols = [rd[0], rd[1], rd[2], rs, ax, ay]
    az = np.ascontiguousarray(np.broadcast_to(np.asarray(azimuth, dtype=np.float64), shape)).ravel()
    v, e, st = _core.glossmeter_readings(*cols, int(paint.normalization), az, float(tol))
    _raise_first("readings", st, shape)
    return Readings(v.reshape(shape + (7,)), e.reshape(shape + (7,)), st.reshape(shape))


def readings_bridge(target: Union[str, int], params: Any, *, tol: float = 0.0) -> Readings:
    """The virtual glossmeter's readings of gloss-bridge ``target`` materials (``params``: a
    :class:`pgloss.bridge.Params`, or a mapping under the target's own names as ``pgloss bridge``
    prints them; arrays broadcast): the target's microfacet lobe with its Fresnel and energy
    compensation plus its diffuse base (docs/glossmeter.md, "Microfacet targets"). The targets are
    isotropic, so there is no azimuth. Raises :class:`pgloss.PglossError` for a material the core
    rejects (NaN, negative, a base channel above 1, F0 = 1, α > 1)."""
    from . import bridge
    t = bridge._target("readings_bridge", target)
    shape, cols = bridge._param_columns("readings_bridge", params, t)
    v, e, st = _core.glossmeter_readings_bridge(t, *cols, float(tol))
    _raise_first("readings_bridge", st, shape)
    return Readings(v.reshape(shape + (7,)), e.reshape(shape + (7,)), st.reshape(shape))


def from_gloss_units(L: Any, gloss_60: Any, *, gloss_20: Any = None, haze: Any = None, doi: Any = None,
                     d: Any = None, a: Any = 0.0, b: Any = 0.0, normalization: int = 0,
                     errors: str = "raise") -> Any:
    """The pgloss paint (CIELAB ``L``, ``a``, ``b``; eq. 2 with ``normalization``) whose virtual
    60° gloss is ``gloss_60`` and whose 20° gloss, haze or DOI (at most one) is the given one;
    with none of them, d is ``d`` or, if None, :data:`ASSUMED_DOI_GLOSS` (α = 0.07, the middle of
    the paper's stimuli). All arguments broadcast. Returns a :class:`pgloss.Perceptual`; with
    ``errors="status"`` ``(Perceptual, status)`` instead of raising. NO_FIT (−16): no paint of
    the model reads so (the result then holds the nearest in the second reading). The haze's
    two solutions: the sharper lobe is returned (haze is a high-gloss measure, ISO 13803)."""
    from . import Perceptual
    given = [(k, x) for k, x in ((1, gloss_20), (2, haze), (3, doi)) if x is not None]
    if len(given) > 1 or (given and d is not None):
        raise ValueError("pgloss.glossmeter.from_gloss_units: give at most one of gloss_20, haze, doi, d")
    if errors not in ("raise", "status"):
        raise ValueError("pgloss.glossmeter.from_gloss_units: errors must be 'raise' or 'status'")
    second, x = given[0] if given else (0, ASSUMED_DOI_GLOSS if d is None else d)
    arrs = np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in (L, a, b, gloss_60, x)))
    shape = arrs[0].shape
    flat = [np.ascontiguousarray(v).ravel() for v in arrs]
    c, dd, st = _core.paint_from_gloss_units(*flat, int(second), int(normalization))
    if shape == ():
        out = Perceptual(float(flat[0][0]), float(flat[1][0]), float(flat[2][0]), float(c[0]), float(dd[0]))
    else:
        out = Perceptual(arrs[0], arrs[1], arrs[2], c.reshape(shape), dd.reshape(shape))
    if errors == "status":
        return out, (int(st[0]) if shape == () else st.reshape(shape))
    _raise_first("from_gloss_units", st, shape, out)
    return out


class Finish(NamedTuple):
    """A trade finish and its gloss-unit ranges (NaN: no bound)."""

    name: str
    level: str
    gloss_60_min: float
    gloss_60_max: float
    sheen_85_min: float
    sheen_85_max: float
    source: str


FINISHES: Tuple[Finish, ...] = tuple(Finish(*f) for f in _core.finishes())


class FinishPaint(NamedTuple):
    """A finish's representative paint (60° gloss the middle of its range, d assumed), the
    ranges of c and d it spans, and whether the paint meets the finish's 85° range."""

    finish: str
    paint: Any
    c_range: Tuple[float, float]
    d_range: Tuple[float, float]
    sheen_ok: bool
    status: int


def finish(name: str, L: float = 50.0, a: float = 0.0, b: float = 0.0, normalization: int = 0) -> FinishPaint:
    """The representative paint of a finish (``"satin"``, ``"G4"``, ``"mpi-g4"``…) at a colour."""
    from . import Perceptual
    c, d, c0, c1, d0, d1, sheen, st, fname = _core.finish_paint(str(name), float(L), float(a), float(b),
                                                                int(normalization))
    res = FinishPaint(fname, Perceptual(float(L), float(a), float(b), c, d), (c0, c1), (d0, d1), sheen, st)
    if st < 0 and st != _ERR_NO_FIT:
        raise PglossError(st, "glossmeter.finish", result=res)
    return res


def fresnel_dielectric(n: float, cos_i: float) -> float:
    """Unpolarised Fresnel reflectance of a dielectric of index n > 1 at incidence cosine cos_i."""
    r, st = _core.fresnel_dielectric(float(n), float(cos_i))
    if st < 0:
        raise PglossError(st, "glossmeter.fresnel_dielectric")
    return float(r)


__all__: List[str] = ["GLOSS_20", "GLOSS_60", "GLOSS_85", "HAZE_20", "HAZE_INDEX", "DOI_30", "CONTRAST_60",
                      "KINDS", "STANDARD_INDEX", "ASSUMED_DOI_GLOSS", "Readings", "readings", "readings_bridge",
                      "from_gloss_units", "Finish", "FINISHES", "FinishPaint", "finish", "fresnel_dielectric"]
