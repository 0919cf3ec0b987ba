"""CONTRIBUTING.md's rule "No module over 400 lines", checked on every module of the package."""

from pathlib import Path

import fuzzynav

PACKAGE = Path(fuzzynav.__file__).resolve().parent
MOST = 400


def test_no_module_is_over_400_lines():
    sizes = {str(source.relative_to(PACKAGE)): len(source.read_text(encoding="utf-8").splitlines())
             for source in sorted(PACKAGE.rglob("*.py"))}
    assert len(sizes) > 100
    assert {name: lines for name, lines in sizes.items() if lines > MOST} == {}, "split these modules by purpose"
