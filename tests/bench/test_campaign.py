"""``fuzzynav bench``: files, resume after a kill, local = Ray, bad input."""

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from fuzzynav.bench.measures import barn_score
from fuzzynav.bench.suites import parse_suite
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.cli import main
from fuzzynav.sim import metrics, run_episode

DATA = Path(__file__).resolve().parents[1] / "data" / "barn"
FINAL = ("runs.csv", "runs.jsonl", "summary.json", "summary.md")
CONTROLLERS = "goal-seeking,vfh"


def _bench(out, *extra):
    return main(["bench", "circles:3:5", "--controllers", CONTROLLERS, "--seeds", "2", "--workers", "1",
                 "--out", str(out), "--quiet", "--gallery", "1", *extra])


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    out = tmp_path_factory.mktemp("bench") / "reference"
    assert _bench(out) == 0
    return out


def test_files_rows_and_summary(reference):
    for name in (*FINAL, "index.html", "rates.png", "path_ratio.png"):
        assert (reference / name).is_file(), name
    lines = (reference / "runs.csv").read_text().splitlines()
    assert lines[0].startswith("suite,world,seed,controller,outcome,time_s,path_length_m,shortest_path_m,path_ratio")
    assert len(lines) == 1 + 3 * 2 * 2
    rows = [json.loads(line) for line in (reference / "runs.jsonl").read_text().splitlines()]
    assert [r["world"] for r in rows[:4]] == ["circles-5-000"] * 2 + ["circles-5-001"] * 2  # seed 0 first
    assert {r["world"][:9] for r in rows[6:]} == {"circles-6"}  # seed 1 draws its own worlds
    assert {r["outcome"] for r in rows} >= {"reached", "collision"}  # both kinds below
    for r in rows:
        assert r["shortest_path_m"] > 0
        if r["outcome"] == "reached":  # driven / shortest, of the successful runs only
            assert r["path_ratio"] == pytest.approx(r["path_length_m"] / r["shortest_path_m"], rel=1e-12)
            assert r["path_ratio"] >= 1.0 - 1e-9
        else:
            assert r["path_ratio"] is None
    summary = json.loads((reference / "summary.json").read_text())
    assert [(s["suite"], s["controller"]) for s in summary["results"]] == [("circles:3:5", "goal-seeking"),
                                                                           ("circles:3:5", "vfh")]
    assert "failures-" in (reference / "index.html").read_text() or all(r["outcome"] == "reached" for r in rows)
    assert (reference / "cache" / "shortest").is_dir() and len(list((reference / "cache" / "shortest").iterdir())) == 6


def test_each_row_holds_the_metrics_of_its_episode(reference):
    """A row's numbers are those fuzzynav.sim.metrics gives the episode run alone (world, controller, seed)."""
    suite = parse_suite("circles:3:5")
    rows = [json.loads(line) for line in (reference / "runs.jsonl").read_text().splitlines()]
    keys = ("outcome", "time_s", "path_length_m", "min_clearance_m", "steering_effort_rad", "steering_variation_rad",
            "final_distance_m", "collision_by")
    for r in rows[:4] + rows[-2:]:  # both controllers on worlds of both seeds
        index = int(r["world"].rsplit("-", 1)[1])
        scenario = suite.scenario(index, r["seed"])
        assert scenario.name == r["world"]
        numbers = metrics(run_episode(scenario, make_controller(r["controller"]), seed=r["seed"]), scenario)
        assert {key: r[key] for key in keys} == {key: numbers[key] for key in keys}, r["world"]


def test_existing_campaign_needs_resume(reference, tmp_path, capsys):
    copy = tmp_path / "copy"
    shutil.copytree(reference, copy)
    assert _bench(copy) == 2
    assert "--resume" in capsys.readouterr().err
    capsys.readouterr()
    assert _bench(copy, "--resume") == 0  # nothing left to run: the same files
    out, err = capsys.readouterr()
    assert f"--resume: 12 runs already in {copy}, 0 to run" in err
    lines = out.splitlines()  # the rates on the terminal, a line per suite and controller
    assert lines[0].split() == ["suite", "controller", "runs", "success", "collision", "timeout", "median", "time"]
    summary = json.loads((reference / "summary.json").read_text())["results"]
    assert len(lines) == 1 + len(summary)
    for line, record in zip(lines[1:], summary):
        assert line.split()[:3] == [record["suite"], record["controller"], str(record["runs"])]
        assert f"{100 * record['reached']['rate']:.1f} %" in line
    for name in FINAL:
        assert (copy / name).read_bytes() == (reference / name).read_bytes(), name


def test_a_folder_of_someone_elses_reports_is_not_overwritten(tmp_path, capsys):
    """A folder holding an index.html, a summary.md (a user's, say) but no runs.jsonl is no campaign's:
    the campaign used to overwrite them. Other files of a folder are never touched."""
    out = tmp_path / "mine"
    out.mkdir()
    (out / "index.html").write_text("precious")
    (out / "summary.md").write_text("notes")
    assert _bench(out) == 2
    assert "holds summary.md, index.html but no runs.jsonl" in capsys.readouterr().err
    assert (out / "index.html").read_text() == "precious" and not (out / "runs.jsonl").exists()
    assert sorted(p.name for p in out.iterdir()) == ["index.html", "summary.md"]  # not even a lock file left
    (out / "index.html").unlink(), (out / "summary.md").unlink()
    (out / "notes.txt").write_text("kept")
    assert _bench(out) == 0 and (out / "notes.txt").read_text() == "kept"


@pytest.mark.slow
def test_killed_half_way_then_resumed_gives_the_same_files(reference, tmp_path):
    out = tmp_path / "killed"
    command = [sys.executable, "-c", "import sys; from fuzzynav.cli import main; sys.exit(main(sys.argv[1:]))", "bench", "circles:3:5", "--controllers", CONTROLLERS,
               "--seeds", "2", "--workers", "1", "--out", str(out), "--quiet", "--gallery", "1"]
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and process.poll() is None:
        jsonl = out / "runs.jsonl"
        if jsonl.is_file() and len(jsonl.read_text().splitlines()) >= 4:
            break
        time.sleep(0.02)
    os.kill(process.pid, signal.SIGKILL)
    process.wait()
    done = len((out / "runs.jsonl").read_text().splitlines())
    assert 4 <= done < 12, "the campaign must be killed half-way"
    with open(out / "runs.jsonl", "a") as handle:  # a line cut by the kill
        handle.write('{"suite": "circles:3:5", "wor')
    assert main([*command[3:], "--resume"]) == 0
    for name in FINAL:
        assert (out / name).read_bytes() == (reference / name).read_bytes(), name
    assert [p.name for p in out.rglob("*") if ".tmp" in p.name] == []  # no stray temporary file


@pytest.mark.slow
def test_ray_backend_gives_byte_identical_runs(reference, tmp_path):
    if os.environ.get("CI"):  # .ci/run installs the 'cluster' extra: there the test must run, never skip
        import ray  # noqa: F401
    else:
        pytest.importorskip("ray", reason="the Ray backend is the 'cluster' extra (.ci/run installs it)")
    out = tmp_path / "ray"
    assert _bench(out, "--backend", "ray", "--workers", "2") == 0
    for name in FINAL:
        assert (out / name).read_bytes() == (reference / name).read_bytes(), name


def test_folder_suite_with_barn_reference_scores(tmp_path):
    barn = tmp_path / "barn"
    assert main(["import", "barn", str(DATA / "world_0.world"), "--out", str(barn), "--scale", "1.5"]) == 0
    out = tmp_path / "out"
    assert main(["bench", str(barn), "--controllers", "astar-pp", "--workers", "1", "--out", str(out), "--quiet"]) == 0
    (row,) = [json.loads(line) for line in (out / "runs.jsonl").read_text().splitlines()]
    assert row["suite"] == "barn" and row["world"] == "world_0"
    assert row["outcome"] == "reached"
    optimal = json.loads((barn / "benchmark.json").read_text())["scenarios"]["world_0"]["barn_optimal_path_m"]
    assert row["barn_score"] == pytest.approx(barn_score(True, row["time_s"], optimal))
    assert 0.0 < row["barn_score"] <= 0.5


def test_barn_score_follows_run_py():
    assert barn_score(True, 3.0, 10.0) == pytest.approx(5.0 / 10.0)  # clipped below at 2 t_opt
    assert barn_score(True, 20.0, 10.0) == pytest.approx(5.0 / 20.0)
    assert barn_score(True, 90.0, 10.0) == pytest.approx(5.0 / 40.0)  # clipped above at 8 t_opt
    assert barn_score(False, 20.0, 10.0) == 0.0


@pytest.mark.parametrize("argv, field", [
    (["bench", "nowhere", "--controllers", "dwa"], "SUITE"),
    (["bench", "barn-1.5", "--controllers", "dwa"], "`fuzzynav import barn` writes a folder of BARN worlds"),
    (["bench", "mixd:3", "--controllers", "dwa"], "(did you mean mixed?)"),
    (["bench", "mixed:x", "--controllers", "dwa"], "COUNT"),
    (["bench", "mixed:2", "--controllers", "dwb"], "--controllers"),
    (["bench", "mixed:2", "--controllers", "missing.json"], "missing.json"),
    (["bench", "mixed:2", "--controllers", "dwa,dwa"], "repeat"),
    (["bench", "mixed:2", "mixed:2", "--controllers", "dwa"], "repeat"),
])
def test_bad_input_exits_2_naming_the_field(argv, field, capsys, tmp_path):
    assert main([*argv, "--out", str(tmp_path / "o")]) == 2
    assert field in capsys.readouterr().err


def test_index_page_has_html_tables_and_a_sentence_per_plot(reference):
    from html.parser import HTMLParser

    class Page(HTMLParser):
        def __init__(self):
            super().__init__()
            self.tags, self.cells, self.images, self.headings, self.text = [], [], [], [], []

        def handle_starttag(self, tag, attrs):
            self.tags.append(tag)
            if tag == "img":
                self.images.append(dict(attrs)["src"])

        def handle_data(self, data):
            self.text.append(data)
            if not data.strip():
                return
            if self.tags and self.tags[-1] in ("td", "th"):
                self.cells.append(data)
            if self.tags and self.tags[-1] == "h2":
                self.headings.append(data)

    page = Page()
    page.feed((reference / "index.html").read_text())
    assert "table" in page.tags and "pre" not in page.tags
    assert {"goal-seeking", "vfh", "success %", "collision %", "timeout %"} <= set(page.cells)
    assert page.images[:2] == ["rates.png", "path_ratio.png"]
    assert len(page.headings) == 1 + len(page.images)  # the tables' heading, then one per plot
    assert "|---|" not in "".join(page.text)  # no Markdown left in the page


def test_no_progress_bar_on_a_redirected_stderr(tmp_path, capsys):
    assert main(["bench", "circles:1", "--controllers", "goal-seeking", "--workers", "1", "--gallery", "0",
                 "--out", str(tmp_path / "o")]) == 0  # no --quiet: stderr is not a terminal here
    err = capsys.readouterr().err
    assert "run/s" not in err and "%|" not in err
