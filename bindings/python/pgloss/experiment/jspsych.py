# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""``export-jspsych``: one of the paper's procedures as a self-contained jsPsych 8 study.

It writes a folder that runs from any static web server (``OUT/index.html``) and the same study as
a JATOS study archive (``OUT.jzip``). jsPsych and its plugins come from npm, pinned by
``web/jspsych/package-lock.json`` (``bash scripts/jspsych.sh`` installs them), and are copied into
the study's ``lib/`` with their licences: the study loads nothing from elsewhere.

The JATOS archive follows what JATOS reads on import (JATOS 3.x, ``ImportExportService``,
``StudyDeserializer``, ``StudyProperties``/``ComponentProperties``/``BatchProperties``): a ZIP
with exactly one ``.jas`` file and one folder (the study assets) at its root; the ``.jas`` is JSON
``{"version": "3", "data": {…}}`` whose ``version`` (read first) must not exceed 3, the current
study serial version; ``data`` holds uuid, title (≤ 255 characters, no HTML), dirName (a file
name without ``\\s*?"\\/,`<>|:~!§$%&^°`` and none of jatos, publix, public, assets,
study_assets_root, study_assets), componentList (uuid, title, htmlFilePath matching
``^[\\w\\d_-][\\w\\d/_-]*\\.[\\w\\d_-]+$``, reloadable, active, comments, jsonData) and batchList (uuid,
title, active, limits, allowedWorkerTypes from JATOS's worker types). UUIDs are derived from the
manifest and the options, so a re-export updates the same study in JATOS instead of adding one.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import tempfile
import uuid
import zipfile
from pathlib import Path
from typing import Dict, List, Optional

from . import design
from .manifest import SpecError, sha256

HERE = Path(__file__).resolve().parent
STATIC = HERE / "static"
TEMPLATE = HERE / "jspsych_study"
#: Data format of the study's rows (``pgloss_format``), checked by the import.
FORMAT_VERSION = 1
#: The npm packages the study bundles: package → (file in the package, name in lib/).
BUNDLE = {
    "jspsych": [("dist/index.browser.min.js", "jspsych.js"), ("css/jspsych.css", "jspsych.css")],
    "@jspsych/plugin-html-button-response": [("dist/index.browser.min.js", "plugin-html-button-response.js")],
    "@jspsych/plugin-fullscreen": [("dist/index.browser.min.js", "plugin-fullscreen.js")],
    "@jspsych/plugin-virtual-chinrest": [("dist/index.browser.min.js", "plugin-virtual-chinrest.js")],
}
#: Where scripts/jspsych.sh installs the pinned packages, in a pgloss checkout.
NODE_MODULES = Path("web/jspsych/node_modules")
#: JATOS's worker types (``models/common/workers/*Worker.WORKER_TYPE``) that a study link can use.
WORKER_TYPES = ("Jatos", "PersonalSingle", "PersonalMultiple", "GeneralSingle", "GeneralMultiple")
#: What JATOS forbids in a study assets folder name (IOUtils.REGEX_ILLEGAL_IN_FILENAME) and the
#: names it reserves (StudyProperties.INVALID_DIR_NAMES).
JATOS_ILLEGAL = re.compile(r"[\s\n\r\t\f*?\"\\\0/,`<>|:~!§$%&^°]")
JATOS_RESERVED = ("jatos", "publix", "public", "assets", "study_assets_root", "study_assets")
JATOS_HTML_PATH = re.compile(r"^[\w\d_-][\w\d/_-]*\.[\w\d_-]+$")
#: jsPsych's licence (its repository's license.txt is the MIT licence; the npm packages omit the file).
MIT = """
jsPsych and its plugins: The MIT License (MIT). Copyright (c) Joshua R. de Leeuw and the jsPsych
contributors (https://github.com/jspsych/jsPsych).

Permission is hereby granted, free of charge, to any person obtaining a copy of this software and
associated documentation files (the "Software"), to deal in the Software without restriction,
including without limitation the rights to use, copy, modify, merge, publish, distribute,
sublicense, and/or sell copies of the Software, and to permit persons to whom the Software is
furnished to do so, subject to the following conditions:

The above copyright notice and this permission notice shall be included in all copies or
substantial portions of the Software.

THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR IMPLIED, INCLUDING BUT
NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY, FITNESS FOR A PARTICULAR PURPOSE AND
NONINFRINGEMENT. IN NO EVENT SHALL THE AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES
OR OTHER LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM, OUT OF OR IN
CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE SOFTWARE.
"""


def load_texts(path: Optional[Path]) -> Dict[str, str]:
    """The subjects' texts: the package's texts.json, with the keys of ``path`` (if given) over it."""
    texts = json.loads((STATIC / "texts.json").read_text(encoding="utf-8"))
    if path is not None:
        try:
            mine = json.loads(Path(path).read_text(encoding="utf-8"))
        except (OSError, ValueError) as e:
            raise SpecError(f"--texts {path}: not a JSON file ({e})") from None
        if not isinstance(mine, dict) or not all(isinstance(v, str) for v in mine.values()):
            raise SpecError(f"--texts {path}: want a JSON object of strings (see the package's texts.json)")
        unknown = sorted(set(mine) - set(texts))
        if unknown:
            raise SpecError(f"--texts {path}: unknown keys {unknown} (known: {sorted(texts)})")
        texts.update(mine)
    return texts


def _checkouts() -> List[Path]:
    out = []
    for start in (Path.cwd(), HERE):
        for folder in [start, *start.parents]:
            if (folder / NODE_MODULES).is_dir() and folder not in out:
                out.append(folder)
                break
    return out


def find_node_modules(given: Optional[Path]) -> Path:
    """The node_modules folder with jsPsych 8 and the plugins: --jspsych, $PGLOSS_JSPSYCH, or
    web/jspsych/node_modules of the pgloss checkout around the working directory or this package."""
    env = os.environ.get("PGLOSS_JSPSYCH")
    candidates = [Path(given)] if given else [Path(env)] if env else [r / NODE_MODULES for r in _checkouts()]
    for nm in candidates:
        if (nm / "jspsych/package.json").is_file():
            return nm
    where = f" ({', '.join(map(str, candidates))} has none)" if candidates else ""
    raise SpecError("no jsPsych: run `bash scripts/jspsych.sh` in the pgloss checkout (npm ci of web/jspsych), or give "
                    f"--jspsych NODE_MODULES (or set PGLOSS_JSPSYCH) with jspsych 8 and {', '.join(list(BUNDLE)[1:])}"
                    + where)


def _bundle(nm: Path, lib: Path) -> Dict[str, str]:
    versions, notices = {}, []
    for package, files in BUNDLE.items():
        meta_path = nm / package / "package.json"
        try:
            meta = json.loads(meta_path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            raise SpecError(f"{nm}: no {package} (run `bash scripts/jspsych.sh`)") from None
        version = str(meta.get("version", ""))
        if package == "jspsych" and not version.startswith("8."):
            raise SpecError(f"{meta_path}: jsPsych {version}; the study is written for jsPsych 8")
        versions[package] = version
        for src, dst in files:
            if not (nm / package / src).is_file():
                raise SpecError(f"{nm / package / src}: missing (a broken install? run `bash scripts/jspsych.sh`)")
            shutil.copyfile(nm / package / src, lib / dst)
        author = meta.get("author", "")
        author = author.get("name", "") if isinstance(author, dict) else author
        notices.append(f"{package} {version}: licence {meta.get('license', '?')}; author {author}; "
                       f"{meta.get('homepage', '')}")
    # jspsych's browser build bundles its dependencies (auto-bind, random-words, seedrandom): their
    # licence files travel with it where the packages ship them.
    for dep in ("auto-bind", "random-words", "seedrandom"):
        if not (nm / dep / "package.json").is_file():
            continue
        meta = json.loads((nm / dep / "package.json").read_text(encoding="utf-8"))
        found = sorted((nm / dep).glob("[Ll][Ii][Cc][Ee][Nn][Ss][Ee]*"))
        for f in found:
            shutil.copyfile(f, lib / f"LICENSE-{dep}.txt")
        notices.append(f"{dep} {meta.get('version', '')} (inside jspsych.js): licence {meta.get('license', '?')}"
                       + (f"; see LICENSE-{dep}.txt" if found else ""))
    (lib / "LICENSES.txt").write_text(
        "The study bundles these npm packages unchanged (their browser builds):\n\n" + "\n".join(notices) + "\n\n"
        + MIT.strip() + "\n", encoding="utf-8")
    return versions


def study_id(manifest: dict, procedure: str) -> str:
    """What every row of the study's data carries and the import checks: procedure and manifest."""
    return f"pgloss:{procedure}:{sha256(Path(manifest['path']))}"


def _uuid(key: str, what: str) -> str:
    return str(uuid.uuid5(uuid.NAMESPACE_URL, f"pgloss-jatos:{what}:{key}"))


def jas(config: dict, dir_name: str, title: str) -> dict:
    """The JATOS study description (.jas) of the study."""
    key = hashlib.sha256(json.dumps(config, sort_keys=True).encode()).hexdigest()
    return {
        "version": "3",
        "data": {
            "uuid": _uuid(key, "study"), "title": title,
            "description": f"Pellacini, Ferwerda & Greenberg (2000) {config['procedure']} procedure; "
                           f"{len(config['stimuli'])} stimuli. Written by pgloss experiment export-jspsych.",
            "groupStudy": False, "linearStudy": False, "allowPreview": False, "dirName": dir_name,
            "comments": f"study id {config['study_id']}", "jsonData": None, "endRedirectUrl": None,
            "studyEntryMsg": None,
            "componentList": [{"uuid": _uuid(key, "component"), "title": title, "htmlFilePath": "index.html",
                               "reloadable": False, "active": True, "comments": "", "jsonData": None}],
            "batchList": [{"uuid": _uuid(key, "batch"), "title": "Default", "active": True, "maxActiveMembers": None,
                           "maxTotalMembers": None, "maxTotalWorkers": None, "allowedWorkerTypes": list(WORKER_TYPES),
                           "comments": None, "jsonData": None}],
        },
    }


def export_jspsych(manifest: dict, out: Path, *, procedure: str, texts: Optional[Path] = None,
                   visual_angle: float = 3.2, iti_ms: int = 500, break_every: int = 60, chinrest_reps: int = 5,
                   practice: int = design.PRACTICE, completion_code: Optional[str] = None,
                   redirect_url: Optional[str] = None, title: Optional[str] = None,
                   node_modules: Optional[Path] = None) -> List[Path]:
    """Writes the study folder ``out`` and ``out.jzip``; returns both paths."""
    if procedure not in design.PROCEDURES:
        raise SpecError(f"--procedure {procedure!r}: want one of {list(design.PROCEDURES)}")
    if not (0 < visual_angle <= 60) or not (0 <= iti_ms <= 10000) or break_every < 0 or not (0 <= chinrest_reps <= 20) \
            or not (0 <= practice <= 50):
        raise SpecError("want 0 < --visual-angle ≤ 60, 0 ≤ --iti-ms ≤ 10000, --break-every ≥ 0, "
                        "0 ≤ --chinrest-reps ≤ 20, 0 ≤ --practice ≤ 50")
    if completion_code is not None and not re.fullmatch(r"[A-Za-z0-9_-]{1,64}", completion_code):
        raise SpecError("--completion-code: want 1–64 letters, digits, '-' or '_'")
    if redirect_url is not None and not re.fullmatch(r"https?://[^\s\"'<>]{1,2000}", redirect_url):
        raise SpecError("--redirect-url: want an http(s) URL")
    out = Path(out).resolve()
    if out.exists() and any(out.iterdir()) and not (out / "study-config.js").is_file():
        raise SpecError(f"{out}: exists and is not a study written here; give an empty or new folder")
    nm = find_node_modules(node_modules)
    display = manifest.get("display") or {"white": 80.0, "black": 0.2, "gamma": 2.2,
                                          "model": "assumed: the manifest states no display (sRGB-like)"}
    ids = [s["id"] for s in manifest["stimuli"]]
    title = title or f"Gloss {'differences' if procedure == 'pairs' else 'magnitude estimation'} (pgloss)"
    if not title.strip() or len(title) > 255 or re.search(r"[<>&]", title):
        raise SpecError("--title: want 1–255 characters without HTML")

    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.", dir=out.parent))
    tmp.chmod(0o755)  # mkdtemp's 0700 would keep a web server's user out
    try:
        (tmp / "lib").mkdir()
        (tmp / "stimuli").mkdir()
        versions = _bundle(nm, tmp / "lib")
        folder = Path(manifest["path"]).parent
        stimuli = []
        for s in manifest["stimuli"]:
            src = folder / s["file"]
            if sha256(src) != s["sha256"]:
                raise SpecError(f"{src}: changed since the manifest was written (SHA-256 differs)")
            shutil.copyfile(src, tmp / "stimuli" / s["file"])
            stimuli.append({"id": s["id"], "file": f"stimuli/{s['file']}"})
        config = {
            "format_version": FORMAT_VERSION, "study_id": study_id(manifest, procedure), "procedure": procedure,
            "stimuli": stimuli, "image_width": int(manifest["renderer"]["width"]),
            "image_height": int(manifest["renderer"]["height"]), "display": display, "visual_angle_deg": visual_angle,
            "iti_ms": iti_ms, "break_every": break_every, "chinrest_reps": chinrest_reps, "practice": practice,
            "repeats": design.REPEATS, "completion_code": completion_code, "redirect_url": redirect_url,
            "texts": load_texts(texts), "bundled": versions, "trials": len(design.trials(ids, procedure, 0)),
        }
        (tmp / "study-config.js").write_text(
            "// Written by `python -m pgloss experiment export-jspsych`; export again to change it.\n"
            f"window.PGLOSS_STUDY = {json.dumps(config, indent=1, ensure_ascii=False)};\n", encoding="utf-8")
        for name in ("index.html", "study.js", "study.css"):
            shutil.copyfile(TEMPLATE / name, tmp / name)
        for name in ("design.js", "display.js", "display.css"):
            shutil.copyfile(STATIC / name, tmp / name)
        if out.exists():
            shutil.rmtree(out)
        tmp.replace(out)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise

    dir_name = re.sub(r"[^A-Za-z0-9_-]", "_", f"pgloss_{procedure}_{config['study_id'].split(':')[-1][:12]}")
    assert not JATOS_ILLEGAL.search(dir_name) and dir_name not in JATOS_RESERVED
    jzip = out.with_name(out.name + ".jzip")
    part = jzip.with_name(f".{jzip.name}.tmp")
    with zipfile.ZipFile(part, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr(f"{dir_name}.jas", json.dumps(jas(config, dir_name, title), indent=1, ensure_ascii=False))
        for path in sorted(out.rglob("*")):
            if path.is_file():
                z.write(path, f"{dir_name}/{path.relative_to(out).as_posix()}")
    part.replace(jzip)
    return [out, jzip]
