"""Hostile input for `rbi sweep --dask`: what another local user can reach while a `--dask local`
sweep runs, addresses that never answer, Ctrl-C, and more workers than the machine has.

Kept few and fast: one LocalCluster start (a few seconds) serves the port and Ctrl-C checks.
See docs/security.md, "Ports".
"""

from __future__ import annotations

import contextlib
import os
import signal
import socket
import subprocess
import sys
import threading
import time
import urllib.request

import pytest

from tests.conftest import BODIES, one_line_exit_2, run_rbi
from tests.conftest import run_rbi_inprocess as rbi

pytest.importorskip("distributed")
psutil = pytest.importorskip("psutil")

BOLTED = BODIES / "top_bolted.yaml"


def listening(pid: int) -> set[tuple[str, int]]:
    """(address, port) of every TCP socket listening in the process ``pid`` and its children."""
    root = psutil.Process(pid)
    found = set()
    for process in [root, *root.children(recursive=True)]:
        try:
            connections = process.net_connections(kind="inet")
        except psutil.NoSuchProcess:
            continue
        found |= {(c.laddr.ip, c.laddr.port) for c in connections if c.status == psutil.CONN_LISTEN}
    return found


def plain_clients_get_in(addresses: list[str], seconds: float = 5.0) -> list[str]:
    """The addresses where a distributed.Client without credentials connects and can run a
    function (tried at once; an attempt still hanging after ``seconds`` counts as no)."""
    from distributed import Client

    got_in = []

    def attempt(address):
        try:
            client = Client(address, timeout="3s", set_as_default=False)
            client.submit(os.getpid, pure=False).result(timeout=5)
            got_in.append(address)
            client.close()
        except Exception:  # noqa: BLE001 - any failure is the wanted outcome
            pass

    threads = [threading.Thread(target=attempt, args=(a,), daemon=True) for a in addresses]
    for thread in threads:
        thread.start()
    deadline = time.monotonic() + seconds
    for thread in threads:
        thread.join(max(0.0, deadline - time.monotonic()))
    return got_in


def http_answers(port: int) -> bool:
    try:
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/info/main/workers.html", timeout=3) as reply:
            return reply.status < 500
    except Exception:  # noqa: BLE001 - refused, reset, not HTTP: nobody answered
        return False


def test_a_local_cluster_lets_no_credential_less_client_in_and_ctrl_c_is_one_line(tmp_path):
    """rbi 2's --dask local left an unauthenticated scheduler on a TCP port (another local user
    ran code as the sweep's user through it) and a dashboard on :8787; Ctrl-C printed 67 lines."""
    pytest.importorskip("cryptography")
    out = tmp_path / "d.csv"
    scratch = tmp_path / "tmp"  # Dask's default scratch space is the fixed $TMPDIR/dask-scratch-space
    scratch.mkdir()
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "rbi",
            "sweep",
            str(BOLTED),
            "--spin",
            "150:250:200000",
            "--duration",
            "0.5",
            "--dask",
            "local",
            "--workers",
            "1",
            "--out",
            str(out),
        ],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
        env={**os.environ, "TMPDIR": str(scratch)},
    )
    try:
        deadline = time.monotonic() + 120
        while (
            time.monotonic() < deadline
            and proc.poll() is None
            and (not out.exists() or out.read_bytes().count(b"\n") < 2)
        ):
            time.sleep(0.1)
        assert proc.poll() is None, proc.communicate()[1]
        ports = listening(proc.pid)
        assert ports, "the cluster listens nowhere: nothing to check"
        assert all(address == "127.0.0.1" for address, _ in ports), ports
        assert 8787 not in {port for _, port in ports}
        assert [p.name for p in scratch.iterdir() if not p.name.startswith("rbi-dask-")] == []
        assert (
            plain_clients_get_in(
                [f"{scheme}://127.0.0.1:{port}" for _, port in ports for scheme in ("tcp", "tls")]
            )
            == []
        )
        assert [port for _, port in ports if http_answers(port)] == []
        workers = psutil.Process(proc.pid).children(recursive=True)
        assert workers
        os.killpg(proc.pid, signal.SIGINT)  # what Ctrl-C in a terminal does: the whole group
        _, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    assert proc.returncode == 130, err
    assert err.startswith("rbi: interrupted:") and len(err.strip().splitlines()) == 1, err
    time.sleep(0.5)
    assert not [w for w in workers if w.is_running() and w.status() != psutil.STATUS_ZOMBIE]
    assert list(scratch.iterdir()) == []  # the private scratch folder is gone too


@pytest.fixture
def quick_connect(monkeypatch):
    from rbi.sweeps import execute

    assert execute.CONNECT_SECONDS + 2 < 30  # the promise: exit 2 within 30 s
    monkeypatch.setattr(execute, "CONNECT_SECONDS", 1.0)
    return 1.0


def _silent_server(send: bytes | None = None):
    """A TCP server on 127.0.0.1 that accepts connections and then says nothing (or ``send``)."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(8)
    held = []

    def serve():
        while True:
            try:
                connection, _ = server.accept()
            except OSError:
                return
            held.append(connection)
            if send is not None:
                connection.sendall(send)

    threading.Thread(target=serve, daemon=True).start()
    return server, held


@pytest.mark.parametrize("kind", ["refused", "silent", "http", "bad-scheme"])
def test_an_address_where_no_scheduler_answers_is_exit_2_in_time(quick_connect, kind):
    """rbi 2: exit 1 after 20 s for a refused port, a hang for a silent one."""
    server = None
    if kind == "refused":
        probe = socket.socket()
        probe.bind(("127.0.0.1", 0))
        address = f"tcp://127.0.0.1:{probe.getsockname()[1]}"
        probe.close()
    elif kind in ("silent", "http", "garbage"):
        send = {"silent": None, "http": b"HTTP/1.1 200 OK\r\n\r\nhello", "garbage": os.urandom(4096)}[kind]
        server, _ = _silent_server(send)
        address = f"tcp://127.0.0.1:{server.getsockname()[1]}"
    elif kind == "no-such-host":
        address = "tcp://no-such-host.invalid:8786"
    else:
        address = "gopher://127.0.0.1:8786"
    started = time.monotonic()
    try:
        proc = rbi("sweep", BOLTED, "--spin", "200", "--duration", "0.1", "--dask", address)
    finally:
        if server is not None:
            server.close()
    elapsed = time.monotonic() - started
    one_line_exit_2(proc, "--dask")
    assert elapsed < quick_connect + 9, elapsed  # the connection wait plus a loaded machine's start-up


def test_more_workers_than_cores_are_clamped_with_one_line(monkeypatch):
    """rbi 2 passed --workers 1024 to the OpenMP kernel as threads (libgomp aborts when it
    cannot start them)."""
    from rbi.sweeps import execute

    seen = []
    real = execute.run_local

    def spy(compute, ranges, threads, on_rows):
        seen.append(threads)
        return real(compute, ranges, threads, on_rows)

    monkeypatch.setattr(execute, "run_local", spy)
    args = ["sweep", BOLTED, "--spin", "150:250:3", "--duration", "0.1", "--format", "csv"]
    proc = rbi(*args, "--workers", "1024")
    assert proc.returncode == 0, proc.stderr
    assert seen == [execute.available_cores()]
    assert len(proc.stderr.strip().splitlines()) == 1 and "--workers 1024" in proc.stderr
    assert proc.stdout == rbi(*args).stdout


def test_a_server_that_speaks_first_is_exit_2_at_once():
    """rbi 4: an SSH server's banner read as a Dask frame length ('MemoryError 2.82 EiB') after
    21 s, then a traceback from Client.__del__. The server lives at most 30 s."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(8)
    server.settimeout(30)

    def serve():
        with contextlib.suppress(OSError):
            while True:
                connection, _ = server.accept()
                connection.sendall(b"SSH-2.0-OpenSSH_9.0\r\n")

    threading.Thread(target=serve, daemon=True).start()
    address = f"tcp://127.0.0.1:{server.getsockname()[1]}"
    started = time.monotonic()
    try:
        proc = run_rbi("sweep", BOLTED, "--spin", "200", "--duration", "0.1", "--dask", address)
    finally:
        server.close()
    elapsed = time.monotonic() - started
    one_line_exit_2(proc, f"--dask {address}: ")
    assert "SSH-2.0-OpenSSH_9.0" in proc.stderr and "Error" not in proc.stderr, proc.stderr
    assert elapsed < 8, elapsed
