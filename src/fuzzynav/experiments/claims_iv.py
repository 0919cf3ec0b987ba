"""Chapter IV's experiments (the fuzzy navigators, §IV.6–IV.7, and the hand-made wall follower
of §VI.5.3.1, whose runs share chapter IV's module) with the thesis' claim of each."""

from __future__ import annotations

import math

from fuzzynav.catalog.experiments import Experiment
from fuzzynav.experiments.claims import Check, Claim

MODULE = "fuzzynav.experiments.chapter4"
ARRIVAL_SPEED_MPS = 0.15  # "slows to zero at the goal": the speed at arrival under this bound


def _reached_without_contact(numbers, names) -> list[Check]:
    checks = []
    for name in names:
        run = numbers[name]
        checks.append(Check(f"{name}: outcome", run["outcome"], "reached", run["outcome"] == "reached"))
        checks.append(Check(f"{name}: smallest clearance (m)", run["min_clearance_m"], "> 0",
                            run["min_clearance_m"] is not None and run["min_clearance_m"] > 0))
    return checks


def _fig_iv_12(numbers):
    runs = [r for panel in ("a", "b") for r in numbers[panel]]
    reached = sum(r["outcome"] == "reached" for r in runs)
    slowest = max(r["final_speed_mps"] for r in runs)
    return [Check("goals reached", reached, f"all {len(runs)}", reached == len(runs)),
            Check("largest speed at arrival (m/s)", slowest, f"< {ARRIVAL_SPEED_MPS}", slowest < ARRIVAL_SPEED_MPS)]


def _fig_iv_13(numbers):
    return [Check("outcome", numbers["outcome"], "reached", numbers["outcome"] == "reached"),
            Check("top speed (m/s)", numbers["max_speed_mps"], "≥ 3.0", numbers["max_speed_mps"] >= 3.0),
            Check("speed at the goal (m/s)", numbers["final_speed_mps"], f"< {ARRIVAL_SPEED_MPS}",
                  numbers["final_speed_mps"] < ARRIVAL_SPEED_MPS),
            Check("first steering (°)", round(math.degrees(numbers["first_steering_rad"]), 1), "> 0 (left)",
                  numbers["first_steering_rad"] > 0)]


def _fig_iv_15(numbers):
    names = ("fig-IV-15a", "fig-IV-15b")
    return _reached_without_contact(numbers, names) + [
        Check(f"{name}: behaviour switches", numbers[name]["behaviour_changes"], "≥ 2",
              numbers[name]["behaviour_changes"] >= 2) for name in names]


def _wall_follower(numbers):
    bend, corner = numbers["fig-VI-27"]["outcome"], numbers["fig-VI-28"]["outcome"]
    return [Check("bend (Fig VI.27)", bend, "no collision", bend != "collision"),
            Check("sharp corner (Fig VI.28)", corner, "collision", corner == "collision")]


def _eval_iv(numbers):
    two, five = numbers["fuzzy-2b-thesis/circles"], numbers["fuzzy-5b-thesis/mixed"]
    return [Check(f"fuzzy-2b-thesis success on {two['n']} circle worlds", two["success_rate"], "≥ 0.9",
                  two["success_rate"] >= 0.9, "package"),
            Check(f"fuzzy-5b-thesis success on {five['n']} mixed worlds", five["success_rate"], "≥ 0.9",
                  five["success_rate"] >= 0.9, "package"),
            Check(f"fuzzy-5b-thesis collision rate on {five['n']} mixed worlds", five["collision_rate"], "= 0",
                  five["collision_rate"] == 0, "package")]


EXPERIMENTS = [
    Experiment("fig-IV-12", f"{MODULE}:fig_iv_12", "free goal seeking from five starts per panel, Table IV.1",
               "§IV.6.1, Fig IV.12, Table IV.1", Claim(
                   "From any start the robot turns towards the goal with a large steering angle and a low speed, "
                   "speeds up to about 3.5 m/s once aligned and far, and slows to zero at the goal.",
                   "All ten start/goal pairs are reached and the speed at arrival is below 0.15 m/s.", _fig_iv_12)),
    Experiment("fig-IV-13", f"{MODULE}:fig_iv_13", "free navigation and its commands α, V_r",
               "§IV.6.1, Figs IV.13–IV.14", Claim(
                   "A positive maximal steering turns the robot left towards the goal; the speed rises to about "
                   "3.5–4 m/s and falls to zero at the goal.",
                   "The goal is reached, the first steering is to the left, the top speed is at least 3 m/s and the "
                   "speed at the goal below 0.15 m/s.", _fig_iv_13)),
    Experiment("fig-IV-15", f"{MODULE}:fig_iv_15", "fuzzy-2b-thesis past circular obstacles, switches A...H",
               "§IV.6.2, Fig IV.15, Table IV.2", Claim(
                   "Goal seeking plus obstacle avoidance (Table IV.2): from S1 the robot passes four obstacles, "
                   "switching behaviour at the points A…H, and reaches G1 slowing down.",
                   "Both worlds are reached without contact, with at least two behaviour switches each.",
                   _fig_iv_15)),
    Experiment("fig-IV-22", f"{MODULE}:fig_iv_22", "fuzzy-5b-thesis in unknown cluttered worlds",
               "§IV.7.1, Fig IV.22", Claim(
                   "The five-behaviour navigator reaches its goal in unknown cluttered worlds of any obstacle shape.",
                   "Both worlds are reached without contact.",
                   lambda numbers: _reached_without_contact(numbers, ("fig-IV-22a", "fig-IV-22b")))),
    Experiment("fig-IV-23", f"{MODULE}:fig_iv_23", "fuzzy-5b-thesis reaches a goal inside a U-shaped wall",
               "§IV.7.1, Fig IV.23", Claim(
                   "A goal inside a U-shaped wall is reached by following the wall.",
                   "The goal is reached without contact.",
                   lambda numbers: _reached_without_contact(numbers, ("fig-IV-23",)))),
    Experiment("eval-IV", f"{MODULE}:eval_iv",
               "fuzzy-2b-thesis on circle worlds, fuzzy-5b-thesis on mixed worlds: success/collision rates",
               "§IV.6–IV.7", Claim(
                   "The chapter IV navigators reach their goals in worlds they do not know; the thesis gives no "
                   "rates.",
                   "This package's targets: fuzzy-2b-thesis ≥ 90 % success on circle worlds; fuzzy-5b-thesis ≥ 90 % "
                   "success with no collision on mixed worlds.", _eval_iv)),
    Experiment("fig-VI-28", f"{MODULE}:fig_vi_28", "hand-made wall follower: bend followed, sharp corner hit",
               "§VI.5.3.1, Figs VI.27–VI.28, Table VI.2", Claim(
                   "The hand-made fuzzy wall follower (Table VI.2) follows walls but collides at sharp corners.",
                   "The bend is followed without collision and the sharp corner is hit.", _wall_follower)),
]
