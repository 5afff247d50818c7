"""The displacement profile of one direct shear run: mean horizontal grain displacement
against height, with the shear band (paper Fig. 11)."""

import csv
import html

import numpy as np

from .plotting import ALL_COLOR, BAND_COLOR, Figure, plt
from .reading import read_csv_columns


def fig_displacement_profile(run, out_dir):
    """Fig. 11: mean horizontal grain displacement against height, shear band shaded."""
    f = Figure("Horizontal grain displacement against height", "Fig. 11",
               "Mean horizontal displacement of the grains since the start of shear, per height layer, at the "
               "end of the test, against height above the shear plane (the middle of the gap between the box "
               "halves, z = H/2 in the engine's frame). The shaded layer is the shear band.")
    p = run.path("analysis/profile.csv")
    if not p.is_file():
        return f.missing("analysis/profile.csv")
    try:
        prof = read_csv_columns(p)
    except (OSError, ValueError, csv.Error) as e:
        f.notes.append(f"not available: analysis/profile.csv unreadable ({e})")
        return f
    lacking = [c for c in ("z_m", "displacement_x_m") if c not in prof]
    if lacking:
        return f.missing("analysis/profile.csv column " + " and ".join(lacking))
    z0 = run.shear_plane_z
    ref = 0.0 if z0 is None else z0
    ylabel = ("height above the shear plane, z − H/2 (mm)" if z0 is not None
              else "height z (mm, engine frame)")
    if z0 is None:
        f.notes.append("config.box.height missing from run.json: heights shown in the engine's frame")
    z = 1e3 * (prof["z_m"] - ref)
    ux = 1e3 * prof["displacement_x_m"]
    order = np.argsort(z)
    fig, ax = plt.subplots(figsize=(5.2, 5.0))
    band = run.band()
    if band is not None:
        lo, hi, method, source = band
        ax.axhspan(1e3 * (lo - ref), 1e3 * (hi - ref), color=BAND_COLOR, alpha=0.15,
                   label=f"shear band, {1e3 * (hi - lo):.2f} mm thick")
        f.caption += f" Band from {html.escape(source)}" + (f" ({html.escape(method)})." if method else ".")
    else:
        f.missing("analysis/band.json and series.csv band_low_m/band_high_m (no band shaded)")
    ax.plot(ux[order], z[order], "o-", color=ALL_COLOR, ms=3.5, lw=1.2, label="layer mean")
    if z0 is not None:
        ax.axhline(0, color="0.3", lw=0.8, ls=":", label="shear plane")
    ax.set_xlabel("horizontal grain displacement $u_x$ (mm)")
    ax.set_ylabel(ylabel)
    ax.legend(loc="upper left")
    ax.set_title("Horizontal displacement profile")
    return f.save(fig, out_dir, "displacement_profile.png")
