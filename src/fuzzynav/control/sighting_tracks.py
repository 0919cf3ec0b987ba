"""Moving obstacles tracked from successive range scans, and their time to collision under a
constant-velocity prediction — what ``fuzzy-5b-yield`` reads (docs/dynamic.md).

Each step, the beams whose echo lies off the previous scan's outline (it moved) are grouped into
clusters (neighbouring beams less than ``JOIN`` m apart); a cluster's centre is its mean point
pushed away from the robot by half its extent (a disc seen from one side). A cluster extends the
track whose predicted centre lies within ``GATE`` m of it, or starts a new one. A track's
velocity is the least-squares slope of its last ``WINDOW`` sightings, so a 0.1 s step's noise is
averaged over up to a second; a track is confirmed after ``CONFIRM`` sightings, and kept — its
centre predicted at constant velocity — ``MEMORY`` s after its last one, so an obstacle that
walks into the lidar's blind sector behind the robot is still avoided.

The time to collision of a confirmed track is the first time t ≥ 0 at which the relative
position p + w t (w: the track's velocity less the robot's) comes within the sum of the radii:
the collision-cone test of velocity obstacles (P. Fiorini, Z. Shiller, "Motion planning in
dynamic environments using velocity obstacles", IJRR 17(7), 1998), solved in closed form; a
track whose relative motion misses the robot has none (inf).

:class:`ScanTracker` feeds one robot's observations to its tracks, for the navigators that decide
one robot at a time and plan against the predicted positions (``dwa-tracks``, ``vfh-tracks``:
:mod:`fuzzynav.control.classic.local_map`); ``fuzzy-5b-yield-tracks`` feeds a batch of them
itself (:mod:`fuzzynav.control.yielding`), through the same :func:`moved_echoes`.
"""

from __future__ import annotations

import numpy as np

JOIN = 0.6  # m: neighbouring moved echoes closer than this belong to one obstacle
GATE = 1.0  # m: a cluster extends a track whose predicted centre is this close
WINDOW = 8  # sightings in a track's velocity fit
CONFIRM = 5  # sightings before a track is believed
MIN_SPEED = 0.4  # m/s: a slower track is taken for noise of the outline test
MEMORY = 2.0  # s: a track unseen this long is forgotten
MARGIN = 0.2  # m added to the sum of the radii


def clusters(points: np.ndarray, moved: np.ndarray, here: np.ndarray) -> list[tuple[np.ndarray, float]]:
    """(centre, radius) of each group of neighbouring moved echoes (``points`` (B, 2) in beam
    order, ``moved`` (B,) bool) seen from ``here``."""
    found: list[tuple[np.ndarray, float]] = []
    index = np.flatnonzero(moved)
    if not len(index):
        return found
    breaks = np.flatnonzero(np.hypot(*np.diff(points[index], axis=0).T) > JOIN) + 1
    for group in np.split(index, breaks):
        if len(group) < 2:
            continue
        seen = points[group]
        radius = max(0.2, 0.5 * float(np.hypot(*(seen[-1] - seen[0]))))
        middle = seen.mean(axis=0)
        away = middle - here
        centre = middle + 0.5 * radius * away / max(float(np.hypot(*away)), 1e-9)
        found.append((centre, radius))
    return found


class Track:
    """One moving obstacle: its sightings (time, centre), its radius and velocity."""

    def __init__(self, t: float, centre: np.ndarray, radius: float):
        self.times, self.centres, self.radius = [t], [centre], radius
        self.velocity = np.zeros(2)

    def predict(self, t: float) -> np.ndarray:
        return self.centres[-1] + self.velocity * (t - self.times[-1])

    def add(self, t: float, centre: np.ndarray, radius: float) -> None:
        self.times, self.centres = (self.times + [t])[-WINDOW:], (self.centres + [centre])[-WINDOW:]
        self.radius = max(self.radius, radius)
        times = np.asarray(self.times) - self.times[0]
        if len(times) >= 2 and np.ptp(times) > 0:
            self.velocity = np.polyfit(times, np.asarray(self.centres), 1)[0]

    @property
    def confirmed(self) -> bool:
        return len(self.times) >= CONFIRM and float(np.hypot(*self.velocity)) >= MIN_SPEED


class SightingTracks:
    """The tracks of one robot (module docstring)."""

    def __init__(self):
        self.tracks: list[Track] = []

    def update(self, t: float, points: np.ndarray, moved: np.ndarray, here: np.ndarray) -> None:
        """Add the step's moved echoes (``points`` (B, 2) in beam order, ``moved`` (B,)) at time ``t``."""
        free = list(self.tracks)
        for centre, radius in clusters(points, moved, here):
            if free:
                gaps = [float(np.hypot(*(track.predict(t) - centre))) for track in free]
                k = int(np.argmin(gaps))
                if gaps[k] <= GATE:
                    free.pop(k).add(t, centre, radius)
                    continue
            self.tracks.append(Track(t, centre, radius))
        self.tracks = [track for track in self.tracks if t - track.times[-1] <= MEMORY]

    def time_to_collision(self, t: float, pose: np.ndarray, speed: float, robot_radius: float) -> tuple[float, float]:
        """(time to collision (s, inf: none), bearing of that obstacle from the heading (rad))
        of the confirmed tracks against the robot at ``pose`` driving straight on at ``speed``."""
        best, bearing = np.inf, 0.0
        own = speed * np.array([np.cos(pose[2]), np.sin(pose[2])])
        for track in self.tracks:
            if not track.confirmed:
                continue
            p = track.predict(t) - pose[:2]
            w = track.velocity - own
            reach = robot_radius + track.radius + MARGIN
            when = _first_contact(p, w, reach)
            if when < best:
                best = when
                bearing = float(np.angle(np.exp(1j * (np.arctan2(p[1], p[0]) - pose[2]))))
        return best, bearing


def moved_echoes(points, tracked, before, valid, dt: float, mover_speed: float) -> np.ndarray:
    """Which of this scan's echoes (``points`` (B, 2), world frame; only the ``tracked`` (B,) ones
    are tested) moved faster than ``mover_speed`` since the scan before (``before`` (B, 2),
    ``valid`` (B,)), ``dt`` s earlier: how far each lies off that scan's outline (:func:`off_outline`)."""
    moved = np.zeros(len(points), dtype=bool)
    if tracked.any():
        off, _ = off_outline(points[tracked], before, valid)
        moved[tracked] = off / dt > mover_speed
    return moved


class ScanTracker:
    """The moving obstacles one robot tracks from its successive scans (module docstring): its
    echoes within ``track_range`` m that moved faster than ``mover_speed`` m/s feed its
    :class:`SightingTracks`."""

    def __init__(self, mover_speed: float = 0.3, track_range: float = 6.0):
        self.mover_speed, self.track_range = float(mover_speed), float(track_range)
        self.reset()

    def reset(self) -> None:
        """Forget every track (a new episode)."""
        self.tracks = SightingTracks()
        self._previous: tuple[np.ndarray, np.ndarray] | None = None

    def observe(self, obs) -> np.ndarray:
        """Feed the scan of one robot's observation ``obs`` (pose, ranges, sensor angles, time);
        returns which beams' echoes moved, (B,) bool (none at the first scan)."""
        pose, ranges = np.asarray(obs.pose, dtype=float), np.asarray(obs.ranges, dtype=float)
        heading = pose[2] + np.asarray(obs.sensor_angles, dtype=float)
        points = pose[:2] + ranges[:, None] * np.column_stack([np.cos(heading), np.sin(heading)])
        valid = ranges < obs.max_range - 1e-6
        previous, self._previous = self._previous, (points, valid)
        if previous is None or previous[0].shape != points.shape:
            return np.zeros(len(ranges), dtype=bool)
        tracked = ranges < min(obs.max_range - 1e-6, self.track_range)
        moved = moved_echoes(points, tracked, previous[0], previous[1], obs.dt, self.mover_speed)
        self.tracks.update(float(obs.t), points, moved, pose[:2])
        return moved

    def confirmed(self) -> list[Track]:
        """The tracks believed now (:attr:`Track.confirmed`)."""
        return [track for track in self.tracks.tracks if track.confirmed]


def _first_contact(p: np.ndarray, w: np.ndarray, reach: float) -> float:
    """Smallest t ≥ 0 with |p + w t| ≤ ``reach`` (0 when already within; inf when never)."""
    c = float(p @ p) - reach * reach
    if c <= 0:
        return 0.0
    a, b = float(w @ w), 2.0 * float(p @ w)
    disc = b * b - 4 * a * c
    if a <= 1e-12 or b >= 0 or disc < 0:
        return np.inf
    return (-b - np.sqrt(disc)) / (2 * a)


def off_outline(points, before, valid, bridge: float = 0.3):
    """(distance (P,), nearest point (P, 2)) of the scan ``points`` (P, 2) to the outline of the
    scan before (``before`` (S, 2), ``valid`` (S,)): segments between neighbouring valid beams
    less than ``bridge`` m apart (distance inf when there is none) — how far each echo moved, a
    surface that stands still being on it."""
    a, b = before[:-1], before[1:]
    joined = valid[:-1] & valid[1:] & (np.hypot(*(b - a).T) < bridge)
    a, e = a[joined], (b - a)[joined]
    if not len(a):
        return np.full(len(points), np.inf), np.array(points, dtype=float)
    u = np.clip(np.einsum("pk,sk->ps", points, e) - np.einsum("sk,sk->s", a, e)[None], 0.0, None)
    u = np.minimum(u / np.maximum(np.einsum("sk,sk->s", e, e), 1e-12)[None], 1.0)
    foot = a[None] + u[..., None] * e[None]  # (P, S, 2) nearest point of each segment
    dist = np.hypot(*(points[:, None] - foot).transpose(2, 0, 1))
    s = np.argmin(dist, axis=1)
    return dist[np.arange(len(points)), s], foot[np.arange(len(points)), s]


def tracked_variant(navigator_class, name: str):
    """The factory of the named variant of ``navigator_class`` that predicts moving obstacles from
    their tracks (``tracks=True``): ``dwa-tracks``, ``vfh-tracks``, ``fuzzy-5b-yield-tracks``."""

    def make(**options):
        navigator = navigator_class(**{"tracks": True, **options})
        navigator.name = name
        return navigator

    make.__doc__ = f"Factory of ``{name}``: the navigator with ``tracks=True``."
    return make
