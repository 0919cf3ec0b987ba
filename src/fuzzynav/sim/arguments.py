"""The arguments of the Python API's simulator (:func:`~fuzzynav.sim.simulator.run_episode`,
:class:`~fuzzynav.sim.simulator.Simulator`, :class:`~fuzzynav.sim.simulator.BatchSimulator`,
:func:`~fuzzynav.sim.metrics.metrics`), checked before anything runs.

A wrong type or value is an :class:`~fuzzynav.errors.InputError` naming the argument and saying
what it takes — never an ``AttributeError`` from deep inside the loop: the scenario a
:class:`~fuzzynav.world.scenario.Scenario` (``load_scenario`` makes one from a name or a file),
the controller an object with ``act`` or ``act_batch`` (``make_controller`` makes one from a
name) or a sequence of one per robot, ``robot_params`` a ``TricycleParams``, ``sensors`` a
``SensorRing`` or a ring's name, ``seed`` an integer in [0, 2**63 - 1], ``n`` and the number of
start poses at most ``validation.MAX_ROBOTS``.
"""

from __future__ import annotations

from fuzzynav import validation
from fuzzynav.control.hooks import BringsSensors
from fuzzynav.errors import InputError
from fuzzynav.robot.sensors import SensorRing, named_ring
from fuzzynav.robot.tricycle import TricycleParams
from fuzzynav.sim.trace import Trace
from fuzzynav.world import limits
from fuzzynav.world.scenario import Scenario


def _kind(value) -> str:
    return f"{type(value).__name__} {validation.shown(value)}"


def check_trace(trace) -> Trace:
    """``trace``, a :class:`Trace` (what ``run_episode`` returns)."""
    if not isinstance(trace, Trace):
        raise InputError(f"must be a Trace (what run_episode returns), got {_kind(trace)}", field="trace")
    return trace


def check_scenario(scenario) -> Scenario:
    """``scenario``, a :class:`Scenario`."""
    if not isinstance(scenario, Scenario):
        raise InputError(f"must be a Scenario (load_scenario(name or file) makes one), got {_kind(scenario)}",
                         field="scenario")
    return scenario


def check_ran_on(trace, scenario) -> tuple[Trace, Scenario]:
    """``trace`` and ``scenario`` (:func:`check_trace`, :func:`check_scenario`), the trace run on that
    scenario (its name and task): measured or drawn on another, its numbers and plots would be wrong."""
    check_trace(trace), check_scenario(scenario)
    if (trace.scenario, trace.task) != (scenario.name, scenario.task):
        raise InputError(f"the trace was run on the {trace.task} scenario {trace.scenario!r}, not on the "
                         f"{scenario.task} scenario {scenario.name!r}: measure or draw it with the scenario it ran "
                         "on", field="scenario")
    return trace, scenario


def is_controller(value) -> bool:
    """Whether ``value`` is one controller (it has ``act`` or ``act_batch``)."""
    return callable(getattr(value, "act", None)) or callable(getattr(value, "act_batch", None))


def check_controllers(controller, n: int) -> list | None:
    """``None`` for one controller, else the list of ``n`` controllers ``controller`` holds."""
    if is_controller(controller):
        return None
    hint = "make_controller(name) makes one"
    if isinstance(controller, (str, bytes, dict)) or not isinstance(controller, (list, tuple)):
        raise InputError(f"must be a controller (an object with act or act_batch; {hint}) or a list of one per "
                         f"robot, got {_kind(controller)}", field="controller")
    if len(controller) != n:
        raise InputError(f"{len(controller)} controllers for {n} robots", field="controller")
    for i, each in enumerate(controller):
        if not is_controller(each):
            raise InputError(f"must be a controller ({hint}), got {_kind(each)}", field=f"controller[{i}]")
    return list(controller)


def check_params(robot_params) -> TricycleParams | None:
    """``robot_params``: ``None`` (the scenario's robot) or a :class:`TricycleParams`."""
    if robot_params is not None and not isinstance(robot_params, TricycleParams):
        raise InputError("must be a fuzzynav.robot.tricycle.TricycleParams (e.g. "
                         f"dataclasses.replace(scenario.robot, radius=0.3)), got {_kind(robot_params)}",
                         field="robot_params")
    return robot_params


MIN_DT, MAX_DT = 1e-3, 10.0  # s: a robot's time step (a run of limits.MAX_TIME holds at most 3.6 million steps)


def check_robot(params: TricycleParams, field: str) -> TricycleParams:
    """The robot simulated — a scenario's or ``robot_params`` — within the bounds a scenario file
    sets on its size (:func:`fuzzynav.world.limits.length`: a robot built in Python as well; one of
    radius 1e-9 m split each step's collision test into 10⁸ pieces) and with a time step ``dt`` in
    [:data:`MIN_DT`, :data:`MAX_DT`]; ``field`` names where it came from."""
    for name in ("radius", "wheelbase", "width"):
        limits.length(getattr(params, name), field=f"{field}.{name}")
    validation.number(params.dt, field=f"{field}.dt", lo=MIN_DT, hi=MAX_DT)
    return params


def check_sensors(sensors) -> SensorRing | None:
    """``sensors``: ``None``, a :class:`SensorRing` or a ring's name (``thesis``, ``beam``, ``lidar``)."""
    if sensors is None or isinstance(sensors, SensorRing):
        return sensors
    if isinstance(sensors, str):
        return named_ring(sensors)
    raise InputError(f"must be a SensorRing or a ring's name, got {_kind(sensors)}", field="sensors")


def check_seed(seed) -> int | None:
    """``seed``: ``None`` or an integer in [0, 2**63 - 1]."""
    return None if seed is None else validation.seed(seed, field="seed")


def check_robots(n) -> int:
    """``n``: the number of robots, in [1, ``MAX_ROBOTS``]."""
    return validation.count(n, field="n", hi=validation.MAX_ROBOTS)


def default_ring(scenario: Scenario, controller) -> SensorRing:
    """The ring of the scenario's ``sensors`` key, else the controller's own (``sensors``
    attribute: the lidar of the gap-aware navigators), else the thesis' seven rays."""
    if scenario.sensors is not None:
        return named_ring(scenario.sensors)
    first = controller if is_controller(controller) else next(iter(controller))
    ring = first.sensors if isinstance(first, BringsSensors) else None
    return ring if isinstance(ring, SensorRing) else SensorRing()
