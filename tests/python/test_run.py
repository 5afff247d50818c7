"""grainlab.run and grainlab.Run: the command line's run, in Python.

A tiny direct shear run from Python writes the same series.csv bytes as
`grainlab run` with the same config; a run stopped by Ctrl-C (a real SIGINT
to this process) keeps a checkpoint, and resume=True then finishes it with
the same bytes as a run never stopped; the DataFrame's columns and units are
those docs/outputs.md documents.
"""

import os
import re
import signal

import pytest

import grainlab
from conftest import SOURCE, tiny_config


def read(path):
    with open(path, "rb") as f:
        return f.read()


@pytest.fixture(scope="module")
def python_run(tmp_path_factory):
    """The tiny config run from Python, with a progress callback recording what it is given."""
    folder = tmp_path_factory.mktemp("py") / "run"
    seen = []
    run = grainlab.run(grainlab.Config.from_dict(tiny_config(folder)), progress=seen.append, threads=1)
    return run, seen


def test_a_run_from_python_writes_the_command_lines_bytes(cli_run, python_run):
    run, _ = python_run
    assert run.finished
    for name in ("series.csv", "analysis/profile.csv", "analysis/derived.csv"):
        assert read(run.folder / name) == read(cli_run / name), name
    # The same config.toml, but for the folder it names.
    assert read(run.folder / "config.toml") == read(cli_run / "config.toml").replace(
        str(cli_run).encode(), str(run.folder).encode())
    assert read(run.folder / "series.csv").count(b"\n") > 8


def test_progress_reaches_the_callback(python_run):
    _, seen = python_run
    assert len(seen) > 3
    steps = [p["step"] for p in seen]
    assert steps == sorted(steps) and steps[-1] > steps[0]
    assert seen[0]["loading"] is False and seen[0]["phase"] == "deposit"
    loading = [p for p in seen if p["loading"]]
    assert loading and loading[-1]["progress_label"] == "shear strain"
    assert loading[-1]["progress"] == pytest.approx(loading[-1]["final_progress"], rel=0.3)


def test_ctrl_c_checkpoints_and_resume_gives_the_same_bytes(tmp_path, cli_run):
    config = grainlab.Config.from_dict(tiny_config(tmp_path / "run"))
    series = tmp_path / "run" / "series.csv"

    def interrupt_during_shear(progress):
        # Ctrl-C once shear has written a few rows: the signal, as a terminal sends it.
        if progress["loading"] and series.exists() and read(series).count(b"\n") >= 4:
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        grainlab.run(config, progress=interrupt_during_shear)
    assert (tmp_path / "run" / "checkpoint.bin").is_file()
    assert not (tmp_path / "run" / "run.json").exists()
    rows = read(series).count(b"\n")
    assert 4 <= rows < read(cli_run / "series.csv").count(b"\n")
    assert not [p for p in (tmp_path / "run").iterdir() if ".tmp" in p.name]  # no torn file

    lines = []
    run = grainlab.run(config, resume=True, log=lines.append)
    assert any(line.startswith("resuming at step") for line in lines), lines
    assert read(series) == read(cli_run / "series.csv")
    assert run.finished


def test_an_exception_in_the_callback_stops_the_run_and_is_raised(tmp_path):
    config = grainlab.Config.from_dict(tiny_config(tmp_path / "run"))

    def fail(progress):
        raise ValueError("stop here")

    with pytest.raises(ValueError, match="stop here"):
        grainlab.run(config, progress=fail)
    # Stopped at its first chunk of steps, with a checkpoint to go on from.
    assert (tmp_path / "run" / "checkpoint.bin").is_file()
    assert not (tmp_path / "run" / "run.json").exists()


def documented_columns(test_title="Direct shear"):
    """(column, unit) of the direct shear table of docs/outputs.md, in order."""
    text = (SOURCE / "docs" / "outputs.md").read_text(encoding="utf-8")
    section = text[text.index(f"**{test_title}**"):]
    section = section[:section.index("\n\n", section.index("| --- |"))]
    columns = []
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 3 or cells[0] in ("column", "---"):
            continue
        for name in re.findall(r"`([^`]+)`", cells[0]):
            columns.append((name, cells[1]))
    return columns


def test_series_columns_and_units_are_the_documented_ones(python_run):
    run, _ = python_run
    frame = run.series
    documented = documented_columns()
    assert len(documented) > 15
    assert list(frame.columns) == [name for name, _ in documented]
    assert frame.attrs["units"] == dict(documented)
    assert run.units == dict(documented)
    assert frame["shear_strain"].iloc[-1] == pytest.approx(0.01, abs=0.002)


def test_summary_peaks_snapshots(python_run):
    run, _ = python_run
    summary = run.summary
    assert summary["config"]["test"] == "direct-shear" and summary["grains"] > 10
    assert run.peaks == summary["peaks"] and "friction_angle_deg" in run.peaks
    assert set(run.snapshots) == {"grains", "contacts", "walls"}
    assert all(path.is_file() for path in run.snapshots.values())
    assert run.config["shear.final_strain"] == 0.01
    again = grainlab.Run(run.folder)
    assert again.summary == summary
    with pytest.raises(grainlab.ConfigError, match="not a run folder"):
        grainlab.Run(run.folder / "analysis")


def test_a_bad_resume_is_refused_as_by_the_command_line(tmp_path):
    config = grainlab.Config.from_dict(tiny_config(tmp_path / "none"))
    with pytest.raises(grainlab.ConfigError, match="--resume: no checkpoint"):
        grainlab.run(config, resume=True)


def test_report_writes_the_command_lines_html(python_run):
    run, _ = python_run
    index = run.report()
    assert index == run.folder / "report" / "index.html" and index.is_file()
    assert "stress_ratio.png" in index.read_text(encoding="utf-8")
