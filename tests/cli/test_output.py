"""Output paths: what rbi refuses to replace, and how it writes what it may."""

from __future__ import annotations

import io
import os
import stat
import sys

import pytest

from rbi.files.output import check_distinct, open_output, output_target, write_output
from rbi.spec.errors import InputError


def test_new_file_is_written_with_the_umask_not_0600(tmp_path):
    old = os.umask(0o022)
    try:
        target = output_target(str(tmp_path / "a.csv"), "--out", ("csv",))
        write_output(target, "t,x\n0,1\n")
    finally:
        os.umask(old)
    assert (tmp_path / "a.csv").read_text() == "t,x\n0,1\n"
    assert stat.S_IMODE(os.stat(tmp_path / "a.csv").st_mode) == 0o644


def test_a_replaced_file_keeps_its_mode(tmp_path):
    path = tmp_path / "a.csv"
    path.write_text("old")
    os.chmod(path, 0o640)
    write_output(output_target(str(path), "--out", ("csv",)), "new")
    assert path.read_text() == "new"
    assert stat.S_IMODE(os.stat(path).st_mode) == 0o640


def test_a_fifo_is_refused(tmp_path):
    fifo = tmp_path / "pipe.csv"
    os.mkfifo(fifo)
    with pytest.raises(InputError, match="FIFO"):
        output_target(str(fifo), "--out", ("csv",))
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)


def test_a_device_is_refused_and_left_alone():
    before = os.stat("/dev/null")
    with pytest.raises(InputError, match="is a device"):
        output_target("/dev/null", "--out", ("csv",))
    after = os.stat("/dev/null")
    assert stat.S_ISCHR(after.st_mode) and after.st_rdev == before.st_rdev


def test_a_link_to_a_device_is_refused_and_the_link_kept(tmp_path):
    link = tmp_path / "null.csv"
    os.symlink("/dev/null", link)
    with pytest.raises(InputError, match="symbolic link to a device"):
        output_target(str(link), "--out", ("csv",))
    assert os.path.islink(link) and os.readlink(link) == "/dev/null"


def test_a_link_to_a_regular_file_is_written_through(tmp_path):
    real = tmp_path / "real.csv"
    real.write_text("old")
    link = tmp_path / "link.csv"
    os.symlink(real, link)
    write_output(output_target(str(link), "--out", ("csv",)), "new")
    assert os.path.islink(link)
    assert real.read_text() == "new"


def test_a_dangling_link_is_refused(tmp_path):
    link = tmp_path / "gone.csv"
    os.symlink(tmp_path / "nowhere.csv", link)
    with pytest.raises(InputError, match="link to nothing"):
        output_target(str(link), "--out", ("csv",))


def test_a_folder_is_refused(tmp_path):
    (tmp_path / "d.csv").mkdir()
    with pytest.raises(InputError, match="folder"):
        output_target(str(tmp_path / "d.csv"), "--out", ("csv",))


def test_the_input_spec_is_never_an_output(tmp_path):
    spec = tmp_path / "top.yaml"
    spec.write_text("parts: []\n")
    with pytest.raises(InputError, match="input"):
        output_target(str(spec), "--out", ("yaml", "csv"), inputs=[str(spec)])
    link = tmp_path / "alias.csv"
    os.symlink(spec, link)
    with pytest.raises(InputError, match="input"):
        output_target(str(link), "--out", ("csv",), inputs=[str(spec)])
    assert spec.read_text() == "parts: []\n"


def test_the_extension_decides_the_format(tmp_path):
    with pytest.raises(InputError, match=r"cannot write '\.json'.*\.csv"):
        output_target(str(tmp_path / "x.json"), "--out", ("csv",))
    with pytest.raises(InputError, match="no extension"):
        output_target(str(tmp_path / "x"), "--plot", ("png", "svg"))
    assert output_target(str(tmp_path / "X.PNG"), "--plot", ("png",)).format == "png"


@pytest.mark.parametrize(
    "path,why",
    [("", "empty"), ("   ", "empty"), ("a\0b.csv", "NUL"), ("x" * 300 + ".csv", "longer than 255")],
)
def test_impossible_paths_are_refused(path, why):
    with pytest.raises(InputError, match=why):
        output_target(path, "--out", ("csv",))


def test_a_missing_folder_is_refused(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        output_target(str(tmp_path / "no" / "x.csv"), "--out", ("csv",))


def test_two_outputs_naming_one_file_are_refused(tmp_path):
    a = output_target(str(tmp_path / "x.png"), "--out", ("csv", "png"))
    b = output_target(str(tmp_path / "." / "x.png"), "--plot", ("png",))
    with pytest.raises(InputError, match="--plot.*also the --out output"):
        check_distinct([a, None, b])


def test_dash_is_standard_output_only_where_allowed(tmp_path, monkeypatch):
    with pytest.raises(InputError, match="standard output"):
        output_target("-", "--plot", ("png",))
    target = output_target("-", "--out", ("csv",), stdout_format="csv")
    buffer = io.StringIO()
    monkeypatch.setattr(sys, "stdout", buffer)
    write_output(target, "a,b\n")
    assert buffer.getvalue() == "a,b\n"
    assert not os.path.exists("-")


def test_a_failed_run_leaves_neither_target_nor_temporary_file(tmp_path):
    path = tmp_path / "x.csv"
    path.write_text("kept")
    target = output_target(str(path), "--out", ("csv",))
    with pytest.raises(RuntimeError):
        with open_output(target) as handle:
            handle.write("half")
            raise RuntimeError("the run failed")
    assert path.read_text() == "kept"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.csv"]


def test_a_write_error_is_one_input_error(tmp_path):
    target = output_target(str(tmp_path / "x.png"), "--plot", ("png",))

    def full_disk(temp):
        raise OSError(28, "No space left on device")

    with pytest.raises(InputError, match="No space left on device"):
        write_output(target, writer=full_disk)
    assert list(tmp_path.iterdir()) == []
