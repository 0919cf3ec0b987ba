"""Fields given a value that only looks empty — ``0``, ``false``, ``''``, ``{}``, ``[]`` — where a
list or a choice goes. Such a value was taken for the field's absence: ``obstacles: 0`` ran a
world without obstacles, ``defuzzifier: false`` in a fuzzy system file ran the method's default
(a weighted average, where the file's rules were written for a weighted sum), and a scenario
``name: ''`` named its runs and plots with nothing. Refused now; a field that is absent or
``null`` still takes its default.

The cases run as those of ``cases.py`` do (``test_hostile_corpus.py``)."""

from __future__ import annotations

import pytest

from tests.validation.hostile_cases import Case

from .test_hostile_corpus import test_hostile_case as run_case

SCENARIO = "world: {width: 20, height: 20}\nrobot: {x: 1, y: 1}\ngoal: {x: 15, y: 15}\n"
RUN = ("run", "{d}/s.yaml", "--controller", "goal-seeking", "--max-time", "1", "--json")

# one input of two triangles that are not a strong partition: at x = 0.25 only rule 1 fires, at 0.5,
# so a weighted sum answers 0.5 and a weighted average 1.0
SYSTEM = """format: fuzzynav-fis
version: 1
method: ts0
defuzzifier: DEFUZZIFIER
inputs:
  - {name: x, universe: [0, 1], terms: {lo: {kind: triangle, params: [0, 0, 0.5]},
                                        hi: {kind: triangle, params: [0.5, 1, 1]}}}
outputs:
  - {name: y, universe: [0, 2], terms: {a: {kind: singleton, params: [1]}, b: {kind: singleton, params: [2]}}}
rules: [IF x IS lo THEN y IS a, IF x IS hi THEN y IS b]
"""
EVAL = ("fis", "eval", "{d}/f.yaml", "--input", "x=0.25")

CASES = [
    *[Case(f"scenario-obstacles-{label}", {"s.yaml": SCENARIO + f"obstacles: {value}\n"}, RUN,
           expect=f"s.yaml: obstacles: must be a list, got {kind}")
      for label, value, kind in (("zero", "0", "int"), ("false", "false", "bool"), ("empty-text", "''", "str"),
                                 ("empty-mapping", "{}", "dict"))],
    *[Case(f"scenario-obstacles-{label}-ok", {"s.yaml": SCENARIO + f"obstacles: {value}\n"}, RUN, status=0,
           expect='"outcome": "timeout"') for label, value in (("null", ""), ("empty-list", "[]"))],
    *[Case(f"fuzzy-yaml-defuzzifier-{label}", {"f.yaml": SYSTEM.replace("DEFUZZIFIER", value)}, EVAL,
           expect=f"f.yaml: defuzzifier: must be one of weighted_sum, weighted_average, got {shown}")
      for label, value, shown in (("zero", "0", "0"), ("false", "false", "False"), ("empty-text", "''", "''"),
                                  ("empty-list", "[]", "[]"))],
    # an empty name ran as " / goal-seeking" and drew "_--goal-seeking.png"; absent, the file's stem names it
    *[Case(f"scenario-name-{label}", {"s.yaml": SCENARIO + f"name: {value}\n"}, RUN, expect="s.yaml: name: must not be empty")
      for label, value in (("empty", "''"), ("blank", "'  '"))],
    Case("scenario-name-absent-is-the-file-stem", {"s.yaml": SCENARIO}, RUN, status=0, expect='"scenario": "s"'),
    Case("fuzzy-yaml-defuzzifier-weighted-sum", {"f.yaml": SYSTEM.replace("DEFUZZIFIER", "weighted_sum")}, EVAL,
         status=0, expect='{"y": 0.5}'),
    Case("fuzzy-yaml-defuzzifier-null-is-the-default", {"f.yaml": SYSTEM.replace("DEFUZZIFIER", "null")}, EVAL,
         status=0, expect='{"y": 1.0}'),
]


@pytest.mark.parametrize("case", CASES, ids=[case.name for case in CASES])
def test_falsy_field_case(case, tmp_path, capsys):
    run_case(case, tmp_path, capsys)
