"""The command-line contracts: bad input exits 2 with a message naming the
option or file, never a traceback; files written atomically keep ordinary permissions."""

import os
import stat
import subprocess
import sys

import numpy as np
import pytest

from fuzzynav.cli import main
from fuzzynav.fuzzy.io import dumps
from fuzzynav.fuzzy.io.document import to_document
from fuzzynav.fuzzy.systems import get_system
from fuzzynav.storage import save_json_atomic


def run_cli(capsys, *argv):
    """Exit status and stderr of ``fuzzynav argv`` (argparse errors exit through SystemExit)."""
    try:
        status = main(list(argv))
    except SystemExit as exit_:
        status = exit_.code
    return status, capsys.readouterr().err


@pytest.mark.parametrize("argv", [
    ["run", "path-v", "--controller", "stanley"],
    ["train", "q-goal", "--episodes", "1", "--quiet"],
    ["evaluate", "--controller", "fuzzy-2b", "--worlds", "circles", "--n", "1"],
    ["reproduce", "fig-IV-12", "--quick"],
])
def test_negative_seed_is_a_usage_error(capsys, tmp_path, monkeypatch, argv):
    monkeypatch.chdir(tmp_path)
    status, err = run_cli(capsys, *argv, "--seed", "-1")
    assert status == 2
    assert "--seed: must be a non-negative integer, got -1" in err
    assert "Traceback" not in err and not list(tmp_path.iterdir())


@pytest.mark.parametrize("argv,option", [
    (["demo", "--no-plots", "--out", ""], "--out"),
    (["reproduce", "fig-IV-12", "--quick", "--out", ""], "--out"),
    (["train", "q-goal", "--episodes", "1", "--out", " "], "--out"),
    (["evaluate", "--worlds", "circles", "--n", "1", "--save-failures", ""], "--save-failures"),
    (["bench", "circles:1", "--out", ""], "--out"),
    (["worlds", "generate", "circles", "--out", ""], "--out"),
])
def test_an_empty_path_is_a_usage_error_not_the_current_folder(capsys, tmp_path, monkeypatch, argv, option):
    monkeypatch.chdir(tmp_path)
    status, err = run_cli(capsys, *argv)
    assert status == 2 and f"{option}: is empty" in err and "Traceback" not in err
    assert not list(tmp_path.iterdir())  # nothing written into the current folder


@pytest.mark.parametrize("n, said", [(1, "wrote 1 scenario file to {out}/ (mixed-0-000.yaml);"),
                                     (2, "wrote 2 scenario files to {out}/ (mixed-0-000.yaml … mixed-0-001.yaml);")])
def test_worlds_generate_names_what_it_wrote(capsys, tmp_path, n, said):
    # one world was "1 scenario files (mixed-0-000.yaml … mixed-0-000.yaml)"
    assert main(["worlds", "generate", "mixed", "--n", str(n), "--out", str(tmp_path)]) == 0
    assert said.format(out=tmp_path) in capsys.readouterr().out


def test_evaluate_workers_out_of_range_is_a_usage_error(capsys):
    status, err = run_cli(capsys, "evaluate", "--worlds", "circles", "--n", "1", "--workers", "0")
    assert status == 2
    assert "--workers: must be an integer in [1, 1024], got 0" in err and "Traceback" not in err


def test_corrupt_npz_model_is_input_error(capsys, tmp_path):
    model = tmp_path / "model.npz"
    model.write_bytes(b"PK\x03\x04 not really a zip archive")
    status, err = run_cli(capsys, "run", "path-v", "--model", str(model))
    assert status == 2
    assert f"{model}: cannot read model file" in err


def test_atomic_model_file_has_umask_permissions(tmp_path):
    path = tmp_path / "m.json"
    save_json_atomic(path, {"kind": "q-goal"})
    mask = os.umask(0)
    os.umask(mask)
    assert stat.S_IMODE(path.stat().st_mode) == 0o666 & ~mask
    assert [p.name for p in tmp_path.iterdir()] == ["m.json"]  # no temporary file left


def test_unwritable_model_path_is_input_error(capsys, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("a file, not a folder")
    out = blocker / "model.json"
    status, err = run_cli(capsys, "train", "q-goal", "--episodes", "1", "--quiet", "--out", str(out))
    assert status == 2
    assert "cannot write" in err and str(blocker) in err and "Traceback" not in err


def test_train_out_directory_rejected_before_training(capsys, tmp_path):
    status, err = run_cli(capsys, "train", "q-goal", "--quiet", "--out", str(tmp_path))
    assert status == 2
    assert "--out:" in err and "is a directory" in err
    assert not list(tmp_path.iterdir())  # nothing trained, no checkpoint


def test_unwritable_output_file_exits_2_naming_it(capsys, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    status, err = run_cli(capsys, "fis", "convert", "goal-seeking", "--to", "fll", "-o", str(blocker / "gs.fll"))
    assert status == 2
    assert str(blocker / "gs.fll") in err and "Traceback" not in err


@pytest.mark.parametrize("argv, message", [
    (["run", "path-v", "--controller", "stanley", "--plot", "out.jpgx"], "matplotlib cannot write '.jpgx'"),
    (["run", "path-v", "--controller", "stanley", "--animate", "out.mp4"], "ending in .gif"),
    (["fis", "plot", "goal-seeking", "-o", "out.foo"], "matplotlib cannot write '.foo'"),
])
def test_figure_file_types_checked_before_running(capsys, tmp_path, monkeypatch, argv, message):
    monkeypatch.chdir(tmp_path)
    status, err = run_cli(capsys, *argv)
    assert status == 2 and message in err
    assert not list(tmp_path.iterdir())


@pytest.mark.skipif(sys.platform == "win32", reason="a child started without a standard output: POSIX fds")
def test_a_command_started_without_standard_output_says_so_instead_of_losing_its_answer():
    # ``fuzzynav fis show goal-seeking >&-``: Python makes sys.stdout None, where print writes nothing
    process = subprocess.run([sys.executable, "-m", "fuzzynav", "fis", "show", "goal-seeking"], stdin=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, preexec_fn=lambda: os.close(1), timeout=120)
    assert process.returncode == 2
    assert process.stderr.decode().strip() == "fuzzynav fis show: error: standard output is closed"


def test_closed_stdout_pipe_ends_quietly():
    process = subprocess.Popen([sys.executable, "-m", "fuzzynav", "fis", "show", "goal-seeking"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    process.stdout.close()  # the reader (``| head``) goes away before the command writes
    err = process.stderr.read().decode()
    assert process.wait(timeout=60) == 141
    assert "Traceback" not in err


@pytest.mark.parametrize("inputs, message", [
    (["drg=5", "theta=0", "drg=6"], "--input drg=6: drg is given twice"),
    (["drg=nan", "theta=0"], "--input drg=nan: NaN input"),
])
def test_fis_eval_rejects_ambiguous_inputs(capsys, inputs, message):
    argv = ["fis", "eval", "goal-seeking"]
    for pair in inputs:
        argv += ["--input", pair]
    status, err = run_cli(capsys, *argv)
    assert status == 2 and message in err


def test_fis_eval_csv_nan_names_file_and_line(capsys, tmp_path):
    table = tmp_path / "in.csv"
    table.write_text("drg,theta\n5,0.3\n2,nan\n")
    status, err = run_cli(capsys, "fis", "eval", "goal-seeking", "--csv", str(table))
    assert status == 2
    assert f"{table}: line 3: NaN input" in err


def _yaml_with(tmp_path, old, new):
    text = dumps(get_system("goal-seeking"), "yaml")
    assert old in text
    path = tmp_path / "fis.yaml"
    path.write_text(text.replace(old, new, 1))
    return path


@pytest.mark.parametrize("old, new, message", [
    ("tnorm: product", "tnrom: min", "tnrom: unknown key 'tnrom' (did you mean 'tnorm'?)"),
    ("  universe:", "  universes:", "inputs[0].universes: unknown key 'universes' (did you mean 'universe'?)"),
    ("      kind: singleton", "      knd: singleton", "outputs[0].terms.NG.knd: unknown key 'knd'"),
])
def test_fis_document_typos_are_rejected(capsys, tmp_path, old, new, message):
    status, err = run_cli(capsys, "fis", "show", str(_yaml_with(tmp_path, old, new)))
    assert status == 2 and message in err


def test_fis_document_keeps_a_model_files_own_keys(tmp_path):
    """A learned controller's file is a fuzzy system plus its kind and training record."""
    system = get_system("goal-seeking")
    document = {"kind": "fql-goal", **to_document(system), "constant_speed": None, "training": {"episodes": 3}}
    path = tmp_path / "model.json"
    save_json_atomic(path, document)
    from fuzzynav.fuzzy.io import load

    X = np.array([[5.0, 0.3], [1.0, -1.0]])
    np.testing.assert_array_equal(load(path).evaluate(X), system.evaluate(X))


def test_fll_unknown_key_names_the_line(capsys, tmp_path):
    text = dumps(get_system("goal-seeking"), "fll")
    path = tmp_path / "gs.fll"
    path.write_text(text.replace("  lock-range: true", "  lock-rnge: true", 1))
    line = text.splitlines().index("  lock-range: true") + 1
    status, err = run_cli(capsys, "fis", "show", str(path))
    assert status == 2
    assert f"line {line}: 'lock-rnge' is not a key of InputVariable" in err


def test_fis_show_of_a_non_fuzzy_model_file_says_what_it_is(capsys, tmp_path):
    path = tmp_path / "q.json"
    save_json_atomic(path, {"kind": "q-goal", "q": [[0.0]]})
    status, err = run_cli(capsys, "fis", "show", str(path))
    assert status == 2
    assert f"{path}: kind: a 'q-goal' model file, not a fuzzy system" in err


@pytest.mark.parametrize("argv", [
    ["run", "fig-IV-12a", "--max-time", "1_0"], ["run", "fig-IV-12a", "--seed", "٣"],
    ["run", "fig-IV-12a", "--fps", "١٠"], ["train", "q-goal", "--episodes", "1_0"],
    ["demo", "--controllers", ""], ["demo", "--controllers", ","], ["warmup", "--controllers", " , "],
])
def test_numbers_are_ascii_decimals_and_name_lists_are_not_empty(argv, capsys):
    """Python's int and float read 1_0 and other scripts' digits: options took them silently; an
    empty --controllers ran every default controller (55 demo runs)."""
    with pytest.raises(SystemExit) as stop:  # argparse's usage error
        main(argv)
    assert stop.value.code == 2
    assert capsys.readouterr().err.strip().splitlines()[-1].startswith("fuzzynav ")


def test_one_file_for_the_plot_and_the_animation_is_refused(tmp_path, capsys):
    target = tmp_path / "x.gif"  # the plot was written, then the animation over it: "wrote x.gif" twice
    assert main(["run", "fig-IV-12a", "--plot", str(target), "--animate", str(target)]) == 2
    assert "is the --plot file too" in capsys.readouterr().err and not target.exists()


@pytest.mark.parametrize(("argv", "command", "hint"), [
    (["run", "fig-IV-23", "--contoller", "fuzzy-2b"], "fuzzynav run", "--controller"),
    (["fis", "eval", "goal-seeking", "--inpt", "drg=5"], "fuzzynav fis eval", "--input"),
])
def test_an_unknown_option_is_said_by_its_command_with_the_close_one(capsys, argv, command, hint):
    """As the command's other argparse errors: its usage line and its name, not fuzzynav's."""
    status, err = run_cli(capsys, *argv)
    assert status == 2
    assert err.startswith(f"usage: {command} ") and f"\n{command}: error: unrecognized arguments: " in err
    assert err.rstrip().endswith(f"(did you mean {hint}?)")


@pytest.mark.parametrize(("argv", "command"), [
    (["fis", "eval", "goal-seeking", "--input", "nope=1"], "fuzzynav fis eval"),
    (["fis", "show", "no-such-system"], "fuzzynav fis show"),
    (["import", "barn", "missing.world", "--out", "barn"], "fuzzynav import barn"),
    (["run", "no-such-scenario"], "fuzzynav run"),
])
def test_an_error_of_a_sub_command_is_said_by_its_own_name(capsys, tmp_path, monkeypatch, argv, command):
    """As argparse's errors are: ``fuzzynav fis eval: error: …``, not ``fuzzynav fis: error: …``."""
    monkeypatch.chdir(tmp_path)
    status, err = run_cli(capsys, *argv)
    assert status == 2 and err.startswith(f"{command}: error: "), err
