"""The one validation layer for user-facing values: every parser and constructor checks through it.

A value read from a file, a command-line flag or a Python call is checked here before it is
used: numbers finite and inside a documented range, integers bounded, strings and types as
expected, documents bounded in size and nesting depth, YAML aliases bounded and numbers read by
the YAML 1.2 rules (:mod:`fuzzynav.yaml_loader`). Every failure is an
:class:`~fuzzynav.errors.InputError` naming the source (file), the field and the problem — never
another exception, never a silently wrong value. The limits are documented in ``docs/limits.md``.
"""

from __future__ import annotations

import csv
import difflib
import io
import json
import math
import operator
import os
import stat
import warnings
import zipfile
from pathlib import Path
from typing import NoReturn

import numpy as np
import yaml

from fuzzynav.errors import InputError
from fuzzynav.yaml_loader import load_yaml

# -- resource limits (docs/limits.md) ---------------------------------------------------------
MAX_TEXT_BYTES = 8 * 2**20  # a JSON or FLL fuzzy-system file, a CSV table
MAX_YAML_BYTES = 2**20  # a YAML scenario or fuzzy-system file (a few seconds of parsing at most)
MAX_MODEL_BYTES = 64 * 2**20  # a JSON model or checkpoint file
MAX_NPZ_BYTES = 256 * 2**20  # the arrays of an .npz model, uncompressed, all members together
MAX_DEPTH = 64  # nesting of lists / mappings in a document
MAX_NODES = 2_000_000  # values in a document (lists, mappings and scalars together)
MAX_STRING = 100_000  # characters in one string field
MAX_INTEGER = 2**53  # |integer| accepted where the field takes an integer (exact as a float)
MAX_DOCUMENT_INTEGER = 2**130  # |integer| anywhere in a document (a checkpoint's RNG state is 128-bit)
MAX_MAGNITUDE = 1e15  # |number| accepted where no tighter range is documented
MAX_EPISODES = 10_000_000  # training episodes (``train --episodes``, ``--checkpoint-every``)
MAX_RESOLUTION = 10_000  # centroid samples of a Mamdani output (fuzzylite's default is 1,000)
MAX_UNIVERSE_WIDTH = 1e300  # a fuzzy variable's hi - lo: MAX_RESOLUTION samples across it stay finite
MAX_WORLDS = 100_000  # generated worlds of one request (``worlds generate --n``, a bench suite's COUNT, Gym n_worlds)
MAX_SEED = 2**63 - 1  # a seed (``--seed``, ``seed=``, Gym ``world_seed``): NumPy takes non-negative seeds
MAX_SEEDS = 10_000  # seeds of one campaign (``bench --seeds``)
MAX_SMALL_SEED = 2**32 - 1  # the seed of scikit-learn's MLP and of the tuners: ``tune``, ``reproduce --seed``
MAX_CAMPAIGN_RUNS = 1_000_000  # runs of one campaign: suites' worlds x seeds x controllers
MAX_WORKERS = 1024  # parallel workers (``bench --workers``; default: the cores)
MAX_ROBOTS = 100_000  # robots stepped together (``BatchSimulator`` n / starts, Gym ``num_envs``)
MAX_DECISION_STEPS = 1_000  # simulator steps per Gym action (``decision_steps``; 100 s of 0.1 s steps)
MAX_EPISODE_STEPS = 10_000_000  # Gym ``max_steps`` (decisions before truncation)


def fail(problem: str, source=None, field=None) -> NoReturn:
    """Raise the :class:`InputError` of ``problem`` at ``source`` / ``field``."""
    raise InputError(problem, source=None if source is None else str(source), field=field)


def shown(value) -> str:
    """``repr(value)`` cut to a readable length (a 400-digit integer is not echoed whole)."""
    text = repr(value) if not isinstance(value, int) or abs(value) < 10**30 else f"an integer of {len(str(abs(value)))} digits"
    return text if len(text) <= 80 else text[:77] + "..."


def number(value, source=None, field=None, *, lo: float = -MAX_MAGNITUDE, hi: float = MAX_MAGNITUDE,
           lo_open: bool = False, hi_open: bool = False) -> float:
    """``value`` as a float: a real number (not a bool, not a string), finite, in [lo, hi]
    (``lo_open`` / ``hi_open`` exclude an end)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) and not _is_numpy_number(value):
        fail(f"must be a number, got {shown(value)}", source, field)
    try:
        result = float(value)
    except OverflowError:
        fail(f"must be <= {hi:g} in magnitude, got {shown(value)}", source, field)
    if not math.isfinite(result):
        fail(f"must be finite, got {shown(result)}", source, field)
    if result <= lo if lo_open else result < lo:
        fail(f"must be {'>' if lo_open else '>='} {lo:g}, got {shown(value)}", source, field)
    if result >= hi if hi_open else result > hi:
        fail(f"must be {'<' if hi_open else '<='} {hi:g}, got {shown(value)}", source, field)
    return result


def positive(value, source=None, field=None) -> float:
    """``value`` as a float: a real number (not a bool, not a string), finite and > 0 (a size, a
    time, a gain, a distance)."""
    try:
        result = float(value) if isinstance(value, (int, float)) or _is_numpy_number(value) else math.nan
    except OverflowError:
        result = math.inf
    if isinstance(value, bool) or not (math.isfinite(result) and result > 0):
        fail(f"must be a finite number > 0, got {shown(value)}", source, field)
    return result


def finite_array(value, source=None, field=None, *, ndim: int | None = None, shape: tuple | None = None,
                 empty: bool = True) -> np.ndarray:
    """``value`` as a float array of finite numbers (no strings, booleans, NaN or infinities) of
    ``ndim`` dimensions or exactly ``shape`` when given, not empty unless ``empty``."""
    try:
        array = np.asarray(value)
    except ValueError:  # ragged nesting
        array = np.asarray(None)
    expected = (f"an array of shape {tuple(shape)}" if shape is not None else
                f"a {ndim}-D array" if ndim is not None else "an array")
    if array.dtype.kind not in "iuf" or (ndim is not None and array.ndim != ndim) or \
            (shape is not None and array.shape != tuple(shape)):
        fail(f"must be {expected} of numbers, got {shown(value)}", source, field)
    if array.size == 0 and not empty:
        fail("must not be empty", source, field)
    array = array.astype(float)
    if not np.isfinite(array).all():
        fail(f"must be finite numbers (no NaN or infinity), got {shown(value)}", source, field)
    return array


def _is_numpy_number(value) -> bool:
    return type(value).__module__ == "numpy" and hasattr(value, "dtype") and value.dtype.kind in "iuf" \
        and getattr(value, "ndim", 0) == 0


def integer(value, source=None, field=None, *, lo: int = -MAX_INTEGER, hi: int = MAX_INTEGER) -> int:
    """``value`` as an int: an integer (not a bool, not a float, not a string) in [lo, hi]."""
    if isinstance(value, bool):
        fail(f"must be an integer, got {shown(value)}", source, field)
    try:
        result = operator.index(value)
    except TypeError:
        fail(f"must be an integer, got {type(value).__name__} {shown(value)}", source, field)
    if not lo <= result <= hi:
        fail(f"must be an integer in [{lo}, {hi}], got {shown(value)}", source, field)
    return result


def count(value, source=None, field=None, *, hi: int, lo: int = 1) -> int:
    """A count (worlds, seeds, steps, workers...): an integer in [lo, hi], checked before any work."""
    return integer(value, source, field, lo=lo, hi=hi)


def seed(value, source=None, field=None) -> int:
    """A random seed: an integer in [0, :data:`MAX_SEED`] (NumPy refuses negative seeds)."""
    return integer(value, source, field, lo=0, hi=MAX_SEED)


def file_path(value, source=None, field=None) -> Path:
    """``value`` as a :class:`~pathlib.Path`: a string or path-like object, not empty, at most
    4,096 characters (``None``, a number or a list is refused, not passed to ``open``)."""
    if not isinstance(value, (str, Path)) and not hasattr(value, "__fspath__"):
        fail(f"must be a file name (a string or a path), got {type(value).__name__} {shown(value)}", source, field)
    name = str(value) if isinstance(value, str) else str(Path(value))  # (Path("") is ".")
    if not name.strip() or len(name) > 4096 or "\x00" in name:
        fail(f"must be a file name of 1 to 4096 characters, none NUL, got {len(name)} ({shown(name)})", source, field)
    return Path(value)


def float_array(value, source=None, field=None) -> np.ndarray:
    """``value`` as a float array (numbers, nested lists of numbers); anything else is refused."""
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError, OverflowError):
        fail(f"must be numbers, got {type(value).__name__} {shown(value)}", source, field)


def text(value, source=None, field=None, *, max_length: int = MAX_STRING, allow_empty: bool = True,
         one_line: bool = False) -> str:
    """``value`` as a string of at most ``max_length`` characters (non-empty unless ``allow_empty``;
    ``one_line``: a name printed and plotted, no control character: ESC, NUL, a line break)."""
    if not isinstance(value, str):
        fail(f"must be a string, got {type(value).__name__} {shown(value)}", source, field)
    if len(value) > max_length:
        fail(f"must be at most {max_length} characters, got {len(value)}", source, field)
    if not allow_empty and not value.strip():
        fail("must not be empty", source, field)
    if one_line and any(ord(c) < 32 or 127 <= ord(c) < 160 for c in value):  # Unicode's control characters, Cc
        fail(f"must not hold control characters, got {shown(value)}", source, field)
    return value


def choice(value, options, source=None, field=None) -> str:
    """``value``, one of the strings ``options``."""
    if not isinstance(value, str) or value not in options:
        fail(f"must be one of {', '.join(map(str, options))}, got {shown(value)}", source, field)
    return value


def mapping(value, source=None, field=None) -> dict:
    """``value``, a mapping with string keys."""
    if not isinstance(value, dict):
        got = "nothing (an empty document)" if value is None and not field else type(value).__name__
        fail(f"must be a mapping, got {got}", source, field)
    for key in value:
        if not isinstance(key, str):
            fail(f"keys must be strings, got {type(key).__name__} {shown(key)}", source, field or "(top level)")
    return value


def sequence(value, source=None, field=None, *, min_length: int = 0, max_length: int = MAX_NODES) -> list:
    """``value``, a list (or tuple) of ``min_length`` to ``max_length`` items."""
    if not isinstance(value, (list, tuple)):
        fail(f"must be a list, got {type(value).__name__}", source, field)
    if not min_length <= len(value) <= max_length:
        fail(f"must have {min_length} to {max_length} items, got {len(value)}", source, field)
    return list(value)


def numbers(value, source=None, field=None, *, length: int | None = None, **bounds) -> list[float]:
    """A list of numbers (each checked by :func:`number` with ``bounds``), of ``length`` if given."""
    items = sequence(value, source, field)
    if length is not None and len(items) != length:
        fail(f"must be a list of {length} numbers, got {len(items)} items", source, field)
    return [number(item, source, f"{field}[{i}]", **bounds) for i, item in enumerate(items)]


# -- documents --------------------------------------------------------------------------------
def check_tree(document, source=None, *, max_depth: int = MAX_DEPTH, max_nodes: int = MAX_NODES,
               string_keys: bool = True):
    """Walk a parsed document (without recursion): nesting at most ``max_depth``, at most
    ``max_nodes`` values, mapping keys strings (``string_keys``); returns the document."""
    stack = [(document, 0, "")]
    seen = 0
    while stack:
        node, depth, where = stack.pop()
        seen += 1
        if seen > max_nodes:
            fail(f"document too large (more than {max_nodes} values)", source)
        if depth > max_depth:
            fail(f"nested deeper than {max_depth} levels", source, where or None)
        if isinstance(node, dict):
            for key, item in node.items():
                if string_keys and not isinstance(key, str):
                    fail(f"keys must be strings, got {type(key).__name__} {shown(key)}", source,
                         where or "(top level)")
                stack.append((item, depth + 1, f"{where}.{key}" if where else str(key)))
        elif isinstance(node, (list, tuple)):
            stack.extend((item, depth + 1, f"{where}[{i}]") for i, item in enumerate(node))
        elif isinstance(node, int) and not -MAX_DOCUMENT_INTEGER <= node <= MAX_DOCUMENT_INTEGER:
            fail(f"integer too large ({shown(node)})", source, where or None)
    return document


FILE_KINDS = {stat.S_IFIFO: "a named pipe", stat.S_IFDIR: "a folder"}


def read_bytes(path, *, max_bytes: int = MAX_TEXT_BYTES, source=None) -> bytes:
    """The bytes of the file ``path`` or of a binary stream (``sys.stdin.buffer``), at most
    ``max_bytes``; unreadable or too large: InputError."""
    source = str(getattr(path, "name", path)) if source is None else source
    try:
        if hasattr(path, "read"):
            data = path.read(max_bytes + 1)
        else:  # a named pipe would make the read wait for ever: only a regular file is opened
            kind = stat.S_IFMT(os.stat(path).st_mode)
            if kind != stat.S_IFREG:
                fail(f"is {FILE_KINDS.get(kind, 'a socket or device')}, not a regular file", source)
            with open(path, "rb") as handle:
                data = handle.read(max_bytes + 1)
    except OSError as error:
        fail(f"cannot read file ({error.strerror or error})", source)
    if len(data) > max_bytes:
        fail(f"file larger than the {max_bytes // 2**20} MiB limit", source)
    return data


def decode(data: bytes, source=None, *, strip_bom: bool = True) -> str:
    """UTF-8 text of ``data`` (a leading byte-order mark, as Excel writes, removed)."""
    try:
        result = data.decode("utf-8")
    except UnicodeDecodeError as error:
        fail(f"cannot read file: not UTF-8 text (byte {error.start}: {error.reason})", source)
    return result[1:] if strip_bom and result.startswith("\ufeff") else result


def read_text(path, *, max_bytes: int = MAX_TEXT_BYTES, source=None) -> str:
    """UTF-8 text of the file ``path``, bounded in size (:func:`read_bytes`, :func:`decode`)."""
    source = str(path) if source is None else source
    return decode(read_bytes(path, max_bytes=max_bytes, source=source), source)


def _unique_keys(pairs) -> dict:
    """A JSON object whose keys are all different (``json`` would silently keep the last one)."""
    result = {}
    for key, value in pairs:
        if key in result:
            raise ValueError(f"the key {shown(key)} appears twice in one object")
        result[key] = value
    return result


def parse_json(content: str, source=None):
    """A JSON document, bounded (:func:`check_tree`), no key twice in one object; syntax errors
    name the line and column. (The text's size is bounded where it is read: :func:`read_text`.)"""
    try:
        document = json.loads(content, object_pairs_hook=_unique_keys)
    except json.JSONDecodeError as error:
        fail(f"invalid JSON: {error.msg}", source, f"line {error.lineno}, column {error.colno}")
    except RecursionError:
        fail(f"nested deeper than {MAX_DEPTH} levels", source)
    except ValueError as error:  # an integer of more digits than Python converts
        fail(f"invalid JSON: {error}", source)
    return check_tree(document, source)


def parse_yaml(content: str, source=None):
    """A YAML document read by :func:`fuzzynav.yaml_loader.load_yaml` (YAML 1.2 numbers, no
    duplicate keys, aliases and depth bounded), bounded (:func:`check_tree`)."""
    if len(content) > MAX_YAML_BYTES:
        fail(f"YAML document larger than the {MAX_YAML_BYTES // 2**20} MiB limit", source)
    try:
        document = load_yaml(content)
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        where = f"line {mark.line + 1}, column {mark.column + 1}" if mark else None
        fail(f"invalid YAML: {getattr(error, 'problem', None) or error}", source, where)
    except RecursionError:
        fail(f"nested deeper than {MAX_DEPTH} levels", source)
    return check_tree(document, source)


def load_document(path, fmt: str | None = None):
    """Parse the JSON (``.json``) or YAML (anything else, or ``fmt``) file ``path``, bounded."""
    path = Path(path)
    fmt = fmt or ("json" if path.suffix.lower() == ".json" else "yaml")
    content = read_text(path, max_bytes=MAX_TEXT_BYTES if fmt == "json" else MAX_YAML_BYTES)
    return parse_json(content, str(path)) if fmt == "json" else parse_yaml(content, str(path))


def known_keys(value, known, source=None, field=None, *, required=(), near_misses_only: bool = False) -> dict:
    """``value``, a mapping whose keys are all in ``known`` (an unknown key is refused, the closest
    known one its hint) and include ``required``; ``near_misses_only``: only misspellings of known
    keys are refused (``tnrom``; the top level of a model file, whose loader reads its own keys)."""
    mapping(value, source, field)
    for key in (key for key in value if key not in known):
        close = difflib.get_close_matches(str(key), list(known), n=1, cutoff=0.75 if near_misses_only else 0.6)
        if close or not near_misses_only:
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            fail(f"unknown key {shown(key)}{hint}; known: {', '.join(known)}", source, f"{field}.{key}" if field else key)
    for key in (key for key in required if key not in value):
        fail("missing", source, f"{field}.{key}" if field else key)
    return value


def check_npz(path, *, max_bytes: int = MAX_NPZ_BYTES, what: str = "model file") -> None:
    """Refuse an ``.npz`` (a ``what``) before decompressing it: every member a ``.npy`` array of a
    plain (non-object) dtype, the sizes its zip headers and its array headers declare within
    ``max_bytes`` in total (a "deflate bomb" or an array declaring terabytes is refused)."""
    source = str(path)
    total = 0
    try:
        with zipfile.ZipFile(path) as archive:
            members = archive.infolist()
            if len(members) > 1000:
                fail(f"more than 1000 arrays ({len(members)})", source)
            for info in members:
                total += info.file_size
                if total > max_bytes:
                    fail(f"arrays larger than the {max_bytes // 2**20} MiB limit once decompressed", source,
                         info.filename)
                with archive.open(info) as member, warnings.catch_warnings():
                    warnings.simplefilter("ignore")  # the header of hostile bytes may hold odd escapes
                    version = np.lib.format.read_magic(member)
                    shape, _, dtype = (np.lib.format.read_array_header_1_0 if version == (1, 0)
                                       else np.lib.format.read_array_header_2_0)(member, max_header_size=10_000)
                if dtype.hasobject:
                    fail(f"cannot read {what}: its array {info.filename} holds Python objects, which fuzzynav never loads",
                         source)
                declared = dtype.itemsize * math.prod(shape)  # Python ints: no wrap-round
                if declared > max_bytes:
                    fail(f"declares an array of {declared} bytes, more than the {max_bytes // 2**20} MiB limit",
                         source, info.filename)
    except InputError:
        raise
    except Exception as error:  # zipfile / numpy header parsing of hostile bytes raise many types
        fail(f"cannot read {what} ({type(error).__name__}: {error})", source)


def csv_table(content: str, source=None) -> tuple[list[str], list[tuple[int, dict]]]:
    """The header and the data rows ``(line number, {column: text or None})`` of CSV text.

    Any line ending is accepted, blank lines are skipped, a UTF-8 byte-order mark has already
    been removed (:func:`decode`); a column name given twice is refused (``csv.DictReader``
    would silently keep the last column) and names are stripped of surrounding blanks."""
    try:
        reader = csv.reader(io.StringIO(content, newline=""))
        lines = [(reader.line_num, cells) for cells in reader if cells]
    except csv.Error as error:
        fail(f"unreadable CSV ({error})", source)
    if not lines:
        return [], []
    header = [name.strip() for name in lines[0][1]]
    repeated = sorted({name for name in header if header.count(name) > 1})
    if repeated:
        fail(f"column(s) {', '.join(map(repr, repeated))} appear more than once", source, "header")
    for number, cells in lines[1:]:
        if len(cells) > len(header):
            fail(f"{len(cells)} values for {len(header)} columns", source, f"line {number}")
    return header, [(number, {name: cells[j] if j < len(cells) else None for j, name in enumerate(header)})
                    for number, cells in lines[1:]]
