# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Scenes of a chosen triangle count for the tracer's scaling benchmark: a tracer scene whose
`mesh` lines' OBJ files are subdivided, each triangle into n^2 (its edges cut into n equal
parts, the new vertices on the triangle's plane).

The surface does not change, so every size renders the same image: what grows is the cost of
the triangles alone (BVH depth, build time, memory). Vertices on an edge that two triangles
share are computed once, from the edge's lower vertex index, so the subdivided mesh stays
watertight where the original was (no cracks for rays to leak through).

    python examples/tracer/bench/subdivide_mesh.py SCENE N OUT_DIR   # writes OUT_DIR/SCENE-STEM-nN.scene
"""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

import numpy as np


def read_obj(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (v x y z) and faces (f, fan-triangulated, 0-based) of an OBJ file."""
    verts, faces = [], []
    for line in path.read_text().splitlines():
        w = line.split("#", 1)[0].split()
        if not w:
            continue
        if w[0] == "v":
            verts.append([float(x) for x in w[1:4]])
        elif w[0] == "f":
            idx = [int(t.split("/")[0]) for t in w[1:]]
            idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
            faces.extend([idx[0], idx[k], idx[k + 1]] for k in range(1, len(idx) - 1))
    return np.array(verts, dtype=np.float64), np.array(faces, dtype=np.int64)


def subdivide(v: np.ndarray, f: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Each triangle (a, b, c) into n^2: the points P(i, j) = a + i/n (b - a) + j/n (c - a),
    i, j >= 0, i + j <= n, joined as triangles that keep (a, b, c)'s orientation. The two of a
    grid cell follow each other as a pair (p, q, r), (p, r, s) sharing the diagonal p r, as a
    quad mesh's exporter writes its quads: (P(i+1, j), P(i+1, j+1), P(i, j+1)) and
    (P(i+1, j), P(i, j+1), P(i, j)); the cells along the edge b c have the second alone."""
    if n == 1:
        return v, f
    nt = len(f)
    # Unique edges (lo, hi) and each triangle side's edge index.
    sides = np.stack([f[:, [0, 1]], f[:, [0, 2]], f[:, [1, 2]]], axis=1)  # ab, ac, bc
    lo, hi = sides.min(axis=2), sides.max(axis=2)
    edges, inverse = np.unique(np.stack([lo.ravel(), hi.ravel()], axis=1), axis=0, return_inverse=True)
    side_edge = inverse.reshape(nt, 3)
    # Edge vertices: lo + k/n (hi - lo), k = 1 .. n-1; interior vertices per triangle.
    k = np.arange(1, n)[None, :, None] / n
    ev = v[edges[:, 0]][:, None, :] * (1 - k) + v[edges[:, 1]][:, None, :] * k
    edge_base = len(v)
    n_int = (n - 1) * (n - 2) // 2
    int_base = edge_base + len(edges) * (n - 1)
    a, b, c = (v[f[:, m]] for m in range(3))
    grid = {}  # (i, j) -> global vertex index per triangle
    interior = []
    for i in range(n + 1):
        for j in range(n + 1 - i):
            if (i, j) in ((0, 0), (n, 0), (0, n)):
                grid[i, j] = f[:, {(0, 0): 0, (n, 0): 1, (0, n): 2}[i, j]]
                continue
            if j == 0 or i == 0 or i + j == n:
                s = 0 if j == 0 else 1 if i == 0 else 2  # side ab, ac or bc
                t = i if j == 0 else j  # steps from the side's first vertex (a, a, b)
                first = f[:, 0] if s < 2 else f[:, 1]
                forward = first == edges[side_edge[:, s], 0]  # the side runs from the edge's lo
                kk = np.where(forward, t, n - t)
                grid[i, j] = edge_base + side_edge[:, s] * (n - 1) + (kk - 1)
                continue
            grid[i, j] = int_base + np.arange(nt) * n_int + len(interior)
            interior.append(a + (i / n) * (b - a) + (j / n) * (c - a))
    iv = np.stack(interior, axis=1).reshape(-1, 3) if interior else np.zeros((0, 3))
    verts = np.concatenate([v, ev.reshape(-1, 3), iv])
    cells = []  # per cell, (nt, 3) or (nt, 6): its triangles, a triangle's in consecutive rows
    for i in range(n):
        for j in range(n - i):
            up = [grid[i + 1, j], grid[i, j + 1], grid[i, j]]
            if i + j + 2 <= n:
                cells.append(np.stack([grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1], *up], axis=1))
            else:
                cells.append(np.stack(up, axis=1))
    # Each original triangle's n^2 triangles together (the file's order of triangles kept).
    return verts, np.concatenate(cells, axis=1).reshape(-1, 3)


def write_obj(path: Path, v: np.ndarray, f: np.ndarray, note: str) -> None:
    with path.open("w") as out:
        out.write(f"# {note}\n")
        np.savetxt(out, v, fmt="v %.9g %.9g %.9g")
        np.savetxt(out, f + 1, fmt="f %d %d %d")


def make_scene(scene: Path, n: int, out_dir: Path) -> tuple[Path, int]:
    """Writes OUT_DIR/<stem>-n<N>.scene and its subdivided OBJ files; returns the scene's path
    and its mesh triangle count."""
    out_dir.mkdir(parents=True, exist_ok=True)
    text, total, done = scene.read_text(), 0, {}

    def sub(m: re.Match) -> str:
        nonlocal total
        src = (scene.parent / m.group(1)).resolve()
        if src not in done:
            v, f = subdivide(*read_obj(src), n)
            dst = out_dir / f"{src.stem}-n{n}.obj"
            write_obj(dst, v, f, f"{src.name}, each triangle subdivided into {n}^2 (subdivide_mesh.py)")
            done[src] = (dst.name, len(f))
        total += done[src][1]
        return f"file={done[src][0]}"

    text = re.sub(r"(?m)(?<=\s)file=(\S+)", sub, text)
    path = out_dir / f"{scene.stem}-n{n}.scene"
    path.write_text(text)
    return path, total


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene", type=Path)
    ap.add_argument("n", type=int, help="edge cuts: each triangle becomes n^2")
    ap.add_argument("out_dir", type=Path)
    a = ap.parse_args(argv)
    if a.n < 1:
        ap.error("n must be at least 1")
    path, tris = make_scene(a.scene, a.n, a.out_dir)
    print(f"{path}: {tris} mesh triangles")
    return 0


if __name__ == "__main__":
    sys.exit(main())
