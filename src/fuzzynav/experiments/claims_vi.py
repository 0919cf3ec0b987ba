"""Chapter VI's experiments (Q-learning and fuzzy Q-learning, §VI.2 and §VI.5) with the thesis'
claim of each, checked on the numbers of :mod:`fuzzynav.experiments.chapter6`.

Every run follows the thesis' protocol (one robot, episodes one by one, q = 0 at start, the
conclusion of best quality; :data:`fuzzynav.learn.tasks.common.THESIS`). A check marked
``thesis`` states what the French text says (its numbers are approximate readings of curves:
"à partir de l'épisode 250"); ``package`` checks are targets the thesis does not give (success
rates over 100 or 300 random worlds, a fifth of the hand-made follower's collisions). A run that did
not converge within its budget reports ``None`` and fails the checks that need convergence.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.catalog.experiments import Experiment
from fuzzynav.experiments.claims import Check, Claim

MODULE = "fuzzynav.experiments.chapter6"
STOPPED = 0.9  # share of runs that must reach their goal at ≤ 0.2 m/s
RANK = 0.8  # Spearman's ρ of Table VI.1: increasing up to one swap of neighbours (4 sizes)


def _converged(phase: str, numbers, source: str = "thesis") -> Check:
    value, budget = numbers["converged_at"][phase], numbers.get("episodes", {}).get(phase)
    return Check(f"{phase}: episodes to converge", value, f"within the budget ({budget} episodes)",
                 value is not None and (budget is None or value <= budget), source)


def _episodes(value, budget) -> float:
    """Episodes to converge for a comparison: a run that did not converge counts as budget + 1."""
    return budget + 1 if value is None else value


def _slower(name: str, slow: tuple, fast: tuple) -> Check:
    """``slow`` (converged_at, budget) needs more episodes than ``fast``; both unconverged fails."""
    passed = not (slow[0] is None and fast[0] is None) and _episodes(*slow) > _episodes(*fast)
    return Check(name, {"slower": slow[0], "faster": fast[0]}, "the first converges later than the second", passed)


# The relative claims of §VI.5.1.1: per id, its name and the (converged_at, budget) of the arm the
# thesis says is slower, then of the faster one, read from the id's numbers.
RELATIVE = {
    "fig-VI-8": ("tabular Q-learning (Fig VI.1) slower than FQL from the same start, same ε and β",
                 lambda n: (n["q_learning"]["converged_at"], n["q_learning"]["episodes"]),
                 lambda n: (n["converged_at"]["steering"], n["episodes"]["steering"])),
    "fig-VI-13": ("35 rules × 5 slower than 15 rules × 3 (steering)",
                  lambda n: (n["converged_at"]["steering"], n["episodes"]["steering"]),
                  lambda n: (n["rules_15"]["converged_at"], n["rules_15"]["episodes"])),
    "fig-VI-16": ("FQL without traces slower than with traces (steering)",
                  lambda n: (n["no_traces"]["converged_at"], n["no_traces"]["episodes"]),
                  lambda n: (n["converged_at"]["steering"], n["episodes"]["steering"])),
}


def _relative(key: str, numbers) -> Check:
    name, slow, fast = RELATIVE[key]
    return _slower(name, slow(numbers), fast(numbers))


def relative_over_seeds(key: str, runs: list[dict]) -> Check:
    """The relative claim of ``key`` (:data:`RELATIVE`) over several seeds' numbers: the median
    episodes to converge of the slower arm (a run that did not converge counts as its budget + 1)
    exceeds the faster arm's. The value lists both arms per seed and their medians."""
    name, slow, fast = RELATIVE[key]
    arms = [(slow(numbers), fast(numbers)) for numbers in runs]
    medians = [float(np.median([_episodes(*arm[k]) for arm in arms])) for k in (0, 1)] if arms else []
    return Check(f"{name}, median of {len(arms)} seeds",
                 {"slower": [arm[0][0] for arm in arms], "faster": [arm[1][0] for arm in arms],
                  "medians": medians},
                 "the first's median exceeds the second's", bool(medians) and medians[0] > medians[1])


def _success(numbers, bound: float = 0.95) -> Check:
    evaluation = numbers["evaluation"]
    return Check(f"success on {evaluation['runs']} random goals", evaluation["success"], f"≥ {bound:g}",
                 evaluation["success"] >= bound, "package")


def _learned_goal(success: float | None = 0.95):
    """Steering converged within the budget, and the learned controller reaches ``success`` of the
    random goals — or, for a fixed start (``success=None``), its own goal."""
    def test(numbers):
        checks = [_converged("steering", numbers)]
        if success is None:
            outcomes = numbers["trajectories"]
            checks.append(Check("trajectory after learning", outcomes, "reached",
                                all(outcome == "reached" for outcome in outcomes)))
        else:
            checks.append(_success(numbers, success))
        return checks
    return test


def _table_vi_1(numbers):
    rho = numbers["rank_correlation"]
    checks = [Check("rank correlation of episodes to converge with state–action pairs (Spearman ρ)", rho,
                    f"≥ {RANK:g} (thesis: 1, 3,260 < 4,100 < 6,200 < 8,950)", rho is not None and rho >= RANK)]
    for row in numbers["rows"]:
        size = f"{row['states']} × {row['actions']}"
        value = row["episodes_to_converge"]
        checks.append(Check(f"{size}: episodes to converge (thesis {row['thesis_episodes']})", value,
                            f"within {row['episodes']} episodes", value is not None))
        checks.append(Check(f"{size}: success on random goals", row["success"], "≥ 0.85", row["success"] >= 0.85,
                            "package"))
    return checks


def _fig_vi_8(numbers):
    return _learned_goal(None)(numbers) + [_relative("fig-VI-8", numbers)]


def _fig_vi_9(numbers):
    evaluation, curve = numbers["evaluation"], numbers["curve"]["speed"]
    return [_converged("steering", numbers),
            Check("speed phase: mean reinforcement, first → last tenth of the episodes", curve,
                  "rises (last > first)", curve["last"] > curve["first"]),
            Check(f"runs reaching the goal at ≤ 0.2 m/s (of {evaluation['runs']})", evaluation["stopped"],
                  f"≥ {STOPPED:g} (the robot stops at the goal)", evaluation["stopped"] >= STOPPED),
            _success(numbers)]


def _fig_vi_13(numbers):
    return [_converged("steering", numbers), _relative("fig-VI-13", numbers), _success(numbers)]


def _fig_vi_16(numbers):
    return [_converged("steering", numbers), _relative("fig-VI-16", numbers), _success(numbers)]


def _fig_vi_22(numbers):
    evaluation, initial = numbers["evaluation"], numbers["initial_table"]
    return [Check("collisions in training episodes 1–20 (Figs VI.18–VI.19)", numbers["collisions_first_20"], "≥ 1",
                  numbers["collisions_first_20"] >= 1),
            _converged("steering", numbers),
            Check("after learning, along a wall to its goal (Fig VI.21)", numbers["wall_following"], "reached",
                  numbers["wall_following"] == "reached"),
            Check("rules that differ from the initial table (q = 0)", numbers["rules_changed"],
                  f"≥ 1 of {numbers['rules_learned']}", numbers["rules_changed"] >= 1, "package"),
            Check(f"success on {evaluation['runs']} random obstacle worlds", evaluation["success"], "≥ 0.9",
                  evaluation["success"] >= 0.9, "package"),
            Check("collisions on the random worlds", evaluation["collisions"], "= 0", evaluation["collisions"] == 0,
                  "package"),
            Check("success of the initial table on the same worlds", initial["success"],
                  f"< the learned navigator's {evaluation['success']:g}", initial["success"] < evaluation["success"],
                  "package")]


def _fig_vi_24(numbers):
    runs = {key: value for key, value in numbers.items() if isinstance(value, dict)}
    return [Check(f"{key}: outcome on {numbers['world']} (straight route blocked)", run["outcome"], "reached",
                  run["outcome"] == "reached") for key, run in runs.items()]


def _fig_vi_29(numbers):
    corners, evaluation = numbers["corners"], numbers["evaluation"]
    handmade, learned = evaluation["wall-follow"]["collisions"], evaluation["fql-wall"]["collisions"]
    return [Check("hand-made follower at the corners of Fig VI.28", corners["wall-follow"], "collision at every one",
                  all(o == "collision" for o in corners["wall-follow"].values())),
            Check("FQL-optimised follower at the same corners", corners["fql-wall"],
                  "goal along the wall reached at every one (a collision or a timeout fails)",
                  all(o == "reached" for o in corners["fql-wall"].values())),
            Check(f"collisions on {evaluation['fql-wall']['courses']} random wall courses, learned vs hand-made",
                  {"fql-wall": learned, "wall-follow": handmade}, "learned ≤ hand-made / 5",
                  5 * learned <= handmade and handmade > 0, "package")]


def _spec(key: str, description: str, reference: str, thesis: str, asserted: str, test, **extra) -> Experiment:
    return Experiment(key, f"{MODULE}:{key.lower().replace('-', '_')}", description, reference,
                      Claim(thesis, asserted, test), **extra)


_GOAL = "Steering converges within the budget; the learned controller reaches ≥ 95 % of random goals."

EXPERIMENTS = [
    _spec("fig-VI-1", "tabular Q-learning goal seeking, fixed start: curve and trajectory", "§VI.2, Figs VI.1–VI.2",
          "Tabular Q-learning (reward VI.2) from a fixed start converges around episode 1,000.",
          "The learning curve converges within the budget and the learned route reaches the goal.",
          _learned_goal(None)),
    _spec("fig-VI-4", "tabular Q-learning, random starts: curve and trajectories", "§VI.2, Figs VI.3–VI.4",
          "With random starts and goals the tabular learner converges after about 3,500 episodes.", _GOAL,
          _learned_goal()),
    _spec("table-VI-1", "episodes to converge for 9/11/13/19 states", "§VI.2, Table VI.1",
          "More state–action pairs need more episodes to converge: 9 states × 3 actions 3,260; 11 × 3 4,100; "
          "13 × 3 6,200; 19 × 5 8,950.",
          f"With 10,000 episodes per size, the episodes to converge rank with the state–action pairs (Spearman "
          f"ρ ≥ {RANK:g}), every size converges and reaches ≥ 85 % of random goals.", _table_vi_1, position=4.5),
    _spec("fig-VI-8", "FQL 15 rules, fixed start, beside tabular Q-learning", "§VI.5.1.1, Figs VI.7–VI.8",
          "Fuzzy Q-learning with 15 rules × 3 conclusions from a fixed start converges by about episode 180, "
          "faster than Q-learning (Fig VI.1: ~1,000).",
          "Steering converges within the budget, the learned route reaches the goal, and tabular Q-learning from "
          "the same start converges later.", _fig_vi_8),
    _spec("fig-VI-9", "FQL 15 rules, random starts, steering then speed", "§VI.5.1.1, Figs VI.9–VI.10",
          "With random starts, FQL (15 rules) learns the steering in about 3,000 episodes, then the speed in "
          "about 900; both curves improve, and the robot heads for the goal and stops when it reaches it.",
          f"Steering converges; the speed phase's reinforcement rises; ≥ {STOPPED:.0%} of 100 random runs reach "
          "the goal at ≤ 0.2 m/s; ≥ 95 % reach it.", _fig_vi_9),
    _spec("fig-VI-13", "FQL 35 rules x 5 conclusions, beside 15 rules", "§VI.5.1.1, Figs VI.13–VI.14",
          "On the chapter IV partition, 35 rules × 5 conclusions, learning is slower than with 15 rules: about "
          "5,000 episodes.",
          "Steering converges, later than the 15 rules' steering (same seed); ≥ 95 % of random goals reached.",
          _fig_vi_13),
    _spec("fig-VI-16", "FQL with eligibility traces, beside FQL without", "§VI.5.1.1, Figs VI.15–VI.16",
          "Eligibility traces speed FQL up: about 1,400 episodes, against ~3,000 without (Fig VI.9).",
          "Steering with traces converges, earlier than without (same seed); ≥ 95 % of random goals reached.",
          _fig_vi_16),
    _spec("fig-VI-22", "FQL obstacle avoidance from q = 0: episodes 1 and 20, curves, wall following",
          "§VI.5.2, Figs VI.18–VI.22",
          "FQL obstacle avoidance (8 rules, q = 0 at start, rewards VI.20–VI.21) collides in early episodes "
          "(episodes 1 and 20), converges from about episode 250 (steering) and 2,000 (speed); the conclusions of "
          "best quality then avoid obstacles and follow walls to reach a goal (Fig VI.21).",
          "From q = 0: a collision in the first 20 training episodes, steering converges, the learned navigator "
          "follows a wall to its goal, differs from and beats its initial table, and reaches ≥ 90 % of 300 random "
          "obstacle worlds with no collision.", _fig_vi_22),
    _spec("fig-VI-24", "chapter IV navigator vs FQL navigator on a world where both must avoid",
          "§VI.5.2.1, Figs VI.23–VI.24",
          "On the same world the chapter IV fuzzy navigator and the FQL navigator both avoid the obstacle and "
          "reach the goal; the FQL one reacts very satisfactorily.",
          "Both reach the goal of a world whose straight route is blocked.", _fig_vi_24),
    _spec("fig-VI-29", "hand-made vs FQL-optimised wall follower: two corners, 100 wall courses",
          "§VI.5.3.2, Figs VI.28–VI.30",
          "The hand-made follower of Table VI.2 collides at sharp corners (Fig VI.28 a–b); after FQL optimisation "
          "of its interpretations the robot moves without collision and follows walls of various shapes, "
          "satisfactorily in all the cases shown.",
          "At both corners the hand-made follower collides and the learned one follows the wall round to the goal; "
          "on 100 random courses the learned one collides on at most a fifth as many.", _fig_vi_29),
]
