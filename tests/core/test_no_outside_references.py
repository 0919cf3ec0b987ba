"""The project stands alone: no code, help text or document points to the team's working notes
(the thesis is cited as "thesis Table IV.1" or through docs/thesis.md) or to issue numbers."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
OUTSIDE = re.compile(r"\bSPEC\b|\bDESIGN\.md\b|\b[Ii]ssue[ -]?#?\d+|\.\./shared\b")


def project_texts():
    for folder, patterns in (("src", ("*.py", "*.yaml")), ("docs", ("*.md",)), ("benchmarks", ("*.py",))):
        for pattern in patterns:
            yield from (ROOT / folder).rglob(pattern)
    yield from (ROOT / name for name in ("README.md", "CONTRIBUTING.md"))


def test_no_reference_to_working_notes_or_issue_numbers():
    found = [f"{path.relative_to(ROOT)}:{number}: {line.strip()[:100]}"
             for path in project_texts() if path.is_file()
             for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
             if OUTSIDE.search(line)]
    assert not found, "references outside the project:\n" + "\n".join(found)
