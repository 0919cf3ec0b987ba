"""``fuzzynav tune`` without ``--out`` says when the search starts, not after it, that the tuned
system will only be reported (it used to run the whole search and then print "nothing written");
a run refused by a check says only why."""

from fuzzynav.cli import main
from fuzzynav.tune.fitness import Fitness

ARGV = ["tune", "goal-seeking:gsb", "--worlds", "mixed:1", "--budget", "2", "--population", "2", "--validation",
        "none", "--quiet"]
NOTE = "no --out: the tuned system will be reported, not written (and no checkpoint kept)"


def test_a_run_without_out_says_so_before_the_search(monkeypatch, capsys):
    said = []
    original = Fitness.objectives
    monkeypatch.setattr(Fitness, "objectives", lambda self, p: said.append(capsys.readouterr().err) or original(self, p))
    assert main(ARGV) == 0
    assert said == [NOTE + "\n"]  # before the first generation was simulated
    assert capsys.readouterr().err == ""  # and said once


def test_a_run_with_out_does_not_say_it(tmp_path, capsys):
    assert main([*ARGV, "--out", str(tmp_path / "t.yaml")]) == 0
    assert "--out" not in capsys.readouterr().err


def test_a_refused_run_says_only_why(capsys):
    assert main([*ARGV, "--holdout", "mixed:1"]) == 2  # held-out worlds that are training worlds
    err = capsys.readouterr().err
    assert NOTE not in err and len(err.splitlines()) == 1, err
