"""The command-line reference, ``docs/cli.md``, rendered from the parser itself
(:func:`fuzzynav.cli.build_parser`): every command and sub-command with its description, usage
line, options (flag, value, help, default) and examples. The page is committed (it is read on
GitHub as well as in the site); ``tests/docs/test_cli_reference.py`` fails when it differs from
what the parser renders, and this writes it again::

    python -m fuzzynav.cli.reference docs/cli.md
"""

from __future__ import annotations

import argparse
import html
import re
import sys
from pathlib import Path

from fuzzynav.cli import build_parser

WIDTH = 100  # columns of the usage lines (a fixed width: the page is the same on every terminal)
INTRO = """# Command line

Every `fuzzynav` command and sub-command, with its options and examples: the `--help` of each,
as a page. It is generated from the command line's own parser (`python -m fuzzynav.cli.reference
docs/cli.md` writes it, and `tests/docs/test_cli_reference.py` fails when it is out of date), so it
names exactly the options the installed version takes. The guide's pages say what the commands
are for; limits of every value are in [limits of every input](limits.md).
"""


def _anchor(prog: str) -> str:
    """The id MkDocs gives the heading ``prog`` (``fuzzynav fis eval`` -> ``fuzzynav-fis-eval``)."""
    return re.sub(r"[^\w-]+", "-", prog.lower()).strip("-")


def _code(text: str) -> str:
    """``text`` as code in a table cell: a ``|`` in it would end the cell on GitHub, and ``\\|``
    stays a backslash in MkDocs' code spans, so such a text is an HTML ``<code>`` with ``&#124;``."""
    if "|" not in text:
        return f"`{text}`"
    return "<code>" + html.escape(text).replace("|", "&#124;") + "</code>"


def _text(text: str | None) -> str:
    """Help or description text as Markdown for a table cell: Sphinx roles as code, and what
    Markdown would read (``*`` of ``2**63``, ``_``, ``<``, the ``|`` of a table) escaped outside
    code spans."""
    text = re.sub(r":\w+:`~?([^`]+)`", r"`\1`", " ".join((text or "").split())).replace("``", "`")
    parts = re.split(r"`([^`]*)`", text)
    for i, part in enumerate(parts):
        parts[i] = _code(part) if i % 2 else "".join(
            "\\" + c if c in "*_|" else "&lt;" if c == "<" else c for c in part)
    return "".join(parts)


def _usage(parser: argparse.ArgumentParser) -> str:
    formatter = argparse.HelpFormatter(prog=parser.prog, width=WIDTH)
    formatter.add_usage(parser.usage, parser._actions, parser._mutually_exclusive_groups, prefix="")
    return formatter.format_help().rstrip()


def _subcommands(parser: argparse.ArgumentParser) -> argparse._SubParsersAction | None:
    return next((a for a in parser._actions if isinstance(a, argparse._SubParsersAction)), None)


def _default(action: argparse.Action) -> str:
    if action.required and (action.option_strings or action.nargs not in ("?", "*")):  # argparse marks '*' required
        return "required"
    if action.default in (None, False, argparse.SUPPRESS) or isinstance(action, argparse._StoreTrueAction):
        return ""
    return _code(str(action.default))


def _options(parser: argparse.ArgumentParser) -> list[str]:
    """The table of ``parser``'s arguments (``--help`` left out)."""
    formatter = argparse.HelpFormatter(prog=parser.prog, width=WIDTH)
    rows = []
    for action in parser._actions:
        if isinstance(action, (argparse._HelpAction, argparse._SubParsersAction)) or action.help == argparse.SUPPRESS:
            continue
        if action.option_strings:
            name = ", ".join(f"`{flag}`" for flag in action.option_strings)
            value = "" if action.nargs == 0 else formatter._format_args(
                action, formatter._get_default_metavar_for_optional(action))
        else:
            name = formatter._metavar_formatter(action, formatter._get_default_metavar_for_positional(action))(1)[0]
            value = formatter._format_args(action, formatter._get_default_metavar_for_positional(action))
            name, value = _code(name), "" if value == name else value
        value = _code(value) if value else ""
        help_text = _text(formatter._expand_help(action)) if action.help else ""
        rows.append(f"| {name} | {value} | {help_text} | {_default(action)} |")
    if not rows:
        return []
    return ["| Argument | Value | What it does | Default |", "|---|---|---|---|", *rows, ""]


def _epilog(epilog: str | None) -> list[str]:
    """The epilog as a text block (a listing, such as the controllers of ``run``), then its
    ``examples:`` as a code block."""
    if not epilog:
        return []
    head, _, examples = ("\n" + epilog).partition("\nexamples:\n")
    lines = []
    if head.strip():
        lines += ["```text", head.strip("\n"), "```", ""]
    if examples.strip():
        commands = [line[2:] if line.startswith("  ") else line for line in examples.rstrip().splitlines()]
        # bash, whose commands tests/docs/test_commands_in_docs.py parses, unless one names a placeholder
        language = "text" if any(re.match(r"fuzzynav [A-Z]", command) for command in commands) else "bash"
        lines += ["Examples:", "", f"```{language}", *commands, "```", ""]
    return lines


def _command(parser: argparse.ArgumentParser, level: int, helps: dict[str, str]) -> list[str]:
    lines = [f"{'#' * level} {parser.prog}", ""]
    if parser.prog in helps:
        lines += [f"*{_text(helps[parser.prog])}*", ""]
    if parser.description:
        lines += [_text(parser.description), ""]
    lines += ["```text", _usage(parser), "```", ""]
    lines += _options(parser)
    sub = _subcommands(parser)
    if sub is not None:
        lines += [f"| {sub.metavar or 'COMMAND'} | What it does |", "|---|---|"]
        for choice in sub._choices_actions:
            prog = sub.choices[choice.dest].prog
            lines.append(f"| [{choice.dest}](#{_anchor(prog)}) | {_text(choice.help)} |")
        lines.append("")
    lines += _epilog(parser.epilog)
    if sub is not None:
        for choice in sub._choices_actions:
            helps[sub.choices[choice.dest].prog] = choice.help or ""
            lines += _command(sub.choices[choice.dest], level + 1, helps)
    return lines


def render() -> str:
    """The Markdown of ``docs/cli.md``."""
    parser = build_parser()
    lines = [INTRO]
    lines += [line for line in _command(parser, 2, {}) if line != "#"]
    return "\n".join(lines).rstrip() + "\n"


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    text = render()
    if args:
        Path(args[0]).write_text(text, encoding="utf-8")
        print(f"wrote {args[0]}", file=sys.stderr)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
