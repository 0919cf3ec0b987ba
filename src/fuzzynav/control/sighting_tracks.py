"""Moving obstacles tracked from successive range scans, and their time to collision under a
constant-velocity prediction, for one robot — what ``dwa-tracks`` and ``vfh-tracks`` read
(:mod:`fuzzynav.control.classic.local_map`; docs/dynamic.md). The tracker itself is compiled
(:mod:`fuzzynav.kernels.scan_tracks`, whose docstring gives the method: clusters of moved echoes,
gated association, velocity fitted over ``WINDOW`` sightings, the collision cone of Fiorini &
Shiller's velocity obstacles); the yield layer runs it for a batch of robots
(:mod:`fuzzynav.kernels.threats`).

:class:`ScanTracker` feeds one robot's observations to its :class:`SightingTracks`, the
tracks of one robot seen as :class:`Track` records.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.kernels import outline, scan_tracks
from fuzzynav.kernels.records import Tracks
from fuzzynav.kernels.scan_tracks import CONFIRM, JOIN, MARGIN, MEMORY, MIN_SPEED, WINDOW

__all__ = ["CONFIRM", "JOIN", "MARGIN", "MEMORY", "MIN_SPEED", "WINDOW", "ScanTracker", "SightingTracks", "Track",
           "clusters", "moved_echoes", "off_outline", "tracked_variant"]


def clusters(points: np.ndarray, moved: np.ndarray, here: np.ndarray) -> list[tuple[np.ndarray, float]]:
    """(centre, radius) of each group of neighbouring moved echoes (``points`` (B, 2) in beam
    order, ``moved`` (B,) bool) seen from ``here`` (:func:`fuzzynav.kernels.scan_tracks.clusters`)."""
    centres, radii = scan_tracks.clusters(np.asarray(points, dtype=float), np.asarray(moved, dtype=bool),
                                          np.asarray(here, dtype=float))
    return [(centre, float(radius)) for centre, radius in zip(centres, radii)]


class Track:
    """One tracked moving obstacle as it stands now (a copy): its sightings (``times``,
    ``centres``, oldest first), ``radius``, ``velocity`` and whether it is ``confirmed``."""

    def __init__(self, tracks: Tracks, i: int, k: int):
        one = slice(i, i + 1), slice(k, k + 1)
        self._one = Tracks(tracks.times[one].copy(), tracks.centres[one].copy(), tracks.sightings[one].copy(),
                           tracks.radius[one].copy(), tracks.velocity[one].copy(), np.ones(1, np.int64))
        n = int(tracks.sightings[i, k])
        self.times, self.centres = self._one.times[0, 0, :n], self._one.centres[0, 0, :n]
        self.radius, self.velocity = float(tracks.radius[i, k]), self._one.velocity[0, 0]
        self.confirmed = bool(scan_tracks.confirmed(tracks, i, k))

    def predict(self, t: float) -> np.ndarray:
        """Its centre at time ``t``, at constant velocity."""
        return np.array(scan_tracks.predict(self._one, 0, 0, float(t)))


class SightingTracks:
    """The tracks of one robot (:mod:`fuzzynav.kernels.scan_tracks`)."""

    def __init__(self):
        self.state = scan_tracks.empty(1)

    @property
    def tracks(self) -> list[Track]:
        """Its tracks now, oldest first."""
        return [Track(self.state, 0, k) for k in range(int(self.state.count[0]))]

    def update(self, t: float, points: np.ndarray, moved: np.ndarray, here: np.ndarray) -> None:
        """Add the step's moved echoes (``points`` (B, 2) in beam order, ``moved`` (B,)) at time ``t``."""
        scan_tracks.update(self.state, 0, float(t), np.asarray(points, dtype=float), np.asarray(moved, dtype=bool),
                           np.asarray(here, dtype=float))

    def time_to_collision(self, t: float, pose: np.ndarray, speed: float, robot_radius: float) -> tuple[float, float]:
        """(time to collision (s, inf: none), bearing of that obstacle from the heading (rad))
        of the confirmed tracks against the robot at ``pose`` driving straight on at ``speed``."""
        return scan_tracks.time_to_collision(self.state, 0, float(t), np.asarray(pose, dtype=float), float(speed),
                                             float(robot_radius))


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


def off_outline(points, before, valid, bridge: float = outline.BRIDGE):
    """(distance (P,), nearest point (P, 2)) of the scan ``points`` (P, 2) to the outline of the
    scan before (``before`` (S, 2), ``valid`` (S,)): segments between neighbouring valid beams
    less than ``bridge`` m apart (distance inf when there is none) — how far each echo moved, a
    surface that stands still being on it (compiled: :func:`fuzzynav.kernels.outline.off_outline`)."""
    return outline.off_outline(np.ascontiguousarray(points, dtype=float), np.ascontiguousarray(before, dtype=float),
                               np.ascontiguousarray(valid, dtype=bool), float(bridge))


def tracked_variant(navigator_class, name: str):
    """The factory of the named variant of ``navigator_class`` that predicts moving obstacles from
    their tracks (``tracks=True``): ``dwa-tracks``, ``vfh-tracks``, ``fuzzy-5b-yield-tracks``."""

    def make(**options):
        navigator = navigator_class(**{"tracks": True, **options})
        navigator.name = name
        return navigator

    make.__doc__ = f"Factory of ``{name}``: the navigator with ``tracks=True``."
    return make
