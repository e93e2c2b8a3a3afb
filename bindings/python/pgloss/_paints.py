# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The paints: :class:`Physical` (eq. 2's parameters) and :class:`Perceptual` (Fig. 13's
L*, a*, b*, c, d), one paint or an array of paints, and the conversions and checks between
them."""

from __future__ import annotations

import math
from typing import Any, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import Material
from ._inputs import (_F32_MAX, ArrayLike, _as_real, _channels, _color_space, _float, _normalization, _out_dtype,
                      _shape_out)
from ._perceptual import gloss_distance
from ._status import ColorSpace, Normalization, PglossError, _errors, _finish, _status_out, _verdict


def _field(function: str, name: str, v: Any) -> Union[float, np.ndarray]:
    """A scalar field as a float (as before arrays were accepted), an array field as a
    read-only float64 copy (the object is immutable, whatever the caller does to its array)."""
    if np.ndim(v) == 0 and not isinstance(v, np.ndarray):
        return _float(function, name, v)
    a = np.array(_as_real(function, name, v), dtype=np.float64)
    if a.ndim == 0:
        return float(a)
    a.flags.writeable = False
    return a


def _broadcast_fields(function: str, names: Sequence[str], fields: Sequence[Any],
                      shapes: Sequence[Tuple[int, ...]]) -> Tuple[int, ...]:
    try:
        return tuple(np.broadcast_shapes(*shapes))
    except ValueError:
        what = ", ".join(f"{n}{s}" for n, s in zip(names, shapes))
        raise ValueError(f"pgloss.{function}: fields do not broadcast: {what}") from None


def _view(a: Union[float, np.ndarray], shape: Tuple[int, ...]) -> np.ndarray:
    """A read-only broadcast view of a field (no copy)."""
    return np.broadcast_to(np.asarray(a, dtype=np.float64), shape)


def _flat(a: Union[float, np.ndarray], shape: Tuple[int, ...]) -> np.ndarray:
    """A field as a flat float64 array of the broadcast shape: a view where numpy can make one
    (stride 0 for one value), as the core's strided batches read it."""
    return _view(a, shape).reshape(-1)


def _to_float32(fields: Sequence[Any], shape: Tuple[int, ...]) -> np.ndarray:
    """Fields (floats or arrays broadcasting to ``shape``) rounded to float as the C API receives
    them, as one (len(fields),) + shape float32 block: beyond float range ±inf (a cast rounds the
    doubles just above FLT_MAX down to it, which is checked where the cast gave ±FLT_MAX)."""
    block = np.empty((len(fields),) + shape, np.float32)
    with np.errstate(over="ignore"):
        for k, x in enumerate(fields):
            np.copyto(block[k], x, casting="unsafe")
    edge = np.abs(block) == _F32_MAX
    if edge.any():
        wide = np.stack([_view(x, shape) for x in fields])[edge]
        block[edge] = np.where(np.abs(wide) > _F32_MAX, np.copysign(np.inf, wide), wide)
    return block


def _index_of(shape: Tuple[int, ...], key: Any) -> np.ndarray:
    """numpy's indexing of an array of ``shape``, as flat positions (every index numpy accepts)."""
    return np.arange(int(np.prod(shape, dtype=np.int64)), dtype=np.intp).reshape(shape)[key]


def _array_repr(a: np.ndarray) -> str:
    return np.array2string(np.asarray(a), separator=", ", threshold=8, edgeitems=2, precision=6)


class _PaintShape:
    """The shape of one paint or an array of paints (a texture), shared by Physical and
    Perceptual; ``_shape`` is None for one paint."""

    __slots__ = ()
    _shape: Optional[Tuple[int, ...]]

    @property
    def shape(self) -> Tuple[int, ...]:
        """``()`` for one paint, else the broadcast shape of the fields."""
        return () if self._shape is None else self._shape

    @property
    def ndim(self) -> int:
        """``len(shape)``."""
        return len(self.shape)

    @property
    def size(self) -> int:
        """Number of paints (1 for a scalar)."""
        return int(np.prod(self.shape, dtype=np.int64))

    @property
    def is_array(self) -> bool:
        """True for an array of paints (even of shape ``(1,)``)."""
        return self._shape is not None


class Physical(_PaintShape):
    """Physical parameters of the BRDF (``pgloss_physical``, paper eq. 2): one paint, or an
    array of paints (a texture).

    Parameters
    ----------
    rho_d : float, sequence of 3 floats, or array_like (..., 3)
        Diffuse reflectance, linear RGB of the working space (default Rec. 709). A single
        number means grey; for arrays the last axis is the colour channel (size 3, or 1 for grey).
    rho_s : float or array_like
        Specular energy (achromatic).
    alpha : float or array_like, optional
        Lobe spread α of the paper (isotropic: αx = αy = α).
    alpha_x, alpha_y : float or array_like, optional
        Anisotropic spreads (Ward 1992); keyword-only, instead of ``alpha``.
        ``alpha_y`` defaults to ``alpha_x``.
    normalization : Normalization or int
        Normalisation of the specular lobe (default: the paper's eq. 2, ``WARD``); one value
        for the whole array.

    Notes
    -----
    The fields broadcast against each other (``rho_d`` without its channel axis): the result
    is a scalar paint when every field is a number (and ``rho_d`` a number or 3 numbers),
    else an array of paints of the broadcast :attr:`shape`. Array fields are copied and
    read-only: the object is immutable. As one paint compiles its :class:`Material` once, an
    array of paints rounds its parameters to float once, on its first :func:`eval`,
    :func:`pdf`, :func:`eval_pdf` or :func:`sample` call, and keeps them (half the memory of
    its float64 fields): later calls read them as they are.

    A ``Physical`` is a record, like the C struct: it holds any numbers. Whether they make a
    material is decided by the core where they are used — :meth:`material` (and so
    :func:`eval`…) raises :class:`PglossError` for NaN, negative reflectances, α ≤ 0 or an
    unknown normalisation; :meth:`check` says whether they lie inside the paper's model
    (energy ρd + ρs ≤ 1, α ≤ 0.2).

    Scalar paints have value equality, a hash and a ``repr`` that rebuilds them. Array paints
    have :attr:`shape`, :attr:`ndim`, :attr:`size`, ``len()``, iteration over the first axis
    and numpy indexing (``m[i, j]`` is a scalar ``Physical``, ``m[2:5]`` an array one); ``==``
    is one bool (same shape, normalisation and fields); they are not hashable.

    Examples
    --------
    >>> p = Physical(0.193, 0.066, 0.07)          # grey stimulus of Experiment 1
    >>> q = p.to_perceptual()                      # L*, a*, b*, c, d
    >>> round(q.c, 3), round(q.d, 2)
    (0.087, 0.93)
    >>> tex = Physical(0.193, [0.033, 0.066, 0.099], 0.07)
    >>> tex.shape, tex[1] == p
    ((3,), True)
    """

    __slots__ = ("_rho_d", "_rho_s", "_alpha_x", "_alpha_y", "_normalization", "_material", "_block", "_shape")

    def __init__(self, rho_d: Union[float, Sequence[float], ArrayLike], rho_s: Union[float, ArrayLike],
                 alpha: Optional[Union[float, ArrayLike]] = None, *,
                 alpha_x: Optional[Union[float, ArrayLike]] = None, alpha_y: Optional[Union[float, ArrayLike]] = None,
                 normalization: Union[Normalization, int] = Normalization.WARD) -> None:
        fn = "Physical"
        rd: Any
        if np.ndim(rho_d) == 0:
            g = _float(fn, "rho_d", rho_d)
            rd = (g, g, g)
        elif np.ndim(rho_d) == 1 and not isinstance(rho_d, np.ndarray) and len(rho_d) == 3:  # type: ignore[arg-type]
            rd = tuple(_float(fn, "rho_d", x) for x in rho_d)  # type: ignore[union-attr]
        else:
            a = _as_real(fn, "rho_d", rho_d)
            if a.shape[-1] not in (1, 3):
                raise ValueError(f"pgloss.{fn}: rho_d must be a number, 3 numbers (r, g, b) or an array whose last "
                                 f"axis is the channel (size 3, or 1 for grey), got shape {a.shape}")
            if a.ndim == 1:
                rd = tuple(float(x) for x in np.broadcast_to(a, (3,)))
            else:  # stored channel-first, (3,) + shape: each channel a contiguous column for the core
                rd = np.array(np.broadcast_to(np.moveaxis(a, -1, 0), (3,) + a.shape[:-1]), dtype=np.float64,
                              order="C", copy=True)
                rd.flags.writeable = False
        if alpha is not None:
            if alpha_x is not None or alpha_y is not None:
                raise TypeError(f"pgloss.{fn}: give alpha, or alpha_x and alpha_y, not both")
            ax = ay = _field(fn, "alpha", alpha)
        elif alpha_x is not None:
            ax = _field(fn, "alpha_x", alpha_x)
            ay = ax if alpha_y is None else _field(fn, "alpha_y", alpha_y)
        else:
            raise TypeError(f"pgloss.{fn}: missing alpha (or alpha_x, alpha_y)")
        rs = _field(fn, "rho_s", rho_s)
        self._normalization = _normalization(fn, normalization)
        self._material: Optional[Material] = None
        self._block: Optional[np.ndarray] = None
        rd_shape = rd.shape[1:] if isinstance(rd, np.ndarray) else ()
        shapes = [rd_shape, np.shape(rs), np.shape(ax), np.shape(ay)]
        if not any(shapes):
            self._shape: Optional[Tuple[int, ...]] = None
            self._rho_d = rd
            self._rho_s, self._alpha_x, self._alpha_y = rs, ax, ay
            return
        shape = _broadcast_fields(fn, ("rho_d", "rho_s", "alpha_x", "alpha_y"), (rd, rs, ax, ay), shapes)
        self._set_arrays(shape, rd, rs, ax, ay)

    def _set_arrays(self, shape: Tuple[int, ...], rd: Any, rs: Any, ax: Any, ay: Any) -> None:
        """Array storage: ``_rho_d`` channel-first (3,) + shape, the others of ``shape``; all
        read-only (broadcast views where a field was smaller)."""
        self._shape = shape
        rd3 = np.asarray(rd, dtype=np.float64)
        if rd3.ndim == 1:  # one colour for all
            rd3 = rd3.reshape((3,) + (1,) * len(shape))
        self._rho_d = np.broadcast_to(rd3, (3,) + shape)
        self._rho_s, self._alpha_x, self._alpha_y = (_view(v, shape) for v in (rs, ax, ay))

    @classmethod
    def _adopt(cls, rd3: np.ndarray, rs: np.ndarray, ax: np.ndarray, ay: np.ndarray,
               normalization: Union[Normalization, int]) -> "Physical":
        """An array Physical over new arrays the caller gives up (a conversion's outputs): no
        copy. rd3: (3,) + shape."""
        self = cls.__new__(cls)
        for x in (rd3, rs, ax, ay):
            x.flags.writeable = False
        self._normalization = normalization
        self._material = None
        self._block = None
        self._set_arrays(tuple(rs.shape), rd3, rs, ax, ay)
        return self

    @classmethod
    def stack(cls, paints: Sequence[Union["Physical", Material]]) -> "Physical":
        """An array ``Physical`` of shape ``(len(paints),) + paints[0].shape`` from scalar
        (or equal-shaped array) ``Physical`` or :class:`Material` objects, which must share
        one normalisation."""
        fn = "Physical.stack"
        items = []
        for k, p in enumerate(paints):
            if isinstance(p, Material):
                v, nrm = p.parameters
                p = Physical(v[0:3], v[3], alpha_x=v[4], alpha_y=v[5], normalization=nrm)
            if not isinstance(p, Physical):
                raise TypeError(f"pgloss.{fn}: element {k} is a {type(p).__name__}, not a pgloss.Physical")
            items.append(p)
        if not items:
            raise ValueError(f"pgloss.{fn}: no paints")
        norms = {int(p._normalization) for p in items}
        if len(norms) > 1:
            raise ValueError(f"pgloss.{fn}: the paints have different normalizations {sorted(norms)}; an array of "
                             f"paints has one")
        try:
            rd = np.stack([np.broadcast_to(np.asarray(p.rho_d, dtype=np.float64), p.shape + (3,)) for p in items])
            f = [np.stack([_view(getattr(p, a), p.shape) for p in items]) for a in ("_rho_s", "_alpha_x", "_alpha_y")]
        except ValueError:
            raise ValueError(f"pgloss.{fn}: the paints differ in shape") from None
        return cls(rd, f[0], alpha_x=f[1], alpha_y=f[2], normalization=items[0]._normalization)

    # Fields ---------------------------------------------------------------------------------
    @property
    def rho_d(self) -> Any:
        """Diffuse reflectance (r, g, b), linear RGB; an array ``shape + (3,)`` for arrays (a
        read-only view of the channel-first storage)."""
        if self._shape is not None:
            return np.moveaxis(self._rho_d, 0, -1)
        return self._rho_d

    @property
    def rho_s(self) -> Any:
        """Specular energy ρs (a float, or an array of :attr:`shape`)."""
        return self._rho_s

    @property
    def alpha_x(self) -> Any:
        """Lobe spread along x."""
        return self._alpha_x

    @property
    def alpha_y(self) -> Any:
        """Lobe spread along y."""
        return self._alpha_y

    @property
    def alpha(self) -> Any:
        """α of the paper: αx when isotropic, else √(αx αy) (the core's extension of eq. 3)."""
        if self._shape is not None:
            ax, ay = self._alpha_x, self._alpha_y
            with np.errstate(invalid="ignore"):
                return np.where(ax == ay, ax, np.sqrt(ax * ay))
        if self._alpha_x == self._alpha_y:
            return self._alpha_x
        return math.sqrt(self._alpha_x * self._alpha_y)

    @property
    def is_isotropic(self) -> bool:
        """αx == αy (for every paint of an array)."""
        if self._shape is not None:
            return bool(np.array_equal(self._alpha_x, self._alpha_y))
        return self._alpha_x == self._alpha_y

    @property
    def normalization(self) -> Union[Normalization, int]:
        """Normalisation of the specular lobe (a plain int if unknown to this version)."""
        return self._normalization

    def _fields(self) -> Tuple[float, float, float, float, float, float]:
        return (*self._rho_d, self._rho_s, self._alpha_x, self._alpha_y)

    def _core_arrays(self, shape: Optional[Tuple[int, ...]] = None, dtype: Any = np.float64) -> Tuple[Any, ...]:
        """The paints as the core's batches read them (``pgloss_physical_array``): ρd as a
        (3, n) array, ρs, αx, αy as (n,) arrays, broadcast to ``shape`` (default the paints' own;
        n = its size) as views where numpy can (stride 0 for a field of one value), and the
        normalisation.

        ``dtype`` float64: the fields themselves. float32 (the float batch reads float32
        parameters): the fields rounded to float, beyond float range ±inf (which the core
        reports as NONFINITE, as ``pgloss_material_init`` does for a double beyond FLT_MAX),
        built on the first float32 call and kept, as one paint's :class:`Material` is: the
        fields are read-only copies, so it cannot go stale, and a texture evaluated many times
        is rounded once."""
        shape = self.shape if shape is None else shape
        if dtype == np.float32:
            if self._block is None:
                block = _to_float32(self._six(), self.shape)
                block.flags.writeable = False
                self._block = block
            rd, *rest = self._block[0:3], *self._block[3:]
        else:
            rd, *rest = np.asarray(self._rho_d, dtype=np.float64), self._rho_s, self._alpha_x, self._alpha_y
        lead = (1,) * (len(shape) - self.ndim)
        rd = np.broadcast_to(np.reshape(rd, (3,) + lead + self.shape), (3,) + shape).reshape(3, -1)
        rest = [np.broadcast_to(np.reshape(np.asarray(x, dtype=dtype), lead + self.shape), shape).reshape(-1)
                for x in rest]
        return (rd, *rest, int(self._normalization))

    def _six(self) -> List[Any]:
        """ρd r, g, b, ρs, αx, αy (floats, or arrays of the paints' shape)."""
        return [*self._rho_d, self._rho_s, self._alpha_x, self._alpha_y]

    # Conversions ------------------------------------------------------------------------------
    def material(self) -> Material:
        """The evaluation-ready :class:`Material` (``pgloss_material_init``), built once and cached.

        Raises :class:`PglossError` (NONFINITE, NEGATIVE, ALPHA, NORMALIZATION), and
        ``TypeError`` for an array of paints (pass it to :func:`eval` & co. directly)."""
        if self._shape is not None:
            raise TypeError(f"pgloss.Physical.material: an array of paints (shape {self._shape}) has no single "
                            f"Material; pass it to pgloss.eval, pdf, eval_pdf or sample directly")
        if self._material is None:
            m, st = _core.material_init(self._fields(), int(self._normalization))
            if st < 0:
                raise PglossError(st, "material_init", None, m)
            self._material = m
        return self._material

    def check(self) -> Any:
        """Is this inside the paper's model? The first reason it is not, or ``Status.OK``
        (``pgloss_check_physical``: NONFINITE, NEGATIVE, ALPHA, NORMALIZATION, ENERGY, then the
        warning WARN_ALPHA_UNTRUSTED). Never raises for a bad value: it reports it. For an
        array of paints, an int8 array of :class:`Status` values of :attr:`shape`."""
        return check_physical(self)

    def to_perceptual(self, space: Union[ColorSpace, int] = ColorSpace.LINEAR_REC709, *,
                      errors: str = "raise", check: bool = True) -> Any:
        """L*a*b* of ρd, c (eq. 4) and d (eq. 3): :func:`perceptual_from_physical`, with its
        ``check`` (default: the core's verdict on the paint, ENERGY included) and ``errors``
        (``"status"`` returns ``(Perceptual, status)`` instead of raising)."""
        return perceptual_from_physical(self, space, errors=errors, check=check)

    def distance(self, other: Union["Physical", "Perceptual"]) -> Any:
        """Gloss difference to another paint (eq. 5), from both paints' c and d
        (:meth:`to_perceptual`, which raises for a paint outside the model)."""
        return _paint_distance(self, other)

    def to_array(self) -> np.ndarray:
        """The paint(s) as one channel-last float64 array of shape ``shape + (6,)``: ρd r, g, b,
        ρs, αx, αy (the layout of images in numpy, OpenImageIO and colour-science).
        :meth:`from_array` reads it back."""
        if self._shape is None:
            return np.array(self._fields(), dtype=np.float64)
        out = np.empty(self._shape + (6,), dtype=np.float64)
        out[..., 0:3] = self.rho_d
        for k, v in enumerate((self._rho_s, self._alpha_x, self._alpha_y)):
            out[..., 3 + k] = v
        return out

    @classmethod
    def from_array(cls, array: ArrayLike, normalization: Union[Normalization, int] = Normalization.WARD
                   ) -> "Physical":
        """Paints from a channel-last array ``(..., 6)`` of ρd r, g, b, ρs, αx, αy (as
        :meth:`to_array` writes it): one paint for shape ``(6,)``, else an array of paints of
        shape ``array.shape[:-1]``."""
        a = _channels("Physical.from_array", "array", array, 6)
        if a.ndim == 1:
            v = [float(x) for x in a]
            return cls(v[0:3], v[3], alpha_x=v[4], alpha_y=v[5], normalization=normalization)
        return cls(a[..., 0:3], a[..., 3], alpha_x=a[..., 4], alpha_y=a[..., 5], normalization=normalization)

    def replace(self, **changes: Any) -> "Physical":
        """A copy with some fields changed (``rho_d``, ``rho_s``, ``alpha``, ``alpha_x``,
        ``alpha_y``, ``normalization``)."""
        kw: dict = dict(rho_d=self.rho_d, rho_s=self._rho_s, alpha_x=self._alpha_x, alpha_y=self._alpha_y,
                        normalization=self._normalization)
        if "alpha" in changes:
            kw.pop("alpha_x"), kw.pop("alpha_y")
        kw.update(changes)
        rho_d, rho_s = kw.pop("rho_d"), kw.pop("rho_s")
        return Physical(rho_d, rho_s, **kw)

    # Array protocol ---------------------------------------------------------------------------
    def __len__(self) -> int:
        if self._shape is None or not self._shape:
            raise TypeError("len() of a single pgloss.Physical (it is not an array of paints)")
        return self._shape[0]

    def __getitem__(self, key: Any) -> "Physical":
        if self._shape is None:
            raise TypeError("a single pgloss.Physical is not indexable (it is not an array of paints)")
        sel = _index_of(self._shape, key)
        rd = np.stack([np.asarray(self._rho_d[k]).reshape(-1)[sel] for k in range(3)], axis=-1)
        f = [np.asarray(v).reshape(-1)[sel] for v in (self._rho_s, self._alpha_x, self._alpha_y)]
        if sel.ndim == 0:
            return Physical(tuple(float(x) for x in rd), float(f[0]), alpha_x=float(f[1]), alpha_y=float(f[2]),
                            normalization=self._normalization)
        return Physical(rd, f[0], alpha_x=f[1], alpha_y=f[2], normalization=self._normalization)

    def __iter__(self):
        for k in range(len(self)):
            yield self[k]

    # Protocols ----------------------------------------------------------------------------------
    def __repr__(self) -> str:
        nm = self._normalization
        ns = f"Normalization.{nm.name}" if isinstance(nm, Normalization) else repr(nm)
        if self._shape is not None:
            al = (f"alpha={_array_repr(self._alpha_x)}" if self.is_isotropic
                  else f"alpha_x={_array_repr(self._alpha_x)}, alpha_y={_array_repr(self._alpha_y)}")
            return (f"Physical(rho_d={_array_repr(self.rho_d)}, rho_s={_array_repr(self._rho_s)}, {al}, "
                    f"normalization={ns})  # shape {self._shape}")
        rd = self._rho_d
        rd_s = repr(rd[0]) if rd[0] == rd[1] == rd[2] else f"({rd[0]!r}, {rd[1]!r}, {rd[2]!r})"
        al = (f"alpha={self._alpha_x!r}" if self.is_isotropic
              else f"alpha_x={self._alpha_x!r}, alpha_y={self._alpha_y!r}")
        return f"Physical(rho_d={rd_s}, rho_s={self._rho_s!r}, {al}, normalization={ns})"

    def _key(self):
        return (self._fields(), int(self._normalization))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Physical):
            return NotImplemented
        if self._shape is None and other._shape is None:
            return self._key() == other._key()
        if self._shape != other._shape or int(self._normalization) != int(other._normalization):
            return False
        return all(bool(np.array_equal(_view(a, self.shape), _view(b, self.shape)))
                   for a, b in zip(self._six(), other._six()))

    def __hash__(self) -> int:
        if self._shape is not None:
            raise TypeError("unhashable type: an array of pgloss.Physical (like numpy arrays)")
        return hash(("pgloss.Physical",) + self._key())

    def __reduce__(self):
        if self._shape is not None:
            return (_make_physical, (np.ascontiguousarray(self.rho_d), np.ascontiguousarray(self._rho_s),
                                     np.ascontiguousarray(self._alpha_x), np.ascontiguousarray(self._alpha_y),
                                     int(self._normalization)))
        return (_make_physical, (self._rho_d, self._rho_s, self._alpha_x, self._alpha_y, int(self._normalization)))


def _make_physical(rho_d, rho_s, alpha_x, alpha_y, normalization) -> Physical:
    return Physical(rho_d, rho_s, alpha_x=alpha_x, alpha_y=alpha_y, normalization=normalization)


_PERCEPTUAL_FIELDS = ("L", "a", "b", "c", "d")


class Perceptual(_PaintShape):
    """The paper's five-parameter colour/gloss description (Fig. 13, ``pgloss_perceptual``):
    one paint, or an array of paints (a texture).

    Parameters
    ----------
    L : float or array_like
        CIELAB lightness L* in [0, 100] of the diffuse colour.
    a, b : float or array_like
        CIELAB a*, b* (D65); 0, 0 is grey.
    c : float or array_like
        Contrast gloss (eq. 4), ≥ 0.
    d : float or array_like
        Distinctness-of-image gloss (eq. 3), < 1; the paper trusts d ≥ 0.8.

    Notes
    -----
    The fields broadcast against each other: all numbers give one paint, any array an array
    of paints of the broadcast :attr:`shape` (with ``shape``, ``len()``, indexing and
    iteration as :class:`Physical`; not hashable). An immutable record, like the C struct;
    :meth:`check` says whether it lies inside the model (gamut, envelope, energy),
    :meth:`to_physical` converts (eqs. 6–8) or raises.

    Examples
    --------
    >>> q = Perceptual(L=35.0, a=45.0, b=25.0, c=0.06, d=0.95)   # a dark red paint
    >>> p = q.to_physical()
    >>> round(p.alpha, 6)
    0.05
    >>> Perceptual(L=[30.0, 60.0], a=0.0, b=0.0, c=0.05, d=0.95).to_physical().rho_s.shape
    (2,)
    """

    __slots__ = ("_v", "_shape")

    def __init__(self, L: Union[float, ArrayLike], a: Union[float, ArrayLike], b: Union[float, ArrayLike],
                 c: Union[float, ArrayLike], d: Union[float, ArrayLike]) -> None:
        fn = "Perceptual"
        v = tuple(_field(fn, n, x) for n, x in zip(_PERCEPTUAL_FIELDS, (L, a, b, c, d)))
        shapes = [np.shape(x) for x in v]
        if not any(isinstance(x, np.ndarray) for x in v):
            self._shape: Optional[Tuple[int, ...]] = None
            self._v: Tuple[Any, ...] = v
            return
        shape = _broadcast_fields(fn, _PERCEPTUAL_FIELDS, v, shapes)
        self._shape = shape
        self._v = tuple(_view(x, shape) for x in v)

    @classmethod
    def _adopt(cls, cols: Sequence[np.ndarray]) -> "Perceptual":
        """An array Perceptual over new arrays the caller gives up (a conversion's outputs): no copy."""
        self = cls.__new__(cls)
        for x in cols:
            x.flags.writeable = False
        self._shape = tuple(cols[0].shape)
        self._v = tuple(cols)
        return self

    @classmethod
    def achromatic(cls, L: Union[float, ArrayLike], c: Union[float, ArrayLike],
                   d: Union[float, ArrayLike]) -> "Perceptual":
        """A grey paint (a* = b* = 0): the paper's three-parameter model (L, c, d)."""
        return cls(L, 0.0, 0.0, c, d)

    @classmethod
    def stack(cls, paints: Sequence["Perceptual"]) -> "Perceptual":
        """An array ``Perceptual`` of shape ``(len(paints),) + paints[0].shape``."""
        items = list(paints)
        if not items or not all(isinstance(p, Perceptual) for p in items):
            raise TypeError("pgloss.Perceptual.stack: expected a non-empty sequence of pgloss.Perceptual")
        try:
            cols = [np.stack([_view(p._v[k], p.shape) for p in items]) for k in range(5)]
        except ValueError:
            raise ValueError("pgloss.Perceptual.stack: the paints differ in shape") from None
        return cls(*cols)

    @property
    def L(self) -> Any:
        """CIELAB lightness L*."""
        return self._v[0]

    @property
    def a(self) -> Any:
        """CIELAB a*."""
        return self._v[1]

    @property
    def b(self) -> Any:
        """CIELAB b*."""
        return self._v[2]

    @property
    def c(self) -> Any:
        """Contrast gloss (eq. 4)."""
        return self._v[3]

    @property
    def d(self) -> Any:
        """Distinctness-of-image gloss (eq. 3)."""
        return self._v[4]

    def _core_arrays(self) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The paints as the core's batches read them (``pgloss_perceptual_array``): L*, a*, b*,
        c and d as (n,) views, each of its own strides (no copy)."""
        return tuple(_flat(x, self.shape) for x in self._v[0:5])  # type: ignore[return-value]

    def check(self, space: Union[ColorSpace, int] = ColorSpace.LINEAR_REC709) -> Any:
        """Is this inside the model? First reason it is not (``pgloss_check_perceptual``:
        NONFINITE, LIGHTNESS, NEGATIVE, ALPHA, GAMUT, ENVELOPE, ENERGY, then the warning
        WARN_ALPHA_UNTRUSTED), or ``Status.OK``. Never raises for a bad value. For an array
        of paints, an int8 array of :class:`Status` values of :attr:`shape`."""
        return check_perceptual(self, space)

    def to_physical(self, normalization: Union[Normalization, int] = Normalization.WARD,
                    space: Union[ColorSpace, int] = ColorSpace.LINEAR_REC709, *, errors: str = "raise",
                    check: bool = True) -> Any:
        """ρd (linear RGB), ρs (eq. 7), α = 1 − d (eq. 8): :func:`physical_from_perceptual`,
        with its ``check`` (default: the core's verdict on the paint, ENVELOPE and ENERGY
        included) and ``errors`` (``"status"`` returns ``(Physical, status)`` instead of
        raising)."""
        return physical_from_perceptual(self, normalization, space, errors=errors, check=check)

    def distance(self, other: Union["Perceptual", Physical]) -> Any:
        """Gloss difference to another paint, D = √(Δc² + (1.78 Δd)²) (eq. 5); a
        :class:`Physical` ``other`` through its c and d (:meth:`Physical.to_perceptual`)."""
        return _paint_distance(self, other)

    def to_array(self) -> np.ndarray:
        """The paint(s) as one channel-last float64 array of shape ``shape + (5,)``: L*, a*, b*,
        c, d. :meth:`from_array` reads it back."""
        if self._shape is None:
            return np.array(self._v, dtype=np.float64)
        out = np.empty(self._shape + (5,), dtype=np.float64)
        for k, v in enumerate(self._v):
            out[..., k] = v
        return out

    @classmethod
    def from_array(cls, array: ArrayLike) -> "Perceptual":
        """Paints from a channel-last array ``(..., 5)`` of L*, a*, b*, c, d (an image of paints,
        as numpy, OpenImageIO and colour-science lay images out): one paint for shape ``(5,)``,
        else an array of paints of shape ``array.shape[:-1]``."""
        a = _channels("Perceptual.from_array", "array", array, 5)
        if a.ndim == 1:
            return cls(*(float(x) for x in a))
        return cls(*(a[..., k] for k in range(5)))

    def replace(self, **changes: Any) -> "Perceptual":
        """A copy with some of L, a, b, c, d changed."""
        kw = dict(zip(_PERCEPTUAL_FIELDS, self._v))
        unknown = set(changes) - set(kw)
        if unknown:
            raise TypeError(f"pgloss.Perceptual.replace: unknown fields {sorted(unknown)}")
        kw.update(changes)
        return Perceptual(**kw)

    def __len__(self) -> int:
        if self._shape is None or not self._shape:
            raise TypeError("len() of a single pgloss.Perceptual (it is not an array of paints)")
        return self._shape[0]

    def __getitem__(self, key: Any) -> "Perceptual":
        if self._shape is None:
            raise TypeError("a single pgloss.Perceptual is not indexable (it is not an array of paints)")
        sel = _index_of(self._shape, key)
        v = [np.asarray(x).reshape(-1)[sel] for x in self._v]
        if sel.ndim == 0:
            return Perceptual(*(float(x) for x in v))
        return Perceptual(*v)

    def __iter__(self):
        for k in range(len(self)):
            yield self[k]

    def __repr__(self) -> str:
        if self._shape is not None:
            body = ", ".join(f"{n}={_array_repr(x)}" for n, x in zip(_PERCEPTUAL_FIELDS, self._v))
            return f"Perceptual({body})  # shape {self._shape}"
        L, a, b, c, d = self._v
        return f"Perceptual(L={L!r}, a={a!r}, b={b!r}, c={c!r}, d={d!r})"

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Perceptual):
            return NotImplemented
        if self._shape is None and other._shape is None:
            return self._v == other._v
        if self._shape != other._shape:
            return False
        return all(bool(np.array_equal(x, y)) for x, y in zip(self._v, other._v))

    def __hash__(self) -> int:
        if self._shape is not None:
            raise TypeError("unhashable type: an array of pgloss.Perceptual (like numpy arrays)")
        return hash(("pgloss.Perceptual",) + self._v)

    def __reduce__(self):
        if self._shape is not None:
            return (Perceptual, tuple(np.ascontiguousarray(x) for x in self._v))
        return (Perceptual, self._v)


def _paint_distance(a: Union[Physical, Perceptual], b: Union[Physical, Perceptual]) -> Any:
    """Eq. 5 between two paints, each through its c and d."""
    cd = []
    for p in (a, b):
        if isinstance(p, Physical):
            p = p.to_perceptual()
        if not isinstance(p, Perceptual):
            raise TypeError(f"pgloss: distance to a pgloss.Physical or pgloss.Perceptual, not {type(p).__name__}")
        cd += [p.c, p.d]
    return gloss_distance(*cd)


# ---------------------------------------------------------------------------------------------
# Checks and conversions (one paint or an array of paints, or a channel-last array of them; the
# batched C functions of pgloss/perceptual_batch.h, a status per element).

_PHYSICAL_CHANNELS = "rho_d r, g, b, rho_s, alpha_x, alpha_y"
_PERCEPTUAL_CHANNELS = "L*, a*, b*, c, d"


def _paint_arg(function: str, value: Any, cls: type) -> Tuple[Any, Optional[np.dtype]]:
    """A paint of type ``cls``, or a channel-last array of them (Physical: (..., 6), Perceptual:
    (..., 5)) read with ``cls.from_array``; with the dtype of the array to return (None: return
    a paint)."""
    if isinstance(value, cls):
        return value, None
    n, what = (6, _PHYSICAL_CHANNELS) if cls is Physical else (5, _PERCEPTUAL_CHANNELS)
    if isinstance(value, (_PaintShape, Material)) or isinstance(value, (str, bytes, dict)):
        raise TypeError(f"pgloss.{function}: expected a pgloss.{cls.__name__} or an array (..., {n}) of "
                        f"{what}, not {type(value).__name__}")
    a = _channels(function, cls.__name__.lower(), value, n)
    return cls.from_array(a), _out_dtype((value,), (a,))


def _paint_out(function: str, paint: Any, dtype: Optional[np.dtype]) -> Any:
    """A conversion's result as its caller gave the input: a paint, or a channel-last array."""
    if dtype is None:
        return paint
    a = paint.to_array()
    return _shape_out(function, a, a.shape, dtype)


def check_physical(physical: Union[Physical, ArrayLike]) -> Any:
    """Is ``physical`` inside the paper's model? Returns the first reason it is not, in this
    order: NONFINITE, NEGATIVE, ALPHA, NORMALIZATION, ENERGY (max over channels of
    ρd + ρs > 1), then WARN_ALPHA_UNTRUSTED (max(αx, αy) > 0.2); ``Status.OK`` otherwise
    (``pgloss_check_physical``). Reports, never raises, for bad values.

    For an array of paints, or a channel-last array ``(..., 6)`` of (ρd r, g, b, ρs, αx, αy)
    (normalisation ``WARD``): an int8 array of :class:`Status` values, of the paints' shape
    (``pgloss_check_physical_batch``)."""
    physical, _ = _paint_arg("check_physical", physical, Physical)
    st = np.empty(physical.size, np.int8)
    _core.check_physical(physical._core_arrays(), st)
    return _status_out(st, physical.shape)


def check_perceptual(perceptual: Union[Perceptual, ArrayLike],
                     space: Union[ColorSpace, int] = ColorSpace.LINEAR_REC709) -> Any:
    """Is ``perceptual`` inside the model? First reason it is not, in this order: NONFINITE,
    LIGHTNESS, NEGATIVE (c < 0), ALPHA (d ≥ 1), GAMUT (no non-negative linear RGB),
    ENVELOPE (c beyond the envelope at L), ENERGY (a colour channel of ρd plus ρs exceeds 1),
    then WARN_ALPHA_UNTRUSTED (d < 0.8); ``Status.OK`` otherwise (``pgloss_check_perceptual_ex``).
    GAMUT and ENERGY are decided in the working ``space``; an unknown space gives ERR_ARGUMENT.

    For an array of paints, or a channel-last array ``(..., 5)`` of (L*, a*, b*, c, d): an int8
    array of :class:`Status` values, of the paints' shape (``pgloss_check_perceptual_batch_ex``)
    — the way to find the texels of a texture that are out of gamut or beyond the envelope
    without an exception."""
    perceptual, _ = _paint_arg("check_perceptual", perceptual, Perceptual)
    sp = _color_space("check_perceptual", space)
    st = np.empty(perceptual.size, np.int8)
    _core.check_perceptual(*perceptual._core_arrays(), sp, st)
    return _status_out(st, perceptual.shape)


def physical_from_perceptual(perceptual: Union[Perceptual, ArrayLike],
                             normalization: Union[Normalization, int] = Normalization.WARD,
                             space: Union[ColorSpace, int] = ColorSpace.LINEAR_REC709, *,
                             errors: str = "raise", check: bool = True) -> Any:
    """Fig. 13's colour/gloss description → physical parameters: CIELAB (D65) → linear RGB ρd
    of the working ``space`` (default Rec. 709); ρs from eq. 7 with Y = f⁻¹(L) (the same in
    every space); α = αx = αy = 1 − d (eq. 8). An unknown space raises ARGUMENT.

    One paint gives one ``Physical``; an array of paints an array ``Physical`` of the same
    shape, in one batched call (``pgloss_physical_from_perceptual_batch_ex``); a channel-last
    array ``(..., 5)`` of (L*, a*, b*, c, d) — an image — a channel-last array ``(..., 6)`` of
    (ρd r, g, b, ρs, αx, αy) (float32 for float32 input, else float64).

    check : bool
        ``True`` (default): the verdict is the core's on the paint, as the C tool's
        ``to-physical`` gives it: the conversion's errors, then :func:`check_perceptual`'s
        (ENVELOPE: c beyond the envelope at L, i.e. ρd + ρs > 1; ENERGY: a colour channel of ρd
        plus ρs > 1). ``False``: only the conversion's own errors
        (``pgloss_physical_from_perceptual``), for paints outside the model on purpose.
    errors : ``"raise"`` (default) or ``"status"``
        ``"raise"``: the first failing element raises :class:`PglossError` NONFINITE,
        LIGHTNESS, NEGATIVE (c < 0), ALPHA (d ≥ 1), NORMALIZATION, GAMUT, ENVELOPE or ENERGY,
        with its ``index``, the ``status_array`` of all elements and the converted paints on
        ``result`` (the exact, negative ρd for GAMUT, the computed values for ENVELOPE and
        ENERGY, the core's fallback elsewhere); d < 0.8 warns :class:`AlphaUntrustedWarning`.
        ``"status"``: returns ``(Physical, status)`` — ``status`` a :class:`Status` for one
        paint, else an int8 array of the paints' shape — and neither raises for a bad element
        nor warns.

    >>> physical_from_perceptual(Perceptual(L=95.0, a=0.0, b=0.0, c=0.3, d=0.95))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgloss.PglossError: pgloss.physical_from_perceptual: ... [PGLOSS_ERR_ENVELOPE]
    """
    fn = "physical_from_perceptual"
    perceptual, dtype = _paint_arg(fn, perceptual, Perceptual)
    want_status = _errors(fn, errors)
    norm = _normalization(fn, normalization)
    sp = _color_space(fn, space)
    q = perceptual._core_arrays()
    shape, n = perceptual.shape, perceptual.size
    block = np.zeros((5, n))  # ρd r, g, b (channel-first, as a Physical stores them), ρs, α; 0 if unwritten
    st = np.empty(n, np.int8)
    _core.physical_from_perceptual(*q, int(norm), sp, block[0:3], block[3], block[4], st)
    if check:
        checked = np.empty(n, np.int8)
        _core.check_perceptual(*q, sp, checked)
        st = _verdict(st, checked)
    if shape == ():
        v = [float(x) for x in block[:, 0]]
        out = Physical(v[0:3], v[3], alpha_x=v[4], alpha_y=v[4], normalization=norm)
    else:
        alpha = block[4].reshape(shape)  # αx = αy (eq. 8): one array for both
        out = Physical._adopt(block[0:3].reshape((3,) + shape), block[3].reshape(shape), alpha, alpha,
                              normalization=norm)
    return _finish(fn, want_status, _paint_out(fn, out, dtype), st, shape)


def perceptual_from_physical(physical: Union[Physical, ArrayLike],
                             space: Union[ColorSpace, int] = ColorSpace.LINEAR_REC709, *,
                             errors: str = "raise", check: bool = True) -> Any:
    """Physical parameters → (L*, a*, b*) of ρd (linear RGB of the working ``space``, default
    Rec. 709), c from eq. 4 with Y = luminance(ρd), d = 1 − α with α = √(αx αy) (geometric
    mean for anisotropic lobes: an extension). An unknown space raises ARGUMENT.

    One paint gives one ``Perceptual``, an array of paints an array ``Perceptual``
    (``pgloss_perceptual_from_physical_batch_ex``), a channel-last array ``(..., 6)`` of
    (ρd r, g, b, ρs, αx, αy) a channel-last array ``(..., 5)`` of (L*, a*, b*, c, d).
    Raises :class:`PglossError` NONFINITE, NEGATIVE, ALPHA and, with ``check=True`` (the
    default: the C tool's ``to-perceptual`` verdict), :func:`check_physical`'s NORMALIZATION
    and ENERGY (with ``index`` and ``status_array`` for arrays); warns for α > 0.2.
    ``errors="status"`` returns ``(Perceptual, status)`` instead, as
    :func:`physical_from_perceptual`.
    """
    fn = "perceptual_from_physical"
    physical, dtype = _paint_arg(fn, physical, Physical)
    want_status = _errors(fn, errors)
    sp = _color_space(fn, space)
    p = physical._core_arrays()
    shape, n = physical.shape, physical.size
    block = np.zeros((5, n))  # L*, a*, b*, c, d; 0 if unwritten (an error of the whole call)
    st = np.empty(n, np.int8)
    _core.perceptual_from_physical(p, sp, *block, st)
    if check:
        checked = np.empty(n, np.int8)
        _core.check_physical(p, checked)
        st = _verdict(st, checked)
    if shape == ():
        out = Perceptual(*(float(x) for x in block[:, 0]))
    else:
        out = Perceptual._adopt([r.reshape(shape) for r in block])
    return _finish(fn, want_status, _paint_out(fn, out, dtype), st, shape)
