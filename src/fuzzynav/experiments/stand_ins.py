"""Stand-ins for what the experiments run, in force inside a ``with`` block: the replaced rule
bases of ``reproduce --fis`` (:mod:`.rule_bases`) and the replaced learned models
(:mod:`.learned_models`), each kept in a context variable (per thread and task)."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from contextvars import ContextVar
from types import MappingProxyType

from fuzzynav.errors import InputError


class StandIns:
    """Stand-ins by name among ``known`` (``what`` and ``known_label`` word the refusal of another
    name, ``field`` names the option that gave it)."""

    def __init__(self, name: str, known, what: str, known_label: str, field: str):
        self._current: ContextVar[Mapping] = ContextVar(name, default=MappingProxyType({}))
        self.known, self.what, self.known_label, self.field = tuple(known), what, known_label, field

    @contextmanager
    def replaced(self, stand_ins: Mapping) -> Iterator[None]:
        """Run the experiments inside with ``stand_ins`` ({name: stand-in}) in force."""
        unknown = sorted(set(stand_ins) - set(self.known))
        if unknown:
            raise InputError(f"unknown {self.what} {', '.join(unknown)} ({self.known_label}: {', '.join(self.known)})",
                             field=self.field)
        token = self._current.set(dict(stand_ins))
        try:
            yield
        finally:
            self._current.reset(token)

    def current(self) -> Mapping:
        """The stand-ins in force now ({name: stand-in}; empty outside :meth:`replaced`)."""
        return self._current.get()
