"""Tracks of moving obstacles from successive scans and their time to collision
(control/sighting_tracks.py)."""

import numpy as np
import pytest

from fuzzynav.control.sighting_tracks import CONFIRM, MEMORY, SightingTracks, clusters
from fuzzynav.kernels.scan_tracks import first_contact

DT = 0.1


def _scan(centre, radius=0.4, beams=361):
    """Echoes (beams, 2) of a disc seen from the origin over 360°, and which beams hit it."""
    here = np.zeros(2)
    angles = np.linspace(-np.pi, np.pi, beams)
    d = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    m = d @ (centre - here)
    disc = m * m - (np.sum((centre - here) ** 2) - radius * radius)
    hit = (disc >= 0) & (m > 0)
    r = np.where(hit, m - np.sqrt(np.maximum(disc, 0)), 8.0)
    return here + r[:, None] * d, hit


def test_a_crossing_disc_is_tracked_with_its_velocity_and_predicted_out_of_sight():
    tracks = SightingTracks()
    velocity = np.array([0.0, 1.2])
    for k in range(12):
        centre = np.array([3.0, -3.0]) + velocity * k * DT
        points, hit = _scan(centre)
        tracks.update(k * DT, points, hit, np.zeros(2))
    (track,) = tracks.tracks
    assert track.confirmed and len(track.times) >= CONFIRM
    np.testing.assert_allclose(track.velocity, velocity, atol=0.05)
    truth = np.array([3.0, -3.0]) + velocity * 1.1
    assert np.hypot(*(track.predict(1.1) - truth)) < 0.25  # the centre, from the near side's echoes
    # it walks towards the path of a robot driving along x at 2.5 m/s: a collision ahead
    ttc, bearing = tracks.time_to_collision(1.1, np.array([0.0, 0.0, 0.0]), 2.5, 0.3)
    assert 0.0 < ttc < 2.0 and -np.pi / 2 < bearing < 0.0  # ahead on the right, where it comes from
    # a robot standing still far off its line is never reached
    assert tracks.time_to_collision(1.1, np.array([0.0, -6.0, 0.0]), 0.0, 0.3)[0] == np.inf
    # out of sight (no echo moved) it is still predicted, then forgotten after MEMORY s
    empty = np.zeros(361, dtype=bool)
    tracks.update(1.1 + MEMORY / 2, points, empty, np.zeros(2))
    assert len(tracks.tracks) == 1
    tracks.update(1.1 + 1.5 * MEMORY, points, empty, np.zeros(2))
    assert tracks.tracks == []


def test_standing_echoes_make_no_track():
    points, hit = _scan(np.array([2.0, 1.0]))
    assert clusters(points, np.zeros(len(points), dtype=bool), np.zeros(2)) == []
    tracks = SightingTracks()
    for k in range(10):
        tracks.update(k * DT, points, np.zeros(len(points), dtype=bool), np.zeros(2))
    assert tracks.tracks == []


@pytest.mark.parametrize("p, w, reach, expected", [
    ((5.0, 0.0), (-1.0, 0.0), 1.0, 4.0),        # head-on at 1 m/s: contact when 1 m apart
    ((5.0, 0.0), (1.0, 0.0), 1.0, np.inf),      # going away
    ((5.0, 2.0), (-1.0, 0.0), 1.0, np.inf),     # passes 2 m off: misses
    ((0.5, 0.0), (1.0, 0.0), 1.0, 0.0),         # already within reach
    ((3.0, 4.0), (-0.6, -0.8), 2.0, 3.0),       # straight at it at 1 m/s from 5 m
])
def test_first_contact_is_the_collision_cone_in_closed_form(p, w, reach, expected):
    assert first_contact(*p, *w, reach) == pytest.approx(expected)
