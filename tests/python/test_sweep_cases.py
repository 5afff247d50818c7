"""The cases of a sweep and one case's task, without a cluster.

The TOML writer round-trips through tomllib; the cases are the Cartesian product in
order with readable, unique folder names; every form of base gives the same cases;
a case is skipped only when its run finished with the same config, runs again from the
start when its config changed, and waits for a grainlab that still holds its folder.
"""

import fcntl
import os
import signal
import threading
import time
import tomllib

import pytest

from grainlab import _sweep_task, _toml_write
from grainlab._sweep_cases import SweepError, plan_cases
from sweep_helpers import grainlab, grainlab_processes_in, run_with_cli, tiny


def test_toml_text_reads_back_as_the_same_dict():
    d = {"seed": 7, "test": "direct-shear", "grains": {"preset": "sub-angular", "d_min": 7.07e-4, "faces": 120},
         "material": {"friction": 0.19, "hertz-material": {"youngs_modulus": 4e9}, "note": 'a "quoted"\\ \n\tx'},
         "oedometer": {"stresses": [2e5, 4e5], "loading": "stages"}, "flags": {"on": True, "off": False},
         "odd key": {"x.y": 1e-05, "inf": float("inf")}}
    assert tomllib.loads(_toml_write.dumps(d)) == d
    with pytest.raises(TypeError, match="not dict_keys"):
        _toml_write.dumps({"a": {}.keys()})


def test_cases_are_the_grid_crossed_with_seeds_in_order(tmp_path):
    cases = plan_cases(tiny(), str(tmp_path), grid={"consolidation.normal_stress": [50e3, 1.5e5],
                                                    "material.preset": ["ottawa", "glass beads"]}, seeds=[1, 2])
    assert [c.name for c in cases][:5] == [
        "normal_stress-50000_preset-ottawa_seed-1", "normal_stress-50000_preset-ottawa_seed-2",
        "normal_stress-50000_preset-glass_beads_seed-1", "normal_stress-50000_preset-glass_beads_seed-2",
        "normal_stress-150000_preset-ottawa_seed-1"]
    assert len(cases) == 8 and len({c.config_hash for c in cases}) == 8
    c = tomllib.loads(cases[2].config_text)
    assert c["seed"] == 1 and c["consolidation"]["normal_stress"] == 50e3 and c["material"]["preset"] == "glass beads"
    assert c["output"]["folder"] == "." and c["grains"]["faces"] == 120
    assert cases[2].inputs == {"consolidation.normal_stress": 50e3, "material.preset": "glass beads", "seed": 1}
    assert cases[2].folder == os.path.join(str(tmp_path), cases[2].name)


def test_every_form_of_base_gives_the_same_cases(tmp_path):
    path = tmp_path / "base.toml"
    path.write_text(tiny())

    class Config:
        def to_toml(self):
            return tiny()

    forms = [str(path), path, tiny(), tomllib.loads(tiny()), Config()]
    hashes = [[c.config_hash for c in plan_cases(b, "out", seeds=[1, 2])] for b in forms]
    assert all(h == hashes[0] for h in hashes)
    with pytest.raises(SweepError, match="no config file at 'missing.toml'"):
        plan_cases("missing.toml", "out", seeds=[1])


def test_keys_that_share_a_last_part_are_named_in_full_and_paths_made_absolute(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    cases = plan_cases(tomllib.loads(tiny()) | {"specimen": {"from": "prep/specimen.bin"}}, "out",
                       grid={"shear.final_strain": [0.1], "triaxial.final_strain": [0.2]})
    assert cases[0].name == "shear.final_strain-0.1_triaxial.final_strain-0.2"
    assert tomllib.loads(cases[0].config_text)["specimen"]["from"] == str(tmp_path / "prep" / "specimen.bin")


def _job(folder, text):
    import hashlib
    return {"name": "c", "folder": str(folder), "config_text": text, "inputs": {},
            "config_hash": hashlib.sha256(text.encode()).hexdigest(), "grainlab": grainlab(), "threads": 1,
            "lock_wait_s": 0.5}


def test_a_case_runs_once_and_again_only_when_its_config_changed(tmp_path):
    folder = tmp_path / "c"
    first = _sweep_task.run_case(_job(folder, tiny()))
    assert first["status"] == "finished" and not first["resumed"], first
    series = (folder / "series.csv").read_bytes()
    assert _sweep_task.run_case(_job(folder, tiny()))["status"] == "skipped"
    changed = _sweep_task.run_case(_job(folder, tiny(strain=0.012)))
    assert changed["status"] == "finished" and not changed["resumed"], changed
    assert (folder / "series.csv").read_bytes() != series
    assert (folder / "sweep.log").read_text().count("# ") == 2


def test_a_case_stopped_by_a_signal_continues_from_its_checkpoint(tmp_path):
    folder = tmp_path / "c"
    job = _job(folder, tiny(strain=0.06))
    outcome = {}
    task = threading.Thread(target=lambda: outcome.update(_sweep_task.run_case(job)))
    task.start()
    while not (folder / "checkpoint.bin").exists() and task.is_alive():
        time.sleep(0.01)
    for pid in grainlab_processes_in(str(folder)):
        os.kill(pid, signal.SIGINT)  # what Ctrl-C sends
    task.join()
    assert outcome["status"] == "stopped" and outcome["exit_code"] == 130, outcome
    again = _sweep_task.run_case(job)
    assert again["status"] == "finished" and again["resumed"], again
    cli = run_with_cli([(tiny(strain=0.06, folder=str(tmp_path / "cli")), str(tmp_path / "cli"))])[0]
    assert (folder / "series.csv").read_bytes() == open(os.path.join(cli, "series.csv"), "rb").read()


def test_a_case_waits_for_the_grainlab_that_holds_its_folder(tmp_path):
    folder = tmp_path / "c"
    folder.mkdir()
    fd = os.open(folder / ".grainlab.lock", os.O_RDWR | os.O_CREAT)
    fcntl.flock(fd, fcntl.LOCK_EX)
    r = _sweep_task.run_case(_job(folder, tiny()))
    assert r["status"] == "failed" and "holds the case folder's lock" in r["error"], r
    assert not (folder / "series.csv").exists()
    os.close(fd)
    assert _sweep_task.run_case(_job(folder, tiny()))["status"] == "finished"


EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples")


def test_the_four_sand_study_files_plan_its_runs():
    from grainlab import _sweep_file
    plans = {}
    for name in ("four_sands", "four_sands_damping"):
        kw = _sweep_file.read(os.path.join(EXAMPLES, name + ".sweep.toml"))
        plans[name] = plan_cases(kw["base"], kw["out"], grid=kw.get("grid"), seeds=kw.get("seeds"),
                                 variants=kw.get("variants"))
    sands = {c.name: tomllib.loads(c.config_text) for c in plans["four_sands"]}
    assert len(sands) == 12 and "angular_seed-9" in sands
    # bench/study_four_sands: 12 x 12 x 6 largest grains, Dr 0.9 on the own indices, 10 % (angular 20 %).
    d_max = 8.41e-4
    for name, c in sands.items():
        assert c["box"]["length"] == pytest.approx(12 * d_max) and c["box"]["height"] == pytest.approx(6 * d_max)
        assert c["specimen"]["relative_density"] == 0.9 and c["specimen"]["indices"] == "own"
        assert c["shear"]["final_strain"] == (0.2 if name.startswith("angular") else 0.1)
    damping = [tomllib.loads(c.config_text) for c in plans["four_sands_damping"]]
    assert [(c["material"]["hertz"]["gamma_n"], c["material"]["hertz"]["gamma_t"]) for c in damping] == [
        (40, 20), (20, 10), (80, 40)]
    assert damping[0]["specimen"]["from"].endswith("runs/four_sands/glass-beads_seed-7/specimen.bin")
    beads = sands["glass-beads_seed-7"]  # the specimen they shear: the same grains in the same box
    assert all(c["grains"] == beads["grains"] and c["box"] == beads["box"] and c["seed"] == 7 for c in damping)
