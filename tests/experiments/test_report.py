"""``reproduce --out DIR`` writes DIR/<id>/ and an offline DIR/index.html: claim beside figure."""

import json
from html.parser import HTMLParser
from pathlib import Path

from fuzzynav.catalog import experiments as registry
from fuzzynav.cli import main
from fuzzynav.experiments.claims import CLAIMS


class Page(HTMLParser):
    """Collects the section ids, image sources and external references of a page."""

    def __init__(self):
        super().__init__()
        self.sections, self.images, self.external = [], [], []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "section":
            self.sections.append(attrs["id"])
        if tag == "img":
            self.images.append(attrs["src"])
        for key in ("src", "href"):
            if attrs.get(key, "").startswith(("http:", "https:", "//")):
                self.external.append(attrs[key])


def read_page(folder: Path) -> tuple[Page, str]:
    text = (folder / "index.html").read_text(encoding="utf-8")
    page = Page()
    page.feed(text)
    return page, text


def test_every_experiment_has_a_claim():
    assert set(CLAIMS) == set(registry.available())


def test_index_puts_each_claim_beside_its_figure_and_works_offline(tmp_path, capsys):
    assert main(["reproduce", "fig-V-7", "fig-VI-28", "--quick", "--out", str(tmp_path)]) == 0
    page, text = read_page(tmp_path)
    assert page.sections == ["fig-V-7", "fig-VI-28"]  # in the order of reproduce --list
    assert page.images and not page.external
    for src in page.images:
        assert (tmp_path / src).is_file(), src
    assert {src.split("/")[0] for src in page.images} == {"fig-V-7", "fig-VI-28"}
    assert CLAIMS["fig-VI-28"].thesis in text and "claim holds" in text and "run time" in text
    record = json.loads((tmp_path / "fig-VI-28" / "run.json").read_text())
    assert record["holds"] and record["quick"] and record["seconds"] > 0
    assert "sharp corner (Fig VI.28): collision" in record["verdict"]
    # a later run adds its section to the same page
    assert main(["reproduce", "fig-IV-13", "--quick", "--out", str(tmp_path)]) == 0
    assert read_page(tmp_path)[0].sections == ["fig-IV-13", "fig-V-7", "fig-VI-28"]
    assert "report:" in capsys.readouterr().out


def test_a_claim_that_does_not_hold_is_reported_as_such():
    holds, verdict = CLAIMS["fig-VI-28"].check({"fig-VI-27": {"outcome": "reached"},
                                                "fig-VI-28": {"outcome": "reached"}})
    assert not holds and "sharp corner (Fig VI.28): reached" in verdict
    holds, verdict = CLAIMS["table-VI-1"].check({"rows": [{"states": 9, "actions": 3, "thesis_episodes": 3260,
                                                           "episodes": 500, "episodes_to_converge": None,
                                                           "success": 1.0}]})
    assert not holds and "not converged within 500 episodes" in verdict and "501" not in verdict
    holds, verdict = CLAIMS["fig-V-7"].check({})
    assert not holds and "did not report" in verdict


def test_reproduce_list_counts_the_experiments(capsys):
    assert main(["reproduce", "--list"]) == 0
    assert capsys.readouterr().out.splitlines()[-1] == f"{len(registry.available())} figures and tables"
