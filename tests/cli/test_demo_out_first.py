"""``fuzzynav demo --out`` that is a file (or lies under one) is refused before the demo prints its
header or says it compiles (it used to print both, then fail "is a file, not a folder")."""

import pytest

from fuzzynav.cli import main


@pytest.mark.parametrize("under, expected", [
    ("", "afile: --out: is a file, not a folder (give a new or an existing folder)"),
    ("sub", "--out: cannot write in {afile}: a file, not a folder"),
])
def test_an_out_that_is_a_file_is_refused_first(tmp_path, capsys, under, expected):
    afile = tmp_path / "afile"
    afile.write_text("x")
    assert main(["demo", "--scenario", "fig-IV-12a", "--out", str(afile / under if under else afile)]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""  # no header
    assert captured.err.strip().endswith(expected.format(afile=afile)) and len(captured.err.splitlines()) == 1, \
        captured.err
    assert afile.read_text() == "x"


def test_a_table_name_taken_by_a_folder_is_refused_first(tmp_path, capsys):
    (tmp_path / "o" / "metrics.md").mkdir(parents=True)
    assert main(["demo", "--scenario", "fig-IV-12a", "--out", str(tmp_path / "o")]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and "metrics.md: --out: is a folder where this command writes a file" in captured.err
