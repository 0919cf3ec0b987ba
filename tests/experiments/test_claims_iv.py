"""The claim of Figs IV.13–IV.14 checks what the text says of the steering: "braquage maximale et
positive pour tourner à gauche … puis elle se diminue pour être nulle" — on numbers made up
for each way it can fail (the closed-loop run that passes is in test_chapter4.py). And each check of
chapter IV's other claims fails, alone, on numbers that follow the published tables' runs but for
one departure from the thesis."""

import math

import pytest

from fuzzynav.catalog.experiments import spec
from fuzzynav.experiments.routes import reference

RUN = {"outcome": "reached", "final_speed_mps": 0.05, "max_speed_mps": 3.7, "first_steering_rad": math.pi / 10,
       "largest_steering_rad": math.pi / 10, "aligned_at_s": 2.3, "largest_steering_once_aligned_rad": 0.0,
       "route": [[2.0, 3.0], [16.0, 17.0]]}


def _steering_checks(**changes):
    checks = spec("fig-IV-13").claim.evaluate({**RUN, **changes})[1]
    return {c.name: c.passed for c in checks if "steering" in c.name}


def test_a_first_steering_to_the_left_that_is_the_runs_largest_and_falls_to_zero_passes():
    assert _steering_checks() == {"first steering (°)": True, "largest steering once aligned (°)": True}


@pytest.mark.parametrize(("changes", "failed"), [
    ({"first_steering_rad": -math.pi / 10}, "first steering (°)"),  # to the right
    ({"largest_steering_rad": math.pi / 5}, "first steering (°)"),  # larger later: not "maximale" at first
    ({"aligned_at_s": None, "largest_steering_once_aligned_rad": None}, "largest steering once aligned (°)"),  # never 0
    ({"largest_steering_once_aligned_rad": math.radians(8)}, "largest steering once aligned (°)"),  # swerves again
])
def test_each_way_the_steering_departs_from_the_text_fails(changes, failed):
    checks = _steering_checks(**changes)
    assert not checks[failed] and all(passed for name, passed in checks.items() if name != failed)


def published(key: str, **run) -> dict:
    """A run along the published tables' route, switch points and obstacle sides of run ``key``."""
    return {**reference(key), **run}


def free_goals(**changes):
    """Fig IV.12: ten runs along the published routes, stopping at their goals; ``changes`` edit run a3."""
    panels = {panel: [published(f"fig-IV-12/{panel}{i}", outcome="reached", final_speed_mps=0.05) for i in range(1, 6)]
              for panel in "ab"}
    panels["a"][2].update(changes)
    return panels


def past_obstacles(**changes):
    """Fig IV.15: both worlds as published, without contact, three switches each; ``changes`` edit run b."""
    runs = {name: published(f"fig-IV-15/{name}", outcome="reached", min_clearance_m=0.2, behaviour_changes=3)
            for name in ("fig-IV-15a", "fig-IV-15b")}
    runs["fig-IV-15b"].update(changes)
    return runs


def rates(layered_collisions=0.0):
    return {"fuzzy-2b-thesis/circles": {"n": 100, "success_rate": 0.9, "collision_rate": 0.05},
            "fuzzy-2b-layered/circles": {"n": 100, "success_rate": 0.95, "collision_rate": 0.0},
            "fuzzy-5b-thesis/mixed": {"n": 100, "success_rate": 0.9, "collision_rate": 0.05},
            "fuzzy-5b-layered/mixed": {"n": 100, "success_rate": 0.95, "collision_rate": layered_collisions}}


def wall_runs(second="reached"):
    return {name: published(f"fig-VI-28/{name}", outcome=outcome)
            for name, outcome in (("fig-VI-27", "reached"), ("fig-VI-27b", second), ("fig-VI-28", "collision"))}


def moved(key, dx=0.6):
    return [[x + dx, y] for x, y in reference(key)["route"]]


CASES = [  # (id, numbers, the checks that must fail: none for the published numbers)
    ("fig-IV-12", free_goals(), []),
    ("fig-IV-12", free_goals(outcome="timeout"), ["goals reached"]),
    ("fig-IV-12", free_goals(final_speed_mps=0.2), ["largest speed at arrival (m/s)"]),
    ("fig-IV-12", free_goals(route=moved("fig-IV-12/a3")),
     ["farthest distance of the 10 routes from those of the published table (m)"]),
    ("fig-IV-13", {**RUN, "route": reference("fig-IV-13")["route"]}, []),
    ("fig-IV-13", {**RUN, "route": reference("fig-IV-13")["route"], "outcome": "timeout"}, ["outcome"]),
    ("fig-IV-13", {**RUN, "route": reference("fig-IV-13")["route"], "final_speed_mps": 0.2},
     ["speed at the goal (m/s)"]),
    ("fig-IV-15", past_obstacles(), []),
    ("fig-IV-15", past_obstacles(outcome="timeout"), ["fig-IV-15b: outcome"]),
    ("fig-IV-15", past_obstacles(min_clearance_m=-0.01), ["fig-IV-15b: smallest clearance (m)"]),
    ("fig-IV-15", past_obstacles(behaviour_changes=1), ["fig-IV-15b: behaviour switches"]),
    ("fig-IV-15", past_obstacles(obstacle_sides=["apart", "right", "apart", "apart", "right", "apart"]),
     ["fig-IV-15b: side of the robot each obstacle is passed on"]),  # the fifth passed on the other side
    ("eval-IV", rates(), []),
    ("eval-IV", rates(layered_collisions=0.01), ["fuzzy-5b-layered collision rate on 100 mixed worlds"]),
    ("fig-VI-28", wall_runs(), []),
    ("fig-VI-28", wall_runs(second="collision"), ["second corner (Fig VI.27 b)"]),
]


@pytest.mark.parametrize("key, numbers, failing", CASES)
def test_each_check_fails_on_the_numbers_that_contradict_it_alone(key, numbers, failing):
    verdict, checks = spec(key).claim.evaluate(numbers)
    assert [c.name for c in checks if not c.passed] == failing
    assert verdict == ("partly" if failing else "reproduced")
