"""``fuzzynav import barn`` reads every world before it makes ``--out``: an invalid world leaves no
empty folder behind (it used to), and an ``--out`` that is a file is refused before any world is read."""

from fuzzynav.cli import main


def test_an_invalid_world_leaves_no_folder(tmp_path, capsys):
    (tmp_path / "bad.world").write_text("<sdf/>\n")
    assert main(["import", "barn", str(tmp_path / "bad.world"), "--out", str(tmp_path / "barn")]) == 2
    assert "no <world> element" in capsys.readouterr().err
    assert not (tmp_path / "barn").exists()


def test_an_out_that_is_a_file_is_refused_before_the_worlds_are_read(tmp_path, capsys):
    (tmp_path / "bad.world").write_text("<sdf/>\n")
    (tmp_path / "afile").write_text("x")
    assert main(["import", "barn", str(tmp_path / "bad.world"), "--out", str(tmp_path / "afile")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.endswith("afile: --out: is a file, not a folder (give a new or an existing folder)"), err
