"""Save / load fuzzy systems as JSON, YAML, FLL or MATLAB .fis, chosen by the file suffix.

JSON and YAML hold the document of :mod:`fuzzynav.fuzzy.io.document` (exact round trip of a
:class:`FuzzySystem`); ``.fll`` is the fuzzylite language (:mod:`fuzzynav.fuzzy.io.fll`) and
``.fis`` MATLAB's format (:mod:`fuzzynav.fuzzy.io.fis`): both also hold engines beyond what a
FuzzySystem expresses (:class:`~fuzzynav.fuzzy.engine.Engine`). YAML is read with
``yaml.safe_load`` semantics only (:mod:`fuzzynav.yaml_loader`: duplicate keys rejected, ``1e3``
read as a float). Syntax errors name the file and the line.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import yaml

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.io.document import from_document, to_document
from fuzzynav.fuzzy.engine import Engine
from fuzzynav.fuzzy.io.fis import from_fis, to_fis
from fuzzynav.fuzzy.io.fll import from_fll, to_fll
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.yaml_loader import load_yaml

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
    if fmt == "fis":
        return to_fis(system)
    if fmt in ("json", "yaml") and isinstance(system, Engine):
        raise InputError(f"{system.name or 'this engine'} uses fuzzylite features a {fmt.upper()} document does not "
                         "hold (per-output settings, hedges, OR, several rule blocks...): write it as fll or fis",
                         field="--to")
    if fmt == "json":
        return json.dumps(to_document(system), indent=2, allow_nan=False) + "\n"
    if fmt == "yaml":
        return yaml.safe_dump(to_document(system), sort_keys=False, allow_unicode=True, width=120)
    if fmt == "fll":
        return to_fll(system)
    raise InputError(f"unknown format {fmt!r} (one of {', '.join(FORMATS)})", field="format")


def loads(text: str, fmt: str, source: str | None = None) -> FuzzySystem | Engine:
    """Parse ``text`` in ``fmt``; errors name ``source``."""
    if fmt == "fll":
        return from_fll(text, source=source)
    if fmt == "fis":
        return from_fis(text, source=source)
    if fmt == "json":
        try:
            doc = json.loads(text)
        except json.JSONDecodeError as error:
            raise InputError(f"invalid JSON: {error.msg}", source=source,
                             field=f"line {error.lineno}, column {error.colno}") from None
    elif fmt == "yaml":
        try:
            doc = load_yaml(text)
        except yaml.YAMLError as error:
            mark = getattr(error, "problem_mark", None)
            where = f"line {mark.line + 1}, column {mark.column + 1}" if mark else None
            raise InputError(f"invalid YAML: {getattr(error, 'problem', None) or error}", source=source,
                             field=where) from None
    else:
        raise InputError(f"unknown format {fmt!r} (one of {', '.join(FORMATS)})", field="format")
    return from_document(doc, source=source)


def save(system: FuzzySystem | Engine, path, fmt: str | None = None) -> Path:
    """Write ``system`` to ``path`` (format from the suffix unless ``fmt``), atomically."""
    path = Path(path)
    text = dumps(system, fmt or format_of(path))
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)
    return path


def load(path, fmt: str | None = None) -> FuzzySystem | Engine:
    """Read a fuzzy system file (``.json``, ``.yaml``/``.yml``, ``.fll`` or ``.fis``)."""
    path = Path(path)
    fmt = fmt or format_of(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise InputError(f"cannot read: {error.strerror or error}", source=str(path)) from None
    return loads(text, fmt, source=str(path))
