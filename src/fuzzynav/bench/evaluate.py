"""One controller over generated worlds, summarised in memory (``fuzzynav evaluate``): success,
collision and timeout rates.

:func:`evaluate` runs one episode per world of :func:`fuzzynav.world.generate.generate_worlds`
and summarises them: ``success_rate``, ``collision_rate``, ``timeout_rate``,
``invalid_command_rate`` (fractions of the ``n`` worlds; the last counts episodes the simulator
stopped on a NaN or infinite command, each with its ``invalid_command`` reason), ``mean_time_s``
and ``mean_path_length_m`` over the successful episodes, plus the per-world outcomes. The
controller is a registered name or a trained model file, built as a campaign builds its
controllers (:func:`fuzzynav.bench.cells.controller_maker`); the rates are those of a campaign's
summary (:func:`fuzzynav.bench.stats.rate`). With ``save_failures`` (a folder), each world not
reached is written there as a scenario file with the plot of its episode (:func:`save_failure`),
so ``fuzzynav run FILE`` reruns it.

What it is beside a campaign (:mod:`fuzzynav.bench.campaign`): the same worlds, episodes and
outcome rates, for one controller on one family and one seed, returned rather than written —
no runs file, resume, seeds, shortest paths (the path ratio, the BARN score) or
confidence intervals; what it adds is a sensor ring chosen for every world, factory options
and rule bases given as objects (the chapter IV experiments), and the failed worlds saved.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from fuzzynav import progress as progress_bars, validation
from fuzzynav.bench.backends import pool_map
from fuzzynav.bench.cells import controller_maker
from fuzzynav.bench.stats import rate
from fuzzynav.robot.sensors import named_ring
from fuzzynav.sim import metrics, run_episode
from fuzzynav.sim.plants import DEFAULT_PLANT, check_plant
from fuzzynav.world.generate import check_family, generate_world


def save_failure(folder: str | Path, scenario, trace, controllers: tuple[str, ...] = ()) -> Path:
    """Write a failed world as ``folder/<world>.yaml`` (naming the built-in ``controllers``, for
    ``fuzzynav demo --scenario FILE``) and the plot of the episode as ``folder/<world>.png``;
    returns the scenario file."""
    from fuzzynav.viz.trajectories import plot_episode
    from fuzzynav.world.scenario_file import save_scenario

    path = save_scenario(scenario, Path(folder) / f"{scenario.name}.yaml", controllers=controllers)
    plot_episode(trace, scenario, path.with_suffix(".png"))
    return path


def _keep_edited_failures(folder: Path, worlds: str, seed: int, n: int, named: tuple[str, ...]) -> None:
    """Before any run: refuse a ``folder`` holding the file of one of these worlds with other
    content than a failure there would be saved with (:func:`save_failure`): an edited world."""
    from fuzzynav.world.scenario_file import refuse_overwriting_edits, scenario_yaml

    prefix = f"{worlds}-{seed}-"
    indices = [int(path.stem[len(prefix):]) for path in folder.glob(f"{prefix}*.yaml") if path.stem[len(prefix):].isdigit()]
    texts = {folder / f"{world.name}.yaml": scenario_yaml(world, named)
             for world in (generate_world(worlds, seed, i) for i in sorted(indices) if i < n)}
    refuse_overwriting_edits(texts, folder, "save_failures")


_JOB: dict = {}
"""What every world of the current :func:`evaluate` shares (set in each worker by :func:`_share`)."""


def _share(job: dict) -> None:
    _JOB.clear()
    _JOB.update(job)


def _world(index: int) -> dict:
    """One episode of the shared job on its world ``index`` (drawn here, so the workers share the
    drawing too): its outcome numbers (and the saved failure)."""
    scenario = generate_world(_JOB["worlds"], _JOB["seed"], index)
    trace = run_episode(scenario, _JOB["build"](), seed=_JOB["seed"], sensors=_JOB["ring"], plant=_JOB["plant"])
    numbers = metrics(trace, scenario)
    run = {key: numbers[key] for key in ("scenario", "outcome", "time_s", "path_length_m", "min_clearance_m")}
    if numbers["invalid_command"] is not None:
        run["invalid_command"] = numbers["invalid_command"]
    if _JOB["save_failures"] is not None and numbers["outcome"] != "reached":
        run["saved"] = str(save_failure(_JOB["save_failures"], scenario, trace, _JOB["named"]))
    return run


def _check_arguments(progress, model, systems, save_failures, sensors, options, plant, workers) -> None:
    """The arguments of :func:`evaluate` that no lower layer checks before the first world: each
    of its type (an :class:`InputError` naming it, never a ``TypeError`` from a worker)."""
    if progress is not None and not callable(progress):
        validation.fail(f"must be a function progress(i, outcome) or None, got {type(progress).__name__} "
                        f"{validation.shown(progress)}", field="progress")
    if model is not None:
        validation.file_path(model, field="model")
    for name, value in (("systems", systems), ("options", options)):
        if value is not None:
            validation.mapping(value, field=name)
    if save_failures is not None:
        folder = validation.file_path(save_failures, field="save_failures")
        try:
            is_file = folder.is_file()
        except OSError as error:  # a name too long for the file system, ...
            validation.fail(f"not a usable folder name ({error.strerror or error})", field="save_failures")
        if is_file:
            validation.fail(f"{folder} is a file; give a folder", field="save_failures")
    if sensors is not None:
        validation.text(sensors, field="sensors", max_length=200)
    check_plant(plant)
    validation.count(workers, field="workers", hi=validation.MAX_WORKERS)


def evaluate(controller: str | None = None, worlds: str = "mixed", n: int = 100, seed: int = 0,
             progress: Callable[[int, dict], None] | None = None, *, model: str | Path | None = None,
             systems: dict | None = None, save_failures: str | Path | None = None, sensors: str | None = None,
             options: dict | None = None, plant: str = DEFAULT_PLANT, workers: int = 1) -> dict:
    """Run the registered ``controller`` (with its fuzzy ``systems`` replaced by role, if given, and
    the keyword ``options`` of its factory, e.g. ``layers=``) —
    or the one stored in the ``model`` file — on ``n`` seeded worlds of family ``worlds``, with the
    sensor ring named ``sensors`` (default: the controller's, :func:`fuzzynav.sim.simulator.default_ring`);
    ``progress(i, outcome)`` is called after each world (in the order they finish); ``plant`` moves
    the robot (:mod:`fuzzynav.sim.plants`); ``workers`` processes share the worlds
    (:func:`fuzzynav.bench.backends.pool_map`): every episode is seeded alone, so the result does
    not depend on ``workers`` (an integer from 1 to :data:`fuzzynav.validation.MAX_WORKERS`). A
    controller that cannot do a goal task (every generated world is one) is refused.

    A model is loaded once and every episode runs a copy of it, as a registered controller is
    built afresh per world (:class:`~fuzzynav.bench.cells.controller_maker`). A progress bar shows on a terminal
    (:mod:`fuzzynav.progress`).
    """
    _check_arguments(progress, model, systems, save_failures, sensors, options, plant, workers)
    build = controller_maker(controller, model=model, systems=systems, options=options)
    controller = build.name
    n, seed = check_family(worlds, n, seed)
    named: tuple[str, ...] = () if model is not None else (controller,)
    job = {"build": build, "worlds": worlds, "seed": seed, "ring": None if sensors is None else named_ring(sensors), "plant": plant,
           "save_failures": save_failures, "named": named}
    if save_failures is not None:
        _keep_edited_failures(Path(save_failures), worlds, seed, n, named)
    runs: list = [None] * n
    reached_so_far = 0
    bar = progress_bars.bar(total=n, desc=f"{controller} on {worlds} worlds", unit="world", leave=False)

    def finished(i: int, run: dict) -> None:
        nonlocal reached_so_far
        runs[i] = run
        reached_so_far += run["outcome"] == "reached"
        bar.update()
        bar.set_postfix(reached=reached_so_far)
        if progress is not None:
            progress(i, run)

    try:
        pool_map(_world, range(n), max(1, min(workers, n)), finished, initializer=_share, initargs=(job,))
    finally:
        _JOB.clear()  # in one process the job was shared here: do not keep its controller alive
        bar.close()
    outcomes = [r["outcome"] for r in runs]
    reached = np.array(outcomes) == "reached"
    return {
        "controller": controller,
        "model": None if model is None else str(model),
        "worlds": worlds,
        "n": int(n),
        "seed": int(seed),
        "plant": plant,
        "success_rate": rate(outcomes, "reached"),
        "collision_rate": rate(outcomes, "collision"),
        "timeout_rate": rate(outcomes, "timeout"),
        "invalid_command_rate": rate(outcomes, "invalid_command"),
        "mean_time_s": float(np.mean([r["time_s"] for r, ok in zip(runs, reached) if ok])) if reached.any() else None,
        "mean_path_length_m": (float(np.mean([r["path_length_m"] for r, ok in zip(runs, reached) if ok]))
                               if reached.any() else None),
        "episodes": runs,
    }
