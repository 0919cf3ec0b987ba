"""``save_scenario`` / ``scenario_yaml``: the ``controllers`` argument names the file's controllers
(it replaces the scenario's own), one name may be given as a string, and bad names are refused
before anything is written."""

from dataclasses import replace

import pytest

from fuzzynav.errors import InputError
from fuzzynav.world.scenario import load_scenario, scenario_from_dict
from fuzzynav.world.scenario_file import save_scenario, scenario_yaml

DOCUMENT = {"name": "sv", "world": {"width": 10, "height": 10}, "robot": {"x": 1, "y": 1},
            "goal": {"x": 8, "y": 8}, "controllers": ["fuzzy-2b", "goal-seeking"]}


@pytest.fixture
def scenario():
    return scenario_from_dict(DOCUMENT)


def test_the_argument_replaces_the_scenarios_own_controllers(scenario, tmp_path):
    save_scenario(scenario, tmp_path / "sv1.yaml", controllers=("dwa",))
    assert load_scenario(tmp_path / "sv1.yaml").controllers == ("dwa",)
    assert scenario_yaml(scenario, ["dwa", "vfh"]).count("controllers:") == 1


def test_one_name_as_a_string_is_one_controller(scenario, tmp_path):
    save_scenario(scenario, tmp_path / "sv2.yaml", controllers="dwa")
    assert load_scenario(tmp_path / "sv2.yaml").controllers == ("dwa",)


def test_without_the_argument_the_scenarios_own_are_written(scenario, tmp_path):
    for empty in ((), [], None):
        save_scenario(scenario, tmp_path / "sv3.yaml", controllers=empty)
        assert load_scenario(tmp_path / "sv3.yaml").controllers == ("fuzzy-2b", "goal-seeking")
    bare = replace(scenario, controllers=())
    assert "controllers" not in scenario_yaml(bare)
    assert scenario_yaml(bare, ("dwa",)).splitlines()[:2] == ["name: sv", "controllers: [dwa]"]


@pytest.mark.parametrize("controllers, expected", [
    ([5], r"controllers\[0\]: must be a string, got int 5"),
    (["dwa", ""], r"controllers\[1\]: must not be empty"),
    (["x" * 101], r"controllers\[0\]: must be at most 100 characters"),
    (5, r"controllers: must be a list, got int"),
    ({"dwa": 1}, r"controllers: must be a list, got dict"),
])
def test_bad_names_are_refused_and_nothing_is_written(scenario, tmp_path, controllers, expected):
    with pytest.raises(InputError, match=expected):
        save_scenario(scenario, tmp_path / "bad.yaml", controllers=controllers)
    assert not (tmp_path / "bad.yaml").exists()
    with pytest.raises(InputError, match=expected):
        scenario_yaml(scenario, controllers)
