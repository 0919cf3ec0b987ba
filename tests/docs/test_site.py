"""The user guide: every page of docs/ in the site's navigation, and the API reference renders
(tables of parameters, links, no literal Sphinx roles) — built with MkDocs as ``.ci/run`` does."""

import re
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"


def nav_pages(entries) -> list[str]:
    """The files the ``nav`` of mkdocs.yml names, in order."""
    pages = []
    for entry in entries:
        for value in (entry.values() if isinstance(entry, dict) else [entry]):
            pages += nav_pages(value) if isinstance(value, list) else [value]
    return pages


def test_every_docs_page_is_in_the_navigation_once():
    config = yaml.safe_load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"))
    assert config["docs_dir"] == "docs"
    pages = nav_pages(config["nav"])
    assert len(pages) == len(set(pages))
    on_disk = {str(path.relative_to(DOCS)) for path in DOCS.rglob("*.md")}
    assert on_disk == set(pages)
    stems = [Path(page).name for page in pages if not page.startswith("results/")]
    assert len(stems) == len(set(stems)), "two pages of one name (one page per subject)"


class Tags(HTMLParser):
    def __init__(self):
        super().__init__()
        self.tags, self.links, self.text = [], [], []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        if tag == "a":
            self.links.append(dict(attrs).get("href", ""))

    def handle_data(self, data):
        self.text.append(data)


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    out = tmp_path_factory.mktemp("site")
    done = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--site-dir", str(out)], cwd=ROOT,
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    return out


@pytest.mark.slow
def test_the_api_page_has_parameter_tables_links_and_no_sphinx_roles(site):
    page = Tags()
    page.feed((site / "guide" / "api" / "index.html").read_text(encoding="utf-8"))
    text = "".join(page.text)
    assert page.tags.count("table") >= 20  # a parameter table per documented function
    assert not re.search(r":(func|class|meth|mod|data|attr|exc):`?", text)
    assert "#fuzzynav.sim.trace.Trace" in page.links  # cross-references are links
    for field in ("name", "world", "start", "goal", "controllers"):  # the dataclass' fields are listed
        assert f'id="fuzzynav.world.scenario.Scenario.{field}"' in (site / "guide" / "api" / "index.html").read_text()


@pytest.mark.slow
def test_every_results_page_says_its_machine_date_and_command(site):
    for page in (DOCS / "results").glob("*.md"):
        head = page.read_text(encoding="utf-8")[:1500]
        assert "**Machine:**" in head and "**Date:**" in head and "**Reproduce:**" in head, page.name
        assert (site / "results" / page.stem / "index.html").is_file()


def test_the_home_page_is_the_site_root():
    """``mkdocs serve`` opens ``/`` and the site title links there: the home page is docs/index.md."""
    config = yaml.safe_load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"))
    assert config["nav"][0] == {"Home": "index.md"}
    assert (DOCS / "index.md").is_file()


@pytest.mark.slow
def test_the_built_site_has_the_user_guide_at_its_root(site):
    home = (site / "index.html").read_text(encoding="utf-8")
    assert "fuzzynav user guide" in home
    page = Tags()
    page.feed(home)
    for link in ("guide/getting-started/", "guide/scenarios/", "dynamic/", "guide/api/"):
        assert link in page.links, link
