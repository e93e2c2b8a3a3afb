# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""``python -m pgloss COMMAND …``, and the wheel's ``pgloss`` command: the package's command line.

The package's own commands (``python -m pgloss COMMAND --help`` for each):

* ``figures OUTDIR`` — the paper's Figs. 9, 10 and 11, computed by the library (below);
* ``mds …`` — the paper's MDS analysis (§3) on proximity matrices in CSV
  (:mod:`pgloss.psychophysics.cli`);
* ``magnitude …`` — the paper's magnitude-estimation analysis (Figs. 7, 8, hypotheses ranked)
  (:mod:`pgloss.psychophysics.magnitude_cli`);
* ``experiment stimuli|serve|export|export-jspsych|import …`` — run the paper's experiments in a
  browser, locally or as a jsPsych/JATOS study (:mod:`pgloss.experiment.cli`).
* ``image-meter IMAGE …`` — (c, d) of the sphere in a linear render of the stimulus scene
  (:mod:`pgloss.image_meter`).

Every other command (``to-physical``, ``check``, ``match``, ``distance``, ``eval``, ``demo``, …,
``--version``) is the C tool's, which the wheel ships and which runs as it is (:mod:`pgloss.cli`);
``--help`` lists both.

A package command is one entry of :data:`COMMANDS`: its name, help line, a function that adds
its arguments to an ``argparse`` parser and one that runs it (imported only when it is used).

``figures`` writes PNG and SVG (matplotlib, Agg backend, no display needed) of

* Fig. 9 — the perceptually uniform gloss space: the 27 stimuli of Experiment 1
  (ρd ∈ {0.03, 0.193, 0.767} × ρs ∈ {0.033, 0.066, 0.099} × α ∈ {0.04, 0.07, 0.10}) at their
  predicted (c, d) (eqs. 3, 4), lightness L* as the third axis, with the (c, d) plane inset;
* Fig. 10 — the envelope of gloss space (largest c per lightness under ρd + ρs ≤ 1) and c
  against lightness at a fixed specular energy (ρs = 0.033, 0.066, 0.099);
* Fig. 11 — isogloss difference contours (eq. 5) of ΔD = 0.04 and 0.08 around the reference
  c = 0.087, d = 0.93 (the grey stimulus ρd = 0.193, ρs = 0.066, α = 0.07), with the grey
  stimuli; the d axis is drawn 1.78× the c axis so that the contours are circles.

The numbers come from pgloss (gloss_from_physical, envelope_contrast, contrast_gloss,
luminance_from_lightness, isogloss_contour, gloss_distance); matplotlib only draws them.
"""

from __future__ import annotations

import argparse
import errno
import os
import subprocess
import sys
from pathlib import Path
from typing import Callable, List, NamedTuple, Optional, Sequence, Tuple

import numpy as np

import pgloss

#: Experiment 1's stimuli (paper §3.2.3.1).
RHO_D = (0.03, 0.193, 0.767)
RHO_S = (0.033, 0.066, 0.099)
ALPHA = (0.04, 0.07, 0.10)
#: Fig. 11's reference paint and contour steps (§5.1).
REFERENCE = (0.087, 0.93)
STEPS = (0.04, 0.08)

_FILL = {0.03: "0.1", 0.193: "0.55", 0.767: "0.97"}
_NAME = {0.03: "black", 0.193: "grey", 0.767: "white"}
_MARKER = {0.033: "o", 0.066: "s", 0.099: "D"}


def experiment1():
    """The 27 stimuli: (rho_d, rho_s, alpha) grids and their predicted (L, c, d)."""
    rd, rs, al = np.meshgrid(RHO_D, RHO_S, ALPHA, indexing="ij")
    L, c, d = pgloss.gloss_from_physical(rd, rs, al)
    return rd, rs, al, L, c, d


def _save(fig, outdir: Path, stem: str) -> List[Path]:
    paths = []
    for ext in ("png", "svg"):
        path = outdir / f"{stem}.{ext}"
        meta = {"Date": None} if ext == "svg" else {"Software": None}
        fig.savefig(path, dpi=150 if ext == "png" else None, metadata=meta, bbox_inches="tight")
        paths.append(path)
    return paths


def figure9(plt, outdir: Path) -> List[Path]:
    rd, rs, al, L, c, d = experiment1()
    fig = plt.figure(figsize=(12.0, 6.0))
    grid = fig.add_gridspec(1, 2, width_ratios=(1.7, 1.0), wspace=0.15)
    ax = fig.add_subplot(grid[0], projection="3d")
    for i, r in enumerate(RHO_D):
        for j, s in enumerate(RHO_S):
            ax.scatter(c[i, j], d[i, j], L[i, j], s=46, marker=_MARKER[s], c=_FILL[r], edgecolors="k",
                       depthshade=False, label=f"ρd = {r} ({_NAME[r]})" if j == 1 else None)
    for i in range(len(RHO_D)):  # drop lines to the (c, d) plane at L = 0
        for j in range(len(RHO_S)):
            for k in range(len(ALPHA)):
                ax.plot([c[i, j, k]] * 2, [d[i, j, k]] * 2, [0, L[i, j, k]], color="0.75", lw=0.6)
    ax.set_xlabel("contrast gloss c (eq. 4)")
    ax.set_ylabel("DOI gloss d = 1 − α (eq. 3)")
    ax.set_zlabel("lightness L*")
    ax.set_zlim(0, 100)
    ax.view_init(elev=18, azim=-60)
    fig.suptitle("Fig. 9 — perceptually uniform gloss space: Experiment 1's stimuli at their predicted (c, d, L*)")
    handles = [plt.Line2D([], [], ls="", marker=_MARKER[s], mfc="none", mec="k", label=f"ρs = {s}") for s in RHO_S]
    handles += [plt.Line2D([], [], ls="", marker="o", mfc=_FILL[r], mec="k", label=f"ρd = {r} ({_NAME[r]})")
                for r in RHO_D]
    ax.legend(handles=handles, loc="upper left", fontsize=8)
    plane = fig.add_subplot(grid[1])
    for i, r in enumerate(RHO_D):
        for j, s in enumerate(RHO_S):
            plane.scatter(c[i, j], d[i, j], s=36, marker=_MARKER[s], c=_FILL[r], edgecolors="k")
    plane.set_xlabel("contrast gloss c")
    plane.set_ylabel("DOI gloss d")
    plane.set_aspect(pgloss.D_WEIGHT)  # equal distances (eq. 5) look equal
    plane.set_title("the (c, d) plane (inset of Fig. 9)", fontsize=10)
    paths = _save(fig, outdir, "fig09_gloss_space")
    plt.close(fig)
    return paths


def figure10(plt, outdir: Path) -> List[Path]:
    L = np.linspace(0.0, 100.0, 401)
    c_max = pgloss.envelope_contrast(L)
    rho_d = pgloss.luminance_from_lightness(L)
    fig, ax = plt.subplots(figsize=(7.0, 4.8))
    ax.plot(L, c_max, "k-", lw=2, label="envelope: largest c at L* (ρd + ρs ≤ 1)")
    ax.fill_between(L, c_max, c_max.max() * 1.05, color="0.9", label="outside gloss space")
    for s, ls in zip(RHO_S, (":", "-.", "--")):
        ok = rho_d + s <= 1.0  # beyond the envelope the paint would reflect more than it receives
        ax.plot(L[ok], pgloss.contrast_gloss(rho_d[ok], s), "k", ls=ls, lw=1.3, label=f"fixed specular energy ρs = {s}")
    Ls, cs = pgloss.gloss_from_physical(np.array(RHO_D), RHO_S[-1], ALPHA[0])[:2]
    ax.scatter(Ls, cs, c=[_FILL[r] for r in RHO_D], edgecolors="k", zorder=3,
               label="black, grey, white paints at ρs = 0.099")
    ax.set_xlim(0, 100)
    ax.set_ylim(0, float(c_max.max()) * 1.05)
    ax.set_xlabel("lightness L*")
    ax.set_ylabel("contrast gloss c")
    ax.set_title("Fig. 10 — effect of surface lightness on apparent gloss")
    ax.legend(fontsize=8, loc="upper right")
    paths = _save(fig, outdir, "fig10_envelope")
    plt.close(fig)
    return paths


def figure11(plt, outdir: Path) -> List[Path]:
    rd, rs, al, L, c, d = experiment1()
    c0, d0 = REFERENCE
    fig, ax = plt.subplots(figsize=(6.4, 6.4))
    for D, ls in zip(STEPS, ("-", "--")):
        cc, dd = pgloss.isogloss_contour(c0, d0, D, 256)
        ax.plot(np.append(cc, cc[0]), np.append(dd, dd[0]), "k", ls=ls, lw=1.2, label=f"ΔD = {D} (eq. 5)")
    grey = 1  # ρd = 0.193
    for j, s in enumerate(RHO_S):
        ax.scatter(c[grey, j], d[grey, j], s=50, marker=_MARKER[s], c=_FILL[0.193], edgecolors="k",
                   label=f"grey stimuli, ρs = {s}", zorder=3)
    ax.scatter([c0], [d0], s=140, marker="*", c="w", edgecolors="k", zorder=4, label="reference c = 0.087, d = 0.93")
    # The 12 and 3 o'clock points of the first contour: sharp/low-contrast vs blurry/high-contrast.
    for theta, name in ((np.pi / 2, "12 o'clock"), (0.0, "3 o'clock")):
        pc, pd = c0 + STEPS[0] * np.cos(theta), d0 + STEPS[0] / pgloss.D_WEIGHT * np.sin(theta)
        assert abs(pgloss.gloss_distance(c0, d0, pc, pd) - STEPS[0]) < 1e-12
        ax.annotate(name, (pc, pd), textcoords="offset points", xytext=(6, 6), fontsize=8)
    ax.set_aspect(pgloss.D_WEIGHT)  # one unit of d is 1.78 units of c: the contours are circles
    ax.set_xlabel("contrast gloss c")
    ax.set_ylabel("DOI gloss d")
    ax.set_title("Fig. 11 — isogloss difference contours")
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    paths = _save(fig, outdir, "fig11_isogloss")
    plt.close(fig)
    return paths


def figures(outdir: Path) -> List[Path]:
    """Writes the three figures (PNG + SVG) into outdir; returns the paths written."""
    try:
        import matplotlib
    except ImportError:  # pragma: no cover - depends on the environment
        raise SystemExit("pgloss figures needs matplotlib: pip install 'pgloss[figures]'") from None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    matplotlib.rcParams["svg.hashsalt"] = "pgloss"  # reproducible SVG ids
    outdir.mkdir(parents=True, exist_ok=True)
    paths: List[Path] = []
    for make in (figure9, figure10, figure11):
        paths += make(plt, outdir)
    return paths


def _figures_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("outdir", type=Path, metavar="OUTDIR")


def _figures_run(args: argparse.Namespace) -> int:
    for p in figures(args.outdir):
        print(p)
    return 0


def _mds_arguments(p: argparse.ArgumentParser) -> None:
    from .psychophysics import cli

    cli.add_arguments(p)


def _mds_run(args: argparse.Namespace) -> int:
    from .psychophysics import cli

    return cli.run(args)


def _magnitude_arguments(p: argparse.ArgumentParser) -> None:
    from .psychophysics import magnitude_cli

    magnitude_cli.add_arguments(p)


def _magnitude_run(args: argparse.Namespace) -> int:
    from .psychophysics import magnitude_cli

    return magnitude_cli.run(args)


def _experiment_arguments(p: argparse.ArgumentParser) -> None:
    from .experiment import cli

    cli.add_arguments(p)


def _experiment_run(args: argparse.Namespace) -> int:
    from .experiment import cli

    return cli.run(args)


class Command(NamedTuple):
    """One of the package's commands: name, usage arguments, help line, argument set-up and
    runner (returns the exit status)."""

    name: str
    args: str
    help: str
    arguments: Callable[[argparse.ArgumentParser], None]
    run: Callable[[argparse.Namespace], int]
    description: str = ""


#: The package's own commands, in the order ``--help`` lists them (after the C tool's).
COMMANDS: Tuple[Command, ...] = (
    Command("figures", "OUTDIR", "the paper's Figs. 9, 10, 11 as PNG + SVG in OUTDIR", _figures_arguments,
            _figures_run),
    Command("mds", "CSV... | --example NAME", "MDS of proximity matrices (§3, Figs. 2-8)", _mds_arguments, _mds_run,
            "MDS analysis of proximity matrices (CSV), one per subject: stress curve, dimensionality, weighted "
            "Euclidean non-metric fit, confirmatory MDS; --example cities reproduces Figs. 2 and 3 "
            "(see pgloss.psychophysics.cli)."),
    Command("magnitude", "RATINGS.csv [--out DIR]", "magnitude estimation: hypotheses ranked by r², Figs. 7, 8",
            _magnitude_arguments, _magnitude_run,
            "The paper's §3.3.4 analysis (see pgloss.psychophysics.magnitude_cli)."),
    Command("experiment", "stimuli|serve|export|export-jspsych|import ...", "the paper's experiments in a browser",
            _experiment_arguments, _experiment_run,
            "Render stimuli (stimuli), run pairwise gloss differences (§3.2.3) and magnitude estimation (§3.3.3) "
            "in a browser, stored in SQLite (serve), as a jsPsych/JATOS study (export-jspsych, import), write "
            "proximity matrices and the magnitude table (export); see pgloss.experiment."),
    Command("image-meter", "IMAGE [options]", "(c, d) of the sphere in a linear render of the stimulus scene",
            lambda p: __import__("pgloss.image_meter").image_meter.add_arguments(p),
            lambda a: __import__("pgloss.image_meter").image_meter.run(a),
            "Fits the Ward paint that reproduces the sphere's pixels (see pgloss.image_meter, docs/image-meter.md)."),
)

#: Exit code when the output could not be written (the C tool's too).
WRITE_ERROR = 3


def _flush_stdout(text: str = "") -> int:
    """Writes text and flushes stdout: 0, or WRITE_ERROR after the C tool's message if the
    output is lost (stdout then points at the null device, so that the interpreter's own
    flush at exit fails no more)."""
    try:
        if sys.stdout is None:  # started with descriptor 1 closed
            raise OSError(errno.EBADF, os.strerror(errno.EBADF))
        sys.stdout.write(text)
        sys.stdout.flush()
    except OSError as e:
        sys.stderr.write(f"pgloss: cannot write the output: {e.strerror or e}\n")
        try:
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, sys.stdout.fileno())
            os.close(null)
        except (OSError, ValueError, AttributeError):
            pass
        return WRITE_ERROR
    return 0


def usage() -> str:
    """``--help``: the C tool's commands (its own usage text), then the package's."""
    from . import cli

    tool = subprocess.run([str(cli.tool()), "--help"], capture_output=True, text=True, check=False)
    lines = [tool.stdout.rstrip("\n"), "commands of the Python package (python -m pgloss, or the wheel's pgloss):"]
    for c in COMMANDS:
        head = f"{c.name} {c.args}"
        lines.append(f"  {head:<32} {c.help}" if len(head) <= 32 else f"  {head}\n  {'':<32} {c.help}")
    return "\n".join(lines) + "\n"


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Runs a command; returns its exit code. Called with argv None (as a program), a command of
    the C tool replaces this process with the tool; called with a list, it runs in a child.
    No command, or an option (--help, --version), ends in SystemExit, as argparse's options do."""
    from . import cli

    args = list(sys.argv[1:] if argv is None else argv)
    if not args or args[0] in ("-h", "--help"):
        text = usage()
        if not args:
            sys.stderr.write(text)
            raise SystemExit(2)
        raise SystemExit(_flush_stdout(text))
    command = next((c for c in COMMANDS if c.name == args[0]), None)
    if command is None:
        if argv is None:
            cli.exec_tool(args)
        rc = cli.run(args)
        if args[0].startswith("-"):
            raise SystemExit(rc)
        return rc
    parser = argparse.ArgumentParser(prog=f"pgloss {command.name}", description=command.description or command.help)
    command.arguments(parser)
    rc = command.run(parser.parse_args(args[1:]))
    return _flush_stdout() or rc


if __name__ == "__main__":
    sys.exit(main())
