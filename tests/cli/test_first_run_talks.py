"""The first hour of a new user: a first run that says it is compiling, an example in every
``--help``, defaults that run, and commands that say what they wrote."""

import json
import os
import sys
from types import SimpleNamespace

import numba
import pytest
from numba.core import event

from fuzzynav.cli import build_parser, main
from fuzzynav.jit import COMPILE_NOTICE, NOTICE, CompileNotice


def _kernel(x):
    return x + 1


def _other(x):
    return x * 2


_kernel.__module__ = "fuzzynav.kernels.example"  # a kernel of the package, as numba sees it


def test_the_compile_notice_is_said_once_and_only_for_the_package(capsys, monkeypatch):
    monkeypatch.setattr(NOTICE, "said", True)  # the process' own notice stays quiet: only the one below speaks
    notice = CompileNotice()
    with event.install_listener("numba:compile", notice):
        numba.njit(_other)(1)  # not a kernel of the package
        assert COMPILE_NOTICE not in capsys.readouterr().err
        numba.njit(_kernel)(1)
        numba.njit(_kernel)(1.5)  # a second compilation: nothing more
    assert capsys.readouterr().err.count(COMPILE_NOTICE) == 1
    silent = CompileNotice()
    silent.silence()
    with event.install_listener("numba:compile", silent):
        numba.njit(_kernel)(2)
    assert COMPILE_NOTICE not in capsys.readouterr().err


@pytest.mark.skipif(not hasattr(os, "fork"), reason="workers are forked on POSIX only")
def test_forked_workers_say_the_notice_once_between_them(monkeypatch):
    notice = CompileNotice()
    compiling = SimpleNamespace(data={"dispatcher": SimpleNamespace(py_func=_kernel)})
    said = []
    for _ in range(2):  # two workers forked by one command, compiling one after the other
        read, write = os.pipe()
        pid = os.fork()
        if pid == 0:  # the worker: its stderr is the pipe
            os.dup2(write, 2)
            sys.stderr = os.fdopen(2, "w")
            notice.on_start(compiling)
            os._exit(0)
        os.close(write)
        os.waitpid(pid, 0)
        with os.fdopen(read) as pipe:
            said.append(pipe.read())
    assert said == [COMPILE_NOTICE + "\n", ""]


def _subcommands(parser, prefix=()):
    """(words, parser) of every command and sub-command."""
    yield prefix, parser
    for action in parser._actions:
        for name, sub in getattr(action, "choices", None).items() if hasattr(action, "_name_parser_map") else ():
            yield from _subcommands(sub, (*prefix, name))


def test_every_help_shows_an_example_and_no_markup():
    helps = {" ".join(words): parser.format_help() for words, parser in _subcommands(build_parser())}
    assert len(helps) >= 17
    for words, text in helps.items():
        assert "\nexamples:\n  fuzzynav " in text, words
        assert "%%" not in text and "``" not in text and ":func:" not in text and "`" not in text, words


@pytest.mark.slow
def test_warmup_compiles_and_says_how_long(capsys):
    assert main(["warmup", "--controllers", "goal-seeking"]) == 0
    captured = capsys.readouterr()
    assert "compiling the simulator's kernels" in captured.err
    assert captured.out.startswith("kernels ready in ")
    assert main(["warmup", "--controllers", "no-such-navigator"]) == 2


def test_the_demo_says_what_it_does_first_and_checks_before_compiling(capsys, tmp_path):
    assert main(["demo", "--scenario", str(tmp_path / "missing.yaml"), "--out", str(tmp_path / "d")]) == 2
    out, err = capsys.readouterr()
    assert out.startswith("fuzzynav demo: ") and "missing.yaml" in err and "compiling" not in out + err


@pytest.mark.slow
def test_run_defaults_to_fuzzy_5b_on_a_goal_and_to_the_scenarios_own_controller(capsys):
    assert main(["run", "fig-IV-12a", "--max-time", "1", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["controller"] == "fuzzy-5b"
    assert main(["run", "path-n", "--max-time", "1", "--json"]) == 0  # a path: its first listed tracker
    assert json.loads(capsys.readouterr().out)["controller"] == "fuzzy-tracker"


@pytest.mark.slow
def test_save_failures_says_none_failed_and_leaves_no_empty_folder(tmp_path, capsys):
    folder = tmp_path / "deep" / "failed"
    assert main(["evaluate", "--controller", "fuzzy-5b", "--worlds", "circles", "--n", "1", "--quiet",
                 "--save-failures", str(folder)]) == 0
    assert "no world failed: nothing saved" in capsys.readouterr().out
    assert not (tmp_path / "deep").exists()  # made to check it can be written, removed when empty
    folder.mkdir(parents=True)  # a folder that was there stays
    assert main(["evaluate", "--controller", "fuzzy-5b", "--worlds", "circles", "--n", "1", "--quiet",
                 "--save-failures", str(folder)]) == 0
    assert folder.is_dir()


def test_a_shown_scenario_copy_takes_its_files_name(tmp_path, capsys):
    assert main(["scenarios", "--show", "fig-IV-15a"]) == 0
    copy = tmp_path / "my-world.yaml"
    copy.write_text(capsys.readouterr().out)
    from fuzzynav.world.scenario import load_scenario

    assert load_scenario(copy).name == "my-world"


@pytest.mark.slow
def test_run_says_what_it_wrote(tmp_path, capsys):
    plot, gif = tmp_path / "u.png", tmp_path / "u.gif"
    assert main(["run", "fig-IV-12a", "--max-time", "1", "--plot", str(plot), "--animate", str(gif)]) == 0
    err = capsys.readouterr().err
    assert f"wrote {plot}" in err and f"wrote {gif}" in err
