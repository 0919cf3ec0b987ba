"""A model file or a fuzzy system given where a scenario is read is named as what it is, not
refused for its first key ("kind: unknown key 'kind'")."""

import pytest

from fuzzynav.cli import main


@pytest.mark.parametrize(("write", "said"), [
    (["train", "anfis-tracker", "--quiet", "--out", "{f}"], "kind: a model file (kind 'anfis-tracker'), not a "
     "scenario: a model drives a scenario (`fuzzynav run SCENARIO --model FILE`)"),
    (["fis", "convert", "goal-seeking", "--to", "yaml", "-o", "{f}"], "a fuzzy system, not a scenario: it stands in "
     "for a controller's rule table (`fuzzynav run SCENARIO --fis ROLE=FILE`"),
])
def test_a_file_of_another_kind_given_as_a_scenario_is_named_as_such(write, said, tmp_path, capsys):
    path = tmp_path / ("m.json" if "train" in write else "s.yaml")
    assert main([arg.format(f=path) for arg in write]) == 0
    capsys.readouterr()
    assert main(["run", str(path)]) == 2
    assert f"{path.name}: {said}" in capsys.readouterr().err
