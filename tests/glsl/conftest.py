# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pytest fixtures of the GLSL tests: one EGL context for the session."""
from __future__ import annotations

import os
import pathlib
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))


@pytest.fixture(scope="session")
def gl_ctx():
    """Headless EGL OpenGL 4.5 context on the device PGLOSS_GLSL_DEVICE names (llvmpipe by
    default). Without EGL/llvmpipe: a failure under PGLOSS_REQUIRE_ALL=1, else a skip."""
    import glsl_vectors

    try:
        ctx = glsl_vectors.create_context()
    except Exception as e:  # noqa: BLE001 - any EGL/driver failure means "no device"
        if os.environ.get("PGLOSS_REQUIRE_ALL") == "1":
            pytest.fail(f"no OpenGL 4.5 context through EGL ({e}); PGLOSS_REQUIRE_ALL=1 forbids skipping")
        pytest.skip(f"no OpenGL 4.5 context through EGL: {e}")
    print(f"\nGL renderer: {ctx.info['GL_RENDERER']} | {ctx.info['GL_VERSION']}")
    yield ctx
    ctx.release()


sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from require_all import pytest_sessionfinish, pytest_terminal_summary  # noqa: E402,F401
