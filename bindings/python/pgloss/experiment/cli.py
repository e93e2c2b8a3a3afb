# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""``python -m pgloss experiment stimuli|serve|export``: run the paper's experiments.

    python -m pgloss experiment stimuli [SPEC] --out out/stimuli          # Fig. 4's 27 by default
    python -m pgloss experiment serve out/stimuli/manifest.json --db out/exp1.sqlite
    python -m pgloss experiment export out/stimuli/manifest.json --db out/exp1.sqlite --out out/exp1
    python -m pgloss mds out/exp1/pairs/*.csv --stimuli out/exp1/stimuli.csv --out out/exp1/mds
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
    v.add_argument("--token", help="experimenter's token (default: a random one, printed)")
    v.add_argument("--quiet", action="store_true", help="no request log")

    e = sub.add_parser("export", help="per-subject proximity matrices (for `mds`) and the magnitude table")
    e.add_argument("manifest", type=Path, metavar="MANIFEST")
    e.add_argument("--db", type=Path, help="SQLite database (default: responses.sqlite next to the manifest)")
    e.add_argument("--out", type=Path, default=Path("out/experiment"), help="output folder")


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
            path = render(args.spec, args.out, tracer=args.tracer, scene=args.scene, size=args.size, spp=args.spp,
                          seed=args.seed, threads=args.threads)
            print(f"manifest: {path}")
            return 0
        manifest = load_manifest(args.manifest)
        db = args.db or Path(manifest["path"]).parent / "responses.sqlite"
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
                                    display=args.display_size, quiet=args.quiet)
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
