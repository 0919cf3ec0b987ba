"""Files a user keeps: trained models and checkpoints, written atomically and read safely.

A document (a JSON object with a ``kind`` field) is stored in the format its file's extension
names: ``.json`` → JSON text, ``.npz`` → a NumPy archive holding ``kind`` and the JSON text as
0-d strings (``document``). Any other extension is refused before anything is trained
(:func:`document_format`). Reading looks at the content, not the name, so either reader accepts
either format and a misnamed file still loads; an ``.npz`` is opened with ``allow_pickle=False``
and never unpickled. Writing goes through a temporary file renamed onto the target, so a crash
while saving never corrupts the previous file.
"""

from __future__ import annotations

import json
import os
import stat
import tempfile
import time
from pathlib import Path

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def remove_stale_temporaries(path, older_than: float | None = None) -> list[Path]:
    """Remove the ``.NAME.*.tmp`` files beside ``path`` (those last modified before
    ``older_than``, a ``time.time()``, when given) that a killed save left; returns the files removed."""
    path = Path(path)
    removed = []
    for tmp in path.parent.glob(f".{path.name}.*.tmp") if path.parent.is_dir() else ():
        try:
            if older_than is None or tmp.stat().st_mtime < older_than:
                tmp.unlink()
                removed.append(tmp)
        except OSError:
            continue  # gone already, or not ours to remove
    return removed


def remove_temporaries_under(folder) -> list[Path]:
    """Remove every ``.NAME.*.tmp`` file under ``folder`` (a killed save's leftovers); only for
    a caller that holds the folder's lock, so that no save into it is under way."""
    removed = []
    for tmp in Path(folder).rglob(".*.tmp") if Path(folder).is_dir() else ():
        try:
            tmp.unlink()
            removed.append(tmp)
        except OSError:
            continue  # gone already, or not ours to remove
    return removed


def atomic_write(path, write) -> None:
    """Write through ``write(handle)`` (a binary file) to a temporary file ``.NAME.XXXX.tmp``
    beside ``path``, then rename it onto ``path``; temporaries an earlier killed save left
    beside ``path`` are then removed (:func:`remove_stale_temporaries`).

    The file gets the usual permissions (0666 less the umask, not mkstemp's 0600); a path that
    cannot be written (missing permission, a directory, ...) is an :class:`InputError` naming it.
    A symbolic link is kept: the file it points to is written. A path that is not a file to
    replace — a device, a pipe (``/dev/null``, ``/dev/stdout``) — is written in place, as a shell's
    ``>`` would, never replaced by a file.
    """
    path = Path(path)
    if _is_stream(path):
        try:
            with open(path, "wb") as handle:
                write(handle)
        except OSError as error:
            raise InputError(f"cannot write ({error.strerror or error})", source=str(path)) from None
        return
    path = Path(os.path.realpath(path)) if path.is_symlink() else path
    tmp = None
    started = time.time()
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
        with os.fdopen(fd, "wb") as handle:
            write(handle)
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    except BaseException as error:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)
        if isinstance(error, OSError):
            blocking = next((p for p in path.parents if p.is_file()), None)
            if blocking is not None:
                raise InputError(f"{blocking} is a file, not a folder: cannot write {path.name} in it",
                                 source=str(path)) from None
            raise InputError(f"cannot write ({error.strerror or error})", source=str(path)) from None
        raise
    remove_stale_temporaries(path, older_than=started - 1.0)


def _is_stream(path: Path) -> bool:
    """Whether ``path`` (links followed) exists and is neither a regular file nor a folder, or is
    a name in the system's ``/dev`` or ``/proc`` (``/dev/stdout`` redirected to a file is a link
    to that file; replacing it would leave the shell writing to a file no longer there)."""
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):  # missing, a dangling link, a name the system refuses
        return False
    return not (stat.S_ISREG(mode) or stat.S_ISDIR(mode)) or path.parts[:2] in (("/", "dev"), ("/", "proc"))


def file_name_part(text: str) -> str:
    """``text`` (a scenario's or controller's name) made safe as part of one file name: every
    character but letters, digits, ``.``, ``_`` and ``-`` becomes ``_``, and a leading ``.`` too,
    so a name such as ``../../x`` cannot place a file outside its folder."""
    safe = "".join(c if (c.isascii() and c.isalnum()) or c in "._-" else "_" for c in str(text))
    return ("_" + safe[1:] if safe.startswith(".") else safe) or "_"


def write_text_atomic(path, text: str) -> None:
    """Write ``text`` (UTF-8) to ``path`` atomically."""
    data = text.encode("utf-8")
    atomic_write(path, lambda handle: handle.write(data))


def savefig_atomic(figure, path, **options) -> None:
    """``figure.savefig(path, **options)`` atomically (format from the suffix, PNG without one)."""
    suffix = Path(path).suffix.lower().lstrip(".")
    options.setdefault("format", suffix or "png")
    atomic_write(path, lambda handle: figure.savefig(handle, **options))


def save_json_atomic(path, document: dict) -> None:
    """Write ``document`` as JSON to ``path`` atomically (temporary file, then rename)."""
    data = json.dumps(document, indent=2, sort_keys=False).encode()
    atomic_write(path, lambda handle: handle.write(data))


def save_npz_atomic(path, **arrays) -> None:
    """Write arrays as ``.npz`` atomically; strings are stored as 0-d unicode arrays."""
    atomic_write(path, lambda handle: np.savez(handle, **arrays))


FORMATS = {".json": "JSON", ".npz": "NPZ"}
_NPZ_MAGIC = b"PK"  # an .npz is a zip archive


def is_model_file(name) -> bool:
    """True when ``name`` names a model file by its extension (:data:`FORMATS`, any case), as a
    ``--controllers`` entry or a ``fis`` argument may, rather than a registered name."""
    return Path(name).suffix.lower() in FORMATS


def document_format(path, field: str = "--out") -> str:
    """``".json"`` or ``".npz"``: the format ``path`` names; another extension is an InputError."""
    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        raise InputError(f"must end in {' or '.join(FORMATS)} (the format to write)", source=str(path), field=field)
    return suffix


def save_document(path, document: dict) -> None:
    """Write ``document`` atomically in the format of ``path``'s extension (module docstring)."""
    if document_format(path) == ".npz":
        save_npz_atomic(path, kind=np.array(str(document["kind"])), document=np.array(json.dumps(document)))
    else:
        save_json_atomic(path, document)


def _read_npz(path: Path, what: str) -> dict:
    validation.check_npz(path)  # sizes and dtypes its headers declare, before decompressing
    try:
        with np.load(path, allow_pickle=False) as data:
            document = {key: data[key] for key in data.files}
    except Exception as error:  # corrupt data past the checked headers (zlib, CRC, truncation, ...)
        raise InputError(f"cannot read {what}: not a valid NumPy archive ({type(error).__name__}: {error})",
                         source=str(path)) from None
    if "document" in document:  # a JSON document stored in an archive (save_document)
        stored, kind = document["document"], document.get("kind")
        if stored.dtype.kind != "U" or stored.ndim != 0:  # str() of another array is no JSON: say what it is
            raise InputError(f"must be one text (a 0-d unicode array, as fuzzynav writes it), got an array of "
                             f"{stored.dtype} of shape {stored.shape}", source=str(path), field="document")
        text = validation.text(str(stored), str(path), "document", max_length=validation.MAX_MODEL_BYTES)
        parsed = validation.parse_json(text, str(path))
        if kind is not None and isinstance(parsed, dict) and str(kind) != parsed.get("kind"):  # (an edited archive)
            raise InputError(f"the archive's kind {validation.shown(str(kind))} is not its document's "
                             f"{parsed.get('kind')!r} (an edited archive? its document is what would run)",
                             source=str(path), field="kind")
        return parsed
    if "kind" in document:
        document["kind"] = str(document["kind"]) if document["kind"].dtype.kind == "U" else document["kind"]
    return document


def check_model_file(path, field: str | None = None, what: str = "model file") -> Path:
    """``path`` as a Path when it is a regular file; else an InputError naming it: a folder,
    missing, or what :func:`~fuzzynav.validation.read_bytes` refuses to open (a named pipe, whose
    read would wait for ever; a loop of symbolic links)."""
    path = Path(path)
    if not path.is_file():
        if path.is_dir() or not (path.exists() or path.is_symlink()):
            raise InputError(f"is a folder, not a {what}" if path.is_dir() else f"no such {what}",
                             source=str(path), field=field)
        try:
            validation.read_bytes(path, max_bytes=0)  # refused before a byte is read: it is not a regular file
        except InputError as error:
            raise InputError(error.problem, source=str(path), field=field) from None
    return path


def read_document(path, what: str = "model file") -> dict:
    """Read a document written by :func:`save_document` (either format, whatever the name says)
    or an archive of arrays with a ``kind``; a file that is neither is an InputError naming it, and
    ``what`` it was to be ("model file", "checkpoint").

    Bounded before anything is decoded (:mod:`fuzzynav.validation`): a JSON file by its size,
    nesting and values; an ``.npz`` by the sizes its zip and array headers declare
    (:func:`fuzzynav.validation.check_npz`), never unpickled.
    """
    path = check_model_file(path, what=what)
    try:
        with path.open("rb") as handle:
            npz = handle.read(len(_NPZ_MAGIC)) == _NPZ_MAGIC
    except OSError as error:
        raise InputError(f"cannot read {what} ({error.strerror or error})", source=str(path)) from None
    if npz:
        document = _read_npz(path, what)
    else:
        data = validation.read_bytes(path, max_bytes=validation.MAX_MODEL_BYTES)
        try:
            document = validation.parse_json(validation.decode(data, str(path)), str(path))
        except InputError as error:
            if not error.problem.startswith(("invalid JSON", "cannot read file")):
                raise  # valid JSON past a limit: the error names the field
            where = f", {error.field}" if error.field else ""
            kind = "neither an .npz archive (no zip header) nor" if path.suffix.lower() == ".npz" else "not"
            raise InputError(f"cannot read {what}: {kind} a valid JSON document ({error.problem}{where})",
                             source=str(path)) from None
    if not isinstance(document, dict) or "kind" not in document:
        raise InputError(f"not a fuzzynav {what} (no 'kind' field)", source=str(path), field="kind")
    validation.text(document["kind"], str(path), "kind", max_length=100)
    return document


def matches(found, expected) -> bool:
    """``found == expected`` for whatever a document's field holds: False for a boolean standing for
    1 or 0, and for an array of several values or none (a field of an ``.npz`` archive), whose
    ``==`` compares value by value."""
    try:
        return not isinstance(found, bool) and bool(found == expected)
    except ValueError:  # the truth of an array of several values, or of none, is ambiguous
        return False


def supported_version(document: dict, version: int, source=None, *, required: bool = False) -> None:
    """Refuse a ``document`` whose ``version`` is not ``version`` (a boolean is not a version);
    one without the field is of ``version`` unless it is ``required``."""
    if required and "version" not in document:
        validation.fail(f"unsupported version None (this package reads {version})", source, "version")
    found = document.get("version", version)
    if not matches(found, version):
        validation.fail(f"unsupported version {validation.shown(found)} (this package reads {version})", source, "version")
