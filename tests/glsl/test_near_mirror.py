# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pgloss_eval_pdf near the mirror direction, on unit directions rounded to float, against
eq. 2 in double (tests/vectors/near_mirror.py): the accuracy of the cancellation-free half
vector of pgloss_impl_eval_pdf, and exact reciprocity of f."""
from __future__ import annotations

import sys

import glsl_vectors as gv

sys.path.insert(0, str(gv.ROOT / "tests" / "vectors"))
import near_mirror as nm  # noqa: E402


def test_near_mirror_accuracy_and_reciprocity(gl_ctx) -> None:
    c = nm.cases()

    def jobs(wo, wi):
        return [gv.Job({"id": "near_mirror"}, "brdf_eval",
                       [0.0, 0.0, 0.0, nm.RHO_S, float(a), float(a)] + [float(v) for v in o] + [float(v) for v in i],
                       [gv.FN["brdf_eval"], 0, 3, 0])  # WARD, all lobes (the material: specular only)
                for a, o, i in zip(c["alpha"], wo, wi)]

    fout, iout = gv.run_jobs(gl_ctx, jobs(c["wo"], c["wi"]))
    fswap, _ = gv.run_jobs(gl_ctx, jobs(c["wi"], c["wo"]))
    assert (iout[:, :4] == 0).all(), "statuses of eval, pdf, eval_pdf, material_init"
    # eval_pdf's f (slots 4-6) and pdf (7); eval's f (0-2) must be the same numbers
    assert (fout[:, 0] == fout[:, 4]).all()
    print("\nGLSL " + nm.check(fout[:, 4], fout[:, 7], fswap[:, 4], c))
