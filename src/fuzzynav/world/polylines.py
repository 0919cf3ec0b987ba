"""Polylines (m, 2) of points: their length, the distance along them and the points at given
distances — for routes, reference paths, moving obstacles' tracks and the robot's own path."""

from __future__ import annotations

import numpy as np


def arc_lengths(points) -> np.ndarray:
    """``(m,)``: the distance (m) along the polyline ``points`` from its first point to each point."""
    points = np.asarray(points, dtype=float)
    return np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(points, axis=0).T))])


def path_length(points) -> float:
    """Length (m) of the polyline ``points``."""
    return float(np.hypot(*np.diff(np.asarray(points, dtype=float), axis=0).T).sum())


def at_arc(points, arc, s) -> np.ndarray:
    """``(len(s), 2)``: the points at distances ``s`` along the polyline ``points`` whose
    :func:`arc_lengths` are ``arc`` (linear between its points, its ends beyond them)."""
    points = np.asarray(points, dtype=float)
    return np.column_stack([np.interp(s, arc, points[:, 0]), np.interp(s, arc, points[:, 1])])
