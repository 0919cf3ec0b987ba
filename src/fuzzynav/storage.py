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
import tempfile
import zipfile
from pathlib import Path

import numpy as np

from fuzzynav.errors import InputError


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _atomic_write(path: Path, write) -> None:
    """Write through ``write(handle)`` to a temporary file, then rename it onto ``path``.

    The file gets the usual permissions (0666 less the umask, not mkstemp's 0600); a path that
    cannot be written (missing permission, a directory, ...) is an :class:`InputError` naming it.
    """
    path = Path(path)
    tmp = None
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
            raise InputError(f"cannot write ({error.strerror or error})", source=str(path)) from None
        raise


def save_json_atomic(path, document: dict) -> None:
    """Write ``document`` as JSON to ``path`` atomically (temporary file, then rename)."""
    data = json.dumps(document, indent=2, sort_keys=False).encode()
    _atomic_write(Path(path), lambda handle: handle.write(data))


def save_npz_atomic(path, **arrays) -> None:
    """Write arrays as ``.npz`` atomically; strings are stored as 0-d unicode arrays."""
    _atomic_write(Path(path), lambda handle: np.savez(handle, **arrays))


FORMATS = {".json": "JSON", ".npz": "NPZ"}
_NPZ_MAGIC = b"PK"  # an .npz is a zip archive


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


def _read_npz(path: Path) -> dict:
    with np.load(path, allow_pickle=False) as data:
        document = {key: data[key] for key in data.files}
    if "document" in document:  # a JSON document stored in an archive (save_document)
        return json.loads(str(document["document"]))
    if "kind" in document:
        document["kind"] = str(document["kind"])
    return document


def read_document(path) -> dict:
    """Read a document written by :func:`save_document` (either format, whatever the name says)
    or an archive of arrays with a ``kind``; a file that is neither is an InputError naming it."""
    path = Path(path)
    if not path.is_file():
        raise InputError("no such model file", source=str(path))
    npz = False
    try:
        with path.open("rb") as handle:
            npz = handle.read(len(_NPZ_MAGIC)) == _NPZ_MAGIC
        document = _read_npz(path) if npz else json.loads(path.read_bytes().decode("utf-8"))
    except (OSError, ValueError, EOFError, zipfile.BadZipFile) as error:
        what = "NumPy archive" if npz else "JSON document"
        detail = "it holds Python objects, which fuzzynav never loads" if "pickle" in str(error) else error
        raise InputError(f"cannot read model file: not a valid {what} ({detail})", source=str(path)) from None
    if not isinstance(document, dict) or "kind" not in document:
        raise InputError("not a fuzzynav model file (no 'kind' field)", source=str(path), field="kind")
    return document
