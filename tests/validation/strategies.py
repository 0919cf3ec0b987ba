"""Hypothesis strategies of the fuzz suite: structurally random documents, valid documents
mutated at a random place, and text mutated at random characters.

Every fuzz test runs :data:`FUZZ` settings: derandomized (the same examples on every run, so CI
is deterministic), no deadline, ``FUZZYNAV_FUZZ_EXAMPLES`` examples per parser (default 1,000).
"""

from __future__ import annotations

import copy
import os

from hypothesis import HealthCheck, settings, strategies as st

FUZZ = settings(max_examples=int(os.environ.get("FUZZYNAV_FUZZ_EXAMPLES", "1000")), derandomize=True,
                deadline=None, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.filter_too_much])

HOSTILE_NUMBERS = st.sampled_from([0, -1, 1, 2, 10**400, -(10**400), 2**63, 1e308, -1e308, 1e-320, float("nan"),
                                   float("inf"), float("-inf"), 0.5, 1e14, 1e9, True, False, None, "abc", "1:20",
                                   "inf", "", [], {}, [200], {"a": 1}]).map(copy.deepcopy)  # fresh lists
SCALARS = (st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=8) | HOSTILE_NUMBERS)


def documents(keys=st.text(max_size=8)):
    """Structurally random JSON-like documents (lists, mappings, any scalar, nesting up to ~6)."""
    return st.recursive(SCALARS, lambda children: st.lists(children, max_size=4)
                        | st.dictionaries(keys, children, max_size=4), max_leaves=24)


def _paths(node, prefix=()):
    yield prefix
    if isinstance(node, dict):
        for key, value in node.items():
            yield from _paths(value, prefix + (key,))
    elif isinstance(node, list):
        for i, value in enumerate(node):
            yield from _paths(value, prefix + (i,))


@st.composite
def mutated(draw, valid: dict, keys=st.text(max_size=8)):
    """``valid`` with one to three random edits: a value replaced (by a hostile number or a
    random document), a key or item removed, a key added, or a list item duplicated."""
    doc = copy.deepcopy(valid)
    for _ in range(draw(st.integers(1, 3))):
        paths = [p for p in _paths(doc) if p]
        if not paths:
            break
        path = draw(st.sampled_from(paths))
        parent = doc
        for step in path[:-1]:
            parent = parent[step]
        last = path[-1]
        action = draw(st.sampled_from(["replace", "replace", "remove", "add", "duplicate"]))
        if action == "replace":
            parent[last] = draw(HOSTILE_NUMBERS | documents(keys))
        elif action == "remove":
            del parent[last]
        elif action == "add" and isinstance(parent, dict):
            parent[draw(keys)] = draw(SCALARS | documents(keys))
        elif action == "duplicate" and isinstance(parent, list):
            parent.insert(last, copy.deepcopy(parent[last]))
    return doc


@st.composite
def mutated_text(draw, valid: str):
    """``valid`` with one to five characters inserted, deleted or replaced at random places."""
    text = valid
    for _ in range(draw(st.integers(1, 5))):
        i = draw(st.integers(0, len(text)))
        piece = draw(st.sampled_from(["", " ", "\n", ":", "-", "[", "]", "{", "}", "#", "&a", "*a", "1e999", "nan",
                                     "\t", "'", '"', "0x", "1:20", "?", "!!"]) | st.text(max_size=3))
        cut = draw(st.integers(0, 3))
        text = text[:i] + piece + text[i + cut:]
    return text
