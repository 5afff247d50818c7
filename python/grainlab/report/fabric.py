"""Fabric of one direct shear run: 3D rose diagrams of the contact normals with Kanatani's
density (paper Fig. 15) and the fabric factor Psi against strain (Fig. 16)."""

import json
import math

import numpy as np
import matplotlib.ticker
from matplotlib import cm, colors

from .plotting import Figure, all_band_figure, plt
from .reading import num


def fig_fabric_psi(run, out_dir):
    """Fig. 16: octahedral fabric factor Psi, all grains and band, against strain."""
    f = all_band_figure(
        run, out_dir, "fabric_psi.png", ("fabric_psi", "fabric_psi_band"),
        "octahedral fabric factor $\\Psi$ (–)", "Fabric anisotropy", "Fig. 16",
        "Generalised octahedral fabric factor &Psi; = [(&phi;<sub>1</sub>&minus;&phi;<sub>2</sub>)<sup>2</sup> + "
        "(&phi;<sub>1</sub>&minus;&phi;<sub>3</sub>)<sup>2</sup> + (&phi;<sub>2</sub>&minus;&phi;<sub>3</sub>)"
        "<sup>2</sup>]<sup>1/2</sup>/&radic;2 of the principal values of the contact-normal fabric tensor "
        "(Eq. 29), for all contacts and for contacts in the shear band, against shear strain "
        "(0 = isotropic).")
    return f


# -- Fig. 15: rose diagrams -------------------------------------------------

def rose_surface(density, z_edges, az_edges):
    """The 3D rose as a closed surface r(theta, phi) = bin frequency: one vertex at the centre of
    every bin at radius = its density (plus the two poles, at the mean of the polar bins), joined
    into quads; the azimuth seam is closed. Returns X, Y, Z vertex grids and R per quad (mean of
    its corners), for colouring."""
    zc = 0.5 * (z_edges[:-1] + z_edges[1:])
    ac = 0.5 * (az_edges[:-1] + az_edges[1:])
    z = np.concatenate([[-1.0], zc, [1.0]])
    a = np.concatenate([ac, [ac[0] + 2 * math.pi]])
    r = np.vstack([np.full(len(ac), density[0].mean()), density, np.full(len(ac), density[-1].mean())])
    r = np.hstack([r, r[:, :1]])
    rho = np.sqrt(np.clip(1 - z ** 2, 0, None))[:, None]
    X, Y, Z = r * rho * np.cos(a)[None, :], r * rho * np.sin(a)[None, :], r * z[:, None]
    quad_r = 0.25 * (r[:-1, :-1] + r[1:, :-1] + r[:-1, 1:] + r[1:, 1:])
    return X, Y, Z, quad_r


def load_fabric(run, f):
    """analysis/fabric.json as {'all': {...}, 'band': {...}}, or None with a note in f."""
    p = run.path("analysis/fabric.json")
    if not p.is_file():
        f.missing("analysis/fabric.json")
        return None
    try:
        fab = json.loads(p.read_text())
    except (OSError, ValueError) as e:
        f.notes.append(f"not available: analysis/fabric.json unreadable ({e})")
        return None
    if not isinstance(fab, dict):
        f.notes.append("not available: analysis/fabric.json is not a JSON object")
        return None
    return fab


def as_array(x, shape):
    """x as a float array of the given shape, or None when it is missing or malformed."""
    try:
        a = np.asarray(x, float).reshape(shape)
    except (TypeError, ValueError):
        return None
    return a if np.all(np.isfinite(a)) else None


def fabric_set(entry, which, f):
    """The rose histogram, Kanatani grid, Psi and principal values of one set ('all' or 'band') of
    fabric.json, as the engine wrote them; None with a note when nothing can be drawn."""
    contacts = entry.get("contacts")
    if contacts == 0:
        f.notes.append(f"fabric.json '{which}': no contacts" + (f" ({entry['note']})" if entry.get("note") else ""))
        return None
    grid = entry.get("kanatani_grid") if isinstance(entry.get("kanatani_grid"), dict) else {}
    th, ph = as_array(grid.get("theta_rad"), (-1,)), as_array(grid.get("phi_rad"), (-1,))
    fk = None
    if th is not None and ph is not None:
        fk = as_array(grid.get("density_per_sr"), (len(th), len(ph)))
    if fk is None:
        f.missing(f"analysis/fabric.json '{which}' kanatani_grid")
        return None
    rose = entry.get("rose") if isinstance(entry.get("rose"), dict) else {}
    ze, ae = as_array(rose.get("z_edges"), (-1,)), as_array(rose.get("azimuth_edges_rad"), (-1,))
    hist = None
    if ze is not None and ae is not None and len(ze) > 1 and len(ae) > 1:
        dens = as_array(rose.get("density_per_sr"), (len(ze) - 1, len(ae) - 1))
        hist = None if dens is None else (dens, ze, ae)
    if hist is None:
        f.notes.append(f"fabric.json '{which}': no rose histogram, only Kanatani's density is drawn")
    T, P = np.meshgrid(th, ph, indexing="ij")
    unit = np.stack([np.sin(T) * np.cos(P), np.sin(T) * np.sin(P), np.cos(T)], axis=-1)
    return {"contacts": num(contacts), "unit": unit, "kanatani": fk, "hist": hist, "psi": num(entry.get("psi")),
            "principal_values": as_array(entry.get("principal_values"), (3,))}


def fig_rose(run, out_dir):
    """Fig. 15: 3D rose diagrams of contact normals (all and band) with Kanatani's surface."""
    f = Figure("Contact normals: 3D rose diagrams and Kanatani's density", "Fig. 15",
               "Spherical histograms of the contact normals at the end of the test (each normal counted as n and "
               "&minus;n, bins of equal solid angle): every face sits at a distance from the centre equal to the "
               "bin's frequency per steradian, coloured by it. The black wireframe is Kanatani's fourth-order "
               "density f(n) = (1 + D<sub>ij</sub>n<sub>i</sub>n<sub>j</sub> + "
               "D<sub>ijkl</sub>n<sub>i</sub>n<sub>j</sub>n<sub>k</sub>n<sub>l</sub>)/4&pi; (Eqs. 23-28) of the "
               "same normals; both as the engine computed them (analysis/fabric.json). An isotropic fabric is a sphere of radius 1/4&pi; = 0.080 sr<sup>&minus;1</sup>. "
               "x is the shear direction, z is up.")
    fab = load_fabric(run, f)
    if fab is None:
        return f
    sets = []
    for which, title in (("all", "all contacts"), ("band", "contacts in the shear band")):
        if not isinstance(fab.get(which), dict):
            f.missing(f"analysis/fabric.json '{which}' entry")
            continue
        s = fabric_set(fab[which], which, f)
        if s is not None:
            sets.append((which, title, s))
    if not sets:
        return f
    rmax, drawn = 0.0, []
    for which, title, st in sets:
        fk = st["kanatani"]
        if np.any(fk < 0):
            f.notes.append(f"'{which}': Kanatani's density is negative in places (drawn as 0)")
            fk = np.clip(fk, 0, None)
        hist = st["hist"]
        rmax = max(rmax, float(fk.max()), 0.0 if hist is None else float(hist[0].max()))
        drawn.append((which, title, st, fk, hist))
    rmax *= 1.05
    norm = colors.Normalize(0, rmax)
    cmap = cm.viridis
    fig = plt.figure(figsize=(5.6 * len(drawn) + 0.8, 5.8))
    fig.subplots_adjust(left=0.0, right=0.9, bottom=0.1, top=0.92, wspace=0.05)
    side = ["Left", "Right"] if len(drawn) == 2 else ["Shown"]
    for k, (which, title, s, fk, hist) in enumerate(drawn):
        ax = fig.add_subplot(1, len(drawn), k + 1, projection="3d", computed_zorder=False)
        if hist is not None:
            X, Y, Z, quad_r = rose_surface(*hist)
            ax.plot_surface(X, Y, Z, facecolors=cmap(norm(quad_r)), rstride=1, cstride=1, linewidth=0.25,
                            edgecolor=(1, 1, 1, 0.3), antialiased=True, shade=True, zorder=1)
        grid = s["unit"]
        ax.plot_wireframe(fk * grid[..., 0], fk * grid[..., 1], fk * grid[..., 2], rstride=2, cstride=3,
                          color="black", linewidth=0.4, alpha=0.6, zorder=2)
        ax.set_xlim(-rmax, rmax), ax.set_ylim(-rmax, rmax), ax.set_zlim(-rmax, rmax)
        ax.set_box_aspect((1, 1, 1), zoom=0.95)  # a sphere must look round
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.set_major_locator(matplotlib.ticker.MaxNLocator(4, symmetric=True))
        ax.view_init(elev=18, azim=-72)
        ax.set_xlabel("$f\\,n_x$ (sr$^{-1}$), x = shear", labelpad=2)
        ax.set_ylabel("$f\\,n_y$ (sr$^{-1}$)", labelpad=2)
        ax.set_zlabel("$f\\,n_z$ (sr$^{-1}$), z = up", labelpad=2)
        ax.tick_params(labelsize=7, pad=0)
        n_c = "contacts not given" if s["contacts"] is None else f"{s['contacts']:.0f} contacts"
        psi = "not given" if s["psi"] is None else f"{s['psi']:.3f}"
        ax.set_title(f"{title}\n$\\Psi$ = {psi}, {n_c}", fontsize=10)
        pv = ("" if s["principal_values"] is None else
              ", principal values of &phi;<sub>ij</sub> " + " / ".join(f"{v:.3f}" for v in s["principal_values"]))
        f.caption += f" {side[k]}: {title} ({n_c}, &Psi; = {psi}{pv})."
    if any(hist is not None for *_, hist in drawn):
        cb = fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=fig.axes, shrink=0.6, pad=0.04)
        cb.set_label("frequency of contact normals per solid angle (sr$^{-1}$)")
    return f.save(fig, out_dir, "rose_diagram.png")
