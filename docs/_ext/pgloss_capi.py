# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The C API reference, generated from the public headers (no Doxygen, no libclang).

The directive ``.. pgloss-c-api::`` (docs/api/c.rst) reads every header of
``pgloss_capi_include_dir/pgloss/*.h`` (not ``detail/``): ``pgloss.h`` first, then the headers
it includes in its order, then the others by name. For each header it emits a section holding
the header's top comment, then, in the header's order, every declaration with the comment
block immediately above it, as Sphinx's C domain objects (cross-referenceable):

* ``PGLOSS_API`` function declarations → ``c:function`` (the mark is left out of the signature);
* ``static inline`` / ``PGLOSS_INLINE_FN`` functions of the public names → ``c:function``
  (names with a prefix of ``pgloss_capi_internal_prefixes`` are internal and left out);
* ``typedef struct`` → ``c:struct`` with a ``c:member`` per field, ``typedef enum`` →
  ``c:enum`` with a ``c:enumerator`` per value, other typedefs → ``c:type``;
* ``#define`` constants outside conditional blocks → ``c:macro`` with their value.

A declaration without a comment of its own that follows a commented one of the same kind on the
next line shares its comment (one entry with several signatures). A comment on the line where a
field or enumerator ends is that field's; a comment on lines of its own inside a struct or enum
body is shown in its place between the fields.

Nothing is dropped silently: a declaration this reader does not recognise (a function without
``PGLOSS_API``, a variable, a nested struct, a directive it does not know) is a warning at the
header's line, and so is anything the C domain cannot parse (its warning is located at the
header's line too); the docs build runs with -W, so either fails it. A new function, type or
constant in a header appears in the reference without editing the docs.

Comment text goes in as text: prose paragraphs reflowed with every reST special escaped, and
paragraphs laid out with indentation or aligned columns (tables, formulas) as preformatted
``text`` blocks, so that no comment can produce markup or a warning.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from docutils import nodes
from docutils.statemachine import StringList
from sphinx.application import Sphinx
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective
from sphinx.util.nodes import nested_parse_with_titles

logger = logging.getLogger(__name__)


# ---- reading a header ------------------------------------------------------------------------


@dataclass
class Comment:
    text: str  # cleaned: no /* */ or leading " * ", dedented
    line: int  # 1-based first line
    end: int  # 1-based last line


@dataclass
class Member:
    """A struct field or an enumerator (sig), its trailing comment, or a free comment (sig None)."""
    sig: str | None
    line: int
    doc: str = ""


@dataclass
class Decl:
    kind: str  # function, struct, enum, type, macro
    name: str
    sigs: list[str]
    line: int
    end: int
    doc: str = ""
    values: list[tuple[str, str]] = field(default_factory=list)  # macro: (name, value) per signature
    members: list[Member] = field(default_factory=list)


@dataclass
class Header:
    path: Path
    name: str  # pgloss/brdf.h
    top: str = ""
    decls: list[Decl] = field(default_factory=list)
    includes: list[str] = field(default_factory=list)
    problems: list[tuple[int, str]] = field(default_factory=list)


def _clean_comment(raw: str) -> str:
    """/* ... */ or // ... → its text, without the comment marks and the ' * ' gutter."""
    if raw.startswith("//"):
        lines = [ln[2:] for ln in raw.splitlines()]
    else:
        body = raw[2:-2]
        lines = body.split("\n")
        out = []
        for i, ln in enumerate(lines):
            s = ln.rstrip()
            if i > 0:
                m = re.match(r"^\s*\*(?!/)", s)
                if m:
                    s = s[m.end():]
                else:
                    s = s.lstrip()  # a continuation line without the gutter (aligned text)
            out.append(s)
        lines = out
    while lines and not lines[0].strip():
        lines.pop(0)
    while lines and not lines[-1].strip():
        lines.pop()
    # a first line right after "/*" has lost its indentation; dedent the rest by their common indent
    rest = [ln for ln in lines[1:] if ln.strip()]
    indent = min((len(ln) - len(ln.lstrip(" ")) for ln in rest), default=0)
    first = lines[0].strip() if lines else ""
    lines = [first] + [ln[indent:] if ln.strip() else "" for ln in lines[1:]]
    if lines and not first:
        lines = lines[1:]
    return "\n".join(lines).strip("\n")


def _preprocess(text: str, header: Header) -> tuple[str, list[Decl]]:
    """Blanks preprocessor lines and the contents of conditional blocks (keeping line numbers);
    returns the remaining text and the #define constants found outside conditionals."""
    lines = text.split("\n")
    out: list[str] = []
    macros: list[Decl] = []
    depth = 0  # conditional nesting, the include guard not counted
    guard: str | None = None
    in_comment = False
    i = 0
    while i < len(lines):
        ln = lines[i]
        stripped = ln.strip()
        if not in_comment and stripped.startswith("#"):
            start = i
            full = ln
            while full.endswith("\\") and i + 1 < len(lines):  # continuation lines
                i += 1
                full = full[:-1] + " " + lines[i]
            m = re.match(r"\s*#\s*(\w+)\s*(.*)$", full)
            directive, rest = (m.group(1), m.group(2)) if m else ("", "")
            blank = [""] * (i - start + 1)
            if directive in ("if", "ifdef", "ifndef"):
                nxt = lines[i + 1].strip() if i + 1 < len(lines) else ""
                if (guard is None and directive == "ifndef" and depth == 0
                        and re.fullmatch(r"#\s*define\s+" + re.escape(rest.strip()), nxt)):
                    guard = rest.strip()
                    out += blank + [""]
                    i += 2
                    continue
                depth += 1
            elif directive == "endif":
                if depth > 0:
                    depth -= 1
                elif guard is None:
                    header.problems.append((start + 1, "#endif without #if"))
            elif directive in ("else", "elif"):
                pass
            elif depth > 0:
                pass  # inside a conditional block: not part of the reference
            elif directive == "include":
                inc = re.match(r'"([^"]+)"', rest.strip())
                if inc:
                    header.includes.append(inc.group(1))
            elif directive == "define":
                d = _parse_define(rest, start + 1, header)
                if d:
                    macros.append(d)
            elif directive in ("undef", "pragma"):
                pass
            else:
                header.problems.append((start + 1, f"unrecognised preprocessor directive #{directive}"))
            out += blank
            i += 1
            continue
        if depth > 0:
            out.append("")
        else:
            out.append(ln)
        # track block comments, so that a '#' inside one is not taken for a directive
        pos = 0
        while True:
            if in_comment:
                e = ln.find("*/", pos)
                if e < 0:
                    break
                in_comment, pos = False, e + 2
            else:
                s = ln.find("/*", pos)
                sl = ln.find("//", pos)
                if s < 0 or (0 <= sl < s):
                    break
                in_comment, pos = True, s + 2
        i += 1
    return "\n".join(out), macros


def _parse_define(rest: str, line: int, header: Header) -> Decl | None:
    doc = ""
    m = re.search(r"/\*(.*?)\*/\s*$", rest)  # a trailing comment
    if m:
        doc = _clean_comment("/*" + m.group(1) + "*/")
        rest = rest[: m.start()]
    m = re.match(r"(\w+)(\([^)]*\))?\s*(.*)$", rest.strip())
    if not m:
        header.problems.append((line, f"cannot read #define {rest.strip()!r}"))
        return None
    name, params, value = m.group(1), m.group(2) or "", m.group(3).strip()
    if not value and not params:
        header.problems.append((line, f"#define {name} without a value: not a constant the reference knows"))
        return None
    return Decl("macro", name, [name + params], line, line, doc=doc, values=[(name + params, value)])


@dataclass
class _Tok:
    kind: str  # comment, stmt
    text: str
    line: int
    end: int


def _line_of(text: str, pos: int) -> int:
    return text.count("\n", 0, pos) + 1


def _tokens(text: str, header: Header) -> list[_Tok]:
    """Top-level comments and statements (up to ';' at brace depth 0, or a function body)."""
    toks: list[_Tok] = []
    i, n = 0, len(text)
    stmt_start = None
    depth = 0
    while i < n:
        c = text[i]
        if text.startswith("/*", i) or text.startswith("//", i):
            e = _comment_end(text, i)
            if depth == 0 and stmt_start is None:
                toks.append(_Tok("comment", text[i:e], _line_of(text, i), _line_of(text, e - 1)))
            i = e
            continue
        if c in "\"'":  # a string or character literal
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            i = j + 1
            continue
        if c.isspace():
            i += 1
            continue
        if stmt_start is None:
            stmt_start = i
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth < 0:
                header.problems.append((_line_of(text, i), "unbalanced '}'"))
                depth = 0
            if depth == 0:
                head = text[stmt_start: text.find("{", stmt_start)]
                if _strip_comments(head).rstrip().endswith(")"):  # a function definition ends here
                    toks.append(_Tok("stmt", text[stmt_start: i + 1], _line_of(text, stmt_start), _line_of(text, i)))
                    stmt_start = None
        elif c == ";" and depth == 0:
            toks.append(_Tok("stmt", text[stmt_start: i + 1], _line_of(text, stmt_start), _line_of(text, i)))
            stmt_start = None
        i += 1
    if stmt_start is not None:
        header.problems.append((_line_of(text, stmt_start), "unterminated declaration at the end of the header"))
    return toks


def _comment_end(s: str, i: int) -> int:
    """The end (exclusive) of the comment that starts at s[i]."""
    if s.startswith("/*", i):
        e = s.find("*/", i + 2)
        return len(s) if e < 0 else e + 2
    e = s.find("\n", i)
    return len(s) if e < 0 else e


def _strip_comments(s: str) -> str:
    s = re.sub(r"/\*.*?\*/", " ", s, flags=re.S)
    return re.sub(r"//[^\n]*", " ", s)


def _one_line(s: str) -> str:
    s = re.sub(r"\s+", " ", _strip_comments(s)).strip()
    return re.sub(r"\(\s+", "(", re.sub(r"\s+\)", ")", s))


def _split_top(s: str, sep: str) -> list[str]:
    """s split at sep outside (), [] and {}."""
    parts, depth, cur = [], 0, ""
    for ch in s:
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == sep and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    parts.append(cur)
    return parts


def _body_items(body: str, line0: int, sep: str) -> list[tuple[str | None, int, str]]:
    """The items of a struct (sep ';') or enum (sep ',') body with their comments:
    (text, line, trailing comment) for an item, (None, line, comment) for a free comment."""
    items: list[list] = []  # [text or None, line, doc, end line]
    cur, cur_line, cur_last, cur_doc = "", None, None, ""
    last_item = None
    i, n, depth = 0, len(body), 0

    def line_at(p: int) -> int:
        return line0 + body.count("\n", 0, p)

    while i < n:
        if body.startswith("/*", i) or body.startswith("//", i):
            e = _comment_end(body, i)
            text = _clean_comment(body[i:e])
            ln = line_at(i)
            if cur.strip() and cur_last == ln:
                cur_doc = (cur_doc + "\n\n" + text).strip()
            elif not cur.strip() and last_item is not None and last_item[3] == ln:
                last_item[2] = (last_item[2] + "\n\n" + text).strip()
            elif cur.strip():
                cur_doc = (cur_doc + "\n\n" + text).strip()  # inside a declaration spread over lines
            else:
                items.append([None, ln, text, line_at(e - 1)])
            i = e
            continue
        ch = body[i]
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == sep and depth == 0:
            if cur.strip():
                last_item = [_one_line(cur), cur_line, cur_doc, line_at(i)]
                items.append(last_item)
            cur, cur_line, cur_last, cur_doc = "", None, None, ""
        else:
            if not ch.isspace():
                if cur_line is None:
                    cur_line = line_at(i)
                cur_last = line_at(i)
            cur += ch
        i += 1
    if cur.strip():
        items.append([_one_line(cur), cur_line, cur_doc, cur_last])
    return [(t, ln, d) for t, ln, d, _ in items]


_DECLARATOR = re.compile(r"^(.*?)(\**\s*\w+\s*(?:\[[^\]]*\]\s*)*)$")


def _members(body: str, line0: int, header: Header, where: str) -> list[Member]:
    out = []
    for text, ln, doc in _body_items(body, line0, ";"):
        if text is None:
            out.append(Member(None, ln, doc))
            continue
        if re.search(r"\b(struct|union|enum)\b[^;]*\{", text) or "{" in text:
            header.problems.append((ln, f"{where}: a nested struct, union or enum is not supported: {text!r}"))
            continue
        parts = [p.strip() for p in _split_top(text, ",")]
        if len(parts) == 1:
            out.append(Member(parts[0], ln, doc))
            continue
        m = _DECLARATOR.match(parts[0])
        if not m or not m.group(1).strip():
            header.problems.append((ln, f"{where}: cannot split the field declaration {text!r}"))
            continue
        base = m.group(1).strip()
        for k, p in enumerate([m.group(2).strip()] + parts[1:]):
            out.append(Member(f"{base} {p}", ln, doc if k == 0 else ""))
    return out


def _enumerators(body: str, line0: int) -> list[Member]:
    return [Member(t, ln, d) for t, ln, d in _body_items(body, line0, ",")]


def _function_name(sig: str) -> str | None:
    m = re.search(r"(\w+)\s*\(", sig)
    return m.group(1) if m else None


def _statement(tok: _Tok, text: str, header: Header, internal: tuple[str, ...]) -> Decl | None:
    s = tok.text
    flat = _one_line(s)
    bare = flat.rstrip(";").strip()
    # typedef struct / enum with a body, or a plain struct / enum definition
    m = re.match(r"^(typedef\s+)?(struct|enum)\s*(\w+)?\s*\{", bare)
    if m:
        kind = m.group(2)
        ob = s.index("{")
        cb = s.rindex("}")
        after = _one_line(s[cb + 1:]).rstrip(";").strip()
        tag = m.group(3)
        if m.group(1):
            if not re.fullmatch(r"\w+", after):
                header.problems.append((tok.line, f"typedef {kind} declaring {after!r}: not a single type name"))
                return None
            name = after
        else:
            if after:
                header.problems.append((tok.line, f"a {kind} definition that also declares {after!r} (a variable)"))
                return None
            name = tag
        if not name:
            header.problems.append((tok.line, f"an anonymous {kind} without a typedef name"))
            return None
        body_line = tok.line + s.count("\n", 0, ob)
        body = s[ob + 1: cb]
        d = Decl(kind, name, [name], tok.line, tok.end)
        d.members = (_members(body, body_line, header, name) if kind == "struct"
                     else _enumerators(body, body_line))
        return d
    if bare.startswith("typedef "):
        rest = bare[len("typedef "):]
        name = None
        fp = re.search(r"\(\s*\*\s*(\w+)\s*\)", rest)
        if fp:
            name = fp.group(1)
        else:
            mm = re.search(r"(\w+)\s*(\[[^\]]*\]\s*)*$", rest)
            name = mm.group(1) if mm else None
        if not name:
            header.problems.append((tok.line, f"cannot read the typedef {bare!r}"))
            return None
        return Decl("type", name, [rest], tok.line, tok.end)
    if "{" in s:  # a function definition
        head = _one_line(s[: s.index("{")])
        m = re.match(r"^(static\s+inline|PGLOSS_INLINE_FN)\s+(.*)$", head)
        if not m:
            header.problems.append((tok.line, f"a definition that is not a static inline function: {head!r}"))
            return None
        sig = "static inline " + m.group(2)
        name = _function_name(m.group(2))
        if name is None:
            header.problems.append((tok.line, f"cannot find the function's name in {head!r}"))
            return None
        if name.startswith(internal):
            return None
        return Decl("function", name, [sig], tok.line, tok.end)
    if re.search(r"\bPGLOSS_API\b", bare):
        sig = re.sub(r"\bPGLOSS_API\b\s*", "", bare).strip()
        name = _function_name(sig)
        if name is None or not sig.endswith(")"):
            header.problems.append((tok.line, f"PGLOSS_API on something that is not a function declaration: {bare!r}"))
            return None
        return Decl("function", name, [sig], tok.line, tok.end)
    name = _function_name(bare)
    if name and bare.endswith(")"):
        if name.startswith(internal):
            return None
        header.problems.append((tok.line, f"function {name} is declared without PGLOSS_API (not exported by a shared build): {bare!r}"))
        return None
    header.problems.append((tok.line, f"unrecognised declaration {bare!r}"))
    return None


def read_header(path: Path, name: str, internal: tuple[str, ...]) -> Header:
    header = Header(path, name)
    raw = path.read_text(encoding="utf-8")
    code, macros = _preprocess(raw, header)
    toks = _tokens(code, header)
    # the header's top comment: its first block comment (the SPDX lines are // comments)
    items: list[Decl] = []
    first_comment = True
    pending: Comment | None = None
    stmt_decls: list[tuple[_Tok, Decl | None]] = []
    comments: list[Comment] = []
    for t in toks:
        if t.kind == "comment":
            if t.text.startswith("//") and "SPDX-" in t.text:
                continue
            if first_comment and t.text.startswith("/*"):
                header.top = _clean_comment(t.text)
                first_comment = False
                continue
            comments.append(Comment(_clean_comment(t.text), t.line, t.end))
        else:
            first_comment = False
            stmt_decls.append((t, _statement(t, code, header, internal)))
    decls = [d for _, d in stmt_decls if d is not None] + macros
    # every top-level thing in line order, to find what is immediately above each declaration
    events: list[tuple[int, int, object]] = [(c.line, 0, c) for c in comments]
    events += [(t.line, 1, (t, d)) for t, d in stmt_decls]
    events += [(m.line, 1, (None, m)) for m in macros]
    events.sort(key=lambda e: (e[0], e[1]))
    prev_end = -10  # last line of the previous declaration or comment
    prev_decl: Decl | None = None
    for line, _, ev in events:
        if isinstance(ev, Comment):
            if prev_decl is not None and ev.line == prev_end and not prev_decl.doc:
                prev_decl.doc = ev.text  # a comment on the line where the declaration ends
                continue
            pending = ev
            prev_end = ev.end
            prev_decl = None
            continue
        tok, d = ev
        end = tok.end if tok is not None else line
        if d is None:
            pending, prev_decl, prev_end = None, None, end
            continue
        if pending is not None and pending.end == line - 1:
            d.doc = (pending.text + ("\n\n" + d.doc if d.doc else "")).strip()
            items.append(d)
        elif (prev_decl is not None and prev_end == line - 1 and not d.doc and prev_decl.kind == d.kind
              and d.kind in ("function", "macro") and prev_decl.doc):
            prev_decl.sigs += d.sigs  # shares the comment above the group
            prev_decl.values += d.values
            prev_end = end
            continue
        else:
            items.append(d)
        pending = None
        prev_decl, prev_end = d, end
    header.decls = items
    return header


# ---- writing reST ----------------------------------------------------------------------------

_SPECIAL = re.compile(r"([\\`*_|:\[\]<>])")


def _is_preformatted(par: list[str]) -> bool:
    for k, ln in enumerate(par):
        if k > 0 and ln.startswith((" ", "\t")):
            return True
        if re.search(r"\S {3,}\S", ln) or (k == 0 and ln.startswith((" ", "\t"))):
            return True
        if re.match(r"\s*([-*+•]|\d+\.)\s", ln) and k == 0 and len(par) > 1:
            return True
    return False


def comment_rst(text: str, indent: str) -> list[str]:
    """A comment as reST: prose paragraphs escaped and reflowed, laid-out ones preformatted."""
    out: list[str] = []
    pars: list[list[str]] = []
    cur: list[str] = []
    for ln in text.split("\n"):
        if ln.strip():
            cur.append(ln.rstrip())
        elif cur:
            pars.append(cur)
            cur = []
    if cur:
        pars.append(cur)
    for par in pars:
        if _is_preformatted(par):
            out += [f"{indent}.. code-block:: text", ""]
            out += [f"{indent}   {ln}" for ln in par]
        else:
            flat = " ".join(ln.strip() for ln in par)
            flat = _SPECIAL.sub(r"\\\1", flat)
            if not flat.startswith("\\"):
                flat = "\\" + flat  # no list, section, directive or transition can start here
            out.append(indent + flat)
        out.append("")
    return out


def _literal(s: str) -> str:
    if "``" in s or s.endswith("`") or s.startswith("`"):
        return ":code:`" + s.replace("\\", "\\\\").replace("`", "\\`") + "`"
    return f"``{s}``"


def header_rst(h: Header) -> list[tuple[str, int]]:
    """(line, header line number) pairs: the section of one header."""
    out: list[tuple[str, int]] = []

    def add(lines, ln):
        out.extend((x, ln) for x in lines)

    add(["", h.name, "-" * max(len(h.name), 4), ""], 1)
    add(comment_rst(h.top, ""), 1)
    for d in h.decls:
        directive = {"function": "c:function", "struct": "c:struct", "enum": "c:enum",
                     "type": "c:type", "macro": "c:macro"}[d.kind]
        pad = " " * (len(directive) + 5)
        lines = [f".. {directive}:: {d.sigs[0]}"] + [pad + s for s in d.sigs[1:]]
        lines.append("")
        if d.doc:
            lines += comment_rst(d.doc, "   ")
        if len(d.values) == 1:
            lines += [f"   Value: {_literal(d.values[0][1])}", ""]
        else:
            for sig, value in d.values:
                lines += [f"   | {_literal(sig)}: {_literal(value)}"]
            lines.append("")
        add(lines, d.line)
        for m in d.members if d.kind in ("struct", "enum") else []:
            if m.sig is None:
                add(comment_rst(m.doc, "   "), m.line)
                continue
            sub = "c:member" if d.kind == "struct" else "c:enumerator"
            ml = [f"   .. {sub}:: {m.sig}", ""]
            if m.doc:
                ml += comment_rst(m.doc, "      ")
            add(ml, m.line)
    return out


def ordered_headers(include_dir: Path) -> list[Path]:
    root = include_dir / "pgloss"
    all_h = sorted(p for p in root.glob("*.h"))
    order: list[Path] = []
    umbrella = root / "pgloss.h"
    if umbrella.exists():
        order.append(umbrella)
        for inc in re.findall(r'#\s*include\s+"pgloss/([^"/]+\.h)"', umbrella.read_text(encoding="utf-8")):
            p = root / inc
            if p.exists() and p not in order:
                order.append(p)
    order += [p for p in all_h if p not in order]
    return order


class CApiDirective(SphinxDirective):
    """``.. pgloss-c-api::`` — every public header, one section each."""

    has_content = False
    required_arguments = 0

    def run(self) -> list[nodes.Node]:
        cfg = self.config
        include_dir = Path(self.env.srcdir, cfg.pgloss_capi_include_dir).resolve()
        internal = tuple(cfg.pgloss_capi_internal_prefixes)
        headers = ordered_headers(include_dir)
        if not headers:
            logger.warning("pgloss_capi: no headers in %s", include_dir, location=self.get_location())
            return []
        content = StringList()
        for path in headers:
            self.env.note_dependency(str(path))
            rel = f"pgloss/{path.name}"
            h = read_header(path, rel, internal)
            for ln, msg in h.problems:
                logger.warning("pgloss_capi: %s", msg, location=f"{path}:{ln}", type="pgloss_capi")
            for text, ln in header_rst(h):
                content.append(text, str(path), ln - 1)
        node = nodes.container()  # a holder; its children are returned
        nested_parse_with_titles(self.state, content, node)
        return node.children


def setup(app: Sphinx) -> dict:
    app.add_config_value("pgloss_capi_include_dir", "../libpgloss/include", "env")
    app.add_config_value("pgloss_capi_internal_prefixes", ["pgloss_inl_", "pgloss__"], "env")
    app.add_directive("pgloss-c-api", CApiDirective)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
