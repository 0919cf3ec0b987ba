"""The process pool of ``evaluate``, ``bench``, ``demo`` and ``reproduce`` (:func:`pool_map`)."""

import time
from pathlib import Path

import pytest

from fuzzynav.bench.backends import pool_map


def _slow_unless_first(item: tuple[Path, int]) -> int:
    folder, index = item
    (folder / str(index)).touch()
    if index == 0:
        raise ValueError("item 0 is broken")
    time.sleep(0.5)
    return index


def test_results_come_back_for_every_item_with_its_index(tmp_path):
    items = [(tmp_path, i) for i in range(1, 12)]
    got = {}
    pool_map(_slow_unless_first, items, 3, got.__setitem__)
    assert got == {i: i + 1 for i in range(11)}


def test_an_item_that_fails_stops_the_items_not_started(tmp_path):
    items = [(tmp_path, i) for i in range(40)]  # 8 in flight at once (4 per worker)
    with pytest.raises(ValueError, match="item 0 is broken"):
        pool_map(_slow_unless_first, items, 2, lambda index, result: None)
    started = len(list(tmp_path.iterdir()))
    assert started <= 4, started  # item 0, the other worker's item, at most one more each
