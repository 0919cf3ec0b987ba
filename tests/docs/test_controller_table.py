"""The controller table of the user guide is the one the specs generate (names, aliases, what
each is, its source, the tasks it does and what it reads)."""

from pathlib import Path

from fuzzynav.catalog.controllers import controller_table

GUIDE = Path(__file__).resolve().parents[2] / "docs" / "guide" / "controllers.md"


def test_the_guide_shows_the_table_of_the_specs():
    assert controller_table() in GUIDE.read_text(encoding="utf-8"), (
        "docs/guide/controllers.md is out of date: paste fuzzynav.catalog.controllers.controller_table()")
