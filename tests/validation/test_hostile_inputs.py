"""Every hostile input of the validation review, as a regression test: refused with exit status
2 (or an InputError) and a message naming the file and the field — or accepted where it is fine
(a CSV with a UTF-8 byte-order mark). Cases: ``hostile_cases.py``."""

from __future__ import annotations

import os

import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError

from .hostile_cases import CASES, PYTHON_PRELUDE, argv_of, write_files


@pytest.mark.parametrize("case", CASES, ids=[case.name for case in CASES])
def test_hostile_input(case, tmp_path, capsys):
    write_files(case, tmp_path)
    if case.python:
        namespace = {"d": tmp_path}
        exec(PYTHON_PRELUDE, namespace)  # noqa: S102 - the test's own code
        if case.status == 0:
            exec(case.python, namespace)  # noqa: S102
            assert case.expect in capsys.readouterr().out
            return
        with pytest.raises(InputError) as error:
            exec(case.python, namespace)  # noqa: S102
        assert case.expect in str(error.value)
        return
    try:
        status = main(argv_of(case, tmp_path))
    except SystemExit as exit_:  # refused by an option's type (argparse)
        status = exit_.code
    out, err = capsys.readouterr()
    assert status == case.status, err
    assert case.expect in (err if status else out), err
    if status:
        assert out == "" and "Traceback" not in err


def test_fis_convert_output_is_atomic(tmp_path, monkeypatch):
    """``fis convert -o`` writes a temporary file beside the output and renames it onto the output."""
    import fuzzynav.storage

    renames = []
    real = os.replace
    monkeypatch.setattr(fuzzynav.storage.os, "replace", lambda src, dst: (renames.append((src, dst)), real(src, dst)))
    out = tmp_path / "g.fll"
    assert main(["fis", "convert", "goal-seeking", "--to", "fll", "-o", str(out)]) == 0
    assert [os.path.basename(dst) for _, dst in renames] == ["g.fll"]
    assert os.path.basename(renames[0][0]).startswith(".g.fll.") and out.read_text().startswith("Engine:")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["g.fll"]


def test_stale_temporary_is_removed_by_the_next_save(tmp_path):
    from fuzzynav.storage import save_json_atomic

    stale = tmp_path / ".m.json.abc123.tmp"
    stale.write_text("half a model")
    os.utime(stale, (0, 0))  # left by a save killed long ago
    save_json_atomic(tmp_path / "m.json", {"kind": "x"})
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.json"]


def test_npz_deflate_bomb_refused_before_decompressing(tmp_path):
    """A member declaring more than the limit once decompressed is refused from its zip header."""
    import zipfile

    import numpy as np

    from fuzzynav.validation import check_npz

    path = tmp_path / "bomb.npz"
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        with archive.open("kind.npy", "w") as member:
            np.lib.format.write_array(member, np.zeros(2**18))  # 2 MiB of zeros, a few KiB compressed
    assert path.stat().st_size < 50_000
    with pytest.raises(InputError, match="bomb.npz: kind.npy: arrays larger than the 1 MiB limit"):
        check_npz(path, max_bytes=2**20)
