"""``fuzzynav fis show|eval|convert|plot`` end to end, and the plots."""

import json

import numpy as np
import pytest

from fuzzynav.cli import main
from fuzzynav.fuzzy.io import from_fll, load, to_fll
from fuzzynav.fuzzy.plot import plot_surface, plot_system, surface
from fuzzynav.fuzzy.systems import get_system


def test_show_prints_the_table_as_printed(capsys):
    assert main(["fis", "show", "goal-seeking"]) == 0
    out = capsys.readouterr().out
    assert "theta \\ drg" in out
    assert [line.split() for line in out.splitlines() if line.startswith("NM ")][-1] == \
        ["NM", "PP/Z", "PG/F", "PM/F", "PP/M", "PM/M"]


def test_eval_one_input_as_json(capsys):
    assert main(["fis", "eval", "goal-seeking", "--input", "drg=5.75", "--input", "theta=-0.5"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["alpha"] == pytest.approx(get_system("goal-seeking").evaluate_one(5.75, -0.5)[0])
    assert main(["fis", "eval", "goal-seeking", "--input", "drg=5"]) == 2
    assert "missing input(s) theta" in capsys.readouterr().err


def test_eval_csv_table(tmp_path, capsys):
    src = tmp_path / "in.csv"
    src.write_text("theta_er,dtheta_er\n0.1,0.2\n-3,1\n")
    dst = tmp_path / "out.csv"
    assert main(["fis", "eval", "tracking", "--csv", str(src), "-o", str(dst)]) == 0
    rows = [line.split(",") for line in dst.read_text().splitlines()]
    assert rows[0] == ["theta_er", "dtheta_er", "alpha"]
    expected = get_system("tracking").evaluate(np.array([[0.1, 0.2], [-3, 1]]))[:, 0]
    np.testing.assert_array_equal([float(r[2]) for r in rows[1:]], expected)
    src.write_text("theta_er,dtheta_er\n0.1,oops\n")
    assert main(["fis", "eval", "tracking", "--csv", str(src)]) == 2
    assert "in.csv: line 2: 'oops' is not a number" in capsys.readouterr().err


@pytest.mark.parametrize("fmt", ["fll", "json", "yaml"])
def test_convert_round_trips_through_files(fmt, tmp_path, capsys):
    path = tmp_path / f"gs.{fmt}"
    assert main(["fis", "convert", "goal-seeking", "--to", fmt, "-o", str(path)]) == 0
    assert load(path) == get_system("goal-seeking")
    assert main(["fis", "eval", str(path), "--input", "drg=3", "--input", "theta=0.1"]) == 0
    assert json.loads(capsys.readouterr().out)["v"] == pytest.approx(get_system("goal-seeking").evaluate_one(3, 0.1)[1])
    assert main(["fis", "show", "nonsense"]) == 2


@pytest.mark.parametrize("target", ["fuzzy-5b:", "fuzzy-5b:nosuch"])
def test_an_unknown_role_names_the_argument_given(target, capsys):
    assert main(["fis", "show", target]) == 2
    assert "error: system: fuzzy-5b has no role" in capsys.readouterr().err


def test_a_misspelt_system_gets_close_names(capsys):
    assert main(["fis", "show", "goal-seekin"]) == 2
    assert "(did you mean goal-seeking," in capsys.readouterr().err


def test_plots(tmp_path):
    x1, x2, y = surface(get_system("tracking"), n=21)
    assert y.shape == (21, 21) and y.max() == pytest.approx(np.pi / 4) and y.min() == pytest.approx(-np.pi / 4)
    assert len(plot_system(get_system("goal-seeking")).axes) == 4
    plot_surface(get_system("goal-seeking"), "v").savefig(tmp_path / "s.png")
    assert main(["fis", "plot", "tracking", "--surface", "-o", str(tmp_path / "v7.png")]) == 0
    assert (tmp_path / "v7.png").stat().st_size > 10_000


def test_a_takagi_sugeno_file_plots_its_constant_conclusions_as_bars():
    """Table IV.1 read from an FLL file that stays an engine (a Function term) holds its
    conclusions as Constant terms of a weighted defuzzifier: values, drawn as the built-in
    system's singletons are (one bar each), not as flat degrees across the axis; a Mamdani
    output's Constant term stays a degree over its axis."""
    text = to_fll(get_system("goal-seeking")).replace("term: P Triangle 0.1 3.5 8.0",
                                                      "term: P Function max(0, 1 - abs(drg - 3.5) / 4)")
    built_in, engine = get_system("goal-seeking"), from_fll(text, source="gs.fll")  # a Function term: an engine
    assert engine.outputs[0].terms["NG"].kind == "constant"
    for system in (built_in, engine):
        alpha = plot_system(system).axes[2]
        assert len(alpha.collections) == 7 and not alpha.lines  # NG … PG, as bars
    mamdani = from_fll(MAMDANI_CONSTANT, source="m.fll")
    assert len(plot_system(mamdani).axes[1].lines) == 2  # a Constant degree over the axis, and a triangle


MAMDANI_CONSTANT = """Engine: m
InputVariable: x
  range: 0 1
  term: lo Triangle 0 0 1
OutputVariable: v
  range: 0 1
  aggregation: Maximum
  defuzzifier: Centroid 100
  term: half Constant 0.5
  term: hi Triangle 0 1 1
RuleBlock: rb
  conjunction: Minimum
  implication: Minimum
  activation: General
  rule: if x is lo then v is hi
"""


def test_a_function_term_reading_an_unknown_name_is_refused_when_read(tmp_path, capsys):
    """It was read, shown and converted, then failed with a traceback at the first evaluation."""
    text = to_fll(get_system("goal-seeking"))
    assert text.index("term: Z Constant 0.0") < text.index("OutputVariable: v")  # alpha's Z comes first
    bad = tmp_path / "gs-fn.fll"
    bad.write_text(text.replace("term: Z Constant 0.0", "term: Z Function foo", 1))
    for command in (["show"], ["eval", "--input", "drg=5", "--input", "theta=0.3"]):
        assert main(["fis", command[0], str(bad), *command[1:]]) == 2
        err = capsys.readouterr().err.strip()
        assert err.endswith("gs-fn.fll: alpha.Z: Function 'foo' reads foo, not a variable of this system "
                            "(alpha, drg, theta, v; x is the term's own input)"), err
    infinite = tmp_path / "gs-inf.fll"  # a constant that is infinite: refused when read, naming the term
    infinite.write_text(text.replace("term: Z Constant 0.0", "term: Z Function 1/0", 1))
    assert main(["fis", "show", str(infinite)]) == 2
    assert "gs-inf.fll: alpha.Z: Function '1/0' gives inf at every input" in capsys.readouterr().err
    good = tmp_path / "gs-ok.fll"  # a name of the system is fine
    good.write_text(text.replace("term: Z Constant 0.0", "term: Z Function 0 * drg", 1))
    assert main(["fis", "eval", str(good), "--input", "drg=5", "--input", "theta=0.3"]) == 0
