"""`rbi uncertainty` and `Body.uncertainty`: the contract's JSON, reproducible draws, bad input."""

from __future__ import annotations

import json

import pytest

import rbi
from tests.conftest import BODIES, one_line_exit_2, run_rbi, run_rbi_inprocess

TOLERANCED = BODIES / "top_bolted_toleranced.yaml"


def test_json_is_the_contracts_form():
    out = json.loads(run_rbi_inprocess("uncertainty", TOLERANCED, "-f", "json").stdout)
    # the contract's keys, then the warnings every body's JSON carries (third round)
    assert list(out) == ["name", "units", "method", "samples", "quantities", "warnings"]
    assert out["warnings"] == [] and out["method"] == "linear" and out["samples"] is None
    names = [q["quantity"] for q in out["quantities"]]
    assert names[:4] == ["mass", "center_of_mass[0]", "center_of_mass[1]", "center_of_mass[2]"]
    assert "inertia[0][2]" in names and names[-3:] == ["moments[0]", "moments[1]", "moments[2]"]
    mass = out["quantities"][0]
    assert list(mass) == ["quantity", "value", "u", "interval", "coverage", "contributions"]
    assert mass["value"] == pytest.approx(0.52) and mass["u"] == pytest.approx(0.001, rel=1e-12)
    assert mass["interval"] == pytest.approx([0.52 - 1.959964 * 0.001, 0.52 + 1.959964 * 0.001], rel=1e-7)
    top = mass["contributions"][0]
    assert list(top) == ["input", "value", "u", "sensitivity", "contribution", "share"]
    assert top["input"] == "parts.bolt.mass" and top["share"] == pytest.approx(1.0)
    ixz = out["quantities"][names.index("inertia[0][2]")]
    ranked = [c["contribution"] for c in ixz["contributions"]]
    assert ranked == sorted(ranked, reverse=True)
    assert sum(c["share"] for c in ixz["contributions"]) == pytest.approx(1.0)
    # Ixz = -Σ m x z about the CoM: only the bolt moves it; by hand (-Σ m x z + M x_c z_c), ∂Ixz/∂z_bolt = -m_b (x_b - x_c)
    m_b, big_m, x_b = 0.02, 0.52, 0.04
    x_c = m_b * x_b / big_m
    by_z = next(c for c in ixz["contributions"] if c["input"] == "parts.bolt.position[2]")
    assert by_z["sensitivity"] == pytest.approx(-m_b * (x_b - x_c), rel=1e-9)


def test_monte_carlo_is_reproducible_and_says_whether_linear_is_validated():
    args = ("uncertainty", TOLERANCED, "--of", "mass", "--of", "inertia[0][2]", "--method", "monte-carlo")
    first = json.loads(run_rbi_inprocess(*args, "--seed", "7", "--samples", "20000", "-f", "json").stdout)
    again = json.loads(run_rbi_inprocess(*args, "--seed", "7", "--samples", "20000", "-f", "json").stdout)
    assert first == again and first["samples"] == 20000
    for q in first["quantities"]:
        low, high = q["interval"]
        assert low < q["value"] < high and isinstance(q["linear"]["validated"], bool)
    table = run_rbi_inprocess(*args, "--seed", "7", "--samples", "20000").stdout
    assert "linear ok" in table and "Monte Carlo, 20,000 draws" in table


@pytest.mark.parametrize("method", ["linear", "monte-carlo"])
def test_every_quantity_has_its_unit_and_the_tables_fit_80_columns(method, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    args = ("uncertainty", TOLERANCED, "--method", method, "--samples", "2000", "--seed", "1")
    table = run_rbi_inprocess(*args).stdout
    assert max(len(line) for line in table.splitlines()) <= 80
    header, rows = first_table(table)
    assert header[:4] == ["quantity", "unit", "value", "u"]  # no header cut
    units = {row[0]: row[1] for row in rows}
    assert units["mass"] == "kg" and units["center_of_mass[2]"] == "m" and units["moments[0]"] == "kg·m²"


def first_table(text: str) -> tuple[list[str], list[list[str]]]:
    """The header cells and rows of the first table rbi printed (title, header, rule, rows:
    each row a line indented by one space, its cells apart by spaces; no cell here holds one)."""
    lines = text.splitlines()
    rule = next(k for k, line in enumerate(lines) if line.startswith("─"))
    rows = []
    for line in lines[rule + 1 :]:
        if not line.startswith(" "):  # the next table's title
            break
        rows.append(line.split())
    return lines[rule - 1].split(), rows


def test_api_gives_the_same():
    body = rbi.load(TOLERANCED)
    result = body.uncertainty(of=["inertia[0][2]"])
    cli = json.loads(
        run_rbi_inprocess("uncertainty", TOLERANCED, "--of", "inertia[0][2]", "-f", "json").stdout
    )
    assert result.to_dict() == cli
    frame = result.to_pandas()
    assert list(frame["input"]) == [c["input"] for c in cli["quantities"][0]["contributions"]]
    assert "inertia[0][2]" in str(result)


@pytest.mark.parametrize(
    "args, word",
    [
        (("--of", "volume"), "--of"),
        (("--method", "bayes"), "--method"),
        (("--samples", "1"), "--samples"),
        (("--coverage", "1.5"), "--coverage"),
    ],
)
def test_bad_options(args, word):
    one_line_exit_2(run_rbi_inprocess("uncertainty", TOLERANCED, *args), word)


@pytest.mark.parametrize("bad", ['"0.04 ± -1"', '"± 3"', '"1 ± 2 ± 3"', '"0.04 ± nan"'])
def test_bad_plus_minus_exit_2(write_spec, bad):
    text = TOLERANCED.read_text().replace("0.04 ± 0.0005", bad, 1)
    for command in ("uncertainty", "inertia"):
        one_line_exit_2(run_rbi(command, write_spec(text)), "body.yaml", "parts[0] (cone)", "radius")


def test_plus_minus_on_a_name_exit_2(write_spec):
    text = TOLERANCED.read_text().replace("name: bolt", "name: bolt ± 1")
    one_line_exit_2(run_rbi_inprocess("inertia", write_spec(text)), "parts[2]", "name")


def test_inertia_and_principal_carry_uncertainty_only_with_plus_minus():
    inertia = json.loads(run_rbi_inprocess("inertia", TOLERANCED, "-f", "json").stdout)["uncertainty"]
    assert list(inertia) == ["mass", "center_of_mass", "inertia"]
    assert inertia["mass"] == pytest.approx(0.001, rel=1e-12)
    # Ixx of the cone about its own CoM is 3/80 m (4 r² + h²): ∂/∂r = 3/10 m r, the only r term
    cone = 0.3 * 0.4 * 0.04 * 0.0005
    assert inertia["inertia"][0][0] > cone and inertia["inertia"][0][1] == 0.0
    principal = json.loads(run_rbi_inprocess("principal", TOLERANCED, "-f", "json").stdout)["uncertainty"]
    assert list(principal) == ["mass", "center_of_mass", "moments", "axes_deg"]
    assert all(d > 0 for d in principal["axes_deg"][:2]) and principal["axes_deg"][2] == 0.0
    plain = json.loads(run_rbi_inprocess("principal", BODIES / "top_bolted.yaml", "-f", "json").stdout)
    assert "uncertainty" not in plain
    assert "±" in run_rbi_inprocess("principal", TOLERANCED).stdout


def test_symmetric_top_axes_are_null_with_a_warning(write_spec):
    text = (BODIES / "top.yaml").read_text().replace("radius: 0.04", "radius: 0.04 ± 0.0005")
    proc = run_rbi("principal", write_spec(text), "-f", "json")
    out = json.loads(proc.stdout)
    assert out["uncertainty"]["axes_deg"].count(None) == 2
    assert sum("not determined" in w for w in out["warnings"]) == 2


def test_momentum_about_the_pivot_against_uncertainties():
    from uncertainties import ufloat

    r, m_b, x_b = ufloat(0.04, 0.0005), ufloat(0.02, 0.001), ufloat(0.04, 0.0005)
    izz = 0.3 * 0.4 * r**2 + 0.5 * 0.1 * 0.008**2 + m_b * x_b**2  # about the z axis through the pivot
    out = json.loads(
        run_rbi_inprocess(
            "momentum", TOLERANCED, "--omega", "0,0,200", "--about", "pivot", "-f", "json"
        ).stdout
    )
    spread = out["uncertainty"]
    assert list(spread) == ["mass", "center_of_mass", "angular_momentum", "kinetic_energy"]
    assert spread["angular_momentum"][2] == pytest.approx((200 * izz).std_dev, rel=1e-9)
    assert spread["kinetic_energy"] == pytest.approx((0.5 * 200**2 * izz).std_dev, rel=1e-9)


def test_parts_carry_each_parts_own_uncertainty():
    out = json.loads(run_rbi_inprocess("parts", TOLERANCED, "-f", "json").stdout)
    cone, stem, bolt = (p["uncertainty"] for p in out["parts"])
    # the cone's moments 3/80 m (4 r² + h²) and 3/10 m r²: ∂/∂r = 3/10 m r and 3/5 m r
    assert cone["inertia_about_com"][0][0] == pytest.approx(0.3 * 0.4 * 0.04 * 0.0005, rel=1e-12)
    assert cone["inertia_about_com"][2][2] == pytest.approx(0.6 * 0.4 * 0.04 * 0.0005, rel=1e-12)
    assert stem == {"mass": 0.0, "center_of_mass": [0.0] * 3, "inertia_about_com": [[0.0] * 3] * 3}
    assert bolt["mass"] == 0.001 and bolt["center_of_mass"] == [0.0005, 0.0, 0.0005]
    assert out["uncertainty"]["mass"] == pytest.approx(0.001)
    assert "uncertainty" not in json.loads(
        run_rbi_inprocess("parts", BODIES / "top_bolted.yaml", "-f", "json").stdout
    )


def _with_plus_minus(raw: dict) -> dict:
    """The spec with the first number of its first part that has one ± 1 % (its mass or numeric
    density) or ± 0.001 (a coordinate)."""
    for part in raw["parts"]:
        for field in ("mass", "density"):
            if isinstance(part.get(field), (int, float)):
                part[field] = f"{part[field]} ± 1%"
                return raw
        for field in ("position", "center", "start", "apex"):
            if field in part:
                part[field][0] = f"{part[field][0]} ± 0.001"
                return raw
    raise AssertionError(f"no number to tolerance in {raw['parts']}")


@pytest.mark.parametrize("spec", sorted(p.name for p in BODIES.glob("*.yaml") if p.name != "flange.yaml"))
def test_every_bundled_body_with_plus_minus(tmp_path, spec):
    import shutil

    import yaml

    for other in BODIES.iterdir():  # meshes, clouds and sub-assemblies beside the spec
        shutil.copy(other, tmp_path / other.name)
    path = tmp_path / spec
    path.write_text(
        yaml.safe_dump(_with_plus_minus(yaml.safe_load((BODIES / spec).read_text())), allow_unicode=True)
    )
    for args in (("inertia",), ("principal",), ("parts",), ("momentum", "--omega", "0,0,1")):
        out = json.loads(run_rbi_inprocess(*args, path, "-f", "json").stdout)
        assert "uncertainty" in out, args
        for fmt in ("table", "csv"):
            assert run_rbi_inprocess(*args, path, "-f", fmt).returncode == 0
    budget = json.loads(run_rbi_inprocess("uncertainty", path, "-f", "json").stdout)
    assert any(q["u"] > 0 for q in budget["quantities"])
    assert (
        run_rbi_inprocess("uncertainty", path, "--method", "monte-carlo", "--samples", "2000").returncode == 0
    )


def test_of_a_whole_vector_or_matrix_is_its_entries():
    body = rbi.load(TOLERANCED)
    names = [q["quantity"] for q in body.uncertainty(of=["center_of_mass", "moments[1]"]).quantities]
    assert names == ["center_of_mass[0]", "center_of_mass[1]", "center_of_mass[2]", "moments[1]"]
    assert len(body.uncertainty(of="inertia").quantities) == 9


def test_the_linear_table_gives_each_quantitys_unit(tmp_path):
    table = run_rbi_inprocess("uncertainty", TOLERANCED).stdout
    header, rows = first_table(table)  # the quantities' table
    assert header == ["quantity", "unit", "value", "u", "±", "U"]  # the last header is "± U"
    units = {row[0]: row[1] for row in rows}
    assert units["mass"] == "kg" and units["center_of_mass[2]"] == "m" and units["moments[0]"] == "kg·m²"
    spec = tmp_path / "mm.yaml"  # the file's units
    spec.write_text(
        'units: {length: mm, mass: g}\nparts: [{shape: point, mass: "2 ± 0.1", position: [1, 0, 0]}]\n'
    )
    assert "g·mm²" in run_rbi_inprocess("uncertainty", spec, "--of", "inertia[1][1]").stdout


def test_a_spec_without_plus_minus_says_so_once_in_every_form():
    """A spec with no ± has a budget of zeros: exit 0, and one warning line saying why (stderr for
    table and CSV, ``"warnings"`` in JSON), never on a spec that does write ±."""
    plain = BODIES / "top.yaml"
    for fmt in ("table", "csv"):
        result = run_rbi("uncertainty", plain, "-f", fmt)
        assert result.returncode == 0
        assert result.stderr.splitlines() == [
            "rbi: warning: the spec writes no number with ± (VALUE ± U): every uncertainty is zero"
        ]
    out = json.loads(run_rbi("uncertainty", plain, "-f", "json").stdout)
    assert all(q["u"] == 0 for q in out["quantities"]) and len(out["warnings"]) == 1
    assert json.loads(run_rbi("uncertainty", TOLERANCED, "-f", "json").stdout)["warnings"] == []
