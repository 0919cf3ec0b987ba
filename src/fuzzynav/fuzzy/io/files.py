"""Save / load fuzzy systems as JSON, YAML, FLL or MATLAB .fis, chosen by the file suffix.

JSON and YAML hold the document of :mod:`fuzzynav.fuzzy.io.document` (exact round trip of a
:class:`FuzzySystem`); ``.fll`` is the fuzzylite language (:mod:`fuzzynav.fuzzy.io.fll`) and
``.fis`` MATLAB's format (:mod:`fuzzynav.fuzzy.io.fis`): both also hold engines beyond what a
FuzzySystem expresses (:class:`~fuzzynav.fuzzy.engine.Engine`). Files of every format are read
through :mod:`fuzzynav.validation` (bounded size and nesting, UTF-8; YAML by the 1.2 rules of
:mod:`fuzzynav.yaml_loader`). Syntax errors name the file and the line.
"""

from __future__ import annotations

import json
from pathlib import Path

import yaml

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.engine import Engine
from fuzzynav.fuzzy.engine.convert import system_refusal
from fuzzynav.fuzzy.io.document import from_document, to_document
from fuzzynav.fuzzy.io.fis import from_fis, to_fis
from fuzzynav.fuzzy.io.fll import from_fll, to_fll
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.storage import write_text_atomic

FORMATS = ("json", "yaml", "fll", "fis")
_SUFFIX = {".json": "json", ".yaml": "yaml", ".yml": "yaml", ".fll": "fll", ".fis": "fis"}


def format_of(path) -> str:
    """``json`` / ``yaml`` / ``fll`` / ``fis`` from the file suffix (InputError otherwise)."""
    suffix = Path(path).suffix.lower()
    if suffix not in _SUFFIX:
        raise InputError(f"unknown fuzzy-system file type {suffix!r} (use .json, .yaml, .yml, .fll or .fis)",
                         source=str(path))
    return _SUFFIX[suffix]


def dumps(system: FuzzySystem | Engine, fmt: str) -> str:
    """``system`` as text in ``fmt`` (json, yaml, fll or fis)."""
    if fmt in ("fll", "fis"):  # line-based formats: a line break would end the key and break the file
        for key in ("name", "description"):
            if any(mark in str(getattr(system, key, "")) for mark in "\r\n"):
                raise InputError(f"holds a line break, which a .{fmt} file cannot hold (one line per key)", field=key)
    if fmt == "fis":
        return to_fis(system)
    if fmt in ("json", "yaml") and isinstance(system, Engine):
        refusal = system_refusal(system)
        if refusal is not None:  # shaped as a system, refused for one value
            raise InputError(f"is a fuzzylite engine, not a fuzzy system: {refusal.problem}", field=refusal.field)
        held = " or ".join(line for line, write in (("fll", to_fll), ("fis", to_fis)) if _holds(write, system))
        raise InputError(f"{system.name or 'this engine'} uses fuzzylite features a {fmt.upper()} document does not "
                         f"hold (per-output settings, hedges, OR, several rule blocks...): "
                         + (f"write it as {held}" if held else "nor can an .fll or a .fis file"), field="--to")
    if fmt == "json":
        return json.dumps(to_document(system), indent=2, allow_nan=False) + "\n"
    if fmt == "yaml":
        return yaml.safe_dump(to_document(system), sort_keys=False, allow_unicode=True, width=120)
    if fmt == "fll":
        return to_fll(system)
    raise InputError(f"unknown format {fmt!r} (one of {', '.join(FORMATS)})", field="format")


def _holds(write, system) -> bool:
    """Can the line format ``write`` writes (:func:`to_fll`, :func:`to_fis`) hold ``system``, which
    each refuses to write rather than answer otherwise (a MATLAB bisector in an .fll file)?"""
    try:
        write(system)
    except InputError:
        return False
    return True


def loads(text: str, fmt: str, source: str | None = None) -> FuzzySystem | Engine:
    """Parse ``text`` in ``fmt``; errors name ``source``."""
    if fmt == "fll":
        return from_fll(text, source=source)
    if fmt == "fis":
        return from_fis(text, source=source)
    if fmt == "json":
        doc = validation.parse_json(text, source)
    elif fmt == "yaml":
        doc = validation.parse_yaml(text, source)
    else:
        raise InputError(f"unknown format {fmt!r} (one of {', '.join(FORMATS)})", field="format")
    return from_document(doc, source=source)


def save(system: FuzzySystem | Engine, path, fmt: str | None = None) -> Path:
    """Write ``system`` to ``path`` (format from the suffix unless ``fmt``), atomically."""
    if not isinstance(system, (FuzzySystem, Engine)):
        raise InputError(f"must be a FuzzySystem or an Engine (e.g. fuzzynav.get_system(NAME)), got "
                         f"{type(system).__name__} {validation.shown(system)}", field="system")
    path = validation.file_path(path, field="path")
    text = dumps(system, fmt or format_of(path))
    write_text_atomic(path, text)
    return path


def load(path, fmt: str | None = None) -> FuzzySystem | Engine:
    """Read a fuzzy system file (``.json``, ``.yaml``/``.yml``, ``.fll`` or ``.fis``)."""
    path = validation.file_path(path, field="path")
    fmt = fmt or format_of(path)
    return loads(validation.read_text(path), fmt, source=str(path))
