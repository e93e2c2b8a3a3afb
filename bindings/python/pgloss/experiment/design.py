# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Each subject's trials, drawn from a recorded seed so that a session can be reconstructed.

* ``pairs`` (§3.2.3.2): every unordered pair of the n stimuli once, n(n−1)/2 trials (378 for
  Fig. 4's 27), in random order, each with a random left/right placement;
* ``magnitude`` (§3.3.3.2): the stimuli in a random sequence, repeated ``repeats`` times (3),
  each repetition a fresh permutation.

Practice trials (not part of the data) come from the same seed.

The order is defined here once and computed in two places: this module (the local server, the
import's checks) and ``static/design.js`` (the jsPsych study, which draws its subject's seed in
the browser). So the generator is one that both languages compute exactly: SplitMix64 (Steele,
Lea & Flood 2014; the generator of ``java.util.SplittableRandom``), 64-bit integer arithmetic
only. A seed is an integer 0 ≤ seed < 2⁵³ (exact in a JavaScript number); the stream of each
use starts at state ``4·seed + k`` (k: 0 pairs, 1 magnitude, 2 and 3 their practice). An integer
below n is an unbiased draw (rejection above the largest multiple of n under 2⁶⁴); a shuffle is
Fisher–Yates from the end; a left/right placement is the top bit of one draw.
tests/experiment/test_design.py holds both implementations to each other and to Java's.
"""

from __future__ import annotations

import itertools
from typing import Iterator, List, Sequence, Tuple

PROCEDURES = ("pairs", "magnitude")
#: Practice trials per procedure.
PRACTICE = 3
#: Repetitions of the magnitude-estimation sequence (§3.3.3.2).
REPEATS = 3
#: Seeds are below this (2⁵³: exact in JavaScript numbers and in JSON everywhere).
SEED_LIMIT = 1 << 53

Trial = Tuple[str, ...]  # the stimulus ids shown, left to right

_MASK = (1 << 64) - 1
_GAMMA = 0x9E3779B97F4A7C15


def splitmix64(state: int) -> Iterator[int]:
    """The SplitMix64 outputs from ``state`` (64-bit): the mix of state + k·γ for k = 1, 2, …"""
    while True:
        state = (state + _GAMMA) & _MASK
        z = state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & _MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & _MASK
        yield z ^ (z >> 31)


class _Stream:
    def __init__(self, seed: int, k: int):
        if not (isinstance(seed, int) and 0 <= seed < SEED_LIMIT):
            raise ValueError(f"seed {seed!r}: want an integer 0 ≤ seed < 2^53")
        self._gen = splitmix64(4 * seed + k)

    def next(self) -> int:
        return next(self._gen)

    def below(self, n: int) -> int:
        limit = (1 << 64) - (1 << 64) % n
        while True:
            z = self.next()
            if z < limit:
                return z % n

    def shuffle(self, items: list) -> None:
        for i in range(len(items) - 1, 0, -1):
            j = self.below(i + 1)
            items[i], items[j] = items[j], items[i]


def _stream(procedure: str, seed: int, practice: bool) -> _Stream:
    if procedure not in PROCEDURES:
        raise ValueError(f"procedure {procedure!r}: want one of {PROCEDURES}")
    return _Stream(seed, PROCEDURES.index(procedure) + (2 if practice else 0))


def trials(ids: Sequence[str], procedure: str, seed: int, *, repeats: int = REPEATS) -> List[Trial]:
    """The main trials of one subject, in presentation order."""
    rng = _stream(procedure, seed, False)
    if procedure == "pairs":
        pairs = list(itertools.combinations(ids, 2))
        rng.shuffle(pairs)
        return [(b, a) if rng.next() >> 63 else (a, b) for a, b in pairs]
    out: List[Trial] = []
    for _ in range(repeats):
        seq = list(ids)
        rng.shuffle(seq)
        out += [(s,) for s in seq]
    return out


def practice(ids: Sequence[str], procedure: str, seed: int, n: int = PRACTICE) -> List[Trial]:
    """Practice trials: random pairs (or single images) spanning the set, not recorded as data."""
    rng = _stream(procedure, seed, True)
    k = 2 if procedure == "pairs" else 1
    out: List[Trial] = []
    for _ in range(n):
        pool = list(ids)
        for t in range(k):  # the first k of a Fisher–Yates shuffle from the front
            j = t + rng.below(len(pool) - t)
            pool[t], pool[j] = pool[j], pool[t]
        out.append(tuple(pool[:k]))
    return out
