"""The plant interface without MuJoCo: the kinematic default, unknown names, a missing extra."""

import subprocess
import sys

import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.sim.plants import DEFAULT_PLANT, PLANTS, check_plant

WITHOUT_MUJOCO = "import sys; sys.modules['mujoco'] = None  # import mujoco now raises ImportError\n"


def test_the_default_plant_is_the_kinematic_model_in_the_compiled_step():
    from fuzzynav.sim.plants import make_plant
    from fuzzynav.world.scenario import load_scenario

    assert DEFAULT_PLANT == "kinematic" and set(PLANTS) >= {"kinematic", "mujoco"}
    scenario = load_scenario("fig-IV-22a")
    plant = make_plant("kinematic", scenario, scenario.robot, None, 1)
    assert plant.in_kernel and plant.name == "kinematic"


@pytest.mark.parametrize("name", ["bullet", "", None, "Mujoco"])
def test_an_unknown_plant_is_refused_naming_the_choices(name):
    with pytest.raises(InputError, match="kinematic, mujoco") as error:
        check_plant(name)
    assert error.value.field == "--plant"


def test_without_mujoco_the_package_runs_and_the_mujoco_plant_names_its_extra(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "mujoco", None)
    with pytest.raises(InputError, match=r"\.\[physics\]"):
        check_plant("mujoco")
    for command in (["run", "fig-IV-22a", "--plant", "mujoco"],
                    ["evaluate", "--worlds", "mixed", "--n", "1", "--plant", "mujoco"],
                    ["bench", "mixed:1", "--controllers", "fuzzy-5b", "--plant", "mujoco", "--out", "unused"]):
        assert main(command) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and "optional extra 'physics'" in err[0] and "--plant" in err[0], err


def test_importing_fuzzynav_and_a_kinematic_run_need_no_mujoco():
    code = WITHOUT_MUJOCO + """
import fuzzynav, fuzzynav.cli, fuzzynav.sim.simulator, fuzzynav.bench.campaign
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.world.scenario import load_scenario
trace = fuzzynav.run_episode(load_scenario("fig-IV-22a"), make_controller("goal-seeking"), max_time=1.0)
assert len(trace.t) == 11, len(trace.t)
print("ok")
"""
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0 and done.stdout.strip() == "ok", done.stderr
