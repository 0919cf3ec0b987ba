"""The dense and utrap families of world/generate.py."""

import hashlib
import json

import numpy as np
import pytest

from fuzzynav.world.generate import TURNING_MARGIN, connected, generate_world, generate_worlds
from fuzzynav.world.shapes import Wall


@pytest.mark.parametrize("kind", ("dense", "utrap"))
def test_worlds_are_solvable_and_reproducible(kind):
    worlds = generate_worlds(kind, 5, 7)
    for i, scenario in enumerate(worlds):
        assert connected(scenario.world, scenario.start[:2], scenario.goal.position, 0.3 + TURNING_MARGIN)
        assert generate_world(kind, 7, i).to_dict() == scenario.to_dict()
        assert np.hypot(*(scenario.goal.position - scenario.start[:2])) >= 10


def test_dense_has_more_obstacles_than_mixed():
    dense = [len(s.world.obstacles) for s in generate_worlds("dense", 10, 0)]
    mixed = [len(s.world.obstacles) for s in generate_worlds("mixed", 10, 0)]
    assert min(dense) >= 12 and max(dense) <= 20
    assert np.mean(dense) > np.mean(mixed) + 3


def test_utrap_walls_block_the_straight_line_to_the_goal():
    for scenario in generate_worlds("utrap", 5, 0):
        walls = [o for o in scenario.world.obstacles if isinstance(o, Wall)]
        assert len(walls) >= 3
        line = scenario.start[:2] + np.linspace(0, 1, 400)[:, None] * (scenario.goal.position - scenario.start[:2])
        assert (scenario.world.clearance(line) < 0).any(), scenario.name


def test_existing_families_unchanged_by_the_new_ones():
    """World i depends only on (kind, seed, i); circles and mixed draw the worlds they drew before
    dense and utrap existed (digests of world 0 from the generator without them)."""
    assert generate_world("mixed", 0, 3).to_dict() == generate_worlds("mixed", 4, 0)[3].to_dict()
    digest = lambda s: hashlib.sha1(json.dumps(s.to_dict(), sort_keys=True).encode()).hexdigest()
    assert digest(generate_world("circles", 0, 0)) == "bc90e75c05018cc02368b1790705b256640fa04d"
    assert digest(generate_world("mixed", 0, 0)) == "30043108d45ad136e5cfb007fae6c37e22d80865"
