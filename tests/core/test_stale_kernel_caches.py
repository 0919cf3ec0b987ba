"""A cached kernel is never loaded against a changed callee: :func:`fuzzynav.jit.clear_stale_caches`
deletes the package's numba caches when a kernel source changed, and only then — beside the sources,
or under ``NUMBA_CACHE_DIR`` when it is set."""

import os
import subprocess
import sys
from functools import partial
from pathlib import Path

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


LOOKED_AT = """
import inspect, sys
from pathlib import Path
from numba.core.caching import _CacheLocator
from fuzzynav import jit
from fuzzynav.kernels import car_search

cache_dir = Path(sys.argv[1])
numbas = cache_dir / _CacheLocator.get_suitable_cache_subpath(inspect.getfile(car_search.push.py_func))
numbas.mkdir(parents=True, exist_ok=True)  # where numba caches car_search's kernels, imported from where it was
print(numbas in jit._cache_places(jit.PACKAGE, str(cache_dir))[1])
"""


def test_under_numba_cache_dir_it_checks_the_folders_numba_names_for_a_package_reached_by_a_link(tmp_path):
    """numba names a folder under ``NUMBA_CACHE_DIR`` by the path its kernels' module was imported
    from, a symbolic link kept (``/tmp`` on macOS is ``/private/tmp``): the check looks there."""
    source = Path(jit.__file__).resolve().parents[1]  # the folder holding the package
    (tmp_path / "link").symlink_to(source, target_is_directory=True)
    env = {**os.environ, "PYTHONPATH": str(tmp_path / "link"), "NUMBA_CACHE_DIR": str(tmp_path / "cache")}
    done = subprocess.run([sys.executable, "-c", LOOKED_AT, str(tmp_path / "cache")], env=env, capture_output=True,
                          text=True, check=True)
    assert done.stdout.strip() == "True", done.stderr


def test_the_stamp_is_the_same_whichever_path_reaches_the_package(tmp_path):
    package = _package(tmp_path / "package")
    (tmp_path / "link").symlink_to(package, target_is_directory=True)
    jit.clear_stale_caches(package, IN_TREE)
    caches = _cache(package)
    assert jit.clear_stale_caches(tmp_path / "link", IN_TREE) is False  # the caches beside the sources: kept
    assert all(cached.exists() for cached in caches)


def test_a_numba_without_its_cache_locator_leaves_the_caches_to_numba(tmp_path, monkeypatch):
    """The folders under NUMBA_CACHE_DIR are named by a private class of numba's: should a later numba
    move it, importing fuzzynav must not fail."""
    import numba.core.caching

    package = _package(tmp_path / "package")
    monkeypatch.delattr(numba.core.caching, "_CacheLocator")
    assert jit.clear_stale_caches(package, str(tmp_path / "numba-cache")) is False
