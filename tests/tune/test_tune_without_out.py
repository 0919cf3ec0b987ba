"""``fuzzynav tune`` without ``--out`` says before the search, not after it, that the tuned system
will only be reported (it used to run the whole search and then print "nothing written")."""

from fuzzynav.cli import main
from fuzzynav.tune import session


def test_a_run_without_out_says_so_before_the_search(monkeypatch, capsys):
    said = []
    original = session.tune
    monkeypatch.setattr(session, "tune", lambda request: said.append(capsys.readouterr().err) or original(request))
    assert main(["tune", "goal-seeking:gsb", "--worlds", "mixed:1", "--budget", "2", "--population", "2",
                 "--validation", "none", "--quiet"]) == 0
    assert said == ["no --out: the tuned system will be reported, not written (and no checkpoint kept)\n"]
    assert capsys.readouterr().err == ""  # said once


def test_a_run_with_out_does_not_say_it(tmp_path, capsys):
    assert main(["tune", "goal-seeking:gsb", "--worlds", "mixed:1", "--budget", "2", "--population", "2",
                 "--validation", "none", "--quiet", "--out", str(tmp_path / "t.yaml")]) == 0
    assert "--out" not in capsys.readouterr().err
