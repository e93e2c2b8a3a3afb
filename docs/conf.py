# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The pgloss docs site: Sphinx with MyST-Parser (Markdown pages). `bash scripts/docs.sh` builds
# it into out/docs with warnings as errors, runs its Python examples (the doctest builder) and
# compiles and runs its C examples (docs/examples/*.c).
#
# Why Sphinx (and not MkDocs): what this site needs is built in — the C domain (the C API
# reference, generated from the headers by docs/_ext/pgloss_capi.py, cross-referenceable),
# autodoc for the pybind11 module and the package's docstrings, and the doctest builder that
# executes the examples; colour-science, MaterialX and Mitsuba 3 document themselves with it.
# MyST-Parser lets the pages (and the design notes that the README links to) stay Markdown.
import os
import re
import sys
from pathlib import Path

here = Path(__file__).resolve().parent
sys.path.insert(0, str(here / "_ext"))

version_h = (here.parent / "libpgloss/include/pgloss/version.h").read_text(encoding="utf-8")
release = re.search(r'#define PGLOSS_VERSION_STRING "([^"]+)"', version_h).group(1)
version = release
project = "pgloss"
author = "The pgloss authors"
copyright = "2026, The pgloss authors"

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.doctest",
    "sphinx.ext.mathjax",
    "sphinx.ext.napoleon",
    "pgloss_capi",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "examples", "README.md", "**/README.md"]

# Everything offline: no intersphinx (no network while building); MathJax is loaded by the
# reader's browser, not by the build.

# MyST: ```{directive} fences, ::: fences (colon_fence), $…$ and $$…$$ maths (dollarmath,
# amsmath), and anchors for ## and ### headings, so that [text](page.md#a-heading) resolves.
myst_enable_extensions = ["colon_fence", "dollarmath", "amsmath", "deflist"]
myst_heading_anchors = 3

# Every C cross-reference must resolve ({c:func}`pgloss_eval` in a page, a type in a signature),
# except the C standard library's types. Python references are not held to it: the docstrings'
# type descriptions name numpy's and the standard library's classes, which an offline build
# (no intersphinx) cannot link.
nitpicky = True
nitpick_ignore_regex = [
    (r"c:identifier", r"(u?int(8|16|32|64)_t|u?intptr_t|size_t|ptrdiff_t|FILE|bool)"),
    (r"py:.*", r".*"),
]

# The C domain: PGLOSS_API is an attribute (pgloss/export.h), if a page writes it in a signature.
c_id_attributes = ["PGLOSS_API"]
c_maximum_signature_line_length = 100
pgloss_capi_include_dir = "../libpgloss/include"

# autodoc: members in the source's order; the pybind11 signatures come from the docstrings.
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "show-inheritance": True}
autodoc_typehints = "description"

# Docstrings are numpydoc-styled ("Parameters", "Examples" sections): napoleon reads them.
napoleon_google_docstring = False
napoleon_numpy_docstring = True

# doctest: every ```{doctest} block of the pages and every >>> block of the docstrings that
# autodoc brings in run as they are written (no global setup: an example imports what it uses).
doctest_test_doctest_blocks = "default"

html_theme = "alabaster"
html_title = f"pgloss {release}"
html_theme_options = {"description": "Pellacini, Ferwerda & Greenberg's gloss model", "fixed_sidebar": False}
html_static_path = []
html_show_sourcelink = False
