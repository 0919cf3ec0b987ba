"""Name registries: each name maps to a spec that says what the thing is and where it lives.

The tables of the command line (controllers, training tasks, thesis experiments) are such
registries. A spec names its object as a ``"module:attribute"`` string, imported only when the
entry is used (:func:`load`), so listing names stays cheap. :class:`Registry` holds specs by name:
it refuses a second spec under a name (or alias) already taken, resolves aliases, suggests close
names for an unknown one, and adds the specs that installed distributions declare under an entry
point group (plug-ins, read once on first use).
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Iterator, Mapping
from importlib import import_module, metadata
from typing import Generic, Protocol, TypeVar, cast

from fuzzynav.errors import InputError


class Spec(Protocol):
    """What a registry needs of a spec: its name and the other names it answers to."""

    @property
    def name(self) -> str: ...

    @property
    def aliases(self) -> tuple[str, ...]: ...


S = TypeVar("S", bound=Spec)


def load(target: str):
    """The object ``"module:attribute"`` names (the module is imported now)."""
    module_name, attribute = target.split(":")
    return getattr(import_module(module_name), attribute)


def descriptions(table: dict[str, tuple[str, str]]) -> dict[str, str]:
    """Names with their one-line descriptions, sorted by name."""
    return {name: description for name, (_, description) in sorted(table.items())}


def unknown(names, name: str, *, what: str, field: str, listing: str | None = None) -> InputError:
    """The error for a ``name`` that is none of ``names``: close names suggested, then ``listing``
    (default: every known name)."""
    close = difflib.get_close_matches(name, list(names), n=3)
    hint = f" (did you mean {', '.join(close)}?)" if close else ""
    return InputError(f"unknown {what} {name!r}{hint}; {listing or 'known: ' + ', '.join(sorted(names))}",
                      field=field)


def resolve(table: dict[str, tuple[str, str]], name: str, *, what: str, field: str, listing: str | None = None):
    """The object registered as ``name``; an unknown name is an :class:`InputError` on ``field``
    that suggests close names and ends with ``listing`` (default: every known name)."""
    if name not in table:
        raise unknown(table, name, what=what, field=field, listing=listing)
    return load(table[name][0])


class Registry(Mapping[str, S], Generic[S]):
    """Specs by name (a read-only mapping over the names; aliases resolve through :meth:`find`).

    ``what`` and ``field`` word the error for an unknown name (``unknown controller 'x'`` on
    ``--controller``); ``group`` is the entry point group whose objects — a spec or a sequence of
    specs — are registered on first use, so an installed distribution adds its own entries;
    ``check(spec, registered)`` (optional) raises a ``ValueError`` when ``spec`` conflicts with
    the specs already registered in a way names do not show.
    """

    def __init__(self, what: str, field: str, kind: type, group: str | None = None,
                 check: Callable[[S, list[S]], None] | None = None):
        self.what, self.field, self.kind, self.group, self.check = what, field, kind, group, check
        self._specs: dict[str, S] = {}
        self._aliases: dict[str, str] = {}
        self._plugins_read = group is None

    def register(self, spec: S) -> S:
        """Add ``spec``; a name or alias already taken is a ``ValueError`` (nothing is replaced)."""
        if not isinstance(spec, self.kind):
            raise TypeError(f"a {self.what} registry holds {self.kind.__name__} objects, got {spec!r}")
        names = (spec.name, *spec.aliases)
        for name in names:
            owner = self._specs.get(name) or self._specs.get(self._aliases.get(name, ""))
            if owner is not None:
                raise ValueError(f"{self.what} name {name!r} is already registered (by {owner.name!r}); "
                                 "give the new one another name, or an alias")
        if len(set(names)) != len(names):
            raise ValueError(f"{self.what} {spec.name!r} lists a name twice: {', '.join(names)}")
        if self.check is not None:
            self.check(spec, list(self._specs.values()))
        self._specs[spec.name] = spec
        self._aliases.update({alias: spec.name for alias in spec.aliases})
        return spec

    def unregister(self, name: str) -> S:
        """Remove the spec named ``name`` with its aliases, and return it."""
        spec = self._specs.pop(name)
        for alias in spec.aliases:
            del self._aliases[alias]
        return spec

    def find(self, name: str, listing: str | None = None) -> S:
        """The spec registered as ``name`` or under the alias ``name``; an :class:`InputError` on
        the registry's field otherwise, suggesting close names (or aliases) and ending with
        ``listing`` (default: every name, aliases left out)."""
        self._read_plugins()
        if name in self._specs:
            return self._specs[name]
        if name in self._aliases:
            return self._specs[self._aliases[name]]
        raise unknown(self.names(), name, what=self.what, field=self.field,
                      listing=listing or "known: " + ", ".join(sorted(self._specs)))

    def names(self) -> list[str]:
        """Every name and alias, sorted."""
        self._read_plugins()
        return sorted([*self._specs, *self._aliases])

    def aliases(self) -> dict[str, str]:
        """alias -> the name it stands for."""
        self._read_plugins()
        return dict(self._aliases)

    def _read_plugins(self) -> None:
        if self._plugins_read or self.group is None:
            return
        self._plugins_read = True
        for point in metadata.entry_points(group=self.group):
            source = f"entry point {point.name} = {point.value} ({self.group})"
            try:
                found = point.load()
            except Exception as error:  # a broken plug-in is named, not a traceback
                raise InputError(f"cannot be loaded: {error}", source=source) from error
            for spec in found if isinstance(found, list | tuple) else (found,):
                if not isinstance(spec, self.kind):
                    raise InputError(f"is not a {self.kind.__name__} (got {type(spec).__name__})", source=source)
                try:
                    self.register(cast(S, spec))
                except ValueError as error:
                    raise InputError(str(error), source=source) from None

    def __getitem__(self, name: str) -> S:
        self._read_plugins()
        return self._specs[name]

    def __iter__(self) -> Iterator[str]:
        self._read_plugins()
        return iter(dict(self._specs))

    def __len__(self) -> int:
        self._read_plugins()
        return len(self._specs)

    def __repr__(self) -> str:
        return f"Registry({self.what}: {', '.join(self)})"

