"""Every command against random input: random YAML/JSON documents (from nonsense to nearly valid
bodies), random bytes and random option values, run in-process in a fresh folder.

Whatever comes in, rbi must: exit 0 or 2 (1 only for a failed `rbi check`); on failure print
exactly one line on stderr and write nothing; never print a traceback or an internal error;
leave no temporary file; print valid JSON whenever `--format json` succeeds.

The command list comes from ``rbi.cli.app.COMMANDS``, and each command's options from its
own parameters, so a new command or option is fuzzed without touching this file. Values are
drawn per option name where rbi has a meaning for the name (kept small: tiny durations, few
samples and runs, so the whole file runs in well under a minute), else from a generic pool.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import shutil
import tempfile
from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rbi.cli.app import COMMANDS
from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as rbi

EXCLUDED = {
    "bench": "takes no spec and measures the machine for seconds to minutes (its refusals are "
    "tested in tests/files/test_writes.py)",
}
OPTIONS_NOT_FUZZED = {
    "--dask": "starts a cluster or dials a network address",
    "--help": "prints help and exits 0 whatever else is given",
    "--workers": "drawn separately (1 or junk): more processes would only slow the run",
}
FUZZED = [name for name in COMMANDS if name not in EXCLUDED]
LISTS_PROBLEMS_ON_STDOUT = {"validate"}
"""Commands whose output is the list of problems (one per line on stdout, exit 2 when there is
any) with at most a one-line summary on stderr."""

EXAMPLES = int(os.environ.get("RBI_FUZZ_EXAMPLES", "12"))


# --- documents ------------------------------------------------------------------------------------


def _numbers():
    return st.one_of(
        st.integers(-5, 5),
        st.floats(-1e3, 1e3, allow_nan=False),
        st.sampled_from([0, -0.0, 1e-300, 1e300, -1, 0.5, 1e160, float("inf"), float("nan")]),
    )


def _vectors():
    return st.lists(_numbers(), min_size=0, max_size=4)


SHAPES = [
    "point",
    "sphere",
    "cylinder",
    "box",
    "cone",
    "rod",
    "custom",
    "shell",
    "torus",
    "hemisphere",
    "capsule",
    "mesh",
    "point_cloud",
    "tube",
    "nonsense",
]
FIELDS = [
    "mass",
    "density",
    "radius",
    "inner_radius",
    "length",
    "size",
    "center",
    "position",
    "start",
    "end",
    "apex",
    "base",
    "axis",
    "rotation",
    "inertia",
    "subtract",
    "file",
    "major_radius",
    "minor_radius",
    "pattern",
    "scale",
    "material",
    "name",
    "thickness",
]


def _field_values():
    return st.one_of(
        _numbers(),
        _vectors(),
        st.booleans(),
        st.none(),
        st.text(max_size=8),
        st.fixed_dictionaries(
            {},
            optional={
                "axis": _vectors(),
                "angle_deg": _numbers(),
                "quaternion": _vectors(),
                "count": st.integers(-2, 5),
                "step": _vectors(),
                "through": _vectors(),
            },
        ),
    )


def _nearly_valid_bodies():
    part = st.fixed_dictionaries(
        {"shape": st.sampled_from(SHAPES)}, optional={f: _field_values() for f in FIELDS}
    )
    body = st.fixed_dictionaries(
        {"parts": st.lists(part, min_size=0, max_size=4)},
        optional={
            "name": st.text(max_size=10),
            "pivot": _vectors(),
            "units": st.fixed_dictionaries(
                {},
                optional={
                    "length": st.sampled_from(["m", "mm", "in", "x"]),
                    "mass": st.sampled_from(["kg", "g", "lb", "?"]),
                },
            ),
            "expect": st.fixed_dictionaries(
                {},
                optional={
                    "mass": st.fixed_dictionaries(
                        {"value": _numbers(), "tol": st.sampled_from([0.1, "1%", "x"])}
                    )
                },
            ),
        },
    )
    return body


def _json_values():
    return st.recursive(
        st.one_of(st.none(), st.booleans(), st.integers(), st.floats(allow_nan=False), st.text(max_size=10)),
        lambda children: (
            st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=8), children, max_size=4)
        ),
        max_leaves=20,
    )


def _valid_body_texts():
    return st.sampled_from(sorted(p.read_text() for p in BODIES.glob("*.yaml")))


def _robot_texts():
    return st.sampled_from(sorted(p.read_text() for p in BODIES.glob("*.urdf")))


URDF = """<robot name="r"><link name="{name}"><inertial><origin xyz="{x} 0 0"/><mass value="{mass}"/>
<inertia ixx="{i}" iyy="{i}" izz="{i}" ixy="0" ixz="0" iyz="0"/></inertial></link></robot>"""


def _documents():
    """(file name, bytes) of a spec: a bundled body, a body with random fields, any YAML or JSON
    value, random bytes, or a small robot description."""
    as_yaml = lambda v: yaml.safe_dump(v, allow_unicode=True).encode()  # noqa: E731
    as_json = lambda v: json.dumps(v).encode()  # noqa: E731
    return st.one_of(
        st.tuples(st.just("body.yaml"), _valid_body_texts().map(str.encode)),
        st.tuples(st.just("body.yaml"), _nearly_valid_bodies().map(as_yaml)),
        st.tuples(st.just("body.json"), _nearly_valid_bodies().map(as_json)),
        st.tuples(st.sampled_from(["doc.yaml", "doc.json"]), _json_values().map(as_json)),
        st.tuples(st.sampled_from(["doc.yaml", "doc.yml"]), _json_values().map(as_yaml)),
        st.tuples(st.sampled_from(["raw.yaml", "raw.json", "raw.urdf"]), st.binary(max_size=200)),
        st.tuples(st.just("arm.urdf"), _robot_texts().map(str.encode)),
        st.tuples(
            st.just("robot.urdf"),
            st.builds(
                lambda name, x, mass, i: URDF.format(name=name, x=x, mass=mass, i=i).encode(),
                st.sampled_from(["base", "a&b", "x\x1b[2J"]),
                _numbers(),
                _numbers(),
                _numbers(),
            ),
        ),
    )


# --- option values --------------------------------------------------------------------------------

JUNK = st.sampled_from(
    [
        "",
        "x",
        "nan",
        "inf",
        "-1",
        "0",
        "1e400",
        "1,2",
        "1,2,3,4",
        "a,b,c",
        "=1+1",
        "\x1b]0;t\x07",
        "-",
        "--",
        "10" * 30,
        "1_000",
        "0x10",
        "１",
    ]
)


def _mostly(*valid):
    """Valid values three times as likely as junk, so runs get past option parsing."""
    good = st.sampled_from(list(valid))
    return st.one_of(good, good, good, JUNK)


GOOD_VECTOR = st.tuples(*[st.sampled_from([0, 1, -2, 0.5, 10, 1e-9])] * 3).map(
    lambda v: ",".join(map(str, v))
)
VECTORS = st.one_of(
    GOOD_VECTOR,
    GOOD_VECTOR,
    st.tuples(_numbers(), _numbers(), _numbers()).map(lambda v: ",".join(map(str, v))),
    JUNK,
)
BAD_OUTPUTS = [
    "out.json",
    "out.yaml",
    "out",
    "-",
    "",
    "body.yaml",
    "/dev/null",
    "missing/x.csv",
    ".",
    "x" * 300 + ".csv",
    "/sys/x.csv",
]


def _outputs(*good):
    return st.one_of(st.sampled_from(list(good)), st.sampled_from(list(good)), st.sampled_from(BAD_OUTPUTS))


BY_NAME = {
    "--format": _mostly("table", "json", "csv"),
    "--method": _mostly("default", "rk45", "dop853", "exact"),
    "--to": _mostly("urdf", "mjcf", "sdf"),
    "--tilt-axis": _mostly("x", "y"),
    "--about": st.one_of(_mostly("com", "origin", "pivot"), VECTORS),
    "--units": _mostly("SI", "mm,g", "in,lb", "cm,kg"),
    "--rotate": _mostly("principal", "x:90", "1,0,0:30", "0,0,1:-45"),
    "--omega": VECTORS,
    "--velocity": VECTORS,
    "--alpha": VECTORS,
    "--accel": VECTORS,
    "--force": VECTORS,
    "--torque": VECTORS,
    "--axis": VECTORS,
    "--spin": _mostly("0", "10", "200", "-50", "1e9", "1e300", "100:200:3", "0:1:2"),
    "--tilt": _mostly("0", "5", "90", "180", "-10", "0:10:2", "1:2:1000000000"),
    "--gravity": _mostly("0", "9.81", "1.62", "1e300"),
    "--duration": _mostly("0", "0.01", "0.05", "1e9", "1e-300"),
    "--samples": _mostly("1", "2", "11", "0", "1e23", "2e7", "3.5"),
    "--max-steps": _mostly("1", "100", "10000", "0", "1e99"),
    "--rtol": _mostly("1e-12", "1e-15", "1e-16", "1e-6", "0.5"),
    "--runs": _mostly("1", "3", "0", "1e12"),
    "--seed": _mostly("0", "42", "-1"),
    "--vary": _mostly(
        "parts.cone.mass=0.1:0.5:2",
        "parts.bolt.mass=normal(0.02,0.001)",
        "parts.bolt.position[0]=0:0.1:2",
        "mass=1",
        "parts..=1:2:3",
    ),
    "--speed": _mostly("0.5", "1", "0", "1e9"),
    "--fps": _mostly("1", "5", "0", "1000"),
    "--link": _mostly("base", "nope"),
    "--products": _mostly("tensor", "cad"),
    "--only": _mostly("latency"),
}
GENERIC = st.one_of(
    JUNK, VECTORS, _mostly("0", "1", "0.05"), _outputs("out.csv", "out.png"), st.text(max_size=10)
)


def _command_parameters(name: str):
    import typer._click as click
    import typer.main

    from rbi.cli.app import app

    group = typer.main.get_command(app)
    return group.get_command(click.Context(group), name).params


def _option_arguments(name: str):
    """A strategy for a random selection of ``name``'s options with random values."""
    choices, required_options = [], []
    for param in _command_parameters(name):
        opts = [o for o in param.opts if o.startswith("--")]
        if not opts or opts[0] in OPTIONS_NOT_FUZZED or param.param_type_name != "option":
            continue
        option = opts[0]
        if getattr(param, "is_flag", False):
            flags = [option, *getattr(param, "secondary_opts", [])]
            choices.append(st.sampled_from(flags).map(lambda f: [f]))
        else:
            values = BY_NAME.get(option)
            if values is None:
                values = _output_values(param)
            if values is None:
                values = GENERIC
            choices.append(values.map(lambda v, o=option: [o, v]))
            if getattr(param, "required", False):  # present in most runs, so the run gets going
                required_options.append(
                    (param, st.one_of(choices[-1], choices[-1], choices[-1], st.just([])))
                )
    if any(o == "--workers" for p in _command_parameters(name) for o in p.opts):
        choices.append(st.sampled_from([["--workers", "1"], ["--workers", "0"], ["--workers", "x"]]))
    required = [option_strategy for param, option_strategy in required_options]
    chosen = st.lists(st.one_of(choices), max_size=4) if choices else st.just([])
    return st.tuples(st.tuples(*required) if required else st.just(()), chosen).map(
        lambda both: [a for group in (*both[0], *both[1]) for a in group]
    )


def _output_values(param):
    """For an option whose metavar names file extensions (``FILE.html|FILE.gif``, ``DIR|FILE.yaml``):
    files of those kinds, a new folder's name, or a path rbi must refuse."""
    metavar = str(param.metavar or "")
    extensions = re.findall(r"\.([a-z0-9]+)", metavar)
    if not extensions:
        return None
    good = [f"out.{e}" for e in extensions] + (["outdir"] if "DIR" in metavar else [])
    return _outputs(*good)


def _takes_a_file(name: str) -> bool:
    return any(p.param_type_name == "argument" for p in _command_parameters(name))


# --- the property ---------------------------------------------------------------------------------


def _listing(folder: Path) -> dict[str, bytes]:
    return {
        str(p.relative_to(folder)): (p.read_bytes() if p.is_file() else b"")
        for p in sorted(folder.rglob("*"))
    }


def _check_run(command: str, document, options: list[str]) -> None:
    file_name, content = document
    with tempfile.TemporaryDirectory(prefix="rbi-fuzz-") as temp, contextlib.chdir(temp):
        folder = Path(temp)
        args = [command]
        if _takes_a_file(command):
            for companion in BODIES.iterdir():  # files the bundled bodies name (meshes)
                if companion.suffix not in (".yaml", ".yml"):
                    shutil.copy(companion, folder / companion.name)
            (folder / file_name).write_bytes(content)
            args.append(file_name)
        args += options
        before = _listing(folder)
        proc = rbi(*args)
        after = _listing(folder)
    shown = f"rbi {' '.join(map(repr, args))} -> exit {proc.returncode}\nstderr: {proc.stderr!r}"
    allowed = (0, 1, 2) if command == "check" else (0, 2)
    assert proc.returncode in allowed, shown
    assert "Traceback" not in proc.stderr and "internal error" not in proc.stderr, shown
    assert not any(Path(name).name.startswith(".rbi-") for name in after), (shown, sorted(after))
    if proc.returncode == 2 and command not in LISTS_PROBLEMS_ON_STDOUT:
        assert len(proc.stderr.strip().splitlines()) == 1, shown
        assert proc.stderr.startswith("rbi: "), shown
    assert len(proc.stderr.strip().splitlines()) <= 1 or proc.returncode == 0, shown
    if proc.returncode != 0:
        assert after == before, (shown, sorted(set(after) ^ set(before)))
    formats = [options[i + 1] for i, o in enumerate(options[:-1]) if o in ("--format", "-f")]
    if proc.returncode == 0 and formats and formats[-1] == "json":
        json.loads(proc.stdout)


@pytest.mark.parametrize("command", FUZZED)
def test_any_input_is_a_result_or_one_line_exit_2(command):
    options = _option_arguments(command)

    @settings(
        max_examples=EXAMPLES,
        deadline=None,
        derandomize=True,
        database=None,
        suppress_health_check=list(HealthCheck),
    )
    @given(document=_documents(), options=options)
    def run(document, options):
        _check_run(command, document, options)

    run()


@pytest.mark.parametrize("command", FUZZED)
def test_valid_bodies_with_random_options(command):
    """Bundled bodies (so the options, not the spec, decide the outcome)."""
    options = _option_arguments(command)

    @settings(
        max_examples=EXAMPLES,
        deadline=None,
        derandomize=True,
        database=None,
        suppress_health_check=list(HealthCheck),
    )
    @given(document=st.tuples(st.just("body.yaml"), _valid_body_texts().map(str.encode)), options=options)
    def run(document, options):
        _check_run(command, document, options)

    run()


def test_the_fuzzed_commands_are_every_command_but_the_excluded():
    assert set(FUZZED) | set(EXCLUDED) == set(COMMANDS)
    assert all(reason for reason in EXCLUDED.values())


def test_found_by_fuzzing_animate_with_a_huge_duration(tmp_path):
    """Found by this fuzz test (a MemoryError, exit 1); fixed: a GIF's frame count is bounded first."""
    with contextlib.chdir(tmp_path):
        proc = rbi("animate", BODIES / "dumbbell.yaml", "--out", "out.gif", "--duration", "1e9")
    assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("mode", [["--force", "0,0,0"], ["--torque", "0,0,1"], ["--alpha", "0,0,1"]])
def test_found_by_fuzzing_dynamics_about_a_far_point(mode):
    """Found by this fuzz test (numpy's SVD met inf: LinAlgError, exit 1); fixed: an inertia
    about the point that overflows is refused, naming --about."""
    proc = rbi("dynamics", BODIES / "top.yaml", *mode, "--about", "0,1e300,0")
    assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    assert "--about" in proc.stderr
