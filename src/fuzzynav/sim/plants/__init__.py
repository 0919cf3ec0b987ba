"""Plants: what moves the robots and what their range sensors read, under the simulator's loop.

The simulator (:class:`fuzzynav.sim.simulator.BatchSimulator`) asks the controllers for their
commands, clips them, and after the move judges every robot (collision of the footprint disc,
task done, time limit) and measures its nearest obstacle on the world's exact geometry, whatever
the plant: the plant only decides where the commands take the robots and what the ranges read.

- ``kinematic`` (the default, :class:`Plant`): the thesis' tricycle model (eq IV.1–IV.2) and
  exact ray casting, both inside the compiled step (one call per step);
- ``mujoco`` (the optional extra ``physics``, :mod:`.mujoco_plant`): the same tricycle as a
  rigid-body model in the MuJoCo physics engine (mass, inertia, tyre friction, a steered front
  wheel and two driven rear wheels with torque limits) and its ranges by MuJoCo's ray casting.

A plant plugs in by one entry of :data:`PLANTS` (``"module:Class"``, imported when first asked
for, so an optional engine costs nothing until used) and a class deriving :class:`Plant`.
"""

from __future__ import annotations

import importlib

import numpy as np

from fuzzynav.errors import InputError

DEFAULT_PLANT = "kinematic"
PLANTS = {
    "kinematic": "fuzzynav.sim.plants:Plant",
    "mujoco": "fuzzynav.sim.plants.mujoco_plant:MujocoPlant",
}
EXTRAS = {"mujoco": ("mujoco", "physics")}  # plant -> (module it needs, optional extra that installs it)


class Plant:
    """The kinematic plant, and the interface of every other: a plant is built for one
    scenario, robot and sensor ring (``scenario``, ``params`` a
    :class:`~fuzzynav.robot.tricycle.TricycleParams`, ``sensors`` a
    :class:`~fuzzynav.robot.sensors.SensorRing`, ``n`` robots).

    ``in_kernel`` True: the compiled step moves and senses (this class; the methods are not
    called). A plant with ``in_kernel`` False receives :meth:`reset` with the start poses, then
    each step :meth:`move` (the clipped commands in the state's ``steering`` and ``speed``
    columns, see :data:`fuzzynav.kernels.step.STATE_FIELDS`: it writes the new x, y, θ of the
    ``rows`` it moves) and, after the stop tests, :meth:`sense` (it overwrites the readings of
    the ``rows`` still running).
    """

    name = "kinematic"
    in_kernel = True

    def __init__(self, scenario, params, sensors, n: int):
        self.scenario, self.params, self.sensors, self.n = scenario, params, sensors, n

    def reset(self, state: np.ndarray, ranges: np.ndarray, rows: np.ndarray) -> None:
        """Robots at the poses of ``state`` (N, STATE_FIELDS), at rest; the readings of ``rows``."""

    def move(self, state: np.ndarray, rows: np.ndarray) -> None:
        """Advance the robots of ``rows`` (N,) bool by one step Δt under their commands."""

    def sense(self, state: np.ndarray, ranges: np.ndarray, rows: np.ndarray) -> None:
        """Write the readings (N, S) of the robots of ``rows``."""


def check_plant(name) -> str:
    """``name`` if it is a known plant whose engine is installed, else an :class:`InputError`
    (field ``--plant``) naming the choices, or the optional extra to install."""
    if not isinstance(name, str) or name not in PLANTS:
        raise InputError(f"unknown plant {name!r} (choose {', '.join(PLANTS)})", field="--plant")
    if name in EXTRAS:
        module, extra = EXTRAS[name]
        try:
            importlib.import_module(module)
        except ImportError:
            raise InputError(f"the {name} plant needs the optional extra '{extra}': "
                             f"pip install -e '.[{extra}]' in the clone", field="--plant") from None
    return name


def make_plant(name: str, scenario, params, sensors, n: int) -> Plant:
    """The plant called ``name`` (:data:`PLANTS`) for ``n`` robots in ``scenario``."""
    module, _, attribute = PLANTS[check_plant(name)].partition(":")
    return getattr(importlib.import_module(module), attribute)(scenario, params, sensors, n)
