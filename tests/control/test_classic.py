"""The classic navigators (dwa, apf, vfh, astar-pp): closed-loop runs on generated worlds."""

import numpy as np
import pytest

from fuzzynav.catalog.controllers import available, make_controller
from fuzzynav.control.classic.astar_pp import PLANNERS, AStarPurePursuit
from fuzzynav.errors import InputError
from fuzzynav.sim import metrics, run_episode
from fuzzynav.world.dead_ends import dead_end, dead_ends
from fuzzynav.world.generate import generate_world
from fuzzynav.world.scenario import scenario_from_dict
from tests.world.test_hybrid_astar import bay

CLASSIC = ("dwa", "apf", "vfh", "astar-pp")


@pytest.mark.slow
@pytest.mark.parametrize("name", CLASSIC)
def test_reaches_the_goal_on_mixed_worlds_without_collision(name):
    for i in range(3):
        scenario = generate_world("mixed", 0, i)
        trace = run_episode(scenario, make_controller(name), seed=0)
        assert trace.outcome == "reached", (name, scenario.name, trace.outcome)
        assert metrics(trace, scenario)["min_clearance_m"] > 0


def test_registered_and_map_awareness_labelled():
    listing = available()
    assert set(CLASSIC) <= set(listing)
    assert "MAP-AWARE" in listing["astar-pp"]
    assert getattr(make_controller("astar-pp"), "map_aware", False)
    assert not any(getattr(make_controller(name), "map_aware", False) for name in ("dwa", "apf", "vfh"))


WALL = {"robot": {"x": 2, "y": 5, "theta": 0}, "goal": {"x": 18, "y": 5},
        "obstacles": [{"wall": {"start": [10, 3.5], "end": [10, 6.5], "thickness": 0.3}}], "max_time": 60}


@pytest.mark.parametrize("name", ("dwa", "apf", "vfh"))
def test_reactive_navigators_pass_a_wall_they_only_see_with_the_range_sensors(name):
    """A 3 m wall across the way. (A 7.6 m one traps all three in loops in front of it: they
    remember one second of range hits, so the wall's far parts are forgotten while they turn.)"""
    scenario = scenario_from_dict(dict(WALL, world={"width": 20, "height": 10}))
    trace = run_episode(scenario, make_controller(name), seed=0)
    assert trace.outcome == "reached"
    assert trace.pose[:, 1].max() > 6.5 or trace.pose[:, 1].min() < 3.5  # went round an end of the wall


def test_astar_pp_plans_for_its_body_radius():
    """A 1.0 m gap: a 0.3 m body passes through it, a 0.6 m body must go round."""
    doc = {"world": {"width": 20, "height": 12}, "robot": {"x": 2, "y": 6, "theta": 0}, "goal": {"x": 18, "y": 6},
           "obstacles": [{"wall": {"start": [10, 0], "end": [10, 5.5], "thickness": 0.3}},
                         {"wall": {"start": [10, 6.5], "end": [10, 10], "thickness": 0.3}}]}
    scenario = scenario_from_dict(doc)
    small, large = AStarPurePursuit(radius=0.3), AStarPurePursuit(radius=0.6)
    small.prepare(scenario)
    large.prepare(scenario)
    crossing = lambda path: path[np.argmin(np.abs(path[:, 0] - 10.0)), 1]
    assert 5.5 < crossing(small.path) < 6.5
    assert crossing(large.path) > 10.0
    assert run_episode(scenario, AStarPurePursuit(radius=0.3), seed=0).outcome == "reached"


def test_astar_pp_drives_round_where_the_grid_path_cannot_be_driven():
    """Start facing away from the goal in a corridor too narrow to turn round in (1.4 m between
    the walls' axes, a U-turn needs 1.6 m): the grid A* path leads straight back, and the car
    following it does not get there; the hybrid A* path turns in the room beyond, and the car does."""
    scenario = bay(1.4)
    grid = AStarPurePursuit(planner="grid")
    # (version 2 drove into the wall; version 3 backs off or stands where no arc is clear)
    assert run_episode(scenario, grid, seed=0).outcome == "timeout" and grid.planner == "grid-A*"
    before = PLANNERS["hybrid-A*"]
    hybrid = AStarPurePursuit()
    trace = run_episode(scenario, hybrid, seed=0)
    assert trace.outcome == "reached" and hybrid.planner == "hybrid-A*"
    assert PLANNERS["hybrid-A*"] == before + 1
    assert metrics(trace, scenario)["min_clearance_m"] > 0.1
    assert trace.pose[:, 0].max() > 6.0  # turned round in the room


@pytest.mark.parametrize("name, option", [("dwa", "braking"), ("apf", "influence"), ("vfh", "window"),
                                          ("astar-pp", "lookahead"), ("astar-pp", "planner"), ("dwa", "radius")])
def test_bad_options_name_the_field(name, option):
    with pytest.raises(InputError, match=option):
        make_controller(name, **{option: -1.0})


@pytest.mark.parametrize("width", [1.0, 1.6, 2.2])
def test_astar_pp_backs_out_of_a_dead_end_it_starts_facing(width):
    """Facing the closed end of a corridor no forward path leaves: hybrid A* with backward arcs
    plans the way out, and the car backs along it, then drives to the goal without touching a wall."""
    scenario = scenario_from_dict(dead_end(width=width))
    navigator = AStarPurePursuit()
    trace = run_episode(scenario, navigator, seed=0)
    assert trace.outcome == "reached" and navigator.planner == "hybrid-A*"
    assert (navigator.gear < 0).any() and any(label.endswith("-back") for label in trace.behaviour.tolist())
    assert trace.pose[20, 0] < trace.pose[0, 0]  # backing away from the closed end first
    assert metrics(trace, scenario)["min_clearance_m"] > 0


@pytest.mark.parametrize("index", [7, 13, 20, 33])
def test_astar_pp_plans_again_where_its_tracker_leaves_the_plan(index):
    """Dead ends the tracker could not hold to the prepared plan (a full-lock U-turn cut wide:
    worlds 13 and 33; off the path after a cusp: 7 and 20) and hit a wall on: it now plans again
    from where it is, with backward arcs, and gets out to the goal."""
    scenario = dead_ends(index + 1, 0)[index]
    navigator = AStarPurePursuit()
    trace = run_episode(scenario, navigator, seed=0)
    assert trace.outcome == "reached" and navigator.replans >= 1
    assert any(label.endswith("-back") for label in trace.behaviour.tolist())
    assert metrics(trace, scenario)["min_clearance_m"] > 0
    navigator.reset()  # a new episode starts from the prepared plan again
    assert navigator.replans == 0 and navigator.path is navigator._prepared[0]


def test_astar_pp_keeps_forward_plans_where_they_exist():
    """Where a forward path exists, the plan has no backward leg and the pure-pursuit tracker follows it."""
    navigator = AStarPurePursuit()
    navigator.prepare(generate_world("mixed", 0, 0))
    assert navigator.planner == "hybrid-A*" and navigator.gear is None and navigator.heading is None


@pytest.mark.parametrize("world", [("maze", 4, 44), ("dead-end", 1, 68)])
def test_astar_pp_never_drives_into_the_map_it_knows(world):
    """Where the tracker lags a planned full-lock turn near a wall and no replan from there finds a
    path (``maze`` seed 4 world 44; dead end 68 of seed 1), no arc ahead is clear: the car backs on a
    clear arc behind, or stands, and no longer takes the clearest arc ahead into the wall. Every
    replan tried counts, so the stalemate does not search at every step."""
    family, seed, index = world
    scenario = dead_ends(index + 1, seed)[index] if family == "dead-end" else generate_world(family, seed, index)
    navigator = AStarPurePursuit()
    trace = run_episode(scenario, navigator, seed=0)  # to the time limit: no collision in the stalemate either
    labels = trace.behaviour.tolist()
    assert trace.outcome != "collision" and metrics(trace, scenario)["min_clearance_m"] > 0
    assert any(label.endswith("-back-check") for label in labels)
    assert navigator.replans == 4  # the budget spent, on tries that found nothing too
