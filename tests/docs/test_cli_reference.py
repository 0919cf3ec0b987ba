"""docs/cli.md is what the command line's parser renders (:mod:`fuzzynav.cli.reference`): a new
option, command or help text changes the page, and this test fails until the page is written
again (``python -m fuzzynav.cli.reference docs/cli.md``)."""

import argparse
from pathlib import Path

from fuzzynav.cli import build_parser
from fuzzynav.cli.reference import render

PAGE = Path(__file__).resolve().parents[2] / "docs" / "cli.md"


def test_the_committed_page_is_what_the_parser_renders():
    assert PAGE.read_text(encoding="utf-8") == render(), \
        "docs/cli.md is out of date: python -m fuzzynav.cli.reference docs/cli.md"


def _parsers(parser):
    yield parser
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for child in action.choices.values():
                yield from _parsers(child)


def test_every_command_and_option_is_on_the_page():
    page = PAGE.read_text(encoding="utf-8")
    for parser in _parsers(build_parser()):
        assert f"# {parser.prog}\n" in page, parser.prog  # its heading
        for action in parser._actions:
            for flag in action.option_strings:
                assert flag in ("-h", "--help") or f"`{flag}`" in page, (parser.prog, flag)


def test_the_page_does_not_depend_on_the_terminal(monkeypatch):
    monkeypatch.setenv("COLUMNS", "40")
    assert render() == PAGE.read_text(encoding="utf-8")
