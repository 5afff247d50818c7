"""grainlab.report, the report's subpackage: in-process reports and its command line.

A triaxial comparison in-process (fabricated runs, scripts/make_fake_run.py)
gets the engine's Mohr-Coulomb fit (mohr_coulomb.json) before the figures, as
`grainlab report` does; a folder that is not a run is a ConfigError. The
figures and pages themselves are scripts/test_report.sh's (ctest
report_script); Run.report() of a real run is test_run.py's.
"""

import json
import os
import subprocess
import sys

import pytest

import grainlab

from conftest import SOURCE


def fake_run(folder, *args):
    subprocess.run([sys.executable, str(SOURCE / "scripts" / "make_fake_run.py"), str(folder), *args],
                   check=True, stdout=subprocess.DEVNULL)
    return folder


def test_a_triaxial_comparison_in_process_draws_the_engines_fit(tmp_path):
    runs = [fake_run(tmp_path / f"s{s}", "--test", "triaxial", "--sigma3", str(s), "--phi", "34", "--cohesion", "5")
            for s in (50, 200)]
    index = grainlab.report(runs)
    assert index == (tmp_path / "comparison" / "report" / "index.html").resolve()
    fit = json.loads((index.parent / "mohr_coulomb.json").read_text())
    assert abs(fit["peak"]["phi_deg"] - 34.0) < 0.1 and abs(1e-3 * fit["peak"]["c_Pa"] - 5.0) < 0.1
    assert (index.parent / "mohr_circles.png").is_file()
    assert "<tr><td>peak</td><td>34.00</td><td>5.00</td>" in index.read_text(encoding="utf-8")


def test_a_folder_that_is_no_run_is_a_config_error(tmp_path):
    with pytest.raises(grainlab.ConfigError, match="has no series.csv: not a grainlab run folder"):
        grainlab.report([tmp_path])
    assert not (tmp_path / "report").exists()


def test_the_subpackage_is_the_command_line_and_a_function(tmp_path):
    assert callable(grainlab.report) and grainlab.report.write_report and grainlab.report.__doc__
    p = subprocess.run([sys.executable, "-m", "grainlab.report", str(tmp_path)], capture_output=True, text=True,
                       env={**os.environ, "PYTHONDONTWRITEBYTECODE": "1"})
    assert p.returncode == 1
    assert p.stderr.startswith("grainlab report: error: ") and "has no series.csv" in p.stderr, p.stderr
    assert len(p.stderr.strip().splitlines()) == 1
