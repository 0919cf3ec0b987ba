"""Which sensor ring a run uses: --sensors, else the scenario's ``sensors`` key, else the
controller's (lidar for the gap-aware fuzzy-2b-gap / fuzzy-5b-gap and the default fuzzy-5b, also named
fuzzy-5b-gap-robust; the thesis' rays for the rest, fuzzy-5b-rays among them)."""

import json

import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.scenario import load_scenario, scenario_from_dict

OPEN = {"robot": {"x": 2, "y": 2}, "goal": {"x": 15, "y": 12}}


@pytest.mark.parametrize("controller, scenario_ring, count, beam", [
    ("fuzzy-5b-gap", None, 271, 0.0), ("fuzzy-2b-gap", None, 271, 0.0), ("fuzzy-5b-thesis", None, 7, 0.0),
    ("fuzzy-5b-rays", None, 7, 0.0), ("goal-seeking", None, 7, 0.0), ("fuzzy-5b-thesis", "beam", 7, 30.0),
    ("fuzzy-5b-rays", "lidar", 271, 0.0), ("fuzzy-5b-gap", "thesis", 7, 0.0), ("fuzzy-5b", None, 271, 0.0),
    ("fuzzy-5b-gap-robust", None, 271, 0.0)])
def test_ring_of_scenario_else_controller(controller, scenario_ring, count, beam):
    doc = {**OPEN, **({"sensors": scenario_ring} if scenario_ring else {})}
    sim = BatchSimulator(scenario_from_dict(doc), make_controller(controller), record=False)
    assert sim.sensors.count == count and sim.sensors.beam_width == pytest.approx(beam * 3.141592653589793 / 180)


def test_unknown_ring_in_a_scenario_names_the_field():
    with pytest.raises(InputError, match="sensors"):
        scenario_from_dict({**OPEN, "sensors": "sonar"})
    assert scenario_from_dict({**OPEN, "sensors": "lidar"}).to_dict()["sensors"] == "lidar"


def test_cli_sensors_option(capsys):
    assert main(["run", "fig-IV-15a", "--controller", "fuzzy-2b-thesis", "--sensors", "beam", "--json",
                 "--max-time", "3"]) == 0
    assert json.loads(capsys.readouterr().out)["steps"] == 30
    assert main(["run", "fig-IV-15a", "--controller", "fuzzy-2b", "--sensors", "sonar"]) == 2
    assert "sensors" in capsys.readouterr().err


@pytest.mark.parametrize("figure", ["fig-IV-15a", "fig-IV-22a", "fig-IV-23"])
def test_thesis_ring_kept_by_the_navigators_of_the_figures(figure):
    scenario = load_scenario(figure)
    for controller in scenario.controllers:
        assert BatchSimulator(scenario, make_controller(controller), record=False).sensors.count == 7
