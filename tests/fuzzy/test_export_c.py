"""C export: the generated C99 compiles with the system compiler (-std=c99 -Wall -Wextra -pedantic
-Werror) and computes what Python computes on 10,000 random inputs (10 % beyond the ranges):
≤ 1e-12 in double, ≤ 1e-3 × output range in Q16.16 (the bound documented in export_c: for
Mamdani where the strongest rule fires at >= 0.01)."""

import ctypes
import shutil
import subprocess

import numpy as np
import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.fuzzy import FuzzySystem, Gaussian, Triangular, Variable, strong_partition
from fuzzynav.fuzzy.export_c import to_c
from fuzzynav.fuzzy.systems import get_system

CC = shutil.which("cc") or shutil.which("gcc")
N = 10_000


def _mamdani() -> FuzzySystem:
    x = Variable("x", (0.0, 10.0), strong_partition([0.0, 5.0, 10.0], ["lo", "mid", "hi"]))
    y = Variable("y", (-1.0, 1.0), {"n": Triangular(-1.5, -1.0, -0.3), "p": Triangular(0.3, 1.0, 1.5)})
    out = Variable("u", (0.0, 4.0), {"s": Triangular(0.0, 0.5, 2.0), "m": Triangular(1.0, 2.0, 3.0),
                                     "b": Triangular(2.0, 3.5, 4.0)})
    rules = ["IF x IS lo AND y IS n THEN u IS s", "IF x IS mid THEN u IS m WITH 0.8", "IF x IS hi AND y IS p THEN u IS b",
             "IF y IS p THEN u IS m WITH 0.5"]
    return FuzzySystem([x, y], [out], rules, method="mamdani", tnorm="min", implication="min", aggregation="max",
                       resolution=200, name="mamdani example")


def _compile(system, fixed, tmp_path):
    assert CC, "a C compiler (cc) is needed to test the C export"
    header, source = to_c(system, name="fis", fixed=fixed)
    (tmp_path / "fis.h").write_text(header)
    (tmp_path / "fis.c").write_text(source)
    library = tmp_path / f"fis_{'fixed' if fixed else 'double'}.so"
    done = subprocess.run([CC, "-std=c99", "-O2", "-Wall", "-Wextra", "-pedantic", "-Werror", "-shared", "-fPIC",
                           "-o", str(library), str(tmp_path / "fis.c"), "-lm"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return ctypes.CDLL(str(library)).fis_evaluate


def _run(function, X, n_out, fixed):
    dtype = np.int32 if fixed else np.float64
    inputs = np.ascontiguousarray(np.round(X * 65536) if fixed else X, dtype=dtype)
    out = np.zeros((len(X), n_out), dtype=dtype)
    flags = np.array([function(inputs[k].ctypes.data_as(ctypes.c_void_p), out[k].ctypes.data_as(ctypes.c_void_p))
                      for k in range(len(X))])
    return (out / 65536.0 if fixed else out), flags


def _inputs(system, seed):
    lo = np.array([v.universe[0] for v in system.inputs])
    hi = np.array([v.universe[1] for v in system.inputs])
    return np.random.default_rng(seed).uniform(lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo), (N, len(lo)))


@pytest.mark.parametrize("make", [lambda: get_system("goal-seeking"), lambda: get_system("tracking"), _mamdani],
                         ids=["table-IV.1", "table-V.1", "mamdani"])
@pytest.mark.parametrize("fixed", [None, "Q16.16"])
def test_c_matches_python(make, fixed, tmp_path):
    system = make()
    X = _inputs(system, 7)
    expected = system.evaluate(X)
    ours, flags = _run(_compile(system, fixed, tmp_path), X, len(system.outputs), fixed)
    span = np.array([v.universe[1] - v.universe[0] for v in system.outputs])
    fired = ~np.isnan(expected)
    assert ((flags == 0) == fired.all(axis=1)).all()  # the "no rule fired" mask says where Python gives NaN
    rows = fired.all(axis=1)
    if fixed and system.method == "mamdani":
        rows &= system.firing_strengths(X, normalise=False).max(axis=1) >= 0.01
    error = np.abs(ours - expected)[rows]
    if fixed:
        assert error.max() <= 1e-3 * span.max()
        assert error.max() > 0  # it is fixed point: not the double computation in disguise
    else:
        assert error.max() <= 1e-12


def test_mamdani_example_leaves_rows_unfired():
    # the mamdani example has input regions where no rule fires (the flags of the C function must
    # then match Python's NaN, which test_c_matches_python checks row by row)
    system = _mamdani()
    X = _inputs(system, 7)
    assert np.isnan(system.evaluate(np.array([[0.0, 0.0]]))).all()
    assert 0.01 < np.isnan(system.evaluate(X)).mean() < 0.5


def test_fixed_point_refuses_curved_terms():
    x = Variable("x", (0.0, 1.0), {"a": Gaussian(0.2, 0.3), "b": Gaussian(0.2, 0.7)})
    system = FuzzySystem([x], [Variable("y", (0.0, 1.0), {"u": Triangular(0, 0.5, 1)})], ["IF x IS a THEN y IS u"],
                         method="mamdani")
    to_c(system)  # double: exp() of <math.h>
    with pytest.raises(InputError, match="Gaussian terms have no fixed-point form"):
        to_c(system, fixed="Q16.16")


def test_cli_writes_c_and_header(tmp_path, capsys):
    target = tmp_path / "controller.c"
    assert main(["fis", "export-c", "goal-seeking", "-o", str(target), "--fixed", "Q16.16"]) == 0
    assert '#include "controller.h"' in target.read_text()
    assert "int controller_evaluate(const controller_real in[CONTROLLER_N_INPUTS]" in (tmp_path / "controller.h").read_text()
    assert "malloc" not in target.read_text()
    assert main(["fis", "export-c", "goal-seeking", "-o", str(tmp_path / "controller.txt")]) == 2
    assert "-o" in capsys.readouterr().err


def test_a_ramp_narrower_than_the_fixed_point_step_is_a_step_and_names_stay_in_comments(tmp_path):
    """A term edge 1e-6 wide rounds to 0 in Q16.16: it is exported as a step (dividing by its width
    would trap on every input); a system name holding ``*/`` cannot end a comment of the code."""
    x = Variable("x", (0.0, 1.0), {"lo": Triangular(0.0, 0.1, 0.100001),
                                                       "hi": Triangular(0.1, 0.100002, 1.0)})
    y = Variable("y", (0.0, 1.0), {"s": Triangular(0.0, 0.0, 1.0), "b": Triangular(0.0, 1.0, 1.0)})
    rules = ["IF x IS lo THEN y IS s", "IF x IS hi THEN y IS b"]
    system = FuzzySystem([x], [y], rules, method="mamdani", name="t */ int oops = ; /*")  # (a line break: refused)
    X = np.array([[0.05], [0.5], [0.9], [0.1000005]])
    for fixed in (None, "Q16.16"):
        ours, flags = _run(_compile(system, fixed, tmp_path), X, 1, fixed)  # compiled with -Werror
        assert (flags == 0).all()
        np.testing.assert_allclose(ours[:3], system.evaluate(X)[:3], atol=2e-3)


def test_a_term_that_q16_would_shrink_to_a_point_is_refused():
    """Table IV.1's theta scaled by 1e-6: each term's breakpoints are one value in Q16.16, every term
    fired at 0 and the C answered v = 15.6 on a [0, 4] universe. Refused in fixed point; double is fine."""
    system = get_system("goal-seeking")
    theta = system.inputs[1]
    tiny = {label: Triangular(*(p * 1e-6 for p in mf.params())) for label, mf in theta.terms.items()}
    small = FuzzySystem([system.inputs[0], Variable("theta", (-3.2e-6, 3.2e-6), tiny)], system.outputs,
                        [rule.text() for rule in system.rules], method=system.method)
    to_c(small)
    with pytest.raises(InputError, match=r"--fixed: theta\.NG: its breakpoints -1\.5e-06, -7\.5e-07 are one value"):
        to_c(small, fixed="Q16.16")


def test_a_narrow_ramp_far_from_the_input_does_not_overflow_q16(tmp_path):
    """A ramp a few fixed-point steps wide on a wide range: (x - a) / (b - a) is about 10^9 for an x
    far from it, past int32; the input is held to the ramp before the division."""
    x = Variable("x", (-10.0, 10.0), {"lo": Triangular(-10.0, -10.0, 0.0), "hi": Triangular(0.0, 1e-4, 10.0)})
    y = Variable("y", (0.0, 1.0), {"s": Triangular(0.0, 0.0, 1.0), "b": Triangular(0.0, 1.0, 1.0)})
    system = FuzzySystem([x], [y], ["IF x IS lo THEN y IS s", "IF x IS hi THEN y IS b"], method="mamdani")
    X = np.array([[9.0], [5.0], [-9.0], [0.5]])
    ours, flags = _run(_compile(system, "Q16.16", tmp_path), X, 1, "Q16.16")
    np.testing.assert_allclose(ours, system.evaluate(X), atol=2e-3)
