"""A fake installed distribution for the plug-in tests: a ``*.dist-info`` directory on ``sys.path``
whose ``entry_points.txt`` names objects under fuzzynav's entry point groups, as ``pip install``
of a package declaring ``[project.entry-points."fuzzynav.controllers"]`` would leave it."""

from __future__ import annotations

import contextlib


@contextlib.contextmanager
def installed(monkeypatch, tmp_path, registry, entries: dict[str, str]):
    """Within the block, a distribution ``fuzzynav-plugin-test`` declares ``entries``
    (name -> ``"module:object"``) under ``registry``'s group, and ``registry`` has read it."""
    info = tmp_path / "fuzzynav_plugin_test-1.0.dist-info"
    info.mkdir(parents=True)
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: fuzzynav-plugin-test\nVersion: 1.0\n")
    lines = "".join(f"{name} = {target}\n" for name, target in entries.items())
    (info / "entry_points.txt").write_text(f"[{registry.group}]\n{lines}")
    monkeypatch.syspath_prepend(str(tmp_path))
    before = set(registry)
    monkeypatch.setattr(registry, "_plugins_read", False)  # read the entry points again, now
    try:
        yield
    finally:
        for name in set(registry) - before:
            registry.unregister(name)
