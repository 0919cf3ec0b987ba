"""Sensors with a beam width read the nearest echo inside their cone (kernels.beams): a thin post
between two ray directions is missed by the rays and seen by the beams; the lidar ring is 1° apart."""

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.robot.sensors import named_ring
from fuzzynav.world import World
from fuzzynav.world.shapes import Circle, Ellipse, Polygon

POST = Circle(np.array([5.0, 3.0]), 0.075)


def pose_seeing(point, bearing_deg, distance):
    """A pose from which ``point`` lies ``distance`` away at ``bearing_deg`` from the heading 0."""
    b = np.deg2rad(bearing_deg)
    return np.array([[point[0] - distance * np.cos(b), point[1] - distance * np.sin(b), 0.0]])


def test_beam_sees_a_post_between_two_ray_directions():
    post = Circle(np.array([10.0, 10.0]), 0.075)
    world = World(20.0, 20.0, (post,))
    pose = pose_seeing(post.center, 15.0, 3.0)  # halfway between the 0° and 30° sensors
    rays = named_ring("thesis").read(world, pose)[0]
    beams = named_ring("beam").read(world, pose)[0]
    assert np.all(rays[[0, 2]] == 4.0)  # the single rays pass either side of it
    assert beams[0] == pytest.approx(3.0 - 0.075) and beams[2] == pytest.approx(3.0 - 0.075)  # both cones touch it
    assert beams[1] == 4.0 and beams[3] == 4.0  # the right-hand cones do not


def test_beam_reading_is_the_nearest_echo_and_never_beyond_the_ray():
    world = World(12.0, 12.0, (POST, Circle(np.array([7.0, 7.0]), 0.5),
                               Polygon(np.array([[2.0, 8.0], [4.0, 8.0], [3.0, 10.0]])),
                               Ellipse(np.array([9.0, 3.0]), np.array([0.8, 0.3]), 0.4)))
    rng = np.random.default_rng(0)
    poses = np.column_stack([rng.uniform(1, 11, 200), rng.uniform(1, 11, 200), rng.uniform(-np.pi, np.pi, 200)])
    angles = np.deg2rad([0.0, 45.0, -120.0])
    rays = world.ranges(poses, angles, 4.0)
    beams = world.ranges(poses, angles, 4.0, beam_width=np.deg2rad(30.0))
    assert np.all(beams <= rays + 1e-12)
    fan = np.min([world.ranges(poses, angles + np.deg2rad(d), 4.0) for d in np.linspace(-15, 15, 301)], axis=0)
    np.testing.assert_allclose(beams, fan, atol=0.01)  # a dense fan of rays finds the same echo


def test_named_rings():
    assert named_ring("thesis").count == 7 and named_ring("thesis").beam_width == 0.0
    assert named_ring("beam").beam_width == pytest.approx(np.deg2rad(30.0))
    lidar = named_ring("lidar")
    assert lidar.count == 271 and np.allclose(np.diff(np.rad2deg(lidar.angles)), 1.0)
    with pytest.raises(InputError, match="sensors"):
        named_ring("sonar")
