# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Each subject's trials, drawn from a recorded seed so that a session can be reconstructed.

* ``pairs`` (§3.2.3.2): every unordered pair of the n stimuli once, n(n−1)/2 trials (378 for
  Fig. 4's 27), in random order, each with a random left/right placement;
* ``magnitude`` (§3.3.3.2): the stimuli in a random sequence, repeated ``repeats`` times (3),
  each repetition a fresh permutation.

Practice trials (not part of the data) come from the same seed. The generator is Python's
:class:`random.Random` seeded with the string ``"pgloss:PROCEDURE:SEED"`` (version-2 string
seeding and ``shuffle``/``random`` have been stable since Python 3.2), so that
``trials(ids, procedure, seed)`` returns the same list on any machine.
"""

from __future__ import annotations

import itertools
import random
from typing import List, Sequence, Tuple

PROCEDURES = ("pairs", "magnitude")
#: Practice trials per procedure.
PRACTICE = 3
#: Repetitions of the magnitude-estimation sequence (§3.3.3.2).
REPEATS = 3

Trial = Tuple[str, ...]  # the stimulus ids shown, left to right


def _rng(procedure: str, seed: int, what: str = "") -> random.Random:
    return random.Random(f"pgloss:{procedure}{what}:{seed}")


def trials(ids: Sequence[str], procedure: str, seed: int, *, repeats: int = REPEATS) -> List[Trial]:
    """The main trials of one subject, in presentation order."""
    if procedure not in PROCEDURES:
        raise ValueError(f"procedure {procedure!r}: want one of {PROCEDURES}")
    rng = _rng(procedure, seed)
    if procedure == "pairs":
        pairs = list(itertools.combinations(ids, 2))
        rng.shuffle(pairs)
        return [(a, b) if rng.random() < 0.5 else (b, a) for a, b in pairs]
    out: List[Trial] = []
    for _ in range(repeats):
        seq = list(ids)
        rng.shuffle(seq)
        out += [(s,) for s in seq]
    return out


def practice(ids: Sequence[str], procedure: str, seed: int, n: int = PRACTICE) -> List[Trial]:
    """Practice trials: random pairs (or single images) spanning the set, not recorded as data."""
    rng = _rng(procedure, seed, ":practice")
    k = 2 if procedure == "pairs" else 1
    return [tuple(rng.sample(list(ids), k)) for _ in range(n)]
