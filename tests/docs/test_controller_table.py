"""The controller table of the user guide is the one the specs generate (names, aliases, what
each is, its source, the tasks it does and what it reads)."""

from pathlib import Path

from fuzzynav.catalog.controllers import controller_table

GUIDE = Path(__file__).resolve().parents[2] / "docs" / "guide" / "controllers.md"


def test_the_guide_shows_the_table_of_the_specs():
    assert controller_table() in GUIDE.read_text(encoding="utf-8"), (
        "docs/guide/controllers.md is out of date: paste fuzzynav.catalog.controllers.controller_table()")


def test_no_other_page_describes_the_controllers_in_a_table_of_its_own():
    """A table whose first column names three or more registered controllers and that has a
    descriptive column ("what") is a copy of the specs: pages link the guide's instead. Tables of
    measured numbers (one row a controller) are not descriptions and stay."""
    import re

    from fuzzynav.catalog.controllers import CONTROLLERS

    docs = GUIDE.parents[1]
    copies = []
    for page in sorted(docs.rglob("*.md")):
        if page == GUIDE:
            continue
        for table in re.findall(r"(?:^\|.*\|\n)+", page.read_text(encoding="utf-8"), flags=re.M):
            header, *rows = table.splitlines()
            first = [re.match(r"\| `([\w-]+)`", row) for row in rows]
            named = [match.group(1) for match in first if match and match.group(1) in CONTROLLERS]
            if len(named) >= 3 and re.search(r"\|\s*what\b", header):
                copies.append(page.relative_to(docs).as_posix())
    assert copies == []
