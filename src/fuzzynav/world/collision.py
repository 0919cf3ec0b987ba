"""Vectorised geometric kernels: distances to and ray hits on many shapes at once.

Every function takes ``points`` / ray ``origins`` ``(N, 2)`` and a packed set of K shapes, and
returns ``(N, K)`` arrays, so one call answers for all robots (or all sensor rays) and all
obstacles together. Rays are ``origin + t · direction`` with unit directions; a ray that misses
gives ``t = inf``. Used by :class:`fuzzynav.world.world.World`.
"""

from __future__ import annotations

import numpy as np


def segment_distance(points, a, b):
    """Distances ``(N, M)`` and nearest points ``(N, M, 2)`` from points to segments a–b ``(M, 2)``."""
    e = b - a  # (M, 2)
    length2 = np.einsum("ij,ij->i", e, e)
    rel = points[:, None, :] - a[None, :, :]  # (N, M, 2)
    u = np.clip(np.einsum("nmk,mk->nm", rel, e) / length2, 0.0, 1.0)
    nearest = a[None, :, :] + u[..., None] * e[None, :, :]
    diff = points[:, None, :] - nearest
    return np.hypot(diff[..., 0], diff[..., 1]), nearest


def crossings(points, a, b):
    """Even-odd test parts ``(N, M)``: does the ray from each point towards +x cross segment a–b."""
    px, py = points[:, 0:1], points[:, 1:2]
    ay, by = a[None, :, 1], b[None, :, 1]
    straddles = (ay > py) != (by > py)
    with np.errstate(divide="ignore", invalid="ignore"):
        x_cross = a[None, :, 0] + (py - ay) * (b[None, :, 0] - a[None, :, 0]) / (by - ay)
    return straddles & (px < x_cross)


def ellipse_frame(points, centers, angles):
    """Points ``(N, 2)`` in the frames of K ellipses, ``(N, K, 2)`` (rotated, not scaled)."""
    c, s = np.cos(angles), np.sin(angles)
    rel = points[:, None, :] - centers[None, :, :]
    return np.stack([c * rel[..., 0] + s * rel[..., 1], -s * rel[..., 0] + c * rel[..., 1]], axis=-1)


def ellipse_nearest(local, radii, iterations: int = 4):
    """Nearest points on ellipses (frame coordinates) to ``local`` ``(N, K, 2)``.

    A fixed-point iteration on the evolute (the curvature-centre method): it converges from
    inside and outside in a few steps and needs no branches, so it vectorises. Works in the
    first quadrant (the ellipse is symmetric) and restores the signs at the end.
    """
    a, b = radii[:, 0], radii[:, 1]
    c2 = a * a - b * b
    ka, kb = c2 / a, -c2 / b
    px, py = np.abs(local[..., 0]), np.abs(local[..., 1])
    tx = np.full(px.shape, np.sqrt(0.5))
    ty = tx.copy()
    for _ in range(iterations):
        ex, ey = ka * tx * tx * tx, kb * ty * ty * ty  # centre of curvature at (a tx, b ty)
        qx, qy = px - ex, py - ey
        ratio = np.hypot(a * tx - ex, b * ty - ey) / np.maximum(np.hypot(qx, qy), 1e-12)
        tx = np.minimum(np.maximum((qx * ratio + ex) / a, 0.0), 1.0)
        ty = np.minimum(np.maximum((qy * ratio + ey) / b, 0.0), 1.0)
        norm = np.hypot(tx, ty)
        tx, ty = tx / norm, ty / norm
    return np.stack([np.copysign(a * tx, local[..., 0]), np.copysign(b * ty, local[..., 1])], axis=-1)


def ray_segments(origins, directions, a, b):
    """Hit distances ``(R, M)`` of rays on segments a–b (2-D broadcasting, no (R, M, 2) temporaries)."""
    ex, ey = (b[:, 0] - a[:, 0])[None, :], (b[:, 1] - a[:, 1])[None, :]
    dx, dy = directions[:, 0:1], directions[:, 1:2]
    rx, ry = a[None, :, 0] - origins[:, 0:1], a[None, :, 1] - origins[:, 1:2]
    denom = dx * ey - dy * ex
    with np.errstate(divide="ignore", invalid="ignore"):
        inverse = 1.0 / denom
        t = (rx * ey - ry * ex) * inverse
        u = (rx * dy - ry * dx) * inverse
    hit = (t >= 0.0) & (u >= 0.0) & (u <= 1.0)  # parallel rays give inf/nan and fail these tests
    return np.where(hit, t, np.inf)


def _quadratic_first_hit(half_b, c, a=1.0):
    """Smallest t ≥ 0 solving a t² + 2 half_b t + c = 0 (inf when none)."""
    disc = half_b * half_b - a * c
    root = np.sqrt(np.maximum(disc, 0.0))
    t1 = (-half_b - root) / a
    t2 = (-half_b + root) / a
    t = np.where(t1 >= 0.0, t1, t2)
    return np.where((disc >= 0.0) & (t >= 0.0), t, np.inf)


def ray_circles(origins, directions, centers, radii):
    """Hit distances ``(R, C)`` of rays on circles (from inside: distance to the surface)."""
    f = origins[:, None, :] - centers[None, :, :]
    half_b = np.einsum("rck,rk->rc", f, directions)
    c = np.einsum("rck,rck->rc", f, f) - radii[None, :] ** 2
    return _quadratic_first_hit(half_b, c)


def ray_ellipses(origins, directions, centers, radii, angles):
    """Hit distances ``(R, E)`` of rays on ellipses: rays mapped to the ellipse frame, scaled to
    the unit circle, where |o' + t d'| = 1 is a quadratic in the same t."""
    o = ellipse_frame(origins, centers, angles) / radii[None, :, :]
    d = ellipse_frame(directions, np.zeros_like(centers), angles) / radii[None, :, :]
    a = np.einsum("rek,rek->re", d, d)
    half_b = np.einsum("rek,rek->re", o, d)
    c = np.einsum("rek,rek->re", o, o) - 1.0
    return _quadratic_first_hit(half_b, c, a)


def ray_box(origins, directions, width, height):
    """Distances ``(R,)`` from origins inside [0, W] × [0, H] to its sides along the rays."""
    with np.errstate(divide="ignore", invalid="ignore"):
        tx = np.where(directions[:, 0] > 0, (width - origins[:, 0]) / directions[:, 0],
                      np.where(directions[:, 0] < 0, -origins[:, 0] / directions[:, 0], np.inf))
        ty = np.where(directions[:, 1] > 0, (height - origins[:, 1]) / directions[:, 1],
                      np.where(directions[:, 1] < 0, -origins[:, 1] / directions[:, 1], np.inf))
    return np.maximum(np.minimum(tx, ty), 0.0)
