"""MATLAB .fis files: every membership function against its formula in the Fuzzy Logic Toolbox
reference (written out here independently), MATLAB's semantics, round trips, errors."""

import json
import math
import re

import numpy as np
import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.engine import Engine
from fuzzynav.fuzzy.fis_terms import term_from_fis, term_to_fis
from fuzzynav.fuzzy.io import dumps, load, loads
from fuzzynav.fuzzy.io.fis import from_fis
from fuzzynav.fuzzy.systems import get_system
from tests.hostile.cases import _FLL

FLL_DEFAULT = _FLL.replace("  default: nan", "  default: 0.25")  # x = 5: no rule fires

X = np.linspace(-3.0, 13.0, 3201)


def _sig(x, a, c):
    return 1.0 / (1.0 + np.exp(-a * (x - c)))


def _smf(x, a, b):
    m = (a + b) / 2
    return np.select([x <= a, x <= m, x <= b], [0.0, 2 * ((x - a) / (b - a)) ** 2, 1 - 2 * ((x - b) / (b - a)) ** 2], 1.0)


def _zmf(x, a, b):
    return 1.0 - _smf(x, a, b)


MATLAB = {  # name: (parameters, formula of the MATLAB reference page)
    "trimf": ([1.0, 4.0, 9.0], lambda x, a, b, c: np.maximum(np.minimum((x - a) / (b - a), (c - x) / (c - b)), 0)),
    "trapmf": ([0.0, 2.0, 5.0, 11.0],
               lambda x, a, b, c, d: np.maximum(np.minimum(np.minimum((x - a) / (b - a), 1), (d - x) / (d - c)), 0)),
    "gaussmf": ([1.7, 4.0], lambda x, s, c: np.exp(-((x - c) ** 2) / (2 * s * s))),
    "gauss2mf": ([1.0, 3.0, 2.0, 6.0], lambda x, s1, c1, s2, c2: np.where(x <= c1, np.exp(-((x - c1) ** 2) / (2 * s1 * s1)), 1)
                 * np.where(x >= c2, np.exp(-((x - c2) ** 2) / (2 * s2 * s2)), 1)),
    "gbellmf": ([2.0, 3.0, 5.0], lambda x, a, b, c: 1 / (1 + np.abs((x - c) / a) ** (2 * b))),
    "sigmf": ([2.0, 4.0], lambda x, a, c: _sig(x, a, c)),
    "dsigmf": ([5.0, 2.0, 5.0, 7.0], lambda x, a1, c1, a2, c2: np.abs(_sig(x, a1, c1) - _sig(x, a2, c2))),
    "psigmf": ([2.0, 3.0, -5.0, 8.0], lambda x, a1, c1, a2, c2: _sig(x, a1, c1) * _sig(x, a2, c2)),
    "smf": ([1.0, 8.0], _smf),
    "zmf": ([3.0, 7.0], _zmf),
    "pimf": ([1.0, 4.0, 5.0, 10.0], lambda x, a, b, c, d: _smf(x, a, b) * _zmf(x, c, d)),
    "linsmf": ([2.0, 6.0], lambda x, a, b: np.clip((x - a) / (b - a), 0, 1)),
    "linzmf": ([2.0, 6.0], lambda x, a, b: np.clip((b - x) / (b - a), 0, 1)),
}


@pytest.mark.parametrize("kind", list(MATLAB))
def test_membership_function_matches_matlab_formula(kind):
    params, formula = MATLAB[kind]
    label, mf = term_from_fis(f"'t':'{kind}',[{' '.join(map(str, params))}]", "t.fis", 1)
    assert label == "t"
    np.testing.assert_allclose(mf(X), formula(X, *params), rtol=0, atol=1e-12)
    # written back the same way
    assert term_to_fis(mf) == f"'{kind}',[{' '.join(repr(float(p)) for p in params)}]"


def test_constant_and_linear_conclusions():
    text = """[System]
Name='lin'
Type='sugeno'
NumInputs=2
NumOutputs=1
AndMethod='prod'
OrMethod='probor'
DefuzzMethod='wtaver'

[Input1]
Name='a'
Range=[0 1]
MF1='lo':'trimf',[-1 0 1]
MF2='hi':'trimf',[0 1 2]

[Input2]
Name='b'
Range=[0 2]
MF1='all':'trapmf',[-1 0 2 3]

[Output1]
Name='y'
Range=[-10 10]
MF1='c':'constant',[2.5]
MF2='l':'linear',[1 -2 0.5]

[Rules]
1 1, 1 (1) : 1
2 0, 2 (0.5) : 1
"""
    system = loads(text, "fis", source="lin.fis")
    a, b = 0.3, 1.2
    w1, w2 = 0.7, 0.5 * 0.3
    expected = (w1 * 2.5 + w2 * (a - 2 * b + 0.5)) / (w1 + w2)
    assert system.evaluate_one(a, b)[0] == pytest.approx(expected, abs=1e-14)


MAMDANI = """[System]
Name='tip'
Type='mamdani'
Version=2.0
NumInputs=1
NumOutputs=1
NumRules=2
AndMethod='min'
OrMethod='max'
ImpMethod='min'
AggMethod='max'
DefuzzMethod='centroid'

[Input1]
Name='service'
Range=[0 10]
NumMFs=2
MF1='poor':'trapmf',[0 0 2 6]
MF2='good':'trapmf',[4 8 10 10]

[Output1]
Name='tip'
Range=[0 30]
NumMFs=2
MF1='low':'trimf',[0 5 15]
MF2='high':'trimf',[10 25 30]

[Rules]
1, 1 (1) : 1
-2, 2 (0.5) : 1
"""


def test_matlab_semantics():
    system = loads(MAMDANI, "fis", source="tip.fis")
    assert isinstance(system, Engine)
    # MATLAB: the output sampled at 101 points from end to end (evalfis' default), clipped by min, max-aggregated
    s = 5.0
    poor, good = max(0, min(1, (6 - s) / 4)), max(0, min(1, (s - 4) / 4))
    w = [poor, 0.5 * (1 - good)]  # rule 2: NOT good, weight 0.5
    y = np.linspace(0, 30, 101)
    low = np.maximum(np.minimum((y - 0) / 5, (15 - y) / 10), 0)
    high = np.maximum(np.minimum((y - 10) / 15, (30 - y) / 5), 0)
    mu = np.maximum(np.minimum(w[0], low), np.minimum(w[1], high))
    assert system.evaluate_one(s)[0] == pytest.approx((mu * y).sum() / mu.sum(), abs=1e-12)
    # MATLAB: no rule fires -> the middle of the output range (fuzzylite's reading: NaN)
    only_not_good = MAMDANI.replace("[Rules]\n1, 1 (1) : 1\n", "[Rules]\n").replace("NumRules=2", "NumRules=1")
    matlab = loads(only_not_good, "fis", source="tip.fis")
    assert matlab.evaluate_one(2.0)[0] != 15.0  # good = 0: "not good" fires
    assert matlab.evaluate_one(10.0)[0] == 15.0  # good = 1: nothing fires
    assert math.isnan(from_fis(only_not_good, semantics="fuzzylite").evaluate_one(10.0)[0])
    # inputs are not clipped: at 40 "good" (trapmf [4 8 10 10]) is 0, so "not good" fires as at 2
    # (clipped to 10, nothing would fire)
    assert matlab.evaluate_one(40.0) == matlab.evaluate_one(2.0)


def test_matlab_bisector_is_the_first_sample_reaching_half_the_area():
    """MATLAB's bisector (``defuzzBisector`` of its fis.c): the first of the 101 samples where the
    running area reaches half of it; fuzzylite's (which this reader gave): the sample closest to
    half. fuzzylite cannot compute MATLAB's, so it is not written as .fll."""
    system = loads(MAMDANI.replace("DefuzzMethod='centroid'", "DefuzzMethod='bisector'"), "fis", source="tip.fis")
    y = np.linspace(0, 30, 101)
    low = np.maximum(np.minimum((y - 0) / 5, (15 - y) / 10), 0)
    high = np.maximum(np.minimum((y - 10) / 15, (30 - y) / 5), 0)
    for s in (0.5, 3.0, 4.6, 5.0, 5.5, 7.3):
        poor, good = max(0, min(1, (6 - s) / 4)), max(0, min(1, (s - 4) / 4))
        mu = np.maximum(np.minimum(poor, low), np.minimum(0.5 * (1 - good), high))
        assert system.evaluate_one(s)[0] == pytest.approx(y[np.argmax(np.cumsum(mu) >= mu.sum() / 2)], abs=1e-12), s
    with pytest.raises(InputError, match="tip: its Bisector is MATLAB.s"):
        dumps(system, "fll")


@pytest.mark.parametrize("method,pick", [("som", np.argmin), ("lom", np.argmax)])
def test_matlab_smallest_and_largest_of_maximum_are_by_magnitude(method, pick):
    """MATLAB's som / lom (``defuzzSmallestOfMax`` of its fis.c): the maximizing sample smallest /
    largest in magnitude, the first on ties; fuzzylite's (which this reader gave): in value. They
    differ on an output range below 0, and such a one is not written as .fll."""
    text = (MAMDANI.replace("DefuzzMethod='centroid'", f"DefuzzMethod='{method}'").replace("Range=[0 30]", "Range=[-30 0]")
            .replace("'trimf',[0 5 15]", "'trimf',[-15 -5 0]").replace("'trimf',[10 25 30]", "'trimf',[-30 -25 -10]"))
    system = loads(text, "fis", source="tip.fis")
    y = np.linspace(-30, 0, 101)
    low = np.maximum(np.minimum((y + 15) / 10, -y / 5), 0)
    high = np.maximum(np.minimum((y + 30) / 5, (-10 - y) / 15), 0)
    for s in (0.5, 3.0, 5.5, 7.3):
        poor, good = max(0, min(1, (6 - s) / 4)), max(0, min(1, (s - 4) / 4))
        mu = np.maximum(np.minimum(poor, low), np.minimum(0.5 * (1 - good), high))
        top = np.flatnonzero(mu == mu.max())
        assert system.evaluate_one(s)[0] == pytest.approx(y[top[pick(np.abs(y[top]))]], abs=1e-12), s
    with pytest.raises(InputError, match="is MATLAB's"):
        dumps(system, "fll")


def test_round_trips(tmp_path):
    system = loads(MAMDANI, "fis", source="tip.fis")
    text = dumps(system, "fis")
    again = loads(text, "fis", source="again.fis")
    x = np.linspace(-2, 12, 301)[:, None]
    np.testing.assert_array_equal(again.evaluate(x), system.evaluate(x))
    assert dumps(again, "fis") == text
    # a .fis read MATLAB's way and written as FLL computes the same in fuzzylite terms
    fll = loads(dumps(system, "fll"), "fll", source="x.fll")
    np.testing.assert_allclose(fll.evaluate(x), system.evaluate(x), rtol=0, atol=1e-12)
    # the thesis' systems as .fis (open shoulders as linzmf / linsmf) and back
    gsb = get_system("goal-seeking")
    path = tmp_path / "gsb.fis"
    assert main(["fis", "convert", "goal-seeking", "--to", "fis", "-o", str(path)]) == 0
    assert "'linzmf',[0.1 3.5]" in path.read_text()
    X = np.random.default_rng(1).uniform([0, -3], [28, 3], (500, 2))
    np.testing.assert_allclose(load(path).evaluate(X), gsb.evaluate(X), rtol=0, atol=1e-12)


@pytest.mark.parametrize("name", ["obstacle-avoidance", "goal-seeking", "tracking"])
def test_a_fis_round_trip_answers_as_before_outside_the_ranges_too(name, tmp_path):
    """The inputs' clipping to their range (lock-range) and the outputs' default travel in the
    .fis file (fuzzylite's keys), so the written file answers as the system everywhere."""
    path = tmp_path / f"{name}.fis"
    assert main(["fis", "convert", name, "--to", "fis", "-o", str(path)]) == 0
    system, again = get_system(name), load(path)
    assert type(again) is type(system)  # a FuzzySystem again, which a controller's role takes (--fis)
    _only_keys_other_readers_take(path.read_text())
    lo, hi = np.array([v.universe for v in system.inputs]).T
    wide = lo - (hi - lo), hi + (hi - lo)  # a third inside the ranges, the rest outside
    X = np.random.default_rng(2).uniform(*wide, (600, len(lo)))
    np.testing.assert_allclose(again.evaluate(X), system.evaluate(X), rtol=0, atol=1e-12)


def _only_keys_other_readers_take(text: str) -> None:
    """The keys of each section outside comments are ones fuzzylite's FisImporter takes (MATLAB's,
    and an output's LockRange, LockPrevious and a numeric Default); the package's others are in
    ``% fuzzynav:`` comments."""
    section, allowed = None, {"Input": set(), "Output": {"LockRange", "LockPrevious", "Default"}}
    for line in text.splitlines():
        line = line.split("%", 1)[0].strip()
        if line.startswith("["):
            section = line.strip("[]").rstrip("0123456789")
        elif line and section in allowed:
            key, _, value = line.partition("=")
            assert key in {"Name", "Enabled", "Range", "NumMFs"} | allowed[section] or key.startswith("MF"), line
            assert key != "Default" or math.isfinite(float(value)), line


def test_a_fis_file_written_from_a_role_drives_its_controller_as_the_role(tmp_path, capsys):
    path = tmp_path / "gsb.fis"
    assert main(["fis", "convert", "goal-seeking", "--to", "fis", "-o", str(path)]) == 0
    runs = []
    for extra in ([], ["--fis", f"gsb={path}"]):
        assert main(["run", "fig-IV-23", "--controller", "goal-seeking", "--json", *extra]) == 0
        runs.append(json.loads(capsys.readouterr().out))
    assert runs[1]["outcome"] == runs[0]["outcome"] and runs[1]["time_s"] == runs[0]["time_s"]


HAND = """Engine: hand
InputVariable: a
  range: 0 10
  term: lo Triangle 0 0 6
  term: hi Triangle 4 10 10
OutputVariable: y
  range: 0 100
  aggregation: Maximum
  defuzzifier: Centroid 1000
  default: nan
  term: s Triangle 0 0 37
  term: l Triangle 33 100 100
RuleBlock: rb
  conjunction: Minimum
  implication: Minimum
  rule: if a is lo then y is s
  rule: if a is hi then y is l
"""


def test_a_centroids_samples_travel_in_the_fis_file():
    """fuzzylite's 1,000 midpoints were read back on MATLAB's 101 end-to-end points: 14.48 for
    14.74 at a = 3.3, silently. They travel as comments now; MATLAB's own stay unwritten."""
    system = loads(HAND, "fll", source="hand.fll")
    text = dumps(system, "fis")
    assert "% fuzzynav: Resolution=1000\n% fuzzynav: Grid=midpoints" in text
    again = loads(text, "fis", source="hand.fis")
    X = np.linspace(0, 10, 201)[:, None]
    np.testing.assert_array_equal(again.evaluate(X), system.evaluate(X))
    assert again.evaluate([[3.3]])[0, 0] == pytest.approx(14.740366328753357, abs=1e-12)
    matlab = loads(text.replace("% fuzzynav: Resolution=1000\n% fuzzynav: Grid=midpoints\n", ""), "fis", source="m.fis")
    assert "Resolution" not in dumps(matlab, "fis")  # MATLAB's 101 points need no comment
    through_fll = loads(dumps(loads(dumps(matlab, "fll"), "fll", source="m.fll"), "fis"), "fis", source="m2.fis")
    np.testing.assert_allclose(through_fll.evaluate(X), matlab.evaluate(X), rtol=0, atol=1e-12)
    one = loads(text.replace("Resolution=1000", "Resolution=1"), "fis", source="one.fis")  # fuzzylite's Centroid 1
    np.testing.assert_array_equal(loads(dumps(one, "fis"), "fis", source="again.fis").evaluate(X), one.evaluate(X))
    with pytest.raises(InputError, match="Resolution=1 samples one point: only with Grid=midpoints"):
        loads(text.replace("Resolution=1000", "Resolution=1").replace("Grid=midpoints", "Grid=linspace"), "fis",
              source="b.fis")
    for bad, problem in (("Resolution=0", "whole number of samples"), ("Grid=cells", "one of midpoints, linspace")):
        with pytest.raises(InputError, match=problem):
            loads(text.replace("Resolution=1000" if bad.startswith("R") else "Grid=midpoints", bad), "fis",
                  source="b.fis")


def test_an_outputs_default_travels_in_the_fis_file():
    fll = FLL_DEFAULT
    system = loads(fll, "fll", source="d.fll")
    again = loads(dumps(system, "fis"), "fis", source="d.fis")
    X = np.array([[5.0], [0.5]])  # x = 5: no rule fires, the default answers
    np.testing.assert_allclose(again.evaluate(X), system.evaluate(X), rtol=0, atol=1e-12)
    assert system.evaluate(X)[0, 0] == 0.25


@pytest.mark.parametrize(("edit", "refusal"), [
    (("activation: General", "activation: Highest 1"), r"activation: the rule block's activation is Highest 1"),
    (("activation: General", "activation: Threshold >= 0.5"), r"activation: the rule block's activation is Threshold"),
    (("  enabled: true", "  enabled: false"), r"drg: drg is disabled \(enabled: false\)"),  # the first input
])
def test_what_a_fis_file_cannot_hold_is_refused_not_dropped(edit, refusal, tmp_path, capsys):
    # written without it, the file answered otherwise than the engine it came from (the conversion said nothing)
    assert main(["fis", "convert", "goal-seeking", "--to", "fll", "-o", str(tmp_path / "g.fll")]) == 0
    text = (tmp_path / "g.fll").read_text()
    assert edit[0] in text
    (tmp_path / "e.fll").write_text(text.replace(edit[0], edit[1], 1))
    capsys.readouterr()
    assert main(["fis", "convert", str(tmp_path / "e.fll"), "--to", "fis", "-o", str(tmp_path / "e.fis")]) == 2
    assert re.search(rf"e\.fll: {refusal}.*write it as fll$", capsys.readouterr().err.strip())
    assert not (tmp_path / "e.fis").exists()
    assert main(["fis", "convert", str(tmp_path / "e.fll"), "--to", "json", "-o", str(tmp_path / "e.json")]) == 2
    assert capsys.readouterr().err.strip().endswith("does not hold (per-output settings, hedges, OR, several rule "
                                                    "blocks...): write it as fll")  # not "or fis"


def test_errors_name_file_line_and_field(tmp_path):
    bad = MAMDANI.replace("MF2='high':'trimf',[10 25 30]", "MF2='high':'blobmf',[10 25 30]")
    with pytest.raises(InputError, match=r"t\.fis: line 26: high: unknown membership function 'blobmf'"):
        loads(bad, "fis", source="t.fis")
    with pytest.raises(InputError, match=r"t\.fis: line 30 \(tip\): term 3 of tip does not exist"):
        loads(MAMDANI.replace("-2, 2 (0.5) : 1", "-2, 3 (0.5) : 1"), "fis", source="t.fis")
    with pytest.raises(InputError, match=r"t\.fis: line \d+ \(AndMethod\): unknown AndMethod 'avg'"):
        loads(MAMDANI.replace("AndMethod='min'", "AndMethod='avg'"), "fis", source="t.fis")
    with pytest.raises(InputError, match=r"t\.fis: line 30: expected 1 input and 1 output codes"):
        loads(MAMDANI.replace("-2, 2 (0.5) : 1", "-2 1, 2 (0.5) : 1"), "fis", source="t.fis")
    with pytest.raises(InputError, match=r"t\.fis: line 16 \(Range\): Range must be \[lo hi\]"):
        loads(MAMDANI.replace("Range=[0 10]", "Range=[0 ten]"), "fis", source="t.fis")
    path = tmp_path / "x.fis"
    path.write_text(MAMDANI.replace("Range=[0 10]", "Range=[0 ten]"))
    assert main(["fis", "show", str(path)]) == 2


def test_a_matlab_bisector_that_yaml_cannot_hold_is_sent_to_the_one_format_that_can(tmp_path, capsys):
    """Its bisector is MATLAB's, which an .fll file refuses too: the refusal names .fis alone."""
    (tmp_path / "b.fis").write_text(MAMDANI.replace("DefuzzMethod='centroid'", "DefuzzMethod='bisector'"))
    assert main(["fis", "convert", str(tmp_path / "b.fis"), "--to", "fll", "-o", str(tmp_path / "b.fll")]) == 2
    assert main(["fis", "convert", str(tmp_path / "b.fis"), "--to", "fis", "-o", str(tmp_path / "c.fis")]) == 0
    capsys.readouterr()
    assert main(["fis", "convert", str(tmp_path / "b.fis"), "--to", "yaml", "-o", str(tmp_path / "b.yaml")]) == 2
    assert capsys.readouterr().err.strip().endswith("several rule blocks...): write it as fis")  # not "fll or fis"
