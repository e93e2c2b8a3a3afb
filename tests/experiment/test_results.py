# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""`experiment import` without a browser: result files written here in the formats the jsPsych
study gives (jsPsych 8's ``data.json()`` and ``data.csv()``, the rows it appends to JATOS one a
line, a JATOS results archive), with the rows the study's plugins write (jspsych_study/study.js)
and each subject's trials drawn from the study's own design (design.py, held to Java's SplitMix64
and to design.js in test_design.py). Good files go in whole; each bad file (truncated JSON or CSV,
a damaged archive, another study, duplicated or conflicting trials, a trial outside the design, a
rating that is not a number) is refused with its reason, and the store is left exactly as it was,
also when the bad file sits in the middle of a batch of good ones. Then the JATOS study archive
(.jzip) of `export-jspsych` against JATOS's documented format."""
from __future__ import annotations

import hashlib
import importlib.util
import json
import re
import shutil
import sqlite3
import uuid
import zipfile
import zlib
from html.parser import HTMLParser
from pathlib import Path
from typing import Callable, Dict, List, Tuple

import pytest

from conftest import MAGNITUDE, PAIRS, ROOT, jrzip, pgloss_cli

spec = importlib.util.spec_from_file_location("design", ROOT / "bindings/python/pgloss/experiment/design.py")
design = importlib.util.module_from_spec(spec)
spec.loader.exec_module(design)

FORMAT = 1  # pgloss_format of the study's rows (jspsych.FORMAT_VERSION)


class Study:
    """The manifest's stimulus ids and each procedure's study id (procedure and the manifest's
    SHA-256, as every row of the study carries it)."""

    def __init__(self, manifest: Path):
        self.manifest = manifest
        self.ids = [s["id"] for s in json.loads(manifest.read_text())["stimuli"]]
        digest = hashlib.sha256(manifest.read_bytes()).hexdigest()
        self.study_id = {p: f"pgloss:{p}:{digest}" for p in design.PROCEDURES}


@pytest.fixture(scope="module")
def study(manifest: Path) -> Study:
    return Study(manifest)


def rating_of(subject: str, trial: int) -> int:
    return (37 * trial + 11 * len(subject)) % 101


def run_rows(study: Study, procedure: str, subject: str, seed: int) -> List[dict]:
    """One subject's run as jsPsych 8 records it: consent, the screen, practice, the main trials
    (each row: the plugin's data, then trial_type, trial_index, plugin_version, time_elapsed,
    then the properties the study adds to every row)."""
    props = {"pgloss_study": study.study_id[procedure], "pgloss_format": FORMAT, "procedure": procedure,
             "subject": subject, "subject_source": "url", "seed": seed}
    rows: List[dict] = []

    def add(data: dict, trial_type: str) -> None:
        k = len(rows)
        rows.append({**data, "trial_type": trial_type, "trial_index": k, "plugin_version": "1",
                     "time_elapsed": 1000 * k + 250, **props})

    add({"rt": 2100, "stimulus": "<p>consent</p>", "response": 0}, "html-button-response")
    add({"dpr": 1, "screen_width": 1920, "screen_height": 1080, "px_per_mm": 3.95, "view_dist_mm": 301.2,
         "image_device_width": 84, "image_device_height": 63, "gamma_code": 186, "black_code": 4}, "pgloss-screen")
    for k, shown in enumerate(design.practice(study.ids, procedure, seed)):
        add({"phase": "practice", "pgloss_trial": k, "stimuli": " ".join(shown), "rating": 50, "rt": 900,
             "device_exact": True, "time_iso": f"2026-12-04T10:00:{k:02d}.000Z"}, "pgloss-trial")
    for t, shown in enumerate(design.trials(study.ids, procedure, seed)):
        add({"phase": "main", "pgloss_trial": t, "stimuli": " ".join(shown), "rating": rating_of(subject, t),
             "rt": 1500 + t, "device_exact": True, "time_iso": f"2026-12-04T10:{1 + t // 60:02d}:{t % 60:02d}.000Z"},
            "pgloss-trial")
    return rows


def json_text(rows: List[dict]) -> str:
    """jsPsych's data.json(): JSON.stringify of the array (no spaces)."""
    return json.dumps(rows, separators=(",", ":"))


def csv_text(rows: List[dict]) -> str:
    """jsPsych's data.csv() (JSON2CSV in jspsych/src/modules/data/utils.ts): the columns in order
    of first appearance, every value in double quotes, objects as JSON, each line ended by CRLF."""
    cols: List[str] = []
    for r in rows:
        cols += [k for k in r if k not in cols]

    def cell(v) -> str:
        text = json.dumps(v) if v is None or isinstance(v, (bool, dict, list)) else str(v)
        return '"' + text.replace('"', '""') + '"'

    return "".join(",".join(line) + "\r\n" for line in
                   [[cell(c) for c in cols]] + [[cell(r[c]) if c in r else '""' for c in cols] for r in rows])


def jsonl_text(rows: List[dict]) -> str:
    """What the study appends to JATOS: one JSON row a line (on_data_update)."""
    return "".join(json.dumps(r, separators=(",", ":")) + "\n" for r in rows)


def write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8", newline="")
    return path


def main_trials(rows: List[dict]) -> Dict[int, Tuple[str, int]]:
    return {r["pgloss_trial"]: (r["stimuli"].replace(" ", ","), r["rating"]) for r in rows
            if r.get("trial_type") == "pgloss-trial" and r["phase"] == "main"}


def store_state(db: Path) -> dict:
    """Counts of every table and every stored response: what an import may change."""
    if not db.exists():
        return {}
    with sqlite3.connect(f"file:{db}?mode=ro", uri=True) as con:
        state = {t: con.execute(f"SELECT COUNT(*) FROM {t}").fetchone()[0]
                 for t in ("subjects", "sittings", "responses", "screens")}
        state["rows"] = con.execute("SELECT subject, procedure, trial, stimuli, rating, sitting FROM responses "
                                    "ORDER BY 1, 2, 3").fetchall()
        state["seeds"] = con.execute("SELECT subject, procedure, seed FROM subjects ORDER BY 1, 2").fetchall()
    return state


def import_files(study: Study, db: Path, *files: Path, check: bool = True):
    return pgloss_cli("experiment", "import", str(study.manifest), *map(str, files), "--db", str(db), check=check)


@pytest.fixture(scope="module")
def populated(study: Study, tmp_path_factory) -> Tuple[Path, dict, Dict[str, List[dict]]]:
    """A store with four subjects imported from the four formats (JSON, CSV, JSON lines, a JATOS
    archive of two runs); checked to hold exactly the answers in the files."""
    d = tmp_path_factory.mktemp("results")
    runs = {"obs-json": run_rows(study, "pairs", "obs-json", 1),
            "obs-csv": run_rows(study, "pairs", "obs-csv", 2**53 - 1),
            "obs-jsonl": run_rows(study, "magnitude", "obs-jsonl", 3),
            "jatos-77-pairs": run_rows(study, "pairs", "jatos-77", 4),
            "jatos-77-magnitude": run_rows(study, "magnitude", "jatos-77", 5)}
    files = [write(d / "obs-json.json", json_text(runs["obs-json"])),
             write(d / "obs-csv.csv", csv_text(runs["obs-csv"])),
             write(d / "obs-jsonl.txt", jsonl_text(runs["obs-jsonl"])),
             jrzip(d / "results.jrzip", [("pairs", write(d / "a.txt", jsonl_text(runs["jatos-77-pairs"]))),
                                         ("magnitude", write(d / "b.txt", jsonl_text(runs["jatos-77-magnitude"])))])]
    db = d / "store.sqlite"
    run = import_files(study, db, *files)
    total = 3 * PAIRS + 2 * MAGNITUDE
    assert f"{total} responses in 5 sittings imported" in run.stdout, run.stdout
    state = store_state(db)
    want = sorted((r["subject"], r["procedure"], t, shown, rating) for rows in runs.values()
                  for t, (shown, rating) in main_trials(rows).items() for r in rows[:1])
    assert [row[:5] for row in state["rows"]] == want
    assert state["screens"] == 5 and state["subjects"] == 5
    assert state["seeds"] == sorted((rows[0]["subject"], rows[0]["procedure"], rows[0]["seed"]) for rows in runs.values())
    again = import_files(study, db, *files)
    assert "0 responses in 0 sittings imported" in again.stdout and f"({total} already there)" in again.stdout
    assert store_state(db) == state
    return db, state, runs


def _cut_json(study, d):
    return write(d / "cut.json", json_text(run_rows(study, "pairs", "obs-x", 7))[:-500])


def _cut_jsonl(study, d):
    return write(d / "cut.txt", jsonl_text(run_rows(study, "pairs", "obs-x", 7))[:-200])


def _cut_csv_line_end(study, d):
    return write(d / "cut.csv", csv_text(run_rows(study, "pairs", "obs-x", 7))[:-2])


def _cut_csv_row(study, d):
    text = csv_text(run_rows(study, "pairs", "obs-x", 7))
    return write(d / "cut.csv", text[:text.rindex('","', 0, len(text) - 40) + 2] + "\r\n")


def _archive(study, d, compression=zipfile.ZIP_DEFLATED):
    return jrzip(d / "bad.jrzip", [("pairs", write(d / "x.txt", jsonl_text(run_rows(study, "pairs", "obs-x", 7))))],
                 compression)


def _jrzip_truncated(study, d):
    path = _archive(study, d)
    data = path.read_bytes()
    return write_bytes(path, data[:len(data) // 2])


def _jrzip_crc(study, d):
    """A flipped byte in a stored (uncompressed) member: only the CRC-32 tells."""
    path = _archive(study, d, zipfile.ZIP_STORED)
    data = bytearray(path.read_bytes())
    data[data.index(b'"rating":') + 9] ^= 0x01  # a digit of a rating: still valid JSON
    return write_bytes(path, bytes(data))


def _jrzip_deflate(study, d):
    """A flipped byte in a deflated member where the stream itself breaks (zlib's 'invalid
    distance' and the like), before the CRC could tell: the first such byte of data.txt's stream."""
    path = _archive(study, d)
    data = bytearray(path.read_bytes())
    with zipfile.ZipFile(path) as z:
        info = z.infolist()[0]
    start = info.header_offset + 30 + len(info.filename.encode()) + len(info.extra)
    for k in range(start, start + info.compress_size):
        broken = bytes(data[start:k]) + bytes([data[k] ^ 0xFF]) + bytes(data[k + 1:start + info.compress_size])
        try:
            zlib.decompressobj(-15).decompress(broken)
        except zlib.error:
            data[k] ^= 0xFF
            return write_bytes(path, bytes(data))
    raise AssertionError("no byte breaks the deflate stream")


def write_bytes(path: Path, data: bytes) -> Path:
    path.write_bytes(data)
    return path


def _other_study(study, d):
    rows = run_rows(study, "pairs", "obs-x", 7)
    for r in rows:
        r["pgloss_study"] = "pgloss:pairs:" + "0" * 64
    return write(d / "other.json", json_text(rows))


def _other_procedure(study, d):
    rows = run_rows(study, "pairs", "obs-x", 7)
    for r in rows:
        r["pgloss_study"] = study.study_id["magnitude"]
    return write(d / "other.json", json_text(rows))


def _main(rows: List[dict]) -> List[dict]:
    return [r for r in rows if r.get("phase") == "main"]


def _duplicate(study, d):
    rows = run_rows(study, "pairs", "obs-x", 7)
    rows.append(dict(_main(rows)[5]))
    return write(d / "dup.json", json_text(rows))


def _conflict(study, d):
    rows = run_rows(study, "pairs", "obs-x", 7)
    rows.append({**_main(rows)[5], "rating": (_main(rows)[5]["rating"] + 1) % 101})
    return write(d / "dup.csv", csv_text(rows))


def _out_of_range(study, d, t=PAIRS):
    rows = run_rows(study, "pairs", "obs-x", 7)
    _main(rows)[-1]["pgloss_trial"] = t
    return write(d / "range.json", json_text(rows))


def _negative(study, d):
    return _out_of_range(study, d, -1)


def _wrong_stimuli(study, d):
    rows = run_rows(study, "pairs", "obs-x", 7)
    m = _main(rows)[3]
    m["stimuli"] = " ".join(reversed(m["stimuli"].split()))
    return write(d / "swap.json", json_text(rows))


def _rating(value, fmt=json_text, ext="json"):
    def make(study, d):
        rows = run_rows(study, "pairs", "obs-x", 7)
        _main(rows)[10]["rating"] = value
        return write(d / f"rating.{ext}", fmt(rows))
    return make


def _same_subject_other_seed(study, d):
    """obs-json is in the store with seed 1; a second run under the same id (seed 8) is refused."""
    return write(d / "again.json", json_text(run_rows(study, "pairs", "obs-json", 8)))


def _stored_answer_changed(study, d):
    """obs-json's trial 0 with another rating than the store holds."""
    rows = run_rows(study, "pairs", "obs-json", 1)
    _main(rows)[0]["rating"] = (_main(rows)[0]["rating"] + 1) % 101
    return write(d / "changed.json", json_text(rows))


BAD: Dict[str, Tuple[Callable[[Study, Path], Path], str]] = {
    "truncated JSON": (_cut_json, r"not a complete JSON array .*a truncated file\?"),
    "truncated JSON lines": (_cut_jsonl, r"line \d+: not JSON .*a truncated file\?"),
    "CSV without its last line end": (_cut_csv_line_end, r"the last row has no line end; a truncated file\?"),
    "CSV cut within a row": (_cut_csv_row, r"row \d+: \d+ fields, the header has \d+; a truncated file\?"),
    "truncated .jrzip": (_jrzip_truncated, r"not a complete ZIP / JATOS results archive .*a truncated file\?"),
    ".jrzip with a CRC error": (_jrzip_crc, r"data\.txt is damaged \(CRC\)"),
    ".jrzip with a broken deflate stream": (_jrzip_deflate, r"not a complete ZIP / JATOS results archive \(Error -3"),
    "another study": (_other_study, r"from study 'pgloss:pairs:0{64}', not this manifest's .*the wrong study or manifest"),
    "this manifest, the other procedure": (_other_procedure, r"the wrong study or manifest"),
    "a trial twice": (_duplicate, r"trial \d+ of obs-x \(pairs\) appears twice .*duplicated trials"),
    "a trial twice, answered differently": (_conflict, r"trial \d+ of obs-x \(pairs\) appears twice .*duplicated trials"),
    "trial index past the design": (_out_of_range, rf"trial {PAIRS} is not a trial of the design \(0–{PAIRS - 1}\)"),
    "negative trial index": (_negative, r"trial -1 is not a trial of the design"),
    "stimuli not the seed's": (_wrong_stimuli, r"but seed 7 puts .* there: not this study's design"),
    "rating a word (JSON)": (_rating("high"), r"field rating is 'high', want int"),
    "rating a word (CSV)": (_rating("high", csv_text, "csv"), r"field rating is 'high', want int"),
    "rating a numeric string (JSON)": (_rating("50"), r"field rating is '50', want int"),
    "rating a fraction": (_rating(50.5), r"field rating is 50.5, want int"),
    "rating empty (CSV)": (_rating("", csv_text, "csv"), r"field rating is None, want int"),
    "rating above 100": (_rating(101), r"rating 101 is outside 0–100"),
    "a subject's second run, another seed": (_same_subject_other_seed, r"nothing imported: subject obs-json \(pairs\) "
                                             r"is in .* with seed 1, and .* has seed 8"),
    "a stored answer changed": (_stored_answer_changed, r"nothing imported: trial 0 of obs-json/pairs is stored with"),
}


@pytest.fixture(scope="module")
def batch(study: Study, tmp_path_factory) -> List[Path]:
    """Two good files of two new subjects, to go around a bad one."""
    d = tmp_path_factory.mktemp("batch")
    return [write(d / "new-a.json", json_text(run_rows(study, "pairs", "new-a", 11))),
            write(d / "new-b.csv", csv_text(run_rows(study, "magnitude", "new-b", 12)))]


def test_batch_files_import(study: Study, populated, batch: List[Path], tmp_path: Path):
    """The good files around each bad one below import alone: what those imports refuse is the bad file."""
    db = tmp_path / "store.sqlite"
    shutil.copyfile(populated[0], db)
    assert f"{PAIRS + MAGNITUDE} responses in 2 sittings imported" in import_files(study, db, *batch).stdout
    assert store_state(db)["responses"] == populated[1]["responses"] + PAIRS + MAGNITUDE


@pytest.mark.parametrize("case", list(BAD))
def test_bad_file_imports_nothing(case: str, study: Study, populated, batch: List[Path], tmp_path: Path):
    """Each bad file alone, and in the middle of a batch whose other files are good and new:
    exit status 2, the reason on stderr (no traceback), the store unchanged."""
    base, state, _ = populated
    make, reason = BAD[case]
    bad = make(study, tmp_path)
    good = batch
    for files in ([bad], [good[0], bad, good[1]]):
        db = tmp_path / "store.sqlite"
        shutil.copyfile(base, db)
        run = import_files(study, db, *files, check=False)
        assert run.returncode == 2 and "Traceback" not in run.stderr, (case, run.returncode, run.stderr)
        assert re.search(reason, run.stderr), (case, run.stderr)
        assert run.stderr.startswith("pgloss experiment: ") and run.stdout == "", run.stderr
        assert bad.name in run.stderr, run.stderr  # names the file
        assert store_state(db) == state, case


#: JATOS's worker types, as the JAS schema lists them for allowedWorkerTypes.
JATOS_WORKERS = {"GeneralMultiple", "GeneralSingle", "Jatos", "MTSandbox", "MT", "PersonalMultiple", "PersonalSingle"}
#: The JAS schema's optional study properties and their types; None where the documented example
#: itself gives null (studyEntryMsg, jsonData, a batch's comments and limits).
STUDY_OPTIONAL = {"description": str, "groupStudy": bool, "linearStudy": bool, "allowPreview": bool, "comments": str,
                  "jsonData": str, "endRedirectUrl": str, "studyEntryMsg": str, "batchList": list}
COMPONENT_OPTIONAL = {"reloadable": bool, "active": bool, "comments": str, "jsonData": str}
BATCH_OPTIONAL = {"active": bool, "maxActiveMembers": int, "maxTotalMembers": int, "maxTotalWorkers": int,
                  "comments": str, "jsonData": str}


class Links(HTMLParser):
    """The local files an HTML page loads (src and href that are not URLs or fragments)."""

    def __init__(self):
        super().__init__()
        self.files: List[str] = []

    def handle_starttag(self, tag, attrs):
        for k, v in attrs:
            if k in ("src", "href") and v and not re.match(r"[a-z]+:|#|//", v):
                self.files.append(v.split("?")[0].split("#")[0])


def check_types(obj: dict, required: Dict[str, type], optional: Dict[str, type], what: str) -> None:
    def ok(v, kind: type) -> bool:  # JSON's true/false are no integers here
        return isinstance(v, kind) and (kind is bool) == isinstance(v, bool)

    for key, kind in required.items():
        assert ok(obj.get(key), kind), f"{what}: {key} is {obj.get(key)!r}, want {kind.__name__}"
    for key, kind in optional.items():
        assert obj.get(key) is None or ok(obj[key], kind), f"{what}: {key} is {obj[key]!r}, want {kind.__name__} or null"


def check_uuid(text: str, what: str) -> str:
    assert str(uuid.UUID(text)) == text, f"{what}: {text!r} is not a UUID in canonical form"
    return text


def test_jatos_study_archive(study: Study, tmp_path: Path):
    """The .jzip of `export-jspsych` against JATOS's documented study archive format ("JATOS Study
    Archive (JZIP)", https://www.jatos.org/JATOS-Study-Archive-JZIP.html, in the JATOS_docs
    repository, JATOS 3.x): a ZIP holding the study assets directory (named by the study
    properties' dirName) and one .jas file, the study properties as JSON: required version
    (string) and data; data requires uuid, title, dirName and componentList (each component uuid,
    title, htmlFilePath); batchList's batches uuid, title and allowedWorkerTypes from JATOS's
    worker types. Beyond the schema: the UUIDs are UUIDs, unique, the same on a re-export and
    different for the other procedure; each component's HTML file is in the archive, and every
    file it loads but jatos.js (which JATOS serves); the folder in the archive is the exported folder byte for byte."""
    seen: Dict[str, dict] = {}
    for procedure, name in (("pairs", "pairs"), ("magnitude", "magnitude"), ("pairs", "pairs-again")):
        out = tmp_path / name
        pgloss_cli("experiment", "export-jspsych", str(study.manifest), "--procedure", procedure, "--out", str(out))
        jzip = out.with_name(out.name + ".jzip")
        with zipfile.ZipFile(jzip) as z:
            assert z.testzip() is None
            names = [n for n in z.namelist() if not n.endswith("/")]
            assert all(not n.startswith("/") and ".." not in n.split("/") and "\\" not in n for n in names), names
            top = {n.split("/")[0] for n in names}
            jas_files = [n for n in names if "/" not in n]
            assert len(jas_files) == 1 and jas_files[0].endswith(".jas"), jas_files
            folders = top - set(jas_files)
            assert len(folders) == 1, top
            jas = json.loads(z.read(jas_files[0]).decode("utf-8"))
            folder = folders.pop()
            files = {n[len(folder) + 1:]: z.read(n) for n in names if n.startswith(folder + "/")}
        assert isinstance(jas, dict) and set(jas) == {"version", "data"}, jas.keys()
        assert jas["version"] == "3", jas["version"]  # the study serial version the schema describes
        data = jas["data"]
        check_types(data, {"uuid": str, "title": str, "dirName": str, "componentList": list}, STUDY_OPTIONAL, "study")
        assert data["dirName"] == folder and re.fullmatch(r"[A-Za-z0-9_-]{1,100}", folder), (data["dirName"], folder)
        assert data["title"].strip() and not re.search(r"[<>]", data["title"])
        ids = [check_uuid(data["uuid"], "study")]
        assert data["componentList"], "no component"
        for c in data["componentList"]:
            check_types(c, {"uuid": str, "title": str, "htmlFilePath": str}, COMPONENT_OPTIONAL, "component")
            ids.append(check_uuid(c["uuid"], "component"))
            page = c["htmlFilePath"]
            assert not page.startswith("/") and ".." not in page.split("/") and page in files, (page, sorted(files))
            links = Links()
            links.feed(files[page].decode("utf-8"))
            # jatos.js is JATOS's own, served beside the component's page ("jatos.js Reference").
            assert links.files and all(f in files for f in links.files if f != "jatos.js"), (links.files, sorted(files))
        for b in data.get("batchList") or []:
            check_types(b, {"uuid": str, "title": str, "allowedWorkerTypes": list}, BATCH_OPTIONAL, "batch")
            ids.append(check_uuid(b["uuid"], "batch"))
            assert b["allowedWorkerTypes"] and set(b["allowedWorkerTypes"]) <= JATOS_WORKERS, b["allowedWorkerTypes"]
        assert len(set(ids)) == len(ids), ids
        on_disk = {p.relative_to(out).as_posix(): p.read_bytes() for p in out.rglob("*") if p.is_file()}
        assert files == on_disk
        assert len([f for f in files if f.startswith("stimuli/")]) == len(study.ids)
        seen[name] = {"ids": ids, "dir": folder}
    assert seen["pairs-again"] == seen["pairs"]  # a re-export updates the same study in JATOS
    assert not set(seen["pairs"]["ids"]) & set(seen["magnitude"]["ids"]) and seen["pairs"]["dir"] != seen["magnitude"]["dir"]
