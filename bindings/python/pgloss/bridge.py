# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The gloss bridge (``pgloss/bridge.h``) for numpy: paints of the paper's perceptual space
(L*, a*, b*, c, d) to the parameters of the dielectric BRDFs people render with, and back.

Targets (:data:`TARGETS`): ``openpbr``, ``standard_surface``, ``gltf`` (with KHR_materials_ior
and KHR_materials_specular), ``gltf_core``, ``principled`` (Blender, Cycles),
``roughplastic_ggx`` and ``roughplastic_beckmann`` (Mitsuba 3). The criterion, each target's
convention and source, the tables' accuracy and each target's reach are in ``docs/bridge.md``.

* :func:`from_paint` — paints ``(..., 5)`` → :class:`Mapping`: the target's :class:`Params`
  (arrays; :meth:`Params.named` gives them under the target's own names), the paint they read
  as, and a status per paint. Out of the target's reach, the parameters of the nearest
  reachable paint are written and the status names the limit (:data:`ERR_BRIDGE_BASE`,
  :data:`ERR_BRIDGE_SPECULAR`, :data:`ERR_BRIDGE_ROUGHNESS`; :func:`reasons` gives the
  sentences).
* :func:`to_paint` — the target's parameters → the paint ``(..., 5)`` they read as, and how
  Ward-like the target looks (the fit's relative RMS residual).
* :func:`read`, :func:`model_inputs`, :func:`params_from_model`, :func:`target_range` — the
  layers underneath.

All inputs broadcast; arrays are channel-last. With ``errors="raise"`` (the default) the first
element with an error raises :class:`pgloss.PglossError`, which carries the whole result (the nearest
reachable parameters for an out-of-reach paint) and every element's status; with
``errors="status"`` nothing is raised and the statuses are in the result.

Example:

    >>> from pgloss import bridge
    >>> m = bridge.from_paint("openpbr", [50.0, 0.0, 0.0, 0.057, 0.96])
    >>> sorted(m.params.named("openpbr"))[:3]
    ['base_color', 'base_weight', 'specular_ior']
"""

from __future__ import annotations

from typing import Any, Dict, List, Mapping as MappingType, NamedTuple, Optional, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike

from . import _core
from ._status import PglossError

#: The targets' short names, in the order of ``pgloss_bridge_target``.
TARGETS: Tuple[str, ...] = tuple(_core.bridge_target_name(i) for i in range(_core.BRIDGE_TARGET_COUNT))
#: A base colour channel would leave [0, 1] (``PGLOSS_ERR_BRIDGE_BASE``).
ERR_BRIDGE_BASE: int = _core.ERR_BRIDGE_BASE
#: F0 outside the target's range: c too high or too low (``PGLOSS_ERR_BRIDGE_SPECULAR``).
ERR_BRIDGE_SPECULAR: int = _core.ERR_BRIDGE_SPECULAR
#: α outside the target's range: d too high or too low (``PGLOSS_ERR_BRIDGE_ROUGHNESS``).
ERR_BRIDGE_ROUGHNESS: int = _core.ERR_BRIDGE_ROUGHNESS
#: The out-of-reach statuses: the result holds the nearest reachable paint's parameters.
REACH_STATUSES: Tuple[int, ...] = (ERR_BRIDGE_BASE, ERR_BRIDGE_SPECULAR, ERR_BRIDGE_ROUGHNESS)

# Each target's names for (base colour, roughness, IOR, specular) and its fixed inputs, as
# `pgloss bridge` prints them (tools/cmd_bridge.c); docs/bridge.md cites each convention.
_MITSUBA_AIR = 1.000277
_NAMES: Dict[str, Tuple[str, str, str, Optional[str], Dict[str, Any]]] = {
    "openpbr": ("base_color", "specular_roughness", "specular_ior", "specular_weight", {"base_weight": 1.0}),
    "standard_surface": ("base_color", "specular_roughness", "specular_IOR", "specular", {"base": 1.0}),
    "gltf": ("baseColorFactor", "roughnessFactor", "ior", "specularFactor", {"metallicFactor": 0.0}),
    "gltf_core": ("baseColorFactor", "roughnessFactor", "ior", "specularFactor", {"metallicFactor": 0.0}),
    "principled": ("Base Color", "Roughness", "IOR", "Specular IOR Level", {"Metallic": 0.0}),
    "roughplastic_ggx": ("diffuse_reflectance", "alpha", "int_ior", None,
                         {"distribution": "ggx", "ext_ior": _MITSUBA_AIR, "nonlinear": False}),
    "roughplastic_beckmann": ("diffuse_reflectance", "alpha", "int_ior", None,
                              {"distribution": "beckmann", "ext_ior": _MITSUBA_AIR, "nonlinear": False}),
}

_ERRORS = ("raise", "status")


def reasons(status: ArrayLike) -> Any:
    """The core's sentence for each status (``pgloss_status_string``): a ``str`` for one status,
    else an array of ``str`` of the same shape."""
    st = np.asarray(status, dtype=np.int64)
    if st.ndim == 0:
        return _core.status_string(int(st))
    table = {int(s): _core.status_string(int(s)) for s in np.unique(st)}
    out = np.empty(st.shape, dtype=object)
    for s, text in table.items():
        out[st == s] = text
    return out


def status_names(status: ArrayLike) -> Any:
    """The C enumerator's name of each status (``"PGLOSS_ERR_BRIDGE_SPECULAR"``…), as :func:`reasons`."""
    st = np.asarray(status, dtype=np.int64)
    if st.ndim == 0:
        return _core.status_name(int(st))
    out = np.empty(st.shape, dtype=object)
    for s in np.unique(st):
        out[st == s] = _core.status_name(int(s))
    return out


class Params(NamedTuple):
    """A target's parameters (``pgloss_bridge_params``), arrays of the paints' shape:
    ``base_color`` ``(..., 3)`` linear Rec. 709, ``roughness`` (α = roughness² except Mitsuba's
    ``alpha``, which is α), ``ior`` and ``specular`` (the target's specular weight or level; 1
    for Mitsuba). :meth:`named` gives them under the target's own names."""

    base_color: np.ndarray
    roughness: Any
    ior: Any
    specular: Any

    def named(self, target: Union[str, int]) -> Dict[str, Any]:
        """The parameters under ``target``'s own names, with its fixed inputs (the keys of
        ``pgloss bridge``'s JSON ``parameters``): e.g. OpenPBR's ``base_color``,
        ``specular_roughness``, ``specular_ior``, ``specular_weight`` and ``base_weight``;
        glTF's ``baseColorFactor`` has its alpha (1) as a fourth channel."""
        name = TARGETS[_target("Params.named", target)]
        base, rough, ior, spec, fixed = _NAMES[name]
        bc = np.asarray(self.base_color)
        if base == "baseColorFactor":
            bc = np.concatenate([bc, np.ones(bc.shape[:-1] + (1,))], axis=-1)
        out: Dict[str, Any] = {base: bc, rough: self.roughness, ior: self.ior}
        if spec is not None:
            out[spec] = self.specular
        out.update(fixed)
        return out

    @classmethod
    def from_named(cls, target: Union[str, int], parameters: MappingType[str, Any]) -> "Params":
        """The parameters of a mapping under ``target``'s own names (the ``parameters`` of
        ``pgloss bridge``'s JSON, or :meth:`named`'s output); arrays broadcast. Mitsuba has no
        specular input (1)."""
        name = TARGETS[_target("Params.from_named", target)]
        base, rough, ior, spec, _ = _NAMES[name]
        missing = [k for k in (base, rough, ior, spec) if k is not None and k not in parameters]
        if missing:
            raise ValueError(f"pgloss.bridge.Params.from_named: {name} needs {missing}")
        bc = np.asarray(parameters[base], dtype=np.float64)
        if bc.ndim == 0 or bc.shape[-1] not in (3, 4) or (bc.shape[-1] == 4 and base != "baseColorFactor"):
            raise ValueError(f"pgloss.bridge.Params.from_named: {base} must have shape (..., 3), got {bc.shape}")
        return cls(bc[..., :3], parameters[rough], parameters[ior], 1.0 if spec is None else parameters[spec])


class Mapping(NamedTuple):
    """What :func:`from_paint` returns: the target's ``params``, the paint ``(..., 5)`` they read
    as (``reached``: the requested paint to 1e-9 where reachable, else the nearest reachable
    one) and the core's ``status`` per paint (int8; 0 ok, 1 α untrusted, < 0 an error)."""

    params: Params
    reached: np.ndarray
    status: Any

    @property
    def reasons(self) -> Any:
        """The core's sentence for each status."""
        return reasons(self.status)


class Reading(NamedTuple):
    """What :func:`to_paint` returns: the ``paint`` ``(..., 5)`` the parameters read as, the
    Ward fit's relative RMS ``residual`` over the sphere's pixels (how Ward-like the target
    looks) and the core's ``status`` per element."""

    paint: np.ndarray
    residual: Any
    status: Any

    @property
    def reasons(self) -> Any:
        """The core's sentence for each status."""
        return reasons(self.status)


def _target(function: str, target: Union[str, int]) -> int:
    if isinstance(target, str):
        if target not in TARGETS:
            raise ValueError(f"pgloss.bridge.{function}: unknown target {target!r}; one of {', '.join(TARGETS)}")
        return TARGETS.index(target)
    t = int(target)
    if not 0 <= t < len(TARGETS):
        raise ValueError(f"pgloss.bridge.{function}: unknown target {target!r}; one of {', '.join(TARGETS)}")
    return t


def _errors(function: str, errors: str) -> bool:
    if errors not in _ERRORS:
        raise ValueError(f"pgloss.bridge.{function}: errors must be 'raise' or 'status', not {errors!r}")
    return errors == "status"


def _real(function: str, name: str, value: Any) -> np.ndarray:
    a = np.asarray(value)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"pgloss.bridge.{function}: {name} must be real numbers, got dtype {a.dtype}")
    return a.astype(np.float64, copy=False)


def _channels(function: str, name: str, value: Any, n: int) -> np.ndarray:
    a = _real(function, name, value)
    if a.ndim == 0 or a.shape[-1] != n:
        raise ValueError(f"pgloss.bridge.{function}: {name} must have shape (..., {n}), got {a.shape}")
    return a


def _flat(a: np.ndarray, shape: Tuple[int, ...]) -> np.ndarray:
    return np.ascontiguousarray(np.broadcast_to(a, shape), dtype=np.float64).reshape(-1)


def _shaped(a: np.ndarray, shape: Tuple[int, ...]) -> Any:
    """An output in the broadcast shape: a numpy scalar for one element."""
    a = np.asarray(a).reshape(shape + a.shape[1:])
    return a[()] if a.ndim == 0 else a


def _status(st: np.ndarray, shape: Tuple[int, ...]) -> Any:
    st = np.asarray(st, dtype=np.int8).reshape(shape)
    return int(st) if shape == () else st


def _raise_first(function: str, want_status: bool, st: np.ndarray, shape: Tuple[int, ...], result: Any) -> None:
    if want_status:
        return
    flat = np.asarray(st).reshape(-1)
    bad = np.flatnonzero(flat < 0)
    if bad.size:
        i = int(bad[0])
        index = tuple(int(x) for x in np.unravel_index(i, shape)) if shape else None
        raise PglossError(int(flat[i]), f"bridge.{function}", index, result,
                          np.asarray(st, dtype=np.int8).reshape(shape) if shape else None)


def _param_columns(function: str, params: Union[Params, MappingType[str, Any]], target: int):
    if not isinstance(params, Params):
        params = Params.from_named(target, params)
    bc = _channels(function, "base_color", params.base_color, 3)
    rough, ior, spec = (_real(function, n, v) for n, v in
                        (("roughness", params.roughness), ("ior", params.ior), ("specular", params.specular)))
    shape = np.broadcast_shapes(bc.shape[:-1], rough.shape, ior.shape, spec.shape)
    cols = [_flat(bc[..., k], shape) for k in range(3)] + [_flat(v, shape) for v in (rough, ior, spec)]
    return shape, cols


def _params_out(res: Tuple[Any, ...], shape: Tuple[int, ...]) -> Params:
    return Params(np.asarray(res[0]).reshape(shape + (3,)), _shaped(res[1], shape), _shaped(res[2], shape),
                  _shaped(res[3], shape))


def from_paint(target: Union[str, int], paint: ArrayLike, *, errors: str = "raise") -> Mapping:
    """Paints ``(..., 5)`` = (L*, a*, b*, c, d) → the ``target``'s parameters (a :class:`Mapping`).

    Where a paint is out of the target's reach, the parameters of the nearest reachable paint
    (the nearest L* first, then the nearest (c, d) in eq. 5's distance) are written, ``reached``
    holds that paint and the status names the limit met (:data:`REACH_STATUSES`). Errors of the
    paint itself (NONFINITE, LIGHTNESS, NEGATIVE, ALPHA, GAMUT, ENVELOPE, ENERGY) come first and
    leave zeros. ``errors="raise"`` raises :class:`pgloss.PglossError` at the first error (its
    ``result`` is the whole Mapping); ``errors="status"`` does not raise.
    """
    fn = "from_paint"
    want_status = _errors(fn, errors)
    t = _target(fn, target)
    p = _channels(fn, "paint", paint, 5)
    shape = p.shape[:-1]
    res = _core.bridge_from_perceptual(t, *(_flat(p[..., k], shape) for k in range(5)))
    out = Mapping(_params_out(res, shape), np.asarray(res[4]).reshape(shape + (5,)), _status(res[5], shape))
    _raise_first(fn, want_status, res[5], shape, out)
    return out


def to_paint(target: Union[str, int], params: Union[Params, MappingType[str, Any]], *,
             errors: str = "raise") -> Reading:
    """The ``target``'s parameters (a :class:`Params`, or a mapping under the target's own names
    as :meth:`Params.named` and ``pgloss bridge`` give them) → the paint ``(..., 5)`` they read as
    and the fit's residual (a :class:`Reading`). Errors: NONFINITE, NEGATIVE (a base colour
    channel, the roughness, specular or ior ≤ 0), BRIDGE_BASE (a channel above 1),
    BRIDGE_SPECULAR / BRIDGE_ROUGHNESS (F0 or α outside the tables: the reading at the nearest
    point inside is returned), ARGUMENT (gltf_core with ior ≠ 1.5 or specular ≠ 1)."""
    fn = "to_paint"
    want_status = _errors(fn, errors)
    t = _target(fn, target)
    shape, cols = _param_columns(fn, params, t)
    paint, residual, st = _core.bridge_to_perceptual(t, *cols)
    out = Reading(np.asarray(paint).reshape(shape + (5,)), _shaped(residual, shape), _status(st, shape))
    _raise_first(fn, want_status, st, shape, out)
    return out


def read(target: Union[str, int], beta: ArrayLike, f0: ArrayLike, alpha: ArrayLike, *,
         errors: str = "raise") -> Tuple[np.ndarray, Any]:
    """The gloss meter's reading ``(..., 4)`` = (ρd, ρs, α, residual) of the ``target``'s model at
    base luminance ``beta``, normal-incidence reflectance ``f0`` and microfacet ``alpha`` (not
    roughness), and the status: the interpolated tables. Outside them (BRIDGE_BASE,
    BRIDGE_SPECULAR, BRIDGE_ROUGHNESS) the reading at the nearest point inside."""
    fn = "read"
    want_status = _errors(fn, errors)
    t = _target(fn, target)
    a = [_real(fn, n, v) for n, v in (("beta", beta), ("f0", f0), ("alpha", alpha))]
    shape = np.broadcast_shapes(*(x.shape for x in a))
    out, st = _core.bridge_read(t, *(_flat(x, shape) for x in a))
    result = (np.asarray(out).reshape(shape + (4,)), _status(st, shape))
    _raise_first(fn, want_status, st, shape, result)
    return result


def model_inputs(target: Union[str, int], params: Union[Params, MappingType[str, Any]], *,
                 errors: str = "raise") -> Tuple[Any, Any, Any, Any]:
    """The conventions alone: the ``target``'s parameters → (β, F0, α, status): the base
    luminance (Rec. 709 Y of the base colour), the normal-incidence reflectance and the
    microfacet α its model renders with."""
    fn = "model_inputs"
    want_status = _errors(fn, errors)
    t = _target(fn, target)
    shape, cols = _param_columns(fn, params, t)
    beta, f0, alpha, st = _core.bridge_model_inputs(t, *cols)
    result = (_shaped(beta, shape), _shaped(f0, shape), _shaped(alpha, shape), _status(st, shape))
    _raise_first(fn, want_status, st, shape, result)
    return result


def params_from_model(target: Union[str, int], base_color: ArrayLike, f0: ArrayLike, alpha: ArrayLike, *,
                      errors: str = "raise") -> Tuple[Params, Any]:
    """And back: a linear Rec. 709 ``base_color`` ``(..., 3)``, ``f0`` and microfacet ``alpha`` →
    (the ``target``'s :class:`Params`, status), by the rules of ``pgloss_bridge_params_from_model``
    (OpenPBR: specular_weight = F0 / 0.04 at IOR 1.5; glTF: specularFactor up to F0 0.04, the IOR
    above; Standard Surface, Principled and Mitsuba: the IOR)."""
    fn = "params_from_model"
    want_status = _errors(fn, errors)
    t = _target(fn, target)
    bc = _channels(fn, "base_color", base_color, 3)
    f, a = _real(fn, "f0", f0), _real(fn, "alpha", alpha)
    shape = np.broadcast_shapes(bc.shape[:-1], f.shape, a.shape)
    res = _core.bridge_params_from_model(t, *(_flat(bc[..., k], shape) for k in range(3)), _flat(f, shape),
                                         _flat(a, shape))
    result = (_params_out(res, shape), _status(res[4], shape))
    _raise_first(fn, want_status, res[4], shape, result)
    return result


def target_range(target: Union[str, int]) -> Tuple[float, float, float, float]:
    """(F0 min, F0 max, α min, α max) a target reaches (its tables' box within its own limits)."""
    f0_min, f0_max, a_min, a_max, st = _core.bridge_range(_target("target_range", target))
    if st < 0:
        raise PglossError(st, "bridge.target_range")
    return f0_min, f0_max, a_min, a_max


__all__: List[str] = ["TARGETS", "ERR_BRIDGE_BASE", "ERR_BRIDGE_SPECULAR", "ERR_BRIDGE_ROUGHNESS", "REACH_STATUSES",
                      "Params", "Mapping", "Reading", "reasons", "status_names", "from_paint",
                      "to_paint", "read", "model_inputs", "params_from_model", "target_range"]
