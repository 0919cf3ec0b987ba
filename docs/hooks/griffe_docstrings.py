"""A griffe extension for the API reference (mkdocstrings): the docstrings' Sphinx roles become
links, and every documented function gets a parameter table with types.

- ``:func:`~fuzzynav.sim.metrics.metrics``` (and ``:class:``, ``:meth:``, ``:mod:``, ``:data:``,
  ``:attr:``, ``:exc:``) becomes a cross-reference ``[metrics][fuzzynav.sim.metrics.metrics]``
  when the reference renders that object (it is named by a ``::: identifier`` line of
  ``docs/guide/api.md``, or is a member of one), else the name as code;
- a function or method whose docstring has no parameter section gets one from its signature:
  the page shows a table of its parameters with their types and defaults (what each one means
  is said by the docstring's text).

The docstrings in the source stay as they are (Sphinx roles read well in ``help()``).
"""

from __future__ import annotations

import re
from pathlib import Path

import griffe

API_PAGE = Path(__file__).resolve().parents[1] / "guide" / "api.md"
ROLE = re.compile(r":(?:py:)?(?:func|class|meth|mod|data|attr|exc|obj):`(~?)([\w.]+)`")


def rendered_identifiers(page: Path = API_PAGE) -> set[str]:
    """The identifiers of the ``::: identifier`` lines of the API page."""
    return {line[4:].strip() for line in page.read_text(encoding="utf-8").splitlines() if line.startswith("::: ")}


class SphinxRolesToLinks(griffe.Extension):
    """The extension of the module docstring."""

    def __init__(self) -> None:
        super().__init__()
        self.rendered = rendered_identifiers()

    def _linkable(self, path: str) -> bool:
        return any(path == name or path.startswith(name + ".") for name in self.rendered)

    def _replace(self, match: re.Match) -> str:
        tilde, path = match.groups()
        shown = path.rsplit(".", 1)[-1] if tilde else path
        return f"[`{shown}`][{path}]" if self._linkable(path) else f"`{shown}`"

    def on_instance(self, *, obj: griffe.Object, **kwargs) -> None:
        if obj.docstring is None:
            return
        text = ROLE.sub(self._replace, obj.docstring.value)
        if isinstance(obj, griffe.Function) and ":param " not in text:
            text += "".join(f"\n:param {p.name}:" for p in obj.parameters if p.name not in ("self", "cls"))
        obj.docstring.value = text
