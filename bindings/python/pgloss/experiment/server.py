# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The experiment's web server: Python's standard library (``http.server.ThreadingHTTPServer``).

Why the standard library: the server answers one lab's handful of browsers on localhost — a
few static files, the stimulus images and two small JSON endpoints — which needs no routing
framework, template engine or async I/O; it adds no dependency for the researcher to install
or audit, and every request passes through the validation below, in one place.

Endpoints (subject side): ``GET /`` (the page), ``/static/…``, ``/stimuli/ID`` (a manifest image),
``GET /api/config`` (stimuli, sizes, the display's gamma, texts, inter-trial interval, breaks),
``POST /api/session`` ``{"subject", "procedure"}`` → seed, trials, practice, trials done, sitting id;
``POST /api/screen`` ``{"sitting", "subject", "procedure", "screen"}`` (the sitting's screen: size,
DPR, image size in device pixels, the screen check; an object of ≤ 40 numbers, strings, booleans);
``POST /api/response`` ``{"sitting", "subject", "procedure", "trial",
"stimuli", "rating", "rt_ms"}`` → committed before the 200. Experimenter side (``?token=`` printed
at start): ``/experimenter``, ``/api/progress``, ``/export/{responses,magnitude,stimuli}.csv``,
``/export/pairs/SUBJECT.csv``.

Validation: bodies are JSON objects of ≤ 4 KiB sent as ``application/json`` with exactly the
expected keys and types; subject ids match ``[A-Za-z0-9_-]{1,32}``; a response must name a
sitting of that subject and procedure, a trial index of their design, exactly the stimuli that
trial shows (left to right), an integer rating 0–100 and a response time 0–24 h. Anything else
is a 4xx with a message naming the field, and nothing is stored. Bound to a loopback address
the server also checks the Host header (DNS rebinding); a cross-origin page cannot post JSON
without a CORS preflight, which is never granted.
"""

from __future__ import annotations

import functools
import hashlib
import hmac
import csv
import io
import json
import mimetypes
import re
import secrets
import sys
import tempfile
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any, Dict, List, Optional, Tuple
from urllib.parse import parse_qs, urlsplit

from . import design
from .export import export, proximity_rows
from .manifest import SpecError
from .store import Conflict, Store

STATIC = Path(__file__).resolve().parent / "static"
MAX_BODY = 4096
SUBJECT = re.compile(r"[A-Za-z0-9_-]{1,32}")
MAX_RT_MS = 24 * 3600 * 1000.0
_TOKEN_IN_URL = re.compile(r"([?&]token=)[^&\s\"#]*")
#: The files /static/ serves: what the package ships, nothing named by the request.
_STATIC_FILES = frozenset(p.name for p in STATIC.iterdir() if re.fullmatch(r"[a-z-]+\.(html|js|css)", p.name))


class BadRequest(Exception):
    def __init__(self, status: int, message: str):
        super().__init__(message)
        self.status = status


def _require(obj: Dict[str, Any], schema: Dict[str, type]) -> None:
    extra = sorted(set(obj) - set(schema))
    missing = sorted(set(schema) - set(obj))
    if extra or missing:
        raise BadRequest(400, f"fields: missing {missing}, unexpected {extra}; want exactly {sorted(schema)}")
    for k, t in schema.items():
        v = obj[k]
        ok = isinstance(v, t) and not (t in (int, float, (int, float)) and isinstance(v, bool))
        if not ok:
            raise BadRequest(400, f"{k}: wrong type {type(v).__name__}")


class Experiment:
    """The state shared by the handler threads: manifest, store, experimenter token."""

    def __init__(self, manifest: dict, store: Store, token: str, display: Tuple[int, int],
                 texts: Optional[Dict[str, str]] = None, iti_ms: int = 500, break_every: int = 60):
        self.manifest = manifest
        self.store = store
        self.token = token
        self.ids: List[str] = [s["id"] for s in manifest["stimuli"]]
        self.folder = Path(manifest["path"]).parent
        # The images are read once, checked against the manifest's hashes and served from memory:
        # what a subject sees is what the manifest describes, even if a file changes later.
        self.files: Dict[str, bytes] = {}
        for s in manifest["stimuli"]:
            data = (self.folder / s["file"]).read_bytes()
            if hashlib.sha256(data).hexdigest() != s["sha256"]:
                raise SpecError(f"{self.folder / s['file']}: changed since the manifest was written (SHA-256 differs)")
            self.files[s["id"]] = data
        self.display = display
        self.texts = texts or {}
        self.iti_ms, self.break_every = iti_ms, break_every

    @functools.lru_cache(maxsize=256)
    def trials(self, procedure: str, seed: int) -> List[Tuple[str, ...]]:
        return design.trials(self.ids, procedure, seed)

    def session(self, body: Dict[str, Any], client: str) -> Dict[str, Any]:
        _require(body, {"subject": str, "procedure": str})
        subject, procedure = body["subject"], body["procedure"]
        if not SUBJECT.fullmatch(subject):
            raise BadRequest(400, "subject: want 1–32 letters, digits, '-' or '_'")
        if procedure not in design.PROCEDURES:
            raise BadRequest(400, f"procedure: want one of {list(design.PROCEDURES)}")
        s = self.store.open_sitting(subject, procedure, client)
        return {"subject": subject, "procedure": procedure, "seed": s["seed"], "sitting": s["sitting"],
                "done": s["done"], "trials": self.trials(procedure, s["seed"]),
                "practice": design.practice(self.ids, procedure, s["seed"])}

    def _who(self, body: Dict[str, Any]) -> Tuple[str, str]:
        who = self.store.sitting(body["sitting"]) if 0 < body["sitting"] < 1 << 62 else None
        if who is None or who != (body["subject"], body["procedure"]):
            raise BadRequest(404, "sitting: no such sitting for this subject and procedure")
        return who

    def screen(self, body: Dict[str, Any]) -> Dict[str, Any]:
        _require(body, {"sitting": int, "subject": str, "procedure": str, "screen": dict})
        who = self._who(body)
        screen = body["screen"]
        if len(screen) > 40 or not all(isinstance(k, str) and len(k) <= 40 and (
                v is None or isinstance(v, (bool, str)) or (isinstance(v, (int, float)) and abs(v) < 1e9))
                for k, v in screen.items()):
            raise BadRequest(400, "screen: want an object of at most 40 numbers, strings, booleans or nulls")
        self.store.add_screen(body["sitting"], who[0], who[1], screen)
        return {"stored": True}

    def response(self, body: Dict[str, Any]) -> Dict[str, Any]:
        _require(body, {"sitting": int, "subject": str, "procedure": str, "trial": int, "stimuli": list,
                        "rating": int, "rt_ms": (int, float)})
        who = self._who(body)
        seed = self.store.seed(*who)
        assert seed is not None  # a sitting implies its subject row (foreign key)
        trials = self.trials(body["procedure"], seed)
        t = body["trial"]
        if not 0 <= t < len(trials):
            raise BadRequest(404, f"trial: {t} is not a trial index (0–{len(trials) - 1})")
        stimuli = body["stimuli"]
        if not all(isinstance(s, str) for s in stimuli) or any(s not in self.files for s in stimuli):
            raise BadRequest(404, "stimuli: unknown stimulus id")
        if tuple(stimuli) != trials[t]:
            raise BadRequest(409, f"stimuli: trial {t} shows {list(trials[t])}, not {stimuli}")
        if not 0 <= body["rating"] <= 100:
            raise BadRequest(400, f"rating: {body['rating']} is outside 0–100")
        # Compared before float(): a 401-digit integer is valid JSON but overflows a float.
        if not 0 <= body["rt_ms"] <= MAX_RT_MS:
            raise BadRequest(400, "rt_ms: want 0 to 24 h in milliseconds")
        rt = float(body["rt_ms"])
        try:
            stored = self.store.add_response(who[0], who[1], t, stimuli, body["rating"], rt, body["sitting"])
        except Conflict as e:
            raise BadRequest(409, str(e)) from None
        return {"stored": stored, "duplicate": not stored, "trial": t}


class Handler(BaseHTTPRequestHandler):
    server_version = "pgloss-experiment"
    sys_version = ""
    timeout = 30  # a client that stalls mid-request does not hold a thread forever
    experiment: Experiment
    loopback_hosts: Optional[set] = None
    quiet = False

    # -- plumbing
    def log_message(self, fmt: str, *args: Any) -> None:  # noqa: D102
        if not self.quiet:
            # The experimenter's token travels in the query (?token=…); a log is read by others.
            line = _TOKEN_IN_URL.sub(r"\1…", fmt % args)
            sys.stderr.write(f"{self.address_string()} {line}\n")

    def _send(self, status: int, body: bytes, ctype: str, extra: Optional[Dict[str, str]] = None) -> None:
        self.send_response(status)
        self.send_header("Content-Type", ctype)
        self.send_header("Content-Length", str(len(body)))
        headers = {"Cache-Control": "no-store", "X-Content-Type-Options": "nosniff",
                   "Content-Security-Policy": "default-src 'self'; img-src 'self'; frame-ancestors 'none'"}
        headers.update(extra or {})
        for k, v in headers.items():
            self.send_header(k, v)
        self.end_headers()
        if self.command != "HEAD":
            self.wfile.write(body)

    def _json(self, status: int, obj: Any) -> None:
        self._send(status, json.dumps(obj).encode(), "application/json")

    def _check_host(self) -> None:
        if self.loopback_hosts is not None and self.headers.get("Host", "") not in self.loopback_hosts:
            raise BadRequest(421, "Host: this server answers only to its loopback address")

    def _token_ok(self, query: Dict[str, List[str]]) -> bool:
        given = query.get("token", [""])[0]
        return hmac.compare_digest(given.encode(), self.experiment.token.encode())

    def _body(self) -> Dict[str, Any]:
        if self.headers.get("Transfer-Encoding"):
            raise BadRequest(411, "send a Content-Length, not a chunked body")
        ctype = self.headers.get("Content-Type", "").split(";")[0].strip().lower()
        if ctype != "application/json":
            raise BadRequest(415, "Content-Type: want application/json")
        try:
            n = int(self.headers.get("Content-Length", ""))
        except ValueError:
            raise BadRequest(411, "Content-Length: missing or not a number") from None
        if n < 0 or n > MAX_BODY:
            raise BadRequest(413, f"body: {n} bytes, the limit is {MAX_BODY}")
        raw = self.rfile.read(n)
        try:
            body = json.loads(raw.decode("utf-8"), parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))
        except (UnicodeDecodeError, ValueError) as e:
            raise BadRequest(400, f"body: not JSON ({e})") from None
        except RecursionError:  # e.g. [[[…]]] 2,000 deep: fits in 4 KiB, exceeds the parser's stack
            raise BadRequest(400, "body: JSON nested too deeply") from None
        if not isinstance(body, dict):
            raise BadRequest(400, "body: want a JSON object")
        return body

    def _guard(self, fn) -> None:
        try:
            self._check_host()
            fn()
        except BadRequest as e:
            self.close_connection = True  # a rejected body may not have been read in full
            self._json(e.status, {"error": str(e)})
        except Exception as e:  # never leave a request unanswered; nothing was committed
            self.log_error("internal error: %r", e)
            self._json(500, {"error": "internal error (see the server's log)"})

    # -- routes
    def do_GET(self) -> None:  # noqa: D102
        self._guard(self._get)

    do_HEAD = do_GET

    def do_POST(self) -> None:  # noqa: D102
        self._guard(self._post)

    def _get(self) -> None:
        url = urlsplit(self.path)
        path, query = url.path, parse_qs(url.query)
        ex = self.experiment
        if path == "/favicon.ico":
            return self._send(204, b"", "image/x-icon")
        if path in ("/", "/index.html"):
            return self._static("index.html")
        if path == "/experimenter":
            if not self._token_ok(query):
                raise BadRequest(403, "the experimenter's view needs ?token= (printed when the server started)")
            return self._static("experimenter.html")
        if path.startswith("/static/"):
            return self._static(path[len("/static/"):])
        if path.startswith("/stimuli/"):
            sid = path[len("/stimuli/"):]
            if sid not in ex.files:
                raise BadRequest(404, "unknown stimulus id")
            return self._send(200, ex.files[sid], "image/png", {"Cache-Control": "max-age=3600"})
        if path == "/api/config":
            r = ex.manifest["renderer"]
            gamma = (ex.manifest.get("display") or {}).get("gamma", 2.2)
            return self._json(200, {"stimuli": ex.ids, "width": ex.display[0], "height": ex.display[1],
                                    "image_width": r["width"], "image_height": r["height"], "gamma": gamma,
                                    "procedures": list(design.PROCEDURES), "texts": ex.texts,
                                    "iti_ms": ex.iti_ms, "break_every": ex.break_every})
        if path == "/api/progress" or path.startswith("/export/"):
            if not self._token_ok(query):
                raise BadRequest(403, "needs the experimenter's ?token=")
            if path == "/api/progress":
                rows = ex.store.progress()
                for row in rows:
                    row["trials"] = len(ex.trials(row["procedure"], row["seed"]))
                return self._json(200, {"subjects": rows})
            return self._export(path[len("/export/"):])
        raise BadRequest(404, f"no such page {path}")

    def _post(self) -> None:
        path = urlsplit(self.path).path
        ex = self.experiment
        if path == "/api/session":
            body = self._body()
            return self._json(200, ex.session(body, self.headers.get("User-Agent", "")))
        if path == "/api/response":
            return self._json(200, ex.response(self._body()))
        if path == "/api/screen":
            return self._json(200, ex.screen(self._body()))
        raise BadRequest(404, f"no such endpoint {path}")

    def _static(self, name: str) -> None:
        # A set look-up, not the file system: a 300-character name made is_file() raise
        # "File name too long" (a 500).
        if name not in _STATIC_FILES:
            raise BadRequest(404, "no such file")
        ctype = mimetypes.guess_type(name)[0] or "application/octet-stream"
        self._send(200, (STATIC / name).read_bytes(), ctype + "; charset=utf-8")

    def _export(self, what: str) -> None:
        ex = self.experiment
        m = re.fullmatch(r"(responses|magnitude|stimuli)\.csv|pairs/([A-Za-z0-9_-]{1,32})\.csv", what)
        if not m:
            raise BadRequest(404, "export: responses.csv, magnitude.csv, stimuli.csv or pairs/SUBJECT.csv")
        if m.group(2):
            rows = [r for r in ex.store.responses("pairs") if r["subject"] == m.group(2)]
            if not rows:
                raise BadRequest(404, f"no pair ratings from subject {m.group(2)}")
            buf = io.StringIO()
            csv.writer(buf, lineterminator="\r\n").writerows(proximity_rows(rows, ex.ids))
            data = buf.getvalue().encode()
        else:
            with tempfile.TemporaryDirectory() as tmp:
                export(ex.store, ex.manifest, Path(tmp))
                data = (Path(tmp) / what).read_bytes()
        name = what.replace("/", "-")
        self._send(200, data, "text/csv; charset=utf-8", {"Content-Disposition": f'attachment; filename="{name}"'})


class _Server(ThreadingHTTPServer):
    daemon_threads = True
    # The default listen backlog (5) overflows when a room of browsers (or the concurrency test's
    # 20 threads) connect at once; the kernel then drops or resets connections.
    request_queue_size = 128


def make_server(manifest: dict, db: Path, *, host: str = "127.0.0.1", port: int = 8000, token: Optional[str] = None,
                display: Optional[Tuple[int, int]] = None, quiet: bool = False, texts: Optional[Path] = None,
                iti_ms: int = 500, break_every: int = 60) -> Tuple[ThreadingHTTPServer, str]:
    """The server (not yet serving) and the experimenter's token."""
    from .jspsych import load_texts
    from .manifest import sha256

    if not (0 <= iti_ms <= 10000) or break_every < 0:
        raise SpecError("want 0 ≤ --iti-ms ≤ 10000 and --break-every ≥ 0")

    store = Store(db, sha256(Path(manifest["path"])), [s["id"] for s in manifest["stimuli"]])
    store.check_writable()  # refused now, not with an error on every response
    r = manifest["renderer"]
    ex = Experiment(manifest, store, token or secrets.token_urlsafe(16), display or (r["width"], r["height"]),
                    load_texts(texts), iti_ms, break_every)
    server = _Server((host, port), Handler)
    real_port = server.server_address[1]
    loopback = host in ("127.0.0.1", "localhost", "::1")
    hosts = None
    if loopback:
        hosts = {f"{h}:{real_port}" for h in ("127.0.0.1", "localhost", "[::1]")}
    handler = type("BoundHandler", (Handler,), {"experiment": ex, "loopback_hosts": hosts, "quiet": quiet})
    server.RequestHandlerClass = handler
    return server, ex.token
