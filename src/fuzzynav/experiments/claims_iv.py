"""Chapter IV's experiments (the fuzzy navigators, §IV.6–IV.7, and the hand-made wall follower
of §VI.5.3.1, whose runs share chapter IV's module) with the thesis' claim of each.

Besides what the thesis says in words (goal reached, slowing down, collision at the corner…),
each figure's claim checks what its figure shows against the run of the published tables
(:mod:`fuzzynav.experiments.routes`): the route within 0.5 m, the obstacles passed on the same
sides, the behaviour changing at the same places — so an edited rule table that changes the
figure fails its claim (``benchmarks/mutations.py``)."""

from __future__ import annotations

import math

from fuzzynav.catalog.experiments import Experiment
from fuzzynav.experiments.claims import Check, Claim
from fuzzynav.experiments.routes import reference, route_check, switch_check

MODULE = "fuzzynav.experiments.chapter4"
ARRIVAL_SPEED_MPS = 0.15  # "slows to zero at the goal": the speed at arrival under this bound
ALIGNED_DRIFT_DEG = 5.0  # Fig IV.14: once aligned the steering "stays null": no correction above this


def _reached_without_contact(numbers, names) -> list[Check]:
    checks = []
    for name in names:
        run = numbers[name]
        checks.append(Check(f"{name}: outcome", run["outcome"], "reached", run["outcome"] == "reached"))
        checks.append(Check(f"{name}: smallest clearance (m)", run["min_clearance_m"], "> 0",
                            run["min_clearance_m"] is not None and run["min_clearance_m"] > 0))
    return checks


def _as_published(experiment: str, numbers, names, sides: bool = False) -> list[Check]:
    """Route and switch points of each run like the published tables' (and, with ``sides``, each
    circular obstacle passed on the same side)."""
    checks = []
    for name in names:
        run, key = numbers[name], f"{experiment}/{name}"
        checks.append(route_check(name, run, key))
        checks.append(switch_check(name, run, key))
        if sides:
            expected = reference(key)["obstacle_sides"]
            checks.append(Check(f"{name}: side of the robot each obstacle is passed on", run["obstacle_sides"],
                                f"{expected} (the published tables' run)", run["obstacle_sides"] == expected,
                                "package"))
    return checks


def _navigator(experiment: str, names, sides: bool = False):
    def test(numbers):
        return _reached_without_contact(numbers, names) + _as_published(experiment, numbers, names, sides)
    return test


def _fig_iv_12(numbers):
    runs = [r for panel in ("a", "b") for r in numbers[panel]]
    reached = sum(r["outcome"] == "reached" for r in runs)
    slowest = max(r["final_speed_mps"] for r in runs)
    routes = [route_check(f"{panel}{i + 1}", r, f"fig-IV-12/{panel}{i + 1}")
              for panel in ("a", "b") for i, r in enumerate(numbers[panel])]
    worst = max(routes, key=lambda check: check.value)
    return [Check("goals reached", reached, f"all {len(runs)}", reached == len(runs)),
            Check("largest speed at arrival (m/s)", slowest, f"< {ARRIVAL_SPEED_MPS}", slowest < ARRIVAL_SPEED_MPS),
            Check(f"farthest distance of the {len(routes)} routes from those of the published table (m)", worst.value,
                  worst.target, all(c.passed for c in routes), "package")]


def _fig_iv_13(numbers):
    return [route_check("free navigation", numbers, "fig-IV-13"),
            Check("outcome", numbers["outcome"], "reached", numbers["outcome"] == "reached"),
            Check("top speed (m/s)", numbers["max_speed_mps"], "≥ 3.0", numbers["max_speed_mps"] >= 3.0),
            Check("speed at the goal (m/s)", numbers["final_speed_mps"], f"< {ARRIVAL_SPEED_MPS}",
                  numbers["final_speed_mps"] < ARRIVAL_SPEED_MPS),
            Check("first steering (°)", round(math.degrees(numbers["first_steering_rad"]), 1),
                  f"> 0 (left) and the run's largest ({math.degrees(numbers['largest_steering_rad']):.1f})",
                  0 < numbers["first_steering_rad"] >= numbers["largest_steering_rad"]),
            Check("largest steering once aligned (°)", _degrees(numbers["largest_steering_once_aligned_rad"]),
                  f"< {ALIGNED_DRIFT_DEG} (steering falls to 0 and stays there)",
                  numbers["largest_steering_once_aligned_rad"] is not None
                  and math.degrees(numbers["largest_steering_once_aligned_rad"]) < ALIGNED_DRIFT_DEG)]


def _degrees(radians):
    """``radians`` in degrees to 0.1 (None stays None: never aligned)."""
    return None if radians is None else round(math.degrees(radians), 1)


def _fig_iv_15(numbers):
    names = ("fig-IV-15a", "fig-IV-15b")
    return _navigator("fig-IV-15", names, sides=True)(numbers) + [
        Check(f"{name}: behaviour switches", numbers[name]["behaviour_changes"], "≥ 2",
              numbers[name]["behaviour_changes"] >= 2) for name in names]


WALL_RUNS = ("fig-VI-27", "fig-VI-27b", "fig-VI-28")


def _wall_follower(numbers):
    bend, corner = numbers["fig-VI-27"]["outcome"], numbers["fig-VI-28"]["outcome"]
    second = numbers["fig-VI-27b"]["outcome"]
    return [Check("bend (Fig VI.27)", bend, "no collision", bend != "collision"),
            Check("sharp corner (Fig VI.28)", corner, "collision", corner == "collision"),
            Check("second corner (Fig VI.27 b)", second, "no collision", second != "collision"),
            *(route_check(name, numbers[name], f"fig-VI-28/{name}") for name in WALL_RUNS)]


BARE_SUCCESS, LAYERED_SUCCESS = 0.85, 0.9  # this package's targets (the thesis gives no rates)


def _eval_iv(numbers):
    checks = []
    for name, worlds in (("fuzzy-2b", "circles"), ("fuzzy-5b", "mixed")):
        bare, layered = numbers[f"{name}-thesis/{worlds}"], numbers[f"{name}-layered/{worlds}"]
        checks.append(Check(f"{name}-thesis (as published) success on {bare['n']} {worlds} worlds",
                            bare["success_rate"], f"≥ {BARE_SUCCESS}", bare["success_rate"] >= BARE_SUCCESS, "package"))
        checks.append(Check(f"{name}-layered success on {layered['n']} {worlds} worlds", layered["success_rate"],
                            f"≥ {LAYERED_SUCCESS}", layered["success_rate"] >= LAYERED_SUCCESS, "package"))
        checks.append(Check(f"{name}-layered collision rate on {layered['n']} {worlds} worlds",
                            layered["collision_rate"], "= 0", layered["collision_rate"] == 0, "package"))
    return checks


EXPERIMENTS = [
    Experiment("fig-IV-12", f"{MODULE}:fig_iv_12", "free goal seeking from five starts per panel, Table IV.1",
               "§IV.6.1, Fig IV.12, Table IV.1", Claim(
                   "From any start the robot turns towards the goal with a large steering angle and a low speed, "
                   "speeds up to about 3.5 m/s once aligned and far, and slows to zero at the goal.",
                   "All ten start/goal pairs are reached and the speed at arrival is below 0.15 m/s; each route lies "
                   "within 0.5 m of the route Table IV.1 as published drives.", _fig_iv_12)),
    Experiment("fig-IV-13", f"{MODULE}:fig_iv_13", "free navigation and its commands α, V_r",
               "§IV.6.1, Figs IV.13–IV.14", Claim(
                   "A positive maximal steering turns the robot left towards the goal, then falls to zero once the "
                   "robot has the goal's direction; the speed rises to about 3.5–4 m/s and falls to zero at the goal.",
                   "The goal is reached; the first steering is to the left and the largest of the run, and once it "
                   "has fallen below 1° it stays within 5°; the top speed is at least 3 m/s and the speed at the "
                   "goal below 0.15 m/s; the route lies within 0.5 m of the published table's.",
                   _fig_iv_13)),
    Experiment("fig-IV-15", f"{MODULE}:fig_iv_15", "fuzzy-2b-thesis past circular obstacles, switches A...H",
               "§IV.6.2, Fig IV.15, Table IV.2", Claim(
                   "Goal seeking plus obstacle avoidance (Table IV.2): from S1 the robot passes four obstacles, "
                   "switching behaviour at the points A…H, and reaches G1 slowing down.",
                   "fuzzy-2b-thesis (no layer of this package) reaches both worlds without contact, with at least two "
                   "behaviour switches each; route, switch points and the side each obstacle is passed on are those "
                   "of the published tables' run (within 0.5 m).", _fig_iv_15)),
    Experiment("fig-IV-22", f"{MODULE}:fig_iv_22", "fuzzy-5b-thesis in unknown cluttered worlds",
               "§IV.7.1, Fig IV.22", Claim(
                   "The five-behaviour navigator reaches its goal in unknown cluttered worlds of any obstacle shape.",
                   "fuzzy-5b-thesis (no layer of this package) reaches both worlds without contact; route and switch "
                   "points are those of the published tables' run (within 0.5 m).",
                   _navigator("fig-IV-22", ("fig-IV-22a", "fig-IV-22b")))),
    Experiment("fig-IV-23", f"{MODULE}:fig_iv_23", "fuzzy-5b-thesis reaches a goal inside a U-shaped wall",
               "§IV.7.1, Fig IV.23", Claim(
                   "A goal inside a U-shaped wall is reached by following the wall.",
                   "fuzzy-5b-thesis (no layer of this package) reaches the goal without contact; route and switch "
                   "points are those of the published tables' run (within 0.5 m).",
                   _navigator("fig-IV-23", ("fig-IV-23",)))),
    Experiment("eval-IV", f"{MODULE}:eval_iv",
               "fuzzy-2b/5b-thesis (as published) and -layered on circle / mixed worlds: success/collision rates",
               "§IV.6–IV.7", Claim(
                   "The chapter IV navigators reach their goals in worlds they do not know; the thesis gives no "
                   "rates.",
                   "This package's targets: as published (no layer), fuzzy-2b-thesis on circle worlds and "
                   "fuzzy-5b-thesis on mixed worlds reach ≥ 85 % of the goals; with this package's layers "
                   "(fuzzy-*-layered: anti-orbit guard, turning room, safety stop, hysteresis) ≥ 90 % and no "
                   "collision.", _eval_iv)),
    Experiment("fig-VI-28", f"{MODULE}:fig_vi_28", "hand-made wall follower: bend followed, sharp corner hit",
               "§VI.5.3.1, Figs VI.27–VI.28, Table VI.2", Claim(
                   "The hand-made fuzzy wall follower (Table VI.2) follows walls but collides at sharp corners.",
                   "The bend and a wall turning 45° away are followed without collision and the sharp corner is hit, "
                   "along the routes Table VI.2 drives (within 0.5 m).", _wall_follower)),
]
