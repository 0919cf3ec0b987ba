"""A folder of worlds (``bench FOLDER``, ``tune --worlds FOLDER``) holds every scenario file that
``run`` reads: ``.yaml`` and ``.yml``, in any case."""

import pytest

from fuzzynav.bench.suites import parse_suite
from fuzzynav.errors import InputError
from fuzzynav.world.scenario import BUILTIN_DIR


def test_a_folder_reads_yml_and_any_case_in_natural_order(tmp_path):
    text = (BUILTIN_DIR / "example-goal.yaml").read_text()
    for name in ("w10.yaml", "w2.yml", "w3.YAML", "notes.txt"):
        (tmp_path / name).write_text(text)
    suite = parse_suite(str(tmp_path))
    assert [f.rsplit("/", 1)[-1] for f in suite.files] == ["w2.yml", "w3.YAML", "w10.yaml"]


def test_a_folder_without_scenario_files_is_refused_by_name(tmp_path):
    (tmp_path / "notes.txt").write_text("no worlds here")
    with pytest.raises(InputError, match=r"folder has no scenario files \(\*\.yaml, \*\.yml\)"):
        parse_suite(str(tmp_path))


def test_two_files_of_one_name_are_refused_not_merged(tmp_path):
    text = (BUILTIN_DIR / "example-goal.yaml").read_text()
    for name in ("w1.yaml", "W1.yml", "w2.yaml"):
        (tmp_path / name).write_text(text)
    with pytest.raises(InputError, match=r"W1\.yml, w1\.yaml would be one world"):
        parse_suite(str(tmp_path))


def test_seeds_of_a_folder_say_that_its_worlds_repeat(tmp_path, capsys):
    """A folder's worlds are the same for every seed: a deterministic navigator repeats its run, and
    the intervals would count the repeats as trials without a word."""
    from fuzzynav.cli import main

    (tmp_path / "w").mkdir()
    (tmp_path / "w" / "a.yaml").write_text("robot: {x: 2, y: 2}\ngoal: {x: 6, y: 2}\nmax_time: 5\n")
    args = ["bench", str(tmp_path / "w"), "circles:1", "--controllers", "goal-seeking", "--quiet", "--gallery", "0"]
    assert main([*args, "--seeds", "2", "--out", str(tmp_path / "o2")]) == 0
    assert f"note: {tmp_path / 'w'}: a folder's worlds are the same for every seed" in capsys.readouterr().err
    assert main([*args, "--out", str(tmp_path / "o1")]) == 0
    assert "note:" not in capsys.readouterr().err
