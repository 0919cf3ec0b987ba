"""Batches spread over threads: every item once, errors raised, one pool per process."""

import os
import threading
import time

import pytest

from fuzzynav import threads


@pytest.fixture(autouse=True)
def _restore():
    yield
    threads.set_count(None)


@pytest.mark.parametrize("count,items", [(1, 10), (3, 10), (4, 2), (2, 0), (3, 1000)])
def test_every_item_is_run_once(count, items):
    threads.set_count(count)
    seen, lock = [], threading.Lock()

    def task(start, stop):
        with lock:
            seen.extend(range(start, stop))

    threads.spread(task, items)
    assert sorted(seen) == list(range(items))


def test_chunks_run_on_several_threads_and_one_thread_runs_here():
    names, lock, here = set(), threading.Lock(), threading.current_thread().name
    barrier = threading.Barrier(2, timeout=10)  # the first two chunks must run at once to pass it
    calls = []

    def task(start, stop):
        with lock:
            names.add(threading.current_thread().name)
            calls.append(start)
            first_two = len(calls) <= 2
        if first_two and stop - start < 64:
            barrier.wait()

    threads.set_count(2)
    threads.spread(task, 64)
    assert len(names) == 2 and here not in names
    names.clear()
    threads.set_count(1)
    threads.spread(task, 1)  # one chunk: no barrier, run in this thread
    assert names == {here}


def test_an_error_of_a_chunk_is_raised_after_every_chunk_has_ended():
    threads.set_count(2)
    ended = []

    def task(start, stop):
        if start == 0:
            raise RuntimeError("chunk 0")
        ended.append(start)

    with pytest.raises(RuntimeError, match="chunk 0"):
        threads.spread(task, 16)
    assert len(ended) == 15


def test_a_count_below_one_is_refused():
    with pytest.raises(ValueError, match="at least 1"):
        threads.set_count(0)


@pytest.mark.skipif(not hasattr(os, "fork"), reason="only where processes fork")
def test_a_fork_copies_no_thread_of_the_pool_and_both_sides_spread_again():
    import multiprocessing

    threads.set_count(2)
    threads.spread(lambda start, stop: None, 8)  # the pool's threads are running
    assert any(t.name.startswith("fuzzynav") for t in threading.enumerate())
    with multiprocessing.get_context("fork").Pool(1) as pool:  # the fork joins them first
        assert pool.apply_async(_spread_in_a_child).get(timeout=60) == list(range(40))  # a copied pool: a hang
    threads.spread(lambda start, stop: None, 8)  # and the parent makes a new pool


def _spread_in_a_child() -> list[int]:
    seen, lock = [], threading.Lock()

    def task(start, stop):
        with lock:
            seen.extend(range(start, stop))

    threads.set_count(2)
    threads.spread(task, 40)
    return sorted(seen)


def _worker_view(_):
    import signal

    return threads.count(), signal.getsignal(signal.SIGINT) is signal.SIG_IGN, signal.getsignal(signal.SIGTERM)


def test_pool_workers_run_their_batches_on_one_thread_and_leave_ctrl_c_to_the_command():
    import signal

    from fuzzynav.bench.backends import pool_map

    seen = {}
    pool_map(_worker_view, range(4), 2, seen.__setitem__)
    assert set(seen.values()) == {(1, True, signal.SIG_DFL)}


def test_at_most_count_chunks_run_at_once_whatever_the_pool_once_grew_to():
    running, peak, lock = [0], [0], threading.Lock()

    def task(start, stop):
        with lock:
            running[0] += 1
            peak[0] = max(peak[0], running[0])
        threading.Event().wait(0.002)
        with lock:
            running[0] -= 1

    threads.set_count(6)
    threads.spread(task, 60)  # a pool of six
    peak[0] = 0
    with threads.using(2):
        threads.spread(task, 60)
    assert peak[0] == 2 and threads.count() == 6  # using() gave the count back


def test_a_spread_inside_a_chunk_runs_there_and_mixed_errors_come_as_a_group():
    threads.set_count(2)
    seen, lock = [], threading.Lock()

    def inner(start, stop):
        with lock:
            seen.append(threading.current_thread().name)

    threads.spread(lambda start, stop: threads.spread(inner, 4), 4)  # no deadlock: inline in the pool threads
    assert seen and all(name.startswith("fuzzynav") for name in seen)

    def task(start, stop):
        raise (ValueError if start == 0 else KeyError)(start)

    with pytest.raises(ExceptionGroup) as group:
        threads.spread(task, 4)
    assert {type(e) for e in group.value.exceptions} == {ValueError, KeyError}


def _cgroup(tmp_path, membership, files):
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
    (tmp_path / "self-cgroup").write_text(membership)
    return {"root": tmp_path / "fs", "membership": tmp_path / "self-cgroup"}


@pytest.mark.parametrize("membership,files,quota", [
    ("0::/ci/job\n", {"fs/ci/job/cpu.max": "150000 100000\n"}, 1.5),  # v2, the process' own group
    ("0::/\n", {"fs/cpu.max": "200000 100000\n"}, 2.0),  # v2 in a container: its root
    ("0::/ci/job\n", {"fs/ci/job/cpu.max": "max 100000\n"}, None),  # v2, no cap
    ("4:memory:/x\n1:cpu,cpuacct:/docker/abc\n",
     {"fs/cpu,cpuacct/docker/abc/cpu.cfs_quota_us": "50000\n", "fs/cpu,cpuacct/docker/abc/cpu.cfs_period_us": "100000\n"},
     0.5),  # v1, the group under the joint mount
    ("1:cpu:/\n", {"fs/cpu/cpu.cfs_quota_us": "-1\n", "fs/cpu/cpu.cfs_period_us": "100000\n"}, None),  # v1, no cap
    ("0::/ci/job\n", {}, None),  # nothing readable
    ("0::/ci/job\n", {"fs/ci/job/cpu.max": "garbage\n", "fs/cpu.max": "300000 100000"}, 3.0),  # unreadable: next
    ("0::/\n", {"fs/cpu.max": "100000 0\n"}, None),  # a zero period reads as nothing
])
def test_the_cpu_quota_of_a_control_group_is_read(tmp_path, membership, files, quota):
    assert threads.cpu_quota(**_cgroup(tmp_path, membership, files)) == quota


def test_cores_are_capped_by_the_quota_rounded_up_and_never_below_one(monkeypatch):
    monkeypatch.setattr(os, "sched_getaffinity", lambda _: set(range(8)), raising=False)
    for quota, expected in ((None, 8), (1.5, 2), (0.2, 1), (2.0, 2), (64.0, 8)):
        monkeypatch.setattr(threads, "cpu_quota", lambda quota=quota: quota)
        assert threads.cores() == expected


def test_a_quota_set_on_a_group_above_the_process_caps_it_too(tmp_path):
    files = {"fs/ci.slice/cpu.max": "150000 100000\n", "fs/ci.slice/job/cpu.max": "max 100000\n",
             "fs/cpu.max": "400000 100000\n"}
    assert threads.cpu_quota(**_cgroup(tmp_path, "0::/ci.slice/job\n", files)) == 1.5  # the least on the way up


def test_an_interrupt_while_chunks_run_starts_no_further_chunk():
    threads.set_count(2)
    started = []

    def task(start, stop):
        started.append(start)
        if start == 0:
            time.sleep(0.05)  # the other thread takes a few chunks meanwhile
            raise KeyboardInterrupt  # as Ctrl-C (or SIGTERM, as the command line raises it) reaches spread
        time.sleep(0.01)

    with pytest.raises(KeyboardInterrupt):
        threads.spread(task, 160)  # 16 chunks of 10 items
    time.sleep(0.3)  # what would still start, would have by now
    assert len(started) < 16, started
