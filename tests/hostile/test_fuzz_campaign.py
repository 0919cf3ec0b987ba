"""Hypothesis-tampered campaign rows: a resume keeps a row only if it is a valid run of its own
plan, refuses anything else with an InputError naming the line and field, and never crashes."""

from __future__ import annotations

import json
import shutil

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from fuzzynav.bench.campaign import COLUMNS, Plan, run_campaign
from fuzzynav.bench.stored import check_row
from fuzzynav.bench.suites import parse_suite
from fuzzynav.errors import InputError

PLAN = Plan((parse_suite("circles:1"),), (("goal-seeking", "goal-seeking"),), 1, 0.3)
JSON_VALUES = st.recursive(st.none() | st.booleans() | st.floats() | st.integers(-10**30, 10**30) | st.text(max_size=8),
                           lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=3), inner,
                                                                                        max_size=3), max_leaves=5)


@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    out = tmp_path_factory.mktemp("campaign") / "out"
    run_campaign(PLAN, out, progress=False)
    return out


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(column=st.sampled_from(COLUMNS), value=JSON_VALUES)
def test_tampered_row_is_kept_only_when_valid(finished, tmp_path, column, value):
    out = tmp_path / "out"
    shutil.rmtree(out, ignore_errors=True)
    shutil.copytree(finished, out)
    row = json.loads((out / "runs.jsonl").read_text().splitlines()[0])
    row[column] = value
    (out / "runs.jsonl").write_text(json.dumps(row) + "\n")
    try:
        rows = run_campaign(PLAN, out, resume=True, progress=False)
    except InputError as error:
        assert "runs.jsonl: line 1" in str(error)
        return
    assert len(rows) == 1
    check_row(rows[0], COLUMNS, "runs.jsonl", "line 1")
    assert (rows[0]["suite"], rows[0]["world"], rows[0]["seed"], rows[0]["controller"]) in PLAN.order()
