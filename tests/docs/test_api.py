"""The public Python API: every name importable from ``fuzzynav``, documented, imported lazily."""

import inspect
import subprocess
import sys

import fuzzynav


def public_members(obj):
    """The public methods and properties a class defines itself."""
    for name, value in vars(obj).items():
        if name.startswith("_"):
            continue
        if isinstance(value, (classmethod, staticmethod)):
            yield name, value.__func__
        elif callable(value) or isinstance(value, property):
            yield name, value


def test_every_public_name_resolves_and_has_a_docstring():
    undocumented = []
    for name in fuzzynav.__all__:
        obj = getattr(fuzzynav, name)
        if not (inspect.getdoc(obj) or "").strip():
            undocumented.append(name)
        if inspect.isclass(obj) and not issubclass(obj, Exception):
            undocumented += [f"{name}.{member}" for member, value in public_members(obj)
                             if not (value.__doc__ or "").strip()]
    assert not undocumented, undocumented


def test_unknown_names_raise_attribute_error():
    try:
        fuzzynav.no_such_thing  # noqa: B018
    except AttributeError as error:
        assert "no_such_thing" in str(error)
    else:
        raise AssertionError("fuzzynav.no_such_thing did not raise")


def test_import_fuzzynav_loads_no_heavy_module():
    code = "import sys, fuzzynav; print(sorted(m for m in ('numpy', 'matplotlib', 'scipy') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_the_api_runs_a_fuzzy_system_and_lists_controllers():
    system = fuzzynav.thesis_system("goal-seeking")
    alpha, speed = system.evaluate_one(5.0, 0.0)
    assert alpha == 0.0 and speed > 1.0  # goal straight ahead, 5 m away: no steering, cruising (Table IV.1)
    assert "fuzzy-5b" in fuzzynav.list_controllers() and "fql-goal" in fuzzynav.list_training_tasks()
