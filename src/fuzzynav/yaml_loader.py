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

Only safe tags are constructed: no Python objects, ever. Limits: ``docs/limits.md``.
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


class StrictLoader(yaml.SafeLoader):
    """``yaml.SafeLoader`` with YAML 1.2 core-schema scalars, no duplicate or unhashable keys,
    and bounded aliases and nesting."""

    yaml_implicit_resolvers: dict = {}
    # the core-schema tags only: ``!!timestamp``, ``!!binary``, ``!!set``... are not constructed
    yaml_constructors = {tag: constructor for tag, constructor in yaml.SafeLoader.yaml_constructors.items()
                         if tag is None or tag.rsplit(":", 1)[-1] in ("null", "bool", "int", "float", "str",
                                                                       "seq", "map")}

    def __init__(self, stream):
        super().__init__(stream)
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


StrictLoader.add_implicit_resolver("tag:yaml.org,2002:null", _NULL, ["~", "n", "N", ""])
StrictLoader.add_implicit_resolver("tag:yaml.org,2002:bool", _BOOL, list("tTfF"))
StrictLoader.add_implicit_resolver("tag:yaml.org,2002:int", _INT, list("-+0123456789"))
StrictLoader.add_implicit_resolver("tag:yaml.org,2002:float", _FLOAT, list("-+0123456789."))
StrictLoader.add_constructor("tag:yaml.org,2002:int", StrictLoader.construct_yaml_int)
StrictLoader.add_constructor("tag:yaml.org,2002:float", StrictLoader.construct_yaml_float)


def load_yaml(text: str):
    """Parse YAML text with :class:`StrictLoader`; syntax problems raise ``yaml.YAMLError``."""
    return yaml.load(text, Loader=StrictLoader)  # noqa: S506 — a SafeLoader subclass
