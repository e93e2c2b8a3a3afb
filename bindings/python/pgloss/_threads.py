# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The thread count of the array calls (the binding's parallel.h splits a long call)."""

from __future__ import annotations

import os
from typing import Any, Optional

import numpy as np

from . import _core


#: The most threads :func:`set_num_threads` accepts.
MAX_THREADS: int = 1024


def _available_cpus() -> int:
    """The CPUs this process may run on (its affinity mask, e.g. under taskset or a container's
    cpuset), else the machine's."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):  # no affinity on macOS and Windows
        return max(1, os.cpu_count() or 1)


def _thread_count(where: str, n: Any) -> int:
    if isinstance(n, (bool, np.bool_)) or not isinstance(n, (int, np.integer)):
        raise TypeError(f"{where}: the thread count must be a whole number (or None for all CPUs), "
                        f"not {type(n).__name__}")
    if not 1 <= int(n) <= MAX_THREADS:
        raise ValueError(f"{where}: the thread count must be between 1 and {MAX_THREADS}, not {int(n)}")
    return int(n)


def set_num_threads(n: Optional[int]) -> int:
    """Sets how many threads the array calls use, and returns the previous setting.

    ``n``: 1 to :data:`MAX_THREADS` (more than the CPUs is allowed), or ``None`` for the CPUs
    this process may run on (``os.sched_getaffinity``), the default unless the environment
    variable ``PGLOSS_NUM_THREADS`` sets another at import. 1 runs every call on the calling
    thread. Arrays too short to gain from threads run on the calling thread: under
    2 × :data:`MIN_ELEMENTS_PER_THREAD` elements (131 072), or a quarter of that for the
    element-wise scalar functions (``contrast_gloss``, ``gloss_distance``, …), which cost more
    per element. The results are the same, bit for bit, for any setting: outputs, status
    arrays, the index of the first failing element, warnings. Ctrl-C stops a threaded call too.

    The setting is the process's, for every Python thread; a call reads it when it starts.
    """
    count = _available_cpus() if n is None else _thread_count("pgloss.set_num_threads", n)
    return int(_core.set_num_threads(count))


def get_num_threads() -> int:
    """The thread count of the array calls (:func:`set_num_threads`)."""
    return int(_core.get_num_threads())


#: Below twice this many elements an array call runs on the calling thread.
MIN_ELEMENTS_PER_THREAD: int = int(_core.MIN_ELEMENTS_PER_THREAD)


def _threads_from_environment() -> int:
    """``PGLOSS_NUM_THREADS`` (a whole number from 1 to MAX_THREADS; unset or empty: all CPUs)."""
    value = os.environ.get("PGLOSS_NUM_THREADS", "").strip()
    if not value:
        return _available_cpus()
    try:
        n = int(value, 10)
    except ValueError:
        raise ValueError(f"pgloss: the environment variable PGLOSS_NUM_THREADS={value!r} is not a whole number; "
                         f"set it to a thread count from 1 to {MAX_THREADS}, or unset it for all CPUs") from None
    return _thread_count("pgloss: the environment variable PGLOSS_NUM_THREADS", n)


_core.set_num_threads(_threads_from_environment())
