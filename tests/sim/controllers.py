"""Small controllers for the simulator tests (not thesis controllers)."""

from __future__ import annotations

import numpy as np

from fuzzynav.control.base import Command, Controller


class HeadingController(Controller):
    """Proportional heading control towards ``obs.target``; speed grows with the distance."""

    name = "p-heading"

    def __init__(self, gain: float = 2.0, cruise: float = 2.0, floor: float = 0.0):
        self.gain, self.cruise, self.floor = gain, cruise, floor

    def act(self, obs):
        speed = min(self.cruise, obs.target_distance + self.floor)
        label = "near" if obs.obstacle_distance < 1.5 else "seek"
        return Command(self.gain * obs.target_bearing, speed, label)

    def act_batch(self, obs):
        speed = np.minimum(self.cruise, obs.target_distance + self.floor)
        labels = np.where(obs.obstacle_distance < 1.5, "near", "seek")
        return self.gain * obs.target_bearing, speed, labels


class SingleHeading(HeadingController):
    """The same law without ``act_batch`` (exercises the per-robot path)."""

    act_batch = None


class ConstantController(Controller):
    """Constant steering and speed."""

    name = "constant"

    def __init__(self, steering: float = 0.0, speed: float = 1.0):
        self.steering, self.speed = steering, speed

    def act(self, obs):
        return Command(self.steering, self.speed, "constant")


class CountingController(Controller):
    """Stateful: drives straight and counts its calls (checks one copy per robot)."""

    name = "counting"

    def __init__(self):
        self.calls = 0

    def reset(self, rng=None):
        self.calls = 0

    def act(self, obs):
        self.calls += 1
        return Command(0.0, 0.5, f"call{self.calls}")


def load_heading_model(document, path):
    """Model loader for the CLI tests: a JSON document {"kind": ..., "gain": g}."""
    return HeadingController(gain=float(document["gain"]))
