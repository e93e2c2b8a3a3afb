# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""``python -m pgloss experiment stimuli|serve|export|export-jspsych|import``: run the paper's experiments.

    python -m pgloss experiment stimuli [SPEC] --out out/stimuli          # Fig. 4's 27 by default
    python -m pgloss experiment serve out/stimuli/manifest.json --db out/exp1.sqlite
    python -m pgloss experiment export-jspsych out/stimuli/manifest.json --procedure pairs --out out/study
    python -m pgloss experiment import out/stimuli/manifest.json results.jrzip --db out/exp1.sqlite
    python -m pgloss experiment export out/stimuli/manifest.json --db out/exp1.sqlite --out out/exp1
    python -m pgloss mds out/exp1/pairs/*.csv --stimuli out/exp1/stimuli.csv --out out/exp1/mds
    python -m pgloss magnitude out/exp1/magnitude.csv --out out/exp1/magnitude
"""

from __future__ import annotations

import argparse
import signal
import sys
from pathlib import Path

from .manifest import SpecError


def _size(text: str):
    try:
        w, h = (int(v) for v in text.lower().split("x"))
        return w, h
    except ValueError:
        raise argparse.ArgumentTypeError(f"want WxH, e.g. 320x240, not {text!r}") from None


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``experiment`` subcommand's arguments."""
    sub = p.add_subparsers(dest="action", required=True, metavar="ACTION")
    s = sub.add_parser("stimuli", help="render a stimulus set with pgloss-tracer and write its manifest",
                       description="Renders SPEC: 'fig4' (default; the paper's 27), a grid such as "
                       "'rho_d=0.03,0.193 rho_s=0.033,0.099 alpha=0.04,0.1' or 'L=51 c=0.04,0.08,0.12 d=0.9,0.93,0.96', "
                       "or a JSON file of such lists.")
    s.add_argument("spec", nargs="?", default="fig4", metavar="SPEC")
    s.add_argument("--out", type=Path, default=Path("out/stimuli"), help="folder of PNGs + manifest.json")
    s.add_argument("--tracer", help="pgloss-tracer binary (default $PGLOSS_TRACER, else PATH, else the one "
                   "scripts/run.sh built in the pgloss checkout around the working directory: build/examples/tracer/)")
    s.add_argument("--scene", type=Path, help="scene with one 'material paint' line (default "
                   "examples/tracer/scenes/stimulus.scene of the checkout around the working directory, this "
                   "package or the tracer)")
    s.add_argument("--size", type=_size, default=(320, 240), help="image size WxH (default 320x240)")
    s.add_argument("--spp", type=int, default=256, help="samples per pixel (default 256)")
    s.add_argument("--seed", type=int, default=1, help="the renderer's seed")
    s.add_argument("--threads", type=int, help="render threads (default: all)")
    s.add_argument("--display", default="white=108,black=0.7,gamma=2.35", metavar="white=CD,black=CD,gamma=G",
                   help="the display the images are encoded for: white and black luminance (cd/m²) and gamma "
                   "(default the paper's: 108, 0.7, 2.35); recorded in the manifest")
    s.add_argument("--dry-run", action="store_true", help="print the stimuli (CSV: id, rho_d, rho_s, alpha, L, c, d) "
                   "and render nothing")

    v = sub.add_parser("serve", help="the local web server that runs both procedures",
                       description="Serves the experiment: subjects open http://HOST:PORT/, the experimenter "
                       "the /experimenter?token=… address printed at start.")
    v.add_argument("manifest", type=Path, metavar="MANIFEST")
    v.add_argument("--db", type=Path, help="SQLite database (default: responses.sqlite next to the manifest)")
    v.add_argument("--host", default="127.0.0.1", help="listen address (default 127.0.0.1: this machine only)")
    v.add_argument("--port", type=int, default=8000, help="port (default 8000; 0 = any free port)")
    v.add_argument("--display-size", type=_size, help="on-screen image size in CSS pixels (default the "
                   "images' size); fix it for the viewing distance (the paper: 3.2° of visual angle)")
    v.add_argument("--texts", type=Path, help="the subjects' texts (a copy of the package's static/texts.json, edited)")
    v.add_argument("--iti-ms", type=int, default=500, help="black screen between trials, ms (default 500)")
    v.add_argument("--break-every", type=int, default=60, help="a break after every N trials (default 60; 0: none)")
    v.add_argument("--token", help="experimenter's token (default: a random one, printed)")
    v.add_argument("--quiet", action="store_true", help="no request log")

    e = sub.add_parser("export", help="per-subject proximity matrices (for `mds`) and the magnitude table")
    e.add_argument("manifest", type=Path, metavar="MANIFEST")
    e.add_argument("--db", type=Path, help="SQLite database (default: responses.sqlite next to the manifest)")
    e.add_argument("--out", type=Path, default=Path("out/experiment"), help="output folder")

    j = sub.add_parser("export-jspsych", help="one procedure as a jsPsych 8 study: a folder for a static web server "
                       "and a JATOS .jzip", description="Writes OUT/ (open OUT/index.html from any static web server) "
                       "and OUT.jzip (import it in JATOS). jsPsych comes from web/jspsych/node_modules (bash "
                       "scripts/jspsych.sh) or --jspsych.")
    j.add_argument("manifest", type=Path, metavar="MANIFEST")
    j.add_argument("--procedure", choices=("pairs", "magnitude"), required=True,
                   help="pairs: Experiment 1's gloss differences; magnitude: Experiment 2's magnitude estimation")
    j.add_argument("--out", type=Path, required=True, help="the study folder to write (and OUT.jzip beside it)")
    j.add_argument("--visual-angle", type=float, default=3.2, help="width of each image in degrees of visual angle "
                   "at the subject's measured distance (default 3.2, the paper's)")
    j.add_argument("--iti-ms", type=int, default=500, help="black screen between trials, ms (default 500)")
    j.add_argument("--break-every", type=int, default=60, help="a break after every N trials (default 60; 0: none)")
    j.add_argument("--practice", type=int, default=3, help="practice trials (default 3)")
    j.add_argument("--chinrest-reps", type=int, default=5, help="blind-spot measurements of the virtual chinrest "
                   "(default 5; 0 measures no distance: images then at their rendered size)")
    j.add_argument("--texts", type=Path, help="the subjects' texts (a copy of the package's static/texts.json, edited)")
    j.add_argument("--completion-code", help="shown at the end (e.g. Prolific's completion code)")
    j.add_argument("--redirect-url", help="where the study sends the subject at the end (e.g. Prolific's "
                   "https://app.prolific.com/submissions/complete?cc=CODE)")
    j.add_argument("--title", help="the study's title in JATOS")
    j.add_argument("--jspsych", type=Path, help="node_modules with jsPsych 8 and the plugins (default "
                   "web/jspsych/node_modules of the checkout, or $PGLOSS_JSPSYCH)")

    i = sub.add_parser("import", help="jsPsych/JATOS results (.json, .csv, .jsonl, .jrzip) into the database",
                       description="Checks every file (complete, this manifest's study, each trial where the "
                       "subject's seed puts it, no trial twice), then stores all of it in one transaction, or "
                       "nothing. Then `experiment export` writes what `mds` and `magnitude` read.")
    i.add_argument("manifest", type=Path, metavar="MANIFEST")
    i.add_argument("results", type=Path, nargs="+", metavar="RESULTS")
    i.add_argument("--db", type=Path, help="SQLite database (default: responses.sqlite next to the manifest)")


def run(args: argparse.Namespace) -> int:
    """Runs the ``experiment`` subcommand; returns the exit status."""
    from .manifest import load_manifest, sha256
    from .store import Store, StoreError

    try:
        if args.action == "stimuli":
            from .stimuli import paints, parse_spec, render

            if args.dry_run:
                rows = paints(parse_spec(args.spec))  # errors before any output
                print("id,rho_d,rho_s,alpha,L,c,d")
                for i, p in enumerate(rows):
                    print(f"s{i + 1:02d}," + ",".join(f"{p[k]:.9g}" for k in ("rho_d", "rho_s", "alpha", "L", "c", "d")))
                return 0
            from .display import Display

            path = render(args.spec, args.out, tracer=args.tracer, scene=args.scene, size=args.size, spp=args.spp,
                          seed=args.seed, threads=args.threads, display=Display.parse(args.display))
            print(f"manifest: {path}")
            return 0
        manifest = load_manifest(args.manifest)
        if args.action == "export-jspsych":
            from .jspsych import export_jspsych

            for p in export_jspsych(manifest, args.out, procedure=args.procedure, texts=args.texts,
                                    visual_angle=args.visual_angle, iti_ms=args.iti_ms, break_every=args.break_every,
                                    chinrest_reps=args.chinrest_reps, practice=args.practice,
                                    completion_code=args.completion_code, redirect_url=args.redirect_url,
                                    title=args.title, node_modules=args.jspsych):
                print(p)
            return 0
        db = args.db or Path(manifest["path"]).parent / "responses.sqlite"
        if args.action == "import":
            from .results import import_results

            store = Store(db, sha256(args.manifest), [s["id"] for s in manifest["stimuli"]])
            n = import_results(args.results, manifest, store)
            print(f"{db}: {n['responses']} responses in {n['sittings']} sittings imported"
                  + (f" ({n['already']} already there)" if n["already"] else ""))
            return 0
        if args.action == "export":
            from .export import export

            if not db.is_file():
                raise SpecError(f"no database {db} (give --db)")

            store = Store(db, sha256(args.manifest), [s["id"] for s in manifest["stimuli"]])
            for p in export(store, manifest, args.out):
                print(p)
            return 0
        from .server import make_server

        if args.host not in ("127.0.0.1", "localhost"):
            print(f"warning: listening on {args.host}: other machines can reach the experiment", file=sys.stderr)
        server, token = make_server(manifest, db, host=args.host, port=args.port, token=args.token,
                                    display=args.display_size, quiet=args.quiet, texts=args.texts,
                                    iti_ms=args.iti_ms, break_every=args.break_every)
        host, port = server.server_address[:2]
        print(f"pgloss experiment: {len(manifest['stimuli'])} stimuli, responses in {db}", flush=True)
        print(f"subjects:     http://{host}:{port}/", flush=True)
        print(f"experimenter: http://{host}:{port}/experimenter?token={token}", flush=True)
        signal.signal(signal.SIGTERM, lambda *_: (_ for _ in ()).throw(KeyboardInterrupt()))
        try:
            server.serve_forever()
        except KeyboardInterrupt:
            pass
        finally:
            server.server_close()
        return 0
    except (SpecError, StoreError, OSError) as e:
        print(f"pgloss experiment: {e}", file=sys.stderr)
        return 2
