"""What the thesis claims for each reproduced figure / table, and the test of it on our numbers.

:data:`CLAIMS` maps each experiment id of :mod:`fuzzynav.catalog.experiments` to a
:class:`Claim`: the thesis' statement (translated from the French, with its numbers), what this
package asserts of its own run, and :meth:`Claim.check`, which reads the numbers the experiment
returned and says whether the assertion holds, with the numbers behind the verdict.
``fuzzynav reproduce --out DIR`` puts both beside our figure in ``DIR/index.html``
(:mod:`fuzzynav.experiments.report`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

Verdict = tuple[bool, str]


@dataclass(frozen=True)
class Claim:
    """The thesis' statement for one figure / table, our asserted claim and its test."""

    thesis: str  # the thesis' words and numbers, translated
    asserted: str  # what this package asserts of its own run
    test: Callable[[dict], Verdict]  # numbers of the run -> (holds, the numbers behind the verdict)

    def check(self, numbers: dict) -> Verdict:
        """(holds, explanation); numbers missing from the run make the claim fail, not crash."""
        try:
            return self.test(numbers)
        except (KeyError, TypeError, IndexError) as error:
            return False, f"the run did not report the numbers the claim needs ({error!r})"


def _m(value) -> str:
    return "n/a" if value is None else f"{value:.3f} m"


def _converged(value, budget=None) -> str:
    """An episode count, or "not converged within N episodes" (never a number past the budget)."""
    if value is None or (budget is not None and value > budget):
        return f"not converged within {budget} episodes" if budget else "not converged"
    return f"converged at episode {value}"


def _all_reached(names) -> Callable[[dict], Verdict]:
    def test(numbers):
        runs = {name: numbers[name] for name in names}
        text = "; ".join(f"{name}: {r['outcome']} in {r['time_s']:.1f} s, min clearance {_m(r['min_clearance_m'])}"
                         for name, r in runs.items())
        ok = all(r["outcome"] == "reached" and r["min_clearance_m"] > 0 for r in runs.values())
        return ok, text
    return test


def _fig_iv_12(numbers):
    runs = [r for panel in ("a", "b") for r in numbers[panel]]
    reached = sum(r["outcome"] == "reached" for r in runs)
    slowest = max(r["final_speed_mps"] for r in runs)
    return (reached == len(runs) and slowest < 0.15,
            f"{reached} of {len(runs)} goals reached; speed at arrival at most {slowest:.2f} m/s")


def _fig_iv_13(numbers):
    ok = numbers["outcome"] == "reached" and numbers["max_speed_mps"] >= 3.0 and numbers["final_speed_mps"] < 0.15
    return ok, (f"{numbers['outcome']} in {numbers['time_s']:.1f} s; first steering "
                f"{math.degrees(numbers['first_steering_rad']):.0f}° (left); top speed {numbers['max_speed_mps']:.2f} m/s; "
                f"speed at the goal {numbers['final_speed_mps']:.2f} m/s")


def _fig_iv_15(numbers):
    ok, text = _all_reached(("fig-IV-15a", "fig-IV-15b"))(numbers)
    changes = [numbers[n]["behaviour_changes"] for n in ("fig-IV-15a", "fig-IV-15b")]
    return ok and min(changes) >= 2, f"{text}; behaviour switches {changes[0]} and {changes[1]}"


def _wall_follower(numbers):
    bend, corner = numbers["fig-VI-27"]["outcome"], numbers["fig-VI-28"]["outcome"]
    return bend != "collision" and corner == "collision", f"bend (Fig VI.27): {bend}; sharp corner (Fig VI.28): {corner}"


def _eval_iv(numbers):
    two, five = numbers["fuzzy-2b-thesis/circles"], numbers["fuzzy-5b-thesis/mixed"]
    ok = two["success_rate"] >= 0.9 and five["success_rate"] >= 0.9 and five["collision_rate"] == 0
    return ok, (f"fuzzy-2b-thesis on {two['n']} circle worlds: {two['success_rate']:.0%} success, "
                f"{two['collision_rate']:.0%} collisions; fuzzy-5b-thesis on {five['n']} mixed worlds: "
                f"{five['success_rate']:.0%} success, {five['collision_rate']:.0%} collisions")


def _fig_v_7(numbers):
    low, high = numbers["alpha_min_rad"], numbers["alpha_max_rad"]
    ok = math.isclose(low, -math.pi / 4, abs_tol=1e-9) and math.isclose(high, math.pi / 4, abs_tol=1e-9)
    return ok, f"α from {math.degrees(low):.1f}° to {math.degrees(high):.1f}°"


def _star_lines(numbers):
    lines = numbers["lines"]
    done = sum(bool(r["completed"]) for r in lines.values())
    return (done == len(lines),
            f"{done} of {len(lines)} lines completed; worst max cross-track error {_m(numbers['worst_max_cross_track_m'])}")


def _polygon_paths(numbers):
    parts, ok = [], True
    for name in ("path-n", "path-trapezoid"):
        thesis, ours = numbers[name]["thesis"], numbers[name]["anticipation"]
        ok &= bool(thesis["completed"] and ours["completed"])
        parts.append(f"{name}: max cross-track {_m(thesis['max_cross_track_m'])} as in the thesis, "
                     f"{_m(ours['max_cross_track_m'])} with corner anticipation")
    return ok, "; ".join(parts)


def _training(numbers):
    rmse = numbers["validation_rmse_rad"]
    return rmse <= 1e-3, f"validation RMSE {rmse:.2e} rad, largest error {numbers['validation_max_error_rad']:.2e} rad"


TRACKERS = {"fuzzy-tracker": "CF", "neural-tracker": "CN", "anfis-tracker": "CNF"}


def _fig_v_28(numbers):
    error = {key: numbers[key]["max_cross_track_m"] for key in TRACKERS}
    ok = all(numbers[key]["completed"] for key in TRACKERS) and max(error["neural-tracker"],
                                                                    error["anfis-tracker"]) < error["fuzzy-tracker"]
    return ok, "max cross-track error " + ", ".join(f"{TRACKERS[k]} {_m(v)}" for k, v in error.items())


def _captured(*panels: str) -> Callable[[dict], Verdict]:
    def test(numbers):
        groups = {panel: numbers[panel] for panel in panels} if panels else {"": numbers}
        parts, ok = [], True
        for panel, runs in groups.items():
            for key, short in TRACKERS.items():
                r = runs[key]
                ok &= bool(r["captured"])
                when = f"captured at {r['capture_time_s']:.1f} s" if r["captured"] else "not captured"
                parts.append(f"{panel + ' ' if panel else ''}{short} {when}")
        return ok, "; ".join(parts)
    return test


def _learned_goal(success: float | None = 0.95) -> Callable[[dict], Verdict]:
    """Steering converged within the budget, and the learned controller reaches ``success`` of the
    random goals — or, for a fixed start (``success=None``), its own goal."""
    def test(numbers):
        budget = numbers.get("episodes", {})
        steering = numbers["converged_at"]["steering"]
        text = "; ".join(f"{phase}: {_converged(value, budget.get(phase))}"
                         for phase, value in numbers["converged_at"].items())
        ok = steering is not None and steering <= budget.get("steering", steering)
        evaluation = numbers.get("evaluation")
        if success is None:
            ok &= all(outcome == "reached" for outcome in numbers["trajectories"])
            text += f"; trajectory after learning: {', '.join(numbers['trajectories'])}"
            if evaluation:
                text += (f" (from {evaluation['runs']} random starts, not asserted — it learned one route: "
                         f"{evaluation['success']:.0%} reached)")
        else:
            ok &= evaluation["success"] >= success
            text += f"; learned controller reaches {evaluation['success']:.0%} of {evaluation['runs']} random goals"
        return ok, text
    return test


def _table_vi_1(numbers):
    parts, ok = [], True
    for row in numbers["rows"]:
        value = row["episodes_to_converge"]
        ok &= value is not None and row["success"] >= 0.85
        parts.append(f"{row['states']} × {row['actions']}: {_converged(value, row.get('episodes'))} "
                     f"(thesis {row['thesis_episodes']}), {row['success']:.0%} success")
    return ok, "; ".join(parts)


def _fig_vi_22(numbers):
    ok, text = _learned_goal(0.9)(numbers)
    collisions = numbers["evaluation"]["collisions"]
    return ok and collisions == 0, f"{text}, {collisions} collisions"


def _fig_vi_24(numbers):
    runs = {key: value for key, value in numbers.items() if isinstance(value, dict)}
    ok = all(r["outcome"] == "reached" for r in runs.values())
    return ok, "; ".join(f"{key}: {r['outcome']}, {r['evaluation']['success']:.0%} success and "
                         f"{r['evaluation']['collisions']} collisions on {r['evaluation']['runs']} random worlds"
                         for key, r in runs.items())


def _fig_vi_29(numbers):
    evaluation = numbers["evaluation"]
    handmade, learned = evaluation["wall-follow"], evaluation["fql-wall"]
    ok = handmade["fig-VI-28"] == "collision" and learned["fig-VI-28"] != "collision"
    return ok, (f"Fig VI.28 corners: hand-made {handmade['fig-VI-28']}, FQL-optimised {learned['fig-VI-28']}; "
                f"collisions on {learned['courses']} random wall courses: hand-made {handmade['collisions']}, "
                f"FQL-optimised {learned['collisions']}")


_PURSUIT = "The robot (start (4, 4), heading 0) pursues a target that starts at (4, 12)"
_TRACK = ("All three trackers capture the target.", _captured())

CLAIMS: dict[str, Claim] = {
    "fig-IV-12": Claim(
        "From any start the robot turns towards the goal with a large steering angle and a low speed, "
        "speeds up to about 3.5 m/s once aligned and far, and slows to zero at the goal (§IV.6.1, Table IV.1).",
        "All ten start/goal pairs are reached and the speed at arrival is below 0.15 m/s.", _fig_iv_12),
    "fig-IV-13": Claim(
        "A positive maximal steering turns the robot left towards the goal; the speed rises to about "
        "3.5–4 m/s and falls to zero at the goal (Figs IV.13–IV.14).",
        "The goal is reached, the top speed is at least 3 m/s and the speed at the goal below 0.15 m/s.",
        _fig_iv_13),
    "fig-IV-15": Claim(
        "Goal seeking plus obstacle avoidance (Table IV.2): from S1 the robot passes four obstacles, switching "
        "behaviour at the points A…H, and reaches G1 slowing down (Fig IV.15).",
        "Both worlds are reached without contact, with at least two behaviour switches each.", _fig_iv_15),
    "fig-IV-22": Claim(
        "The five-behaviour navigator reaches its goal in unknown cluttered worlds of any obstacle shape (Fig IV.22).",
        "Both worlds are reached without contact.", _all_reached(("fig-IV-22a", "fig-IV-22b"))),
    "fig-IV-23": Claim(
        "A goal inside a U-shaped wall is reached by following the wall (Fig IV.23).",
        "The goal is reached without contact.", _all_reached(("fig-IV-23",))),
    "fig-VI-28": Claim(
        "The hand-made fuzzy wall follower (Table VI.2) follows walls but collides at sharp corners (Figs VI.27–VI.28).",
        "The bend is followed without collision and the sharp corner is hit.", _wall_follower),
    "eval-IV": Claim(
        "The chapter IV navigators reach their goals in worlds they do not know (§IV.6–IV.7); the thesis gives no "
        "rates.",
        "This package's targets: fuzzy-2b-thesis ≥ 90 % success on circle worlds; fuzzy-5b-thesis ≥ 90 % success with no "
        "collision on mixed worlds.", _eval_iv),
    "fig-V-7": Claim(
        "The control surface of the 25-rule fuzzy tracker (Table V.1) spans the steering range ±π/4 (Fig V.7).",
        "The surface spans exactly −45° … +45°.", _fig_v_7),
    "fig-V-10": Claim(
        "The fuzzy tracker CF follows six straight lines leaving (10, 10) in all directions, the robot heading 0 "
        "(§V.3.1, Fig V.10).", "Every line is completed.", _star_lines),
    "fig-V-11": Claim(
        "CF tracks the N-shaped and trapezoidal paths; the error appears at the direction changes (Fig V.11).",
        "Both paths are completed.", _polygon_paths),
    "fig-V-15": Claim(
        "The neural inverse model (MLP, tanh, generalized learning) is validated on about 100 unseen pairs "
        "(§V.3.2, Fig V.15).", "Validation RMSE ≤ 1e-3 rad.", _training),
    "fig-V-18": Claim("The neural tracker CN follows the six straight lines from (10, 10) (Fig V.18).",
                      "Every line is completed.", _star_lines),
    "fig-V-19": Claim("CN tracks the N-shaped and trapezoidal paths (Fig V.19).", "Both paths are completed.",
                      _polygon_paths),
    "fig-V-23": Claim("ANFIS hybrid learning (Table V.2) reaches a training error of about 1e-3 (Fig V.23).",
                      "Validation RMSE ≤ 1e-3 rad.", _training),
    "fig-V-26": Claim("The ANFIS tracker CNF follows the six straight lines from (10, 10) (Fig V.26).",
                      "Every line is completed.", _star_lines),
    "fig-V-27": Claim("CNF tracks the N-shaped and trapezoidal paths (Fig V.27).", "Both paths are completed.",
                      _polygon_paths),
    "fig-V-28": Claim(
        "On the V path the error of CF, CN and CNF appears at the direction change and is smallest for CN and CNF "
        "(§V.4, Fig V.28).", "All three complete the path; CN and CNF have a smaller max cross-track error than CF.",
        _fig_v_28),
    "fig-V-29": Claim(f"{_PURSUIT} moving on a straight line; CF, CN and CNF all reach it (§V.5, Fig V.29).", *_TRACK),
    "fig-V-30": Claim(f"{_PURSUIT} moving on a circle; CF, CN and CNF all reach it (Fig V.30).", *_TRACK),
    "fig-V-31": Claim(f"{_PURSUIT} moving on a sinusoid; CF, CN and CNF all reach it (Fig V.31).", *_TRACK),
    "fig-V-32": Claim("A target on a straight line is caught by CF, CN and CNF; their trajectories compared near "
                      "the capture (§V.5.1, Fig V.32).", *_TRACK),
    "fig-V-33": Claim("Targets on two other straight lines are caught by the three controllers (Fig V.33).",
                      "All three trackers capture both targets.", _captured("fig-V-33a", "fig-V-33b")),
    "fig-V-34": Claim("A circular and a sinusoidal target are caught by the three controllers (Fig V.34).",
                      "All three trackers capture both targets.", _captured("fig-V-34a", "fig-V-34b")),
    "fig-VI-1": Claim(
        "Tabular Q-learning (reward VI.2) from a fixed start converges around episode 1,000 (Figs VI.1–VI.2).",
        "The learning curve converges within the budget and the learned route reaches the goal.", _learned_goal(None)),
    "fig-VI-4": Claim(
        "With random starts and goals the tabular learner converges after about 3,500 episodes (Figs VI.3–VI.4).",
        "The curve converges within the budget; the learned controller reaches ≥ 95 % of random goals.",
        _learned_goal()),
    "table-VI-1": Claim(
        "Episodes to converge grow with the state space: 9 states × 3 actions 3,260; 11 × 3 4,100; 13 × 3 6,200; "
        "19 × 5 8,950 (Table VI.1).",
        "Every size converges within the budget and reaches ≥ 85 % of random goals.", _table_vi_1),
    "fig-VI-8": Claim(
        "Fuzzy Q-learning with 15 rules × 3 conclusions from a fixed start converges by about episode 180 "
        "(Figs VI.7–VI.8).", "Steering converges within the budget and the learned route reaches the goal.",
        _learned_goal(None)),
    "fig-VI-9": Claim(
        "With random starts, FQL (15 rules) learns the steering in about 3,000 episodes, then the speed in about 900 "
        "(Figs VI.9–VI.10).",
        "Steering converges within the budget; the learned controller reaches ≥ 95 % of random goals.",
        _learned_goal()),
    "fig-VI-13": Claim(
        "On the chapter IV partition, 35 rules × 5 conclusions, learning is slower: about 5,000 episodes "
        "(Figs VI.13–VI.14).",
        "Steering converges within the budget; the learned controller reaches ≥ 95 % of random goals.",
        _learned_goal()),
    "fig-VI-16": Claim(
        "Eligibility traces speed FQL up: about 1,400 episodes (Figs VI.15–VI.16).",
        "Steering converges within the budget; the learned controller reaches ≥ 95 % of random goals.",
        _learned_goal()),
    "fig-VI-22": Claim(
        "FQL obstacle avoidance (8 rules, rewards VI.20–VI.21) collides in early episodes, converges by about "
        "episode 250 (steering) and 2,000 (speed), and then reaches goals past obstacles (Figs VI.18–VI.22).",
        "Steering converges within the budget; the learned navigator reaches ≥ 90 % of random obstacle worlds "
        "without collision.", _fig_vi_22),
    "fig-VI-24": Claim(
        "The chapter IV fuzzy navigator and the FQL navigator both reach the goal in the same world "
        "(Figs VI.23–VI.24).", "Both reach the goal of the world shown.", _fig_vi_24),
    "fig-VI-29": Claim(
        "After FQL optimisation of Table VI.2 the wall follower no longer collides and follows walls of various "
        "shapes (Figs VI.29–VI.30).",
        "At the corners of Fig VI.28 the hand-made follower collides and the FQL-optimised one does not.",
        _fig_vi_29),
}
