"""A cached kernel is never loaded against a changed callee: :func:`fuzzynav.jit.clear_stale_caches`
deletes the package's numba caches when a kernel source changed, and only then — beside the sources,
or under ``NUMBA_CACHE_DIR`` when it is set."""

import os
from functools import partial

from numba.core.caching import _CacheLocator

from fuzzynav import jit

IN_TREE = ""  # no NUMBA_CACHE_DIR: the caches beside the sources, whatever the environment running the tests


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
    jit.clear_stale_caches(package, IN_TREE)  # first check: writes the stamp
    caches = _cache(package)
    assert jit.clear_stale_caches(package, IN_TREE) is False
    _touch(package / "cli.py", 10**9)  # not a kernel source
    assert jit.clear_stale_caches(package, IN_TREE) is False
    assert all(cached.exists() for cached in caches)


def test_a_changed_callee_deletes_every_cached_kernel_once(tmp_path):
    package = _package(tmp_path)
    jit.clear_stale_caches(package, IN_TREE)
    caches = _cache(package)
    _touch(package / "kernels" / "callee.py", 10**9)
    assert jit.clear_stale_caches(package, IN_TREE) is True
    assert not any(cached.exists() for cached in caches)
    recompiled = _cache(package)
    assert jit.clear_stale_caches(package, IN_TREE) is False  # the new caches match the sources
    assert all(cached.exists() for cached in recompiled)


def test_a_package_it_cannot_write_to_is_left_alone(tmp_path, monkeypatch):
    package = _package(tmp_path)
    caches = _cache(package)

    def refuse(self, missing_ok=False):
        raise PermissionError(13, "Permission denied", str(self))

    monkeypatch.setattr(type(package), "unlink", refuse)  # a read-only install (tests may run as root)
    assert jit.clear_stale_caches(package, IN_TREE) is False
    assert all(cached.exists() for cached in caches)


def _external(package, cache_dir):
    """Cached kernels of ``package``'s kernels folder where numba puts them under ``cache_dir``."""
    folder = cache_dir / _CacheLocator.get_suitable_cache_subpath(str(package / "kernels" / "caller.py"))
    folder.mkdir(parents=True, exist_ok=True)
    caches = [folder / name for name in ("caller.f-1.py311.nbi", "caller.f-1.py311.1.nbc")]
    for cached in caches:
        cached.write_bytes(b"compiled")
    return caches


def test_caches_under_numba_cache_dir_are_checked_too(tmp_path):
    package, cache_dir = _package(tmp_path / "package"), tmp_path / "numba-cache"
    check = partial(jit.clear_stale_caches, package, str(cache_dir))
    check()  # first check of that cache folder: writes its stamp there
    caches, beside = _external(package, cache_dir), _cache(package)
    assert check() is False and all(cached.exists() for cached in caches)
    _touch(package / "kernels" / "callee.py", 10**9)
    assert check() is True
    assert not any(cached.exists() for cached in caches)
    assert all(cached.exists() for cached in beside)  # the in-tree caches are checked by their own stamp
    assert jit.clear_stale_caches(package, IN_TREE) is True
