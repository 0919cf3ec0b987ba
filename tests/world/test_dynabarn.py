"""The DynaBARN-like family (world/dynabarn.py) and its two BARN scores."""

import json

import numpy as np
import pytest

from fuzzynav.bench.measures import barn_score, run_row
from fuzzynav.bench.suites import parse_suite
from fuzzynav.cli import main
from fuzzynav.world import dynabarn
from fuzzynav.world.generate import generate_world, generate_worlds
from fuzzynav.world.moving import offsets
from fuzzynav.world.shapes import Circle
from fuzzynav.world.traffic import keeps_clear


def _arena(points):
    """World coordinates back to DynaBARN's arena coordinates."""
    return np.asarray(points) - dynabarn.WALL_FACE


def test_worlds_have_dynabarns_set_up():
    worlds = generate_worlds("dynabarn", 12, 3)
    counts = set()
    for scenario in worlds:
        assert tuple(_arena(scenario.start[:2])) == pytest.approx(dynabarn.START)
        assert scenario.start[2] == pytest.approx(np.pi, abs=1e-6)
        assert tuple(_arena(scenario.goal.position)) == pytest.approx(dynabarn.GOAL)
        assert scenario.goal.tolerance == 1.0 and scenario.max_time == 100.0
        world = scenario.world
        assert world.moving == tuple(range(len(world.obstacles)))  # every obstacle moves, nothing stands
        counts.add(len(world.obstacles))
        for obstacle, index in zip(world.obstacles, world.moving):
            motion = world.motions[index]
            assert isinstance(obstacle, Circle) and obstacle.radius == 0.5
            assert motion.type == "waypoints" and motion.loop and 0.3 <= motion.speed <= 1.5
            track = _arena(motion.points)
            inner = dynabarn.WALL_FACE - dynabarn.RADIUS
            assert (np.abs(track[:, 1]) <= inner + 1e-9).all() and (track[:, 0] <= dynabarn.ARENA + 1e-9).all()
            ends = track[[0, len(track) // 2]]  # out and back: the far end is half way round the loop
            on_border = (np.abs(ends[:, 1]) >= inner - 1e-6) | (np.abs(ends[:, 0]) >= inner - 1e-6)
            assert on_border.all(), (scenario.name, ends)
            assert np.allclose(track[1:], track[:0:-1])  # the way back is the way out, reversed
            assert np.hypot(*(track[0] - dynabarn.GOAL)) >= 1.5  # the goal is never covered at t = 0
        assert generate_world("dynabarn", 3, worlds.index(scenario)).to_dict() == scenario.to_dict()
    assert counts <= set(range(2, 6)) and len(counts) > 1


def test_obstacles_cross_the_route_and_never_reach_the_start():
    crossed = 0
    for scenario in generate_worlds("dynabarn", 8, 0):
        assert keeps_clear(scenario.world, [scenario.start[:2]], 100.0, margin=0.3)
        times = np.arange(0.0, 100.0, 0.5)
        centres = np.array([o.center for o in scenario.world.obstacles])[None] + offsets(scenario.world, times)
        crossed += np.any(np.abs(_arena(centres)[..., 1]) < 1.0)
    assert crossed >= 6  # the route y = 0 is crossed in most worlds


def test_challenge_score_is_one_eighth_for_every_success():
    """run.py's path length on DynaBARN is -20 - 11 = -31 m: numpy's clip returns its upper bound
    and every success scores 0.125 whatever its time; the true optimal path (20 m) ranks times."""
    for time_s in (12.0, 30.0, 99.0):
        assert barn_score(True, time_s, -31.0) == pytest.approx(0.125)
        assert float(np.clip(time_s, -31.0, -124.0)) == -124.0  # what run.py computes
    assert barn_score(True, 25.0, 20.0) == pytest.approx(10.0 / 25.0)
    assert barn_score(True, 12.0, 20.0) == pytest.approx(0.5)
    assert barn_score(False, 25.0, -31.0) == 0.0
    numbers = {"outcome": "reached", "time_s": 40.0, "path_length_m": 21.0, "min_clearance_m": 0.2,
               "steering_effort_rad": 0.0, "steering_variation_rad": 0.0, "final_distance_m": 0.9,
               "collision_by": None}
    row = run_row(numbers, 19.0, parse_suite("dynabarn:3").reference(0))
    assert row["barn_score"] == pytest.approx(0.25) and row["barn_score_challenge"] == pytest.approx(0.125)
    assert run_row(numbers, 19.0, parse_suite("mixed:3").reference(0))["barn_score_challenge"] is None


def test_bench_reports_both_scores(tmp_path):
    out = tmp_path / "out"
    assert main(["bench", "dynabarn:2", "--controllers", "dwa", "--workers", "1", "--out", str(out), "--quiet"]) == 0
    rows = [json.loads(line) for line in (out / "runs.jsonl").read_text().splitlines()]
    assert len(rows) == 2
    for row in rows:
        reached = row["outcome"] == "reached"
        assert row["barn_score_challenge"] == (0.125 if reached else 0.0)
        assert row["barn_score"] == pytest.approx(barn_score(reached, row["time_s"], 20.0))
    summary = (out / "summary.md").read_text()
    assert "BARN score (challenge's)" in summary
