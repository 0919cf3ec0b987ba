"""The layers of the navigators compiled (recovery, loop escape, obstacle memory, route).

``data/robust_traces.json`` was written by running ``fuzzy-5b-rays`` (then named ``fuzzy-5b``) /
``fuzzy-2b`` with the layers
of the code before they were compiled (Python, per robot) on five generated worlds of seed 0
where they back out, turn and follow boundaries (the worlds are stored there): outcome, steps,
final pose, sums of the poses and commands, and how often each behaviour label occurs.
"""

import json
from pathlib import Path

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.base import Controller
from fuzzynav.kernels import layers
from fuzzynav.sim import run_episode
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.scenario import scenario_from_dict

REFERENCE = json.loads(Path(__file__).with_name("data").joinpath("robust_traces.json").read_text())


def _scenario(name):
    return scenario_from_dict(REFERENCE["worlds"][name], source=name)


@pytest.mark.parametrize("entry", REFERENCE["traces"], ids=lambda e: f"{e['scenario']}-{e['controller']}")
def test_compiled_layers_drive_as_the_python_layers_did(entry):
    trace = run_episode(_scenario(entry["scenario"]), make_controller(entry["controller"]), seed=0)
    assert (trace.outcome, trace.steps) == (entry["outcome"], entry["steps"])
    np.testing.assert_allclose(trace.pose[-1], entry["final_pose"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(trace.pose.sum(axis=0), entry["pose_sum"], rtol=0, atol=1e-6)
    assert trace.speed.sum() == pytest.approx(entry["speed_sum"], abs=1e-6)
    assert trace.steering.sum() == pytest.approx(entry["steering_sum"], abs=1e-6)
    labels = trace.behaviour.tolist()
    assert {label: labels.count(label) for label in set(labels)} == entry["label_counts"]


class _OneByOne(Controller):
    """The navigator through its one-robot ``act`` (the simulator then copies it per robot)."""

    def __init__(self, navigator):
        self.navigator, self.name = navigator, navigator.name

    def reset(self, rng=None):
        self.navigator.reset(rng)

    def act(self, obs):
        return self.navigator.act(obs)


class _Batch(_OneByOne):
    """The navigator through its ``act_batch`` (not inside the simulator's compiled step)."""

    def act_batch(self, obs):
        return self.navigator.act_batch(obs)


@pytest.mark.parametrize("wrapper", [_OneByOne, _Batch])
def test_one_robot_act_and_act_batch_decide_as_the_compiled_step(wrapper):
    scenario = _scenario("dense-0-007")  # backs out, turns and follows a boundary
    inside = BatchSimulator(scenario, make_controller("fuzzy-2b"), seed=0).run()
    outside = BatchSimulator(scenario, wrapper(make_controller("fuzzy-2b")), n=2, seed=0).run()
    assert inside.controllers[0].params[layers.PARAM.points_slots] > 128  # the obstacle point slots grew on the way
    reference = inside.trace(0)
    for i in range(2):
        trace = outside.trace(i)
        assert trace.steps == reference.steps and (trace.behaviour == reference.behaviour).all()
        np.testing.assert_allclose(trace.pose, reference.pose, rtol=0, atol=1e-12)


def test_route_goes_round_a_wall_on_its_shorter_side_and_not_through_a_closed_box():
    from fuzzynav.kernels import route
    from fuzzynav.kernels.records import Sightings

    wall = np.array([[10.0, y] for y in np.arange(6.0, 16.0, 0.05)])  # x = 10, y 6 … 16; start and goal at y = 9
    found, x, y = route.target(Sightings(wall, len(wall)), 5.0, 9.0, 15.0, 9.0, 0.5, 6.0)
    assert found and x > 10.0 and y < 6.0  # 6 m along the route: past the wall, round its nearer (lower) end
    corners = np.array([[5.0 + a, 9.0 + b] for a, b in ((-1, -1), (1, -1), (-1, 1), (1, 1))])
    box = np.vstack([np.column_stack([np.linspace(p[0], q[0], 41), np.linspace(p[1], q[1], 41)])
                     for p, q in zip(corners[[0, 1, 3, 2]], corners[[1, 3, 2, 0]])])
    assert not route.target(Sightings(box, len(box)), 5.0, 9.0, 15.0, 9.0, 0.3, 2.5)[0]


def test_switches_turn_the_layers_off():
    scenario = _scenario("dense-0-007")
    for options, absent in (({"recovery": False}, {"REC-BACK", "REC-TURN"}), ({"escape": False}, {"BF"})):
        labels = set(run_episode(scenario, make_controller("fuzzy-2b", **options), seed=0).behaviour.tolist())
        assert not labels & absent
