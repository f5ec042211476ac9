"""A large robot file (issue 25): ``rbi.audit`` of a generated URDF of 10⁵ links (each with an
inertial and a box collision, joined by revolute joints into a binary tree), wall time against
the target of 5 s (and the CPU time and load average beside it: on a shared machine the wall
time is mostly waiting); a quick run uses 2,000 links. The file is written into a temporary folder and
removed after.
"""

from __future__ import annotations

import os
from pathlib import Path

from rbi.bench import Progress
from rbi.bench.timing import clocked
from rbi.robot import audit

TARGET_S = 5.0
"""Seconds the audit of the 10⁵-link URDF may take."""


LINKS = {True: 2_000, False: 10**5}
"""Links of the generated URDF: quick run, full run."""


def urdf_text(n: int) -> str:
    """A URDF of ``n`` links in a binary tree (link i hangs from link (i − 1) // 2)."""
    parts = ['<?xml version="1.0"?>\n<robot name="large">\n']
    for i in range(n):
        parts.append(
            f'<link name="l{i}"><inertial><origin xyz="0.1 0 0"/><mass value="1"/><inertia ixx="0.0010416666666666667" '
            'ixy="0" ixz="0" iyy="0.0035416666666666665" iyz="0" izz="0.004166666666666667"/></inertial>'
            '<collision><origin xyz="0.1 0 0"/><geometry><box size="0.2 0.1 0.05"/></geometry></collision></link>\n'
        )
    for i in range(1, n):
        parts.append(
            f'<joint name="j{i}" type="revolute"><parent link="l{(i - 1) // 2}"/><child link="l{i}"/>'
            '<origin xyz="0.2 0 0"/><axis xyz="0 0 1"/><limit effort="10" velocity="1" lower="-1" upper="1"/></joint>\n'
        )
    parts.append("</robot>\n")
    return "".join(parts)


def run(quick: bool, progress: Progress, folder: Path) -> dict:

    n = LINKS[quick]
    progress(f"robot audit: {n:,} links")
    measured = {"target_s": TARGET_S, "links": n}
    path = folder / "large.urdf"
    path.write_text(urdf_text(n), encoding="utf-8")
    size = path.stat().st_size
    try:
        seconds, cpu_seconds, report = clocked(lambda: audit(path))
    except Exception as exc:  # a failed measurement is a row, not the end of the bench
        return measured | {"error": f"{type(exc).__name__}: {exc}"}
    return measured | {
        "megabytes": size / 1e6,
        "seconds": seconds,
        "cpu_seconds": cpu_seconds,
        "load_average": os.getloadavg()[0],
        "links_per_second": n / seconds,
        "total_mass": report.total.mass,
    }
