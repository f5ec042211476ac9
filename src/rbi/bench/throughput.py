"""Mass-property throughput: bodies of many point masses and of many solid parts.

Point clouds (10³ … 10⁶ points): the core's vectorised reduction (mass, centre of mass,
inertia, principal axes) on arrays in memory, and the whole load from a spec file that names
a CSV or ``.npy`` cloud (:mod:`rbi.formats.point_cloud`). Solid parts (10³ … 10⁵ cones,
cylinders and points written out in YAML, and the same spec as JSON): what reading,
validating and translating such a spec costs, step by step.

Every body is random but seeded, so two runs time the same work.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from rbi.bench import Progress
from rbi.bench.largespec import load_steps, spec_text
from rbi.bench.timing import measure
from rbi.core.inertia import centre_of_mass, principal_axes
from rbi.core.mass import combine
from rbi.spec.load import load_body

CLOUDS = {True: (10**3, 10**4, 10**5), False: (10**3, 10**4, 10**5, 10**6)}
"""Points in each cloud: quick run, full run."""
PARTS = {True: (10**3,), False: (10**4, 10**5)}
"""Parts in each spec of solid parts: quick run, full run."""
CSV_FORMAT = "%.10g"
"""Digits written to the generated CSV clouds (a scanner or CAD export carries about this many;
full double precision, %.17g, makes the file about 1.7 times larger and slower to parse)."""


def random_cloud(n: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """``n`` positive masses (kg) and positions (m) scattered around a point off the origin."""
    rng = np.random.default_rng(seed)
    masses = rng.uniform(0.5, 1.5, n) / n
    positions = rng.normal(size=(n, 3)) * [0.3, 0.2, 0.1] + [1.0, -2.0, 0.5]
    return masses, positions


def core_timings(masses: np.ndarray, positions: np.ndarray) -> dict:
    """Median seconds of each step of the in-memory reduction (``combine_s``: mass, centre of
    mass and inertia together; ``total_s``: that and the principal axes)."""

    props = combine(masses, positions)
    steps = {
        "mass_s": lambda: masses.sum(),
        "com_s": lambda: centre_of_mass(masses, positions),
        "combine_s": lambda: combine(masses, positions),
        "principal_s": lambda: principal_axes(props.inertia_about_com),
        "total_s": lambda: principal_axes(combine(masses, positions).inertia_about_com),
    }
    out = {key: measure(step).median for key, step in steps.items()}
    return out | {"ns_per_point": 1e9 * out["total_s"] / masses.size}


def write_cloud(folder: Path, masses: np.ndarray, positions: np.ndarray) -> dict[str, Path]:
    """A CSV and a ``.npy`` cloud of the same points, and a spec naming each."""
    table = np.column_stack((masses, positions))
    csv_path = folder / "cloud.csv"
    np.savetxt(csv_path, table, delimiter=",", fmt=CSV_FORMAT, header="mass,x,y,z", comments="")
    np.save(folder / "cloud.npy", table)
    specs = {kind: folder / f"cloud_{kind}.yaml" for kind in ("csv", "npy")}
    for kind, spec in specs.items():
        spec.write_text(f"name: cloud-{masses.size}\npoint_cloud: {{file: cloud.{kind}}}\n")
    return specs


def file_timings(specs: dict[str, Path], repeats: int) -> dict:
    """Median seconds to load each spec (YAML, cloud file, validation, reduction) and find the
    principal axes: what ``rbi principal`` spends after start-up."""

    out = {}
    for kind, spec in specs.items():
        load = measure(lambda: principal_axes(load_body(spec).props.inertia_about_com), repeats, repeats, 0.0)
        out[f"load_{kind}_s"] = load.median
    out["csv_megabytes"] = (specs["csv"].parent / "cloud.csv").stat().st_size / 1e6
    return out


def check_against_direct_sum(specs: dict[str, Path], masses: np.ndarray, positions: np.ndarray) -> float:
    """Largest relative difference between the loaded body's inertia and a direct
    ``Σ m (|d|² E − d dᵀ)`` (a guard that the timed code computes the right thing)."""

    props = load_body(specs["npy"]).props
    com = masses @ positions / masses.sum()
    d = positions - com
    second = (d * masses[:, None]).T @ d
    direct = np.trace(second) * np.eye(3) - second
    return float(np.max(np.abs(props.inertia_about_com - direct)) / np.max(np.abs(direct)))


def point_cloud(n: int, progress: Progress, tmp: Path) -> dict:
    """The row of a cloud of ``n`` random point masses: the in-memory reduction step by step,
    then the whole load of a CSV and a ``.npy`` spec naming the cloud."""
    progress(f"point cloud of {n:,} points")
    masses, positions = random_cloud(n)
    row = {"points": n} | core_timings(masses, positions)
    folder = tmp / f"cloud{n}"
    folder.mkdir()
    specs = write_cloud(folder, masses, positions)
    row |= file_timings(specs, repeats=3)
    row["relative_difference_to_direct_sum"] = check_against_direct_sum(specs, masses, positions)
    return row


def scaling_exponent(rows: list[dict], key: str = "total_s") -> float | None:
    """Slope of log(time) against log(size) over the sizes ≥ 10⁴ (1 = linear); smaller
    bodies are dominated by fixed per-call costs."""
    pts = [(r["points"], r[key]) for r in rows if r["points"] >= 10**4 and r[key] > 0]
    if len(pts) < 2:
        return None
    x, y = np.log10(np.array(pts, dtype=float)).T
    return float(np.polyfit(x, y, 1)[0])


def solid_parts(n: int, progress: Progress, tmp: Path) -> dict:
    """Seconds for each step of loading a spec of ``n`` parts, once each (these are slow)."""

    progress(f"spec of {n:,} parts in YAML")
    path = tmp / f"parts{n}.yaml"
    path.write_text(spec_text(n, "cone,cylinder,point", seed=1))
    steps, raw, body = load_steps(str(path))
    parts = body.elements  # one stack
    core = measure(lambda: principal_axes(parts.sum().inertia_about_com))
    total = sum(steps.values())
    # The same spec as one JSON object (also valid YAML), as a generating program would write it.
    as_json = path.with_suffix(".json")
    as_json.write_text(json.dumps(raw))
    json_s = sum(load_steps(str(as_json))[0].values())
    return {
        "parts": n,
        "yaml_megabytes": path.stat().st_size / 1e6,
        "read_yaml_s": steps["read"],
        "validate_s": steps["validate"],
        "translate_s": steps["translate"],
        "load_total_s": total,
        "us_per_part": 1e6 * total / n,
        "load_total_json_s": json_s,
        "core_s": core.median,
    }


def _warm_up_loader(folder: Path) -> None:
    """Import and exercise the loader once, so the timings exclude one-off import costs."""

    spec = folder / "warm.yaml"
    spec.write_text(spec_text(2, "point"))
    load_body(spec)


def run(quick: bool, progress: Progress, folder: Path) -> dict:
    _warm_up_loader(folder)
    clouds = [point_cloud(n, progress, folder) for n in CLOUDS[quick]]
    parts = [solid_parts(n, progress, folder) for n in PARTS[quick]]
    return {
        "point_clouds": clouds,
        "scaling_exponent": scaling_exponent(clouds),
        "csv_format": CSV_FORMAT,
        "solid_parts": parts,
    }
