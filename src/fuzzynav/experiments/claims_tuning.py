"""``cmp-VI-tuning``, the comparison the thesis leaves as a perspective (its conclusion), with its claim.

The thesis gives no number to reproduce here: it proposes comparing its methods with genetic
algorithms and optimising fuzzy controllers by ant colonies. The checks are this package's
targets (``source="package"``): on held-out worlds, every tuner and fuzzy Q-learning, averaged
over the seeds, succeed at least as often as the hand-made system they start from (or, for FQL,
replace) and collide no more often. For wall following, success is following: lasting the
episode without a collision at a mean speed of at least half of P
(:func:`fuzzynav.experiments.tuning.held_out_wall`), and a follower must also keep at least
:data:`WALL_SPEED_SHARE` of the hand-made one's mean speed on every seed (the slowest seed is
checked, not the mean, which one creeping seed among fast ones would pass): lasting by creeping
along the wall is not following it.
"""

from __future__ import annotations

from fuzzynav.catalog.experiments import Experiment
from fuzzynav.experiments.claims import Check, Claim

WALL_SPEED_SHARE = 0.5


def _no_worse_than_hand_made(numbers) -> list[Check]:
    checks = []
    for name, task in numbers["tasks"].items():
        rows = task["rows"]
        base = rows["hand-made"][0]
        for method, seeds in rows.items():
            if method == "hand-made":
                continue
            success = sum(s["success"] for s in seeds) / len(seeds)
            collisions = sum(s["collisions"] for s in seeds) / len(seeds)
            checks.append(Check(f"{name}, {method}: held-out success (mean of {len(seeds)} seeds)", success,
                                f"≥ hand-made {base['success']:.3f}", success >= base["success"], "package"))
            checks.append(Check(f"{name}, {method}: held-out collisions (mean per seed)", collisions,
                                f"≤ hand-made {base['collisions']}", collisions <= base["collisions"], "package"))
            if name == "wall":
                speed = min(s["mean_speed_mps"] for s in seeds)
                floor = WALL_SPEED_SHARE * base["mean_speed_mps"]
                checks.append(Check(f"{name}, {method}: held-out mean speed, m/s (slowest of {len(seeds)} seeds)",
                                    speed, f"≥ {WALL_SPEED_SHARE:g} × hand-made {base['mean_speed_mps']:.2f}",
                                    speed >= floor, "package"))
    return checks


EXPERIMENTS = [
    Experiment("cmp-VI-tuning", "fuzzynav.experiments.tuning:cmp_vi_tuning",
               "GA, PSO and ant colony tuning against fuzzy Q-learning, same episodes, every seed",
               "Conclusion, perspectives; Tables IV.1, IV.2, VI.2; §VI.5.1–VI.5.3",
               Claim("Perspectives: compare the methods developed with other stochastic algorithms such as "
                     "genetic algorithms, and optimise fuzzy controllers by ant colony algorithms (no numbers given).",
                     "With the same episodes, tuning Table IV.1 (goal seeking), Table IV.2 (obstacle avoidance) "
                     "and Table VI.2 (wall following) by GA, PSO and ACO, and training FQL, each does at least as "
                     "well as the hand-made table on held-out worlds (success — for wall following, lasting the "
                     "episode without collision at least at half of P — and collisions; mean over the seeds); a wall "
                     "follower also keeps "
                     "at least half the hand-made one's mean speed on every seed.",
                     _no_worse_than_hand_made)),
]
