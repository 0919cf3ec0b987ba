"""The chapter IV navigators on the seven range sensors with layers, ``fuzzy-5b-rays`` and
``fuzzy-2b`` (recovery, loop escape, the robot's size), and their navigators without those two
layers kept as they were (``fuzzy-*-layered``: the thesis' navigators with this package's
anti-orbit guard, turning room, safety stop and hysteresis).

``data/thesis_traces.json`` was written by running ``fuzzy-5b`` / ``fuzzy-2b`` (today's ``-layered``
variants) of the code before the navigators got their layers (every goal scenario of the package, and the mixed worlds
0-008 and 0-009 of seed 0, ``data/mixed_worlds.json``): outcome, steps, final pose and sums of the
poses and commands of each trace.
"""

import json
import math
from pathlib import Path

import numpy as np
import pytest

from fuzzynav.catalog.controllers import CONTROLLERS, make_controller, spec_of
from fuzzynav.control.recovery import recovery_system
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import load_scenario, scenario_from_dict

DATA = Path(__file__).with_name("data")
WORLDS = json.loads((DATA / "mixed_worlds.json").read_text())
U_TRAP = {"name": "u-trap", "robot": {"x": 9.0, "y": 10.0, "theta": 0.0}, "goal": {"x": 16.0, "y": 10.0},
          "obstacles": [{"wall": {"start": [12.0, 6.5], "end": [12.0, 13.5], "thickness": 0.3}},
                        {"wall": {"start": [12.0, 6.5], "end": [7.0, 6.5], "thickness": 0.3}},
                        {"wall": {"start": [12.0, 13.5], "end": [7.0, 13.5], "thickness": 0.3}}], "max_time": 120}


def _scenario(name):
    return scenario_from_dict(WORLDS[name], source=name) if name in WORLDS else load_scenario(name)


@pytest.mark.parametrize("entry", json.loads((DATA / "thesis_traces.json").read_text()),
                         ids=lambda e: f"{e['scenario']}-{e['controller']}")
def test_layered_variants_drive_as_recorded(entry):
    trace = run_episode(_scenario(entry["scenario"]), make_controller(entry["controller"] + "-layered"), seed=0)
    assert (trace.outcome, trace.steps) == (entry["outcome"], entry["steps"])
    np.testing.assert_allclose(trace.pose[-1], entry["final_pose"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(trace.pose.sum(axis=0), entry["pose_sum"], rtol=0, atol=1e-6)
    assert trace.speed.sum() == pytest.approx(entry["speed_sum"], abs=1e-6)
    assert trace.steering.sum() == pytest.approx(entry["steering_sum"], abs=1e-6)
    assert "".join(sorted(set(trace.behaviour.tolist()))) == entry["labels"]


def test_boxed_in_front_of_a_thin_wall_end_it_backs_out_and_reaches_the_goal():
    world = _scenario("mixed-0-009")  # a thin wall end hides between the rays: the safety stop holds for good
    stuck = run_episode(world, make_controller("fuzzy-5b-layered"), seed=0)
    assert stuck.outcome == "timeout" and stuck.speed[-1] == 0.0
    trace = run_episode(world, make_controller("fuzzy-5b-rays"), seed=0)
    assert trace.reached and not trace.collision
    backing = trace.behaviour == "REC-BACK"
    assert backing.any() and (trace.speed[backing] < 0).all()  # it reversed, as the trace says
    assert world.world.clearance(trace.pose[:, :2]).min() > world.robot.radius


@pytest.mark.parametrize("controller, inner", [("fuzzy-5b-rays", "fuzzy-5b-layered"), ("fuzzy-2b", "fuzzy-2b-layered")])
def test_a_robot_in_a_u_trap_escapes_by_following_the_boundary(controller, inner):
    scenario = scenario_from_dict(U_TRAP)
    trapped = run_episode(scenario, make_controller(inner))
    assert trapped.outcome == "timeout"  # without loop escape the navigator circles inside the U
    trace = run_episode(scenario, make_controller(controller))
    assert trace.reached and "BF" in set(trace.behaviour.tolist())


def test_without_reverse_gear_there_is_no_recovery():
    world = dict(WORLDS["mixed-0-009"], max_time=30)
    world["robot"] = dict(world["robot"], max_reverse_speed=0.0)
    trace = run_episode(scenario_from_dict(world), make_controller("fuzzy-5b-rays"), seed=0)
    assert (trace.speed >= 0).all() and not trace.collision


def test_loop_detector_fires_on_a_circle_not_on_a_straight_run():
    from fuzzynav.kernels import escape, layers, row_blocks

    params = make_controller("fuzzy-5b-rays").params
    state = layers.fresh_state(1, params)[0]
    places = row_blocks.places_of(params, state)
    fired = [escape.circling(state, places, params, 0.1 * k, 5 + math.cos(0.05 * k), 5 + math.sin(0.05 * k), 10.0)
             for k in range(600)]
    assert any(fired) and not any(fired[:200])  # after the patience, back where it was
    escape.forget_places(state)
    assert not any(escape.circling(state, places, params, 0.1 * k, 0.1 * k, 0.0, 10.0) for k in range(600))


def test_recovery_rule_base_swings_the_nose_to_the_roomier_side():
    rules = recovery_system()
    # reversing with α < 0 swings the nose left (eq IV.1 with V < 0)
    assert rules.evaluate_one(2.0, 0.0)[0] < 0 < rules.evaluate_one(-2.0, 0.0)[0]
    assert rules.evaluate_one(0.0, 0.0)[0] == 0.0  # alike and the goal ahead: straight back
    assert rules.evaluate_one(0.0, 1.0)[0] < 0  # alike: towards the goal's side


def _sized(radius, task):
    if task == "goal":
        doc = {"robot": {"x": 2.0, "y": 10.0, "radius": radius}, "goal": {"x": 18.0, "y": 10.0},
               "obstacles": [{"circle": {"center": [10.0, 10.5], "radius": 1.0}}], "max_time": 40}
    else:
        doc = {"robot": {"x": 2.0, "y": 14.0, "theta": -0.844, "radius": radius}, "path": [[2, 14], [10, 5], [18, 14]],
               "max_time": 8}
    return scenario_from_dict(doc)


RANGE_NAVIGATORS = ("fuzzy-5b", "fuzzy-5b-rays", "fuzzy-2b", "fuzzy-5b-thesis", "fuzzy-2b-thesis")


@pytest.mark.parametrize("name", sorted(CONTROLLERS))
def test_a_small_and_a_large_robot_run_with_every_controller(name):
    controller = make_controller(name)
    for radius in (0.15, 0.5):
        scenario = _sized(radius, "goal" if "goal" in spec_of(name).tasks else "path")  # a task its spec lists
        trace = run_episode(scenario, controller)
        assert trace.robot_radius == radius and trace.steps > 10
        if name in RANGE_NAVIGATORS:  # they keep the robot's own body clear of the obstacle
            assert trace.reached and scenario.world.clearance(trace.pose[:, :2]).min() > radius
