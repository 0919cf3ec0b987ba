"""The pages that tell a contributor where things are name only what exists: every file path and
every module or attribute (``fuzzynav.kernels.step``, ``kernels.records.CarSearch``,
``catalog.controllers.register_controller``) quoted in CONTRIBUTING.md and docs/ARCHITECTURE.md
is there. A renamed module or moved test breaks this test, not a reader's first try."""

import importlib
import re
from pathlib import Path

import pytest

from fuzzynav.catalog.controllers import CONTROLLERS
from fuzzynav.catalog.experiments import EXPERIMENTS
from fuzzynav.catalog.tasks import TASKS

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "src" / "fuzzynav"
PAGES = [ROOT / "CONTRIBUTING.md", ROOT / "docs" / "ARCHITECTURE.md"]
SUBPACKAGES = sorted(p.name for p in PACKAGE.iterdir() if (p / "__init__.py").is_file())
PATH = re.compile(r"(?<![\w/.<])(?:(?:tests|benchmarks|docs|src)/[\w/.-]+|\w+/[\w/]*\w\.(?:py|md))")
DOTTED = re.compile(rf"^(?:fuzzynav|{'|'.join(SUBPACKAGES)})(?:\.\w+)+")
ENTRY_POINT_GROUPS = {CONTROLLERS.group, TASKS.group, EXPERIMENTS.group}  # names of groups, not of modules
NOT_IMPORTED = {"fuzzynav.__main__"}  # importing it runs the command line


def quoted(page: Path) -> list[str]:
    """The inline code spans of ``page`` that hold no placeholder (``control/<name>.py``)."""
    text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
    return [span for span in re.findall(r"`([^`]+)`", text) if "<" not in span]


def paths(page: Path) -> list[str]:
    return sorted({match for span in quoted(page) for match in PATH.findall(span)})


def names(page: Path) -> list[str]:
    found = {match.group(0) for span in quoted(page) if (match := DOTTED.match(span))}
    return sorted(found - ENTRY_POINT_GROUPS - NOT_IMPORTED)


def resolves(name: str) -> bool:
    """Is ``name`` (``fuzzynav.`` may be left out) a module of the package, or an attribute of one?"""
    parts = (name if name.startswith("fuzzynav.") else f"fuzzynav.{name}").split(".")
    for cut in range(len(parts), 1, -1):
        try:
            found = importlib.import_module(".".join(parts[:cut]))
        except ModuleNotFoundError:
            continue
        for attribute in parts[cut:]:
            if not hasattr(found, attribute):
                return False
            found = getattr(found, attribute)
        return True
    return False


@pytest.mark.parametrize("page", PAGES, ids=lambda page: page.name)
def test_every_path_the_page_quotes_exists(page):
    quoted_paths = paths(page)
    assert len(quoted_paths) >= 5
    missing = [p for p in quoted_paths if not ((ROOT / p).exists() or (PACKAGE / p).exists())]
    assert missing == []


@pytest.mark.parametrize("page", PAGES, ids=lambda page: page.name)
def test_every_module_and_attribute_the_page_names_exists(page):
    quoted_names = names(page)
    assert len(quoted_names) >= 5
    assert [name for name in quoted_names if not resolves(name)] == []


def test_the_checks_see_a_wrong_name(tmp_path):
    page = tmp_path / "page.md"
    page.write_text("`kernels/nowhere.py`, `tests/core/test_import_layers.py`, `kernels.step.no_such_kernel`, "
                    "`fuzzynav.kernels.records.CarSearch`, `control/<name>.py`, `fuzzynav.controllers`\n",
                    encoding="utf-8")
    assert paths(page) == ["kernels/nowhere.py", "tests/core/test_import_layers.py"]
    assert names(page) == ["fuzzynav.kernels.records.CarSearch", "kernels.step.no_such_kernel"]
    assert [resolves(name) for name in names(page)] == [True, False]
