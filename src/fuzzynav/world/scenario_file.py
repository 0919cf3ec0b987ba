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
from fuzzynav.world.scenario import BUILTIN_DIR, Scenario, load_scenario

MAX_CONTROLLER_NAME = 100  # characters of a controller name (as load_scenario reads them)


def controller_names(controllers) -> tuple[str, ...]:
    """``controllers`` checked: one name (a string) or a list / tuple of names, each a non-empty
    string of at most :data:`MAX_CONTROLLER_NAME` characters (whether a controller of that name is
    registered is checked when it is run, as for a scenario file's own ``controllers``)."""
    if controllers is None:
        return ()
    if isinstance(controllers, str):
        controllers = [controllers]
    names = validation.sequence(controllers, field="controllers")
    for i, name in enumerate(names):
        validation.text(name, field=f"controllers[{i}]", max_length=MAX_CONTROLLER_NAME, allow_empty=False)
    return tuple(names)


def scenario_yaml(scenario: Scenario, controllers: tuple[str, ...] | str = ()) -> str:
    """The scenario-file text of ``scenario`` (one line per obstacle), naming ``controllers`` if
    given (:func:`controller_names`: they replace the scenario's own), else the scenario's own."""
    names = controller_names(controllers)
    document = scenario.to_dict()
    if names:
        document.pop("controllers", None)
        document = {"name": document.pop("name"), "controllers": list(names), **document}
    obstacles = document.pop("obstacles")
    text = yaml.safe_dump(document, sort_keys=False, default_flow_style=None, width=100, allow_unicode=True)
    lines = [f"  - {yaml.safe_dump(shape, sort_keys=False, default_flow_style=True, width=1000).strip()}" for shape in obstacles]
    return text + "obstacles:" + ("\n" + "\n".join(lines) if lines else " []") + "\n"


def save_scenario(scenario: Scenario, path, controllers: tuple[str, ...] | str = ()) -> Path:
    """Write ``scenario`` as a YAML scenario file at ``path`` (atomically), naming ``controllers``
    if given, else the scenario's own (:func:`scenario_yaml`); returns the path."""
    if not isinstance(scenario, Scenario):
        raise InputError(f"must be a Scenario, got {type(scenario).__name__}", field="scenario")
    path = validation.file_path(path, field="path")
    text = scenario_yaml(scenario, controllers)  # checked before anything is written
    write_text_atomic(path, text)
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


def shadows_a_name(name_or_path) -> bool:
    """Whether ``name_or_path`` is a file (which :func:`open_scenario` opens) that has the name of
    a built-in scenario or of a generated world, which it hides: the runs would be labelled alike."""
    if not Path(str(name_or_path)).is_file():
        return False
    from fuzzynav.world.generate import generated_world

    return (BUILTIN_DIR / f"{name_or_path}.yaml").is_file() or generated_world(str(name_or_path)) is not None


def refuse_overwriting_edits(texts: dict, source, field: str) -> None:
    """Refuse to write the scenario files ``texts`` (path -> text) when one of them is already there
    with other content (edited by hand, most likely): nothing is overwritten, nothing written."""
    edited = [path.name for path, text in texts.items() if path.is_file() and path.read_bytes() != text.encode()]
    if edited:
        more = f" and {len(edited) - 1} more" if len(edited) > 1 else ""
        validation.fail(f"{edited[0]}{more} already there, with other content (edited?): not overwritten; move "
                        f"{'them' if more else 'it'} away or choose another folder", source, field)
