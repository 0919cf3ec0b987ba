"""The default ``fuzzy-5b`` decides as before its kernels were made cheaper (gap finding by runs
of blocked directions, the car route's search nodes in a hash table): the same outcome, step
count and behaviour labels, and the same final pose, on generated worlds
(tests/control/default_episodes.py recorded them with the earlier kernels)."""

import json

import pytest

from tests.control.default_episodes import FILE, run_all


def test_fuzzy_5b_drives_as_recorded_before_the_cheaper_kernels():
    recorded = json.loads(FILE.read_text())
    runs = run_all()
    assert set(runs) == set(recorded) and len(runs) == 6
    for world, (outcome, steps, labels, pose) in runs.items():
        assert [outcome, steps, labels] == recorded[world][:3], world
        assert pose == pytest.approx(recorded[world][3], abs=1e-6), world
