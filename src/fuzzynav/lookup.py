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


def require(name: str, names, *, what: str, field: str, listing: str | None = None) -> None:
    """Nothing if ``name`` is one of ``names``; else an :class:`InputError` on ``field`` that
    suggests close names and ends with ``listing`` (default: every known name)."""
    if name not in names:
        close = difflib.get_close_matches(name, list(names), n=3)
        hint = f" (did you mean {', '.join(close)}?)" if close else ""
        raise InputError(f"unknown {what} {name!r}{hint}; {listing or 'known: ' + ', '.join(sorted(names))}",
                         field=field)


def resolve(table: dict[str, tuple[str, str]], name: str, *, what: str, field: str, listing: str | None = None):
    """The object registered as ``name``; an unknown name is an :class:`InputError` (:func:`require`)."""
    require(name, table, what=what, field=field, listing=listing)
    module_name, attribute = table[name][0].split(":")
    return getattr(import_module(module_name), attribute)
