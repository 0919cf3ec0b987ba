"""The one exception type for bad user input (files, fields, command-line values).

Every layer raises :class:`InputError` with a message that names the file (when there is one),
the field and what is wrong; the command line prints it on stderr and exits with status 2.
"""

from __future__ import annotations


def escaped(text) -> str:
    """``text`` with its control characters written as escapes (``\\x1b``): a file or an argument
    named with an ESC reached the terminal as a command when the message named it."""
    return "".join(repr(c)[1:-1] if ord(c) < 32 or 127 <= ord(c) < 160 else c for c in str(text))


class InputError(ValueError):
    """Bad user input: the message names the source, the field and the problem."""

    def __init__(self, message: str, *, source: str | None = None, field: str | None = None):
        parts = []
        if source:
            parts.append(escaped(source))
        if field:
            parts.append(escaped(field))
        prefix = ": ".join(parts)
        super().__init__(f"{prefix}: {message}" if prefix else message)
        self.source = source
        self.field = field
        self.problem = message


class CommandError(InputError):
    """A controller returned a command the robot cannot take (missing, not a number, NaN or
    infinite): the message names the controller, the step and the value."""
