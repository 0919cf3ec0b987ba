"""The rule bases the experiments run, by role, and their replacement (``fuzzynav reproduce ID
--fis ROLE=FILE``).

A role names one published table wherever it is used: ``gsb`` (Table IV.1, in ``goal-seeking``,
``fuzzy-2b-thesis`` and ``fuzzy-5b-thesis``), ``oab`` (Table IV.2), ``foa``, ``roa``, ``loa``
(Tables IV.3–IV.5), ``vrb`` (Table IV.6), ``wall`` (Table VI.2) and ``tracker`` (Table V.1, the
fuzzy tracker CF). Inside :func:`replaced`, :func:`controller` builds every controller with the
replacement of each role it has, so a claim can be checked against an edited table
(``benchmarks/mutations.py``).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar

from fuzzynav.catalog.roles import ROLES, check_fits, parse_option
from fuzzynav.errors import InputError
from fuzzynav.experiments.stand_ins import StandIns
from fuzzynav.fuzzy.systems import get_system

# role -> the built-in system it defaults to (every role of every fuzzy controller)
ROLE_SYSTEMS: dict[str, str] = {role: system for roles in ROLES.values() for role, system in roles.items()}

_STAND_INS = StandIns("replaced_rule_bases", ROLE_SYSTEMS, "role(s)", "roles", "--fis")
_READ: ContextVar[set | None] = ContextVar("rule_bases_read", default=None)
replaced = _STAND_INS.replaced
"""``with replaced({role: fuzzy system}):`` the experiments inside run those systems in place of the defaults."""


@contextmanager
def reading() -> Iterator[set]:
    """Collect the roles the experiments inside look up (:func:`system`, :func:`systems_for`,
    :func:`controller`): the replacement of a role never looked up changed nothing they ran."""
    read: set = set()
    token = _READ.set(read)
    try:
        yield read
    finally:
        _READ.reset(token)


def _looked_up(roles) -> None:
    read = _READ.get()
    if read is not None:
        read.update(roles)


def system(role: str):
    """The system of ``role`` the experiments run now: the replacement, else the built-in one."""
    _looked_up((role,))
    return _STAND_INS.current().get(role) or get_system(ROLE_SYSTEMS[role])


def active() -> dict:
    """The replaced roles now in force ({role: system name}), empty for the published tables."""
    return {role: getattr(s, "name", role) for role, s in _STAND_INS.current().items()}


def systems_for(name: str) -> dict:
    """The replacements in force for the roles of controller ``name`` ({role: system})."""
    _looked_up(ROLES.get(name, {}))
    return {role: s for role, s in _STAND_INS.current().items() if role in ROLES.get(name, {})}


def controller(name: str, **options):
    """The registered controller ``name`` with the replacement of each of its roles (if any)."""
    from fuzzynav.catalog.roles import make_with_systems

    return make_with_systems(name, systems_for(name), **options)


def from_options(options: list[str] | None) -> dict:
    """``{role: system}`` from ``--fis ROLE=FILE`` options, each checked to fit its role."""
    from fuzzynav.fuzzy.io import load

    systems = {}
    for option in options or []:
        role, path = parse_option(option)
        if role not in ROLE_SYSTEMS:
            raise InputError(f"unknown role {role!r} (roles: {', '.join(ROLE_SYSTEMS)})", field=f"--fis {option}")
        if role in systems:
            raise InputError(f"role {role} is given twice", field=f"--fis {option}")
        loaded = load(path)
        check_fits(loaded, get_system(ROLE_SYSTEMS[role]), str(path), role)
        systems[role] = loaded
    return systems
