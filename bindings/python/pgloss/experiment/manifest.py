# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The stimulus manifest (written by :mod:`.stimuli`): reading and checking it, and image hashes.
Standard library only, so that the server and the export need nothing else."""

from __future__ import annotations

import hashlib
import json
import re
from pathlib import Path


class SpecError(ValueError):
    """A stimulus SPEC or manifest that cannot be used; the message names the reason."""


def sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 16), b""):
            h.update(block)
    return h.hexdigest()


def load_manifest(path: Path, *, verify: bool = True) -> dict:
    """Reads and checks a manifest: ids unique, the images present and (verify) unchanged."""
    try:
        m = json.loads(Path(path).read_text(encoding="utf-8"))
        ids = [s["id"] for s in m["stimuli"]]
        w, h = int(m["renderer"]["width"]), int(m["renderer"]["height"])
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise SpecError(f"{path}: not a stimulus manifest ({e})") from None
    if len(set(ids)) != len(ids) or len(ids) < 3 or w < 1 or h < 1:
        raise SpecError(f"{path}: want ≥ 3 stimuli with unique ids")
    for s in m["stimuli"]:
        if not re.fullmatch(r"[A-Za-z0-9_-]{1,32}", s["id"]) or "/" in s["file"] or s["file"].startswith("."):
            raise SpecError(f"{path}: bad stimulus id or file name {s['id']!r} {s['file']!r}")
        img = Path(path).parent / s["file"]
        if verify and (not img.is_file() or sha256(img) != s["sha256"]):
            raise SpecError(f"{img}: missing or changed since the manifest was written (SHA-256 differs)")
    m["path"] = str(Path(path).resolve())
    return m
