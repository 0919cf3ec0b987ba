"""A controller over many generated worlds: success, collision and timeout rates (issue 3).

:func:`evaluate` runs one episode per world of :func:`fuzzynav.world.generate.generate_worlds`
and summarises them: ``success_rate``, ``collision_rate``, ``timeout_rate`` (fractions of the
``n`` worlds), ``mean_time_s`` and ``mean_path_length_m`` over the successful episodes, plus the
per-world outcomes. ``fuzzynav evaluate`` prints it. The controller is a registered name or a
trained model file (``model``, built by :func:`fuzzynav.models.load_controller`).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from fuzzynav.control.registry import make_controller
from fuzzynav.errors import InputError
from fuzzynav.robot.sensors import named_ring
from fuzzynav.sim import metrics, run_episode
from fuzzynav.world.generate import generate_worlds


def evaluate(controller: str | None = None, worlds: str = "mixed", n: int = 100, seed: int = 0,
             progress: Callable[[int, dict], None] | None = None, *, model: str | Path | None = None,
             sensors: str | None = None) -> dict:
    """Run the registered ``controller`` — or the one stored in the ``model`` file — on ``n``
    seeded worlds of family ``worlds``, with the sensor ring named ``sensors`` (default: the
    controller's, :func:`fuzzynav.sim.simulator.default_ring`).

    A model is loaded once; every episode starts from the simulator's ``reset(rng)`` of it, as a
    registered controller is built afresh per world.
    """
    if (controller is None) == (model is None):
        raise InputError("give exactly one of a controller name and a model file", field="controller")
    if model is not None:
        from fuzzynav.models import load_controller

        loaded = load_controller(model)
        build, controller = (lambda: loaded), loaded.name
    else:
        build = lambda: make_controller(controller)
    ring = None if sensors is None else named_ring(sensors)
    scenarios = generate_worlds(worlds, n, seed)
    runs = []
    for i, scenario in enumerate(scenarios):
        numbers = metrics(run_episode(scenario, build(), seed=seed, sensors=ring), scenario)
        runs.append({key: numbers[key] for key in ("scenario", "outcome", "time_s", "path_length_m",
                                                    "min_clearance_m")})
        if progress is not None:
            progress(i, runs[-1])
    outcomes = np.array([r["outcome"] for r in runs])
    reached = outcomes == "reached"
    rate = lambda name: float(np.mean(outcomes == name))
    return {
        "controller": controller,
        "model": None if model is None else str(model),
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
