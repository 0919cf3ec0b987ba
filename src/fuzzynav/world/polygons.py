"""Simplicity of a polygon: the check scenario files' polygons pass (:func:`polygon_self_intersects`)."""

from __future__ import annotations

import numpy as np


def _overlapping_pairs(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Index pairs (i < j) of the edges a→b whose x-extents overlap: edges sorted by their left
    end, each paired with the run of edges starting before its right end (a sweep over x).
    O(n log n + k) for k overlapping pairs; k ≤ n²/2 and n ≤ MAX_POLYGON_VERTICES bound it."""
    left, right = np.minimum(a[:, 0], b[:, 0]), np.maximum(a[:, 0], b[:, 0])
    order = np.argsort(left, kind="stable")
    stop = np.searchsorted(left[order], right[order], side="right")  # edges order[k+1:stop[k]] overlap
    counts = np.maximum(stop - np.arange(len(order)) - 1, 0)
    first = np.repeat(np.arange(len(order)), counts)
    offset = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
    i, j = order[first], order[first + 1 + offset]
    return np.minimum(i, j), np.maximum(i, j)


def polygon_self_intersects(points) -> bool:
    """True when two edges of the closed polygon ``points`` cross or touch (other than neighbours
    at their shared vertex), or when it has a repeated vertex or zero area. Only edges whose
    x-extents overlap are compared (:func:`_overlapping_pairs`)."""
    pts = np.asarray(points, dtype=float)
    n = len(pts)
    a, b = pts, np.roll(pts, -1, axis=0)
    if np.any(np.hypot(*(b - a).T) == 0.0):
        return True
    area = 0.5 * np.sum(a[:, 0] * b[:, 1] - b[:, 0] * a[:, 1])
    if area == 0.0:
        return True

    def orient(p, q, r):
        return np.sign((q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1]) - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0]))

    i, j = _overlapping_pairs(a, b)
    keep = (j - i != 1) & ~((i == 0) & (j == n - 1))  # skip neighbouring edges
    i, j = i[keep], j[keep]
    p1, p2, q1, q2 = a[i], b[i], a[j], b[j]
    o1, o2 = orient(p1, p2, q1), orient(p1, p2, q2)
    o3, o4 = orient(q1, q2, p1), orient(q1, q2, p2)
    proper = (o1 * o2 < 0) & (o3 * o4 < 0)

    def on_segment(p, q, r):  # r collinear with p–q and within its box
        return (
            (orient(p, q, r) == 0)
            & (np.minimum(p[:, 0], q[:, 0]) <= r[:, 0]) & (r[:, 0] <= np.maximum(p[:, 0], q[:, 0]))
            & (np.minimum(p[:, 1], q[:, 1]) <= r[:, 1]) & (r[:, 1] <= np.maximum(p[:, 1], q[:, 1]))
        )

    touching = on_segment(p1, p2, q1) | on_segment(p1, p2, q2) | on_segment(q1, q2, p1) | on_segment(q1, q2, p2)
    # neighbours share a vertex; they only "touch" badly when they fold back onto each other
    k = np.arange(n)
    prev_, cur, next_ = a[k], b[k], b[(k + 1) % n]
    folds = (orient(prev_, cur, next_) == 0) & (
        np.einsum("ij,ij->i", cur - prev_, next_ - cur) < 0
    )
    return bool(np.any(proper | touching) or np.any(folds))
