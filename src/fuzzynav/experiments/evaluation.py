"""A controller over many generated worlds: success, collision and timeout rates (issue 3).

:func:`evaluate` runs one episode per world of :func:`fuzzynav.world.generate.generate_worlds`
and summarises them: ``success_rate``, ``collision_rate``, ``timeout_rate`` (fractions of the
``n`` worlds), ``mean_time_s`` and ``mean_path_length_m`` over the successful episodes, plus the
per-world outcomes. ``fuzzynav evaluate`` prints it.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from fuzzynav.control.registry import make_controller
from fuzzynav.sim import metrics, run_episode
from fuzzynav.world.generate import generate_worlds


def evaluate(controller: str, worlds: str = "mixed", n: int = 100, seed: int = 0,
             progress: Callable[[int, dict], None] | None = None) -> dict:
    """Run the registered ``controller`` on ``n`` seeded worlds of family ``worlds``."""
    scenarios = generate_worlds(worlds, n, seed)
    runs = []
    for i, scenario in enumerate(scenarios):
        numbers = metrics(run_episode(scenario, make_controller(controller), seed=seed), scenario)
        runs.append({key: numbers[key] for key in ("scenario", "outcome", "time_s", "path_length_m",
                                                    "min_clearance_m")})
        if progress is not None:
            progress(i, runs[-1])
    outcomes = np.array([r["outcome"] for r in runs])
    reached = outcomes == "reached"
    rate = lambda name: float(np.mean(outcomes == name))
    return {
        "controller": controller,
        "worlds": worlds,
        "n": int(n),
        "seed": int(seed),
        "success_rate": rate("reached"),
        "collision_rate": rate("collision"),
        "timeout_rate": rate("timeout"),
        "mean_time_s": float(np.mean([r["time_s"] for r, ok in zip(runs, reached) if ok])) if reached.any() else None,
        "mean_path_length_m": (float(np.mean([r["path_length_m"] for r, ok in zip(runs, reached) if ok]))
                               if reached.any() else None),
        "episodes": runs,
    }
