"""Wilson intervals and the per controller × suite summary (bench/stats.py)."""

import pytest

from fuzzynav.bench.stats import summarise, wilson


@pytest.mark.parametrize("k, n, low, high", [
    (0, 10, 0.0, 0.27753), (5, 10, 0.23659, 0.76341), (10, 10, 0.72247, 1.0), (95, 100, 0.88825, 0.97846)])
def test_wilson_matches_published_values(k, n, low, high):
    """Values of the Wilson score interval (z = 1.96), e.g. Newcombe, Stat. Med. 17 (1998), Table I."""
    assert wilson(k, n) == pytest.approx((low, high), abs=2e-5)


def test_summary_rates_and_medians():
    def row(outcome, time, ratio, clearance, effort, controller="c", by=None):
        return {"suite": "s", "controller": controller, "outcome": outcome, "time_s": time, "path_ratio": ratio,
                "min_clearance_m": clearance, "steering_effort_rad": effort, "barn_score": None, "collision_by": by}

    rows = [row("reached", 10.0, 1.1, 0.5, 0.1), row("collision", 3.0, None, -0.2, 0.4, "d", "obstacle"),
            row("reached", 20.0, 1.3, 0.7, 0.3), row("timeout", 120.0, None, 0.1, 0.2),
            row("collision", 5.0, None, -0.1, 0.6, by="robot")]
    record, other = summarise(rows)  # one record per suite x controller, in the order of the rows
    assert (record["controller"], record["runs"], other["controller"], other["runs"]) == ("c", 4, "d", 1)
    assert record["reached"]["rate"] == 0.5 and record["collision"]["count"] == 1
    assert record["collision"]["ci95"] == list(wilson(1, 4)) and record["timeout"]["ci95"] == list(wilson(1, 4))
    assert record["collision_at_fault"] == {"count": 1, "rate": 0.25, "ci95": list(wilson(1, 4))}
    assert other["collision_at_fault"]["count"] == 0  # run into by an obstacle: not the robot's fault
    # time and path ratio over the runs that reached the goal; clearance and steering over every run
    assert record["median_time_s"] == 15.0 and record["median_path_ratio"] == pytest.approx(1.2)
    assert record["median_min_clearance_m"] == pytest.approx(0.3) and record["median_steering_effort_rad"] == pytest.approx(0.25)
    assert other["median_time_s"] is None and other["median_min_clearance_m"] == -0.2
    assert record["mean_barn_score"] is None
