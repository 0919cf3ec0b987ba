"""The one exception type for bad user input (files, fields, command-line values).

Every layer raises :class:`InputError` with a message that names the file (when there is one),
the field and what is wrong; the command line prints it on stderr and exits with status 2.
"""

from __future__ import annotations


class InputError(ValueError):
    """Bad user input: the message names the source, the field and the problem."""

    def __init__(self, message: str, *, source: str | None = None, field: str | None = None):
        parts = []
        if source:
            parts.append(str(source))
        if field:
            parts.append(str(field))
        prefix = ": ".join(parts)
        super().__init__(f"{prefix}: {message}" if prefix else message)
        self.source = source
        self.field = field
        self.problem = message


class CommandError(InputError):
    """A controller returned a command the robot cannot take (missing, not a number, NaN or
    infinite): the message names the controller, the step and the value."""
