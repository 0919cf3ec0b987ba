"""Fuzzy-system files: JSON / YAML documents (exact round trip), the fuzzylite language (FLL) and
MATLAB's .fis."""

from fuzzynav.fuzzy.io.document import from_document, to_document
from fuzzynav.fuzzy.io.files import FORMATS, dumps, format_of, load, loads, save
from fuzzynav.fuzzy.io.fis import from_fis, to_fis
from fuzzynav.fuzzy.io.fll import from_fll, to_fll

__all__ = ["FORMATS", "dumps", "format_of", "from_document", "from_fis", "from_fll", "load", "loads", "save",
           "to_document", "to_fis", "to_fll"]
