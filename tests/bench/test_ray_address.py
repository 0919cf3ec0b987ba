"""``bench --backend ray --ray-address ADDR``: an address Ray would misread or keep retrying is
refused before the campaign's folder is made (Ray itself raised a traceback, or retried an
address nobody answers at for minutes)."""

import socket
from collections.abc import Iterator

import pytest

from fuzzynav.bench.backends import ray_address
from fuzzynav.cli import main
from fuzzynav.errors import InputError


@pytest.fixture
def deaf_port() -> Iterator[int]:
    """A port held by a socket that never listens: a connection there is refused, and no other
    process can take the port while the test runs."""
    with socket.socket() as held:
        held.bind(("127.0.0.1", 0))
        yield held.getsockname()[1]


@pytest.mark.parametrize("address", ["not an address", "host:99999", "host:", ":6379", "ray://host:x"])
def test_a_malformed_address_is_refused(address):
    with pytest.raises(InputError, match="must be HOST:PORT, ray://HOST:PORT, auto or local"):
        ray_address(address)


def test_an_address_nobody_answers_at_is_refused_at_once(deaf_port):
    address = f"127.0.0.1:{deaf_port}"
    with pytest.raises(InputError, match=f"--ray-address: no Ray cluster answers at {address}"):
        ray_address(address)


def test_an_address_that_answers_is_kept_and_so_are_auto_and_local(monkeypatch):
    monkeypatch.delenv("RAY_ADDRESS", raising=False)
    with socket.socket() as server:
        server.bind(("127.0.0.1", 0))
        server.listen()
        address = f"127.0.0.1:{server.getsockname()[1]}"
        assert ray_address(address) == address
        assert ray_address(f"ray://{address}") == f"ray://{address}"
    assert ray_address("auto") == "auto" and ray_address("local") == "local" and ray_address(None) is None
    monkeypatch.setenv("RAY_ADDRESS", "")
    assert ray_address(None) is None  # set but empty: a local instance, as Ray reads it


def test_the_environment_variable_is_checked_by_its_name(monkeypatch):
    monkeypatch.setenv("RAY_ADDRESS", "nowhere")
    with pytest.raises(InputError, match="RAY_ADDRESS: must be HOST:PORT"):
        ray_address(None)


@pytest.mark.parametrize("extra, message", [
    ([], "--ray-address: joins a Ray cluster: give --backend ray too"),
    (["--backend", "ray"], "--ray-address: no Ray cluster answers at"),
])
def test_bench_refuses_before_making_its_folder(tmp_path, capsys, deaf_port, extra, message):
    out = tmp_path / "b"
    argv = ["bench", "circles:1", "--controllers", "goal-seeking", "--out", str(out), "--quiet",
            "--ray-address", f"127.0.0.1:{deaf_port}", *extra]
    assert main(argv) == 2
    assert message in capsys.readouterr().err and not out.exists()
