"""Fields given a value that only looks empty — ``0``, ``false``, ``''``, ``{}`` — where a list
goes. Such a value was taken for the field's absence: ``obstacles: 0`` ran a world without
obstacles. Refused now; a field that is absent or ``null`` still takes its default.

The cases run as those of ``cases.py`` do (``test_hostile_corpus.py``)."""

from __future__ import annotations

import pytest

from tests.validation.hostile_cases import Case

from .test_hostile_corpus import test_hostile_case as run_case

SCENARIO = "world: {width: 20, height: 20}\nrobot: {x: 1, y: 1}\ngoal: {x: 15, y: 15}\n"
RUN = ("run", "{d}/s.yaml", "--controller", "goal-seeking", "--max-time", "1", "--json")

CASES = [
    *[Case(f"scenario-obstacles-{label}", {"s.yaml": SCENARIO + f"obstacles: {value}\n"}, RUN,
           expect=f"s.yaml: obstacles: must be a list, got {kind}")
      for label, value, kind in (("zero", "0", "int"), ("false", "false", "bool"), ("empty-text", "''", "str"),
                                 ("empty-mapping", "{}", "dict"))],
    *[Case(f"scenario-obstacles-{label}-ok", {"s.yaml": SCENARIO + f"obstacles: {value}\n"}, RUN, status=0,
           expect='"outcome": "timeout"') for label, value in (("null", ""), ("empty-list", "[]"))],
]


@pytest.mark.parametrize("case", CASES, ids=[case.name for case in CASES])
def test_falsy_field_case(case, tmp_path, capsys):
    run_case(case, tmp_path, capsys)
