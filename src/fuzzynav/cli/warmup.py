"""``fuzzynav warmup [--controllers A,B]`` — compile the simulator's kernels now, with a progress bar.

numba compiles a kernel the first time it runs and keeps it in its on-disk cache
(:mod:`fuzzynav.jit`), so the first run of a command is slow and later ones are not. ``warmup``
drives each controller for a moment on a built-in scenario of its task, which compiles (or, on
a warm cache, loads) the kernels it uses, and says how long that took. ``fuzzynav demo`` runs it
first for the controllers it will run.
"""

from __future__ import annotations

import sys
import time

from fuzzynav.cli import arguments, help_line

STEPS_S = 0.3  # simulated seconds per controller: a few steps run every kernel of the episode loop
FALLBACK_SCENARIO = "fig-IV-23"  # a goal world, for controllers no built-in scenario lists

EXAMPLE = """
fuzzynav warmup                                   # the demo's controllers and the default fuzzy-5b
fuzzynav warmup --controllers fuzzy-5b,dwa"""


def register(subparsers) -> None:
    parser = arguments.command(subparsers, "warmup", run,
                               help=help_line("warmup"),
                               description=__doc__.split("\n\n")[1], example=EXAMPLE)
    parser.add_argument("--controllers", metavar="A,B", type=arguments.names,
                        help="compile what these controllers use (default: the demo's controllers and fuzzy-5b)")


def default_controllers() -> list[str]:
    """The default navigator and every controller a built-in scenario lists (what the demo runs)."""
    from fuzzynav.world.scenario import list_scenarios
    from fuzzynav.world.scenario_file import open_scenario

    names = {"fuzzy-5b": None}
    for scenario in list_scenarios():
        names.update(dict.fromkeys(open_scenario(scenario).controllers))
    return list(names)


def scenario_for(controller: str) -> str:
    """The first built-in scenario that lists ``controller`` (a world of its task), else a goal world."""
    from fuzzynav.world.scenario import list_scenarios
    from fuzzynav.world.scenario_file import open_scenario

    return next((name for name in list_scenarios() if controller in open_scenario(name).controllers),
                FALLBACK_SCENARIO)


def warm_up(controllers: list[str] | None = None) -> float:
    """Run each of ``controllers`` (default: :func:`default_controllers`) for :data:`STEPS_S` on
    :func:`scenario_for` its task, with a progress bar on a terminal (else one line per controller
    on stderr); returns the seconds taken. Callers say first what is happening (:func:`announce`)."""
    from fuzzynav import progress
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim import run_episode
    from fuzzynav.world.scenario_file import open_scenario

    start = time.perf_counter()
    controllers = controllers or default_controllers()
    for name in controllers:
        make_controller(name)  # unknown names fail before any compilation
    bar = progress.bar(total=len(controllers), desc="compiling", unit="controller")
    for name in controllers:
        bar.set_postfix_str(name)
        began = time.perf_counter()
        run_episode(open_scenario(scenario_for(name)), make_controller(name), seed=0, max_time=STEPS_S)
        bar.update()
        if bar.disable:
            print(f"  {name}: kernels ready in {time.perf_counter() - began:.1f} s", file=sys.stderr, flush=True)
    bar.close()
    return time.perf_counter() - start


def announce() -> None:
    """The first line of a command that compiles up front: what is about to happen, said before
    numba is imported; the notice of :mod:`fuzzynav.jit` is then not needed."""
    print("compiling the simulator's kernels if this is the first run (numba: one to two minutes once; later runs "
          "load them from the cache in seconds)", file=sys.stderr, flush=True)
    from fuzzynav.jit import NOTICE

    NOTICE.silence()


def run(args) -> int:
    from fuzzynav.catalog.controllers import spec_of
    from fuzzynav.errors import InputError

    for name in args.controllers or ():
        try:  # refused before the announcement; making one may compile, which the announcement says
            spec_of(name)
        except InputError as error:
            raise InputError(error.problem, field="--controllers") from None
    announce()
    seconds = warm_up(args.controllers)
    print(f"kernels ready in {seconds:.1f} s", flush=True)
    return 0
