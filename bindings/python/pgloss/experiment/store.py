# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The response store: SQLite in WAL mode, every response committed before it is acknowledged.

Durability. ``journal_mode=WAL`` lets the experimenter's view and the export read while subjects
write, and a killed process loses nothing that was committed. ``synchronous=FULL`` also fsyncs
the WAL at every commit, so a response survives a power cut or OS crash once the subject's
browser has its acknowledgement (with NORMAL, WAL commits since the last checkpoint can be lost
then). The cost, one fsync per response, is milliseconds against a subject's seconds per trial.

Idempotence. ``UNIQUE(subject, procedure, trial)``: a repeated submission of the same trial
with the same answer (a browser retrying after a lost acknowledgement) is a no-op; a different
answer to a trial already recorded is a conflict, and the first answer stays.

Each request opens its own connection (``sqlite3`` connections are not shared between threads);
writers serialise on SQLite's lock (``BEGIN IMMEDIATE``, 30 s busy timeout).
"""

from __future__ import annotations

import json
import secrets
import sqlite3
import time
from contextlib import contextmanager
from pathlib import Path
from typing import Dict, Iterator, List, Optional, Sequence, Tuple

SCHEMA = """
CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS subjects (
  subject TEXT NOT NULL, procedure TEXT NOT NULL, seed INTEGER NOT NULL, created_at TEXT NOT NULL,
  PRIMARY KEY (subject, procedure));
CREATE TABLE IF NOT EXISTS sittings (
  id INTEGER PRIMARY KEY, subject TEXT NOT NULL, procedure TEXT NOT NULL, started_at TEXT NOT NULL,
  client TEXT NOT NULL, FOREIGN KEY (subject, procedure) REFERENCES subjects (subject, procedure));
CREATE TABLE IF NOT EXISTS responses (
  subject TEXT NOT NULL, procedure TEXT NOT NULL, trial INTEGER NOT NULL,
  stimuli TEXT NOT NULL,              -- the ids shown, left to right, comma-separated
  rating INTEGER NOT NULL CHECK (rating BETWEEN 0 AND 100),
  rt_ms REAL NOT NULL CHECK (rt_ms >= 0),
  received_at TEXT NOT NULL,          -- UTC, ISO 8601, when the server committed it
  sitting INTEGER NOT NULL REFERENCES sittings (id),
  UNIQUE (subject, procedure, trial),
  FOREIGN KEY (subject, procedure) REFERENCES subjects (subject, procedure));
CREATE TABLE IF NOT EXISTS screens (  -- each sitting's screen: size, DPR, distance, the screen check
  sitting INTEGER NOT NULL REFERENCES sittings (id), subject TEXT NOT NULL, procedure TEXT NOT NULL,
  screen TEXT NOT NULL,               -- JSON object
  recorded_at TEXT NOT NULL);
"""


class StoreError(Exception):
    """The database does not belong to this manifest, or is unusable."""


class Conflict(Exception):
    """A trial already has a different answer."""


def utc_now() -> str:
    t = time.time()
    return time.strftime("%Y-%m-%dT%H:%M:%S", time.gmtime(t)) + f".{int(t % 1 * 1000):03d}Z"


class Store:
    """The experiment's database at ``path``, bound to one stimulus manifest."""

    def __init__(self, path: Path, manifest_sha256: str, stimulus_ids: Sequence[str]):
        self.path = Path(path)
        if not self.path.parent.is_dir():
            raise StoreError(f"{path}: no folder {self.path.parent} for the database (create it, or give another --db)")
        try:
            with self._connect() as db:
                db.execute("PRAGMA journal_mode=WAL")
                db.executescript(SCHEMA)
                row = db.execute("SELECT value FROM meta WHERE key='manifest_sha256'").fetchone()
                if row is None:
                    db.execute("INSERT INTO meta VALUES ('manifest_sha256', ?), ('stimuli', ?), ('created_at', ?)",
                               (manifest_sha256, json.dumps(list(stimulus_ids)), utc_now()))
        except sqlite3.Error as e:
            raise StoreError(f"{path}: cannot open the database ({e})") from None
        if row is not None and row[0] != manifest_sha256:
            raise StoreError(f"{path} holds responses to another stimulus set (manifest SHA-256 {row[0][:12]}…, "
                             f"this one {manifest_sha256[:12]}…): use a new database")

    def check_writable(self) -> None:
        """Raises StoreError unless a response could be committed now: the server checks this at
        start, so that a read-only database (or folder, which WAL mode writes to) is refused with
        a reason instead of answering every response with an error."""
        try:
            with self._write() as db:
                db.execute("INSERT OR REPLACE INTO meta VALUES ('served_at', ?)", (utc_now(),))
        except sqlite3.Error as e:
            raise StoreError(f"{self.path}: the database cannot be written ({e}); the server needs write access "
                             f"to it and to its folder {self.path.parent} (SQLite's WAL files live there)") from None

    @contextmanager
    def _connect(self) -> Iterator[sqlite3.Connection]:
        db = sqlite3.connect(self.path, timeout=30.0, isolation_level=None)
        try:
            db.execute("PRAGMA synchronous=FULL")
            db.execute("PRAGMA foreign_keys=ON")
            yield db
        finally:
            db.close()

    @contextmanager
    def _write(self) -> Iterator[sqlite3.Connection]:
        with self._connect() as db:
            db.execute("BEGIN IMMEDIATE")
            try:
                yield db
            except BaseException:
                db.execute("ROLLBACK")
                raise
            db.execute("COMMIT")

    def open_sitting(self, subject: str, procedure: str, client: str, seed: Optional[int] = None) -> Dict:
        """Starts (or resumes) a subject's procedure: their seed, the trials done, the new sitting's id."""
        with self._write() as db:
            row = db.execute("SELECT seed FROM subjects WHERE subject=? AND procedure=?", (subject, procedure)).fetchone()
            if row is None:
                # 53 bits: exact in JavaScript numbers too.
                seed = secrets.randbelow(1 << 53) if seed is None else int(seed)
                db.execute("INSERT INTO subjects VALUES (?, ?, ?, ?)", (subject, procedure, seed, utc_now()))
            else:
                seed = int(row[0])
            cur = db.execute("INSERT INTO sittings (subject, procedure, started_at, client) VALUES (?, ?, ?, ?)",
                             (subject, procedure, utc_now(), client[:200]))
            sitting = int(cur.lastrowid)
            done = [r[0] for r in db.execute("SELECT trial FROM responses WHERE subject=? AND procedure=? ORDER BY trial",
                                             (subject, procedure))]
        return {"seed": seed, "sitting": sitting, "done": done}

    def add_screen(self, sitting: int, subject: str, procedure: str, screen: Dict) -> None:
        """Records a sitting's screen (a JSON object)."""
        with self._write() as db:
            db.execute("INSERT INTO screens VALUES (?, ?, ?, ?, ?)",
                       (sitting, subject, procedure, json.dumps(screen, sort_keys=True), utc_now()))

    def screens(self) -> List[Dict]:
        with self._connect() as db:
            return self._screens(db)

    @staticmethod
    def _screens(db: sqlite3.Connection) -> List[Dict]:
        rows = db.execute("SELECT sitting, subject, procedure, screen, recorded_at FROM screens "
                          "ORDER BY subject, procedure, sitting").fetchall()
        return [{"sitting": r[0], "subject": r[1], "procedure": r[2], **json.loads(r[3]), "recorded_at": r[4]}
                for r in rows]

    def import_sittings(self, sittings: Sequence[Dict]) -> Dict[str, int]:
        """Stores imported sittings in one transaction: all of them or, on any conflict, nothing.

        Each sitting: subject, procedure, seed, client (where it came from), started_at, screens
        (list of JSON objects) and responses (trial, stimuli, rating, rt_ms, received_at). A subject
        already in the store must have the same seed; a trial already answered must have the same
        answer (then it is not stored again). Raises Conflict naming the first disagreement."""
        counts = {"sittings": 0, "responses": 0, "already": 0}
        with self._write() as db:
            for s in sittings:
                who = (s["subject"], s["procedure"])
                row = db.execute("SELECT seed FROM subjects WHERE subject=? AND procedure=?", who).fetchone()
                if row is None:
                    db.execute("INSERT INTO subjects VALUES (?, ?, ?, ?)", (*who, int(s["seed"]), utc_now()))
                elif int(row[0]) != int(s["seed"]):
                    raise Conflict(f"subject {who[0]} ({who[1]}) is in {self.path} with seed {row[0]}, and "
                                   f"{s['client']} has seed {s['seed']}: another run under the same subject id")
                new = []
                for r in s["responses"]:
                    old = db.execute("SELECT stimuli, rating FROM responses WHERE subject=? AND procedure=? AND trial=?",
                                     (*who, r["trial"])).fetchone()
                    shown = ",".join(r["stimuli"])
                    if old is None:
                        new.append(r)
                    elif old != (shown, r["rating"]):
                        raise Conflict(f"trial {r['trial']} of {who[0]}/{who[1]} is stored with rating {old[1]}; "
                                       f"{s['client']} says {r['rating']}")
                    else:
                        counts["already"] += 1
                # A file imported again brings its screens again: keep each one once.
                stored = {row[0] for row in db.execute("SELECT screen FROM screens WHERE subject=? AND procedure=?", who)}
                screens = [t for t in (json.dumps(x, sort_keys=True) for x in s["screens"]) if t not in stored]
                if not new and not screens:
                    continue
                cur = db.execute("INSERT INTO sittings (subject, procedure, started_at, client) VALUES (?, ?, ?, ?)",
                                 (*who, s["started_at"], s["client"][:200]))
                sitting = int(cur.lastrowid)
                counts["sittings"] += 1
                for r in new:
                    db.execute("INSERT INTO responses VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
                               (*who, r["trial"], ",".join(r["stimuli"]), r["rating"], float(r["rt_ms"]),
                                r["received_at"], sitting))
                counts["responses"] += len(new)
                for screen in screens:
                    db.execute("INSERT INTO screens VALUES (?, ?, ?, ?, ?)", (sitting, *who, screen, utc_now()))
        return counts

    def sitting(self, sitting: int) -> Optional[tuple]:
        with self._connect() as db:
            return db.execute("SELECT subject, procedure FROM sittings WHERE id=?", (sitting,)).fetchone()

    def seed(self, subject: str, procedure: str) -> Optional[int]:
        with self._connect() as db:
            row = db.execute("SELECT seed FROM subjects WHERE subject=? AND procedure=?", (subject, procedure)).fetchone()
        return None if row is None else int(row[0])

    def add_response(self, subject: str, procedure: str, trial: int, stimuli: Sequence[str], rating: int,
                     rt_ms: float, sitting: int) -> bool:
        """Commits one response; True if stored, False if this exact answer was already there.
        Raises Conflict if the trial has a different answer."""
        shown = ",".join(stimuli)
        with self._write() as db:
            old = db.execute("SELECT stimuli, rating FROM responses WHERE subject=? AND procedure=? AND trial=?",
                             (subject, procedure, trial)).fetchone()
            if old is not None:
                if old == (shown, rating):
                    return False
                raise Conflict(f"trial {trial} of {subject}/{procedure} already has rating {old[1]}")
            db.execute("INSERT INTO responses VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
                       (subject, procedure, trial, shown, rating, float(rt_ms), utc_now(), sitting))
        return True

    def progress(self) -> List[Dict]:
        """Per subject and procedure: seed, responses, sittings, first and last activity."""
        with self._connect() as db:
            rows = db.execute("""
              SELECT s.subject, s.procedure, s.seed, s.created_at,
                     (SELECT COUNT(*) FROM responses r WHERE r.subject=s.subject AND r.procedure=s.procedure),
                     (SELECT COUNT(*) FROM sittings t WHERE t.subject=s.subject AND t.procedure=s.procedure),
                     (SELECT MAX(received_at) FROM responses r WHERE r.subject=s.subject AND r.procedure=s.procedure)
              FROM subjects s ORDER BY s.subject, s.procedure""").fetchall()
        keys = ("subject", "procedure", "seed", "created_at", "responses", "sittings", "last_response_at")
        return [dict(zip(keys, r)) for r in rows]

    def responses(self, procedure: Optional[str] = None) -> List[Dict]:
        with self._connect() as db:
            return self._responses(db, procedure)

    @staticmethod
    def _responses(db: sqlite3.Connection, procedure: Optional[str] = None) -> List[Dict]:
        q = "SELECT subject, procedure, trial, stimuli, rating, rt_ms, received_at, sitting FROM responses"
        args: tuple = ()
        if procedure:
            q += " WHERE procedure=?"
            args = (procedure,)
        rows = db.execute(q + " ORDER BY subject, procedure, trial", args).fetchall()
        keys = ("subject", "procedure", "trial", "stimuli", "rating", "rt_ms", "received_at", "sitting")
        return [dict(zip(keys, r)) for r in rows]

    def snapshot(self) -> Tuple[Dict[Tuple[str, str], int], List[Dict], List[Dict]]:
        """Every subject's seed, every response and screen, read in one transaction: what the export
        writes is one consistent state, however many subjects start or answer meanwhile (read
        apart, a subject who started between the two reads had responses but no seed)."""
        with self._connect() as db:
            db.execute("BEGIN")  # a WAL read transaction: one snapshot for both SELECTs
            try:
                seeds = {(s, p): int(seed) for s, p, seed in db.execute("SELECT subject, procedure, seed FROM subjects")}
                rows = self._responses(db)
                screens = self._screens(db)
            finally:
                db.execute("COMMIT")
        return seeds, rows, screens
