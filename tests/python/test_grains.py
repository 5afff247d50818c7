"""grainlab.grains and grainlab.ct run the subcommands a shell runs: the same files, the same table."""

import io

import pandas

import grainlab
from conftest import run_cli


def test_generate_and_metrics_match_the_command_line(tmp_path, grainlab_binary):
    files = grainlab.grains.generate(tmp_path / "py", preset="angular", count=3, seed=7, faces=200)
    assert [f.name for f in files] == ["angular-0001.stl", "angular-0002.stl", "angular-0003.stl"]
    cli = run_cli(grainlab_binary, "grains", "generate", "--preset", "angular", "--count", "3", "--seed", "7",
                  "--faces", "200", "--out", str(tmp_path / "cli"))
    assert cli.returncode == 0, cli.stderr
    for f in files:
        assert f.read_bytes() == (tmp_path / "cli" / f.name).read_bytes()

    table = grainlab.grains.metrics(tmp_path / "py")
    stats = run_cli(grainlab_binary, "grains", "stats", str(tmp_path / "py"))
    assert stats.returncode == 0, stats.stderr
    pandas.testing.assert_frame_equal(table, pandas.read_csv(io.StringIO(stats.stdout)))
    assert len(table) == 3 and (table["convexity"] <= 1).all() and (table["volume_m3"] > 0).all()
    one = grainlab.grains.metrics(files[0])
    assert one["volume_m3"].iloc[0] == table["volume_m3"].iloc[0]


def test_bad_arguments_raise_the_command_lines_errors(tmp_path):
    import pytest
    with pytest.raises(grainlab.ConfigError, match="neither a mesh file nor a folder"):
        grainlab.grains.metrics(tmp_path / "nothing.stl")
    with pytest.raises(grainlab.ConfigError, match="--count"):
        grainlab.grains.generate(tmp_path / "g", count=0)


def test_ct_segment_of_a_synthetic_scan(tmp_path):
    scan = grainlab.ct.synth(tmp_path / "scan.nrrd", size=48, grains=3, touching=1, grain_size=12, seed=2)
    out = grainlab.ct.segment(scan, tmp_path / "seg", quiet=True)
    grains = pandas.read_csv(out / "grains.csv")
    assert 2 <= len(grains) <= 4
    assert all((out / f).is_file() for f in grains["file"])
