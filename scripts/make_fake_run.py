#!/usr/bin/python3
"""Fabricate a plausible grainlab direct shear or triaxial run folder, for testing the report
(grainlab.report, python/grainlab/report/).

    /usr/bin/python3 scripts/make_fake_run.py OUT_DIR [--preset CLASS] [--seed N]
                                             [--no-analysis] [--no-roundness]
    /usr/bin/python3 scripts/make_fake_run.py OUT_DIR --test triaxial [--sigma3 KPA]
                                             [--phi DEG] [--cohesion KPA] [--phi-cs DEG]
                                             [--cohesion-cs KPA] [--preset CLASS] [--seed N]

Writes exactly the files of the run-folder contract that the report reads
(see the docstring of python/grainlab/report/__init__.py):

    OUT_DIR/series.csv                 one row per 0.1 % of shear strain, 0 .. 10 %
    OUT_DIR/run.json                   config, preparation, peaks, final, timings
    OUT_DIR/analysis/profile.csv       z_m, displacement_x_m, count
    OUT_DIR/analysis/band.json         low_m, high_m, method
    OUT_DIR/analysis/fabric.json       contacts, phi, D2, D4, principal_values, psi, normals,
                                       rose, kanatani_grid (all, band)
    OUT_DIR/analysis/force_chains.csv  x1_m .. z2_m, force_N, strong
    OUT_DIR/analysis/derived.csv       shear_strain, dilation_angle_deg

Nothing here is simulated. The curves are synthetic but shaped like the
paper's (He, Zheng & Schaefer 2021, Figs. 10-17): the stress ratio rises to a
peak and softens, the cap contracts a little then dilates, angular grains are
stronger and dilate more than round ones. Grain centres are placed at random
(non-overlapping) in the box; contacts join close pairs and are kept with a
probability that favours the compression diagonal of the shear, so that the
contact normals and the strong forces are anisotropic as in Figs. 15 and 17.
The fabric tensors in fabric.json are computed from those normals with
Kanatani's coefficients (D_ij = 15/2 dev phi_ij, D_ijkl = 315/8 (...)), and
the rose histogram and Kanatani grid as src/analysis/rose.h defines them:
this script stands in for the engine, which computes every number the report
shows.

A triaxial run (--test triaxial) is series.csv (the columns of
src/lab/triaxial.cpp triaxial_series_columns(), one row per 0.1 % of axial
strain to 15 %) and run.json (the keys src/apps/run_lab.cpp writes, with
config.test = "triaxial", config.consolidation.normal_stress = sigma_3 and
the "triaxial" summary of src/lab/triaxial.cpp, computed from the rows by a
port of summarise_triaxial). Its peak q/p' lies exactly on the Mohr-Coulomb
envelope tau = c' + sigma' tan phi' given by --phi and --cohesion, its
critical state on --phi-cs and --cohesion-cs, so a fit over runs at several
--sigma3 recovers them.

Coordinates are in the engine's world frame: x along the shear (box centred
on x = 0), y across, z up from the box floor; the shear plane is at z = H/2.
Only the Python standard library and numpy are used.
"""

import argparse
import csv
import json
import math
import sys
from pathlib import Path

import numpy as np

# Per grain class: peak and residual F/N, strain at peak, final dilation (m),
# mean rotation at 10 % (deg), initial coordination number, mean roundness.
PRESETS = {
    "angular":     dict(r_peak=0.86, r_res=0.64, eps_peak=0.040, dv_end=0.21e-3, rot_end=6.0,  cn0=5.2, R=0.32, mu=0.28),
    "sub-angular": dict(r_peak=0.74, r_res=0.58, eps_peak=0.032, dv_end=0.18e-3, rot_end=8.0,  cn0=5.5, R=0.52, mu=0.19),
    "rounded":     dict(r_peak=0.62, r_res=0.52, eps_peak=0.026, dv_end=0.12e-3, rot_end=10.0, cn0=5.8, R=0.74, mu=0.19),
    "glass-beads": dict(r_peak=0.50, r_res=0.44, eps_peak=0.020, dv_end=0.07e-3, rot_end=12.0, cn0=6.1, R=0.89, mu=0.12),
}

SAND_OF = {"angular": "crushed-limestone", "sub-angular": "griffin", "rounded": "ottawa", "glass-beads": "glass-beads"}

L, W, H, GAP = 8.5e-3, 8.5e-3, 6.0e-3, 0.3e-3
D_MEAN = 0.774e-3
SIGMA_N = 100e3


def peak_shape(eps, eps_peak):
    """Rises from 0 to 1 at eps_peak, then decays slowly (x e^(1-x) shape, flattened)."""
    x = np.maximum(eps, 0) / eps_peak
    return np.where(x < 1, 1 - np.maximum(1 - x, 0) ** 2.2, np.exp(-0.9 * np.maximum(x - 1, 0) ** 1.3 / (1 + 0.3 * (x - 1))))


def kanatani(normals):
    """phi_ij, phi_ijkl, D_ij, D_ijkl from unit normals (Eqs. 24-28, Kanatani's coefficients)."""
    n = np.asarray(normals, float)
    phi2 = np.einsum("ai,aj->ij", n, n) / len(n)
    phi4 = np.einsum("ai,aj,ak,al->ijkl", n, n, n, n) / len(n)
    d = np.eye(3)
    d2 = 7.5 * (phi2 - d / 3)
    # Fully symmetrised delta_ij phi_kl and delta_ij delta_kl.
    sym_dphi = (np.einsum("ij,kl->ijkl", d, phi2) + np.einsum("ik,jl->ijkl", d, phi2)
                + np.einsum("il,jk->ijkl", d, phi2) + np.einsum("jk,il->ijkl", d, phi2)
                + np.einsum("jl,ik->ijkl", d, phi2) + np.einsum("kl,ij->ijkl", d, phi2)) / 6
    sym_dd = (np.einsum("ij,kl->ijkl", d, d) + np.einsum("ik,jl->ijkl", d, d)
              + np.einsum("il,jk->ijkl", d, d)) / 3
    d4 = 315 / 8 * (phi4 - 6 / 7 * sym_dphi + 3 / 35 * sym_dd)
    return phi2, d2, d4


def psi_of(phi2):
    p = np.linalg.eigvalsh(phi2)[::-1]
    return p, math.sqrt(((p[0] - p[1]) ** 2 + (p[0] - p[2]) ** 2 + (p[1] - p[2]) ** 2) / 2)


def rose_histogram(normals):
    """Equal-solid-angle bins (uniform in n_z and azimuth) of n and -n; density in 1/sr (rose.h)."""
    both = np.vstack([normals, -normals])
    n_z = int(np.clip(math.floor(math.sqrt(len(both) / 50) + 0.5), 5, 18))
    n_az = 2 * n_z
    z_edges = np.linspace(-1, 1, n_z + 1)
    az_edges = np.linspace(-math.pi, math.pi, n_az + 1)
    counts, _, _ = np.histogram2d(np.clip(both[:, 2], -1, 1), np.arctan2(both[:, 1], both[:, 0]),
                                  bins=[z_edges, az_edges])
    omega = 4 * math.pi / (n_z * n_az)
    return {"z_edges": z_edges.tolist(), "azimuth_edges_rad": az_edges.tolist(),
            "density_per_sr": (counts / len(both) / omega).tolist()}


def kanatani_grid(d2, d4, n_theta=31, n_phi=61):
    """f(n) = (1 / 4 pi)(1 + D2 n n + D4 n n n n) on the (theta, phi) grid of rose.h."""
    th = np.linspace(0, math.pi, n_theta)
    ph = np.linspace(-math.pi, math.pi, n_phi)
    T, P = np.meshgrid(th, ph, indexing="ij")
    n = np.stack([np.sin(T) * np.cos(P), np.sin(T) * np.sin(P), np.cos(T)], axis=-1)
    q2 = np.einsum("ij,...i,...j->...", d2, n, n)
    q4 = np.einsum("ijkl,...i,...j,...k,...l->...", d4, n, n, n, n, optimize=True)
    return {"theta_rad": th.tolist(), "phi_rad": ph.tolist(), "density_per_sr": ((1 + q2 + q4) / (4 * math.pi)).tolist()}


def fabric_entry(normals):
    phi2, d2, d4 = kanatani(normals)
    p, psi = psi_of(phi2)
    return {"contacts": len(normals), "phi": phi2.tolist(), "D2": d2.tolist(), "D4": d4.tolist(),
            "principal_values": p.tolist(), "psi": psi,
            "normals": [[round(float(c), 6) for c in v] for v in normals],
            "rose": rose_histogram(np.asarray(normals, float)), "kanatani_grid": kanatani_grid(d2, d4)}


def place_grains(rng, count):
    """Random sequential placement of non-overlapping spheres of ~D_MEAN in the box."""
    lo = np.array([-L / 2 + D_MEAN / 2, -W / 2 + D_MEAN / 2, D_MEAN / 2])
    hi = np.array([L / 2 - D_MEAN / 2, W / 2 - D_MEAN / 2, H - D_MEAN / 2])
    pts = np.empty((0, 3))
    tries = 0
    while len(pts) < count and tries < 60 * count:
        tries += 1
        p = lo + rng.random(3) * (hi - lo)
        if len(pts) and np.min(np.sum((pts - p) ** 2, axis=1)) < (0.75 * D_MEAN) ** 2:
            continue
        pts = np.vstack([pts, p])
    return pts


def make_contacts(rng, centres, axis, band, strength):
    """Close pairs, kept with a probability that favours normals along `axis`."""
    diff = centres[:, None, :] - centres[None, :, :]
    dist = np.linalg.norm(diff, axis=2)
    i, j = np.nonzero(np.triu(dist < 1.4 * D_MEAN, 1))
    n = (centres[j] - centres[i]) / dist[i, j][:, None]
    align = (n @ axis) ** 2
    mid_z = 0.5 * (centres[i, 2] + centres[j, 2])
    in_band = (mid_z >= band[0]) & (mid_z <= band[1])
    # Keep probability 0.25 .. 1, peaked along the axis (align^3 keeps the lobes narrow);
    # the band's contacts are more anisotropic than the rest.
    bias = np.where(in_band, 1.0, 0.45) * strength
    keep = rng.random(len(i)) < 0.25 + 0.75 * bias * align ** 3
    i, j, n, align, in_band = i[keep], j[keep], n[keep], align[keep], in_band[keep]
    # Mean contact force from the normal stress: sigma * area / (contacts per area); the
    # shape is exponential, and the strong forces line up with the compression diagonal.
    f_mean = SIGMA_N * D_MEAN ** 2 * 1.6
    force = f_mean * rng.exponential(1.0, len(i)) * (0.35 + 1.6 * align ** 2)
    return i, j, n, force, in_band


def write_csv(path, header, rows):
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(header)
        for r in rows:
            w.writerow([repr(float(v)) for v in r])


# ---------------------------------------------------------------------------
# A fake drained triaxial run (--test triaxial).

TRIAXIAL_COLUMNS = ["time_s", "axial_strain", "volumetric_strain", "axial_stress_Pa", "cell_pressure_Pa",
                    "deviator_stress_Pa", "mean_stress_Pa", "stress_ratio", "side_stress_error", "void_ratio",
                    "coordination_number", "kinetic_energy_J", "unbalanced_force_ratio", "inertial_number"]
# (src/lab/triaxial.cpp triaxial_series_columns(), in its order.)


def grains_material_box(a):
    """run.json's config.grains, config.material and config.box of a fake run of grain class a.preset."""
    return {
        "grains": {"preset": a.preset, "folder": "", "shapes": 24, "faces": 500, "d_min": 0.707e-3, "d_max": 0.841e-3},
        "material": {"preset": SAND_OF[a.preset], "contact_law": "hertz-material", "density": 2650.0,
                     "friction": PRESETS[a.preset]["mu"], "youngs_modulus": 4e9, "poisson_ratio": 0.3,
                     "restitution": 0.5, "k_n": 1e12, "k_t": 8e11, "gamma_n": 40.0, "gamma_t": 20.0,
                     "wall_friction": 0.0},
        "box": {"length": L, "width": W, "height": H, "gap": GAP},
    }


def eta_of_mohr_coulomb(sigma3, phi_deg, c):
    """q/p' of triaxial compression at failure on tau = c + sigma tan(phi), at cell pressure sigma3 (Pa):
    sigma_1 = sigma_3 K_p + 2 c sqrt(K_p), K_p = (1 + sin phi) / (1 - sin phi)."""
    s = math.sin(math.radians(phi_deg))
    kp = (1 + s) / (1 - s)
    sigma1 = sigma3 * kp + 2 * c * math.sqrt(kp)
    return 3 * (sigma1 - sigma3) / (sigma1 + 2 * sigma3)


def summarise_triaxial(rows):
    """src/lab/triaxial.cpp summarise_triaxial, line for line (rows in TRIAXIAL_COLUMNS order): this script
    stands in for the engine, so run.json holds what the engine would compute from these rows."""
    ea, ev, q, eta = rows[:, 1], rows[:, 2], rows[:, 5], rows[:, 7]
    fric = lambda x: math.degrees(math.asin(min(1.0, max(-1.0, 3 * x / (6 + x)))))
    smoothed = [float(np.mean(eta[np.abs(ea - ea[i]) <= 0.005 + 1e-12])) for i in range(len(ea))]
    peak = int(np.argmax(smoothed))  # the first of equal maxima, as the C++'s strict '>'
    q_peak = int(np.argmax(q))
    s = {"peak_stress_ratio": smoothed[peak], "axial_strain_at_peak": float(ea[peak])}
    s["peak_friction_angle_deg"] = fric(s["peak_stress_ratio"])
    s["critical_stress_ratio"] = float(np.mean(eta[ea >= 0.8 * ea[-1]]))
    s["critical_friction_angle_deg"] = fric(s["critical_stress_ratio"])
    psi_p, j = float("nan"), 0
    for i in range(len(ea)):
        j = max(j, i)
        while j < len(ea) and ea[j] < ea[i] + 0.01:
            j += 1
        if j == len(ea):
            break
        r = (ev[j] - ev[i]) / (ea[j] - ea[i])
        psi = math.degrees(math.asin(min(1.0, max(-1.0, -r / (2 - r)))))
        if not psi <= psi_p:
            psi_p = psi
    s["peak_dilatancy_angle_deg"] = psi_p
    half, e50 = 0.5 * q[q_peak], float("nan")
    for i in range(1, q_peak + 1):
        if q[i] >= half:
            e = ea[i - 1] + (half - q[i - 1]) / (q[i] - q[i - 1]) * (ea[i] - ea[i - 1])
            if e > 0:
                e50 = half / e
            break
    s["e50_Pa"] = e50
    s["final_void_ratio"] = float(rows[-1, 9])
    return s


def smoothstep(x):
    x = np.clip(x, 0, 1)
    return x * x * (3 - 2 * x)


def make_triaxial(a, out):
    """series.csv and run.json of a drained triaxial run at cell pressure a.sigma3 (kPa) whose peak q/p'
    lies exactly on the Mohr-Coulomb envelope (a.phi, a.cohesion) and whose critical state lies on
    (a.phi_cs, a.cohesion_cs): q/p' has a plateau at the peak wider than the engine's 1 % averaging and is
    constant, up to noise of zero mean, over the last fifth of the strain, so the engine's summary
    (summarise_triaxial) gives those values exactly and a Mohr-Coulomb fit over several such runs recovers
    the envelope. Noise is added elsewhere (the rise, the softening, sigma_3's hold, eps_v)."""
    P = PRESETS[a.preset]
    rng = np.random.default_rng(a.seed)
    sigma3 = 1e3 * a.sigma3
    eta_p = eta_of_mohr_coulomb(sigma3, a.phi, 1e3 * a.cohesion)
    eta_cs = eta_of_mohr_coulomb(sigma3, a.phi_cs, 1e3 * a.cohesion_cs)
    if not 0 < eta_cs <= eta_p < 3:
        raise SystemExit(f"make_fake_run.py: error: q/p' at the peak {eta_p:.3f} and at the critical state "
                         f"{eta_cs:.3f} need 0 < eta_cs <= eta_p < 3: choose other --phi/--phi-cs/--cohesion")
    final = 0.15
    eps = np.round(np.arange(0, final + 1e-9, 0.001), 6)
    n = len(eps)
    # The peak comes later and the dilation is weaker at a higher cell pressure.
    lvl = math.log(sigma3 / 100e3)
    e_rise = 0.025 + 0.004 * lvl          # q/p' reaches its peak here ...
    e_soft = e_rise + 0.014               # ... holds it to here (wider than the 1 % averaging) ...
    e_cs = 0.10                           # ... and falls to the critical state by here (the last fifth: >= 12 %)
    eta = np.where(eps < e_rise, eta_p * (1 - (1 - eps / e_rise) ** 3),
                   eta_p - (eta_p - eta_cs) * smoothstep((eps - e_soft) / (e_cs - e_soft)))
    away = (eps < e_rise - 0.015) | ((eps > e_soft + 0.015) & (eps < 0.8 * final - 0.001))
    eta = eta + np.where(away & (eps > 0), 0.006 * eta_p * rng.standard_normal(n), 0.0)
    last = eps >= 0.8 * final - 1e-9  # the engine's last fifth: noise of zero mean there
    wobble = 0.006 * eta_p * rng.standard_normal(int(np.sum(last)))
    eta[last] += wobble - wobble.mean()
    eta[0] = 0.0
    # sigma_3 as the sides' servo holds it, and the stresses that follow from q/p' there.
    s3 = sigma3 * (1 + 0.004 * rng.standard_normal(n))
    s3[0] = sigma3
    p = 3 * s3 / (3 - eta)
    q = eta * p
    s1 = s3 + q
    side_err = np.abs(0.008 * rng.standard_normal(n)) + 0.002
    # eps_v (compression +): a contraction, then dilation at a rate that peaks with q/p' and fades by
    # the critical state; the dilatancy follows Bolton's phi_p - phi_cs = 0.8 psi_p.
    psi = math.radians(max(0.5, (a.phi - a.phi_cs) / 0.8) * (1 - 0.1 * lvl))
    r_max = 2 * math.sin(psi) / (1 - math.sin(psi))
    rate = 0.35 * np.exp(-eps / 0.004) - r_max * smoothstep((eps - 0.004) / (e_rise - 0.004)) * \
        (1 - smoothstep((eps - e_soft) / (e_cs + 0.02 - e_soft)))
    ev = np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(eps))])
    ev = ev + np.where(eps > 0, 2e-5 * rng.standard_normal(n), 0.0)
    e0 = 0.62 - 0.01 * lvl + 0.004 * rng.standard_normal()
    void = (1 + e0) * (1 - ev) - 1
    speed = 9e-4 * H / (D_MEAN * math.sqrt(2650.0 * 100.0 / sigma3))
    time = 0.21 + eps * H / speed
    cn = P["cn0"] - 0.7 * (1 - np.exp(-eps / 0.02)) + 0.02 * rng.standard_normal(n) + 0.3 * lvl
    ke = 1e-9 * (1 + 3 * np.abs(rng.standard_normal(n)))
    unb = 0.01 + 0.01 * np.abs(rng.standard_normal(n))
    inertial = 9e-4 * np.sqrt(sigma3 / p) * (1 + 0.03 * rng.standard_normal(n))
    rows = np.column_stack([time, eps, ev, s1, s3, q, p, eta, side_err, void, cn, ke, unb, inertial])
    write_csv(out / "series.csv", TRIAXIAL_COLUMNS, rows)

    t = summarise_triaxial(rows)
    for key, want in (("peak_stress_ratio", eta_p), ("critical_stress_ratio", eta_cs)):
        assert abs(t[key] - want) < 1e-9, (key, t[key], want)  # the curves above are built for this
    t = {"void_ratio_at_shear": float(void[0]), **t}
    dt = 2.4e-7
    e_target = 0.86 - 0.96 * (0.86 - 0.53)
    run = {
        "grainlab_version": "0.1.0",
        "config": {
            "test": "triaxial",
            "seed": a.seed,
            **grains_material_box(a),
            "specimen": {"relative_density": 0.96, "indices": "own", "own_e_max": 0.0, "own_e_min": 0.0,
                         "e_max": 0.86, "e_min": 0.53, "void_ratio": -1.0, "tolerance": 0.02,
                         "relative_density_tolerance": 0.05, "deposition_friction": 0.05},
            "consolidation": {"normal_stress": sigma3, "tolerance": 0.01, "max_unbalanced": 0.1},
            "shear": {"speed": 0.0, "final_strain": 0.1},
            "oedometer": {"stresses": [200e3, 400e3, 800e3, 400e3, 200e3, 100e3]},
            "triaxial": {"final_strain": final},
            "numerics": {"time_step": 0.0, "time_step_fraction": 0.4, "density_scaling": 0.0,
                         "inertial_number": 9e-4, "threads": 0},
            "output": {"folder": str(out), "strain_interval": 0.001, "checkpoint_interval": 60.0,
                       "snapshot_interval": 0.02},
        },
        "seed": a.seed,
        "grains": 1000,
        "time_step_s": dt,
        "density_scaling": 100.0,
        "phase": "done",
        "mean_equivalent_diameter_m": D_MEAN,
        "preparation": {"void_ratio": float(e0 + 0.003), "compacted_void_ratio": float(e0 + 0.02),
                        "relative_density": float((0.86 - e0 - 0.003) / (0.86 - 0.53)),
                        "bulk_void_ratio": float(e0 + 0.03), "relative_density_lab": float((0.86 - e0) / 0.33),
                        "deposition_friction": 0.05, "target_void_ratio": e_target},
        "axial_speed_m_per_s": speed,
        "triaxial": t,
        "timings": {"wall_s": 600.0 * (1.5 + rng.random()), "steps": int(time[-1] / dt),
                    "simulated_s": float(time[-1])},
        "final": {"cap_normal_stress_Pa": float(s3[-1]), "contacts": 2900},
        "specimen_preparation": {},
    }
    if not a.no_roundness:
        run["mean_roundness"] = P["R"]
    (out / "run.json").write_text(json.dumps(run, indent=2) + "\n")
    return 0


OEDOMETER_COLUMNS = ["time_s", "stage", "target_stress_Pa", "vertical_stress_Pa", "floor_stress_Pa",
                     "lateral_stress_Pa", "K0", "vertical_strain", "cap_height_m", "void_ratio",
                     "constrained_modulus_Pa", "coordination_number", "kinetic_energy_J", "unbalanced_force_ratio"]


def make_oedometer(a, out):
    """series.csv and run.json of an oedometer run (lab/oedometer.h) on e = e0 - Cc log10(s / 100 kPa) while
    loading 100 -> 200 -> 400 -> 800 kPa and e = e(800) + Cs log10(800 kPa / s) unloading to 400, 200, 100 kPa
    (Cc 0.035, Cs 0.02), K0 0.55 loading and 0.55 (800 kPa / s)^0.4 unloading. With --loading stages one row per
    stage; with constant-rate 50 rows per decade of stress on the way to each stage's stress, the column stage
    being the stage approached."""
    rng = np.random.default_rng(a.seed)
    cc, cs, e0 = 0.035, 0.02, 0.70
    schedule = [200e3, 400e3, 800e3, 400e3, 200e3, 100e3]
    e800 = e0 - cc * math.log10(8)
    rows, h0 = [], H

    def add(stage, target, s, loading):
        e = e0 - cc * math.log10(s / 100e3) if loading else e800 + cs * math.log10(800e3 / s)
        k0 = 0.55 if loading else 0.55 * (800e3 / s) ** 0.4
        eps = (e0 - e) / (1 + e0)
        m = float("nan") if not rows else (s - rows[-1][3]) / (eps - rows[-1][7])
        rows.append([0.2 + 0.01 * len(rows), stage, target, s, s * (1 + 1e-4 * rng.standard_normal()), k0 * s, k0,
                     eps, h0 * (1 - eps), e, m, 5.0 + 0.1 * rng.standard_normal(), 1e-9, 1e-3])

    add(0, 100e3, 100e3, True)
    previous = 100e3
    for k, target in enumerate(schedule, start=1):
        loading = target > previous
        if a.loading == "constant-rate":
            steps = max(1, int(round(50 * abs(math.log10(target / previous)))))
            for j in range(1, steps):
                add(k, target, previous * (target / previous) ** (j / steps), loading)
        add(k, target, target, loading)
        previous = target
    write_csv(out / "series.csv", OEDOMETER_COLUMNS, np.array(rows))
    run = {
        "grainlab_version": "0.1.0",
        "config": {"test": "oedometer", "seed": a.seed,
                   **grains_material_box(a),
                   "consolidation": {"normal_stress": 100e3, "tolerance": 0.01, "max_unbalanced": 0.01},
                   "oedometer": {"stresses": schedule, "loading": a.loading},
                   "numerics": {"inertial_number": 9e-4, "threads": 0},
                   "output": {"folder": str(out), "strain_interval": 0.001}},
        "seed": a.seed, "grains": 1000, "phase": "done", "mean_equivalent_diameter_m": D_MEAN,
        "preparation": {"void_ratio": e0, "bulk_void_ratio": e0 - 0.004, "relative_density": 0.5},
        "oedometer": {"compression_index": cc, "swelling_index": cs, "max_stress_Pa": 800e3,
                      "K0_at_max_stress": 0.55, "constrained_modulus_at_max_stress_Pa": rows[3][10] if
                      a.loading == "stages" else None, "modulus_stress_exponent": 0.5,
                      "final_void_ratio": rows[-1][9]},
        "timings": {"wall_s": 120.0, "steps": 100000, "simulated_s": rows[-1][0]},
    }
    (out / "run.json").write_text(json.dumps(run, indent=2) + "\n")
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", help="run folder to create (created if missing; files overwritten)")
    ap.add_argument("--preset", default="sub-angular", choices=sorted(PRESETS), help="grain class")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--no-analysis", action="store_true",
                    help="write only series.csv (without the analysis columns) and run.json")
    ap.add_argument("--no-roundness", action="store_true", help="leave mean_roundness out of run.json")
    ap.add_argument("--loading", default="stages", choices=["stages", "constant-rate"],
                    help="oedometer (--test oedometer): stages held to rest, or a constant rate of strain")
    ap.add_argument("--test", default="direct-shear", choices=["direct-shear", "triaxial", "oedometer"],
                    help="the lab test of the run (triaxial: series.csv and run.json only)")
    tx = ap.add_argument_group("triaxial (--test triaxial): the envelopes the run's peak and critical state lie on")
    tx.add_argument("--sigma3", type=float, default=100.0, metavar="KPA", help="cell pressure sigma_3, kPa")
    tx.add_argument("--phi", type=float, default=36.0, metavar="DEG", help="peak friction angle phi', deg")
    tx.add_argument("--cohesion", type=float, default=0.0, metavar="KPA", help="peak cohesion intercept c', kPa")
    tx.add_argument("--phi-cs", type=float, default=31.0, metavar="DEG", help="critical-state phi', deg")
    tx.add_argument("--cohesion-cs", type=float, default=0.0, metavar="KPA", help="critical-state c', kPa")
    a = ap.parse_args(argv)
    if a.test in ("triaxial", "oedometer"):
        out = Path(a.out)
        out.mkdir(parents=True, exist_ok=True)
        return (make_triaxial if a.test == "triaxial" else make_oedometer)(a, out)

    P = PRESETS[a.preset]
    rng = np.random.default_rng(a.seed)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)

    # ---- series.csv -------------------------------------------------------
    eps = np.round(np.arange(0, 0.1000001, 0.001), 6)
    noise = lambda s: s * rng.standard_normal(len(eps))
    time = 0.05 + eps * L / 0.01
    dh = eps * L
    ratio = P["r_res"] * (1 - np.exp(-eps / 0.006)) + (P["r_peak"] - P["r_res"] * (1 - np.exp(-P["eps_peak"] / 0.006))) * peak_shape(eps, P["eps_peak"])
    ratio = np.maximum(ratio + noise(0.008), 0)
    ratio[0] = 0.0
    # Cap: a small contraction, then dilation that flattens towards the end.
    dv = (P["dv_end"] * (1 / (1 + np.exp(-(eps - 0.035) / 0.02)) - 1 / (1 + np.exp(0.035 / 0.02)))
          - 0.02e-3 * (1 - np.exp(-eps / 0.004)))
    dv = dv + noise(0.0005e-3)
    dv[0] = 0.0
    normal_force = SIGMA_N * L * W * (1 + noise(0.004))
    shear_force = ratio * normal_force
    stress = normal_force / (L * W)
    phi_deg = np.degrees(np.arctan(ratio))
    e_target = 0.86 - 0.96 * (0.86 - 0.53)
    e0 = e_target + 0.008 * rng.standard_normal()
    void = e0 + dv / (H - 0.0) * (1 + e0)
    cn = P["cn0"] - 0.9 * (1 - np.exp(-eps / 0.02)) + noise(0.02)
    ke = 1e-9 * (1 + 3 * np.abs(noise(1)))
    unb = 0.01 + 0.01 * np.abs(noise(1))
    inertial = 6e-4 * (1 + noise(0.03))

    cols = ["time_s", "shear_strain", "horizontal_displacement_m", "vertical_displacement_m",
            "shear_force_N", "normal_force_N", "normal_stress_Pa", "stress_ratio",
            "friction_angle_deg", "void_ratio", "coordination_number", "kinetic_energy_J",
            "unbalanced_force_ratio", "inertial_number"]
    data = [time, eps, dh, dv, shear_force, normal_force, stress, ratio, phi_deg, void, cn, ke, unb, inertial]

    # Shear band: widens from the gap to a few grain diameters, centred on the shear plane.
    z_plane = H / 2
    half_width = 0.5 * GAP + 2.2 * D_MEAN * (1 - np.exp(-eps / 0.015))
    band_low, band_high = z_plane - half_width, z_plane + half_width
    final_band = (float(band_low[-1]), float(band_high[-1]))

    if not a.no_analysis:
        growth = 1 - np.exp(-eps / 0.03)
        rot_all = P["rot_end"] * growth / (1 - math.exp(-0.1 / 0.03)) + np.abs(noise(0.05))
        rot_band = 2.0 * rot_all + np.abs(noise(0.1))
        cn_band = cn + 0.35 + noise(0.03)
        cols += ["rotation_mean_deg", "rotation_band_deg", "coordination_number_band"]
        data += [rot_all, rot_band, cn_band]

    # ---- grains, contacts, fabric ------------------------------------------
    centres = place_grains(rng, 1000)
    tilt = math.radians(40 + 15 * (1 - P["R"]))  # compression diagonal, tilted from vertical towards -x
    axis = np.array([-math.sin(tilt), 0.0, math.cos(tilt)])
    strength = min(1.0, 1.25 - 0.6 * P["R"])  # angular grains: more anisotropic fabric
    i, j, normals, force, in_band = make_contacts(rng, centres, axis, final_band, strength)
    fab_all = fabric_entry(normals)
    fab_band = fabric_entry(normals[in_band])

    if not a.no_analysis:
        # Psi rises from near isotropic to a peak, then eases to the final fabric's value.
        x = eps / (1.2 * P["eps_peak"])
        shape = 1 - np.exp(-eps / 0.012) + 0.3 * x * np.exp(1 - x)
        psi_all = 0.02 + (fab_all["psi"] - 0.02) * shape / shape[-1]
        psi_band = 0.03 + (fab_band["psi"] - 0.03) * shape / shape[-1]
        psi_band[0] = float("nan")  # no band before shear starts: the C++ may write nan
        cols += ["fabric_psi", "fabric_psi_band", "band_low_m", "band_high_m"]
        data += [psi_all, psi_band, band_low, band_high]

    write_csv(out / "series.csv", cols, np.column_stack(data))

    # ---- run.json -----------------------------------------------------------
    k_peak = int(np.argmax(ratio))
    dil = np.zeros(len(eps))
    for k in range(len(eps)):
        lo, hi = max(0, k - 2), min(len(eps) - 1, k + 2)
        dil[k] = math.degrees(math.atan((dv[hi] - dv[lo]) / (dh[hi] - dh[lo])))
    k_dil = int(np.argmax(dil))
    tail = eps >= 0.9 * eps[-1]
    dt = 2.4e-7
    run = {
        "grainlab_version": "0.1.0",
        "config": {
            "seed": a.seed,
            **grains_material_box(a),
            "specimen": {"relative_density": 0.96, "e_max": 0.86, "e_min": 0.53, "void_ratio": -1.0,
                         "tolerance": 0.02, "deposition_friction": 0.05},
            "consolidation": {"normal_stress": SIGMA_N, "tolerance": 0.01, "max_unbalanced": 0.1},
            "shear": {"speed": 0.0, "final_strain": 0.1},
            "numerics": {"time_step": 0.0, "time_step_fraction": 0.2, "density_scaling": 0.0,
                         "inertial_number": 1e-3, "threads": 0},
            "output": {"folder": str(out), "strain_interval": 0.001, "checkpoint_interval": 60.0},
        },
        "seed": a.seed,
        "grains": int(len(centres)),
        "time_step_s": dt,
        "density_scaling": 100.0,
        "shear_speed_m_per_s": 0.01,
        "mean_equivalent_diameter_m": D_MEAN,
        "mean_roundness": P["R"],
        "preparation": {"void_ratio": float(e0), "relative_density": float((0.86 - e0) / (0.86 - 0.53)),
                        "bulk_void_ratio": float(e0 - 0.004), "target_void_ratio": e_target},
        # The engine's verdicts (src/analysis/peak.h): no peak in the last 5 % of the strain.
        "peaks": {"friction_angle_deg": float(phi_deg[k_peak]), "strain_at_peak_friction": float(eps[k_peak]),
                  "stress_ratio": float(ratio[k_peak]), "dilation_angle_deg": float(dil[k_dil]),
                  "strain_at_peak_dilation": float(eps[k_dil]),
                  "friction_is_peak": bool(eps[k_peak] < 0.95 * eps.max()),
                  "dilation_is_peak": bool(eps[k_dil] < 0.95 * eps.max())},
        "final": {"friction_angle_deg": float(np.mean(phi_deg[tail])),
                  "dilation_angle_deg": float(np.mean(dil[tail])), "void_ratio": float(void[-1])},
        "timings": {"wall_s": 3600.0 * (1.5 + rng.random()), "steps": int(time[-1] / dt),
                    "simulated_s": float(time[-1])},
    }
    if a.no_roundness:
        del run["mean_roundness"]
    if not a.no_analysis:
        run["peaks"]["fabric_psi"] = float(np.nanmax(data[cols.index("fabric_psi")]))
        run["peaks"]["fabric_psi_band"] = float(np.nanmax(data[cols.index("fabric_psi_band")]))
        run["final"].update({"contacts": int(len(force)), "contact_force_mean_N": float(force.mean()),
                             "contact_force_max_N": float(force.max()),
                             "contact_force_std_N": float(force.std()),
                             "strong_contact_fraction": float(np.mean(force > force.mean()))})
    (out / "run.json").write_text(json.dumps(run, indent=2) + "\n")

    if a.no_analysis:
        return 0

    # ---- analysis/ ----------------------------------------------------------
    an = out / "analysis"
    an.mkdir(exist_ok=True)
    edges = np.arange(0.0, H + 1e-12, D_MEAN / 2)
    zc = 0.5 * (edges[:-1] + edges[1:])
    w = 0.55 * (final_band[1] - final_band[0]) / 4
    disp = dh[-1] / (1 + np.exp(-(zc - z_plane) / w)) + 0.01e-3 * rng.standard_normal(len(zc))
    counts = np.array([np.sum((centres[:, 2] >= a_) & (centres[:, 2] < b_)) for a_, b_ in zip(edges[:-1], edges[1:])])
    write_csv(an / "profile.csv", ["z_m", "displacement_x_m", "count"],
              [(z, d, c) for z, d, c in zip(zc, disp, counts) if c > 0])
    (an / "band.json").write_text(json.dumps(
        {"low_m": final_band[0], "high_m": final_band[1],
         "method": "synthetic: fake run (layers whose displacement is between 10 % and 90 % of the box's)"},
        indent=2) + "\n")
    (an / "fabric.json").write_text(json.dumps({"all": fab_all, "band": fab_band}) + "\n")
    write_csv(an / "force_chains.csv", ["x1_m", "y1_m", "z1_m", "x2_m", "y2_m", "z2_m", "force_N", "strong"],
              np.column_stack([centres[i], centres[j], force, (force > force.mean()).astype(float)]))
    write_csv(an / "derived.csv", ["shear_strain", "dilation_angle_deg"], np.column_stack([eps, dil]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
