"""A cached kernel is never loaded against a changed callee: :func:`fuzzynav.jit.clear_stale_caches`
deletes the package's numba caches when a kernel source changed, and only then."""

import os

from fuzzynav import jit


def _package(tmp_path):
    """A package with two kernel files (one calling the other), a plain file and cached kernels."""
    (tmp_path / "kernels" / "__pycache__").mkdir(parents=True)
    (tmp_path / "kernels" / "callee.py").write_text("from fuzzynav.jit import jit\n")
    (tmp_path / "kernels" / "caller.py").write_text("import numba\n")
    (tmp_path / "cli.py").write_text("print('no kernel here')\n")
    return tmp_path


def _cache(package):
    caches = [package / "kernels" / "__pycache__" / name for name in ("caller.f-1.py311.nbi", "caller.f-1.py311.1.nbc")]
    for cached in caches:
        cached.write_bytes(b"compiled")
    return caches


def _touch(path, later_ns):
    stat = path.stat()
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns + later_ns))


def test_caches_are_kept_while_the_kernel_sources_are_unchanged(tmp_path):
    package = _package(tmp_path)
    jit.clear_stale_caches(package)  # first check: writes the stamp
    caches = _cache(package)
    assert jit.clear_stale_caches(package) is False
    _touch(package / "cli.py", 10**9)  # not a kernel source
    assert jit.clear_stale_caches(package) is False
    assert all(cached.exists() for cached in caches)


def test_a_changed_callee_deletes_every_cached_kernel_once(tmp_path):
    package = _package(tmp_path)
    jit.clear_stale_caches(package)
    caches = _cache(package)
    _touch(package / "kernels" / "callee.py", 10**9)
    assert jit.clear_stale_caches(package) is True
    assert not any(cached.exists() for cached in caches)
    recompiled = _cache(package)
    assert jit.clear_stale_caches(package) is False  # the new caches match the sources
    assert all(cached.exists() for cached in recompiled)


def test_a_package_it_cannot_write_to_is_left_alone(tmp_path, monkeypatch):
    package = _package(tmp_path)
    caches = _cache(package)

    def refuse(self, missing_ok=False):
        raise PermissionError(13, "Permission denied", str(self))

    monkeypatch.setattr(type(package), "unlink", refuse)  # a read-only install (tests may run as root)
    assert jit.clear_stale_caches(package) is False
    assert all(cached.exists() for cached in caches)
