# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The C tool's subcommands for ``python -m pgloss`` (tools/pgloss_cli.c is the specification).

``to-physical``, ``to-perceptual``, ``to-perceptual-rgb``, ``check``, ``match``, ``distance``,
``envelope``, ``eval`` and ``demo`` take the same positional arguments as the C tool
``pgloss``, print the same lines to standard output (the same printf formats) and exit with
the same codes: 0 when the result is ok or a warning, 1 when the core reports an error, 2 for
wrong arguments. One vocabulary for both: the argument names are the C tool's, the
normalisations ``ward``, ``ward-dur``, ``bounded`` are :class:`pgloss.Normalization`'s
``WARD``, ``WARD_DUR``, ``BOUNDED``.

Each command is a :class:`ToolCommand`: its name, its arguments (names of the numbers, and
whether a trailing normalisation is accepted), the usage line of the C tool and the function
that runs it on parsed numbers.
"""

from __future__ import annotations

import argparse
import math
import re
import sys
from typing import Callable, List, NamedTuple, Optional, Sequence, Tuple

import numpy as np

import pgloss
from pgloss import _core

DEG = math.pi / 180.0

#: The C tool's normalisation names.
NORMALIZATIONS = {"ward": pgloss.Normalization.WARD, "ward-dur": pgloss.Normalization.WARD_DUR,
                  "bounded": pgloss.Normalization.BOUNDED}


class ArgumentError(Exception):
    """A bad argument: the message is the C tool's line for it (on stderr); exit code 2."""


_NUMBER = re.compile(r"\s*[+-]?(?:(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?|inf(?:inity)?|nan(?:\([0-9A-Za-z_]*\))?"
                     r"|0[xX](?:[0-9a-fA-F]+\.?[0-9a-fA-F]*|\.[0-9a-fA-F]+)(?:[pP][+-]?\d+)?)", re.I)


def parse_double(text: str, name: str) -> float:
    """strtod's grammar, as the C tool accepts it: the whole string a number, no overflow."""
    if not _NUMBER.fullmatch(text):
        raise ArgumentError(f"pgloss: {name}: '{text}' is not a number")
    body = text.strip().lower()
    try:
        v = float.fromhex(body) if "0x" in body else float(body.split("(")[0])
    except ValueError:
        raise ArgumentError(f"pgloss: {name}: '{text}' is not a number") from None
    if math.isinf(v) and "inf" not in body:  # strtod: ERANGE on overflow
        raise ArgumentError(f"pgloss: {name}: '{text}' is not a number")
    if v == 0.0 and re.search(r"[1-9]", body.split("e")[0] if "0x" not in body else body.split("p")[0]):
        raise ArgumentError(f"pgloss: {name}: '{text}' is not a number")  # strtod: ERANGE on underflow to 0
    return v


def parse_norm(text: str) -> pgloss.Normalization:
    try:
        return NORMALIZATIONS[text]
    except KeyError:
        raise ArgumentError(f"pgloss: normalization: '{text}' is not one of ward, ward-dur, bounded") from None


def report(status: int) -> int:
    """The C tool's status line; the exit code (1 for an error)."""
    st = pgloss.Status(int(status))
    if st == pgloss.Status.OK:
        print("status: ok")
    else:
        print(f"status: {st.c_name} ({st.reason})")
    return 1 if st < 0 else 0


def _call(thunk: Callable[[], object]) -> Tuple[int, object]:
    """Runs a pgloss call; returns (status, result) with the status the C function returned."""
    import warnings

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            out = thunk()
        except pgloss.PglossError as e:
            return int(e.status), e.result
    if any(issubclass(w.category, pgloss.AlphaUntrustedWarning) for w in caught):
        return int(pgloss.Status.WARN_ALPHA_UNTRUSTED), out
    return 0, out


def direction(theta_deg: float, phi_deg: float) -> List[float]:
    """The C tool's direction: double trigonometry, rounded to float."""
    t, p = theta_deg * DEG, phi_deg * DEG
    return [float(np.float32(x)) for x in (math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t))]


# ---------------------------------------------------------------------------------------------
# The commands (v: the parsed numbers; norm: the optional normalisation).


def to_physical(v: List[float], norm: pgloss.Normalization) -> int:
    q = pgloss.Perceptual(*v)
    st, p = _call(lambda: pgloss.physical_from_perceptual(q, norm, check=False))
    if st >= 0 or st == pgloss.Status.ERR_GAMUT:
        rd = p.rho_d  # type: ignore[union-attr]
        print(f"rho_d = ({rd[0]:.6f}, {rd[1]:.6f}, {rd[2]:.6f})  rho_s = {p.rho_s:.6f}  "  # type: ignore[union-attr]
              f"alpha = {p.alpha_x:.6f}")  # type: ignore[union-attr]
    if st < 0:
        return report(st)
    return report(q.check())


def _to_perceptual(p: pgloss.Physical) -> int:
    st, q = _call(lambda: pgloss.perceptual_from_physical(p, check=False))
    if st >= 0:
        print(f"L* = {q.L:.4f}  a* = {q.a:.4f}  b* = {q.b:.4f}  c = {q.c:.6f}  d = {q.d:.6f}")  # type: ignore[union-attr]
    if st < 0:
        return report(st)
    return report(p.check())


def to_perceptual(v: List[float], norm: pgloss.Normalization) -> int:
    return _to_perceptual(pgloss.Physical(v[0], v[1], v[2]))


def to_perceptual_rgb(v: List[float], norm: pgloss.Normalization) -> int:
    return _to_perceptual(pgloss.Physical(v[0:3], v[3], v[4]))


def check(v: List[float], norm: pgloss.Normalization) -> int:
    return report(pgloss.Physical(v[0], v[1], v[2], normalization=norm).check())


def match(v: List[float], norm: pgloss.Normalization) -> int:
    st, r = _call(lambda: pgloss.match_gloss(v[0], v[1], v[2]))
    if st >= 0 or st == pgloss.Status.ERR_ENVELOPE:
        print(f"rho_d = {r[0]:.6f}  rho_s = {r[1]:.6f}")  # type: ignore[index]
    return report(st)


def distance(v: List[float], norm: pgloss.Normalization) -> int:
    st, D = _call(lambda: pgloss.gloss_distance(*v, check=False))
    if st >= 0:
        print(f"D = {D:.6f}")
    return report(st)


def envelope(v: List[float], norm: pgloss.Normalization) -> int:
    st, c = _call(lambda: pgloss.envelope_contrast(v[0]))
    if st >= 0:
        print(f"c_max = {c:.6f}")
    return report(st)


def eval_(v: List[float], norm: pgloss.Normalization) -> int:
    p = pgloss.Physical(v[0], v[1], v[2], normalization=norm)
    st, m = _call(p.material)
    if st != 0:  # the C tool stops at any status of pgloss_material_init
        return report(st)
    f, pdf, st = _core.eval_pdf_reference(m, int(pgloss.Lobe.ALL), direction(v[3], v[4]), direction(v[5], v[6]))
    if st >= 0:
        print("f = %.8g  pdf = %.8g" % (f[0], pdf))
    return report(st)


def demo(v: List[float], norm: pgloss.Normalization) -> int:
    """The paper's worked examples, line for line the C tool's ``pgloss demo``."""
    rd, rs, al = (0.03, 0.193, 0.767), (0.033, 0.066, 0.099), (0.04, 0.07, 0.10)
    names = ("black", "gray", "white")
    print("Experiment 1 stimuli (paper §3.2.3.1) in the perceptual gloss space (Fig. 9):")
    print("  %-6s %6s %6s %5s | %7s %7s %5s" % ("paint", "rho_d", "rho_s", "alpha", "L*", "c", "d"))
    for i in range(3):
        for j in range(3):
            for k in range(3):
                L, c, d = pgloss.gloss_from_physical(rd[i], rs[j], al[k])
                print("  %-6s %6.3f %6.3f %5.2f | %7.3f %7.4f %5.2f" % (names[i], rd[i], rs[j], al[k], L, c, d))

    print("\nMatching apparent gloss (§5.2, Fig. 12): rho_s = 0.099, alpha = 0.04")
    Lw, cw, dw = pgloss.gloss_from_physical(0.767, 0.099, 0.04)
    line = "  same physical gloss: "
    for i in (2, 1, 0):
        line += "%s c = %.3f  " % (names[i], pgloss.gloss_from_physical(rd[i], 0.099, 0.04)[1])
    print(line)
    print("  same perceptual gloss as white (c = %.3f, d = %.2f):" % (cw, dw))
    for i in (2, 1, 0):
        L = pgloss.gloss_from_physical(rd[i], 0.099, 0.04)[0]
        st, r = _call(lambda: pgloss.match_gloss(0.767, 0.099, L))
        print("    %-5s L* = %6.2f  rho_d = %.3f  rho_s = %.4f" % (names[i], L, r[0], r[1]))  # type: ignore[index]

    print("\nIsogloss contour (§5.1, Fig. 11) around c = 0.087, d = 0.93 at D = 0.04:\n  ", end="")
    cs, ds = pgloss.isogloss_contour(0.087, 0.93, 0.04, 8)
    print("".join("(%.3f, %.4f) " % (c, d) for c, d in zip(cs, ds)), end="")

    print("\n\nEnvelope of gloss space (Fig. 10): largest c per lightness\n  ", end="")
    print("".join("L*=%d: %.3f  " % (L, pgloss.envelope_contrast(float(L))) for L in range(0, 101, 20)), end="")

    print("\n\nA dark red paint from the colour/gloss picker (Fig. 13): L*=35 a*=45 b*=25 c=0.06 d=0.95")
    q = pgloss.Perceptual(35.0, 45.0, 25.0, 0.06, 0.95)
    st, p = _call(lambda: pgloss.physical_from_perceptual(q))
    print("  rho_d = (%.4f, %.4f, %.4f)  rho_s = %.4f  alpha = %.3f  [%s]" % (
        *p.rho_d, p.rho_s, p.alpha_x, pgloss.status_name(st)))  # type: ignore[union-attr]
    m = p.material()  # type: ignore[union-attr]
    f, pdf, _ = _core.eval_pdf_reference(m, int(pgloss.Lobe.ALL), direction(30, 0), direction(30, 180))
    print("  BRDF in the mirror direction at 30 degrees: f = (%.4f, %.4f, %.4f) /sr, pdf = %.3f" % (*f, pdf))
    return 0


class ToolCommand(NamedTuple):
    """A subcommand of the C tool: name, number names, optional trailing normalisation, usage
    line (as the C tool's), runner."""

    name: str
    numbers: Tuple[str, ...]
    norm: bool
    usage: str
    run: Callable[[List[float], pgloss.Normalization], int]


#: The C tool's subcommands, in its usage order.
TOOL_COMMANDS: Tuple[ToolCommand, ...] = (
    ToolCommand("to-physical", ("L", "a", "b", "c", "d"), True,
                "perceptual (Fig. 13) -> rho_d (linear Rec.709 RGB), rho_s, alpha", to_physical),
    ToolCommand("to-perceptual", ("rho_d", "rho_s", "alpha"), False, "achromatic physical -> L*, c, d (eqs. 3, 4)",
                to_perceptual),
    ToolCommand("to-perceptual-rgb", ("r", "g", "b", "rho_s", "alpha"), False,
                "RGB physical -> L*, a*, b*, c, d", to_perceptual_rgb),
    ToolCommand("check", ("rho_d", "rho_s", "alpha"), True, "is the paint inside the paper's model, and if not, why",
                check),
    ToolCommand("match", ("rho_d", "rho_s", "L_target"), False, "same apparent gloss at another lightness (Fig. 12)",
                match),
    ToolCommand("distance", ("c1", "d1", "c2", "d2"), False, "gloss difference (eq. 5)", distance),
    ToolCommand("envelope", ("L",), False, "largest c at lightness L (Fig. 10)", envelope),
    ToolCommand("eval", ("rho_d", "rho_s", "alpha", "theta_o", "phi_o", "theta_i", "phi_i"), True,
                "BRDF value and pdf, angles in degrees", eval_),
    ToolCommand("demo", (), False, "the paper's worked examples", demo),
)


def add_arguments(command: ToolCommand, parser: argparse.ArgumentParser) -> None:
    """The arguments as strings (parsed by :func:`run`, with the C tool's messages)."""
    for name in command.numbers:
        parser.add_argument(name, metavar=name)
    if command.norm:
        parser.add_argument("norm", nargs="?", default=None, metavar="norm",
                            help="ward (eq. 2, default) | ward-dur | bounded")
    parser.set_defaults(tool_command=command)


def usage() -> str:
    """The C tool's usage text, from the command table."""
    lines = ["usage: pgloss <command> [args]"]
    for t in TOOL_COMMANDS:
        head = " ".join((t.name, *t.numbers, *(("[norm]",) if t.norm else ())))
        lines.append(f"  {head:<32} {t.usage}" if len(head) <= 32 else f"  {head}\n  {'':<32} {t.usage}")
    lines.append(f"  {'--version':<32} the version of the pgloss library in use")
    lines.append("norm: ward (eq. 2, default) | ward-dur | bounded")
    return "\n".join(lines) + "\n"


def run_argv(command: ToolCommand, argv: Sequence[str]) -> int:
    """Runs a command on its raw arguments, as the C tool reads them: positional only, so that
    negative numbers such as ``-1e3`` or ``-inf`` are numbers, not options; a wrong count or a
    bad number prints the C tool's lines to stderr and returns 2."""
    n = len(command.numbers)
    ok = len(argv) == n or (command.norm and len(argv) == n + 1)
    try:
        if not ok:
            raise ArgumentError("")
        values = [parse_double(a, name) for a, name in zip(argv, command.numbers)]
        norm = parse_norm(argv[n]) if len(argv) > n else pgloss.Normalization.WARD
    except ArgumentError as e:
        if str(e):
            print(e, file=sys.stderr)
        print(f"pgloss {command.name}: wrong arguments\n{usage()}", end="", file=sys.stderr)
        return 2
    return command.run(values, norm)


def run(args: argparse.Namespace) -> int:
    """The argparse entry (``python -m pgloss CMD --help`` shows the arguments)."""
    command: ToolCommand = args.tool_command
    raw = [getattr(args, name) for name in command.numbers]
    if command.norm and args.norm is not None:
        raw.append(args.norm)
    return run_argv(command, raw)


def find(name: str) -> Optional[ToolCommand]:
    """The tool command of that name, if any."""
    return next((t for t in TOOL_COMMANDS if t.name == name), None)


def main(argv: Optional[Sequence[str]] = None) -> int:  # pragma: no cover - use python -m pgloss
    from .__main__ import main as package_main

    return package_main(argv)
