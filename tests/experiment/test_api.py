# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The server's API without a browser: stimuli and manifest, bad requests (4xx, nothing stored),
idempotent resubmission, concurrent subjects, and the seed reproducing the trial order."""
from __future__ import annotations

import csv
import hashlib
import io
import itertools
import json
import os
import shutil
import sqlite3
import struct
import subprocess
import tempfile
import threading
import time
from pathlib import Path
from typing import List

import numpy as np
import pytest

from conftest import LEVELS_C, LEVELS_D, MAGNITUDE, N, PAIRS, PY, ROOT, TOKEN, TRACER, Server, pgloss_cli


def stored(db: Path) -> List[tuple]:
    with sqlite3.connect(f"file:{db}?mode=ro", uri=True) as con:
        return con.execute("SELECT subject, procedure, trial, stimuli, rating FROM responses ORDER BY 1, 2, 3").fetchall()


def test_manifest(manifest: Path):
    """The manifest's images exist with their recorded hash and size, and each paint's physical
    parameters give the requested (c, d) by eqs. 3–4, computed here independently of pgloss."""
    m = json.loads(manifest.read_text())
    assert m["renderer"]["width"] == 48 and m["renderer"]["height"] == 36 and m["renderer"]["spp"] == 16
    assert len(m["stimuli"]) == N
    wanted = set(itertools.product(LEVELS_C, LEVELS_D))
    got = set()
    for s in m["stimuli"]:
        png = (manifest.parent / s["file"]).read_bytes()
        assert hashlib.sha256(png).hexdigest() == s["sha256"]
        assert png[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">II", png[16:24]) == (48, 36)
        c = np.cbrt(s["rho_s"] + s["rho_d"] / 2) - np.cbrt(s["rho_d"] / 2)  # eq. 4
        d = 1 - s["alpha"]  # eq. 3
        assert abs(c - s["c"]) < 1e-6 and abs(d - s["d"]) < 1e-6 and abs(s["L"] - 51) < 1e-6
        got.add((round(float(c), 6), round(d, 6)))
    assert got == wanted
    # The grey of Fig. 4 (ρd = 0.193) is L* ≈ 51 (CIE 1976: 116·Y^(1/3) − 16).
    assert abs(116 * m["stimuli"][0]["rho_d"] ** (1 / 3) - 16 - 51) < 1e-6


def test_fig4_default_and_json_spec(tmp_path: Path):
    """Without SPEC the set is Fig. 4's 27 paints (§3.2.3.1, levels from the paper's text); a JSON
    file works as a SPEC. --dry-run: this checks the set; rendering is the `manifest` fixture's."""
    def listed(*args: str) -> List[dict]:
        lines = pgloss_cli("experiment", "stimuli", *args, "--dry-run").stdout.split()
        return [dict(zip(lines[0].split(",")[1:], map(float, line.split(",")[1:]))) for line in lines[1:]]

    got = sorted((p["rho_d"], p["rho_s"], p["alpha"]) for p in listed())
    assert got == sorted(itertools.product((0.03, 0.193, 0.767), (0.033, 0.066, 0.099), (0.04, 0.07, 0.10)))
    spec = tmp_path / "grid.json"
    spec.write_text(json.dumps({"rho_d": [0.193], "rho_s": [0.033, 0.099], "alpha": [0.04, 0.1]}))
    got = listed(str(spec))
    assert [(p["rho_s"], p["alpha"]) for p in got] == [(0.033, 0.04), (0.033, 0.1), (0.099, 0.04), (0.099, 0.1)]
    # d = 1 − α (eq. 3), c = ∛(ρs + ρd/2) − ∛(ρd/2) (eq. 4), L* of ρd (CIE 1976)
    for p in got:
        assert abs(p["d"] - (1 - p["alpha"])) < 1e-8
        assert abs(p["c"] - (np.cbrt(p["rho_s"] + p["rho_d"] / 2) - np.cbrt(p["rho_d"] / 2))) < 1e-8
        assert abs(p["L"] - (116 * p["rho_d"] ** (1 / 3) - 16)) < 1e-6


def test_bad_specs(tmp_path: Path):
    for spec, why in (("rho_d=0.1 c=0.2", "want exactly"), ("L=50 c=x d=0.9", "numbers"),
                      ("L=50 c=0.05 d=0.9", "at least 3"), ("rho_d=0.9 rho_s=0.5,0.6,0.7 alpha=0.05", "rho")):
        run = pgloss_cli("experiment", "stimuli", spec, "--out", str(tmp_path), "--tracer", "/bin/true", check=False)
        assert run.returncode == 2 and why in run.stderr, (spec, run.stderr)
    run = pgloss_cli("experiment", "stimuli", "--out", str(tmp_path), "--tracer", str(tmp_path / "nope"), check=False)
    assert run.returncode == 2 and f"--tracer {tmp_path / 'nope'}: no pgloss-tracer program there" in run.stderr


def test_bad_requests_store_nothing(manifest: Path, server_factory, tmp_path: Path):
    srv = server_factory(manifest).start()
    status, ses = srv.request("/api/session", {"subject": "alice", "procedure": "pairs"})
    assert status == 200 and len(ses["trials"]) == PAIRS and ses["done"] == []
    t0 = ses["trials"][0]
    good = {"sitting": ses["sitting"], "subject": "alice", "procedure": "pairs", "trial": 0, "stimuli": t0,
            "rating": 40, "rt_ms": 1234.5}
    _, other = srv.request("/api/session", {"subject": "bob", "procedure": "pairs"})

    def bad(**change):
        b = dict(good)
        for k, v in change.items():
            if v is KeyError:
                del b[k]
            else:
                b[k] = v
        return b

    cases = [
        ("rating 101", bad(rating=101), 400), ("rating -1", bad(rating=-1), 400),
        ("rating 50.5", bad(rating=50.5), 400), ("rating '50'", bad(rating="50"), 400),
        ("rating true", bad(rating=True), 400), ("rating null", bad(rating=None), 400),
        ("rt negative", bad(rt_ms=-1), 400), ("rt huge", bad(rt_ms=1e12), 400),
        ("unknown stimulus", bad(stimuli=[t0[0], "s99"]), 404), ("stimuli not strings", bad(stimuli=[1, 2]), 404),
        ("left/right swapped", bad(stimuli=t0[::-1]), 409), ("another trial's stimuli", bad(trial=1), 409),
        ("trial -1", bad(trial=-1), 404), ("trial past the end", bad(trial=PAIRS), 404),
        ("unknown sitting", bad(sitting=10**6), 404), ("another subject's sitting", bad(sitting=other["sitting"]), 404),
        ("procedure mismatch", bad(procedure="magnitude"), 404),
        ("extra field", bad(admin=True), 400), ("missing rating", bad(rating=KeyError), 400),
    ]
    for name, body, want in cases:
        status, reply = srv.request("/api/response", body)
        assert status == want, (name, status, reply)
        assert "error" in reply and reply["error"], name
    raw_cases = [
        ("not JSON", b"{rating: 40}", {}, 400), ("JSON array", b"[1, 2]", {}, 400),
        ("NaN", json.dumps(good).replace("1234.5", "NaN").encode(), {}, 400),
        ("not UTF-8", b"\xff\xfe{}", {}, 400), ("too big", b" " * 5000, {}, 413),
        ("form post", json.dumps(good).encode(), {"Content-Type": "application/x-www-form-urlencoded"}, 415),
    ]
    for name, raw, hdr, want in raw_cases:
        status, reply = srv.request("/api/response", raw=raw, headers=hdr)
        assert status == want, (name, status, reply)
    for body, want in (({"subject": "../etc", "procedure": "pairs"}, 400), ({"subject": "", "procedure": "pairs"}, 400),
                       ({"subject": "x" * 33, "procedure": "pairs"}, 400), ({"subject": "a", "procedure": "ranking"}, 400),
                       ({"subject": "a"}, 400), ({"subject": 7, "procedure": "pairs"}, 400)):
        assert srv.request("/api/session", body)[0] == want, body
    for path, want in (("/api/progress", 403), ("/api/progress?token=wrong", 403), ("/experimenter", 403),
                       ("/export/magnitude.csv", 403), ("/stimuli/s99", 404), ("/stimuli/..%2Fmanifest.json", 404),
                       ("/static/../store.py", 404), ("/nope", 404)):
        assert srv.request(path)[0] == want, path
    # DNS rebinding: another Host header is refused.
    assert srv.request("/api/config", headers={"Host": f"evil.example:{srv.port}"})[0] == 421
    assert stored(srv.db) == []

    # The good response, then the same again (a retry): stored once; a different answer: 409.
    assert srv.request("/api/response", good) == (200, {"stored": True, "duplicate": False, "trial": 0})
    assert srv.request("/api/response", good) == (200, {"stored": False, "duplicate": True, "trial": 0})
    assert srv.request("/api/response", bad(rating=41))[0] == 409
    assert stored(srv.db) == [("alice", "pairs", 0, ",".join(t0), 40)]
    status, prog = srv.request(f"/api/progress?token={TOKEN}")
    assert status == 200 and {(p["subject"], p["responses"], p["trials"]) for p in prog["subjects"]} == {
        ("alice", 1, PAIRS), ("bob", 0, PAIRS)}
    # Resuming: the same seed and trials, the trial done reported.
    status, again = srv.request("/api/session", {"subject": "alice", "procedure": "pairs"})
    assert again["seed"] == ses["seed"] and again["trials"] == ses["trials"] and again["done"] == [0]
    assert again["sitting"] != ses["sitting"]


def test_database_bound_to_manifest(manifest: Path, server_factory, tmp_path: Path):
    """A database that holds another stimulus set's responses is refused, not mixed."""
    other = tmp_path / "other"
    other.mkdir()
    m = json.loads(manifest.read_text())
    m["stimuli"] = m["stimuli"][:3]
    for s in m["stimuli"]:
        (other / s["file"]).write_bytes((manifest.parent / s["file"]).read_bytes())
    (other / "manifest.json").write_text(json.dumps(m))
    db = tmp_path / "db.sqlite"
    run = pgloss_cli("experiment", "export", str(manifest), "--db", str(db), "--out", str(tmp_path / "e"), check=False)
    assert run.returncode == 2 and "no database" in run.stderr
    server_factory(manifest, db).start().stop()  # creates the database, bound to this manifest
    assert pgloss_cli("experiment", "export", str(manifest), "--db", str(db), "--out", str(tmp_path / "e")).returncode == 0
    run = pgloss_cli("experiment", "export", str(other / "manifest.json"), "--db", str(db), "--out",
                     str(tmp_path / "e"), check=False)
    assert run.returncode == 2 and "another stimulus set" in run.stderr
    # A changed image is refused too.
    (other / m["stimuli"][0]["file"]).write_bytes(b"\x89PNG not the same")
    run = pgloss_cli("experiment", "serve", str(other / "manifest.json"), "--db", str(tmp_path / "n.sqlite"),
                     "--port", "0", check=False, timeout=60)
    assert run.returncode == 2 and "SHA-256" in run.stderr


def test_concurrent_subjects(manifest: Path, server_factory):
    """12 subjects post all their trials at once from 12 threads, and 8 threads post the same answer
    to one trial at once: every response is stored exactly once and nothing fails."""
    srv = server_factory(manifest).start()
    errors: List[str] = []
    sessions = []
    for k in range(12):
        status, ses = srv.request("/api/session", {"subject": f"c{k:02d}", "procedure": "pairs" if k % 2 else "magnitude"})
        assert status == 200
        sessions.append(ses)
    start = threading.Barrier(12 + 8)

    def subject(ses):
        start.wait()
        for t, stim in enumerate(ses["trials"]):
            try:
                status, reply = srv.request("/api/response", {"sitting": ses["sitting"], "subject": ses["subject"],
                                            "procedure": ses["procedure"], "trial": t, "stimuli": stim,
                                            "rating": (7 * t) % 101, "rt_ms": 900})
            except OSError as e:
                status, reply = -1, repr(e)
            if status != 200 or not reply["stored"]:
                errors.append(f"{ses['subject']} {t}: {status} {reply}")

    same = sessions[1]
    replies = []

    def retry():
        start.wait()
        try:
            replies.append(srv.request("/api/response", {"sitting": same["sitting"], "subject": same["subject"],
                                       "procedure": same["procedure"], "trial": 0, "stimuli": same["trials"][0],
                                       "rating": 0, "rt_ms": 900}))
        except OSError as e:
            replies.append((-1, {"stored": repr(e)}))

    threads = [threading.Thread(target=subject, args=(s,)) for s in sessions]
    threads[1] = threading.Thread(target=subject, args=({**same, "trials": []},))  # c01's trial 0 comes from retry()
    threads += [threading.Thread(target=retry) for _ in range(8)]
    t0 = time.monotonic()
    for t in threads:
        t.start()
    for t in threads:
        t.join(120)
    seconds = time.monotonic() - t0
    assert not errors, errors[:5]
    assert sorted(r[1]["stored"] for r in replies) == [False] * 7 + [True] and all(r[0] == 200 for r in replies)
    rows = stored(srv.db)
    want = sum(len(s["trials"]) for k, s in enumerate(sessions) if k != 1) + 1
    assert len(rows) == want and len(set((r[0], r[2]) for r in rows)) == want
    print(f"\nconcurrent subjects: {want + 7} responses from 20 threads in {seconds:.2f} s "
          f"({(want + 7) / seconds:.0f}/s, each committed with synchronous=FULL)")


def test_seed_reproduces_trial_order(manifest: Path, server_factory):
    """The recorded seed gives the subject's trials again in a fresh process (pgloss.experiment.design),
    and the orders have the design's properties: each unordered pair once, both placements used,
    magnitude estimation = 3 permutations of the stimuli; another seed, another order."""
    srv = server_factory(manifest).start()
    ids = [s["id"] for s in json.loads(manifest.read_text())["stimuli"]]
    for procedure in ("pairs", "magnitude"):
        _, a = srv.request("/api/session", {"subject": "seed-a", "procedure": procedure})
        _, b = srv.request("/api/session", {"subject": "seed-b", "procedure": procedure})
        code = ("import json, sys; from pgloss.experiment import design; "
                f"print(json.dumps(design.trials({ids!r}, {procedure!r}, int(sys.argv[1]))))")
        for ses in (a, b):
            again = json.loads(subprocess.run([PY, "-c", code, str(ses["seed"])], capture_output=True, text=True,
                                              check=True).stdout)
            assert again == ses["trials"]
        assert a["trials"] != b["trials"]
        if procedure == "pairs":
            for ses in (a, b):
                assert sorted(tuple(sorted(t)) for t in ses["trials"]) == sorted(itertools.combinations(ids, 2))
                assert 0 < sum(t[0] < t[1] for t in ses["trials"]) < PAIRS
        else:
            for ses in (a, b):
                flat = [t[0] for t in ses["trials"]]
                assert len(flat) == MAGNITUDE and all(sorted(flat[k:k + N]) == sorted(ids) for k in (0, N, 2 * N))


# ---- faults and bad input found by an audit under load (each was a 500, a traceback or a leak) ----

def test_export_under_live_load(manifest: Path, server_factory):
    """The export while new subjects start and answer: every poll 200, and every response in the
    export has its subject's seed. Seeds and responses were read in two transactions: a subject
    who started in between had responses but no seed (KeyError, a 500 in 23 of 140 polls)."""
    srv = server_factory(manifest).start()
    stop = threading.Event()
    started: List[str] = []

    def writer(w: int):
        k = 0
        while not stop.is_set():
            subject = f"live{w}-{k:04d}"
            status, ses = srv.request("/api/session", {"subject": subject, "procedure": "pairs"})
            if status == 200:
                srv.request("/api/response", {"sitting": ses["sitting"], "subject": subject, "procedure": "pairs",
                                              "trial": 0, "stimuli": ses["trials"][0], "rating": 50, "rt_ms": 800})
                started.append(subject)
            k += 1

    threads = [threading.Thread(target=writer, args=(w,)) for w in range(6)]
    for t in threads:
        t.start()
    statuses = []
    try:
        deadline = time.monotonic() + 30
        while len(statuses) < 150 and time.monotonic() < deadline:
            status, text = srv.request(f"/export/responses.csv?token={TOKEN}")
            statuses.append(status)
            if status == 200:
                rows = list(csv.DictReader(io.StringIO(text)))
                assert all(r["seed"].isdigit() for r in rows), rows[:3]
    finally:
        stop.set()
        for t in threads:
            t.join(30)
    bad = [s for s in statuses if s != 200]
    print(f"\nexport under load: {len(statuses)} polls while {len(started)} subjects started and answered, "
          f"{len(bad)} not 200")
    assert len(started) >= 5 and len(statuses) >= 10
    assert not bad, bad


def test_hostile_bodies_and_paths_are_4xx(manifest: Path, server_factory):
    """Bodies and paths that made the server answer 500: JSON nested 2,000 deep (RecursionError),
    a 401-digit number (int too large for a float), a 300-character /static/ name (File name too
    long). Each is a 4xx naming the reason, nothing is stored, and the server goes on."""
    srv = server_factory(manifest).start()
    _, ses = srv.request("/api/session", {"subject": "hostile", "procedure": "pairs"})
    good = {"sitting": ses["sitting"], "subject": "hostile", "procedure": "pairs", "trial": 0,
            "stimuli": ses["trials"][0], "rating": 40, "rt_ms": 1234.5}
    huge = "9" * 401
    cases = [
        ("nested 2000 deep", ("[" * 2000 + "]" * 2000).encode(), 400, "nested too deeply"),
        ("nested in a field", json.dumps(good).replace('"rating": 40', '"rating": ' + "[" * 1900 + "]" * 1900).encode(),
         400, "nested too deeply"),
        ("401-digit rt_ms", json.dumps(good).replace("1234.5", huge).encode(), 400, "rt_ms"),
        ("401-digit rating", json.dumps(good).replace('"rating": 40', '"rating": ' + huge).encode(), 400, "rating"),
        ("401-digit trial", json.dumps(good).replace('"trial": 0', '"trial": ' + huge).encode(), 404, "trial"),
        ("401-digit sitting", json.dumps(good).replace(f'"sitting": {ses["sitting"]}', '"sitting": ' + huge).encode(),
         404, "sitting"),
        ("negative 401 digits", json.dumps(good).replace("1234.5", "-" + huge).encode(), 400, "rt_ms"),
        ("1e400 rt_ms", json.dumps(good).replace("1234.5", "1e400").encode(), 400, "rt_ms"),
    ]
    for name, raw, want, words in cases:
        status, reply = srv.request("/api/response", raw=raw)
        assert status == want and words in reply["error"], (name, status, reply)
    for path in ("/static/" + "a" * 300 + ".js", "/static/" + "b" * 5000 + ".css", "/stimuli/" + "s" * 300,
                 "/export/pairs/" + "x" * 300 + f".csv?token={TOKEN}", "/" + "z" * 300):
        status, _ = srv.request(path)
        assert status == 404, (path[:40], status)
    assert srv.request("/static/experiment.js")[0] == 200
    assert stored(srv.db) == []
    assert srv.request("/api/response", good)[0] == 200


def _serve(manifest: Path, db: Path, *extra: str, unprivileged: bool = False, timeout: float = 60):
    """`experiment serve` expected to refuse to start: its CompletedProcess (a TimeoutExpired
    means it started and served, the failure). `unprivileged`: as root, the server runs without
    the capabilities that let root ignore file modes (CAP_DAC_OVERRIDE, CAP_DAC_READ_SEARCH;
    util-linux setpriv). It stays root so that it can still reach a checkout under /root."""
    cmd = [PY, "-m", "pgloss", "experiment", "serve", str(manifest), "--db", str(db), "--port", "0", "--quiet", *extra]
    if unprivileged and os.geteuid() == 0:
        cmd = ["setpriv", "--inh-caps=-all", "--bounding-set=-dac_override,-dac_read_search", *cmd]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)


def test_serve_refuses_a_database_it_cannot_use(manifest: Path, server_factory, tmp_path: Path):
    """A database in a missing folder: a message, not a traceback. A read-only database: refused
    at start with the reason (it started and then answered 500 to every response)."""
    run = _serve(manifest, Path("/nonexistent-pgloss-folder/x.sqlite"))
    assert run.returncode == 2 and "Traceback" not in run.stderr, run.stderr
    assert "no folder /nonexistent-pgloss-folder for the database" in run.stderr, run.stderr
    # A folder anyone may write to, holding a database file nobody may (as root, the server runs
    # without the capabilities that make root ignore file modes).
    folder = Path(tempfile.mkdtemp(prefix="pgloss-ro-"))
    try:
        folder.chmod(0o777)
        db = folder / "ro.sqlite"
        server_factory(manifest, db).start().stop()  # a database with this manifest's tables
        db.chmod(0o444)
        try:
            run = _serve(manifest, db, unprivileged=True, timeout=30)
        except subprocess.TimeoutExpired:
            pytest.fail("the server started on a read-only database")
        assert run.returncode == 2 and "Traceback" not in run.stderr, run.stderr
        assert f"{db}: the database cannot be written (attempt to write a readonly database)" in run.stderr, run.stderr
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def test_request_log_hides_the_token(manifest: Path, tmp_path: Path):
    """The request log (stderr) does not carry the experimenter's token from the query."""
    srv = Server(manifest, tmp_path / "t.sqlite", token="s3cret-t0ken", log=True).start()
    try:
        assert srv.request("/api/progress?token=s3cret-t0ken")[0] == 200
        assert srv.request("/export/magnitude.csv?x=1&token=s3cret-t0ken&y=2")[0] == 200
        assert srv.request("/experimenter?token=wrong-guess")[0] == 403
    finally:
        srv.stop()
    out, err = srv.output
    assert "s3cret-t0ken" in out  # printed once at start, for the experimenter
    assert "s3cret-t0ken" not in err and "wrong-guess" not in err, err
    assert "GET /api/progress?token=… HTTP" in err and "/export/magnitude.csv?x=1&token=…&y=2" in err, err


def test_long_grid_spec(tmp_path: Path):
    """A grid longer than a file name (255 bytes) is a grid: it failed with "File name too long"."""
    levels = ",".join(f"{0.03 + 0.001 * k:.3f}" for k in range(60))
    spec = f"rho_d={levels} rho_s=0.033 alpha=0.07"
    assert len(spec.encode()) > 255
    run = pgloss_cli("experiment", "stimuli", spec, "--dry-run", check=False)
    assert run.returncode == 0, run.stderr
    assert len(run.stdout.split()) == 61


def test_tracer_and_scene_found_where_the_user_has_them(manifest: Path, tmp_path: Path):
    """Without --tracer: the tracer built in the checkout around the working directory (the
    message said "at None"); outside the checkout, with --tracer: the scene of the tracer's
    checkout (it was looked for in the working directory only)."""
    env = {k: v for k, v in os.environ.items() if k != "PGLOSS_TRACER"}
    env["PATH"] = "/usr/bin:/bin"
    spec = "rho_d=0.193 rho_s=0.033,0.066,0.099 alpha=0.07"
    small = ["--size", "8x8", "--spp", "1"]
    outside = tmp_path / "elsewhere"
    outside.mkdir()

    def cli(*args: str, cwd: Path) -> subprocess.CompletedProcess:
        return subprocess.run([PY, "-m", "pgloss", "experiment", "stimuli", spec, *args], capture_output=True,
                              text=True, timeout=300, cwd=cwd, env=env)

    # In the checkout, no --tracer, no PGLOSS_TRACER, not on PATH: the checkout's build.
    run = cli("--out", str(tmp_path / "a"), *small, cwd=ROOT / "tests")
    assert run.returncode == 0, run.stderr
    m = json.loads((tmp_path / "a/manifest.json").read_text())
    assert m["renderer"]["scene"] == "stimulus.scene" and len(m["stimuli"]) == 3
    # Outside it, with --tracer: the scene of the tracer's checkout.
    run = cli("--out", str(tmp_path / "b"), "--tracer", TRACER, *small, cwd=outside)
    assert run.returncode == 0, run.stderr
    assert json.loads((tmp_path / "b/manifest.json").read_text())["renderer"]["scene_sha256"] == m["renderer"]["scene_sha256"]
    # No tracer anywhere (no checkout found: here the venv is inside one, so that search is
    # switched off): a message that says where it looked and what to do.
    code = ("import pgloss.experiment.stimuli as s\ns._checkouts = lambda *starts: []\n"
            "try:\n    s.find_tracer(None)\nexcept s.SpecError as e:\n    print(e)\n")
    run = subprocess.run([PY, "-c", code], capture_output=True, text=True, timeout=60, cwd=outside, env=env)
    assert run.returncode == 0 and "None" not in run.stdout, run.stdout + run.stderr
    assert run.stdout.startswith("no pgloss-tracer: not on PATH. Build it with `bash scripts/run.sh`"), run.stdout
    assert "--tracer PATH" in run.stdout
