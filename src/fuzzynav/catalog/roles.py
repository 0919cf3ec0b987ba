"""The rule bases each fuzzy controller uses, by role, and replacements read from files.

Every fuzzy controller names its systems by role — ``goal-seeking``: ``gsb`` (Table IV.1);
``fuzzy-2b``: ``gsb`` and ``oab`` (Table IV.2); ``fuzzy-5b``: ``gsb``, ``foa``, ``roa``, ``loa``,
``vrb`` (§IV.7); ``wall-follow``: ``wall`` (Table VI.2); ``fuzzy-tracker``: ``tracker`` (Table V.1) — and
its factory accepts
``systems={role: system}``. Which controller has which roles is its spec's ``roles``
(:mod:`fuzzynav.catalog.controllers`); :data:`ROLES` reads them. A replacement comes from any file
:func:`fuzzynav.fuzzy.io.load` reads (``.yaml``/``.json``/``.fll``/``.fis``) and must fit the
role: the same input variables in the same order (the controller feeds them by position) and the
same outputs; otherwise an :class:`InputError` names the file, the variable and what was expected.

    fuzzynav fis convert fuzzy-5b-thesis:foa --to yaml -o foa.yaml      # a role's system, to edit
    fuzzynav run fig-IV-22a --controller fuzzy-5b-thesis --fis foa=foa.yaml
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from pathlib import Path

from fuzzynav.catalog.controllers import CONTROLLERS, make_controller
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.systems import get_system


class _Roles(Mapping[str, Mapping[str, str]]):
    """controller name (or alias) -> ``{role: built-in fuzzy system}``, for the controllers that
    have replaceable rule bases; read from the registered specs, so a plug-in's roles are there too."""

    def _table(self) -> dict[str, Mapping[str, str]]:
        aliases = CONTROLLERS.aliases()
        table = {name: spec.roles for name, spec in CONTROLLERS.items() if spec.roles}
        table.update({alias: CONTROLLERS[name].roles for alias, name in aliases.items() if CONTROLLERS[name].roles})
        return table

    def __getitem__(self, controller: str) -> Mapping[str, str]:
        return self._table()[controller]

    def __iter__(self) -> Iterator[str]:
        return iter(self._table())

    def __len__(self) -> int:
        return len(self._table())


ROLES: Mapping[str, Mapping[str, str]] = _Roles()


def roles_of(controller: str) -> Mapping[str, str]:
    """``{role: built-in system}`` of ``controller`` (InputError for a controller without roles)."""
    if controller not in ROLES:
        from fuzzynav.catalog.controllers import spec_of

        spec_of(controller)  # an unknown name is refused as such (with the names it may mean)
        raise InputError(f"controller {controller!r} has no replaceable fuzzy systems (those that do: "
                         f"{', '.join(ROLES)})", field="--fis")
    return ROLES[controller]


def default_system(controller: str, role: str, field: str = "--fis"):
    """The system ``controller`` uses for ``role`` unless told otherwise; an unknown role is an
    InputError on ``field`` (the option or argument that named it)."""
    roles = roles_of(controller)
    if role not in roles:
        raise InputError(f"{controller} has no role {role!r} (its roles: {', '.join(roles)})", field=field)
    return get_system(roles[role])


def check_fits(system, expected, source: str, role: str) -> None:
    """InputError unless ``system`` reads ``expected``'s inputs in order and gives its outputs."""
    for side in ("input", "output"):
        got, want = getattr(system, f"{side}_names"), getattr(expected, f"{side}_names")
        if got == want:
            continue
        verb = "reads" if side == "input" else "gives"
        for k, name in enumerate(want):
            if k >= len(got) or got[k] != name:
                found = f"{got[k]!r}" if k < len(got) else "missing"
                raise InputError(f"{side} {k + 1} is {found}, expected {name!r} (the role {role} {verb} "
                                 f"{', '.join(want)})", source=source, field=f"{side} {name}")
        extra = got[len(want)]
        raise InputError(f"{side} {extra!r} is one too many (the role {role} {verb} {', '.join(want)})",
                         source=source, field=f"{side} {extra}")


def load_replacement(controller: str, role: str, path: str):
    """The system in ``path``, checked to fit ``controller``'s ``role``."""
    from fuzzynav.fuzzy.engine import Engine
    from fuzzynav.fuzzy.engine.convert import system_refusal
    from fuzzynav.fuzzy.io import load

    expected = default_system(controller, role)
    system = load(path)
    refusal = system_refusal(system) if isinstance(system, Engine) else None
    if refusal is not None:  # read as an engine for this value alone: say it, not what the role needs
        raise InputError(f"is a fuzzylite engine, not a fuzzy system: {refusal.problem}", source=str(path),
                         field=refusal.field)
    check_fits(system, expected, str(path), role)
    return system


def parse_option(option: str) -> tuple[str, str]:
    """(role, file) of one ``--fis ROLE=FILE`` option."""
    role, sep, path = option.partition("=")
    if not sep or not role or not path:
        raise InputError(f"expected ROLE=FILE, got {option!r}", field="--fis")
    return role, path


def replaced_files(options: list[str] | None) -> dict[str, str]:
    """``{role: absolute file}`` of the ``--fis ROLE=FILE`` options, as ``run`` and ``evaluate``
    report them beside their numbers (``bench`` keeps them in ``fis.json``)."""
    return {role: str(Path(path).resolve()) for role, path in map(parse_option, options or [])}


def systems_from_options(controller: str, options: list[str] | None) -> dict:
    """``{role: system}`` from ``--fis ROLE=FILE`` options (empty when there are none)."""
    systems = {}
    for option in options or []:
        role, path = parse_option(option)
        if role in systems:
            raise InputError(f"role {role} is given twice", field=f"--fis {option}")
        default_system(controller, role)  # names the known roles when this one is not
        systems[role] = load_replacement(controller, role, path)
    return systems


def make_with_systems(controller: str, systems: dict, **options):
    """``make_controller(controller, systems=systems)``; a controller whose factory does not take
    replacement systems is refused with an InputError (not a TypeError)."""
    if not systems:
        return make_controller(controller, **options)
    try:
        return make_controller(controller, systems=systems, **options)
    except TypeError as error:
        if "systems" not in str(error):
            raise
        raise InputError(f"controller {controller} does not take replacement systems in this version",
                         field="--fis") from None
