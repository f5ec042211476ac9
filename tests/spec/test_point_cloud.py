"""Point clouds (`point_cloud: {file: ...}`): the same body as point masses written in YAML,
read from CSV or .npy, and every bad file reported as one line naming the spec and the file."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rbi.spec.errors import InputError
from rbi.spec.load import load_body
from tests.conftest import run_rbi


def direct_sums(masses, positions):
    """Mass, CoM and central inertia by the definition ``Σ m (|d|² E − d dᵀ)``."""
    masses = np.asarray(masses, dtype=float)
    positions = np.asarray(positions, dtype=float)
    M = masses.sum()
    com = masses @ positions / M
    I = np.zeros((3, 3))
    for m, p in zip(masses, positions):
        d = p - com
        I += m * (d @ d * np.eye(3) - np.outer(d, d))
    return M, com, I


def write_csv(path, masses, positions, header="mass,x,y,z"):
    rows = [header] + [f"{m!r},{p[0]!r},{p[1]!r},{p[2]!r}" for m, p in zip(masses, positions)]
    path.write_text("\n".join(rows) + "\n")


cloud = st.integers(2, 12).flatmap(
    lambda n: st.tuples(
        st.lists(st.floats(0.01, 10.0), min_size=n, max_size=n),
        st.lists(st.lists(st.floats(-5.0, 5.0), min_size=3, max_size=3), min_size=n, max_size=n),
    )
)


@settings(max_examples=25, deadline=None, derandomize=True)
@given(cloud)
def test_a_csv_cloud_is_the_same_body_as_its_points_in_yaml(tmp_path_factory, points):
    masses, positions = points
    folder = tmp_path_factory.mktemp("cloud")
    write_csv(folder / "pts.csv", masses, positions)
    (folder / "cloud.yaml").write_text("point_cloud: {file: pts.csv}\n")
    parts = "\n".join(
        f"  - {{shape: point, mass: {m:.17e}, position: [{p[0]:.17e}, {p[1]:.17e}, {p[2]:.17e}]}}"
        for m, p in zip(masses, positions)
    )
    (folder / "parts.yaml").write_text("parts:\n" + parts + "\n")
    from_cloud = load_body(folder / "cloud.yaml").props
    from_parts = load_body(folder / "parts.yaml").props
    M, com, I = direct_sums(masses, positions)
    scale = M * max(1.0, float(np.max(np.abs(positions))) ** 2)  # M·L² of the cloud's extent
    assert from_cloud.mass == pytest.approx(from_parts.mass, rel=1e-15)
    np.testing.assert_allclose(from_cloud.center_of_mass, from_parts.center_of_mass, rtol=0, atol=1e-15 * 5)
    np.testing.assert_allclose(
        from_cloud.inertia_about_com, from_parts.inertia_about_com, rtol=0, atol=1e-15 * scale
    )
    assert from_cloud.mass == pytest.approx(M, rel=1e-14)
    np.testing.assert_allclose(from_cloud.center_of_mass, com, rtol=0, atol=1e-13 * 5)
    np.testing.assert_allclose(from_cloud.inertia_about_com, I, rtol=0, atol=1e-13 * scale)


def test_npy_csv_and_any_column_order_agree(tmp_path):
    rng = np.random.default_rng(2)
    masses = rng.uniform(0.1, 2.0, 200)
    positions = rng.normal(size=(200, 3)) + [3.0, 0.0, -1.0]
    np.save(tmp_path / "pts.npy", np.column_stack((masses, positions)))
    # Columns shuffled, an extra column, comment and blank lines: all allowed in CSV.
    lines = ["# exported by a scanner", "", "z, note, X, mass, y"]
    lines += [f"{p[2]!r},a,{p[0]!r},{m!r},{p[1]!r}" for m, p in zip(masses.tolist(), positions.tolist())]
    (tmp_path / "pts.csv").write_text("\n".join(lines) + "\n")
    (tmp_path / "a.yaml").write_text("point_cloud: {file: pts.npy}\n")
    (tmp_path / "b.yaml").write_text("point_cloud: {file: pts.csv}\n")
    a, b = load_body(tmp_path / "a.yaml").props, load_body(tmp_path / "b.yaml").props
    np.testing.assert_array_equal(a.center_of_mass, b.center_of_mass)
    np.testing.assert_array_equal(a.inertia_about_com, b.inertia_about_com)
    M, com, I = direct_sums(masses, positions)
    assert a.mass == pytest.approx(M, rel=1e-14)
    np.testing.assert_allclose(a.inertia_about_com, I, rtol=0, atol=1e-13 * np.max(np.abs(I)))


def test_a_cloud_and_parts_together_and_a_path_relative_to_the_spec(tmp_path, monkeypatch):
    (tmp_path / "data").mkdir()
    write_csv(tmp_path / "data" / "pts.csv", [1.0, 3.0], [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]])
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "parts:\n  - {shape: point, mass: 2.0, position: [2.0, 0.0, 0.0]}\n"
        "point_cloud: {file: data/pts.csv}\n"
    )
    monkeypatch.chdir("/")  # the cloud is found next to the spec, not in the working folder
    body = load_body(spec)
    M, com, I = direct_sums([2.0, 1.0, 3.0], [[2.0, 0, 0], [0, 0, 1.0], [0, 0, -1.0]])
    assert body.props.mass == M
    np.testing.assert_allclose(body.props.center_of_mass, com, rtol=0, atol=1e-15)
    np.testing.assert_allclose(body.props.inertia_about_com, I, rtol=0, atol=1e-14)


def test_a_large_cloud_matches_the_vectorised_definition(tmp_path):
    # 10⁵ points through the CSV reader (a check of the arithmetic at size, not of speed).
    rng = np.random.default_rng(5)
    n = 100_000
    table = np.column_stack(
        (rng.uniform(0.5, 1.5, n), rng.normal(size=(n, 3)) * [1.0, 2.0, 0.5] + [10.0, 0, 0])
    )
    np.savetxt(tmp_path / "big.csv", table, delimiter=",", fmt="%.17g", header="mass,x,y,z", comments="")
    (tmp_path / "big.yaml").write_text("point_cloud: {file: big.csv}\n")
    props = load_body(tmp_path / "big.yaml").props
    m, p = table[:, 0], table[:, 1:]
    com = m @ p / m.sum()
    d = p - com
    I = np.einsum("n,n->", m, np.einsum("ni,ni->n", d, d)) * np.eye(3) - np.einsum("n,ni,nj->ij", m, d, d)
    assert props.mass == pytest.approx(m.sum(), rel=1e-13)
    np.testing.assert_allclose(props.center_of_mass, com, rtol=1e-13)
    np.testing.assert_allclose(props.inertia_about_com, I, rtol=0, atol=1e-12 * np.max(np.abs(I)))


@pytest.mark.parametrize(
    "content, expected",
    [
        ("mass,x,y\n1,2,3\n", "header must name the columns mass, x, y, z (missing z"),
        ("mass,x,y,z\n1,0,0,0\n2,0,abc,0\n", "line 3: column 3: must be a number"),
        ("mass,x,y,z\n1,0,0,0\n2,0,0\n", "line 3: has 3 columns"),
        ("mass,x,y,z\n1,0,0,0\n-2,0,0,0\n", "point 1: mass: must be greater than 0"),
        ("mass,x,y,z\n1,0,0,0\n0,0,0,0\n", "point 1: mass: must be greater than 0"),
        ("mass,x,y,z\n1,0,nan,0\n", "point 0: y: must be a finite number"),
        ("mass,x,y,z\n", "holds no points"),
        ("", "file is empty"),
    ],
)
def test_bad_csv_clouds_are_one_line_errors(tmp_path, content, expected):
    (tmp_path / "pts.csv").write_text(content)
    (tmp_path / "body.yaml").write_text("point_cloud: {file: pts.csv}\n")
    with pytest.raises(InputError) as error:
        load_body(tmp_path / "body.yaml")
    message = str(error.value)
    assert expected in message
    assert message.startswith(f"{tmp_path / 'body.yaml'}: point_cloud: file: pts.csv: ")
    assert "\n" not in message


def test_bad_npy_clouds_and_missing_files(tmp_path):
    np.save(tmp_path / "flat.npy", np.ones(8))
    (tmp_path / "a.yaml").write_text("point_cloud: {file: flat.npy}\n")
    with pytest.raises(InputError, match=r"shape \(N, 4\).*got shape \(8,\)"):
        load_body(tmp_path / "a.yaml")
    (tmp_path / "b.yaml").write_text("point_cloud: {file: nowhere.csv}\n")
    with pytest.raises(InputError, match="point_cloud: file: nowhere.csv: no such file"):
        load_body(tmp_path / "b.yaml")


def test_a_spec_needs_parts_or_a_cloud_and_the_cli_says_so(tmp_path):
    (tmp_path / "empty.yaml").write_text("name: nothing\nparts: []\n")
    proc = run_rbi("inertia", tmp_path / "empty.yaml")
    assert proc.returncode == 2
    assert "parts: must be a non-empty list of parts (or give a point_cloud" in proc.stderr
    assert "Traceback" not in proc.stderr
    (tmp_path / "bad.yaml").write_text("point_cloud: {file: pts.csv, colour: red}\n")
    proc = run_rbi("inertia", tmp_path / "bad.yaml")
    assert proc.returncode == 2
    assert "point_cloud.colour: unknown field" in proc.stderr


# -- hostile or odd cloud files: each refused with one line before the expensive work -----------


def _spec_for(tmp_path, file):
    (tmp_path / "body.yaml").write_text(f"point_cloud: {{file: {file}}}\n")
    return tmp_path / "body.yaml"


def test_an_empty_npy_cloud_is_refused(tmp_path):
    np.save(tmp_path / "empty.npy", np.zeros((0, 4)))
    with pytest.raises(InputError, match="empty.npy: holds no points"):
        load_body(_spec_for(tmp_path, "empty.npy"))


def test_an_npy_header_claiming_more_rows_than_the_file_holds_is_refused_before_allocating(tmp_path):
    from numpy.lib import format as npy

    path = tmp_path / "liar.npy"
    with open(path, "wb") as stream:
        npy.write_array_header_1_0(stream, {"descr": "<f8", "fortran_order": False, "shape": (10**11, 4)})
        stream.write(np.ones(8).tobytes())  # 2 points' worth of data, not 10¹¹
    with pytest.raises(InputError, match=r"header says 100,000,000,000 points .* holds 64 bytes"):
        load_body(_spec_for(tmp_path, "liar.npy"))


def test_a_truncated_or_structured_npy_is_refused_without_its_field_names(tmp_path):
    np.save(tmp_path / "cut.npy", np.ones((10, 4)))
    (tmp_path / "cut.npy").write_bytes((tmp_path / "cut.npy").read_bytes()[:-8])
    with pytest.raises(InputError, match="header says 10 points"):
        load_body(_spec_for(tmp_path, "cut.npy"))
    np.save(tmp_path / "rec.npy", np.zeros((3, 4), dtype=[("hidden_field_name", "f8")]))
    with pytest.raises(InputError) as error:
        load_body(_spec_for(tmp_path, "rec.npy"))
    assert "hidden_field_name" not in str(error.value) and "shape (N, 4)" in str(error.value)


def test_a_csv_cloud_with_a_byte_order_mark_is_the_same_cloud(tmp_path):
    write_csv(tmp_path / "plain.csv", [1.0, 3.0], [[0, 0, 1.0], [0, 2.0, -1.0]])
    (tmp_path / "bom.csv").write_bytes(b"\xef\xbb\xbf" + (tmp_path / "plain.csv").read_bytes())
    (tmp_path / "a.yaml").write_text("point_cloud: {file: plain.csv}\n")
    (tmp_path / "b.yaml").write_text("point_cloud: {file: bom.csv}\n")
    a, b = load_body(tmp_path / "a.yaml").props, load_body(tmp_path / "b.yaml").props
    assert b.mass == a.mass == 4.0
    np.testing.assert_array_equal(b.center_of_mass, [0.0, 1.5, -0.5])
    np.testing.assert_array_equal(b.inertia_about_com, a.inertia_about_com)


def test_a_column_named_twice_is_refused(tmp_path):
    (tmp_path / "twice.csv").write_text("mass,x,y,z,x\n1,0,0,0,5\n")
    with pytest.raises(InputError, match="line 1: column x is named twice"):
        load_body(_spec_for(tmp_path, "twice.csv"))


def test_a_binary_file_named_csv_is_refused(tmp_path):
    (tmp_path / "zeros.csv").write_bytes(b"\x00" * 100_000)
    with pytest.raises(InputError, match="binary data"):
        load_body(_spec_for(tmp_path, "zeros.csv"))
