"""``write_index`` lists a record it cannot read as unreadable (file and reason) instead of crashing."""

import json
import re
from pathlib import Path

import pytest

from fuzzynav.experiments import report
from fuzzynav.experiments.claims import REPRODUCED

KEY, OTHER = "fig-V-7", "fig-IV-12"


def _record(out: Path, key: str) -> None:
    """A record of ``key`` as :func:`report.record_run` writes it, without running the experiment."""
    folder = out / key
    folder.mkdir(parents=True)
    (folder / f"{key}.json").write_text(json.dumps({"answer": 42}))
    check = {"name": "answer", "value": 42, "target": "= 42", "pass": True, "source": "thesis"}
    (folder / "claim.json").write_text(json.dumps({"id": key, "reference": "§V.2", "thesis": "It holds.",
                                                   "asserted": "It holds.", "checks": [check],
                                                   "verdict": REPRODUCED}))
    (folder / "run.json").write_text(json.dumps({"id": key, "seconds": 1.5, "quick": True, "seed": 0,
                                                 "verdict": REPRODUCED, "finished": "2024-01-01 00:00 UTC"}))


@pytest.mark.parametrize("run, claim, expected", [
    ("\n", None, r"fig-IV-12/run\.json: line 2, column 1: invalid JSON"),
    (None, "{}\n", r"fig-IV-12/claim\.json: verdict: missing"),
    ("\n", "{}\n", r"fig-IV-12/run\.json: line 2, column 1: invalid JSON"),
    ('{"verdict": "won", "seconds": 1, "quick": true, "seed": 0, "finished": ""}', None,
     r"fig-IV-12/run\.json: verdict: must be one of"),
    ('{"verdict": "reproduced", "seconds": "1", "quick": true, "seed": 0, "finished": ""}', None,
     r"fig-IV-12/run\.json: seconds: must be a number"),
    (None, '{"verdict": "partly", "reference": "", "thesis": "", "asserted": "", "checks": [{"name": "x"}]}',
     r"fig-IV-12/claim\.json: checks\[0\]\.value: missing"),
    ("[]", None, r"fig-IV-12/run\.json: must be a mapping"),
])
def test_an_unreadable_record_is_listed_and_the_index_still_written(tmp_path, run, claim, expected):
    _record(tmp_path, KEY)
    _record(tmp_path, OTHER)
    for name, text in (("run.json", run), ("claim.json", claim)):
        if text is not None:
            (tmp_path / OTHER / name).write_text(text)
    page = report.write_index(tmp_path).read_text(encoding="utf-8")
    section = page.split(f'<section id="{OTHER}">')[1].split("</section>")[0]
    assert "unreadable record" in section
    assert re.search(expected, section), section
    assert f'<section id="{KEY}">' in page and "It holds." in page  # the readable one is whole
    assert "2 of " in page and "(1 unreadable)" in page and "reproduced: 1 of 1" in page


def test_missing_numbers_file_is_listed_as_unreadable(tmp_path):
    _record(tmp_path, OTHER)
    (tmp_path / OTHER / f"{OTHER}.json").unlink()
    page = report.write_index(tmp_path).read_text(encoding="utf-8")
    assert f"{OTHER}.json: cannot read file" in page and "reproduced: 0 of 0" in page


def test_readable_records_give_the_page_as_before(tmp_path):
    _record(tmp_path, KEY)
    page = report.write_index(tmp_path).read_text(encoding="utf-8")
    assert "unreadable" not in page
    assert f"1 of {len(report.registry.available())} experiments in this folder; reproduced: 1 of 1; their run times add up to" \
        in page
    assert "quick run (short budgets), seed 0, run time 1.5 s (finished 2024-01-01 00:00 UTC)" in page
