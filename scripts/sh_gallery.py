#!/usr/bin/python3
"""A gallery of grains: one row per set, real grains beside generated ones,
each shaded and seen from the same oblique direction in its principal frame
(long axis across, short axis towards the viewer's up), sizes normalised.

    scripts/sh_gallery.py OUT.png "ROW TITLE" REAL_DIR GENERATED_DIR [...]

REAL_DIR and GENERATED_DIR hold binary STL files (`grainlab grains import`,
`grainlab grains generate`); the first four of each (by name) are drawn."""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection


def read_stl(path):
    data = pathlib.Path(path).read_bytes()
    n = int.from_bytes(data[80:84], "little")
    rec = np.frombuffer(data, dtype=np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]),
                        count=n, offset=84)
    return rec["v"].astype(float)


def principal(tris):
    pts = tris.reshape(-1, 3)
    c = pts.mean(axis=0)
    w, v = np.linalg.eigh(np.cov((pts - c).T))
    axes = v[:, ::-1]  # long, intermediate, short
    if np.linalg.det(axes) < 0:
        axes[:, 2] = -axes[:, 2]  # a rotation, not a mirror: faces keep facing out
    t = (tris - c) @ axes
    return t / np.abs(t).max()


def draw(ax, tris, title):
    light = np.array([0.3, -0.6, 0.74])
    normals = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True) + 1e-30
    shade = 0.25 + 0.75 * np.clip(normals @ light, 0, 1)
    colors = np.outer(shade, [0.85, 0.75, 0.55])
    ax.add_collection3d(Poly3DCollection(tris, facecolors=colors, edgecolors="none"))
    for set_lim in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        set_lim(-0.75, 0.75)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=25, azim=-60)
    ax.set_axis_off()
    ax.set_title(title, fontsize=8)


def main():
    args = sys.argv[1:]
    if len(args) < 4 or (len(args) - 1) % 3:
        sys.exit(__doc__)
    out, rows = args[0], [args[i:i + 3] for i in range(1, len(args), 3)]
    fig = plt.figure(figsize=(16, 2.1 * len(rows)))
    for r, (title, real, generated) in enumerate(rows):
        files = [("real", f) for f in sorted(pathlib.Path(real).glob("*.stl"))[:4]]
        files += [("generated", f) for f in sorted(pathlib.Path(generated).glob("*.stl"))[:4]]
        for k, (kind, f) in enumerate(files):
            ax = fig.add_subplot(len(rows), 8, r * 8 + k + 1, projection="3d")
            draw(ax, principal(read_stl(f)), f"{title}: {kind}")
    fig.tight_layout()
    fig.savefig(out, dpi=90)


main()
