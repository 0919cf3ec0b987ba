"""The default navigators' latency compensation (kernels/latency.py): told the robot's actuation
latency, ``fuzzy-5b`` decides at the pose where its command will act; without a latency every
trace is the one of the code before the compensation, bit for bit.

``python -m tests.control.test_latency_compensation`` prints the digests of :data:`UNCHANGED` with
the checkout on ``PYTHONPATH`` (:data:`BEFORE` holds those of the code before the compensation)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from fuzzynav.errors import InputError
from tests.sim.static_hashes import trace_digest

WORLD_6 = Path(__file__).parents[1] / "data" / "barn" / "world_6-scale-1.5.yaml"  # BARN world 6, MIT
# the acceptance set of docs/results/robustness.md but its latency: noise, dropouts, slip and drift
NO_LATENCY = (("robot.sensor_noise.range_sigma", 0.02), ("robot.sensor_noise.dropout", 0.01),
              ("robot.actuation.slip", 0.05), ("robot.odometry.drift", 0.01))
UNCHANGED = (("barn-6", "fuzzy-5b", ()), ("barn-6", "fuzzy-5b", NO_LATENCY), ("fig-IV-22a", "fuzzy-5b", ()),
             ("fig-IV-23", "fuzzy-2b", ()), ("fig-IV-22b", "fuzzy-5b-rays", NO_LATENCY))
# the default as the digests were recorded: its car route's forward arcs at a fixed speed, the
# step after a back-up the navigator's, the arcs driven by the layer only in tight places (the pace
# on the arcs, the chained plan, the wider driving and the 1.25 s pace horizon came later and change the
# decisions, latency or none)
OPTIONS = {"fuzzy-5b": {"pace": {"pace_car": 0.0, "pace_horizon": 1.5}, "guidance": {"guide_car_chain": 0.0, "guide_car_tight": 0.5, "guide_off_heading": 0.0}}}
BEFORE = {
    'barn-6/fuzzy-5b/0': '2c8e8f3569b4e780453d14565ccc21ea7e8e3419e141a144fbc408500ecdaeb2',
    'barn-6/fuzzy-5b/4': 'fbc86f0c1e2448890fc3a3971010fbe279a63334867581f8aa4661ccb1db3cff',
    'fig-IV-22a/fuzzy-5b/0': 'd8e8023d86782a733685602b7448c49e72980c970ce8c89f9aa26a0390557356',
    'fig-IV-23/fuzzy-2b/0': 'cb5db6297e8433bced43266f841dca07e4258040fe62cb8be65d1c3211feed4e',
    'fig-IV-22b/fuzzy-5b-rays/4': '57d5773498febfe95aa5b8e8d208d2a06c65a9a6879d91a3ee855d203a9df281',
}


def scenario(name: str, perturbations=()):
    from fuzzynav.bench.cells import perturb_scenario
    from fuzzynav.world.scenario import load_scenario

    return perturb_scenario(load_scenario(WORLD_6 if name == "barn-6" else name), perturbations)


def run(name: str, controller, perturbations=()):
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim import run_episode

    if isinstance(controller, str):
        controller = make_controller(controller)
    return run_episode(scenario(name, perturbations), controller, seed=0)


def digests() -> dict[str, str]:
    from fuzzynav.catalog.controllers import make_controller

    return {f"{name}/{controller}/{len(perturbations)}":
            trace_digest(run(name, make_controller(controller, **OPTIONS.get(controller, {})), perturbations))
            for name, controller, perturbations in UNCHANGED}


def test_without_latency_every_trace_is_bit_identical_to_before():
    assert digests() == BEFORE


def unaware(name: str = "fuzzy-5b", **options):
    """The navigator told no latency whatever the robot's (the navigator before the compensation)."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.control.robust import RobustNavigator

    navigator = make_controller(name, **options)
    navigator.for_latency = lambda latency: RobustNavigator.for_latency(navigator, 0.0)
    return navigator


def test_compensated_navigator_reaches_where_the_late_one_collides():
    """BARN world 6 at scale 1.5, latency 0.3 s (three steps): ``fuzzy-5b`` deciding on the scan
    it has now turns too late in the narrow passage and touches; deciding at the predicted pose
    it passes and reaches the goal."""
    from fuzzynav.catalog.controllers import make_controller

    late = (("robot.actuation.latency", 0.3),)
    blind = run("barn-6", unaware(**OPTIONS["fuzzy-5b"]), late)  # the trace as recorded (version 5)
    assert blind.outcome == "collision"
    seeing = run("barn-6", make_controller("fuzzy-5b", **OPTIONS["fuzzy-5b"]), late)
    assert seeing.outcome == "reached"
    assert run("barn-6", "fuzzy-5b", late).outcome == "reached"  # and the default of today


def test_navigator_learns_the_latency_in_whole_steps_of_its_robot():
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.kernels.layers import PARAM
    from fuzzynav.sim.simulator import BatchSimulator

    navigator = make_controller("fuzzy-5b")
    BatchSimulator(scenario("fig-IV-22a", (("robot.actuation.latency", 0.3),)), navigator, seed=0)
    dt = navigator.params[PARAM.plant_dt]
    assert navigator.params[PARAM.delay] == round(0.3 / dt) == 3
    with pytest.raises(InputError, match="0.26 s is not a whole number of the simulator's 0.1 s steps"):
        scenario("fig-IV-22a", (("robot.actuation.latency", 0.26),))  # it ran as 0.3 s, without a word
    BatchSimulator(scenario("fig-IV-22a"), navigator, seed=0)
    assert navigator.params[PARAM.delay] == 0
    sparse = make_controller("fuzzy-2b")  # seven rays: a scan too sparse to move (docs/results/robustness.md)
    BatchSimulator(scenario("fig-IV-22a", (("robot.actuation.latency", 0.3),)), sparse, seed=0)
    assert sparse.params[PARAM.delay] == 0


def test_prediction_rolls_the_queued_commands_through_the_kinematics():
    """Three queued commands moved the predicted pose as three steps of ``motion.advance``, and
    the scan moved there reads a wall ahead nearer by the distance driven towards it."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.kernels import latency
    from fuzzynav.kernels.layers import PARAM, STATE, fresh_state
    from fuzzynav.kernels.motion import advance
    from fuzzynav.kernels.records import Reading, Robot
    from fuzzynav.kernels.row_blocks import queue_of
    from fuzzynav.robot.tricycle import DEFAULT_PARAMS

    navigator = make_controller("fuzzy-5b").for_latency(0.3)
    params = navigator.params
    row = fresh_state(1, params)[0]
    commands = [(0.1, 0.5), (0.2, 0.6), (-0.1, 0.7)]
    for steering, speed in commands:
        latency.sent(params, row, steering, speed)
    assert row[STATE.sent] == 3 and queue_of(params, row).shape == (3, 2)
    x, y, theta = 1.0, 2.0, 0.3
    for steering, speed in commands:
        x, y, theta = advance(x, y, theta, steering, speed, DEFAULT_PARAMS.array())
    robot = Robot(1.0, 2.0, 0.3, 0.0, 5.0, 5.0)
    assert latency.predicted(params, row, robot) == (x, y, theta, 0.7)
    angles = np.linspace(-math.pi / 2, math.pi / 2, 181)
    wall = 3.0 / np.cos(angles)  # a wall 3 m ahead, across the heading
    ranges = np.where(np.abs(angles) < 1.2, wall, 8.0)
    out = np.empty_like(ranges)
    latency.shifted(Reading(ranges, angles, 8.0, 3.0, 0.0), 1.0, 0.0, 0.0, 2 * params[PARAM.plant_radius], out)
    assert out[90] == pytest.approx(2.0)
    assert np.all(out[np.abs(angles) < 0.9] < 8.0)  # the wall seen nearer stays closed


if __name__ == "__main__":
    for key, value in digests().items():
        print(f"    {key!r}: {value!r},")
