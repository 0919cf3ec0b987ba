"""Controllers are specs registered once: a name or alias taken twice is refused, aliases reach
the same controller, a distribution adds its own through the ``fuzzynav.controllers`` entry point,
and ``run`` / ``evaluate`` / ``bench`` refuse a controller that cannot do the scenario's task."""

import json

import pytest

from fuzzynav.catalog import controllers as registry
from fuzzynav.catalog.roles import ROLES
from fuzzynav.catalog.specs import ControllerSpec
from fuzzynav.cli import main
from fuzzynav.errors import InputError
from tests.catalog.plugin_navigator import NAVIGATOR
from tests.catalog.plugins import installed


def test_a_name_or_alias_taken_twice_is_refused():
    twin = ControllerSpec("goal-seeking", "tests.catalog.plugin_navigator:make", "a twin", "tests", ("goal",))
    with pytest.raises(ValueError, match="'goal-seeking' is already registered"):
        registry.register_controller(twin)
    alias_twin = ControllerSpec("new-name", "tests.catalog.plugin_navigator:make", "a twin", "tests", ("goal",),
                                aliases=("fuzzy-5b-gap-robust",))
    with pytest.raises(ValueError, match="'fuzzy-5b-gap-robust' is already registered \\(by 'fuzzy-5b'\\)"):
        registry.register_controller(alias_twin)
    assert "new-name" not in registry.CONTROLLERS  # nothing half-registered


@pytest.mark.parametrize("fields, message", [
    ({"name": "Bad Name"}, "is not a name"),
    ({"factory": "no-colon"}, "factory must be 'module:attribute'"),
    ({"tasks": ("fly",)}, "tasks must be some of goal, path, target"),
    ({"tasks": ()}, "tasks must be some of"),
    ({"sensors": "sonar"}, "sensors must be one of"),
    ({"citation": ""}, "give a description and a citation"),
    ({"version": 0}, "version must be an integer >= 1"),
    ({"brief": "x" * 61}, "brief must be at most 60 characters"),
])
def test_a_spec_checks_its_fields(fields, message):
    good = {"name": "x", "factory": "m:f", "description": "d", "citation": "c", "tasks": ("goal",)}
    with pytest.raises(ValueError, match=message):
        ControllerSpec(**{**good, **fields})


def test_an_alias_builds_the_same_controller_under_the_name_asked_for():
    assert registry.spec_of("fuzzy-5b-gap-robust") is registry.CONTROLLERS["fuzzy-5b"]
    assert registry.make_controller("fuzzy-5b-gap-robust").name == "fuzzy-5b-gap-robust"
    assert registry.make_controller("fuzzy-5b").name == "fuzzy-5b"
    assert registry.CONTROLLERS["fuzzy-5b"].version == 15 and "fuzzy-5b-rays" in registry.CONTROLLERS
    assert ROLES["fuzzy-5b-gap-robust"] == ROLES["fuzzy-5b"]


def test_a_controller_from_an_installed_distribution(monkeypatch, tmp_path, capsys):
    """The recipe from outside the package: a module with the class and its spec, and one entry
    point line in the distribution's metadata; nothing of fuzzynav is edited."""
    with installed(monkeypatch, tmp_path, registry.CONTROLLERS,
                   {"plugin-heading": "tests.catalog.plugin_navigator:NAVIGATOR"}):
        assert registry.CONTROLLERS["plugin-heading"] is NAVIGATOR
        assert "plugin-heading" in registry.available()
        assert main(["run", "example-goal", "--controller", "plugin-heading-v1", "--json"]) == 0
        numbers = json.loads(capsys.readouterr().out)
        assert numbers["controller"] == "plugin-heading-v1" and numbers["steps"] > 10
        assert main(["run", "path-v", "--controller", "plugin-heading"]) == 2
        assert "plugin-heading cannot do a path task" in capsys.readouterr().err
    assert "plugin-heading" not in registry.CONTROLLERS


def test_a_broken_or_clashing_plugin_is_named(monkeypatch, tmp_path):
    with pytest.raises(InputError, match="entry point twin = tests.catalog.plugin_navigator:make .* is not a "
                                         "ControllerSpec"):
        with installed(monkeypatch, tmp_path / "a", registry.CONTROLLERS,
                       {"twin": "tests.catalog.plugin_navigator:make"}):
            registry.spec_of("twin")
    clash = tmp_path / "b"
    clash.mkdir()
    (clash / "clashing.py").write_text("from tests.catalog.plugin_navigator import NAVIGATOR\n"
                                       "from dataclasses import replace\nNAVIGATOR = replace(NAVIGATOR, name='dwa')\n")
    with pytest.raises(InputError, match="'dwa' is already registered"):
        with installed(monkeypatch, clash, registry.CONTROLLERS, {"dwa": "clashing:NAVIGATOR"}):
            registry.spec_of("dwa")


@pytest.mark.parametrize("argv, message", [
    (["run", "path-n", "--controller", "fuzzy-5b"],
     "--controller: fuzzy-5b cannot do a path task (it does: goal); for a path task use one of anfis-tracker,"),
    (["run", "example-goal", "--controller", "stanley"],
     "--controller: stanley cannot do a goal task (it does: path, target); for a goal task use one of "),
    (["run", "example-target", "--controller", "goal-seeking"], "goal-seeking cannot do a target task"),
    (["evaluate", "--controller", "pure-pursuit", "--worlds", "circles", "--n", "1"],
     "pure-pursuit cannot do a goal task"),
    (["bench", "circles:1", "--controllers", "goal-seeking,fuzzy-tracker", "--out", "OUT"],
     "--controllers: fuzzy-tracker cannot do a goal task"),
])
def test_a_controller_that_cannot_do_the_task_is_refused(argv, message, capsys, tmp_path):
    argv = [str(tmp_path / "out") if a == "OUT" else a for a in argv]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1
    assert not (tmp_path / "out").exists()


def test_a_long_description_without_a_brief_is_cut_after_a_word():
    spec = ControllerSpec("x", "m:f", "a very long description " * 5 + "; and more", "c", ("goal",))
    assert spec.short == "a very long description a very long description a very…"  # 55 + 1 characters
    assert ControllerSpec("x", "m:f", "short; and more", "c", ("goal",)).short == "short"
