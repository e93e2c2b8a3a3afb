# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pytest set-up for tests/materialx: with PGLOSS_REQUIRE_ALL=1 (the test scripts' default, and CI)
a skipped test is a failure (tests/require_all.py); the ``gl`` fixture, an OpenGL 4.0 context
on llvmpipe through EGL (moderngl) for the tests that run ShaderGen's GLSL."""
import os
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from require_all import pytest_sessionfinish, pytest_terminal_summary  # noqa: E402,F401


@pytest.fixture(scope="module")
def gl():
    moderngl = pytest.importorskip("moderngl", reason="moderngl runs the generated GLSL on llvmpipe")
    os.environ["LIBGL_ALWAYS_SOFTWARE"] = "1"
    os.environ.setdefault("GALLIUM_DRIVER", "llvmpipe")
    try:
        ctx = moderngl.create_context(standalone=True, backend="egl", require=400)
    except Exception as e:  # noqa: BLE001
        pytest.skip(f"no OpenGL context through EGL: {e}")
    assert "llvmpipe" in ctx.info["GL_RENDERER"], ctx.info["GL_RENDERER"]
    yield ctx
    ctx.release()
