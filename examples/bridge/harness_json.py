# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The harnesses' material argument: a JSON object given inline or as a file name."""
from __future__ import annotations

import json
from pathlib import Path


def parameters(text: str, kinds: str) -> dict:
    """The object from JSON text or a file holding it; a ``{"parameters": {...}}`` wrapper (the
    bridge tool's output) is unwrapped. It must have a "type" (one of ``kinds``, for the error)."""
    p = Path(text)
    obj = json.loads(p.read_text() if not text.lstrip().startswith("{") and p.exists() else text)
    if isinstance(obj, dict) and isinstance(obj.get("parameters"), dict):
        obj = obj["parameters"]
    if not isinstance(obj, dict) or "type" not in obj:
        raise ValueError(f"the material must be a JSON object with a 'type' ({kinds})")
    return obj
