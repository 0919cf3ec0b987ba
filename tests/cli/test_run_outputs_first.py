"""``fuzzynav run`` refuses a ``--plot`` or ``--animate`` file it could not write before it runs
the episode (it used to run it first, then fail "cannot write"); a folder that even root cannot
write in (``/proc``) is found by trying, not by asking ``os.access``."""

from pathlib import Path

import pytest

from fuzzynav import sim
from fuzzynav.cli import main


@pytest.fixture
def no_episode(monkeypatch):
    def refused(*args, **kwargs):
        raise AssertionError("the episode ran before the outputs were checked")

    monkeypatch.setattr(sim, "run_episode", refused)


@pytest.mark.parametrize("flag, name", [("--plot", "x.png"), ("--animate", "x.gif")])
def test_an_output_under_a_file_is_refused_before_the_episode(tmp_path, capsys, no_episode, flag, name):
    (tmp_path / "afile").write_text("")
    assert main(["run", "fig-IV-12a", "--controller", "goal-seeking", flag, str(tmp_path / "afile" / name)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.endswith(f"{flag}: cannot write in {tmp_path / 'afile'}: a file, not a folder"), err


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs a /proc file system")
@pytest.mark.parametrize("flag, name", [("--plot", "x.png"), ("--animate", "x.gif")])
def test_an_output_in_proc_is_refused_before_the_episode(capsys, no_episode, flag, name):
    assert main(["run", "fig-IV-12a", "--controller", "goal-seeking", flag, f"/proc/{name}"]) == 2
    err = capsys.readouterr().err.strip()
    assert f"/proc/{name}: {flag}: cannot write" in err and len(err.splitlines()) == 1, err
