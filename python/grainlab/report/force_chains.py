"""Force chains of one direct shear run: the grain-grain contacts at the end, strong chains
highlighted (paper Fig. 17)."""

import csv
import math

import numpy as np
from matplotlib import cm, colors
from matplotlib.collections import LineCollection
from mpl_toolkits.mplot3d.art3d import Line3DCollection

from .plotting import BAND_COLOR, Figure, plt
from .reading import get, num, read_csv_columns


# -- Fig. 17: force chains ----------------------------------------------------

def fig_force_chains(run, out_dir):
    """Fig. 17: contact-force segments, side view (x-z) and 3D, strong chains emphasised."""
    f = Figure("Force chains", "Fig. 17",
               "Grain-grain contact forces at the end of the test, each drawn as a segment between the two "
               "grain centres. Contacts carrying more than the mean force (strong chains, as the engine marks "
               "them in analysis/force_chains.csv) are coloured and "
               "thickened by force; the weaker ones are thin and grey. Left: side view, projected on the x-z "
               "plane (x = shear direction); right: 3D view.")
    p = run.path("analysis/force_chains.csv")
    if not p.is_file():
        return f.missing("analysis/force_chains.csv")
    try:
        fc = read_csv_columns(p)
    except (OSError, ValueError, csv.Error) as e:
        f.notes.append(f"not available: analysis/force_chains.csv unreadable ({e})")
        return f
    need = ["x1_m", "y1_m", "z1_m", "x2_m", "y2_m", "z2_m", "force_N"]
    lacking = [c for c in need if c not in fc]
    if lacking:
        return f.missing("analysis/force_chains.csv columns " + ", ".join(lacking))
    if "strong" not in fc:
        f.missing("analysis/force_chains.csv column strong", "every contact drawn as weak")
    a = np.column_stack([fc[c] for c in need] + [fc.get("strong", np.zeros(len(fc["force_N"])))])
    a = a[np.all(np.isfinite(a), axis=1)]
    if len(a) == 0:
        f.notes.append("not available: analysis/force_chains.csv has no contacts")
        return f
    p1, p2, force = 1e3 * a[:, 0:3], 1e3 * a[:, 3:6], np.abs(a[:, 6])
    order = np.argsort(force)
    p1, p2, force, strong = p1[order], p2[order], force[order], a[order, 7] > 0.5
    fmax = float(force.max())
    mean = num(get(run.info, "final", "contact_force_mean_N"))
    if mean is None:
        f.missing("run.json final.contact_force_mean_N", "colour scale from the weakest strong contact")
        mean = float(force[strong].min()) if np.any(strong) else fmax
    norm = colors.Normalize(mean, fmax if fmax > mean else mean * 1.0001)
    cmap = colors.LinearSegmentedColormap.from_list("chains", cm.inferno_r(np.linspace(0.2, 0.95, 256)))
    t = np.clip((force - mean) / max(fmax - mean, 1e-300), 0, 1)  # 0 at the mean force, 1 at the largest
    crowd = min(1.0, math.sqrt(2000.0 / max(1, int(strong.sum()))))  # thinner lines when there are many
    width = crowd * (0.5 + 3.5 * np.sqrt(t))
    rgba = cmap(norm(force))
    rgba[:, 3] = 0.45 + 0.55 * np.sqrt(t)  # the weakest strong chains fade a little
    weak_max = 30000
    weak = np.nonzero(~strong)[0]
    if len(weak) > weak_max:
        weak = np.random.default_rng(0).choice(weak, weak_max, replace=False)
        f.notes.append(f"{weak_max} of the {int(np.sum(~strong))} weak contacts drawn")

    fig = plt.figure(figsize=(13.5, 5.4))
    gs = fig.add_gridspec(1, 2, width_ratios=[1.0, 1.2], wspace=0.08)
    ax = fig.add_subplot(gs[0, 0])
    ref = run.shear_plane_z
    zr = 0.0 if ref is None else 1e3 * ref
    seg = lambda idx, i, j: np.stack([np.column_stack([p1[idx, i], p1[idx, j] - (zr if j == 2 else 0)]),
                                      np.column_stack([p2[idx, i], p2[idx, j] - (zr if j == 2 else 0)])], axis=1)
    ax.add_collection(LineCollection(seg(weak, 0, 2), colors="0.72", linewidths=0.4, alpha=0.6))
    s_idx = np.nonzero(strong)[0]
    ax.add_collection(LineCollection(seg(s_idx, 0, 2), colors=rgba[s_idx], linewidths=width[s_idx]))
    band = run.band()
    if band is not None:
        for zb in band[:2]:
            ax.axhline(1e3 * zb - zr, color=BAND_COLOR, lw=0.9, ls="--")
        ax.plot([], [], color=BAND_COLOR, lw=0.9, ls="--", label="shear band limits")
    if ref is not None:
        ax.axhline(0, color="0.3", lw=0.8, ls=":", label="shear plane")
    ax.plot([], [], color="0.72", lw=0.6, label=f"weak: force ≤ mean ({mean:.3g} N)")
    ax.plot([], [], color=cmap(0.7), lw=2.5, label="strong: force > mean")
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel("x, shear direction (mm)")
    ax.set_ylabel("height above the shear plane, z − H/2 (mm)" if ref is not None else "z (mm)")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, fontsize=8, frameon=False)
    ax.set_title("side view (x-z projection)")
    ax.grid(False)

    ax3 = fig.add_subplot(gs[0, 1], projection="3d", computed_zorder=False)
    shift = np.array([0.0, 0.0, zr])  # same heights as the side view
    q1, q2 = p1 - shift, p2 - shift
    seg3 = lambda idx: np.stack([q1[idx], q2[idx]], axis=1)
    ax3.add_collection3d(Line3DCollection(seg3(weak), colors="0.65", linewidths=0.3, alpha=0.4))
    ax3.add_collection3d(Line3DCollection(seg3(s_idx), colors=rgba[s_idx],
                                          linewidths=0.7 * width[s_idx]))
    lo, hi = np.minimum(q1.min(0), q2.min(0)), np.maximum(q1.max(0), q2.max(0))
    ax3.set_xlim(lo[0], hi[0]), ax3.set_ylim(lo[1], hi[1]), ax3.set_zlim(lo[2], hi[2])
    ax3.set_box_aspect(tuple(np.maximum(hi - lo, 1e-9)), zoom=1.1)
    ax3.view_init(elev=16, azim=-62)
    ax3.set_xlabel("x, shear (mm)"), ax3.set_ylabel("y (mm)"), ax3.set_zlabel("z − H/2 (mm)" if ref is not None else "z (mm)")
    ax3.tick_params(labelsize=7, pad=0)
    ax3.set_title("3D view")
    cb = fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax3, shrink=0.7, pad=0.16)
    cb.set_label("contact force of strong chains (N)")
    f.caption += (f" {len(force)} contacts; mean force {mean:.3g} N, maximum {fmax:.3g} N, "
                  f"{int(strong.sum())} strong.")
    return f.save(fig, out_dir, "force_chains.png")
