"""The one YAML reader of the project (scenario files, fuzzy-system files): a ``yaml.SafeLoader``
that reads plain scalars by the YAML 1.2 core schema, with bounds a hostile file cannot pass.

- Plain scalars follow YAML 1.2 (core schema), not PyYAML's YAML 1.1: ``1:20`` is the string
  ``"1:20"`` (not 80 in base 60), ``1e3`` is a float, ``017`` is 17 (octal is ``0o17``),
  ``yes`` / ``no`` / ``on`` / ``off`` are strings (booleans are ``true`` / ``false``), dates
  stay strings, ``1_000`` is a string.
- Duplicate keys are an error (PyYAML keeps the last one silently); so is a key that is a list
  or a mapping.
- At most :data:`MAX_ALIASES` aliases (``*name``) and :data:`MAX_DEPTH` levels of nesting: a
  "billion laughs" document or a 100,000-deep list fails fast instead of exhausting memory or
  the Python stack.

Only safe tags are constructed: no Python objects, ever. Where PyYAML has libyaml, its C
parser reads the file (about four times faster) after the aliases and nesting are counted on
its event stream; otherwise :class:`StrictLoader` counts them while composing. Limits:
``docs/limits.md``.
"""

from __future__ import annotations

import re

import yaml

MAX_ALIASES = 1000
MAX_DEPTH = 64

# YAML 1.2 core schema, https://yaml.org/spec/1.2.2/#1032-tag-resolution
_NULL = re.compile(r"^(?:~|null|Null|NULL|)$")
_BOOL = re.compile(r"^(?:true|True|TRUE|false|False|FALSE)$")
_INT = re.compile(r"^(?:[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+)$")
_FLOAT = re.compile(r"^(?:[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?"
                    r"|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$")


class _Core12Resolver(yaml.resolver.BaseResolver):
    """Implicit tags of plain scalars by the YAML 1.2 core schema (registered below)."""

    yaml_implicit_resolvers: dict = {}


class _StrictConstructor(yaml.constructor.SafeConstructor):
    """The core-schema tags only (``!!timestamp``, ``!!binary``, ``!!set``... are not
    constructed), no duplicate or unhashable keys, YAML 1.2 integers and floats."""

    yaml_constructors = {tag: constructor for tag, constructor in yaml.SafeLoader.yaml_constructors.items()
                         if tag is None or tag.rsplit(":", 1)[-1] in ("null", "bool", "int", "float", "str",
                                                                       "seq", "map")}

    def construct_mapping(self, node, deep=False):
        seen = set()
        for key_node, _ in node.value:
            if not isinstance(key_node, yaml.ScalarNode):
                raise yaml.constructor.ConstructorError(None, None, "a key must be a plain value, not a list or "
                                                        "mapping", key_node.start_mark)
            key = self.construct_object(key_node, deep=deep)
            if key in seen:
                raise yaml.constructor.ConstructorError(None, None, f"duplicate key {key!r}", key_node.start_mark)
            seen.add(key)
        return super().construct_mapping(node, deep=deep)

    def construct_yaml_int(self, node):
        value = self.construct_scalar(node)
        try:
            if value.startswith("0o"):
                return int(value[2:], 8)
            if value.startswith("0x"):
                return int(value[2:], 16)
            return int(value, 10)
        except ValueError as error:  # more digits than Python converts (sys.get_int_max_str_digits)
            raise yaml.constructor.ConstructorError(None, None, f"unreadable integer ({error})",
                                                    node.start_mark) from None

    def construct_yaml_float(self, node):
        value = self.construct_scalar(node).lower()
        if value.endswith(".inf"):
            return float("-inf") if value.startswith("-") else float("inf")
        if value == ".nan":
            return float("nan")
        try:
            return float(value)
        except ValueError:  # an explicit ``!!float`` tag on a non-number
            raise yaml.constructor.ConstructorError(None, None, f"not a number: {value!r}", node.start_mark) from None


_Core12Resolver.add_implicit_resolver("tag:yaml.org,2002:null", _NULL, ["~", "n", "N", ""])
_Core12Resolver.add_implicit_resolver("tag:yaml.org,2002:bool", _BOOL, list("tTfF"))
_Core12Resolver.add_implicit_resolver("tag:yaml.org,2002:int", _INT, list("-+0123456789"))
_Core12Resolver.add_implicit_resolver("tag:yaml.org,2002:float", _FLOAT, list("-+0123456789."))
_StrictConstructor.add_constructor("tag:yaml.org,2002:int", _StrictConstructor.construct_yaml_int)
_StrictConstructor.add_constructor("tag:yaml.org,2002:float", _StrictConstructor.construct_yaml_float)


class StrictLoader(yaml.reader.Reader, yaml.scanner.Scanner, yaml.parser.Parser, yaml.composer.Composer,
                   _StrictConstructor, _Core12Resolver):
    """The pure-Python reader: ``yaml.SafeLoader`` with YAML 1.2 core-schema scalars, no duplicate
    or unhashable keys, and aliases and nesting bounded while the document is composed."""

    def __init__(self, stream):
        yaml.reader.Reader.__init__(self, stream)
        yaml.scanner.Scanner.__init__(self)
        yaml.parser.Parser.__init__(self)
        yaml.composer.Composer.__init__(self)
        _StrictConstructor.__init__(self)
        _Core12Resolver.__init__(self)
        self._aliases = 0
        self._depth = 0

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            self._aliases += 1
            if self._aliases > MAX_ALIASES:
                raise yaml.composer.ComposerError(None, None, f"more than {MAX_ALIASES} aliases",
                                                  self.peek_event().start_mark)
        self._depth += 1
        try:
            if self._depth > MAX_DEPTH:
                raise yaml.composer.ComposerError(None, None, f"nested deeper than {MAX_DEPTH} levels",
                                                  self.peek_event().start_mark)
            return super().compose_node(parent, index)
        finally:
            self._depth -= 1


if yaml.__with_libyaml__:
    class _StrictCLoader(yaml.cyaml.CParser, _StrictConstructor, _Core12Resolver):
        """The same reader on libyaml's C parser (about 4 times faster on large files); its
        composer is C, so aliases and nesting are bounded first, on the event stream."""

        def __init__(self, stream):
            yaml.cyaml.CParser.__init__(self, stream)
            _StrictConstructor.__init__(self)
            _Core12Resolver.__init__(self)


def _check_events(text) -> None:
    """Aliases and nesting of ``text`` within bounds, read from libyaml's event stream."""
    depth = aliases = 0
    for event in yaml.parse(text, Loader=yaml.CSafeLoader):
        if isinstance(event, (yaml.SequenceStartEvent, yaml.MappingStartEvent)):
            depth += 1
            if depth > MAX_DEPTH:
                raise yaml.composer.ComposerError(None, None, f"nested deeper than {MAX_DEPTH} levels",
                                                  event.start_mark)
        elif isinstance(event, (yaml.SequenceEndEvent, yaml.MappingEndEvent)):
            depth -= 1
        elif isinstance(event, yaml.AliasEvent):
            aliases += 1
            if aliases > MAX_ALIASES:
                raise yaml.composer.ComposerError(None, None, f"more than {MAX_ALIASES} aliases", event.start_mark)


def load_yaml(text: str):
    """Parse YAML text (libyaml's parser when PyYAML has it, else :class:`StrictLoader`);
    syntax problems and exceeded bounds raise ``yaml.YAMLError``."""
    if yaml.__with_libyaml__:
        try:
            data = text.encode("utf-8")
        except UnicodeEncodeError as error:  # a lone surrogate in a Python string
            raise yaml.YAMLError(f"not UTF-8 text ({error.reason})") from None
        _check_events(data)
        return yaml.load(data, Loader=_StrictCLoader)  # noqa: S506 — safe constructors only
    return yaml.load(text, Loader=StrictLoader)  # noqa: S506 — a SafeLoader subclass
