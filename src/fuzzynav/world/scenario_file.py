"""Writing scenarios as files: the YAML that :func:`fuzzynav.world.scenario.load_scenario` reads back.

``fuzzynav worlds generate`` and ``fuzzynav evaluate --save-failures`` write generated worlds with
:func:`save_scenario`, so any of them can be rerun with ``fuzzynav run FILE`` or edited by hand.
The file is written to a temporary name and renamed, so an interrupted save leaves no half file.
:func:`open_scenario` also opens a generated world by the name ``evaluate`` gives it.
"""

from __future__ import annotations

from pathlib import Path

import yaml

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.storage import write_text_atomic
from fuzzynav.world.scenario import Scenario, load_scenario


def scenario_yaml(scenario: Scenario, controllers: tuple[str, ...] = ()) -> str:
    """The scenario-file text of ``scenario`` (one line per obstacle), naming ``controllers`` if given."""
    document = scenario.to_dict()
    if controllers:
        document = {"name": document.pop("name"), "controllers": list(controllers), **document}
    obstacles = document.pop("obstacles")
    text = yaml.safe_dump(document, sort_keys=False, default_flow_style=None, width=100, allow_unicode=True)
    lines = [f"  - {yaml.safe_dump(shape, sort_keys=False, default_flow_style=True, width=1000).strip()}" for shape in obstacles]
    return text + "obstacles:" + ("\n" + "\n".join(lines) if lines else " []") + "\n"


def save_scenario(scenario: Scenario, path, controllers: tuple[str, ...] = ()) -> Path:
    """Write ``scenario`` as a YAML scenario file at ``path`` (atomically); returns the path."""
    if not isinstance(scenario, Scenario):
        raise InputError(f"must be a Scenario, got {type(scenario).__name__}", field="scenario")
    path = validation.file_path(path, field="path")
    write_text_atomic(path, scenario_yaml(scenario, controllers))
    return path


def open_scenario(name_or_path) -> Scenario:
    """A scenario file, a built-in scenario, or a generated world by its name (``mixed-0-009``:
    world 9 of ``fuzzynav evaluate --worlds mixed --seed 0``)."""
    try:
        return load_scenario(name_or_path)
    except InputError:
        from fuzzynav.world.generate import generated_world

        world = generated_world(str(name_or_path))
        if world is None:
            raise
        return world
