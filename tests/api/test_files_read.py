"""A Body knows the files it was read from (the spec and every file the spec names), and no
picture, animation or sweep written from it replaces one of them; `Body.export_warnings` is what
`rbi export` warns about."""

from __future__ import annotations

import os

import pytest

import rbi
from tests.cli.test_output_inputs import CLOUD, write_cloud_spec
from tests.conftest import BODIES


@pytest.fixture
def cloud_spec(tmp_path):
    return write_cloud_spec(tmp_path)


def test_files_read_are_the_spec_and_the_files_it_names(cloud_spec, monkeypatch):
    spec, cloud = cloud_spec
    body = rbi.load(spec)
    assert body.files_read == [str(spec), str(cloud)]
    assert body.in_units("mm", "g").files_read == body.files_read
    assert rbi.load(BODIES / "top.yaml").files_read == [str(BODIES / "top.yaml")]
    monkeypatch.chdir(cloud.parent)  # text and a dict name their files beside the current folder
    assert rbi.loads(spec.read_text()).files_read == [str(cloud)]
    assert rbi.load({"point_cloud": {"file": "cloud.csv"}}).files_read == [str(cloud)]


def test_no_output_of_a_body_replaces_a_file_it_was_read_from(cloud_spec, tmp_path):
    pytest.importorskip("matplotlib")
    spec, cloud = cloud_spec
    body = rbi.load(spec)
    run = rbi.simulate(body, spin=5, duration=0.1, samples=11)
    link = tmp_path / "alias.png"
    os.symlink(cloud, link)
    page = tmp_path / "alias.html"
    os.link(cloud, page)
    attempts = {
        "show": lambda: rbi.show(body, link),
        "animate": lambda: rbi.animate(body, page, spin=5, duration=0.1),
        "plot": lambda: run.plot(link),
        "sweep": lambda: rbi.sweep(body, spin=[1, 2], duration=0.1, out=cloud),
    }
    for what, attempt in attempts.items():
        with pytest.raises(rbi.SpecError, match="is an input of this run") as caught:
            attempt()
        assert str(cloud) in str(caught.value), what
    assert cloud.read_text() == CLOUD


@pytest.mark.parametrize("how", ["same", "symlink"])
def test_a_sweep_of_a_spec_path_never_replaces_a_file_the_spec_names(cloud_spec, tmp_path, how):
    """rbi.sweep(path) knows the files the spec names once it has translated it: ``out`` is
    refused before any run, as for a Body, by the same ArgumentError."""
    spec, cloud = cloud_spec
    out = cloud if how == "same" else tmp_path / "rows.csv"
    if how == "symlink":
        os.symlink(cloud, out)
    for body in (spec, str(spec), rbi.load(spec)):
        with pytest.raises(rbi.ArgumentError, match="is an input of this run") as caught:
            rbi.sweep(body, spin=[1, 2], duration=0.1, out=out)
        assert str(caught.value).startswith(f"out: {out}: ") and str(cloud) in str(caught.value)
    assert cloud.read_text() == CLOUD


def test_a_sweep_map_never_replaces_a_file_the_spec_names(cloud_spec, tmp_path):
    pytest.importorskip("matplotlib")
    spec, cloud = cloud_spec
    link = tmp_path / "map.png"
    os.symlink(cloud, link)
    for body in (spec, rbi.load(spec)):
        table = rbi.sweep(body, spin=[1, 2], duration=0.1)
        with pytest.raises(rbi.ArgumentError, match="is an input of this run"):
            table.plot(link)
    assert cloud.read_text() == CLOUD
    rbi.sweep(spec, spin=[1, 2], duration=0.1).plot(tmp_path / "other.png")
    assert (tmp_path / "other.png").read_bytes().startswith(b"\x89PNG")


def test_export_warnings_name_the_file_of_a_body_without_three_moments(tmp_path):
    spec = tmp_path / "pt.yaml"
    spec.write_text("parts:\n  - {name: p, shape: point, mass: 1, position: [0, 0, 0]}\n")
    warnings = rbi.load(spec).export_warnings()
    assert len(warnings) == 1 and warnings[0].startswith(f"{spec}: the inertia has a zero principal moment")
    assert rbi.load(BODIES / "top.yaml").export_warnings() == []
