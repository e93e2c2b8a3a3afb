# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""``experiment import``: the jsPsych study's data back into the store that the local server
writes, so that ``experiment export`` and ``python -m pgloss mds`` read both alike.

Reads what the study gives (one or more files, any mix):

* ``.json`` — jsPsych's ``data.get().json()``, the study's JSON download (an array of rows);
* ``.csv`` — jsPsych's ``data.get().csv()``, the study's CSV download;
* ``.jsonl`` / ``.txt`` — one JSON row a line, as the study appends them to JATOS
  (``jatos.appendResultData``), e.g. a ``data.txt`` taken out of JATOS;
* ``.jrzip`` (or ``.zip``) — JATOS's results archive: ``metadata.json`` and
  ``study_result_N/comp-result_M/data.txt`` per run (JATOS 3.x ``ResultStreamer``).

Every row of the study carries ``pgloss_study`` (procedure and the manifest's SHA-256),
``pgloss_format``, subject, seed and procedure. Checked before anything is stored: each file
parses to the end (a truncated file is an error, not a shorter one); it is this manifest's study;
each answer's stimuli are those that the subject's seed puts at that trial (design.py); ratings are
integers 0–100; no trial of a subject appears twice (in a file or across files); one seed per
subject. Then all sittings go into the store in one transaction (:meth:`Store.import_sittings`):
a subject already there with another seed, or a trial already answered differently, refuses the
whole import. Errors name the file, the row and the reason.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import math
import re
import zipfile
import zlib
from pathlib import Path
from typing import Dict, Iterable, List, Tuple

from . import design
from .jspsych import FORMAT_VERSION, study_id
from .manifest import SpecError
from .store import Conflict, Store

SUBJECT = re.compile(r"[A-Za-z0-9_-]{1,32}")


class ResultsError(SpecError):
    """A result file that cannot be imported; the message names the file, row and reason."""


def _json_lines(text: str, where: str) -> List[dict]:
    rows = []
    for k, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        try:
            value = json.loads(line)
        except ValueError as e:
            raise ResultsError(f"{where} line {k}: not JSON ({e}); a truncated file?") from None
        rows += value if isinstance(value, list) else [value]
    return rows


def _parse_json(text: str, where: str) -> List[dict]:
    stripped = text.lstrip()
    if stripped.startswith("["):
        try:
            value = json.loads(text)
        except ValueError as e:
            raise ResultsError(f"{where}: not a complete JSON array ({e}); a truncated file?") from None
        if not isinstance(value, list):
            raise ResultsError(f"{where}: want a JSON array of jsPsych rows")
        return value
    return _json_lines(text, where)


#: The CSV columns read as numbers (jsPsych's CSV quotes every value); the rest stay text, so that
#: a subject id of digits is still a string.
NUMERIC = frozenset({"seed", "pgloss_trial", "rating", "rt", "pgloss_format"})


def _number(text: str):
    try:
        return int(text)
    except ValueError:
        try:
            return float(text)
        except ValueError:
            return text


def _parse_csv(text: str, where: str) -> List[dict]:
    reader = csv.reader(io.StringIO(text, newline=""), strict=True)
    try:
        header = next(reader)
        rows = []
        for k, cells in enumerate(reader, 2):
            if not cells:
                continue
            if len(cells) != len(header):
                raise ResultsError(f"{where} row {k}: {len(cells)} fields, the header has {len(header)}; "
                                   "a truncated file?")
            rows.append({h: _number(v) if h in NUMERIC else v for h, v in zip(header, cells) if v != ""})
    except csv.Error as e:
        raise ResultsError(f"{where}: not CSV ({e}); a truncated file?") from None
    except StopIteration:
        raise ResultsError(f"{where}: empty") from None
    if not text.endswith(("\n", "\r")) and rows:
        # jsPsych ends its CSV with a line break after every row; without one the last row may be cut.
        raise ResultsError(f"{where}: the last row has no line end; a truncated file?")
    return rows


def _read(path: Path) -> List[Tuple[str, List[dict]]]:
    """(source name, rows) for each result in the file."""
    try:
        data = path.read_bytes()
    except OSError as e:
        raise ResultsError(f"{path}: cannot read ({e.strerror})") from None
    if data[:4] == b"PK\x03\x04" or path.suffix.lower() in (".jrzip", ".zip"):
        try:
            with zipfile.ZipFile(io.BytesIO(data)) as z:
                bad = z.testzip()
                if bad:
                    raise ResultsError(f"{path}: {bad} is damaged (CRC); a truncated download?")
                names = [n for n in z.namelist() if n.endswith("/data.txt") or n == "data.txt"]
                if not names:
                    raise ResultsError(f"{path}: a ZIP without data.txt: not a JATOS results archive")
                if "metadata.json" in z.namelist():  # informative (the rows carry what is checked), but
                    meta = json.loads(z.read("metadata.json"))  # a malformed one is not JATOS's
                    if not (isinstance(meta, dict) and isinstance(meta.get("data"), list)):
                        raise ResultsError(f"{path}: metadata.json is not JATOS's results metadata")
                return [(f"{path.name}:{n}", _json_lines(z.read(n).decode("utf-8"), f"{path}:{n}"))
                        for n in sorted(names)]
        # zlib.error: a damaged deflate stream breaks before its CRC can be checked.
        except (zipfile.BadZipFile, zlib.error, EOFError, ValueError, UnicodeDecodeError) as e:
            raise ResultsError(f"{path}: not a complete ZIP / JATOS results archive ({e}); a truncated file?") \
                from None
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as e:
        raise ResultsError(f"{path}: not UTF-8 text ({e})") from None
    if path.suffix.lower() == ".csv":
        return [(path.name, _parse_csv(text, str(path)))]
    return [(path.name, _parse_json(text, str(path)))]


def _field(row: dict, key: str, kind, where: str):
    v = row.get(key)
    if kind is int and isinstance(v, float) and v.is_integer():
        v = int(v)
    if not isinstance(v, kind) or isinstance(v, bool):
        raise ResultsError(f"{where}: field {key} is {v!r}, want {kind.__name__}")
    return v


def collect(paths: Iterable[Path], manifest: dict) -> List[Dict]:
    """The checked sittings in the files (see the module's doc); raises ResultsError."""
    ids = [s["id"] for s in manifest["stimuli"]]
    wanted = {p: study_id(manifest, p) for p in design.PROCEDURES}
    sittings: Dict[Tuple[str, str, str], Dict] = {}
    seen: Dict[Tuple[str, str, int], str] = {}
    seeds: Dict[Tuple[str, str], Tuple[int, str]] = {}
    for path in map(Path, paths):
        digest = hashlib.sha256(path.read_bytes()).hexdigest()[:16] if path.is_file() else ""
        results = _read(path)
        found = 0
        for source, rows in results:
            for k, row in enumerate(rows, 1):
                where = f"{source} row {k}"
                if not isinstance(row, dict):
                    raise ResultsError(f"{where}: not a JSON object")
                if "pgloss_study" not in row:
                    continue
                found += 1
                if row.get("pgloss_format") != FORMAT_VERSION:
                    raise ResultsError(f"{where}: data format {row.get('pgloss_format')!r}, this pgloss reads "
                                       f"{FORMAT_VERSION}")
                procedure = row.get("procedure")
                if procedure not in wanted or row["pgloss_study"] != wanted[procedure]:
                    raise ResultsError(f"{where}: from study {row['pgloss_study']!r}, not this manifest's "
                                       f"({wanted.get(procedure, wanted['pairs'])!r}): the wrong study or manifest")
                subject = _field(row, "subject", str, where)
                if not SUBJECT.fullmatch(subject):
                    raise ResultsError(f"{where}: subject {subject!r}: want 1–32 letters, digits, '-' or '_'")
                seed = _field(row, "seed", int, where)
                if not 0 <= seed < design.SEED_LIMIT:
                    raise ResultsError(f"{where}: seed {seed} is outside 0 … 2^53")
                who = (subject, procedure)
                if seeds.setdefault(who, (seed, source))[0] != seed:
                    raise ResultsError(f"{where}: subject {subject} ({procedure}) has seed {seed} here and "
                                       f"{seeds[who][0]} in {seeds[who][1]}: two runs under one subject id")
                key = (subject, procedure, source)
                s = sittings.setdefault(key, {"subject": subject, "procedure": procedure, "seed": seed,
                                              "client": f"import {source} sha256:{digest}",
                                              "started_at": None, "responses": [], "screens": []})
                if row.get("trial_type") == "pgloss-screen":
                    s["screens"].append({k2: v for k2, v in row.items() if k2 not in ("pgloss_study", "subject")})
                if row.get("trial_type") != "pgloss-trial" or row.get("phase") != "main":
                    continue
                t = _field(row, "pgloss_trial", int, where)
                trials = design.trials(ids, procedure, seed)
                if not 0 <= t < len(trials):
                    raise ResultsError(f"{where}: trial {t} is not a trial of the design (0–{len(trials) - 1})")
                shown = tuple(str(_field(row, "stimuli", str, where)).split())
                if shown != trials[t]:
                    raise ResultsError(f"{where}: trial {t} shows {' '.join(shown)}, but seed {seed} puts "
                                       f"{' '.join(trials[t])} there: not this study's design")
                rating = _field(row, "rating", int, where)
                rt = row.get("rt")
                if not 0 <= rating <= 100:
                    raise ResultsError(f"{where}: rating {rating} is outside 0–100")
                if not isinstance(rt, (int, float)) or isinstance(rt, bool) or not (0 <= rt <= 864e5) or \
                        not math.isfinite(rt):
                    raise ResultsError(f"{where}: rt {rt!r}: want 0 to 24 h in milliseconds")
                dup = seen.get((subject, procedure, t))
                if dup is not None:
                    raise ResultsError(f"{where}: trial {t} of {subject} ({procedure}) appears twice (also {dup}): "
                                       "duplicated trials")
                seen[(subject, procedure, t)] = where
                stamp = row.get("time_iso") if isinstance(row.get("time_iso"), str) else ""
                s["responses"].append({"trial": t, "stimuli": shown, "rating": rating, "rt_ms": float(rt),
                                       "received_at": stamp[:40]})
                if stamp and (s["started_at"] is None or stamp < s["started_at"]):
                    s["started_at"] = stamp[:40]
        if not found:
            raise ResultsError(f"{path}: no rows of a pgloss study (no field pgloss_study)")
    out = list(sittings.values())
    for s in out:
        s["started_at"] = s["started_at"] or "unknown"
    return out


def import_results(paths: Iterable[Path], manifest: dict, store: Store) -> Dict[str, int]:
    """Checks the files, then stores all their sittings in one transaction; returns the counts."""
    sittings = collect(paths, manifest)
    try:
        return store.import_sittings(sittings)
    except Conflict as e:
        raise ResultsError(f"nothing imported: {e}") from None
