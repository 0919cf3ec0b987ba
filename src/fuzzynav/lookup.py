"""Name registries: ``name -> ("module:attribute", description)`` tables, imported lazily.

The tables of the command line (controllers, training tasks, thesis experiments) are such
tables; a module is imported only
when its entry is used, so listing names stays cheap.
"""

from __future__ import annotations

import difflib
from importlib import import_module

from fuzzynav.errors import InputError


def descriptions(table: dict[str, tuple[str, str]]) -> dict[str, str]:
    """Names with their one-line descriptions, sorted by name."""
    return {name: description for name, (_, description) in sorted(table.items())}


def resolve(table: dict[str, tuple[str, str]], name: str, *, what: str, field: str, listing: str | None = None):
    """The object registered as ``name``; an unknown name is an :class:`InputError` on ``field``
    that suggests close names and ends with ``listing`` (default: every known name)."""
    if name not in table:
        close = difflib.get_close_matches(name, table, n=3)
        hint = f" (did you mean {', '.join(close)}?)" if close else ""
        raise InputError(f"unknown {what} {name!r}{hint}; {listing or 'known: ' + ', '.join(sorted(table))}",
                         field=field)
    module_name, attribute = table[name][0].split(":")
    return getattr(import_module(module_name), attribute)
