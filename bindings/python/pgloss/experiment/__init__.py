# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Running the paper's experiments (§3.2.3, §3.3.3) in a browser: ``python -m pgloss experiment``.

* :mod:`.stimuli` renders a stimulus set with pgloss-tracer and writes its manifest;
* :mod:`.design` draws each subject's trial order from a recorded seed;
* :mod:`.store` keeps every response in SQLite (WAL, committed as it is given);
* :mod:`.server` is the local web server (standard library only) and its request validation;
* :mod:`.export` writes the proximity matrices that ``python -m pgloss mds`` reads and the
  magnitude-estimation table;
* :mod:`.cli` is the ``experiment`` command (``stimuli``, ``serve``, ``export``).
"""
