"""The one-robot float branches of the navigators' pieces decide as their array branches, and a
batch of robots drives as the same robots run one by one (the speed work of issue 3 must not
change a single output)."""

import numpy as np
import pytest

from fuzzynav.control import supervisor
from fuzzynav.control.goal_seeking import GuardedGoalSeeking
from fuzzynav.control.registry import make_controller
from fuzzynav.control.turning_room import HitMemory, TurnGuard, cone_echo
from fuzzynav.robot.sensors import THESIS_SENSOR_ANGLES
from fuzzynav.sim import BatchSimulator, run_episode
from fuzzynav.sim.observation import BatchObservation
from fuzzynav.world.generate import generate_worlds
from fuzzynav.world.scenario import load_scenario

RNG_SEED = 20261201


def _rows(rng, n):
    """``n`` random situations of one robot: readings d1…d7, goal distance and bearing."""
    readings = np.where(rng.uniform(size=(n, 7)) < 0.3, 4.0, rng.uniform(0.2, 4.0, (n, 7)))
    return readings, rng.uniform(0.0, 12.0, n), rng.uniform(-np.pi, np.pi, n)


def _pair(row, other):
    """The batch of two whose first robot is ``row`` (the array branch sees it there)."""
    return np.stack([np.asarray(row, dtype=float), np.asarray(other, dtype=float)])


def test_select_on_floats_equals_the_array_branch():
    rng = np.random.default_rng(RNG_SEED)
    readings, distance, bearing = _rows(rng, 400)
    for params in (supervisor.SupervisorParams(), supervisor.relaxed(supervisor.SupervisorParams())):
        batch = supervisor.select(readings, distance, bearing, params)
        one = [supervisor.select(readings[i:i + 1], distance[i:i + 1], bearing[i:i + 1], params)[0]
               for i in range(len(readings))]
        np.testing.assert_array_equal(one, batch)
        assert len(set(one)) == 4  # every behaviour was chosen somewhere


def test_switch_on_ints_equals_the_array_branch():
    rng = np.random.default_rng(RNG_SEED)
    one, two = supervisor.Switch((0, 3, 2, 2, 1, 4), dwell=3), supervisor.Switch((0, 3, 2, 2, 1, 4), dwell=3)
    modes = []
    for _ in range(300):
        wanted, release, urgent = rng.integers(0, 6, 2), rng.uniform(size=2) < 0.7, rng.uniform(size=2) < 0.5
        modes.append(one(wanted[:1], release[:1], urgent[:1])[0])
        assert two(wanted, release, urgent)[0] == modes[-1]
    assert len(set(modes)) == 6


def test_guarded_goal_seeking_on_floats_equals_the_array_branch():
    rng = np.random.default_rng(RNG_SEED)
    _, distance, bearing = _rows(rng, 300)
    gsb = GuardedGoalSeeking()
    steering, speed, guard = gsb(distance, bearing)
    for i in range(len(distance)):
        s1, v1, g1 = gsb(distance[i:i + 1], bearing[i:i + 1])
        assert g1[0] == guard[i]
        assert s1[0] == pytest.approx(steering[i], abs=1e-12) and v1[0] == pytest.approx(speed[i], abs=1e-12)
    assert set(guard.tolist()) == {0, 1, 2}


def test_sonar_echo_and_hit_memory_on_floats_equal_the_array_branch():
    rng = np.random.default_rng(RNG_SEED)
    one, two = HitMemory(steps=3), HitMemory(steps=3)
    for _ in range(20):
        readings, _, bearing = _rows(rng, 2)
        pose = np.column_stack([rng.uniform(0, 20, 2), rng.uniform(0, 20, 2), rng.uniform(-np.pi, np.pi, 2)])
        distance = rng.uniform(0.0, 3.0, 2)
        r1, a1 = cone_echo(readings[:1], THESIS_SENSOR_ANGLES, distance[:1], bearing[:1])
        r2, a2 = cone_echo(readings, THESIS_SENSOR_ANGLES, distance, bearing)
        np.testing.assert_array_equal(r1[0], r2[0])
        np.testing.assert_allclose(a1[0], a2[0], rtol=0, atol=1e-15)
        p1, v1 = one.update(pose[:1], r1, a1, 4.0)
        p2, v2 = two.update(pose, r2, a2, 4.0)
        np.testing.assert_array_equal(v1[0], v2[0])
        np.testing.assert_allclose(p1[0][v1[0]], p2[0][v2[0]], rtol=0, atol=1e-12)


def _observation(pose, readings, distance, bearing, speed, goal):
    n = len(pose)
    return BatchObservation(t=0.0, dt=0.1, pose=pose, speed=speed, steering=np.zeros(n), target=goal,
                            ranges=readings, sensor_angles=THESIS_SENSOR_ANGLES, max_range=4.0,
                            obstacle_distance=distance, obstacle_bearing=bearing, active=np.ones(n, dtype=bool))


def test_turn_guard_and_goal_bearing_on_floats_equal_the_array_branch():
    rng = np.random.default_rng(RNG_SEED)
    one, two = TurnGuard(lane=1.5, margin=0.5, memory=2), TurnGuard(lane=1.5, margin=0.5, memory=2)
    pose = np.array([[10.0, 10.0, 0.3], [5.0, 5.0, -2.0]])
    wanted_seen = set()
    for k in range(400):
        crowd = 0.25 + 0.25 * np.sin(k / 15.0)  # few hits, from none to some: rooms and lanes of every size
        readings = np.where(rng.uniform(size=(2, 7)) < crowd, rng.uniform(0.3, 4.0, (2, 7)), 4.0)
        obs2 = _observation(pose.copy(), readings, rng.uniform(0.3, 3.0, 2), rng.uniform(-np.pi, np.pi, 2),
                            rng.uniform(0.0, 2.0, 2), rng.uniform(0.0, 20.0, (2, 2)))
        obs1 = _observation(obs2.pose[:1], readings[:1], obs2.obstacle_distance[:1], obs2.obstacle_bearing[:1],
                            obs2.speed[:1], obs2.target[:1])
        assert obs1.target_distance[0] == obs2.target_distance[0]
        assert obs1.target_bearing[0] == obs2.target_bearing[0]
        turning = rng.uniform(size=2) < 0.5
        w1, s1 = one(obs1, turning[:1], obs1.target_bearing)
        w2, s2 = two(obs2, turning, obs2.target_bearing)
        assert (w1[0], s1[0]) == (w2[0], s2[0])
        speed = rng.uniform(0.0, 3.0, 2)
        assert one.clearance(speed[:1], 0.1)[0] == pytest.approx(two.clearance(speed, 0.1)[0], abs=1e-12)
        wanted_seen.add(bool(w1[0]))
        pose[:, :2] += rng.uniform(-0.2, 0.2, (2, 2))
        pose[:, 2] += rng.uniform(-0.3, 0.3, 2)
    assert wanted_seen == {True, False}


@pytest.mark.parametrize("controller", ["fuzzy-5b-thesis", "fuzzy-2b-thesis"])
def test_a_batch_of_three_drives_as_three_single_runs(controller):
    scenario = load_scenario("fig-IV-22a")
    starts = np.array([scenario.start, scenario.start + [1.5, -1.0, -0.5], scenario.start + [1.0, -4.0, 0.8]])
    batch = BatchSimulator(scenario, make_controller(controller), starts=starts, max_time=25.0).run()
    labels = set()
    for i, start in enumerate(starts):
        alone = run_episode(scenario, make_controller(controller), start=start, max_time=25.0)
        together = batch.trace(i)
        assert together.outcome == alone.outcome and len(alone.pose) > 50  # every robot drives
        np.testing.assert_array_equal(together.behaviour, alone.behaviour)
        np.testing.assert_allclose(together.pose, alone.pose, rtol=0, atol=1e-9)
        np.testing.assert_allclose(together.speed, alone.speed, rtol=0, atol=1e-9)
        labels |= set(alone.behaviour.tolist())
    assert {"GSB", "FOA+VRB" if controller == "fuzzy-5b-thesis" else "OA"} <= labels  # they avoid obstacles too


def test_a_batch_through_the_safety_stop_stops_as_single_runs():
    world = generate_worlds("mixed", 10, 0)[9]  # mixed-0-009: the stop fires (tests/control/test_switching…)
    starts = np.array([world.start, world.start + [0.0, -1.0, 0.3]])
    batch = BatchSimulator(world, make_controller("fuzzy-5b-thesis"), starts=starts, max_time=20.0).run()
    for i, start in enumerate(starts):
        alone = run_episode(world, make_controller("fuzzy-5b-thesis"), start=start, max_time=20.0)
        together = batch.trace(i)
        assert together.outcome == alone.outcome
        np.testing.assert_allclose(together.pose, alone.pose, rtol=0, atol=1e-9)
        np.testing.assert_array_equal(together.speed == 0.0, alone.speed == 0.0)
    assert batch.trace(0).speed[-1] == 0.0 and not batch.trace(0).collision  # stopped, as alone
