"""``fuzzy-5b-yield`` and ``fuzzy-5b-yield-tracks``: a navigator under the fuzzy yield / evade
layer on the time to collision with moving obstacles (:mod:`fuzzynav.control.yield_layer`), named
variants for dynamic worlds (the thesis' perspective of dynamic obstacles, Conclusion générale;
docs/dynamic.md).

``fuzzy-5b-yield`` runs the layer round ``fuzzy-5b`` at the thesis' speeds (``paced=False``, its
rules were written for them), remembering every point seen. ``fuzzy-5b-yield-tracks``
(``tracks=True``) adds the obstacles tracked over successive scans; its version 2
(:func:`make_tracked`) runs round the default ``fuzzy-5b`` itself — paced, forgetting where moving
obstacles were (:mod:`fuzzynav.kernels.clearing`) — where version 1 ran round ``fuzzy-5b`` at the
thesis' speeds, remembering them. Among moving obstacles the default ``fuzzy-5b`` (version 6) runs
the same layer with tracks itself, so there the two decide alike; in a static world
``fuzzy-5b-yield-tracks`` keeps its layer on. The measurements are in docs/dynamic.md.
"""

from __future__ import annotations

from fuzzynav.control.base import BatchController
from fuzzynav.control.sighting_tracks import tracked_variant
from fuzzynav.control.through_gaps import fuzzy_5b_gap_robust
from fuzzynav.control.yield_layer import YieldLayer

# the layers run round the default as its version 12 started: steering straight at a goal it has a
# free line to, wherever that goal lies (the route to a goal off the heading, version 13, was not
# measured under these layers; docs/results/default-navigator.md, *Version 13*)
STRAIGHT = {"guide_off_heading": 0.0}


class YieldingNavigator(BatchController):
    """``inner`` (default ``fuzzy-5b`` at the thesis' speeds, ``paced=False``: the yield rules
    were written and measured for them, not for the pace layer's faster driving) under the yield /
    evade layer (:class:`~fuzzynav.control.yield_layer.YieldLayer`, ``options`` its settings)."""

    name = "fuzzy-5b-yield"

    def __init__(self, inner=None, **options):
        self.inner = inner if inner is not None else fuzzy_5b_gap_robust(paced=False, forget_moving=False,
                                                                          yield_in_traffic=False, guidance=STRAIGHT)
        self.sensors = getattr(self.inner, "sensors", None)
        self.labels = getattr(self.inner, "labels", ())
        self.layer = YieldLayer(**options)

    def reset(self, rng=None) -> None:
        self.inner.reset(rng)
        self.layer.reset()

    def for_robot(self, robot) -> YieldingNavigator:
        if callable(getattr(self.inner, "for_robot", None)):
            self.inner.for_robot(robot)
        self.layer.for_robot(robot)
        return self

    def for_traffic(self, moving: bool) -> YieldingNavigator:
        """Tell the inner navigator whether the scenario's obstacles move (its ``for_traffic``, if any)."""
        if callable(getattr(self.inner, "for_traffic", None)):
            self.inner.for_traffic(moving)
        return self

    def act_batch(self, obs):
        return self.layer(obs, *self.inner.act_batch(obs))


def make(**options) -> YieldingNavigator:
    """``fuzzy-5b-yield`` (``options``: ``mover_speed``, ``max_speed``, ``tracks``)."""
    return YieldingNavigator(**options)


def _round_the_default(**options) -> YieldingNavigator:
    """The layer round the default ``fuzzy-5b`` (paced, forgetting where moving obstacles were),
    without the default's own layer among moving obstacles."""
    return YieldingNavigator(**{"inner": fuzzy_5b_gap_robust(yield_in_traffic=False, guidance=STRAIGHT), **options})


make_tracked = tracked_variant(_round_the_default, "fuzzy-5b-yield-tracks")
