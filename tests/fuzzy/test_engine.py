"""fuzzylite semantics, computed by hand on small engines (the pyfuzzylite cross-check of the same
engines is in tests/fll): hedges, and/or/parentheses, lock-range, default, lock-previous,
activation methods, chained blocks, FLL round trips, errors naming the line."""

import math

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.engine import Engine
from fuzzynav.fuzzy.io import from_fll, to_fll
from tests.fuzzy.fll_fixtures import ENGINES

ONE_INPUT = """Engine: e
InputVariable: x
  enabled: true
  range: 0.0 1.0
  lock-range: {lock}
  term: up Ramp 0.0 1.0
  term: down Ramp 1.0 0.0
OutputVariable: y
  enabled: true
  range: -10.0 10.0
  lock-range: {out_lock}
  aggregation: none
  defuzzifier: WeightedSum TakagiSugeno
  default: {default}
  lock-previous: {previous}
  term: one Constant 1.0
  term: two Constant 2.0
  term: three Constant 30.0
RuleBlock:
  enabled: true
  conjunction: {conjunction}
  disjunction: {disjunction}
  implication: none
  activation: {activation}
{rules}"""


def engine(rules, lock="false", out_lock="false", default="nan", previous="false", conjunction="Minimum",
           disjunction="Maximum", activation="General"):
    text = ONE_INPUT.format(rules="".join(f"  rule: {r}\n" for r in rules), lock=lock, out_lock=out_lock,
                            default=default, previous=previous, conjunction=conjunction, disjunction=disjunction,
                            activation=activation)
    return from_fll(text, source="e.fll")


@pytest.mark.parametrize("hedge, formula", [
    ("not", lambda u: 1 - u), ("very", lambda u: u * u), ("somewhat", np.sqrt),
    ("extremely", lambda u: np.where(u <= 0.5, 2 * u * u, 1 - 2 * (1 - u) ** 2)),
    ("seldom", lambda u: np.where(u <= 0.5, np.sqrt(u / 2), 1 - np.sqrt((1 - u) / 2))),
    ("very not", lambda u: (1 - u) ** 2), ("any", lambda u: np.ones_like(u)),
])
def test_hedges(hedge, formula):
    term = "" if hedge == "any" else " up"
    e = engine([f"if x is {hedge}{term} then y is one"])
    x = np.linspace(0, 1, 11)[:, None]
    expected = formula(x[:, 0])
    # a weighted sum over rules of degree 0 is NaN in fuzzylite (0/0 · 0), not 0
    np.testing.assert_allclose(e.evaluate(x)[:, 0], np.where(expected == 0, np.nan, expected), rtol=0, atol=1e-15)


def test_and_binds_tighter_than_or_and_parentheses_group():
    x = np.array([[0.3]])  # up 0.3, down 0.7
    loose = engine(["if x is up or x is down and x is up then y is one"])  # up or (down and up) = max(.3, .3)
    grouped = engine(["if (x is up or x is down) and x is up then y is one"])  # min(max(.3, .7), .3)
    mixed = engine(["if x is down or (x is up and x is very down) then y is one"])  # max(.7, min(.3, .49))
    assert loose.evaluate(x)[0, 0] == pytest.approx(0.3)
    assert grouped.evaluate(x)[0, 0] == pytest.approx(0.3)
    assert mixed.evaluate(x)[0, 0] == pytest.approx(0.7)
    product = engine(["if x is up and x is down or x is up then y is one"], conjunction="AlgebraicProduct",
                     disjunction="AlgebraicSum")  # (.21) + .3 - .063
    assert product.evaluate(x)[0, 0] == pytest.approx(0.21 + 0.3 - 0.21 * 0.3)


def test_lock_range_default_and_lock_previous():
    rules = ["if x is up then y is three", "if x is down then y is one"]
    free, locked = engine(rules), engine(rules, lock="true")
    X = np.array([[2.0], [-1.0], [0.5]])
    # outside [0, 1] a ramp keeps its end value: up(2) = 1, down(2) = 0 (clamped or not, the same here)
    np.testing.assert_allclose(free.evaluate(X), locked.evaluate(X))
    tri = from_fll(to_fll(free).replace("Ramp 0.0 1.0", "Triangle 0.0 0.5 1.0").replace("Ramp 1.0 0.0",
                                                                                         "Triangle 0.5 1.0 1.5"), "t")
    tri_locked = from_fll(to_fll(tri).replace("lock-range: false", "lock-range: true", 1), "t")
    assert math.isnan(tri.evaluate_one(2.0)[0])  # nothing fires outside: fuzzylite's weighted sum is NaN
    assert tri_locked.evaluate_one(2.0) == tri_locked.evaluate_one(1.0)  # clamped to the end of the range
    # the output: NaN -> previous row (lock-previous), then default, then clipped (lock-range)
    out = engine(["if x is up then y is three"], default="-2.0", previous="true", out_lock="true")
    Y = out.evaluate(np.array([[0.0], [0.5], [0.0], [1.0], [0.0]]))[:, 0]
    np.testing.assert_allclose(Y, [-2.0, 10.0, 10.0, 10.0, 10.0])  # 15 and 30 clipped to 10


def test_activation_methods():
    rules = ["if x is up then y is one", "if x is down then y is two", "if x is very up then y is three"]
    x = np.array([[0.8]])  # degrees .8, .2, .64
    sums = {"General": 0.8 * 1 + 0.2 * 2 + 0.64 * 30, "Highest 2": 0.8 * 1 + 0.64 * 30, "Lowest 1": 0.2 * 2,
            "First 1 0.5": 0.8 * 1, "Last 2 0.0": 0.2 * 2 + 0.64 * 30, "Threshold < 0.7": 0.2 * 2 + 0.64 * 30,
            "Proportional": (0.8 * 1 + 0.2 * 2 + 0.64 * 30) / 1.64}
    for activation, expected in sums.items():
        assert engine(rules, activation=activation).evaluate(x)[0, 0] == pytest.approx(expected), activation


def test_chained_blocks_and_disabled_block():
    e = from_fll(ENGINES["chained"], source="chained.fll")
    assert isinstance(e, Engine) and len(e.blocks) == 3
    # ambient 0.25: power fully "high" (its own output), which the second block reads as a premise
    power, inverse = e.evaluate(np.array([[0.25]]))[0]
    assert power == pytest.approx(0.75, abs=2e-3)
    assert inverse == pytest.approx(0.2, abs=2e-3)  # inverse "low" (Cosine at 0.2); the disabled block adds nothing
    assert e.evaluate(np.array([[0.0]]))[0, 1] == 0.5  # nothing fires: default 0.5


@pytest.mark.parametrize("name", list(ENGINES))
def test_fll_round_trip(name):
    e = from_fll(ENGINES[name], source=name)
    again = from_fll(to_fll(e), source="again")
    assert to_fll(again) == to_fll(e)
    lo = np.array([v.minimum for v in e.inputs])
    hi = np.array([v.maximum for v in e.inputs])
    X = np.random.default_rng(0).uniform(lo - 0.3 * (hi - lo), hi + 0.3 * (hi - lo), (300, len(lo)))
    np.testing.assert_array_equal(again.evaluate(X), e.evaluate(X))


@pytest.mark.parametrize("change, message", [
    (("then y is one", "then y is four"), r"e\.fll: line 25: expected a term of 'y' \(one, two, three\), got 'four'"),
    (("if x is up", "if x is verry up"), r"line 25: expected a term of 'x'.*got 'verry'"),
    (("conjunction: Minimum", "conjunction: none"), r"rule uses 'and' but the block has no conjunction"),
    (("conjunction: Minimum", "conjunction: Average"), r"unknown conjunction 'Average'"),
    (("activation: General", "activation: Highest two"), r"line 24: bad parameters for Highest"),
    (("WeightedSum TakagiSugeno", "WeightedSum Mamdani"), r"line 13: WeightedSum type must be one of"),
    (("term: up Ramp 0.0 1.0", "term: up Ramp 0.0 one"), r"line 6: term up: 'one' is not a number"),
])
def test_errors_name_the_line(change, message):
    text = ONE_INPUT.format(rules="  rule: if x is up and x is down then y is one\n", lock="false", out_lock="false",
                            default="nan", previous="false", conjunction="Minimum", disjunction="Maximum",
                            activation="General")
    with pytest.raises(InputError, match=message):
        from_fll(text.replace(*change), source="e.fll")


def test_damaged_files_raise_input_errors_only():
    # every line of the FLL and .fis fixtures damaged in turn (a word replaced, inserted or cut):
    # each is either read (and evaluates) or refused with an InputError — never another exception
    import random

    from fuzzynav.fuzzy.io import dumps, loads
    from fuzzynav.fuzzy.systems import get_system

    rng = random.Random(0)
    texts = [(t, "fll") for t in ENGINES.values()] + [(dumps(get_system("goal-seeking"), "fis"), "fis")]
    tokens = ["", "x", "1.2.3", "nan", "-", "(", ")", "inf", "'", ":", ",", "[", "]", "=", "0", "and", "or", "not",
              "very", "Blob", "#", "%"]
    refused = 0
    for _ in range(1500):
        text, fmt = rng.choice(texts)
        lines = text.splitlines()
        k = rng.randrange(len(lines))
        words = lines[k].split(" ")
        j = rng.randrange(len(words))
        choice = rng.random()
        if choice < 0.4:
            words[j] = rng.choice(tokens)
        elif choice < 0.7:
            words.insert(j, rng.choice(tokens))
        else:
            words[j] = words[j][: rng.randrange(len(words[j]) + 1)]
        lines[k] = " ".join(words)
        try:
            system = loads("\n".join(lines), fmt, source="damaged")
        except InputError as error:
            assert str(error).startswith("damaged")
            refused += 1
            continue
        with np.errstate(all="ignore"):
            system.evaluate(np.zeros((3, len(system.inputs))))
    assert refused > 300
