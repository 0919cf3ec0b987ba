"""The reproduction report: ``DIR/index.html``, the thesis' claim beside our figure, per experiment.

``fuzzynav reproduce ID… --out DIR`` runs each experiment in its own folder ``DIR/<id>/`` (its
figures, ``<id>.json`` with the numbers it measured) and records the run (:func:`record_run`):
``DIR/<id>/claim.json`` — the thesis' claim, its checks (``name``, ``value``, ``target``,
``pass``, ``source``) and the verdict of its :class:`~fuzzynav.experiments.claims.Claim`
(``reproduced``, ``partly`` or ``not reproduced``) — and ``DIR/<id>/run.json`` (seconds, quick or
full, seed, verdict). :func:`write_index` then writes one self-contained page over every
experiment recorded in DIR (runs of earlier commands included), in the thesis' order, with the
thesis' checks and this package's own targets apart: no script, no style sheet or font from the
network — it opens offline from the folder.
"""

from __future__ import annotations

import html
import json
from datetime import UTC, datetime
from pathlib import Path

from fuzzynav import validation
from fuzzynav.catalog import experiments as registry
from fuzzynav.errors import InputError
from fuzzynav.experiments.claims import REPRODUCED, SOURCES
from fuzzynav.settings import flag
from fuzzynav.storage import write_text_atomic

RUN_FILE, CLAIM_FILE = "run.json", "claim.json"
VERDICT_CLASS = {"reproduced": "pass", "partly": "partly", "not reproduced": "fail"}
STYLE = """
body { font-family: sans-serif; max-width: 1500px; margin: 1em auto; padding: 0 1em; color: #222; }
section { border-top: 1px solid #bbb; padding: 0.6em 0 1em; }
.claims { display: grid; grid-template-columns: 1fr 1fr; gap: 0.5em 2em; }
.claims h3 { font-size: 0.95em; margin: 0.3em 0; color: #555; }
.pass { color: #16702a; font-weight: bold; } .fail { color: #b3261e; font-weight: bold; }
.partly { color: #9a6700; font-weight: bold; }
img { max-width: 100%; border: 1px solid #ddd; margin-top: 0.6em; }
table { border-collapse: collapse; } td, th { padding: 0.2em 0.7em; text-align: left; }
pre { background: #f5f5f5; padding: 0.5em; overflow-x: auto; font-size: 0.85em; }
"""


def not_anothers(out_dir: Path) -> None:
    """Refuse a folder that holds an ``index.html`` but no experiment's ``run.json``: another
    command's report (a campaign's), which this one's index would overwrite."""
    if (out_dir / "index.html").exists() and not any(out_dir.glob(f"*/{RUN_FILE}")):
        raise InputError(f"holds an index.html but no experiment's {RUN_FILE}: it is not a reproduction's folder, "
                         "and the report would overwrite it; choose another --out", source=str(out_dir), field="--out")


def experiment_dir(out_dir: Path, key: str) -> Path:
    """The folder of experiment ``key`` inside the report folder."""
    return Path(out_dir) / key


def record_run(out_dir: Path, key: str, numbers: dict, seconds: float, *, quick: bool, seed: int) -> dict:
    """Write ``<id>.json`` (the numbers), ``claim.json`` (claim, checks, verdict) and ``run.json``
    (time, setting, verdict); returns the run record."""
    folder = experiment_dir(out_dir, key)
    folder.mkdir(parents=True, exist_ok=True)
    write_text_atomic(folder / f"{key}.json", json.dumps(numbers, indent=2, default=float))
    spec = registry.spec(key)
    verdict, checks = spec.claim.evaluate(numbers)
    claim = {"id": key, "reference": spec.reference, "thesis": spec.claim.thesis, "asserted": spec.claim.asserted,
             "checks": [check.as_json() for check in checks], "verdict": verdict}
    write_text_atomic(folder / CLAIM_FILE, json.dumps(claim, indent=2, default=float, ensure_ascii=False))
    record = {"id": key, "seconds": round(seconds, 2), "quick": quick, "seed": seed, "verdict": verdict,
              "finished": datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC")}
    write_text_atomic(folder / RUN_FILE, json.dumps(record, indent=2))
    return record


def _value(value) -> str:
    return f"{value:.4g}" if isinstance(value, float) else json.dumps(value, default=float, ensure_ascii=False)


def _checks_table(checks: list[dict], source: str) -> str:
    rows = [c for c in checks if c["source"] == source]
    if not rows:
        return ""
    e = html.escape
    title = "The thesis' claim, checked" if source == "thesis" else "This package's own targets (not in the thesis)"
    body = "".join(f'<tr><td>{e(c["name"])}</td><td>{e(_value(c["value"]))}</td><td>{e(c["target"])}</td>'
                   f'<td class="{"pass" if c["pass"] else "fail"}">{"pass" if c["pass"] else "fail"}</td></tr>'
                   for c in rows)
    return (f"<h3>{title}</h3><table><tr><th>check</th><th>measured</th><th>target</th><th></th></tr>"
            f"{body}</table>")


def _required(document: dict, fields, source: str, where: str = "") -> None:
    """An InputError naming the first of ``fields`` that ``document`` lacks."""
    for field in fields:
        if field not in document:
            validation.fail("missing", source, f"{where}{field}")


def _read_json(path: Path, source: str):
    """The JSON document of the file ``path``, bounded; errors name it ``source``."""
    return validation.parse_json(validation.read_text(path, source=source), source)


def _read_record(out_dir: Path, key: str) -> tuple[dict, dict, str]:
    """The run record, the claim and the numbers' text of experiment ``key``, checked to be what
    :func:`record_run` writes (the fields the page shows); otherwise an InputError naming the file
    (relative to ``out_dir``, where the page is)."""
    folder = experiment_dir(out_dir, key)
    source = f"{key}/{RUN_FILE}"
    record = validation.mapping(_read_json(folder / RUN_FILE, source), source)
    _required(record, ("verdict", "seconds", "quick", "seed", "finished"), source)
    validation.choice(record["verdict"], list(VERDICT_CLASS), source, "verdict")
    validation.number(record["seconds"], source, "seconds", lo=0)
    flag(record["quick"], "quick", source)
    validation.seed(record["seed"], source, "seed")
    validation.text(record["finished"], source, "finished")
    source = f"{key}/{CLAIM_FILE}"
    claim = validation.mapping(_read_json(folder / CLAIM_FILE, source), source)
    _required(claim, ("verdict", "reference", "thesis", "asserted", "checks"), source)
    validation.choice(claim["verdict"], list(VERDICT_CLASS), source, "verdict")
    for field in ("reference", "thesis", "asserted"):
        validation.text(claim[field], source, field)
    for i, check in enumerate(validation.sequence(claim["checks"], source, "checks")):
        where = f"checks[{i}]"
        validation.mapping(check, source, where)
        _required(check, ("name", "value", "target", "pass", "source"), source, f"{where}.")
        validation.text(check["name"], source, f"{where}.name")
        validation.text(check["target"], source, f"{where}.target")
        flag(check["pass"], f"{where}.pass", source)
        validation.choice(check["source"], SOURCES, source, f"{where}.source")
    numbers = validation.read_text(folder / f"{key}.json", max_bytes=validation.MAX_MODEL_BYTES,
                                   source=f"{key}/{key}.json")
    return record, claim, numbers


def recorded_seconds(out_dir: Path, key: str, *, quick: bool) -> float | None:
    """The run time a readable earlier run of ``key`` recorded in ``out_dir`` with the same
    ``quick`` setting, else None (``reproduce`` starts the longest first)."""
    try:
        record = _read_record(out_dir, key)[0]
    except InputError:
        return None
    return float(record["seconds"]) if record["quick"] == quick else None


def _section(key: str, record: dict, claim: dict, numbers: str, description: str, folder: Path) -> str:
    verdict = claim["verdict"]
    status = f'<span class="{VERDICT_CLASS[verdict]}">{html.escape(verdict)}</span>'
    setting = "quick run (short budgets)" if record["quick"] else "full run"
    images = "".join(f'<img src="{html.escape(f"{key}/{image.name}")}" alt="{html.escape(key)}: our figure">'
                     for image in sorted(folder.glob("*.png")))
    e = html.escape
    return f"""<section id="{e(key)}">
<h2>{e(key)} — {e(description)}</h2>
<div class="claims">
<div><h3>The thesis ({e(claim["reference"])})</h3><p>{e(claim["thesis"])}</p></div>
<div><h3>Verdict: {status}</h3><p>{e(claim["asserted"])}</p></div>
</div>
{_checks_table(claim["checks"], "thesis")}
{_checks_table(claim["checks"], "package")}
<p>{e(setting)}, seed {record["seed"]}, run time {record["seconds"]:.1f} s (finished {e(record["finished"])})</p>
{images}
<details><summary>all numbers ({e(key)}/{e(key)}.json)</summary><pre>{e(numbers)}</pre></details>
</section>"""


def _row(key: str, record: dict | None) -> str:
    """The summary table's row of ``key`` (``record`` None: an unreadable record)."""
    e = html.escape
    if record is None:
        return f'<tr><td><a href="#{e(key)}">{e(key)}</a></td><td class="fail">unreadable</td><td></td><td></td></tr>'
    return (f'<tr><td><a href="#{e(key)}">{e(key)}</a></td>'
            f'<td class="{VERDICT_CLASS[record["verdict"]]}">{e(record["verdict"])}</td>'
            f'<td>{record["seconds"]:.1f} s</td><td>{"quick" if record["quick"] else "full"}</td></tr>')


def _unreadable_section(key: str, error: InputError, description: str) -> str:
    e = html.escape
    return f"""<section id="{e(key)}">
<h2>{e(key)} — {e(description)}</h2>
<p><span class="fail">unreadable record</span>: {e(str(error))} (run <code>fuzzynav reproduce {e(key)}</code>
again to replace it)</p>
</section>"""


def write_index(out_dir: Path) -> Path:
    """Write ``out_dir/index.html`` over every experiment recorded in ``out_dir``; returns its path.

    An experiment whose ``run.json``, ``claim.json`` or numbers cannot be read or are not what
    :func:`record_run` writes (a run cut short, a file edited by hand) is listed as unreadable,
    with the file and the problem, instead of stopping the page."""
    out_dir = Path(out_dir)
    listing = registry.available()
    records: dict[str, tuple[dict, dict, str]] = {}
    unreadable: dict[str, InputError] = {}
    for key in listing:
        folder = experiment_dir(out_dir, key)
        if (folder / RUN_FILE).is_file() and (folder / CLAIM_FILE).is_file():
            try:
                records[key] = _read_record(out_dir, key)
            except InputError as error:
                unreadable[key] = error
    held = sum(r["verdict"] == REPRODUCED for r, _, _ in records.values())
    rows = "".join(_row(key, records[key][0] if key in records else None) for key in listing
                   if key in records or key in unreadable)
    sections = "\n".join(
        _section(key, *records[key], listing[key], experiment_dir(out_dir, key)) if key in records else
        _unreadable_section(key, unreadable[key], listing[key])
        for key in listing if key in records or key in unreadable)
    found = f"{len(records) + len(unreadable)} of {len(listing)} experiments in this folder" + (
        f" ({len(unreadable)} unreadable)" if unreadable else "")
    page = f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>fuzzynav — reproduction of the thesis</title>
<style>{STYLE}</style></head><body>
<h1>Reproduction of the thesis' figures and tables</h1>
<p>L. Cherroun, <i>Navigation autonome d'un robot mobile par des techniques neuro-floues</i> (doctoral thesis,
Université de Biskra, 2014). Each section puts the thesis' claim (translated) beside the figure and the numbers
of this run, checks the claim on those numbers and gives the verdict: reproduced (every check passes), partly or
not reproduced. Checks of this package's own targets (numbers the thesis does not give) are listed apart.
{found}; reproduced: {held} of {len(records)}; their run times add up to
{sum(r["seconds"] for r, _, _ in records.values()):.0f} s (run side by side in worker processes, a command takes
less).</p>
<table><tr><th>experiment</th><th>verdict</th><th>run time</th><th>setting</th></tr>{rows}</table>
{sections}
</body></html>
"""
    path = out_dir / "index.html"
    write_text_atomic(path, page)
    return path
