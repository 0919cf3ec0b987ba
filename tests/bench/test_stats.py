"""Wilson intervals and the per controller × suite summary (bench/stats.py)."""

import pytest

from fuzzynav.bench.stats import summarise, wilson


@pytest.mark.parametrize("k, n, low, high", [
    (0, 10, 0.0, 0.27753), (5, 10, 0.23659, 0.76341), (10, 10, 0.72247, 1.0), (95, 100, 0.88825, 0.97846)])
def test_wilson_matches_published_values(k, n, low, high):
    """Values of the Wilson score interval (z = 1.96), e.g. Newcombe, Stat. Med. 17 (1998), Table I."""
    assert wilson(k, n) == pytest.approx((low, high), abs=2e-5)


def test_summary_rates_and_medians():
    row = lambda outcome, time, ratio: {"suite": "s", "controller": "c", "outcome": outcome, "time_s": time,
                                        "path_ratio": ratio, "min_clearance_m": 0.5, "steering_effort_rad": 0.1,
                                        "barn_score": None}
    rows = [row("reached", 10.0, 1.1), row("reached", 20.0, 1.3), row("timeout", 120.0, None),
            row("collision", 5.0, None)]
    (record,) = summarise(rows)
    assert record["runs"] == 4
    assert record["reached"]["rate"] == 0.5 and record["collision"]["count"] == 1
    assert record["median_time_s"] == 15.0 and record["median_path_ratio"] == pytest.approx(1.2)
    assert record["mean_barn_score"] is None
