"""Chapter VI's experiments (Q-learning and fuzzy Q-learning, §VI.2 and §VI.5) with the thesis'
claim of each."""

from __future__ import annotations

from fuzzynav.catalog.experiments import Experiment
from fuzzynav.experiments.claims import Check, Claim

MODULE = "fuzzynav.experiments.chapter6"


def _converged(phase: str, numbers) -> Check:
    value, budget = numbers["converged_at"][phase], numbers.get("episodes", {}).get(phase)
    return Check(f"{phase}: episodes to converge", value, f"within the budget ({budget} episodes)",
                 value is not None and (budget is None or value <= budget))


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
            evaluation = numbers["evaluation"]
            checks.append(Check(f"success on {evaluation['runs']} random goals", evaluation["success"],
                                f"≥ {success:g}", evaluation["success"] >= success, "package"))
        return checks
    return test


def _table_vi_1(numbers):
    checks = []
    for row in numbers["rows"]:
        size = f"{row['states']} × {row['actions']}"
        value = row["episodes_to_converge"]
        checks.append(Check(f"{size}: episodes to converge (thesis {row['thesis_episodes']})", value,
                            f"within {row['episodes']} episodes", value is not None))
        checks.append(Check(f"{size}: success on random goals", row["success"], "≥ 0.85", row["success"] >= 0.85,
                            "package"))
    return checks


def _fig_vi_22(numbers):
    collisions = numbers["evaluation"]["collisions"]
    return _learned_goal(0.9)(numbers) + [Check("collisions on the random worlds", collisions, "= 0",
                                                collisions == 0, "package")]


def _fig_vi_24(numbers):
    runs = {key: value for key, value in numbers.items() if isinstance(value, dict)}
    return [Check(f"{key}: outcome", run["outcome"], "reached", run["outcome"] == "reached")
            for key, run in runs.items()]


def _fig_vi_29(numbers):
    evaluation = numbers["evaluation"]
    handmade, learned = evaluation["wall-follow"], evaluation["fql-wall"]
    return [Check("hand-made follower at the Fig VI.28 corners", handmade["fig-VI-28"], "collision",
                  handmade["fig-VI-28"] == "collision"),
            Check("FQL-optimised follower at the Fig VI.28 corners", learned["fig-VI-28"], "no collision",
                  learned["fig-VI-28"] != "collision")]


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
          "Episodes to converge grow with the state space: 9 states × 3 actions 3,260; 11 × 3 4,100; "
          "13 × 3 6,200; 19 × 5 8,950.",
          "Every size converges within the budget and reaches ≥ 85 % of random goals.", _table_vi_1,
          position=4.5),
    _spec("fig-VI-8", "FQL 15 rules, fixed start", "§VI.5.1.1, Figs VI.7–VI.8",
          "Fuzzy Q-learning with 15 rules × 3 conclusions from a fixed start converges by about episode 180.",
          "Steering converges within the budget and the learned route reaches the goal.", _learned_goal(None)),
    _spec("fig-VI-9", "FQL 15 rules, random starts, steering then speed", "§VI.5.1.1, Figs VI.9–VI.10",
          "With random starts, FQL (15 rules) learns the steering in about 3,000 episodes, then the speed in "
          "about 900.", _GOAL, _learned_goal()),
    _spec("fig-VI-13", "FQL 35 rules x 5 conclusions", "§VI.5.1.1, Figs VI.13–VI.14",
          "On the chapter IV partition, 35 rules × 5 conclusions, learning is slower: about 5,000 episodes.",
          _GOAL, _learned_goal()),
    _spec("fig-VI-16", "FQL with eligibility traces", "§VI.5.1.1, Figs VI.15–VI.16",
          "Eligibility traces speed FQL up: about 1,400 episodes.", _GOAL, _learned_goal()),
    _spec("fig-VI-22", "FQL obstacle avoidance: curves and trajectories", "§VI.5.2, Figs VI.18–VI.22",
          "FQL obstacle avoidance (8 rules, rewards VI.20–VI.21) collides in early episodes, converges by about "
          "episode 250 (steering) and 2,000 (speed), and then reaches goals past obstacles.",
          "Steering converges within the budget; the learned navigator reaches ≥ 90 % of random obstacle worlds "
          "without collision.", _fig_vi_22),
    _spec("fig-VI-24", "chapter IV navigator vs FQL navigator on the same world", "§VI.5.2.1, Figs VI.23–VI.24",
          "The chapter IV fuzzy navigator and the FQL navigator both reach the goal in the same world.",
          "Both reach the goal of the world shown.", _fig_vi_24),
    _spec("fig-VI-29", "hand-made vs FQL-optimised wall follower: Fig VI.28 corners, wall courses",
          "§VI.5.3.2, Figs VI.28–VI.30",
          "After FQL optimisation of Table VI.2 the wall follower no longer collides and follows walls of various "
          "shapes.", "At the corners of Fig VI.28 the hand-made follower collides and the FQL-optimised one does not.",
          _fig_vi_29),
]
