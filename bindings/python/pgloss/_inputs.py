# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Argument checks and array preparation shared by the package's functions."""

from __future__ import annotations

import operator
from typing import Any, Sequence, Tuple, Union

import numpy as np

from ._status import Normalization, PglossError, Status

ArrayLike = Any

_SCALARS = (int, float, bool)


def _as_real(function: str, name: str, value: ArrayLike) -> np.ndarray:
    if isinstance(value, np.ma.MaskedArray):  # np.asarray would drop the mask without a word
        raise TypeError(f"pgloss.{function}: {name} is a masked array, and masks are not honoured; "
                        f"pass np.ma.filled({name}, value) or {name}.compressed()")
    try:
        a = np.asarray(value)
    except Exception as exc:  # ragged lists and the like
        raise TypeError(f"pgloss.{function}: {name} is not an array of numbers ({exc})") from None
    if a.dtype.kind not in "biuf":
        raise TypeError(f"pgloss.{function}: {name} must hold real numbers, not dtype {a.dtype}")
    return a


def _channels(function: str, name: str, value: ArrayLike, n: int) -> np.ndarray:
    """A channel-last array: real numbers whose last axis has ``n`` entries (directions and
    colours: 3; a perceptual paint: 5; a physical one: 6)."""
    a = _as_real(function, name, value)
    if a.ndim == 0 or a.shape[-1] != n:
        raise ValueError(f"pgloss.{function}: {name} must have shape (..., {n}), got {a.shape}")
    return a


def _out_dtype(values: Sequence[Any], arrays: Sequence[np.ndarray]) -> np.dtype:
    """float32 if the inputs are float32/float16 (Python scalars do not promote), else float64."""
    items = [v if isinstance(v, _SCALARS) else a for v, a in zip(values, arrays)]
    rt = np.result_type(*items)
    if rt in (np.float32, np.float16):
        return np.dtype(np.float32)
    return np.dtype(np.float64)


def _broadcast(function: str, names: Sequence[str], values: Sequence[Any]):
    """Broadcasts the inputs; returns (flat float64 arrays, shape, output dtype)."""
    arrays = [_as_real(function, n, v) for n, v in zip(names, values)]
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays))
    except ValueError:
        shapes = ", ".join(f"{n}{a.shape}" for n, a in zip(names, arrays))
        raise ValueError(f"pgloss.{function}: shapes do not broadcast: {shapes}") from None
    # Flat float64 views where numpy can make them (stride 0 for a scalar): the core reads strides.
    flat = [np.broadcast_to(np.asarray(a, dtype=np.float64), shape).reshape(-1) for a in arrays]
    return flat, shape, _out_dtype(values, arrays)


_F32_MAX = float(np.finfo(np.float32).max)


def _shape_out(function: str, a: np.ndarray, shape: Tuple[int, ...], dtype: np.dtype) -> Any:
    if dtype == np.float32:
        # The double result of a float32 input is returned as float32: one that does not fit
        # is an error, never a silent inf.
        big = np.abs(a) > _F32_MAX
        if big.any():
            v = float(a[np.argmax(big)])
            raise OverflowError(f"pgloss.{function}: a result ({v:.6g}) does not fit float32, the dtype of "
                                f"the input; pass float64 input")
    if shape == ():
        return float(a.reshape(())[()].astype(dtype))
    return a.reshape(shape).astype(dtype, copy=False)


def _lobes(function: str, lobes: Any) -> int:
    try:
        v = operator.index(lobes)
    except TypeError:
        raise TypeError(f"pgloss.{function}: lobes must be an int or pgloss.Lobe, not {type(lobes).__name__}") from None
    if not 0 <= v <= 0xFFFFFFFF:
        raise ValueError(f"pgloss.{function}: lobes must be a mask in [0, 2**32), got {v}")
    return v


def _normalization(function: str, value: Any) -> Union["Normalization", int]:
    try:
        v = operator.index(value)
    except TypeError:
        raise TypeError(f"pgloss.{function}: normalization must be an int or pgloss.Normalization, "
                        f"not {type(value).__name__}") from None
    if v in Normalization._value2member_map_:
        return Normalization(v)
    if not -2**31 <= v < 2**31:  # cannot even reach the core: same answer it would give
        raise PglossError(Status.ERR_NORMALIZATION, function)
    return v  # unknown: kept, the core reports it


def _color_space(function: str, value: Any) -> int:
    """The working space for the core; unknown ints reach the core, which answers ERR_ARGUMENT."""
    try:
        v = operator.index(value)
    except TypeError:
        raise TypeError(f"pgloss.{function}: space must be an int or pgloss.ColorSpace, "
                        f"not {type(value).__name__}") from None
    if not -2**31 <= v < 2**31:
        raise PglossError(Status.ERR_ARGUMENT, function)
    return v


def _float(function: str, name: str, v: Any) -> float:
    try:
        return float(v)
    except (TypeError, ValueError):
        raise TypeError(f"pgloss.{function}: {name} must be a real number, not {v!r}") from None
