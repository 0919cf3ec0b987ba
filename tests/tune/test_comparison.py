"""``cmp-VI-tuning``: a short comparison runs every tuner and FQL on held-out worlds and its claim
turns the numbers into checks (one success and one collision check per method)."""

import pytest

from fuzzynav.catalog.experiments import spec
from fuzzynav.experiments.tuning import cmp_vi_tuning


@pytest.mark.slow
def test_a_short_comparison_gives_every_method_its_held_out_numbers_and_checks(tmp_path):
    numbers = cmp_vi_tuning(tmp_path, tasks=("goal",), seeds=1, episodes=400)
    rows = numbers["tasks"]["goal"]["rows"]
    assert set(rows) == {"hand-made", "ga", "pso", "aco", "fql"}
    for seeds in rows.values():
        assert 0.0 <= seeds[0]["success"] <= 1.0 and seeds[0]["collisions"] >= 0
    assert (tmp_path / "cmp-VI-tuning.png").stat().st_size > 0
    hand_made = numbers["tasks"]["goal"]["tables"]["hand-made"]
    assert hand_made[1].split("|")[1].split() == ["PM/Z", "PG/F", "PM/F", "PM/F", "PM/F"]  # Table IV.1, row NG
    verdict, checks = spec("cmp-VI-tuning").claim.evaluate(numbers)
    assert len(checks) == 2 * 4 and all(check.source == "package" for check in checks)
    assert verdict in ("reproduced", "partly", "not reproduced")
