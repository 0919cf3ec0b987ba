"""``reproduce --out DIR`` writes DIR/<id>/ (numbers, claim.json with checks and verdict) and an
offline DIR/index.html: claim beside figure; experiments are specs that carry their claim."""

import json
from html.parser import HTMLParser
from pathlib import Path

import pytest

from fuzzynav.catalog import experiments as registry
from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.experiments.claims import NOT_REPRODUCED, PARTLY, REPRODUCED, Check, Claim, verdict_of
from fuzzynav.lookup import Registry


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


def claim_of(key):
    return registry.spec(key).claim


def test_every_experiment_carries_a_claim_and_a_thesis_reference():
    for key, spec in registry.specs().items():
        assert isinstance(spec.claim, Claim) and spec.claim.thesis and spec.claim.asserted, key
        assert spec.reference, key
        assert callable(spec.function()), key


def test_ids_list_in_the_thesis_order():
    ids = list(registry.available())
    assert ids.index("fig-V-7") < ids.index("fig-V-10") < ids.index("fig-V-34")
    assert ids.index("fig-IV-23") < ids.index("fig-V-7") < ids.index("fig-VI-1")
    assert ids.index("fig-VI-4") < ids.index("table-VI-1") < ids.index("fig-VI-8")
    assert ids.index("fig-VI-24") < ids.index("fig-VI-28") < ids.index("fig-VI-29")


def test_index_puts_each_claim_beside_its_figure_and_works_offline(tmp_path, capsys):
    assert main(["reproduce", "fig-V-7", "fig-VI-28", "--quick", "--out", str(tmp_path)]) == 0
    page, text = read_page(tmp_path)
    assert page.sections == ["fig-V-7", "fig-VI-28"]  # in the order of reproduce --list
    assert page.images and not page.external
    for src in page.images:
        assert (tmp_path / src).is_file(), src
    assert {src.split("/")[0] for src in page.images} == {"fig-V-7", "fig-VI-28"}
    assert claim_of("fig-VI-28").thesis in text and "reproduced" in text and "run time" in text
    record = json.loads((tmp_path / "fig-VI-28" / "run.json").read_text())
    assert record["verdict"] == REPRODUCED and record["quick"] and record["seconds"] > 0
    claim = json.loads((tmp_path / "fig-VI-28" / "claim.json").read_text())
    assert set(claim) >= {"thesis", "checks", "verdict"} and claim["verdict"] == REPRODUCED
    corner = next(c for c in claim["checks"] if c["name"] == "sharp corner (Fig VI.28)")
    assert corner == {"name": "sharp corner (Fig VI.28)", "value": "collision", "target": "collision", "pass": True,
                      "source": "thesis"}
    # a later run adds its section to the same page, in the thesis' order
    capsys.readouterr()
    assert main(["reproduce", "fig-IV-13", "--quick", "--out", str(tmp_path)]) == 0
    assert read_page(tmp_path)[0].sections == ["fig-IV-13", "fig-V-7", "fig-VI-28"]
    out, err = capsys.readouterr()
    assert "report:" in out
    # before the first result, which may take minutes, a line says what runs (no bar when piped)
    assert err.splitlines()[0] == f"reproducing 1 experiment into {tmp_path} (1 worker); a line as each one ends"


def test_a_claim_that_does_not_hold_is_reported_as_such():
    from fuzzynav.experiments.routes import reference

    def runs(bend, corner):  # the published routes, with these outcomes
        return {name: {"outcome": outcome, "route": reference(f"fig-VI-28/{name}")["route"]}
                for name, outcome in (("fig-VI-27", bend), ("fig-VI-27b", "reached"), ("fig-VI-28", corner))}

    verdict, checks = claim_of("fig-VI-28").evaluate(runs("reached", "reached"))
    assert verdict == PARTLY and [c.passed for c in checks] == [True, False, True, True, True, True]
    assert checks[1].value == "reached"
    verdict, checks = claim_of("fig-VI-28").evaluate(runs("collision", "reached"))
    assert verdict == PARTLY and [c.passed for c in checks][:2] == [False, False]
    verdict, checks = claim_of("fig-VI-28").evaluate({"fig-VI-27": {"outcome": "collision"},
                                                      "fig-VI-28": {"outcome": "reached"}})
    assert verdict == NOT_REPRODUCED
    verdict, checks = claim_of("fig-V-7").evaluate({})
    assert verdict == NOT_REPRODUCED and len(checks) == 1 and "missing" in checks[0].value


def test_the_verdict_counts_every_check():
    yes, no = Check("a", 1, "= 1", True), Check("b", 2, "= 1", False, "package")
    assert verdict_of([yes, yes]) == REPRODUCED
    assert verdict_of([yes, no]) == PARTLY  # a package target that fails is not hidden
    assert verdict_of([no]) == NOT_REPRODUCED and verdict_of([]) == NOT_REPRODUCED
    with pytest.raises(ValueError, match="source"):
        Check("c", 0, "= 0", True, "elsewhere")


def test_experiments_in_worker_processes_give_the_numbers_of_one_process(tmp_path, capsys):
    ids = ["fig-IV-13", "fig-V-7", "fig-VI-28"]
    for workers in ("1", "3"):
        assert main(["reproduce", *ids, "--quick", "--workers", workers, "--out", str(tmp_path / workers)]) == 0
    printed = capsys.readouterr().out
    for key in ids:
        for name in (f"{key}.json", "claim.json"):  # the same, but for the folder they name
            one, three = ((tmp_path / w / key / name).read_text().replace(str(tmp_path / w), "OUT") for w in ("1", "3"))
            assert one == three, (key, name)
        assert printed.count(f"{key}: reproduced (quick run)") == 2
    assert read_page(tmp_path / "3")[0].sections == ids


def test_an_experiment_from_outside_the_package_is_reproduced_with_its_claim(tmp_path, monkeypatch):
    """CONTRIBUTING's recipe: a function and its spec (with its claim) registered from outside."""
    def fig_ix_1(out_dir, quick=False, seed=0):
        return {"answer": 42 + seed}

    spec = registry.Experiment("fig-IX-1", fig_ix_1, "a figure of a chapter the thesis does not have", "§IX.1",
                               Claim("The answer is 42.", "The answer is 42.",
                                     lambda n: [Check("answer", n["answer"], "= 42", n["answer"] == 42)]))
    fresh = Registry("experiment", "ID", registry.Experiment, group="fuzzynav.experiments")
    monkeypatch.setattr(registry, "EXPERIMENTS", fresh)  # as in a fresh process: the plug-in registers first
    monkeypatch.setattr(registry, "_THESIS_MODULES", tuple(f"fuzzynav.experiments.claims_{c}" for c in ("iv", "v", "vi")))
    registry.register_experiment(spec)
    with pytest.raises(ValueError, match="already registered"):
        registry.register_experiment(spec)
    assert list(registry.available())[-1] == "fig-IX-1" and "fig-IV-12" in registry.available()
    assert main(["reproduce", "fig-IX-1", "--out", str(tmp_path)]) == 0
    assert json.loads((tmp_path / "fig-IX-1" / "claim.json").read_text())["verdict"] == REPRODUCED
    assert main(["reproduce", "fig-IX-1", "--seed", "1", "--out", str(tmp_path)]) == 0
    assert json.loads((tmp_path / "fig-IX-1" / "claim.json").read_text())["verdict"] == NOT_REPRODUCED
    assert "fig-IX-1" in read_page(tmp_path)[0].sections


def test_workers_start_the_experiments_an_earlier_run_found_longest_first(tmp_path, monkeypatch):
    from fuzzynav.bench import backends

    ids = ["fig-IV-13", "fig-V-7", "fig-VI-28"]
    assert main(["reproduce", *ids, "--quick", "--workers", "1", "--out", str(tmp_path)]) == 0
    for key, seconds in zip(ids, (1.0, 100.0, 50.0)):
        path = tmp_path / key / "run.json"
        path.write_text(json.dumps({**json.loads(path.read_text()), "seconds": seconds}))
    started = []

    def one_by_one(task, items, workers, on_result, **options):
        started.extend(item[0] for item in items)
        for index, item in enumerate(items):
            on_result(index, task(item))

    monkeypatch.setattr(backends, "pool_map", one_by_one)
    assert main(["reproduce", *ids, "fig-IV-12", "--quick", "--workers", "2", "--out", str(tmp_path)]) == 0
    assert started == ["fig-IV-12", "fig-V-7", "fig-VI-28", "fig-IV-13"]  # never run here: first
    started.clear()  # the quick runs' times do not order a full run
    assert main(["reproduce", *ids, "--workers", "2", "--out", str(tmp_path)]) == 0
    assert started == ids


def test_an_experiment_registered_at_run_time_in_workers_started_afresh_is_a_clear_error(tmp_path, monkeypatch,
                                                                                          capsys):
    """Spawned workers (macOS, Windows; simulated here) know the thesis' experiments, not those a
    script registered before calling the command: that is said, with the way out."""
    from fuzzynav.bench import backends

    fresh = Registry("experiment", "ID", registry.Experiment, group="fuzzynav.experiments")
    monkeypatch.setattr(registry, "EXPERIMENTS", fresh)
    for key in ("fig-IX-3", "fig-IX-4"):
        registry.register_experiment(registry.Experiment(
            key, "tests.catalog.plugin_figure:fig_ix_2", "registered by a script", "§IX.3",
            Claim("The answer is 42.", "The answer is 42.",
                  lambda n: [Check("answer", n["answer"], "= 42", n["answer"] == 42)])))
    monkeypatch.setattr(backends, "FORKED", False)
    assert main(["reproduce", "fig-IX-3", "fig-IX-4", "--workers", "2", "--out", str(tmp_path)]) == 2
    error = capsys.readouterr().err
    assert "unknown experiment 'fig-IX-" in error and "--workers 1" in error and "Traceback" not in error
    assert main(["reproduce", "fig-IX-3", "--workers", "1", "--out", str(tmp_path)]) == 0


def test_an_experiment_from_an_installed_distribution(tmp_path, monkeypatch):
    """The same from another distribution: its module and one entry point line, nothing of fuzzynav edited."""
    from tests.catalog.plugins import installed

    registry.specs()  # the thesis' own first, as any first use registers them
    with installed(monkeypatch, tmp_path / "site", registry.EXPERIMENTS,
                   {"figures": "tests.catalog.plugin_figure:EXPERIMENTS"}):
        assert "fig-IX-2" in registry.available()
        for seed, verdict in (("0", REPRODUCED), ("1", NOT_REPRODUCED)):  # its claim checks its numbers
            assert main(["reproduce", "fig-IX-2", "--seed", seed, "--out", str(tmp_path / "out")]) == 0
            assert json.loads((tmp_path / "out" / "fig-IX-2" / "claim.json").read_text())["verdict"] == verdict
    assert "fig-IX-2" not in registry.available()
    with pytest.raises(InputError, match="'fig-IV-12' is already registered"):
        with installed(monkeypatch, tmp_path / "clash", registry.EXPERIMENTS, {"twin": "clashing_figure:EXPERIMENT"}):
            (tmp_path / "clash" / "clashing_figure.py").write_text(
                "from dataclasses import replace\nfrom fuzzynav.catalog.experiments import spec\n"
                "EXPERIMENT = replace(spec('fig-IV-12'), run='tests.catalog.plugin_figure:fig_ix_2')\n")
            registry.spec("fig-IV-12")


def test_an_experiment_id_must_name_its_chapter():
    with pytest.raises(ValueError, match="kind-CHAPTER"):
        registry.Experiment("figure 3", "m:f", "", "", claim_of("fig-V-7"))


def test_reproduce_list_counts_the_experiments(capsys):
    assert main(["reproduce", "--list"]) == 0
    assert capsys.readouterr().out.splitlines()[-1] == f"{len(registry.available())} figures and tables"


def test_reproduce_without_ids_lists_them_and_says_nothing_ran(capsys, tmp_path):
    assert main(["reproduce", "--out", str(tmp_path / "f")]) == 2  # a usage error, after the list to choose from
    out, err = capsys.readouterr()
    assert out.splitlines()[-1] == f"{len(registry.available())} figures and tables"
    assert err.startswith("nothing run: name the ids to reproduce")
    assert not (tmp_path / "f").exists()


def test_an_id_named_twice_runs_once(tmp_path, capsys):
    assert main(["reproduce", "fig-IV-13", "fig-IV-13", "--quick", "--out", str(tmp_path)]) == 0
    assert capsys.readouterr().out.count("fig-IV-13:") == 1


def test_reproduce_refuses_a_folder_holding_another_commands_report(tmp_path, capsys):
    from fuzzynav.cli import main

    (tmp_path / "index.html").write_text("<html>a campaign's report</html>")
    assert main(["reproduce", "fig-V-7", "--quick", "--quiet", "--out", str(tmp_path)]) == 2
    assert "not a reproduction's folder" in capsys.readouterr().err
    assert (tmp_path / "index.html").read_text() == "<html>a campaign's report</html>"
    assert main(["reproduce", "fig-V-7", "--quick", "--quiet", "--out", str(tmp_path / "r")]) == 0
    assert main(["reproduce", "fig-V-7", "--quick", "--quiet", "--out", str(tmp_path / "r")]) == 0  # its own, again
