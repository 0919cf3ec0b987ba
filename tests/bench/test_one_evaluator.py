"""One evaluator: ``fuzzynav evaluate`` (bench.evaluate) and a campaign's cells (bench.cells) build
their controllers with the same maker and run the same episodes, so the same controller on the
same generated worlds under the same seed gives the same outcomes, times and paths in both."""

import pytest

from fuzzynav.bench.cells import Cell, controller_maker, run_cell
from fuzzynav.bench.evaluate import evaluate
from fuzzynav.bench.stats import rate, summarise
from fuzzynav.bench.suites import parse_suite
from fuzzynav.errors import InputError
from fuzzynav.robot.tricycle import DEFAULT_PARAMS


def test_evaluate_and_a_campaign_give_the_same_runs():
    result = evaluate("fuzzy-2b", "circles", 2, seed=3)
    suite = parse_suite("circles:2:3")
    rows = [row for index in range(2)
            for row in run_cell(Cell(suite, index, 0, (("fuzzy-2b", "fuzzy-2b"),), DEFAULT_PARAMS.radius))]
    assert [run["scenario"] for run in result["episodes"]] == [row["world"] for row in rows]
    for run, row in zip(result["episodes"], rows, strict=True):
        assert (run["outcome"], run["time_s"], run["path_length_m"]) == (row["outcome"], row["time_s"],
                                                                        row["path_length_m"])
    summary = summarise(rows)[0]
    assert result["success_rate"] == summary["reached"]["rate"]
    assert result["collision_rate"] == summary["collision"]["rate"]


def test_the_maker_builds_a_fresh_controller_each_call_and_wants_one_source():
    make = controller_maker("fuzzy-2b")
    assert make.name == "fuzzy-2b" and make() is not make()
    with pytest.raises(InputError, match="exactly one"):
        controller_maker()
    with pytest.raises(InputError, match="exactly one"):
        controller_maker("fuzzy-2b", model="q.json")


def test_rate_is_the_share_of_an_outcome():
    assert rate(["reached", "collision", "reached", "timeout"], "reached") == 0.5


def test_evaluate_gives_the_same_result_whatever_the_workers():
    """Every world is drawn and run alone in a worker; the episodes come back in world order."""
    one = evaluate("fuzzy-2b", "mixed", 5, seed=4, workers=1)
    calls = []
    three = evaluate("fuzzy-2b", "mixed", 5, seed=4, workers=3, progress=lambda i, run: calls.append(i))
    assert three == one
    assert [run["scenario"] for run in three["episodes"]] == [f"mixed-4-{i:03d}" for i in range(5)]
    assert sorted(calls) == list(range(5))
