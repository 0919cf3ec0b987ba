"""Every case of the hostile corpus (``cases.py``) as a regression test, in process: refused with
exit status 2 / an InputError whose message names the field, or accepted where the input is fine."""

from __future__ import annotations

import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from tests.validation.hostile_cases import argv_of, write_files

from .cases import CASES, PRELUDE


def _python(case, tmp_path) -> tuple[int, str]:
    """(status, message) of a Python case: 2 and the error on an InputError, else its exit code."""
    namespace = {"d": tmp_path}
    exec(PRELUDE, namespace)  # noqa: S102 - the test's own code
    try:
        exec(case.python, namespace)  # noqa: S102
    except InputError as error:
        return 2, str(error)
    except SystemExit as done:
        return int(done.code or 0), ""
    return 0, ""


@pytest.mark.parametrize("case", CASES, ids=[case.name for case in CASES])
def test_hostile_case(case, tmp_path, capsys):
    write_files(case, tmp_path)
    if case.python:
        status, message = _python(case, tmp_path)
    else:
        try:
            status, message = main(argv_of(case, tmp_path)), ""
        except SystemExit as usage:  # argparse refuses a bad value (usage and message on stderr)
            status, message = int(usage.code), ""
    out, err = capsys.readouterr()
    assert status == case.status, (message, err)
    assert case.expect in (message + err if status else out), (message, err, out)
    assert "Traceback" not in err
