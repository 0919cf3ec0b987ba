"""A controller over many generated worlds: success, collision and timeout rates (issue 3).

:func:`evaluate` runs one episode per world of :func:`fuzzynav.world.generate.generate_worlds`
and summarises them: ``success_rate``, ``collision_rate``, ``timeout_rate`` (fractions of the
``n`` worlds), ``mean_time_s`` and ``mean_path_length_m`` over the successful episodes, plus the
per-world outcomes. ``fuzzynav evaluate`` prints it. The controller is a registered name or a
trained model file (``model``, built by :func:`fuzzynav.models.load_controller`). With
``save_failures`` (a folder), each world not reached is written there as a scenario file with
the plot of its episode (:func:`save_failure`), so ``fuzzynav run FILE`` reruns it.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from fuzzynav import progress as progress_bars
from fuzzynav.control.registry import make_controller
from fuzzynav.errors import InputError
from fuzzynav.sim import metrics, run_episode
from fuzzynav.world.generate import generate_worlds


def save_failure(folder: Path, scenario, trace, controllers: tuple[str, ...] = ()) -> Path:
    """Write a failed world as ``folder/<world>.yaml`` (naming the built-in ``controllers``, for
    ``fuzzynav demo --scenario FILE``) and the plot of the episode as ``folder/<world>.png``;
    returns the scenario file."""
    from fuzzynav.viz.trajectories import plot_episode
    from fuzzynav.world.scenario_file import save_scenario

    path = save_scenario(scenario, Path(folder) / f"{scenario.name}.yaml", controllers=controllers)
    plot_episode(trace, scenario, path.with_suffix(".png"))
    return path


def evaluate(controller: str | None = None, worlds: str = "mixed", n: int = 100, seed: int = 0,
             progress: Callable[[int, dict], None] | None = None, *, model: str | Path | None = None,
             systems: dict | None = None, save_failures: str | Path | None = None) -> dict:
    """Run the registered ``controller`` (with its fuzzy ``systems`` replaced by role, if given) —
    or the one stored in the ``model`` file — on ``n`` seeded worlds of family ``worlds``;
    ``progress(i, outcome)`` is called after each world.

    A model is loaded once; every episode starts from the simulator's ``reset(rng)`` of it, as a
    registered controller is built afresh per world. A progress bar shows on a terminal
    (:mod:`fuzzynav.progress`).
    """
    if (controller is None) == (model is None):
        raise InputError("give exactly one of a controller name and a model file", field="controller")
    if model is not None:
        from fuzzynav.models import load_controller

        loaded = load_controller(model)
        build, controller = (lambda: loaded), loaded.name
    else:
        build = lambda: make_controller(controller, systems=systems) if systems else make_controller(controller)
    scenarios = generate_worlds(worlds, n, seed)
    runs = []
    bar = progress_bars.bar(total=len(scenarios), desc=f"{controller} on {worlds} worlds", unit="world", leave=False)
    for i, scenario in enumerate(scenarios):
        trace = run_episode(scenario, build(), seed=seed)
        numbers = metrics(trace, scenario)
        runs.append({key: numbers[key] for key in ("scenario", "outcome", "time_s", "path_length_m",
                                                    "min_clearance_m")})
        if save_failures is not None and numbers["outcome"] != "reached":
            named = () if model is not None else (controller,)
            runs[-1]["saved"] = str(save_failure(save_failures, scenario, trace, named))
        bar.update()
        bar.set_postfix(reached=sum(r["outcome"] == "reached" for r in runs))
        if progress is not None:
            progress(i, runs[-1])
    bar.close()
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
