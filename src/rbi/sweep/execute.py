"""Running the chunks of a sweep: here, on this machine's cores, or on a Dask cluster. Either
way the rows reach ``on_rows`` chunk by chunk in run order."""

from __future__ import annotations

import os
from collections import deque
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Callable

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


def run_local(compute: Callable[[int, int, int], Rows], ranges, threads: int, on_rows: Callable[[Rows], None]) -> None:
    """Each range through ``compute(a, b, threads)`` (whose kernel call spreads the runs over
    ``threads`` cores). Two chunks are in flight, so that one chunk's Python work (building
    bodies, summarising) overlaps the other's integration; rows are delivered in order."""
    with ThreadPoolExecutor(max_workers=2, thread_name_prefix="rbi-sweep") as pool:
        pending: deque = deque()
        try:
            for a, b in ranges:
                pending.append(pool.submit(compute, a, b, threads))
                if len(pending) >= 2:
                    on_rows(pending.popleft().result())
            while pending:
                on_rows(pending.popleft().result())
        finally:
            for future in pending:
                future.cancel()


def run_dask(compute: Callable[[int, int, int], Rows], ranges, address: str, on_rows: Callable[[Rows], None],
             workers: int | None = None) -> None:
    """Each range as a task on the Dask distributed scheduler at ``address`` (``"local"``
    starts a LocalCluster of ``workers`` single-threaded processes, default one per core).
    At most four tasks per worker thread are in flight; rows are delivered in run order."""
    from dask.distributed import Client, LocalCluster

    cluster = None
    if address == "local":
        cluster = LocalCluster(n_workers=workers or available_cores(), threads_per_worker=1, processes=True,
                               dashboard_address=None, silence_logs=50)
        client = Client(cluster)
    else:
        client = Client(address, timeout="20s")
    try:
        compute_remote = client.scatter(compute, broadcast=True, hash=False)
        slots = 4 * max(1, sum(client.nthreads().values()))
        pending: deque = deque()
        for a, b in ranges:
            pending.append(client.submit(_call, compute_remote, a, b, pure=False))
            if len(pending) >= slots:
                on_rows(pending.popleft().result())
        while pending:
            on_rows(pending.popleft().result())
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def _call(compute, a: int, b: int) -> Rows:
    return compute(a, b, 1)
