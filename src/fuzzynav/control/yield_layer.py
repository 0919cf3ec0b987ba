"""The fuzzy yield / evade layer on the time to collision with moving obstacles, fed by the lidar:
what ``fuzzy-5b-yield`` and ``fuzzy-5b-yield-tracks`` put round their navigator
(:mod:`fuzzynav.control.yielding`) and what the default ``fuzzy-5b`` runs among moving obstacles
(:class:`~fuzzynav.control.robust.RobustNavigator`, ``traffic``) — the thesis' perspective of
dynamic obstacles (Conclusion générale; docs/dynamic.md).

The layer reads only the range sensors and the pose the robot believes. Each scan within
``horizon`` m becomes points in the world frame; a point of a standing surface lies on the outline
of the scan before (segments between neighbouring beams:
:func:`~fuzzynav.kernels.outline.off_outline`), a point of a moving obstacle lies off it
by what the obstacle moved. A point that moved faster than ``mover_speed`` and whose gap to
the robot shrank gives a time to collision gap / closing speed (the closing-speed cue of Fiorini &
Shiller's velocity obstacles, 1998, read from two range scans). The smallest one gives the layer's
two inputs: ``ttc`` (s: short, medium, long) and the threat's bearing ``side`` = |φ| (front,
diagonal, abeam, behind). A TS0 rule base (:func:`yield_system`) gives the layer's ``authority``
a ∈ [0, 1], the speed it asks for and a dodge angle; the command is (1 − a) · the navigator's +
a · the layer's speed, and the steering turns by a · dodge away from the threat's side. Something
coming from abeam or behind makes the robot speed out of its way, something diagonal ahead makes
it swerve, something head-on makes it slow down and swerve while the navigator keeps a say (it
avoids what is ahead anyway). The authority fades to nothing as the closest reading within 45° of
the heading comes down to ``close`` m: there the navigator keeps the body off what is near.
Beyond the horizon of the rules (``ttc`` long) the navigator drives alone.

With ``tracks=True`` the layer also tracks the obstacles over successive scans
(:mod:`fuzzynav.kernels.scan_tracks`): their velocity fitted over up to 8 sightings, their
centre predicted at constant velocity for 2 s after the last one, and the first time the relative
motion enters the collision cone (Fiorini & Shiller's velocity obstacles, IJRR 1998) is a second
time to collision. It counts for threats more than ``tracked_beyond`` (60°) off the heading —
abeam, and behind in the lidar's blind sector where the two-scan cue sees nothing; ahead the
two-scan cue decides (tracks ahead too, alone, did worse on the worlds the rules were set on).

With ``evade=True`` (and ``tracks``), the command the rules leave is checked against the tracks'
predicted motion last, and replaced by a sampled evasive one when it would run into one
(:mod:`fuzzynav.kernels.evasion`; label ``EVADE``).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.fuzzy import FuzzySystem, Rule, Singleton, Variable, strong_partition
from fuzzynav.kernels import evasion, scan_tracks, threats
from fuzzynav.kernels.records import Scans, ThreatSettings
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.settings import LENGTH, PREDICTION, ROOM, SLOW, SPEED, Range, checked

TTC_PEAKS = (1.0, 2.5, 4.5)  # s: short, medium, long
SIDE_PEAKS = tuple(np.deg2rad((0.0, 45.0, 90.0, 150.0)))  # front, diagonal, abeam, behind
# (ttc, side) -> (authority, speed m/s, dodge rad); dodge turns away from the threat's side
RULES = {
    ("S", "F"): (0.6, 0.4, 0.6), ("S", "D"): (1.0, 1.2, 0.5), ("S", "A"): (1.0, 2.5, 0.6), ("S", "B"): (1.0, 2.5, 0.0),
    ("M", "F"): (0.3, 0.4, 0.4), ("M", "D"): (0.6, 0.8, 0.3), ("M", "A"): (0.6, 1.8, 0.4), ("M", "B"): (0.6, 1.8, 0.0),
    **{("L", side): (0.0, 0.0, 0.0) for side in "FDAB"},
}


def yield_system() -> FuzzySystem:
    """The yield / evade rule base (module docstring): TS0, product, weighted average."""
    ttc = Variable("ttc", (0.0, 10.0), strong_partition(TTC_PEAKS, ("S", "M", "L"), (0.0, 10.0)))
    side = Variable("side", (0.0, np.pi), strong_partition(SIDE_PEAKS, ("F", "D", "A", "B"), (0.0, np.pi)))
    names = ("authority", "speed", "dodge")
    values = [sorted({row[k] for row in RULES.values()}) for k in range(len(names))]  # each output's singletons
    outputs = [Variable(name, (v[0] - 1.0, v[-1] + 1.0), {f"v{i}": Singleton(x) for i, x in enumerate(v)})
               for name, v in zip(names, values)]
    rules = [Rule((("ttc", t), ("side", s)), tuple((name, f"v{v.index(x)}") for name, v, x in zip(names, values, out)))
             for (t, s), out in RULES.items()]
    return FuzzySystem([ttc, side], outputs, rules, method="ts0", tnorm="product", defuzzifier="weighted_average",
                       name="yield", description="yield / evade on the time to collision with a moving obstacle")


class YieldLayer:
    """The yield / evade layer (module docstring) over a batch of robots: call it with the
    observation and the navigator's command to get the command it leaves; it keeps the scan
    before and the tracks (:meth:`reset` for a new episode)."""

    @checked(mover_speed=SLOW, max_speed=SPEED, horizon=PREDICTION, close=ROOM, track_range=LENGTH,
             tracked_beyond=Range(0.0, 180.0))
    def __init__(self, *, mover_speed: float = 0.3, max_speed: float = 2.5, horizon: float = 3.0,
                 close: float = 0.35, tracks: bool = False, track_range: float = 6.0, tracked_beyond: float = 60.0,
                 evade: bool = False):
        self.system, self.mover_speed, self.max_speed, self.horizon = yield_system(), mover_speed, max_speed, horizon
        self.close, self.tracks, self.track_range, self.radius = close, bool(tracks), track_range, 0.3
        self.evade, self.robot = bool(evade) and bool(tracks), DEFAULT_PARAMS
        self.tracked_beyond = np.deg2rad(tracked_beyond)
        self.reset()

    def reset(self) -> None:
        """Forget the scan before and the tracks (a new episode)."""
        self._previous: Scans | None = None
        self._tracks = scan_tracks.empty(0)
        self._time = 0.0

    def for_robot(self, robot) -> None:
        """Ask for no more than the robot's top speed; its radius for the collision cone."""
        self.max_speed = min(self.max_speed, robot.max_speed)
        self.radius, self.robot = robot.radius, robot

    def threats(self, obs) -> tuple[np.ndarray, np.ndarray]:
        """(time to collision (N,), inf when nothing comes; bearing φ of that threat (N,)):
        :func:`fuzzynav.kernels.threats.threats` against the scan before."""
        pose, ranges = np.asarray(obs.pose, dtype=float), np.asarray(obs.ranges, dtype=float)
        angles = np.asarray(obs.sensor_angles, dtype=float)
        previous, n = self._previous, len(ranges)
        self._time += obs.dt
        if previous is None or previous.points.shape[:2] != ranges.shape:  # a first scan: nothing moved yet
            self._tracks = scan_tracks.empty(n)
            previous = Scans(np.zeros((*ranges.shape, 2)), np.zeros(ranges.shape, dtype=bool), pose[:, :2].copy())
        settings = ThreatSettings(self._time, float(obs.dt), float(obs.max_range), self.mover_speed, self.horizon,
                                  self.track_range, self.tracked_beyond, self.radius, self.tracks)
        ttc, bearing, points = threats.threats(pose, np.asarray(obs.speed, dtype=float), ranges, angles,
                                               np.asarray(obs.active, dtype=bool), previous, self._tracks, settings)
        self._previous = Scans(points, ranges < obs.max_range - 1e-6, pose[:, :2].copy())
        return ttc, bearing

    def __call__(self, obs, steering, speed, labels):
        """The command (steering (N,), speed (N,), labels (N,)) left of the navigator's for ``obs``
        (its robots' ``YIELD`` where the layer has the larger say)."""
        ttc, bearing = self.threats(obs)
        near = np.isfinite(ttc)
        if not near.any() and not (self.evade and self._tracks.count.any()):
            return steering, speed, labels
        steering, speed, labels = np.array(steering, dtype=float), np.array(speed, dtype=float), np.array(labels, dtype=object)
        if near.any():
            self._rules(obs, near, ttc, bearing, steering, speed, labels)
        if self.evade:
            self._evade(obs, steering, speed, labels)
        return steering, speed, labels

    def _rules(self, obs, near, ttc, bearing, steering, speed, labels) -> None:
        """The rule base's say over the robots with a threat (``near``), in place."""
        out = self.system.evaluate(np.column_stack([np.minimum(ttc[near], 10.0), np.abs(bearing[near])]))
        ahead = np.abs(np.asarray(obs.sensor_angles)) <= np.pi / 4
        room = np.asarray(obs.ranges)[near][:, ahead].min(axis=1)  # the navigator keeps the body off what is close ahead
        authority = out[:, 0] * np.clip((room - self.close) / self.close, 0.0, 1.0)
        wanted, dodge = np.minimum(out[:, 1], self.max_speed), out[:, 2]
        speed[near] = (1 - authority) * speed[near] + authority * wanted
        steering[near] = steering[near] - authority * dodge * np.sign(bearing[near])
        labels[near] = np.where(authority > 0.5, "YIELD", labels[near])

    def _evade(self, obs, steering, speed, labels) -> None:
        """Replace, in place, the commands that would run into a predicted track (:func:`evasion.evade`)."""
        evaded = evasion.evade(np.asarray(obs.pose, dtype=float), steering, speed, np.asarray(obs.active, dtype=bool),
                               self._tracks, self._previous, self.robot.array(), self._time)
        labels[evaded] = "EVADE"
