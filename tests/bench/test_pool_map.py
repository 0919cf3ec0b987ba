"""The process pool of ``evaluate``, ``bench``, ``demo`` and ``reproduce`` (:func:`pool_map`)."""

import time
from pathlib import Path

import pytest

from fuzzynav.bench.backends import pool_map


def _slow_unless_first(item: tuple[Path, int]) -> int:
    folder, index = item
    (folder / f"start-{index}").touch()
    if index == 0:
        raise ValueError("item 0 is broken")
    time.sleep(1.0)  # time for the caller to see item 0 fail while the others run
    (folder / f"end-{index}").touch()
    return index


def _markers(folder: Path, kind: str) -> set[int]:
    return {int(path.name.split("-")[1]) for path in folder.glob(f"{kind}-*")}


def test_results_come_back_for_every_item_with_its_index(tmp_path):
    items = [(tmp_path, i) for i in range(1, 12)]
    got = {}
    pool_map(_slow_unless_first, items, 3, got.__setitem__)
    assert got == {i: i + 1 for i in range(11)}


def test_an_item_that_fails_stops_the_items_not_started_and_keeps_the_others(tmp_path):
    items = [(tmp_path, i) for i in range(40)]  # 8 in flight at once (4 per worker)
    reported = {}
    with pytest.raises(ValueError, match="item 0 is broken"):
        pool_map(_slow_unless_first, items, 2, reported.__setitem__)
    started = _markers(tmp_path, "start")
    # item 0, the other worker's item and what the executor had queued, not all 8 in flight
    assert 0 in started and len(started) < 8, started
    assert _markers(tmp_path, "end") == started - {0}  # the error waited for the running ones
    assert set(reported.values()) == started - {0}  # and their results were handed over
    time.sleep(1.5)
    assert _markers(tmp_path, "start") == started  # nothing runs on behind the caller's back
