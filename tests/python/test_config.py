"""grainlab.Config: round trips, and bad input refused with the command line's own message."""

import pytest

import grainlab
from conftest import run_cli, tiny_config


def cli_error(binary, config_path) -> str:
    """The message `grainlab run FILE` gives for a bad config (after 'grainlab: error: ')."""
    done = run_cli(binary, "run", str(config_path))
    assert done.returncode == 2, done.stdout + done.stderr
    prefix = "grainlab: error: "
    assert done.stderr.startswith(prefix), done.stderr
    return done.stderr[len(prefix):].rstrip("\n")


def refused_as_by_the_command_line(binary, path, text=None) -> grainlab.ConfigError:
    """The ConfigError of Config.from_toml(path) (the file holding `text`), checked to carry the CLI's message."""
    if text is not None:
        path.write_text(text)
    with pytest.raises(grainlab.ConfigError) as python:
        grainlab.Config.from_toml(path)
    assert str(python.value) == cli_error(binary, path)
    assert python.value.file == str(path)
    return python.value


def test_file_string_and_dict_give_the_same_config(tmp_path):
    path = tmp_path / "c.toml"
    path.write_text(grainlab.config.dict_to_toml(tiny_config(tmp_path / "out")))
    from_file = grainlab.Config.from_toml(path)
    assert from_file["box.length"] == 0.003 and from_file["grains.faces"] == 120
    again = grainlab.Config.from_string(from_file.to_toml())
    assert again == from_file and again.to_toml() == from_file.to_toml()
    assert grainlab.Config.from_dict(from_file.to_dict()) == from_file
    assert grainlab.Config.from_dict(tiny_config(tmp_path / "out")) == from_file
    changed = from_file.replace({"shear.final_strain": 0.02, "seed": 4})
    assert changed["shear.final_strain"] == 0.02 and changed["seed"] == 4
    assert sorted(changed.differences(from_file)) == ["seed", "shear.final_strain"]
    with pytest.raises(KeyError):
        from_file["shear.no_such_key"]


def test_default_config_is_the_command_lines(grainlab_binary):
    for test in grainlab.lab_tests():
        cli = run_cli(grainlab_binary, "run", "--print-defaults", "--test", test)
        assert cli.returncode == 0, cli.stderr
        default = grainlab.default_config(test=test)
        assert default.test == test
        assert default == grainlab.Config.from_string(cli.stdout)
    with pytest.raises(grainlab.ConfigError):
        grainlab.default_config(test="no-such-test")


def test_unknown_key_refused_with_the_command_lines_message(tmp_path, grainlab_binary):
    error = refused_as_by_the_command_line(grainlab_binary, tmp_path / "bad.toml",
                                           "seed = 2\n[shear]\nfinal_strian = 0.1\n")
    assert error.line == 3 and error.key == "shear.final_strian"
    assert "final_strain" in error.fix  # the suggestion


def test_impossible_value_refused_with_the_command_lines_message(tmp_path, grainlab_binary):
    path = tmp_path / "bad.toml"
    error = refused_as_by_the_command_line(grainlab_binary, path, "[consolidation]\nnormal_stress = -5.0\n")
    assert error.key == "consolidation.normal_stress" and error.line == 2
    assert error.fix.startswith("Set consolidation.normal_stress")
    # The same value from a dict: the same words, the source named <dict>.
    with pytest.raises(grainlab.ConfigError) as from_dict:
        grainlab.Config.from_dict({"consolidation": {"normal_stress": -5.0}})
    assert str(from_dict.value) == str(error).replace(str(path), "<dict>")
    assert from_dict.value.file == "<dict>"


def test_missing_file_and_bad_types(tmp_path, grainlab_binary):
    refused_as_by_the_command_line(grainlab_binary, tmp_path / "none.toml")
    with pytest.raises(grainlab.ConfigError, match="seed"):
        grainlab.Config.from_dict({"seed": "three"})
    with pytest.raises(TypeError, match="box.length"):
        grainlab.Config.from_dict({"box": {"length": object()}})
