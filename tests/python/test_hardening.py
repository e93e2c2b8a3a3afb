# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Bad input and signals at the Python boundary: each case here returned a silent
inf, dropped a mask without a word, or ignored Ctrl-C before."""

from __future__ import annotations

import os
import signal
import threading
import time

import numpy as np
import pytest

import pgloss


def test_float32_results_that_overflow_are_an_error_not_inf() -> None:
    # L* = 3e38 is a finite float32; its luminance (~1.1e109 in double) is not.
    with pytest.raises(OverflowError, match=r"luminance_from_lightness: a result .* does not fit float32"):
        pgloss.luminance_from_lightness(np.float32(3e38))
    with pytest.raises(OverflowError, match="does not fit float32"):
        pgloss.luminance_from_lightness(np.array([50.0, 3e38], dtype=np.float32))
    # float64 input gives the double value; float32 input that fits stays float32.
    assert np.isfinite(pgloss.luminance_from_lightness(np.float64(3e38)))
    y = pgloss.luminance_from_lightness(np.array([50.0], dtype=np.float32))
    assert y.dtype == np.float32 and abs(float(y[0]) - 0.18418651851244416) < 1e-7  # CIE 1976, L* = 50


def test_masked_arrays_are_refused_with_the_reason() -> None:
    L = np.ma.masked_array([20.0, 50.0, 80.0], mask=[False, True, False])
    with pytest.raises(TypeError, match=r"lightness_from_luminance: Y is a masked array"):
        pgloss.lightness_from_luminance(L)
    wo = np.ma.masked_array([[0.0, 0.0, 1.0]], mask=[[False, False, True]])
    m = pgloss.Physical(0.2, 0.05, 0.1)
    with pytest.raises(TypeError, match="masked array"):
        pgloss.eval(m, wo, [0.0, 0.0, 1.0])
    # What the message suggests works.
    assert np.all(np.isfinite(pgloss.lightness_from_luminance(np.ma.filled(L, 0.5) / 100)))


def test_ctrl_c_interrupts_a_long_call() -> None:
    # 2e7 elements through the element-wise double path; SIGINT a moment after the call starts
    # must end it with KeyboardInterrupt long before it would finish.
    Y = np.full(20_000_000, 0.18)
    t0 = time.perf_counter()
    pgloss.lightness_from_luminance(Y)
    full = time.perf_counter() - t0
    # Python's own Ctrl-C handler, whatever the process inherited: a background job (as in CI)
    # starts with SIGINT ignored, and then no KeyboardInterrupt would ever be raised.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        timer = threading.Timer(full / 10, os.kill, (os.getpid(), signal.SIGINT))
        t0 = time.perf_counter()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            pgloss.lightness_from_luminance(Y)
            time.sleep(full)  # only reached if the call ignored the signal: then the sleep takes it
        took = time.perf_counter() - t0
        timer.join()
    finally:
        signal.signal(signal.SIGINT, previous)
    print(f"full call {full:.3f} s; interrupted after {took:.3f} s")
    assert took < 0.6 * full, (took, full)
