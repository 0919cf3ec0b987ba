import numpy as np
import pytest
import yaml

from fuzzynav.errors import InputError
from fuzzynav.world.scenario import BUILTIN_DIR, list_scenarios, load_scenario, scenario_from_dict


def test_examples_load_and_round_trip(tmp_path):
    listing = list_scenarios()
    assert {"example-goal", "example-path", "example-target"} <= set(listing)
    assert all(listing[name] for name in ("example-goal", "example-path", "example-target"))
    for name in ("example-goal", "example-path", "example-target"):
        scenario = load_scenario(name)
        assert scenario.task == name.split("-")[1]
        file = tmp_path / f"{name}.yaml"
        file.write_text(yaml.safe_dump(scenario.to_dict()))
        again = load_scenario(file)
        assert again.to_dict() == scenario.to_dict()
        # every key of the packaged file comes back with its value (a key to_dict dropped would
        # come back as its default on both sides of the comparison above)
        source = yaml.safe_load((BUILTIN_DIR / f"{name}.yaml").read_text(encoding="utf-8"))
        assert {key: again.to_dict().get(key) for key in source} == source


def test_schema_of_architecture():
    s = load_scenario("example-goal")
    assert (s.world.width, s.world.height, s.max_time) == (20.0, 20.0, 120.0)
    np.testing.assert_allclose(s.start, [1, 1, 0])
    np.testing.assert_allclose(s.goal.position, [18, 18])
    assert s.goal.tolerance == 0.3
    assert [o.kind for o in s.world.obstacles] == ["circle", "polygon", "wall", "ellipse"]


def test_defaults():
    s = scenario_from_dict({"robot": {"x": 1, "y": 1}, "path": [[5, 5], [9, 5]]})
    assert s.path.tolerance == 0.5 and s.path.speed == 1.0 and s.start[2] == 0.0
    assert (s.world.width, s.world.height, s.max_time) == (20.0, 20.0, 120.0)
    t = scenario_from_dict({"robot": {"x": 1, "y": 1}, "target": {"x": 5, "y": 5}})
    assert t.target.motion.type == "static" and t.target.tolerance == 0.3


def test_load_by_file_name_and_errors_name_the_file(tmp_path):
    file = tmp_path / "mine.yaml"
    file.write_text("robot: {x: 1, y: 1}\ngoal: {x: 5, y: 5}\n")
    assert load_scenario(str(file)).name == "mine"
    file.write_text("robot: {x: 1, y: 1}\ngoal: {x: 5, y: 5, tolerence: 0.3}\n")
    with pytest.raises(InputError) as error:
        load_scenario(file)
    assert str(file) in str(error.value) and "goal.tolerence" in str(error.value)
    assert "tolerance" in str(error.value)
    with pytest.raises(InputError, match="example-goal"):
        load_scenario("example-gaol")
    with pytest.raises(InputError, match="SCENARIO: is empty"):  # not "is a directory" (the current one)
        load_scenario(" ")
