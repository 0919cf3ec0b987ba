"""fuzzynav — neuro-fuzzy navigation of a simulated tricycle mobile robot.

Implements the systems of L. Cherroun, *Navigation autonome d'un robot mobile par des
techniques neuro-floues* (doctoral thesis, Université de Biskra, 2014): fuzzy behaviours
(chapter IV), fuzzy / neural / ANFIS trajectory tracking (chapter V) and (fuzzy) Q-learning
(chapter VI).

The public API, importable from ``fuzzynav`` (each name is imported on first use, so
``import fuzzynav`` stays light)::

    import fuzzynav

    scenario = fuzzynav.load_scenario("fig-IV-23")          # a built-in name or a YAML file
    controller = fuzzynav.make_controller("fuzzy-5b")       # the default navigator (lidar); list_controllers()
    trace = fuzzynav.run_episode(scenario, controller)
    print(fuzzynav.metrics(trace, scenario)["outcome"])
    fuzzynav.plot_episode(trace, scenario, "fig-IV-23.png")

- scenarios: :func:`load_scenario`, :func:`scenario_from_dict`, :func:`list_scenarios`,
  :func:`save_scenario`, :func:`generate_worlds`, :class:`Scenario`;
- controllers: :func:`make_controller`, :func:`list_controllers`, :func:`load_controller`
  (a trained model file), :class:`Controller`;
- running: :func:`run_episode`, :class:`Simulator`, :class:`BatchSimulator` (many robots in
  step), :func:`evaluate` (a controller over N generated worlds), :class:`Trace`,
  :func:`metrics`;
- plots: :func:`plot_episode`, :func:`plot_trajectory`, :func:`plot_commands`,
  :func:`animate_episode`, :func:`plot_learning_curve`;
- fuzzy systems: :class:`FuzzySystem`, :class:`Variable`, :class:`Rule`, :func:`thesis_system`,
  :func:`load_fuzzy_system`, :func:`save_fuzzy_system`;
- training: :func:`train`, :func:`list_training_tasks`;
- errors: :class:`InputError` (bad input: names the file, the field and the problem).
"""

from __future__ import annotations

from importlib import import_module

__version__ = "0.1.0"

# public name -> "module:attribute", imported on first access (PEP 562)
_API: dict[str, str] = {
    "Scenario": "fuzzynav.world.scenario:Scenario",
    "load_scenario": "fuzzynav.world.scenario:load_scenario",
    "scenario_from_dict": "fuzzynav.world.scenario:scenario_from_dict",
    "list_scenarios": "fuzzynav.world.scenario:list_scenarios",
    "save_scenario": "fuzzynav.world.scenario_file:save_scenario",
    "generate_worlds": "fuzzynav.world.generate:generate_worlds",
    "Controller": "fuzzynav.control.base:Controller",
    "make_controller": "fuzzynav.catalog.controllers:make_controller",
    "list_controllers": "fuzzynav.api:list_controllers",
    "load_controller": "fuzzynav.catalog.tasks:load_controller",
    "run_episode": "fuzzynav.sim.simulator:run_episode",
    "Simulator": "fuzzynav.sim.simulator:Simulator",
    "BatchSimulator": "fuzzynav.sim.simulator:BatchSimulator",
    "Trace": "fuzzynav.sim.trace:Trace",
    "metrics": "fuzzynav.sim.metrics:metrics",
    "evaluate": "fuzzynav.bench.evaluate:evaluate",
    "plot_episode": "fuzzynav.viz.trajectories:plot_episode",
    "plot_trajectory": "fuzzynav.viz.trajectories:plot_trajectory",
    "plot_commands": "fuzzynav.viz.trajectories:plot_commands",
    "animate_episode": "fuzzynav.viz.animation:animate_episode",
    "plot_learning_curve": "fuzzynav.viz.curves:plot_learning_curve",
    "FuzzySystem": "fuzzynav.fuzzy.system:FuzzySystem",
    "Variable": "fuzzynav.fuzzy.variable:Variable",
    "Rule": "fuzzynav.fuzzy.rules:Rule",
    "thesis_system": "fuzzynav.fuzzy.systems:get_system",
    "load_fuzzy_system": "fuzzynav.fuzzy.io.files:load",
    "save_fuzzy_system": "fuzzynav.fuzzy.io.files:save",
    "train": "fuzzynav.api:train",
    "list_training_tasks": "fuzzynav.api:list_training_tasks",
    "InputError": "fuzzynav.errors:InputError",
}

__all__ = sorted(_API)


def __getattr__(name: str):
    """Import a public name of :data:`_API` on first access and keep it in the module."""
    if name not in _API:
        raise AttributeError(f"module 'fuzzynav' has no attribute {name!r}")
    module_name, attribute = _API[name].split(":")
    value = getattr(import_module(module_name), attribute)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_API))
