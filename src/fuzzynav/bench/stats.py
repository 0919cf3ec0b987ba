"""Per controller × suite: outcome rates with 95 % Wilson intervals, medians, the BARN score (true
optimal path) and the challenge's own (:mod:`fuzzynav.bench.measures`).

E. B. Wilson, *Probable inference, the law of succession, and statistical inference*, JASA
22(158), 1927: for k successes in n trials, p̂ = k/n and z = 1.96, the interval is
(p̂ + z²/2n ± z √(p̂(1 − p̂)/n + z²/4n²)) / (1 + z²/n) — unlike the normal approximation it stays
inside [0, 1] and is not empty at 0 % or 100 %.
"""

from __future__ import annotations

import math
import statistics

from fuzzynav.sim.trace import OUTCOMES

Z95 = 1.959963984540054


def wilson(k: int, n: int, z: float = Z95) -> tuple[float, float]:
    """The Wilson score interval of ``k`` successes in ``n`` trials (module docstring)."""
    if n == 0:
        return (0.0, 1.0)
    p = k / n
    centre = p + z * z / (2 * n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    scale = 1 + z * z / n
    return (max(0.0, (centre - half) / scale), min(1.0, (centre + half) / scale))


def rate(outcomes: list[str], outcome: str) -> float:
    """The share of ``outcomes`` (one a run) that are ``outcome``."""
    return sum(found == outcome for found in outcomes) / len(outcomes)


def _median(values) -> float | None:
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def summarise(rows: list[dict]) -> list[dict]:
    """One record per (suite, controller), in the order they first appear in ``rows``."""
    groups: dict[tuple, list[dict]] = {}
    for row in rows:
        groups.setdefault((row["suite"], row["controller"]), []).append(row)
    records = []
    for (suite, controller), runs in groups.items():
        n = len(runs)
        record = {"suite": suite, "controller": controller, "runs": n}
        outcomes = [run["outcome"] for run in runs]
        for outcome in OUTCOMES:
            k = outcomes.count(outcome)
            low, high = wilson(k, n)
            record[outcome] = {"count": k, "rate": rate(outcomes, outcome), "ci95": [low, high]}
        k = sum(run.get("collision_by") == "robot" for run in runs)
        record["collision_at_fault"] = {"count": k, "rate": k / n, "ci95": list(wilson(k, n))}
        reached = [run for run in runs if run["outcome"] == "reached"]
        record["median_time_s"] = _median(run["time_s"] for run in reached)
        record["median_path_ratio"] = _median(run["path_ratio"] for run in reached)
        record["median_min_clearance_m"] = _median(run["min_clearance_m"] for run in runs)
        record["median_steering_effort_rad"] = _median(run["steering_effort_rad"] for run in runs)
        for key in ("barn_score", "barn_score_challenge"):
            scores = [run[key] for run in runs if run.get(key) is not None]
            record[f"mean_{key}"] = sum(scores) / len(scores) if scores else None
        records.append(record)
    return records
