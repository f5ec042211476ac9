"""Running the chunks of a sweep: here, on this machine's cores, or on a Dask cluster. Either
way the rows reach ``on_rows`` chunk by chunk in run order."""

from __future__ import annotations

import contextlib
import logging
import os
import re
import shutil
import signal
import tempfile
import threading
from collections import deque
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Any

from rbi.errors import ArgumentError, InputError, literal

Rows = list[list[Any]]


def chunk_ranges(start: int, stop: int, size: int):
    """``(a, b)`` pairs covering ``start .. stop-1`` in steps of ``size``."""
    for a in range(start, stop, size):
        yield a, min(stop, a + size)


def available_cores() -> int:
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:
        return max(1, os.cpu_count() or 1)


def run_local(
    compute: Callable[[int, int, int], Rows], ranges, threads: int, on_rows: Callable[[Rows], None]
) -> None:
    """Each range through ``compute(a, b, threads)`` (whose kernel call spreads the runs over
    ``threads`` cores). Two chunks are in flight, so that one chunk's Python work (building
    bodies, summarising) overlaps the other's integration; rows are delivered in order."""
    threads = usable_workers(threads)
    with ThreadPoolExecutor(max_workers=2, thread_name_prefix="rbi-sweep") as pool:
        pending: deque = deque()
        try:
            _in_order(lambda a, b: pool.submit(compute, a, b, threads), ranges, 2, on_rows, pending)
        finally:
            for future in pending:
                future.cancel()


def _in_order(submit: Callable[[int, int], Any], ranges, in_flight: int, on_rows, pending=None) -> None:
    """Each range ``(a, b)`` submitted as ``submit(a, b)`` (a future), at most ``in_flight`` at
    once (held in ``pending``, a deque); their rows delivered to ``on_rows`` in run order."""
    pending = deque() if pending is None else pending
    for a, b in ranges:
        pending.append(submit(a, b))
        if len(pending) >= in_flight:
            on_rows(pending.popleft().result())
    while pending:
        on_rows(pending.popleft().result())


CONNECT_SECONDS = 10.0
"""How long ``--dask ADDRESS`` waits for a scheduler to answer (connection and handshake)."""


def usable_workers(requested: int | None) -> int:
    """Processes or threads to run on: ``requested`` (default: every core), at most the cores
    this process may use — more would only compete for them, and thousands of threads or
    processes can fail to start (an OpenMP runtime aborts then)."""
    return min(requested or available_cores(), available_cores())


def run_dask(
    compute: Callable[[int, int, int], Rows],
    ranges,
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
        _in_order(lambda a, b: client.submit(_call, compute_remote, a, b, pure=False), ranges, slots, on_rows)
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
    previous = _ignore_sigint()
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
    client.run(_stop_http_of_worker)
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


def _ignore_sigint():
    """Ignore SIGINT while worker processes start (they inherit it); the previous handler, or
    None when this is not the main thread."""

    if threading.current_thread() is not threading.main_thread():
        return None
    return signal.signal(signal.SIGINT, signal.SIG_IGN)


def _stop_http(server) -> None:
    http = getattr(server, "http_server", None)
    if http is not None:
        http.stop()


def _stop_http_of_worker(dask_worker=None) -> None:
    _stop_http(dask_worker)


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


def _call(compute, a: int, b: int) -> Rows:
    return compute(a, b, 1)
