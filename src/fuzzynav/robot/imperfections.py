"""The real robot's imperfections, as scenario keys under ``robot:`` (all off by default):

```yaml
robot:
  sensor_noise: {range_sigma: 0.02, dropout: 0.01, max_range: 8.0}  # m, probability, m
  actuation: {latency: 0.1, steering_rate: 1.5, acceleration: 2.0, slip: 0.05}  # s, rad/s, m/s², fraction
  odometry: {drift: 0.01}                                             # m of error per m driven
```

- ``sensor_noise``: every range reading (rays, beams, lidar) gets zero-mean Gaussian noise of
  ``range_sigma`` and, with probability ``dropout``, reads as nothing within reach (the sensor's
  range); ``max_range`` caps the readings at the real sensor's reach. The nearest-obstacle distance
  the navigators are given gets the same Gaussian noise (the collision test uses the true one).
- ``actuation``: the commands reach the wheels ``latency`` seconds late (a queue of
  latency / Δt steps, holding zero commands at the start: a whole number of steps, else
  refused); the applied steering angle
  moves at most ``steering_rate`` rad/s and the speed at most ``acceleration`` m/s² from the
  previous applied ones; ``slip`` is the mean fraction of the commanded speed and heading rate
  lost at each step (each loss drawn uniformly in [0, 2 slip)).
- ``odometry``: the pose the controller is given (its goal bearing and distance computed from it)
  drifts from the true one by ``drift`` metres per metre driven, in a direction fixed to the
  robot's frame drawn once per episode (a systematic odometry error, Borenstein & Feng 1996,
  UMBmark); the heading stays true. Collisions and the task are judged on the true pose.

The default navigator ``fuzzy-5b`` is told the latency (the simulator calls its
``for_latency``, :class:`fuzzynav.control.hooks.KnowsLatency`, with this key; a real robot's
configuration gives the same figure) and decides where its command will act
(:mod:`fuzzynav.kernels.latency`).

Every draw comes from the episode's seed (:class:`fuzzynav.sim.simulator.BatchSimulator`), in the
compiled step (:mod:`fuzzynav.kernels.imperfect`); with every key off the step is unchanged.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields, replace

import numpy as np

from fuzzynav import validation
from fuzzynav.robot.tricycle import TricycleParams

MAX_LATENCY = 2.0  # s
MAX_SLIP = 0.5  # the losses, drawn in [0, 2 slip), stay below the whole command
MAX_DRIFT = 0.5  # m per m
KEYS = {"sensor_noise": ("range_sigma", "dropout", "max_range"),
        "actuation": ("latency", "steering_rate", "acceleration", "slip"),
        "odometry": ("drift",)}
# the kernel's parameter array (:mod:`fuzzynav.kernels.imperfect`)
PARAM_FIELDS = ("range_sigma", "dropout", "max_range", "delay", "steering_rate", "acceleration", "slip", "drift")


@dataclass(frozen=True)
class Imperfections:
    """The values of the :data:`KEYS` (module docstring); ``None`` (a limit or reach) and 0 are off."""

    range_sigma: float = 0.0
    dropout: float = 0.0
    max_range: float | None = None
    latency: float = 0.0
    steering_rate: float | None = None
    acceleration: float | None = None
    slip: float = 0.0
    drift: float = 0.0

    @property
    def off(self) -> bool:
        """Is every key off (the perfect robot)?"""
        return self == NONE

    def array(self, dt: float) -> np.ndarray:
        """The kernel's parameters (:data:`PARAM_FIELDS`; limits and reach off: infinity; the
        latency in steps of ``dt``)."""
        def limit(value):
            return math.inf if value is None else value

        return np.array([self.range_sigma, self.dropout, limit(self.max_range), delay_steps(self.latency, dt),
                         limit(self.steering_rate), limit(self.acceleration), self.slip, self.drift])

    def to_dict(self) -> dict:
        """The scenario-file keys of the values that are on (``{}`` when all are off)."""
        doc: dict = {}
        for group, keys in KEYS.items():
            values = {key: getattr(self, key) for key in keys if getattr(self, key) != getattr(NONE, key)}
            if values:
                doc[group] = values
        return doc


NONE = Imperfections()


def delay_steps(latency: float, dt: float, source=None, field: str = "latency") -> int:
    """``latency`` (s) as the whole number of steps of ``dt`` the commands wait; a latency between
    two steps is refused (InputError naming ``source`` and ``field``), not rounded to one of them."""
    steps = latency / dt
    if abs(steps - round(steps)) > 1e-9 * max(1.0, steps):
        validation.fail(f"{latency:g} s is not a whole number of the simulator's {dt:g} s steps (commands wait "
                        f"whole steps): give {math.floor(steps) * dt:g} or {math.ceil(steps) * dt:g}", source, field)
    return round(steps)


def _value(value, source, field: str, key: str) -> float:
    """One key's value, checked against its range (InputError naming ``source`` and ``field``)."""
    bounded = {"range_sigma": (0.0, 1.0, False), "dropout": (0.0, 1.0, False), "max_range": (0.0, 1000.0, True),
               "latency": (0.0, MAX_LATENCY, False), "steering_rate": (0.0, 1000.0, True),
               "acceleration": (0.0, 1000.0, True), "slip": (0.0, MAX_SLIP, False), "drift": (0.0, MAX_DRIFT, False)}
    lo, hi, lo_open = bounded[key]
    number = validation.number(value, source, field, lo=lo, hi=hi, lo_open=lo_open, hi_open=key in ("dropout", "slip"))
    if key == "latency":  # a scenario's robot steps by the default Δt (it has no dt key)
        delay_steps(number, TricycleParams.dt, source, field)
    return number


def read(robot: dict, source) -> Imperfections:
    """The imperfections of a scenario's ``robot`` mapping (its ``sensor_noise``, ``actuation``
    and ``odometry`` keys; absent keys off)."""
    values = {}
    for group, keys in KEYS.items():
        if group in robot:
            entry = validation.known_keys(robot[group], keys, source, f"robot.{group}")
            for key, value in entry.items():
                values[key] = _value(value, source, f"robot.{group}.{key}", key)
    return Imperfections(**values)


def perturbed(imperfections: Imperfections, key: str, value, source=None) -> Imperfections:
    """``imperfections`` with one key set, ``key`` written as in a scenario
    (``robot.sensor_noise.range_sigma``; ``fuzzynav bench --perturb KEY=VALUE``)."""
    names = [f"robot.{group}.{name}" for group, keys in KEYS.items() for name in keys]
    if key not in names:
        validation.fail(f"unknown key {validation.shown(key)}; known: {', '.join(names)}", source, key)
    name = key.rsplit(".", 1)[1]
    return replace(imperfections, **{name: _value(value, source, key, name)})


def with_ring_noise(imperfections: Imperfections, noise_std: float) -> Imperfections:
    """``imperfections`` with a sensor ring's own Gaussian noise
    (:attr:`fuzzynav.robot.sensors.SensorRing.noise_std`) added to ``range_sigma``: one noise
    model, two independent Gaussian noises adding in quadrature."""
    if noise_std <= 0.0:
        return imperfections
    return replace(imperfections, range_sigma=math.hypot(imperfections.range_sigma, noise_std))


def describe(imperfections: Imperfections) -> str:
    """One line of the keys that are on, e.g. ``range_sigma=0.02, latency=0.1`` (``none``)."""
    on = [f"{f.name}={getattr(imperfections, f.name):g}" for f in fields(imperfections)
          if getattr(imperfections, f.name) != getattr(NONE, f.name)]
    return ", ".join(on) or "none"
