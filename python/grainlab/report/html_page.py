"""The HTML page: number formatting, tables, figure blocks, the page itself (inline CSS, no
JavaScript, relative links to the PNGs) and the list of PNGs a report may write."""

import html
import os
from pathlib import Path

from .reading import num


# Every PNG the report may write (so stale ones from an earlier report are removed).
SINGLE_PNGS = ["stress_ratio.png", "vertical_displacement.png", "displacement_profile.png", "rotation.png",
               "coordination_number.png", "rose_diagram.png", "fabric_psi.png", "force_chains.png",
               "e_log_sigma.png", "k0.png", "constrained_modulus.png", "triaxial_curves.png", "stress_path.png",
               "series.png"]
COMPARISON_PNGS = ["stress_strain_overlay.png", "peaks_vs_roundness.png"]
TRIAXIAL_COMPARISON_PNGS = ["triaxial_overlay.png", "stress_paths.png", "mohr_circles.png"]
# What a comparison folder may hold besides index.html (both kinds: an --out folder may hold either); a direct
# shear comparison removes all of it, a triaxial one keeps mohr_coulomb.json, which grainlab report writes.
COMPARISON_OUTPUTS = COMPARISON_PNGS + TRIAXIAL_COMPARISON_PNGS + ["mohr_coulomb.json"]


# ---------------------------------------------------------------------------
# Numbers and tables.

def fmt(v, spec=".3g", unit=""):
    v = num(v)
    if v is None:
        return "&mdash;"
    return f"{v:{spec}}" + (f" {unit}" if unit else "")


def fmt_duration(s):
    s = num(s)
    if s is None:
        return "&mdash;"
    h, rem = divmod(int(round(s)), 3600)
    m, sec = divmod(rem, 60)
    return f"{s:.0f} s ({h}:{m:02d}:{sec:02d})"


def esc(x):
    return html.escape(str(x)) if x not in (None, "") else "&mdash;"


def table_html(rows, caption):
    body = "\n".join(f"<tr><th>{k}</th><td>{v}</td></tr>" for k, v in rows)
    return f'<table class="kv"><caption>{caption}</caption>\n{body}\n</table>'


# ---------------------------------------------------------------------------
# The page.

CSS = """
body { font-family: system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif; margin: 2em auto;
       max-width: 1100px; padding: 0 1em; color: #222; line-height: 1.45; }
h1 { font-size: 1.6em; margin-bottom: 0.2em; } h2 { font-size: 1.25em; border-bottom: 1px solid #ccc; margin-top: 2em; }
.sub { color: #555; margin-top: 0; }
table { border-collapse: collapse; margin: 0.8em 0 1.2em; font-size: 0.92em; }
caption { text-align: left; font-weight: 600; padding-bottom: 0.3em; }
table.kv th { text-align: left; font-weight: normal; color: #444; padding: 0.2em 1.2em 0.2em 0; }
table.kv td { padding: 0.2em 0; }
table.grid th, table.grid td { border: 1px solid #ccc; padding: 0.25em 0.5em; text-align: right; }
table.grid th { background: #f3f3f3; } table.grid td:first-child, table.grid td:nth-child(2),
table.grid td:nth-child(3) { text-align: left; }
.tables { display: flex; flex-wrap: wrap; gap: 3em; }
figure { margin: 1.5em 0 2.2em; } figure img { max-width: 100%; border: 1px solid #eee; }
figcaption { font-size: 0.92em; color: #333; max-width: 900px; }
.note { background: #fff7e0; border-left: 4px solid #e0a800; padding: 0.4em 0.8em; margin: 0.4em 0; font-size: 0.92em; }
.warn { background: #fdecea; border-left: 4px solid #c0392b; padding: 0.4em 0.8em; margin: 0.4em 0; font-size: 0.92em; }
footer { color: #777; font-size: 0.85em; margin-top: 3em; }
"""


def figure_html(f):
    parts = [f'<figure id="{html.escape(Path(f.png).stem) if f.png else ""}">' if f.png else "<figure>"]
    parts.append(f"<h3>{html.escape(f.title)} <small>(cf. paper {f.paper})</small></h3>")
    for w in f.warnings:
        parts.append(f'<div class="warn">warning: {w}</div>')
    for n in f.notes:
        parts.append(f'<div class="note">{html.escape(n)}</div>')
    if f.png:
        parts.append(f'<a href="{html.escape(f.png)}"><img src="{html.escape(f.png)}" alt="{html.escape(f.title)}"></a>')
        source = (f"Mirrors {f.paper} of He, Zheng &amp; Schaefer (2021)." if f.paper.startswith("Fig.")
                  else f"Cf. {f.paper}.")
        parts.append(f"<figcaption>{source} {f.caption}</figcaption>")
    parts.append("</figure>")
    return "\n".join(parts)


def write_page(out_dir, title, subtitle, blocks):
    page = (f'<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n<title>{html.escape(title)}</title>\n'
            f"<style>{CSS}</style>\n</head>\n<body>\n<h1>{html.escape(title)}</h1>\n<p class=\"sub\">{subtitle}</p>\n"
            + "\n".join(blocks) +
            "\n<footer>Written by grainlab report (grainlab.report). Figures follow He, Zheng &amp; Schaefer (2021), "
            "<i>Simulating shearing behavior of realistic granular soils using physics engine</i>, Figs. 10-17. "
            "SI units; strains in percent.</footer>\n</body>\n</html>\n")
    path = out_dir / "index.html"
    tmp = out_dir / ".index.html.tmp"
    tmp.write_text(page, encoding="utf-8")
    os.replace(tmp, path)
    return path


def prepare_out(out_dir, names):
    out_dir.mkdir(parents=True, exist_ok=True)
    for n in names:  # stale figures of an earlier report would otherwise linger unlinked
        (out_dir / n).unlink(missing_ok=True)


def run_link(r, out_dir):
    report = r.dir / "report" / "index.html"
    name = esc(r.name)
    if report.is_file():
        name = f'<a href="{html.escape(Path(os.path.relpath(report, out_dir)).as_posix())}">{name}</a>'
    return name


def grid_html(head, rows, caption):
    th = "".join(f"<th>{h}</th>" for h in head)
    body = "\n".join("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in rows)
    return f'<table class="grid"><caption>{caption}</caption>\n<tr>{th}</tr>\n{body}\n</table>'
