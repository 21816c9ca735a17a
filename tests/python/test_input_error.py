"""cosim.InputError: bad input is reported exactly as the program reports it."""
import subprocess

import pytest

import cosim
from conftest import DEFAULT


def stderr_line(cosim_binary, *args):
    p = subprocess.run([cosim_binary, *args], capture_output=True, text=True, timeout=120)
    assert p.returncode == 2
    lines = p.stderr.splitlines()
    assert len(lines) == 1
    return lines[0]


def test_a_bad_key_raises_input_error_with_the_programs_stderr_line(cosim_binary):
    with pytest.raises(cosim.InputError) as e:
        cosim.run(DEFAULT, overrides={"planner.nmae": "astar"})
    line = stderr_line(cosim_binary, "run", DEFAULT, "--no-video", "--set", "planner.nmae=astar")
    assert str(e.value) == line
    assert "planner.nmae" in line
    assert e.value.file == DEFAULT
    assert isinstance(e.value, ValueError)


def test_an_unknown_planner_argument_is_reported_as_cosim_plan_reports_it(cosim_binary):
    with pytest.raises(cosim.InputError) as e:
        cosim.plan(DEFAULT, planner="a_star")
    assert str(e.value) == stderr_line(cosim_binary, "plan", DEFAULT, "--planner", "a_star")
    assert e.value.place == "--planner a_star"


def test_a_missing_scenario_file_is_an_input_error(cosim_binary, tmp_path):
    missing = str(tmp_path / "missing.yaml")
    with pytest.raises(cosim.InputError) as e:
        cosim.run(missing)
    assert str(e.value) == stderr_line(cosim_binary, "run", missing, "--no-video")


def test_a_value_of_the_wrong_kind_names_its_key(cosim_binary):
    with pytest.raises(cosim.InputError) as e:
        cosim.run(DEFAULT, overrides={"sim.max_time": [1, 2]})
    assert str(e.value) == stderr_line(cosim_binary, "run", DEFAULT, "--no-video", "--set",
                                       "sim.max_time=[1, 2]")


def test_run_with_a_missing_scenario_leaves_the_users_files_in_out(tmp_path):
    # cosim.run deletes or replaces only files cosim can prove it wrote, and only once its
    # scenario passed its checks: a folder of the user's keeps everything.
    (tmp_path / "figures").mkdir()
    (tmp_path / "figures" / "thesis.png").write_text("the user's figure")
    (tmp_path / "index.html").write_text("the user's page")
    with pytest.raises(cosim.InputError):
        cosim.run(str(tmp_path / "missing.yaml"), out=tmp_path)
    with pytest.raises(cosim.InputError) as e:
        cosim.run(DEFAULT, overrides={"sim.max_time": 1}, out=tmp_path)
    assert "not written by cosim, or changed since" in str(e.value)
    assert (tmp_path / "index.html").read_text() == "the user's page"
    assert (tmp_path / "figures" / "thesis.png").read_text() == "the user's figure"
