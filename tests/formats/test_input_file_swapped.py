"""The format readers (STEP, STL, point cloud) open their files through rbi.files.safe, which
checks the file it opened, not the name a moment before: a FIFO (or a device, a folder) swapped
in after a spec's path was checked is refused at once, naming what it is, and never waited on.

A FIFO at rest is refused earlier, by the name (rbi.formats.paths.spec_relative_file, the robot
mesh resolver, `rbi import`'s check); these tests hand the FIFO to the readers themselves, as
such a swap would."""

from __future__ import annotations

import os
import threading
from pathlib import Path

import pytest

from rbi.errors import InputError
from rbi.formats import point_cloud
from rbi.formats.mesh_file import read_mesh_arrays
from rbi.formats.step import read_step

WAIT_SECONDS = 5.0


def without_waiting(call, fifo: Path) -> BaseException | None:
    """What ``call()`` raised (None: nothing), failing the test if it waits on ``fifo``: a reader
    blocked in open() is then let go (a writer opens and closes the FIFO) so the test ends."""
    outcome: list[BaseException | None] = []

    def target():
        try:
            call()
            outcome.append(None)
        except BaseException as exc:  # noqa: BLE001 - handed to the test
            outcome.append(exc)

    worker = threading.Thread(target=target, daemon=True)
    worker.start()
    worker.join(WAIT_SECONDS)
    if worker.is_alive():
        try:
            os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
        except OSError:
            pass
        worker.join(WAIT_SECONDS)
        pytest.fail(f"waited on the FIFO {fifo.name} for {WAIT_SECONDS} s instead of refusing it")
    return outcome[0]


@pytest.mark.parametrize(
    "name, read, noun", [("part.step", read_step, "STEP file"), ("part.stl", read_mesh_arrays, "mesh file")]
)
def test_a_fifo_handed_to_the_step_or_stl_reader_is_refused_at_once(tmp_path, name, read, noun):
    fifo = tmp_path / name
    os.mkfifo(fifo)
    error = without_waiting(lambda: read(fifo), fifo)
    assert isinstance(error, ValueError)
    assert str(error) == f"not a regular file but a FIFO (named pipe); give a {noun}"


@pytest.mark.parametrize("suffix", [".csv", ".npy"])
def test_a_fifo_swapped_in_after_its_name_was_checked_is_refused_by_the_cloud_reader(
    tmp_path, monkeypatch, suffix
):
    """The name's check sees the regular file that stood there (Path.stat answers for it); the
    open meets the FIFO put in its place."""
    fifo, before = tmp_path / f"cloud{suffix}", tmp_path / "before.csv"
    before.write_text("mass,x,y,z\n1,0,0,0\n")
    os.mkfifo(fifo)
    real_stat = Path.stat
    monkeypatch.setattr(Path, "stat", lambda self, **kw: real_stat(before if self == fifo else self, **kw))
    label = f"top.yaml: point_cloud: file: cloud{suffix}"
    error = without_waiting(lambda: point_cloud.read_point_cloud(fifo, label), fifo)
    assert isinstance(error, InputError)
    assert str(error) == f"{label}: not a regular file but a FIFO (named pipe); give a point cloud file"


def test_a_csv_cloud_past_its_cap_is_refused_by_its_size_naming_npy(tmp_path, monkeypatch):
    monkeypatch.setattr(point_cloud, "MAX_CSV_BYTES", 10)
    cloud = tmp_path / "cloud.csv"
    cloud.write_text("mass,x,y,z\n1,0,0,0\n")
    with pytest.raises(InputError) as caught:
        point_cloud.read_point_cloud(cloud, "c")
    assert str(caught.value) == (
        "c: file too large for a point cloud (19 bytes; rbi reads at most 10 from CSV: save it as .npy)"
    )
