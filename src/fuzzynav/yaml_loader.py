"""The one YAML reader of the project (scenario files, fuzzy-system files): ``yaml.SafeLoader``
plus two checks a user needs.

- Duplicate keys are an error (PyYAML keeps the last one silently).
- Numbers in exponent notation without a dot (``1e3``, ``2E-1``) are floats, as in YAML 1.2;
  PyYAML follows YAML 1.1 and would read them as strings, so ``radius: 1e-1`` would be
  rejected as "not a number".

Only safe tags are constructed: no Python objects, ever.
"""

from __future__ import annotations

import re

import yaml

_EXPONENT_FLOAT = re.compile(r"^[-+]?(?:[0-9][0-9_]*)(?:\.[0-9_]*)?[eE][-+]?[0-9]+$")


class StrictLoader(yaml.SafeLoader):
    """``yaml.SafeLoader`` that rejects duplicate keys and reads ``1e3`` as a float."""

    def construct_mapping(self, node, deep=False):
        seen = set()
        for key_node, _ in node.value:
            key = self.construct_object(key_node, deep=deep)
            if key in seen:
                raise yaml.constructor.ConstructorError(None, None, f"duplicate key {key!r}", key_node.start_mark)
            seen.add(key)
        return super().construct_mapping(node, deep=deep)


StrictLoader.add_implicit_resolver("tag:yaml.org,2002:float", _EXPONENT_FLOAT, list("-+0123456789"))


def load_yaml(text: str):
    """Parse YAML text with :class:`StrictLoader`; syntax problems raise ``yaml.YAMLError``."""
    return yaml.load(text, Loader=StrictLoader)  # noqa: S506 — a SafeLoader subclass
