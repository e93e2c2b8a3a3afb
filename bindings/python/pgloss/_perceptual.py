# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Lightness, gloss and colour: the element-wise functions of eqs. 3-8 and of CIELAB and the
working colour spaces, with broadcasting (double inside)."""

from __future__ import annotations

import operator
from typing import Any, Callable, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._inputs import ArrayLike, _broadcast, _channels, _color_space, _float, _out_dtype, _shape_out
from ._status import ColorSpace, Normalization, Status, _check, _errors, _finish, _verdict


def _vectorised(function: str, names: Sequence[str], values: Sequence[Any], n_out: int, errors: str = "raise",
                check: Optional[Callable[..., List[np.ndarray]]] = None,
                ignore: Sequence[int] = ()):
    """Runs _core.<function> element-wise; returns the outputs (arrays or floats), and with
    errors="status" the statuses too. ``check(*flat_inputs)``: the statuses of the core's
    checks of the same elements, merged after the function's own (_verdict). ``ignore``:
    statuses of the function's own taken as OK (its outputs are written with them)."""
    want_status = _errors(function, errors)
    flat, shape, dtype = _broadcast(function, names, values)
    n = flat[0].size
    # Zeros: an error of the whole call (an unknown space…) writes nothing, and 0 is what a failed
    # element gets.
    res, st = np.zeros((n_out, n)), np.empty(n, np.int8)
    getattr(_core, function)(*flat, *res, st)
    outs = tuple(_shape_out(function, r, shape, dtype) for r in res)
    if ignore:
        st = np.where(np.isin(st, ignore), np.int8(0), st)
    if check is not None:
        st = _verdict(st, *check(*flat))
    return _finish(function, want_status, outs[0] if n_out == 1 else outs, st, shape, stacklevel=5)


def _grey_physical_check(rho_d: np.ndarray, rho_s: np.ndarray, alpha: np.ndarray) -> List[np.ndarray]:
    """The core's verdict on grey paints (ρd, ρs, α): pgloss_check_physical (ENERGY included)."""
    st = np.empty(rho_d.size, np.int8)
    _core.check_physical((np.broadcast_to(rho_d, (3, rho_d.size)), rho_s, alpha, alpha, int(Normalization.WARD)), st)
    return [st]


def _grey_perceptual_check(L: np.ndarray, c: np.ndarray, d: np.ndarray) -> List[np.ndarray]:
    """The core's verdict on grey paints (L*, 0, 0, c, d): pgloss_check_perceptual (ENVELOPE)."""
    zero = np.broadcast_to(0.0, L.shape)
    st = np.empty(L.size, np.int8)
    _core.check_perceptual(L, zero, zero, c, d, int(ColorSpace.LINEAR_REC709), st)
    return [st]


def lightness_from_luminance(Y: ArrayLike, *, errors: str = "raise") -> Any:
    """CIELAB L* from the luminance factor Y (Yn = 1): κY if Y ≤ ε, else 116 ∛Y − 16.

    Y ≥ 0 (Y > 1 gives L > 100). Raises :class:`PglossError` NONFINITE, NEGATIVE.
    """
    return _vectorised("lightness_from_luminance", ("Y",), (Y,), 1, errors)


def luminance_from_lightness(L: ArrayLike, *, errors: str = "raise") -> Any:
    """Y from L* (the paper's f⁻¹, eq. 6): L/κ if L ≤ 8, else ((L + 16)/116)³.

    L ≥ 0. Raises :class:`PglossError` NONFINITE, LIGHTNESS (L < 0).
    """
    return _vectorised("luminance_from_lightness", ("L",), (L,), 1, errors)


def contrast_gloss(rho_d: ArrayLike, rho_s: ArrayLike, *, errors: str = "raise") -> Any:
    """Contrast gloss c = ∛(ρs + ρd/2) − ∛(ρd/2) (paper eq. 4), without cancellation.

    Broadcasts ``rho_d`` (luminance of the diffuse colour) against ``rho_s``.
    Raises :class:`PglossError` NONFINITE, NEGATIVE.

    >>> round(contrast_gloss(0.193, 0.066), 3)
    0.087
    """
    return _vectorised("contrast_gloss", ("rho_d", "rho_s"), (rho_d, rho_s), 1, errors)


def specular_from_contrast(rho_d: ArrayLike, c: ArrayLike, *, errors: str = "raise") -> Any:
    """ρs = (c + ∛(ρd/2))³ − ρd/2 (paper eq. 7). Raises NONFINITE, NEGATIVE."""
    return _vectorised("specular_from_contrast", ("rho_d", "c"), (rho_d, c), 1, errors)


def gloss_from_physical(rho_d: ArrayLike, rho_s: ArrayLike, alpha: ArrayLike, *, errors: str = "raise",
                        check: bool = True) -> Any:
    """(L*, c, d) of an achromatic paint (eqs. 3, 4 and L* of ρd).

    Returns ``(L, c, d)``. Raises NONFINITE, NEGATIVE, ALPHA (α ≤ 0) and, with ``check=True``
    (the default: the core's verdict on the grey paint, :func:`check_physical`), ENERGY
    (ρd + ρs > 1); warns :class:`AlphaUntrustedWarning` for α > 0.2. ``check=False``: the
    formulas' own errors only (``pgloss_gloss_from_physical``).
    """
    return _vectorised("gloss_from_physical", ("rho_d", "rho_s", "alpha"), (rho_d, rho_s, alpha), 3, errors,
                       _grey_physical_check if check else None)


def physical_from_gloss(L: ArrayLike, c: ArrayLike, d: ArrayLike, *, errors: str = "raise",
                        check: bool = True) -> Any:
    """(ρd, ρs, α) from (L*, c, d) (eqs. 6, 7, 8).

    Returns ``(rho_d, rho_s, alpha)``. Raises NONFINITE, LIGHTNESS (L outside [0, 100]),
    NEGATIVE (c < 0), ALPHA (d ≥ 1) and, with ``check=True`` (the default: the core's verdict
    on the grey paint, :func:`check_perceptual`), ENVELOPE (c beyond the envelope at L: the
    values are then on the exception's ``result``); warns for d < 0.8. ``check=False``: the
    formulas' own errors only (``pgloss_physical_from_gloss``).
    """
    return _vectorised("physical_from_gloss", ("L", "c", "d"), (L, c, d), 3, errors,
                       _grey_perceptual_check if check else None)


def gloss_distance(c1: ArrayLike, d1: ArrayLike, c2: ArrayLike, d2: ArrayLike, *, errors: str = "raise",
                   check: bool = True) -> Any:
    """Gloss difference D = √((c1 − c2)² + (1.78 (d1 − d2))²) (paper eq. 5) between the paints
    (c1, d1) and (c2, d2).

    Raises NONFINITE and, with ``check=True`` (the default: ``pgloss_gloss_distance``'s verdict
    on the two paints, the one :func:`physical_from_gloss` gives on c and d), NEGATIVE (c < 0)
    and ALPHA (d ≥ 1: no lobe), paint 1 first; warns for d < 0.8. ``check=False``: eq. 5 on any
    plane point, NONFINITE only, e.g. between the unclipped points of :func:`isogloss_contour`.

    >>> round(gloss_distance(0.087, 0.93, 0.127, 0.93), 12)
    0.04
    """
    return _vectorised("gloss_distance", ("c1", "d1", "c2", "d2"), (c1, d1, c2, d2), 1, errors,
                       ignore=() if check else (Status.ERR_NEGATIVE, Status.ERR_ALPHA, Status.WARN_ALPHA_UNTRUSTED))


def envelope_contrast(L: ArrayLike, *, errors: str = "raise") -> Any:
    """Largest contrast gloss at lightness L under ρd + ρs ≤ 1 (the envelope of Fig. 10):
    ∛(1 − ρd/2) − ∛(ρd/2), ρd = f⁻¹(L). Raises NONFINITE, LIGHTNESS."""
    return _vectorised("envelope_contrast", ("L",), (L,), 1, errors)


def match_gloss(rho_d: ArrayLike, rho_s: ArrayLike, L_target: ArrayLike, *, errors: str = "raise") -> Any:
    """Same apparent gloss at another lightness (§5.2, Fig. 12): keeps c of (ρd, ρs) and
    moves the paint to ``L_target``; returns ``(rho_d', rho_s')``.

    Raises NONFINITE, NEGATIVE, LIGHTNESS, and ENVELOPE if ρd' + ρs' > 1 — the matched
    values are then on the exception's ``result``.
    """
    return _vectorised("match_gloss", ("rho_d", "rho_s", "L_target"), (rho_d, rho_s, L_target), 2, errors)


def isogloss_contour(c0: float, d0: float, D: float, n: int = 64) -> Tuple[np.ndarray, np.ndarray]:
    """Isogloss contour (§5.1, Fig. 11): ``n`` points at gloss distance ``D`` from (c0, d0),
    c_k = c0 + D cos θk, d_k = d0 + (D/1.78) sin θk, θk = 2πk/n.

    Returns ``(c, d)``, two float64 arrays of length ``n``; the points are not clipped to the
    valid region (check them with :func:`check_perceptual`). Raises NONFINITE, NEGATIVE (D < 0),
    ARGUMENT (n == 0).
    """
    fn = "isogloss_contour"
    try:
        count = operator.index(n)
    except TypeError:
        raise TypeError(f"pgloss.{fn}: n must be an int, not {type(n).__name__}") from None
    if count < 0:
        raise ValueError(f"pgloss.{fn}: n must be >= 0, got {count}")
    c, d = np.zeros(count), np.zeros(count)
    st = _core.isogloss_contour(_float(fn, "c0", c0), _float(fn, "d0", d0), _float(fn, "D", D), c, d)
    _check(fn, np.array([st]), (), (c, d), scalar=True)
    return c, d


def rgb_from_lab(lab: ArrayLike, space: Union[ColorSpace, int] = ColorSpace.LINEAR_REC709, *, errors: str = "raise") -> np.ndarray:
    """CIELAB (L*, a*, b*) (D65) → linear RGB of ``space`` (default Rec. 709), both ``(..., 3)``.

    Raises NONFINITE, LIGHTNESS (L outside [0, 100]), GAMUT (a channel < 0: the exact values
    are on the exception's ``result``), ARGUMENT (unknown space).
    """
    return _triple("rgb_from_lab", "lab", lab, 3, space, errors)


def lab_from_rgb(rgb: ArrayLike, space: Union[ColorSpace, int] = ColorSpace.LINEAR_REC709, *, errors: str = "raise") -> np.ndarray:
    """Linear RGB of ``space`` (default Rec. 709) → CIELAB (L*, a*, b*) (D65), both ``(..., 3)``.
    Raises NONFINITE, NEGATIVE, ARGUMENT (unknown space)."""
    return _triple("lab_from_rgb", "rgb", rgb, 3, space, errors)


def luminance(rgb: ArrayLike, space: Union[ColorSpace, int] = ColorSpace.LINEAR_REC709, *, errors: str = "raise") -> Any:
    """Luminance Y of linear RGB of ``space`` (default Rec. 709) ``(..., 3)`` → ``(...)``.
    Raises NONFINITE, ARGUMENT (unknown space)."""
    return _triple("luminance", "rgb", rgb, 1, space, errors)


def _triple(function: str, name: str, value: Any, n_out: int, space: Any, errors: str = "raise") -> Any:
    want_status = _errors(function, errors)
    sp = _color_space(function, space)
    a = _channels(function, name, value, 3)
    shape = a.shape[:-1]
    dtype = _out_dtype((value,), (a,))
    rows = np.asarray(a, dtype=np.float64).reshape(-1, 3)  # (n, 3) rows, a view where numpy can
    n = rows.shape[0]
    st = np.empty(n, np.int8)
    if n_out == 3:
        res = np.zeros((n, 3))  # as _vectorised's
        getattr(_core, function)(rows.T, sp, res.T, st)
        out = _shape_out(function, res, shape + (3,), dtype)
    else:
        res = np.zeros(n)
        getattr(_core, function)(*rows.T, sp, res, st)
        out = _shape_out(function, res, shape, dtype)
    return _finish(function, want_status, out, st, shape, stacklevel=5)
