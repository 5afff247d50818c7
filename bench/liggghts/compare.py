#!/usr/bin/python3
"""The 2000-bead direct shear run in grainlab and in LIGGGHTS 3.8, one thread
each, alternately; prints the shear phase's steps/s and particle-steps/s, the
whole test's wall time (medians over the repeats) and the results (peak
friction and dilation angles) side by side. bench/sphere_vs_liggghts.sh runs it.

grainlab runs bench/liggghts/beads_direct_shear.toml (a fresh output folder
each time, so each run measures what a first run measures); LIGGGHTS runs
beads_direct_shear.in with grainlab's bead count, shear speed and step counts
(deposition DEP_STEPS, then consolidation up to grainlab's first shear step,
then grainlab's shear steps). Times are read off the programs' output lines
as they arrive: the shear phase is from grainlab's "phase shear" line to its
"phase done" line, and from the deck's SHEAR START to SHEAR END. Beside the
wall-clock figures, the same spans in CPU seconds of the process (user +
system, read from /proc as the lines arrive; the whole test's from the
child's rusage): on a shared machine, where a process gets a varying share
of a core, those compare the codes; on a quiet one the two agree.

Peaks as grainlab takes them (analysis/peak.h, analysis/dilation.h): a sample
every 0.001 strain, phi = atan(F/N) with F the x force on the upper half and
N the cap's force; psi = atan(d d_v / d d_h) over +-2 samples; a largest value
in the last 5 % of the test is no peak (printed with a '*').
"""
import argparse
import json
import math
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DEP_STEPS = 20000  # LIGGGHTS' deposition at 100 g: at rest (KE ~ 1e-6 J) by then
GAP_STEPS = 200    # the deck opens the gap over these steps


TICK = os.sysconf("SC_CLK_TCK")


def cpu_seconds(pid):
    """User + system CPU seconds of a running process (all its threads)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / TICK
    except (OSError, IndexError, ValueError):
        return float("nan")


def timed_lines(cmd, cwd, env=None):
    """Runs cmd; returns (lines as (wall time, CPU seconds, text), wall seconds, CPU seconds, rc)."""
    start = time.monotonic()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         errors="replace", env=env)
    lines = []
    for line in p.stdout:
        lines.append((time.monotonic(), cpu_seconds(p.pid), line.rstrip("\n")))
    rc = p.wait()
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return lines, time.monotonic() - start, cpu, rc


def fail(what, lines):
    tail = "\n".join(l for _, _, l in lines[-30:])
    sys.exit(f"{what} failed; the last lines of its output:\n{tail}")


def at(lines, prefix):
    for t, c, l in lines:
        if l.strip().startswith(prefix):
            return (t, c), l
    return None, None


def peak(values, strains, final):
    """The largest value, and whether it is a peak (not in the last 5 % of the test)."""
    k = max((i for i in range(len(values)) if not math.isnan(values[i])), key=lambda i: values[i])
    return values[k], strains[k] < 0.95 * final


def dilation(dh, dv, h=2):
    out = []
    for k in range(len(dh)):
        lo, hi = max(0, k - h), min(len(dh) - 1, k + h)
        d = dh[hi] - dh[lo]
        out.append(math.degrees(math.atan((dv[hi] - dv[lo]) / d)) if d > 0 else float("nan"))
    return out


def run_grainlab(exe, config, strain, work, k):
    folder = os.path.join(work, f"grainlab_{k}")
    text = open(config).read()
    text = text.replace("final_strain = 0.10", f"final_strain = {strain}")
    text = text.replace('folder = "runs/beads_direct_shear"', f'folder = "{folder}"')
    cfg = os.path.join(work, f"grainlab_{k}.toml")
    open(cfg, "w").write(text)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    lines, wall, cpu, rc = timed_lines([exe, "run", cfg, "--threads", "1"], work, env)
    if rc != 0:
        fail("grainlab run", lines)
    t0, l0 = at(lines, "phase shear from step")
    t1, l1 = at(lines, "phase done from step")
    if t0 is None or t1 is None:
        fail("grainlab run (no shear phase lines)", lines)
    s0, s1 = int(l0.split()[-1]), int(l1.split()[-1])
    rec = json.load(open(os.path.join(folder, "run.json")))
    return {"wall": wall, "cpu": cpu, "shear_s": t1[0] - t0[0], "shear_cpu": t1[1] - t0[1],
            "shear_steps": s1 - s0, "first_shear_step": s0, "after_shear_s": lines[-1][0] - t1[0], "beads": rec["grains"], "speed": rec["shear_speed_m_per_s"],
            "dt": rec["time_step_s"], "e": rec["preparation"]["void_ratio"],
            "deposition_friction": rec["preparation"]["deposition_friction"],
            "phi": rec["peaks"]["friction_angle_deg"], "phi_is_peak": rec["peaks"]["friction_is_peak"],
            "psi": rec["peaks"]["dilation_angle_deg"], "psi_is_peak": rec["peaks"]["dilation_is_peak"]}


def run_liggghts(exe, g, strain, length, work, k):
    folder = os.path.join(work, f"liggghts_{k}")
    os.makedirs(folder, exist_ok=True)
    top = 0.025
    subprocess.run([sys.executable, os.path.join(HERE, "make_box_meshes.py"), os.path.join(folder, "mesh"),
                    str(length), str(length), "0.006", "0.0003", str(top)], check=True)
    every = max(1, round(0.001 * length / (g["speed"] * g["dt"])))
    con = g["first_shear_step"] - DEP_STEPS - GAP_STEPS
    var = {"mesh": "mesh", "n": g["beads"], "dep": DEP_STEPS, "con": con, "shear": g["shear_steps"],
           "vshear": repr(g["speed"]), "top": top, "fdep": repr(g["deposition_friction"]), "every": every}
    # Line-buffered, so that each line is read when it is written (LIGGGHTS
    # buffers a pipe in blocks: SHEAR START would arrive late).
    cmd = (["stdbuf", "-oL"] if shutil.which("stdbuf") else []) + [
        exe, "-in", os.path.join(HERE, "beads_direct_shear.in"), "-log", "log.lammps", "-echo", "none"]
    for key, v in var.items():
        cmd += ["-var", key, str(v)]
    env = dict(os.environ, OMP_NUM_THREADS="1")
    lines, wall, cpu, rc = timed_lines(cmd, folder, env)
    if rc != 0 or any("ERROR" in l for _, _, l in lines):
        fail("liggghts", lines)
    t0, _ = at(lines, "SHEAR START")
    t1, _ = at(lines, "SHEAR END")
    # The shear's thermo rows: step dh capz N F e cpu (the first is the setup's, with doubled forces).
    rows = []
    inside = False
    for _, _, l in lines:
        if l.startswith("SHEAR START"):
            inside = True
        elif l.startswith("SHEAR END"):
            break
        elif inside:
            f = l.split()
            if len(f) == 7 and f[0].isdigit():
                rows.append([float(x) for x in f])
    rows = rows[1:]
    # LIGGGHTS' own wall time of the shear run, to check the lines' times by.
    loop = [l for _, _, l in lines if l.startswith("Loop time of")]
    loop_s = float(loop[-1].split()[3]) if loop else float("nan")
    dh = [r[1] for r in rows]
    dv = [r[2] - rows[0][2] for r in rows]
    strains = [d / length for d in dh]
    phi = [math.degrees(math.atan(r[4] / r[3])) if r[3] > 0 else float("nan") for r in rows]
    psi = dilation(dh, dv)
    phi_p, phi_ok = peak(phi, strains, strain)
    psi_p, psi_ok = peak(psi, strains, strain)
    return {"wall": wall, "cpu": cpu, "shear_s": t1[0] - t0[0], "shear_cpu": t1[1] - t0[1],
            "shear_steps": g["shear_steps"], "beads": g["beads"], "loop_s": loop_s,
            "e": rows[0][5], "phi": phi_p, "phi_is_peak": phi_ok, "psi": psi_p, "psi_is_peak": psi_ok}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="one repeat to 2 %% strain (about 2 minutes quiet)")
    ap.add_argument("--repeats", type=int, default=3, help="runs of each code, alternated (default 3)")
    ap.add_argument("--strain", type=float, default=0.10, help="final shear strain (default 0.10)")
    ap.add_argument("--grainlab", default=os.path.join(ROOT, "build", "grainlab"), help="grainlab binary")
    ap.add_argument("--liggghts", default=shutil.which("liggghts") or "liggghts", help="LIGGGHTS binary")
    ap.add_argument("--keep", help="folder to run in and keep (default: a temporary one, removed)")
    a = ap.parse_args()
    if a.quick:
        a.repeats, a.strain = 1, 0.02
    if os.sep in a.grainlab:  # a path, not a name on PATH: the runs start in another folder
        a.grainlab = os.path.abspath(a.grainlab)
    for exe, what in ((a.grainlab, "build it: cmake --build build --target grainlab"),
                      (a.liggghts, "install the Debian package liggghts")):
        if not shutil.which(exe) and not os.access(exe, os.X_OK):
            sys.exit(f"{exe} not found: {what}")
    work = a.keep or tempfile.mkdtemp(prefix="sphere_vs_liggghts_")
    os.makedirs(work, exist_ok=True)
    config = os.path.join(HERE, "beads_direct_shear.toml")
    length = 0.01139
    g_runs, l_runs = [], []
    for k in range(a.repeats):
        g = run_grainlab(a.grainlab, config, a.strain, work, k)
        g_runs.append(g)
        print(f"grainlab  run {k + 1}: shear {g['shear_steps'] / g['shear_s']:.0f} steps/s "
              f"({g['shear_steps'] / g['shear_cpu']:.0f} per CPU second), whole {g['wall']:.1f} s", flush=True)
        lg = run_liggghts(a.liggghts, g_runs[0], a.strain, length, work, k)
        l_runs.append(lg)
        print(f"LIGGGHTS  run {k + 1}: shear {lg['shear_steps'] / lg['shear_s']:.0f} steps/s "
              f"({lg['shear_steps'] / lg['shear_cpu']:.0f} per CPU second; its own loop time "
              f"{lg['shear_steps'] / lg['loop_s']:.0f} steps/s), whole {lg['wall']:.1f} s", flush=True)
    if not a.keep:
        shutil.rmtree(work, ignore_errors=True)

    def med(runs, f):
        return statistics.median(f(r) for r in runs)

    print(f"\n{g_runs[0]['beads']} beads, one thread each, {a.repeats} run(s) each alternated, "
          f"shear to {a.strain:g} strain ({g_runs[0]['shear_steps']} steps); medians:")
    print(f"{'':30} {'grainlab':>12} {'LIGGGHTS':>12} {'ratio':>7}")
    rows = [("shear steps/s", lambda r: r["shear_steps"] / r["shear_s"], "{:.0f}"),
            ("shear particle-steps/s", lambda r: r["beads"] * r["shear_steps"] / r["shear_s"], "{:.3g}"),
            ("whole test wall s", lambda r: r["wall"], "{:.1f}"),
            ("shear steps per CPU s", lambda r: r["shear_steps"] / r["shear_cpu"], "{:.0f}"),
            ("whole test CPU s", lambda r: r["cpu"], "{:.1f}")]
    for name, f, fmt in rows:
        gv, lv = med(g_runs, f), med(l_runs, f)
        ratio = lv / gv if name.startswith("whole") else gv / lv
        print(f"{name:30} {fmt.format(gv):>12} {fmt.format(lv):>12} {ratio:>6.2f}x")
        if name == "whole test wall s":
            print(f"{'  of which after the shear s':30} {med(g_runs, lambda r: r['after_shear_s']):>12.1f}"
                  "   (grainlab: analysis, outputs, report)")
    print("(ratio: how many times faster grainlab is)")
    print("\nresults (first run of each):")
    for name, key in (("void ratio at the shear's start", "e"), ("peak friction angle phi_p deg", "phi"),
                      ("peak dilation angle psi_p deg", "psi")):
        vals = []
        for r in (g_runs[0], l_runs[0]):
            star = "" if r.get(key + "_is_peak", True) else "*"
            vals.append(f"{r[key]:.3f}{star}" if key == "e" else f"{r[key]:.1f}{star}")
        print(f"{name:34} {vals[0]:>8} {vals[1]:>8}")


main()
