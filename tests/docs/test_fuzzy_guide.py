"""The fuzzy library's guide (docs/guide/fuzzy.md) runs as printed: its Python examples, then its
``fis`` commands on the file the example wrote (a system of one's own, shown and exported to C)."""

import re
import subprocess
import sys
from pathlib import Path

from fuzzynav.cli import main

PAGE = Path(__file__).resolve().parents[2] / "docs" / "guide" / "fuzzy.md"


def test_the_guide_examples_run_as_printed(tmp_path, monkeypatch, capsys):
    text = PAGE.read_text(encoding="utf-8")
    examples = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(examples) == 2
    runs = [subprocess.run([sys.executable, "-c", example], cwd=tmp_path, capture_output=True, text=True, timeout=300)
            for example in examples]
    assert all(run.returncode == 0 for run in runs), [run.stderr for run in runs]
    assert runs[1].stdout.strip() == "(0.14492753623188406, 1.5)"  # the comment says (0.145, 1.5)
    assert "(α, V) = (0.145, 1.5)" in examples[1]
    monkeypatch.chdir(tmp_path)
    assert main(["fis", "show", "mine.fll"]) == 0 and "alpha" in capsys.readouterr().out
    assert "fuzzynav fis export-c mine.fll -o mine.c" in text
    assert main(["fis", "export-c", "mine.fll", "-o", "mine.c"]) == 0
    assert capsys.readouterr().out.strip() == "wrote mine.c and mine.h"
    assert "float" in (tmp_path / "mine.h").read_text() or "double" in (tmp_path / "mine.h").read_text()
