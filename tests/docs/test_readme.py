"""The README's tour and API example run exactly as written, in a fresh folder.

The README is the single source: the tests extract the first ``bash`` block after "## A tour" and
the ``python`` block after "### The Python API", so a command added to the tour is tested too.
``source .venv/bin/activate`` is served by a stand-in ``.venv/bin/activate`` that puts the
``fuzzynav`` script of the Python running the tests on the PATH, as activating its venv would.
"""

import os
import re
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

from fuzzynav.catalog import experiments as registry

pytestmark = pytest.mark.slow
README = Path(__file__).resolve().parents[2] / "README.md"


def block(heading: str, language: str) -> str:
    """The first fenced ``language`` block after the line ``heading`` in the README."""
    text = README.read_text(encoding="utf-8")
    after = text[text.index(f"\n{heading}\n"):]
    return re.search(rf"```{language}\n(.*?)```", after, re.S).group(1)


def fresh_folder(tmp_path: Path) -> Path:
    activate = tmp_path / ".venv" / "bin" / "activate"
    activate.parent.mkdir(parents=True)
    scripts = sysconfig.get_path("scripts")
    assert (Path(scripts) / "fuzzynav").exists(), f"no fuzzynav script in {scripts}: install the package first"
    activate.write_text(f'export PATH="{scripts}:$PATH"\n')
    return tmp_path


def test_the_tour_runs_top_to_bottom(tmp_path):
    tour = block("## A tour", "bash")
    assert tour.startswith("source .venv/bin/activate")
    folder = fresh_folder(tmp_path)
    env = {key: value for key, value in os.environ.items() if key != "VIRTUAL_ENV"}
    env["PATH"] = "/usr/bin:/bin"  # nothing of the test's own venv: the tour must activate it
    done = subprocess.run(["bash", "-euo", "pipefail", "-c", tour], cwd=folder, env=env, capture_output=True,
                          text=True, timeout=900)
    assert done.returncode == 0, f"the tour failed:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
    for made in ("u.png", "u.gif", "my-world.yaml", "outputs.csv", "tracking.fll", "anfis.json", "anfis.fll",
                 "fql.npz", "fql.png", "figures/index.html", "figures/fig-V-28/fig-V-28.png",
                 "worlds/mixed-0-002.yaml", "my-demo/metrics.md"):
        assert (folder / "tour" / made).is_file(), made


def test_the_api_example_runs_and_saves_a_plot(tmp_path):
    example = block("### The Python API", "python")
    assert len(example.strip().splitlines()) <= 10
    done = subprocess.run([sys.executable, "-c", example], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split()[0] == "reached"
    assert (tmp_path / "fig-IV-23.png").stat().st_size > 10_000


def test_the_readme_counts_the_figures_and_tables_as_reproduce_list_does():
    counts = {int(n) for n in re.findall(r"all (\d+) figures/tables", README.read_text(encoding="utf-8"))}
    assert counts == {len(registry.available())}


def test_the_first_screen_says_what_it_is_shows_it_and_installs_it():
    lines = README.read_text(encoding="utf-8").splitlines()
    assert len(lines) <= 250
    screen = "\n".join(lines[:50])
    assert "**fuzzynav**" in screen and "robot" in screen and "thesis" in screen  # what it is
    picture = re.search(r"!\[[^\]]+\]\(([^)]+\.gif)\)", screen)
    assert picture, "no picture in the first screen"
    gif = README.parent / picture.group(1)
    assert 10_000 < gif.stat().st_size < 1_000_000
    assert "Python ≥ 3.11" in screen
    assert ("python3 -m venv .venv && .venv/bin/pip install -e . && .venv/bin/fuzzynav demo --out fuzzynav-out"
            in screen)
    assert "python3 -m venv .venv && .venv/bin/pip install -e '.[test]' && .venv/bin/python -m pytest -q" in screen
    assert "cold" in screen and "warm" in screen  # the first run's compile time, both ways
    prose = " ".join(screen.split())
    assert len(re.findall(r"\d s (?:\*\*)?cold", prose)) == 1, "one current cold figure; the rest in first-run.md"
    assert "(docs/results/first-run.md)" in prose
