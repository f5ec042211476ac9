"""Running the chunks of a sweep: here, on this machine's cores, or on a Dask cluster. Either
way the rows reach ``on_rows`` chunk by chunk in run order."""

from __future__ import annotations

import contextlib
import functools
import logging
import math
import queue
import re
import shutil
import signal
import socket
import struct
import tempfile
import threading
import time
from collections import deque
from collections.abc import Callable
from concurrent.futures import Future
from typing import Any

from rbi.errors import ArgumentError, InputError, literal, shown
from rbi.sim.compiled import available_cores

Rows = list[list[Any]]


CHUNK_SECONDS = 1.0
"""About how long one chunk of simulated runs should take, wall time. The kernel hands back a
chunk's rows only when its last run ends, so this bounds how long finished runs wait before
they reach the output, and how long a stopped sweep waits for the chunks in flight."""

STOP_SECONDS = 3.0
"""How long a stopped sweep (Ctrl-C, SIGTERM, an exception from the progress callback) waits
for the chunks in flight to keep their rows; a chunk not done by then is left to its thread
(a daemon: it does not hold the process; in a process that goes on, such as a notebook calling
:func:`rbi.sweep`, it ends in the background and its rows are dropped) and its runs are
computed by ``--resume``."""


class Chunks:
    """The ranges ``(a, b)`` of runs ``start .. stop-1``, each sized to take about
    :data:`CHUNK_SECONDS` of wall time: by ``run_seconds`` (an estimate of the wall time one
    run adds to a chunk, None when there is none) at first, then by what the chunks took
    (:meth:`took`: the latest chunk's seconds per run, growing at most twofold a chunk);
    never more than ``most`` runs (the memory bound, and the size that keeps short runs
    quick), nor fewer than ``least`` (enough to keep the cores busy) unless ``most`` is."""

    def __init__(
        self, start: int, stop: int, most: int, least: int = 1, run_seconds: float | None = None
    ) -> None:
        self.start, self.stop, self.most, self.least = start, stop, max(1, most), max(1, least)
        self.run_seconds, self._grown = run_seconds, self.most

    def size(self) -> int:
        """Runs in the next chunk."""
        if self.run_seconds is None:
            return self.most
        timed = CHUNK_SECONDS / self.run_seconds if self.run_seconds > 0 else math.inf
        return min(self.most, max(self.least, min(self._grown, int(min(timed, 2**62)))))

    def __iter__(self):
        a = self.start
        while a < self.stop:
            b = min(self.stop, a + self.size())
            yield a, b
            a = b

    def took(self, runs: int, seconds: float) -> None:
        """A chunk of ``runs`` runs took ``seconds`` (wall time, from its start to its rows)."""
        if runs > 0 and math.isfinite(seconds) and seconds >= 0:
            self.run_seconds, self._grown = seconds / runs, 2 * runs


def run_local(
    compute: Callable[[int, int, int], Rows], ranges: Chunks, threads: int, on_rows: Callable[[Rows], None]
) -> None:
    """Each range through ``compute(a, b, threads)`` (whose kernel call spreads the runs over
    ``threads`` cores). Two chunks are in flight, so that one chunk's Python work (building
    bodies, summarising) overlaps the other's integration; rows are delivered in order. Stopped
    (Ctrl-C, SIGTERM), the chunks not started are dropped and those in flight kept as
    :func:`_in_order` says."""
    threads = usable_workers(threads)
    workers = _Workers(2)
    try:
        _in_order(
            lambda a, b: workers.submit(_timed, compute, a, b, threads), ranges, 2, on_rows, workers.drop
        )
    finally:
        workers.close()


class _Workers:
    """Threads that run submitted calls in the order given, each returning a
    :class:`~concurrent.futures.Future`. Daemon threads: a chunk still integrating when the
    sweep is stopped does not keep the process from exiting (the kernel cannot be stopped
    in the middle of a call)."""

    def __init__(self, count: int) -> None:
        self._queue: queue.SimpleQueue = queue.SimpleQueue()
        self._threads = [
            threading.Thread(target=self._work, name="rbi-sweep", daemon=True) for _ in range(count)
        ]
        for thread in self._threads:
            thread.start()

    def submit(self, call: Callable, *args) -> Future:
        future: Future = Future()
        self._queue.put((future, call, args))
        return future

    def _work(self) -> None:
        while (item := self._queue.get()) is not None:
            future, call, args = item
            if not future.set_running_or_notify_cancel():
                continue  # dropped before it started
            try:
                future.set_result(call(*args))
            except BaseException as exc:  # noqa: BLE001 - handed to the caller through the future
                future.set_exception(exc)

    def drop(self) -> None:
        """Cancel every call not started yet."""
        with contextlib.suppress(queue.Empty):
            while True:
                item = self._queue.get_nowait()
                if item is not None:
                    item[0].cancel()

    def close(self) -> None:
        """No more calls: the threads end after the ones running (not waited for)."""
        self.drop()
        for _ in self._threads:
            self._queue.put(None)


def _timed(compute: Callable[[int, int, int], Rows], a: int, b: int, threads: int = 1) -> tuple[Rows, float]:
    """``compute(a, b, threads)`` and the wall time it took (a Dask task runs on one core)."""
    started = time.perf_counter()
    rows = compute(a, b, threads)
    return rows, time.perf_counter() - started


def _in_order(
    submit: Callable[[int, int], Any], ranges: Chunks, in_flight: int, on_rows, drop=lambda: None
) -> None:
    """Each range ``(a, b)`` submitted as ``submit(a, b)`` (a future of ``(rows, seconds)``), at
    most ``in_flight`` at once; their rows delivered to ``on_rows`` in run order, and their
    times to ``ranges`` (:meth:`Chunks.took`). Stopped while it waits or delivers
    (KeyboardInterrupt, SystemExit: Ctrl-C, SIGTERM, the progress callback), ``drop()`` cancels
    what has not started, the chunks in flight that end within :data:`STOP_SECONDS` are
    delivered still, in order, and the stop goes on up."""
    pending: deque = deque()
    try:
        for a, b in ranges:
            pending.append((b - a, submit(a, b)))
            if len(pending) >= in_flight:
                _deliver(pending, ranges, on_rows)
        while pending:
            _deliver(pending, ranges, on_rows)
    except (KeyboardInterrupt, SystemExit):
        drop()
        _keep_in_flight(pending, ranges, on_rows)
        raise


def _deliver(pending: deque, ranges: Chunks, on_rows) -> None:
    """The first pending chunk's rows to ``on_rows`` once it ends, with Ctrl-C and SIGTERM held
    while they are delivered: a stop never leaves a finished chunk half written or untold."""
    runs, future = pending[0]
    rows, seconds = future.result()
    with _signals_held():
        pending.popleft()
        ranges.took(runs, seconds)
        on_rows(rows)


def _keep_in_flight(pending: deque, ranges: Chunks, on_rows) -> None:
    """After a stop: deliver the pending chunks, in order, while each ends within
    :data:`STOP_SECONDS` of the stop and without error (a second stop ends the wait)."""
    deadline = time.monotonic() + STOP_SECONDS
    while pending:
        try:
            failed = pending[0][1].exception(timeout=max(0.0, deadline - time.monotonic()))
        except Exception:  # noqa: BLE001 - not done in time, or cancelled: the rest is not kept
            return
        if failed is not None:
            return
        _deliver(pending, ranges, on_rows)


@contextlib.contextmanager
def _signals_held():
    """SIGINT and SIGTERM, where Python handles them (a callable handler), recorded instead of
    handled in the block, then handed to their handlers after it (in the main thread only:
    nowhere else does Python run handlers or allow setting them)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    caught: list[int] = []
    held: dict[int, Callable] = {}
    try:
        for number in (signal.SIGINT, signal.SIGTERM):
            handler = signal.getsignal(number)
            if callable(handler):
                held[number] = handler
                signal.signal(number, lambda signum, _frame: caught.append(signum))
        yield
    finally:
        for number, handler in held.items():
            signal.signal(number, handler)
        for number in caught:
            held[number](number, None)


CONNECT_SECONDS = 10.0
"""How long ``--dask ADDRESS`` waits for a scheduler to answer (connection and handshake)."""


def usable_workers(requested: int | None) -> int:
    """Processes or threads to run on: ``requested`` (default: every core), at most the cores
    this process may use — more would only compete for them, and thousands of threads or
    processes can fail to start (an OpenMP runtime aborts then)."""
    return min(requested or available_cores(), available_cores())


def run_dask(
    compute: Callable[[int, int, int], Rows],
    ranges: Chunks,
    address: str,
    on_rows: Callable[[Rows], None],
    workers: int | None = None,
) -> None:
    """Each range as a task on the Dask distributed scheduler at ``address`` (``"local"``
    starts a private local cluster of ``workers`` single-threaded processes, default one per
    core: see :func:`local_cluster`). At most four tasks per worker thread are in flight; rows
    are delivered in run order."""
    cluster = scratch = None
    if address == "local":
        cluster, client, scratch = local_cluster(usable_workers(workers))
    else:
        client = connect(address)
    try:
        compute_remote = client.scatter(compute, broadcast=True, hash=False)
        slots = 4 * max(1, sum(client.nthreads().values()))
        _in_order(
            functools.partial(client.submit, _timed, compute_remote, pure=False), ranges, slots, on_rows
        )
    finally:
        _quietly_close(client, cluster)
        if scratch is not None:
            shutil.rmtree(scratch, ignore_errors=True)


def local_cluster(workers: int):
    """A LocalCluster only this run can use, its client, and its private scratch folder (the
    caller removes it).

    Every connection between the scheduler, the nannies, the workers and this client is TLS
    with mutual authentication by throw-away certificates made for this run
    (``Security.temporary()``, held in memory), all bound to 127.0.0.1: a client without them
    (another local user, a browser) gets nowhere. The scheduler's and workers' HTTP servers
    (dashboard, metrics, health, the proxy) are stopped as soon as they are up and serve no
    route meanwhile. The workers' scratch space (spilled data, lock files) is a new private
    folder (``mkdtemp``), not Dask's fixed ``$TMPDIR/dask-scratch-space``, which another user
    could create first and plant lock-file links in. The workers ignore Ctrl-C: the terminal's SIGINT reaches the whole process
    group, and this process shuts them down itself (one line, no traceback from each)."""

    # dask and distributed: optional (the 'dask' extra), imported only when used
    import dask
    from distributed import Client, LocalCluster
    from distributed.security import Security

    security = Security.temporary()
    scratch = tempfile.mkdtemp(prefix="rbi-dask-")
    private = {
        "distributed.scheduler.http.routes": [],
        "distributed.worker.http.routes": [],
        "temporary-directory": scratch,
    }
    # SIGINT ignored while the worker processes start (they inherit it), where this thread may set it
    main = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN) if main else None
    try:
        with dask.config.set(private):
            cluster = LocalCluster(
                n_workers=workers,
                threads_per_worker=1,
                processes=True,
                host="127.0.0.1",
                protocol="tls://",
                security=security,
                dashboard_address=None,
                silence_logs=50,
                local_directory=scratch,
            )
    except BaseException:
        shutil.rmtree(scratch, ignore_errors=True)
        raise
    finally:
        if previous is not None:
            signal.signal(signal.SIGINT, previous)
    client = Client(cluster, security=security, set_as_default=False)
    _stop_http(cluster.scheduler)
    client.run(_stop_http)
    return cluster, client, scratch


_ADDRESS = re.compile(r"(tcp|tls)://(\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9_.-]+):([0-9]{1,5})")
_TLS_CLIENT = ("distributed.comm.tls.client.cert", "distributed.comm.tls.ca-file")


def check_address(address: str) -> None:
    """Refuse at once (before any file is read or connection tried) a ``--dask`` address that
    is not ``local``, ``tcp://HOST:PORT`` or ``tls://HOST:PORT``, and a TLS address when Dask's
    configuration holds no client certificate and CA (``distributed.comm.tls.client.cert``,
    ``.key``, ``distributed.comm.tls.ca-file``): without them no TLS scheduler answers."""

    if address == "local":
        return
    found = _ADDRESS.fullmatch(address) if isinstance(address, str) else None
    if found is None or not 0 < int(found.group(3)) < 65536:
        raise ArgumentError(
            "dask",
            f"{literal(address)} is not a scheduler address: give local, tcp://HOST:PORT or "
            "tls://HOST:PORT (e.g. tcp://10.0.0.5:8786)",
        )
    if found.group(1) == "tls":
        # dask: optional (the 'dask' extra), imported only when used
        import dask

        missing = [key for key in _TLS_CLIENT if not dask.config.get(key, None)]
        if missing:
            raise InputError(
                f"--dask {address}: a TLS scheduler needs this client's certificate and the CA: set "
                f"{' and '.join(missing)} (and distributed.comm.tls.client.key) in Dask's configuration, "
                "e.g. DASK_DISTRIBUTED__COMM__TLS__CLIENT__CERT=client.pem"
            )


def connect(address: str):
    """A client of the scheduler at ``address``; InputError naming ``--dask`` when none answers
    within :data:`CONNECT_SECONDS` (refused, unreachable, or a server that accepts and stays
    silent, on which Dask's own timeout never fires)."""

    _refuse_a_talker(address)
    # distributed: optional (the 'dask' extra), imported only when used
    from distributed import Client

    box: dict = {}

    def attempt():
        try:
            box["client"] = Client(address, timeout=f"{CONNECT_SECONDS}s", set_as_default=False)
        except BaseException as exc:  # noqa: BLE001 - reported below, in the caller's thread
            box["error"] = exc

    thread = threading.Thread(target=attempt, name="rbi-dask-connect", daemon=True)
    thread.start()
    thread.join(CONNECT_SECONDS + 2)
    if "client" in box:
        return box["client"]
    error = box.get("error")
    why = "no answer" if error is None else " ".join(f"{type(error).__name__}: {error}".split())[:160]
    raise InputError(
        f"--dask {address}: no Dask scheduler answered there within {CONNECT_SECONDS:g} s ({why})"
    )


TALKER_SECONDS = 1.0
"""How long :func:`_refuse_a_talker` listens for a server's first bytes."""


def _refuse_a_talker(address: str) -> None:
    """Refuse a server that speaks first with something no Dask scheduler sends (an SSH or
    SMTP banner): Dask would read its first 8 bytes as a frame length (``SSH-2.0-`` is
    2.82 EiB) and fail after its timeout with a MemoryError. A scheduler's first frame (its
    handshake, sent on accept) is a few hundred bytes; a TLS server says nothing before the
    client does. A silent or slow server is left to Dask's own connection."""

    found = _ADDRESS.fullmatch(address)
    if found is None:
        return
    host = found.group(2).strip("[]")
    heard = b""
    with contextlib.suppress(OSError), socket.create_connection((host, int(found.group(3))), 2) as probe:
        probe.settimeout(TALKER_SECONDS)
        while len(heard) < 8 and (chunk := probe.recv(64)):
            heard += chunk
    if heard and (found.group(1) == "tls" or len(heard) < 8 or struct.unpack("<Q", heard[:8])[0] > 2**26):
        said = heard.decode("ascii", "replace").strip()
        raise InputError(f"--dask {address}: not a Dask scheduler (it speaks first: {shown(said, 60)})")


def _stop_http(dask_worker=None) -> None:
    """Stop the HTTP server of a scheduler or a worker (``client.run`` passes the worker by this name)."""
    http = getattr(dask_worker, "http_server", None)
    if http is not None:
        http.stop()


def _quietly_close(client, cluster) -> None:
    """Close the client and the local cluster without the log lines and tracebacks Dask prints
    while its connections go down."""

    quiet = logging.getLogger("distributed")
    level = quiet.level
    quiet.setLevel(logging.CRITICAL + 1)
    try:
        with contextlib.suppress(Exception):
            client.close()
        if cluster is not None:
            with contextlib.suppress(Exception):
                cluster.close()
    finally:
        quiet.setLevel(level)
