# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The BRDF (paper eq. 2): materials, eval, pdf, eval_pdf and sample over (..., 3) arrays of
directions, through the C core's batches."""

from __future__ import annotations

from typing import Any, List, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import Material
from ._inputs import ArrayLike, _channels, _lobes, _out_dtype
from ._paints import Physical
from ._status import Lobe, PglossError


def _material(function: str, m: Any) -> Material:
    if isinstance(m, Material):
        return m
    if isinstance(m, Physical):
        return m.material()
    raise TypeError(f"pgloss.{function}: material must be a pgloss.Physical or pgloss.Material, "
                    f"not {type(m).__name__}")


def _directions(function: str, names: Tuple[str, str], a: Any, b: Any, extra: Tuple[int, ...] = ()):
    """(..., 3) arrays → (n, 3) arrays of one dtype, views where numpy can make them (stride 0
    for a direction shared by every element: the core reads strides), and the batch shape (the
    broadcast of both leading shapes and ``extra``, the material's shape)."""
    arrs = []
    for name, v in zip(names, (a, b)):
        arrs.append(_channels(function, name, v, 3))
    try:
        shape = np.broadcast_shapes(arrs[0].shape[:-1], arrs[1].shape[:-1], extra)
    except ValueError:
        what = f"{names[0]}{arrs[0].shape}, {names[1]}{arrs[1].shape}" + (f", material{extra}" if extra else "")
        raise ValueError(f"pgloss.{function}: shapes do not broadcast: {what}") from None
    dtype = _out_dtype((a, b), arrs)
    rows = [np.broadcast_to(np.asarray(x, dtype=dtype), shape + (3,)).reshape(-1, 3) for x in arrs]
    return rows, shape, dtype


def material_init(physical: Physical) -> Material:
    """Validates ``physical`` and builds the evaluation-ready :class:`Material`
    (``pgloss_material_init``).

    Checks, in this order: NONFINITE (NaN/Inf or beyond float range), NEGATIVE (ρd or ρs < 0),
    ALPHA (αx ≤ 0 or αy ≤ 0), NORMALIZATION; the first failure raises :class:`PglossError`.
    Positive α below :data:`ALPHA_MIN` is raised to it. Energy (ρd + ρs > 1) is not
    rejected here: see :func:`check_physical`.
    """
    if not isinstance(physical, Physical):
        raise TypeError(f"pgloss.material_init: expected a pgloss.Physical, not {type(physical).__name__}")
    return physical.material()


def specular_probability(material: Union[Physical, Material], lobes: int = Lobe.ALL) -> float:
    """Probability that :func:`sample` picks the specular lobe under this mask:
    ws / (wd + ws) over the active lobes (wd = luminance of ρd, ws = ρs); 1 or 0 when only
    one lobe is active, 0 when none is (``pgloss_specular_probability``)."""
    m = _material("specular_probability", material)
    return float(_core.specular_probability(m, _lobes("specular_probability", lobes)))


def _brdf_material(function: str, material: Any) -> Tuple[Optional[Material], Optional[Physical]]:
    """(Material, None) for one paint; (None, array Physical) for an array or a sequence of paints."""
    if isinstance(material, Material):
        return material, None
    if isinstance(material, Physical):
        return (None, material) if material.is_array else (material.material(), None)
    if isinstance(material, (list, tuple)) and material and all(isinstance(p, (Physical, Material)) for p in material):
        return None, Physical.stack(material)
    if isinstance(material, np.ndarray) and material.ndim >= 1 and material.shape[-1] == 6:
        return _brdf_material(function, Physical.from_array(material))
    raise TypeError(f"pgloss.{function}: material must be a pgloss.Physical or pgloss.Material (one paint, an "
                    f"array of paints, or a sequence of them) or a channel-last array (..., 6) of rho_d r, g, b, "
                    f"rho_s, alpha_x, alpha_y, not {type(material).__name__}")


def _out_array(function: str, name: str, out: Any, shape: Tuple[int, ...], dtype: np.dtype,
               inputs: Sequence[Any]) -> Optional[np.ndarray]:
    """Checks an ``out=`` array: exact shape and dtype, C-contiguous, writeable, no overlap with
    any input (the C loops read the inputs chunk by chunk while they write the outputs)."""
    if out is None:
        return None
    if not isinstance(out, np.ndarray):
        raise TypeError(f"pgloss.{function}: out {name} must be a numpy.ndarray, not {type(out).__name__}")
    if out.dtype != dtype:
        raise TypeError(f"pgloss.{function}: out {name} has dtype {out.dtype}; this call's {name} is {dtype}")
    if out.shape != shape:
        raise ValueError(f"pgloss.{function}: out {name} has shape {out.shape}; this call's {name} is {shape}")
    if not out.flags.c_contiguous or not out.flags.writeable:
        raise ValueError(f"pgloss.{function}: out {name} must be C-contiguous and writeable")
    for k, x in enumerate(inputs):
        if isinstance(x, np.ndarray) and np.may_share_memory(out, x):
            raise ValueError(f"pgloss.{function}: out {name} overlaps an input or another output; outputs must not "
                             f"share memory with the inputs")
    return out


def _outs(function: str, out: Any, specs: Sequence[Tuple[str, Optional[Tuple[int, ...]], Any]],
          inputs: Sequence[Any]) -> List[Optional[np.ndarray]]:
    """``out=`` as one array (one output) or a tuple (several); specs: (name, shape or None if
    not produced, dtype)."""
    produced = [s for s in specs if s[1] is not None]
    if out is None:
        return [None] * len(specs)
    if len(produced) == 1 and not isinstance(out, tuple):
        out = tuple(out if s[1] is not None else None for s in specs)
    if not isinstance(out, tuple) or len(out) != len(specs):
        names = ", ".join(s[0] for s in specs)
        raise TypeError(f"pgloss.{function}: out must be a tuple ({names}) of arrays or None")
    checked: List[Optional[np.ndarray]] = []
    seen: List[np.ndarray] = []
    for (name, shape, dtype), o in zip(specs, out):
        if o is not None and shape is None:
            raise TypeError(f"pgloss.{function}: out {name} given, but this call does not produce {name}")
        arr = _out_array(function, name, o, shape, np.dtype(dtype), list(inputs) + seen) if shape is not None else None
        if arr is not None:
            seen.append(arr)
        checked.append(arr)
    return checked


def _material_inputs(arr: Optional[Physical]) -> List[Any]:
    if arr is None:
        return []
    return [np.asarray(x) for x in (arr.rho_d, arr.rho_s, arr.alpha_x, arr.alpha_y)]


def _raise_brdf(function: str, st: int, idx: int, shape: Tuple[int, ...], result: Any,
                statuses: Optional[np.ndarray]) -> None:
    index = None if shape == () else tuple(int(k) for k in np.unravel_index(idx, shape))
    array = None if statuses is None or statuses.size == 0 or shape == () else statuses.reshape(shape)
    raise PglossError(st, function, index, result, array)


def _brdf(function: str, material: Any, wo: Any, wi: Any, lobes: Any, want_f: bool, want_pdf: bool,
          out: Any = None):
    m, arr = _brdf_material(function, material)
    mask = _lobes(function, lobes)
    (o, i), shape, dtype = _directions(function, ("wo", "wi"), wo, wi, () if arr is None else arr.shape)
    specs = [("f", shape + (3,) if want_f else None, dtype), ("pdf", shape if want_pdf else None, dtype)]
    f_out, p_out = _outs(function, out, specs, [np.asarray(wo), np.asarray(wi)] + _material_inputs(arr))
    n = o.shape[0]
    f = (np.empty(shape + (3,), dtype) if f_out is None else f_out) if want_f else None
    p = (np.empty(shape, dtype) if p_out is None else p_out) if want_pdf else None
    statuses = np.empty(n, np.int8)
    st, idx, whole = _core.eval_pdf(m, None if arr is None else arr._core_arrays(shape, dtype), mask, o.T, i.T,
                                    None if f is None else f.reshape(n, 3).T, None if p is None else p.reshape(n),
                                    statuses)
    if whole:  # nothing written: the outputs of a failed element
        for x in (f, p):
            if x is not None:
                x[...] = 0
    if want_pdf and p_out is None and shape == ():
        p = float(p)
    result = (f, p) if want_f and want_pdf else (f if want_f else p)
    if st < 0:
        _raise_brdf(function, st, idx, shape, result, None if arr is None else statuses)
    return result


def eval(material: Union[Physical, Material, Sequence[Physical]], wo: ArrayLike, wi: ArrayLike,
         lobes: int = Lobe.ALL, *, out: Optional[np.ndarray] = None) -> np.ndarray:
    """The BRDF f(wo, wi) per RGB channel, without the cosine factor (paper eq. 2).

    Parameters
    ----------
    material : Physical, sequence of Physical, Material, or array_like (..., 6)
        One paint (a ``Physical`` is compiled once and cached), or an array of paints (an
        array ``Physical``, rounded to float once and kept, a list of them, or a channel-last
        numpy array of ρd r, g, b, ρs, αx, αy as :meth:`Physical.to_array` writes it): one
        material per element, broadcast against the directions' leading shapes.
    wo, wi : array_like, shape (..., 3)
        Directions towards the viewer and towards the light, in the shading frame
        (normal = +z), any length; the leading shapes broadcast against each other and
        against the material's shape.
    lobes : Lobe or int
        Lobes to evaluate (default ``Lobe.ALL``); ``mask & material.lobes`` is used.
    out : numpy.ndarray, optional
        Where to write f: C-contiguous, writeable, of the result's exact shape and dtype, and
        sharing no memory with ``wo``, ``wi`` or the material's arrays (else ``ValueError`` /
        ``TypeError``, before anything is written). It is returned.

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        f per channel: ``float32`` for float32 directions (the vectorised float batch),
        ``float64`` otherwise (the vectorised double batch, double-reference accuracy). The
        material's parameters are float in both (``pgloss_material``; an array of paints is
        rounded element by element). 0 when either direction is at or below the horizon.

    Raises
    ------
    PglossError
        DIRECTION if a direction is zero-length or not finite (``index`` names the first),
        or the material's error (NONFINITE, NEGATIVE, ALPHA, NORMALIZATION) — for an array of
        paints with the first failing element's ``index`` and the ``status_array`` of all.
    ValueError, TypeError
        Wrong shapes (last axis not 3, not broadcastable), non-numeric input, a bad ``out``.

    Examples
    --------
    >>> p = Physical(0.193, 0.066, 0.07)
    >>> f = eval(p, [0.0, 0.0, 1.0], [[0.0, 0.0, 1.0], [0.0, 0.6, 0.8]])
    >>> f.shape
    (2, 3)
    >>> eval([p, p.replace(rho_s=0.033)], [0.0, 0.0, 1.0], [0.0, 0.6, 0.8]).shape
    (2, 3)
    """
    return _brdf("eval", material, wo, wi, lobes, True, False, out)


def pdf(material: Union[Physical, Material, Sequence[Physical]], wo: ArrayLike, wi: ArrayLike,
        lobes: int = Lobe.ALL, *, out: Optional[np.ndarray] = None) -> Any:
    """Solid-angle density with which :func:`sample` draws ``wi`` given ``wo``.

    pdf = (1 − Ps) wi_z/π + Ps p_spec, Ps = :func:`specular_probability`, p_spec from Walter
    2005's half-vector density. Same arguments, broadcasting, dtypes, ``out=`` rules and
    errors as :func:`eval`; returns an array of shape ``(...)``, or a float for one direction
    pair (without ``out``).
    """
    return _brdf("pdf", material, wo, wi, lobes, False, True, out)


def eval_pdf(material: Union[Physical, Material, Sequence[Physical]], wo: ArrayLike, wi: ArrayLike,
             lobes: int = Lobe.ALL, *, out: Optional[Tuple[Optional[np.ndarray], Optional[np.ndarray]]] = None
             ) -> Tuple[np.ndarray, Any]:
    """:func:`eval` and :func:`pdf` in one pass (shared half vector and exponential).

    Returns ``(f, pdf)``: shapes ``(..., 3)`` and ``(...)`` (a float for one pair). ``out``
    is a tuple ``(f, pdf)``; either may be ``None`` (allocated); the two must not overlap.
    """
    return _brdf("eval_pdf", material, wo, wi, lobes, True, True, out)


class SampleRecord(NamedTuple):
    """Result of :func:`sample` (``pgloss_sample_record``), one entry per ``wo``.

    wi : (..., 3) sampled directions, unit length.
    pdf : (...) density of ``wi`` (= :func:`pdf`); 0 marks a rejected sample.
    weight : (..., 3) f · wi_z / pdf; 0 for a rejected sample.
    lobe : (...) uint8 array of :class:`Lobe` values (a ``Lobe`` for one sample).
    """

    wi: np.ndarray
    pdf: Any
    weight: np.ndarray
    lobe: Any


def sample(material: Union[Physical, Material, Sequence[Physical]], wo: ArrayLike, u: ArrayLike,
           lobes: int = Lobe.ALL, *, out: Optional[Tuple[Any, Any, Any, Any]] = None) -> SampleRecord:
    """Draws ``wi`` given ``wo`` from three uniform random numbers per sample.

    Parameters
    ----------
    material : Physical, sequence of Physical, or Material
        One paint, or an array of paints broadcast against the leading shapes of ``wo`` and ``u``.
    wo : array_like, shape (..., 3)
        Directions towards the viewer.
    u : array_like, shape (..., 3)
        Uniform numbers in [0, 1) (others are clamped to [0, 1 − 2⁻²⁴], in float64 as in
        float32, so that both draw the same directions); ``u[..., 0]`` chooses the lobe (specular if <
        :func:`specular_probability`), ``u[..., 1:]`` the direction (Walter 2005 for the
        specular lobe, a concentric-disk cosine lobe for the diffuse one). The leading shapes
        of ``wo`` and ``u`` broadcast.
    lobes : Lobe or int
    out : tuple (wi, pdf, weight, lobe), optional
        Arrays to write into (any may be ``None``); the rules of :func:`eval`'s ``out``
        (``lobe`` is ``uint8``).

    Returns
    -------
    SampleRecord
        ``(wi, pdf, weight, lobe)``. A rejected sample (``wi`` below the horizon, grazing
        ``wo``, no active lobe) has ``pdf == 0`` and ``weight == 0``: end the path.
        float32 input runs the vectorised float batch, float64 the vectorised double batch.

    Raises
    ------
    PglossError
        DIRECTION (zero/non-finite ``wo``), RANDOM (NaN in ``u``) or the material's error,
        with the first index.
    """
    fn = "sample"
    m, arr = _brdf_material(fn, material)
    mask = _lobes(fn, lobes)
    (o, uu), shape, dtype = _directions(fn, ("wo", "u"), wo, u, () if arr is None else arr.shape)
    specs = [("wi", shape + (3,), dtype), ("pdf", shape, dtype), ("weight", shape + (3,), dtype),
             ("lobe", shape, np.uint8)]
    outs = _outs(fn, out, specs, [np.asarray(wo), np.asarray(u)] + _material_inputs(arr))
    wi, p, w, lobe = (np.empty(s[1], s[2]) if x is None else x for s, x in zip(specs, outs))
    n = o.shape[0]
    statuses = np.empty(n, np.int8)
    st, idx, whole = _core.sample(m, None if arr is None else arr._core_arrays(shape, dtype), mask, o.T, uu.T,
                                  wi.reshape(n, 3).T, p.reshape(n), w.reshape(n, 3).T, lobe.reshape(n), statuses)
    if whole:  # nothing written: the outputs of a rejected sample
        for x in (wi, p, w, lobe):
            x[...] = 0
        wi[..., 2] = 1
    if shape == () and out is None:
        rec = SampleRecord(wi, float(p), w, Lobe(int(lobe)))
    else:
        rec = SampleRecord(wi, p, w, lobe)
    if st < 0:
        _raise_brdf(fn, st, idx, shape, rec, None if arr is None else statuses)
    return rec
