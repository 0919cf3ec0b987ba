"""Every ``fuzzynav`` command quoted in the README and the docs parses, and every ``python
benchmarks/<script>.py`` they quote exists: a renamed flag or command breaks this test, not a
reader's first try. A command of a ``bash`` block parses in full (argparse, nothing runs); one
quoted in the text is a synopsis (``fuzzynav evaluate --seed S …``): its command and sub-command
exist and so does every ``--flag`` it names."""

import argparse
import contextlib
import io
import re
import shlex
from pathlib import Path

import pytest

from fuzzynav.cli import build_parser

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", ROOT / "CONTRIBUTING.md", *sorted((ROOT / "docs").rglob("*.md"))]
PLACEHOLDER = re.compile(r"\[[^\]]*\]|…|\.\.\.")  # [--optional] parts and ellipses of synopses


def shell_lines(text: str, blocks: bool) -> list[str]:
    """The lines of the fenced ``bash`` blocks (continuations joined), or the inline code spans."""
    if not blocks:
        return re.findall(r"`([^`]+)`", re.sub(r"```.*?```", "", text, flags=re.S).replace("\n", " "))
    return [line for block in re.findall(r"```bash\n(.*?)```", text, re.S)
            for line in block.replace("\\\n", " ").splitlines()]


def quoted_commands(prefix: str, blocks: bool = True) -> list[tuple[str, str]]:
    """(page, command) for each command starting with ``prefix`` quoted in the pages' ``bash``
    blocks (or their text), one per ``&&`` / ``|`` part, without its comment, redirection or
    placeholders."""
    found = []
    for page in PAGES:
        for line in shell_lines(page.read_text(encoding="utf-8"), blocks):
            for part in re.split(r"&&|\|\||\||;", line.split(" #")[0]):
                part = re.sub(r"^(time|\S*/bin/)", "", part.strip()).strip()
                part = re.split(r"\s[<>]|^[<>]", part)[0].strip()
                if part.startswith(prefix):
                    found.append((page.relative_to(ROOT).as_posix(), PLACEHOLDER.sub("", part).strip()))
    return sorted(set(found))


COMMANDS = quoted_commands("fuzzynav ")
SYNOPSES = quoted_commands("fuzzynav ", blocks=False)
SCRIPTS = sorted(set(quoted_commands("python benchmarks/") + quoted_commands("python benchmarks/", blocks=False)))


def test_the_docs_quote_commands():
    assert len(COMMANDS) > 50 and len(SYNOPSES) > 50 and len(SCRIPTS) > 10


def command_parser(words: list[str]):
    """The parser of the (sub-)command ``words`` name, and the words after its name."""
    parser = build_parser()
    while words:
        choices = next((action.choices for action in parser._actions if isinstance(action, argparse._SubParsersAction)),
                       {})
        if words[0] not in choices:
            break
        parser, words = choices[words[0]], words[1:]
    return parser, words


@pytest.mark.parametrize(("page", "command"), SYNOPSES)
def test_every_command_named_in_the_text_exists_with_its_flags(page, command):
    parser, rest = command_parser(shlex.split(command)[1:])
    assert parser.prog != "fuzzynav" or not rest or rest[0].startswith("-"), f"{page}: {command}: no such command"
    flags = {flag for action in parser._actions for flag in action.option_strings}
    unknown = [word.split("=")[0] for word in rest if word.startswith("--") and word.split("=")[0] not in flags]
    assert not unknown, f"{page}: {command}: {parser.prog} has no {', '.join(unknown)}"


@pytest.mark.parametrize(("page", "command"), COMMANDS)
def test_every_quoted_command_parses(page, command):
    argv = shlex.split(command)[1:]
    with contextlib.redirect_stderr(io.StringIO()) as errors, contextlib.redirect_stdout(io.StringIO()):
        try:
            build_parser().parse_args(argv)
        except SystemExit as exit_:
            assert exit_.code == 0, f"{page}: {command}\n{errors.getvalue()}"


@pytest.mark.parametrize(("page", "command"), SCRIPTS)
def test_every_quoted_benchmark_script_exists(page, command):
    script = shlex.split(command)[1]
    assert (ROOT / script).is_file(), f"{page}: {command}"
