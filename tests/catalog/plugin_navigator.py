"""A controller written outside the package, as a plug-in distribution would ship it: one class
and its spec, which the distribution names under the entry point group ``fuzzynav.controllers``."""

from __future__ import annotations

import numpy as np

from fuzzynav.catalog.specs import ControllerSpec
from fuzzynav.control.base import BatchController


class HeadingNavigator(BatchController):
    """Steers proportionally to the bearing of the goal, slowing down near it (no obstacles seen)."""

    name = "plugin-heading"

    def __init__(self, gain: float = 2.0, cruise: float = 1.5):
        self.gain, self.cruise = gain, cruise

    def act_batch(self, obs):
        speed = np.minimum(self.cruise, obs.target_distance)
        return self.gain * obs.target_bearing, speed, np.full(obs.n, "HEAD")


def make(**options) -> HeadingNavigator:
    return HeadingNavigator(**options)


NAVIGATOR = ControllerSpec("plugin-heading", "tests.catalog.plugin_navigator:make", "proportional heading to the goal",
                      "a plug-in of the tests", ("goal",), aliases=("plugin-heading-v1",))
