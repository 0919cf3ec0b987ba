"""More hostile inputs for the readers: a closed standard input, deeply nested JSON in the files a
command reads back, model files that cannot be read or are not what their kind says (an ``.npz``
archive whose ``version`` or ``format`` is an array of several values or none), special
files named as model or scenario files, options a command would silently ignore, C
file names an #include cannot hold, a model's training record out of range.

The cases of :data:`CASES` run as those of ``cases.py`` do (``test_hostile_corpus.py``); the
others need a process of their own or files a case cannot write (a named pipe, a loop of links)."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from fuzzynav.cli import main
from tests.validation.hostile_cases import Case

from .test_hostile_corpus import test_hostile_case as run_case

NESTED = "'[' * 100000 + ']' * 100000"  # Python text: JSON nested far deeper than json's recursion reaches

FQL = ["fql-goal", "--episodes", "2", "--quiet"]  # a model of a fuzzy rule base with its training record
FIS_COMMANDS = (("show",), ("eval", "--input", "drg=1", "--input", "theta=0"), ("convert", "--to", "json"))

CASES = [
    Case("import-barn-reference-file-nested",
         python="(d / 'o').mkdir(); (d / 'o' / 'benchmark.json').write_text('{\"scenarios\": ' + " + NESTED + " + '}')\n"
                "import_barn(d, barn_world(d, 'world_0'))", expect="benchmark.json: nested deeper than 64 levels"),
    Case("import-barn-reference-file-too-large",
         python="(d / 'o').mkdir(); (d / 'o' / 'benchmark.json').write_text(' ' * (9 * 2**20) + '{}')\n"
                "import_barn(d, barn_world(d, 'world_0'))", expect="benchmark.json: file larger than the 8 MiB limit"),
    Case("campaign-line-nested",
         python="campaign(d, lambda out: open(out / 'runs.jsonl', 'a').write(" + NESTED + " + '\\n'))",
         expect="runs.jsonl: line 2: nested deeper than 64 levels"),
    Case("campaign-line-nested-100",
         python="campaign(d, lambda out: open(out / 'runs.jsonl', 'a').write('[' * 100 + ']' * 100 + '\\n'))",
         expect="runs.jsonl: line 2: nested deeper than 64 levels"),
    Case("tune-checkpoint-options-nested",
         python="tuned_then_resumed(d, lambda a: a.update(options=np.array(" + NESTED + ")))",
         expect="a.yaml.tune.npz: options: nested deeper than 64 levels"),
    Case("tune-checkpoint-options-not-json",
         python="tuned_then_resumed(d, lambda a: a.update(options=np.array('{')))",
         expect="a.yaml.tune.npz: options: invalid JSON"),
    *[Case(f"fis-{argv[0]}-npz-of-objects",
           python="np.savez(d / 'p.npz', kind=np.array('q-goal'), document=np.array([{}], dtype=object))\n"
                  f"from fuzzynav.cli import main\nraise SystemExit(main(['fis', {argv[0]!r}, str(d / 'p.npz'), *{argv[1:]!r}]))",
           expect="p.npz: cannot read model file: its array document.npy holds Python objects")
      for argv in FIS_COMMANDS],
    *[Case(f"fis-{argv[0]}-npz-of-random-bytes", {"junk.npz": bytes(range(255, 155, -1))},
           ("fis", argv[0], "{d}/junk.npz", *argv[1:]),
           expect="junk.npz: cannot read model file: neither an .npz archive (no zip header) nor a valid JSON")
      for argv in FIS_COMMANDS],
    *[Case(f"fis-{argv[0]}-npz-{field}-of-{label}",  # `!=` of an array: "truth value ... ambiguous", a traceback
           python=f"np.savez(d / 'p.npz', kind=np.array('fql-goal'), {field}=np.array({value}))\n"
                  f"from fuzzynav.cli import main\nraise SystemExit(main(['fis', {argv[0]!r}, str(d / 'p.npz'), *{argv[1:]!r}]))",
           expect=f"p.npz: {field}: {problem}")
      for argv in FIS_COMMANDS
      for field, label, value, problem in (("version", "two-values", "[1, 1]", "unsupported version array([1, 1])"),
                                           ("format", "no-value", "[]", "format must be 'fuzzynav-fis', got array([]"))],
    Case("fis-show-npz-missing", argv=("fis", "show", "{d}/nothere.npz"), expect="nothere.npz: no such model file"),
    *[Case(f"run-model-q-goal-relabelled-{kind}",
           python=f"edited_model(d, ['q-goal', '--episodes', '2', '--quiet'], lambda doc: doc.update(kind={kind!r}), "
                  "['run', 'fig-IV-23', '--max-time', '1', '--model'])",
           expect=f"x.json: inputs: missing (a {kind!r} model holds a fuzzy system)")
      for kind in ("fql-goal", "fql-avoid", "fql-wall")],
    Case("reproduce-fis-a-model-file", {"an.json": '{"kind": "anfis-tracker"}'},
         ("reproduce", "fig-V-7", "--quick", "--out", "{d}/r", "--fis", "tracker={d}/an.json"),
         expect="an.json: kind: a 'anfis-tracker' model file, not a fuzzy system (`fuzzynav run --model` runs it)"),
    Case("fis-plot-output-variable-without-surface",
         argv=("fis", "plot", "goal-seeking", "--output-variable", "nope", "-o", "{d}/p.png"),
         expect="--output-variable: chooses the output --surface draws: give --surface too"),
    Case("run-size-without-animate", argv=("run", "fig-IV-12a", "--size", "300", "--fps", "5"),
         expect="--size: sets the --animate GIF: give --animate FILE.gif too"),
    Case("run-fps-without-animate", argv=("run", "fig-IV-12a", "--fps", "5"),
         expect="--fps: sets the --animate GIF: give --animate FILE.gif too"),
    Case("reproduce-list-with-an-id", argv=("reproduce", "--list", "fig-V-28"),  # listed all, ran nothing, said nothing
         expect="--list: lists the experiments and runs none: give the ids without --list"),
    Case("scenarios-show-empty", argv=("scenarios", "--show", ""), expect="--show: no built-in scenario ''"),
    Case("scenarios-show-twice", argv=("scenarios", "--show", "fig-IV-12a", "--show", "fig-IV-15a"),
         expect="--show: is given 2 times: it prints the YAML of one scenario"),
    *[Case(f"fis-export-c-name-with-{what}", argv=("fis", "export-c", "goal-seeking", "-o", "{d}/q" + mark + "x.c"),
           expect="holds a quote, a backslash or a line break, which #include \"...\" cannot hold")
      for what, mark in (("quote", '"'), ("backslash", "\\"), ("line-break", "\n"))],
    Case("fis-show-rules-changed-negative",
         python=f"edited_model(d, {FQL}, lambda doc: doc['training'].update(rules_changed=-5), ['fis', 'show'])",
         expect="x.json: training.rules_changed: must be an integer in [0, 15], got -5"),
    *[Case(f"{run[0]}-training-not-a-mapping",
           python=f"edited_model(d, {FQL}, lambda doc: doc.update(training='x'), {run!r})",
           expect="x.json: training: must be a mapping, got str")
      for run in (["fis", "show"], ["run", "fig-IV-23", "--max-time", "1", "--model"])],
]


@pytest.mark.parametrize("case", CASES, ids=[case.name for case in CASES])
def test_more_hostile_case(case, tmp_path, capsys):
    run_case(case, tmp_path, capsys)


@pytest.mark.skipif(sys.platform == "win32", reason="a child started without a standard input: POSIX fds")
def test_a_csv_read_from_a_closed_standard_input_says_so():
    # ``fuzzynav fis eval goal-seeking --csv - <&-``: Python makes sys.stdin None
    process = subprocess.run([sys.executable, "-m", "fuzzynav", "fis", "eval", "goal-seeking", "--csv", "-"],
                             capture_output=True, preexec_fn=lambda: os.close(0), timeout=120)
    assert process.returncode == 2, process.stderr
    assert process.stderr.decode().strip() == "fuzzynav fis eval: error: -: cannot read file (standard input is closed)"


SPECIAL_FILES = {"named pipe": (os.mkfifo, "is a named pipe, not a regular file"),
                 "symbolic link loop": (lambda path: os.symlink(path.name, path), "Too many levels of symbolic links")}


@pytest.mark.skipif(sys.platform == "win32", reason="named pipes and symbolic links: POSIX")
@pytest.mark.parametrize("special", SPECIAL_FILES)
@pytest.mark.parametrize("name, argv", [("f.json", ("run", "fig-IV-23", "--model", "{f}")), ("f.yaml", ("run", "{f}")),
                                        ("f.json", ("bench", "circles:1", "--controllers", "{f}", "--out", "{d}/o"))])
def test_a_special_file_named_as_a_model_or_scenario_is_refused_by_what_it_is(name, argv, special, tmp_path, capsys):
    make, message = SPECIAL_FILES[special]
    make(tmp_path / name)
    assert main([arg.replace("{f}", str(tmp_path / name)).replace("{d}", str(tmp_path)) for arg in argv]) == 2
    assert message in capsys.readouterr().err
