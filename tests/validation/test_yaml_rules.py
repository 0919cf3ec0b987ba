"""Both YAML readers (libyaml's C parser and the pure-Python one) follow the same YAML 1.2 rules
and bounds: ``1:20`` is a string, aliases and nesting are bounded, keys are plain and unique."""

import pytest
import yaml

from fuzzynav.yaml_loader import MAX_ALIASES, MAX_DEPTH, StrictLoader, load_yaml


def python_reader(text):
    return yaml.load(text, Loader=StrictLoader)  # noqa: S506 — a SafeLoader subclass


READERS = [pytest.param(load_yaml, id="libyaml" if yaml.__with_libyaml__ else "default"),
           pytest.param(python_reader, id="python")]


@pytest.mark.parametrize("read", READERS)
@pytest.mark.parametrize("text, value", [
    ("1:20", "1:20"), ("1e3", 1000.0), ("017", 17), ("0o17", 15), ("0x1F", 31), ("yes", "yes"), ("off", "off"),
    ("true", True), ("~", None), ("1_000", "1_000"), ("2001-12-14", "2001-12-14"), (".inf", float("inf")),
    ("-.5", -0.5), ("3.e1", 30.0),
])
def test_plain_scalars_follow_yaml_1_2(read, text, value):
    assert read(f"v: {text}") == {"v": value}


@pytest.mark.parametrize("read", READERS)
@pytest.mark.parametrize("text, problem", [
    ("[1, 2]: x", "a key must be a plain value"),
    ("a: 1\na: 2", "duplicate key 'a'"),
    ("v: " + "[" * (MAX_DEPTH + 1) + "]" * (MAX_DEPTH + 1), f"nested deeper than {MAX_DEPTH} levels"),
    ("a: &a [1]\nb: [" + ", ".join(["*a"] * (MAX_ALIASES + 1)) + "]", f"more than {MAX_ALIASES} aliases"),
    ("v: !!timestamp 2001-12-14", "could not determine a constructor"),
    ("v: !!python/object:os.system x", "could not determine a constructor"),
    ("v: !!float abc", "not a number"),
    ("v: " + "9" * 5000, "unreadable integer"),
])
def test_refusals(read, text, problem):
    with pytest.raises(yaml.YAMLError, match=problem):
        read(text)


def test_readers_agree_on_a_scenario_file():
    text = ("world: {width: 20, height: 1e1}\nrobot: {x: 1, y: 1}\n"
            "obstacles:\n  - polygon: {points: [[1, 2], [3, 4.5], [0x2, -1]]}\nname: 1:20\n")
    assert load_yaml(text) == python_reader(text)
