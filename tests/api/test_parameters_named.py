"""Bad values given to the API are refused naming the parameter: rbi.SpecError for bad input,
TypeError for a value of the wrong type (issue 26's open doors)."""

from __future__ import annotations

import math
import traceback

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES


@pytest.fixture(scope="module")
def top():
    return rbi.load(BODIES / "top.yaml")


@pytest.mark.parametrize(
    "settings, name",
    [
        ({"spin": True}, "spin"),
        ({"spin": 10.0, "duration": "1"}, "duration"),
        ({"spin": 10.0, "tilt_deg": False}, "tilt_deg"),
        ({"spin": 10.0, "samples": "3"}, "samples"),
        ({"spin": 10.0, "max_steps": True}, "max_steps"),
    ],
)
def test_simulate_refuses_a_value_that_is_not_a_number_naming_it(top, settings, name):
    with pytest.raises(TypeError, match=rf"^{name}: must be"):
        rbi.simulate(top, **{"duration": 0.01, **settings})


def test_samples_are_a_whole_number_whether_int_or_float_as_the_cli_reads_them(top):
    """``--samples 481.0`` runs (the CLI reads 481.0 as 481); so does the API's ``samples=481.0``,
    with the same trajectory as ``samples=481``. A fraction or a count out of range is a
    ValueError naming ``samples`` (the kernel's words too: tests/sim/test_api.py)."""
    whole, floating = (rbi.simulate(top, spin=10.0, duration=0.5, samples=s) for s in (481, 481.0))
    assert len(floating.t) == 481 and floating.t[1] == 0.5 / 480
    np.testing.assert_array_equal(floating.q, whole.q)
    for samples, words in (
        (2.5, "samples: must be a whole number between 1 and 1,000,000 (got 2.5)"),
        (0, "samples: must be a whole number between 1 and 1,000,000 (got 0)"),
        (1e6 + 1, "samples: must be a whole number between 1 and 1,000,000 (got 1000001.0)"),
        (math.nan, "samples: must be a whole number between 1 and 1,000,000 (got nan)"),
    ):
        with pytest.raises(ValueError) as refused:
            rbi.simulate(top, spin=10.0, duration=0.01, samples=samples)
        assert str(refused.value) == words
    with pytest.raises(ValueError) as refused:
        rbi.sweep(top, spin=10.0, duration=0.01, samples=100_001)
    assert (
        str(refused.value) == "samples: must be a whole number between 1 and 100,000 for a sweep (got 100001)"
    )
    assert len(rbi.sweep(top, spin=10.0, duration=0.01, samples=3.0)) == 1


def test_an_integer_too_long_to_print_is_a_spec_error():
    with pytest.raises(rbi.SpecError, match=r"mass: must be a number \(got an integer of 5001 digits\)"):
        rbi.load({"parts": [{"shape": "point", "mass": 10**5000, "position": [0, 0, 0]}]})


def test_a_turn_lost_to_rounding_is_refused(top):
    with pytest.raises(rbi.SpecError, match="too large to be a turn"):
        top.inertia(axes=[("y", 1e300)])
    with pytest.raises(ValueError, match="^tilt_deg: .*too large to be a turn"):
        rbi.simulate(top, spin=10.0, tilt_deg=1e300, duration=0.01)
    assert top.inertia(axes=[("y", 720.0)]) == pytest.approx(top.inertia(), abs=1e-15)


def test_a_traceback_names_spec_error():
    with pytest.raises(rbi.SpecError) as caught:
        rbi.load("/nonexistent/body.yaml")
    text = "".join(traceback.format_exception(caught.value))
    assert text.splitlines()[-1] == "rbi.errors.SpecError: /nonexistent/body.yaml: no such file"
    assert rbi.SpecError.__name__ == "SpecError"


@pytest.mark.parametrize("axis, label", [("y", "final tilt of body y"), (None, "final tilt of body z")])
def test_the_trajectory_table_names_the_axis_it_tilts(top, axis, label):
    from rich.console import Console

    run = rbi.simulate(top, spin=10.0, spin_axis=axis, duration=0.01, samples=3)
    console = Console(width=120, color_system=None)
    with console.capture() as shown:
        console.print(run)
    assert label in shown.get() and shown.get().count("final tilt") == 1, shown.get()


def test_a_lone_surrogate_in_a_dict_or_text_is_a_spec_error():
    part = {"shape": "point", "mass": 1, "position": [0, 0, 0]}
    with pytest.raises(rbi.SpecError, match=r"<dict>: name: holds a lone surrogate \\ud800"):
        rbi.load({"name": "a\ud800", "parts": [part]})
    with pytest.raises(rbi.SpecError, match=r"parts\[0\]\.name: holds a lone surrogate"):
        rbi.loads('{"parts": [{"name": "\\udfff", "shape": "point", "mass": 1, "position": [0, 0, 0]}]}\n')


ARM = (
    '<robot name="arm"><link name="base"/><link name="upper"><inertial><origin xyz="0.5 0 0"/><mass value="2"/>'
    '<inertia ixx="0.01" iyy="0.2" izz="0.2" ixy="0" ixz="0" iyz="0"/></inertial></link>'
    '<joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/><axis xyz="0 1 0"/>'
    '<limit effort="100" velocity="1" lower="-3" upper="3"/></joint></robot>'
)


@pytest.mark.parametrize(
    "settings, head",
    [
        ({"geometry": "colision"}, "geometry: 'colision'"),
        ({"mesh_inertia": "rough"}, "mesh_inertia: 'rough'"),
        ({"density": -1.0}, "density: -1.0"),
        ({"density": "x"}, "density: 'x'"),
        ({"density": 1000.0, "material": "steel"}, "density and material: give one of them"),
        ({"material": "unobtanium"}, "material: unknown material 'unobtanium'"),
        ({"joints": {"elbow": 0.1}}, "joints: "),
        ({"joints": {"shoulder": "a"}}, "joints: 'shoulder=a'"),
        ({"joints": ["shoulder"]}, "joints: 'shoulder'"),
        ({"joints": 5}, "joints: expected a mapping"),
        ({"package_paths": ["nope"]}, "package_paths: 'nope'"),
        (
            {"package_paths": {"p": "/nonexistent/folder"}},
            "package_paths: p=/nonexistent/folder: no such folder",
        ),
        ({"package_paths": [5]}, "package_paths: expected"),
    ],
)
def test_audit_refuses_bad_arguments_naming_the_parameter_not_the_option(tmp_path, settings, head):
    """The audit's options checked in the API speak its parameter names (``density``,
    ``mesh_inertia``): a ValueError, never ``--density``; the CLI still names its options."""
    path = tmp_path / "arm.urdf"
    path.write_text(ARM)
    with pytest.raises(ValueError) as caught:
        rbi.audit(path, **settings)
    message = str(caught.value)
    assert message.startswith(head) and "--" not in message, message
    assert rbi.audit(path, joints={"shoulder": 0.5}).joints[0].torque == pytest.approx(
        -2 * 9.81 * 0.5 * math.cos(0.5), rel=1e-14
    )


@pytest.mark.parametrize("function", [rbi.audit, rbi.import_robot])
def test_robot_functions_name_robot_file_for_a_value_that_is_not_a_path(function):
    with pytest.raises(TypeError, match="^robot_file: expected a path"):
        function(5)


@pytest.mark.parametrize(
    "args, line",
    [
        (["--geometry", "colision"], "rbi: --geometry: 'colision': must be collision, visual or none"),
        (["--density", "1", "--material", "steel"], "rbi: --density and --material: give one of them"),
        (["--joints", "elbow=1"], "rbi: --joints: "),
        (["--package-path", "nope"], "rbi: --package-path: 'nope': give NAME=DIR"),
    ],
)
def test_the_command_line_names_its_options_for_the_same_errors(tmp_path, args, line):
    from tests.conftest import run_rbi_inprocess

    path = tmp_path / "arm.urdf"
    path.write_text(ARM)
    for form in ("table", "json", "csv"):
        proc = run_rbi_inprocess("audit", str(path), "--format", form, *args)
        assert proc.returncode == 2 and proc.stderr.startswith(line), proc.stderr
        assert len(proc.stderr.strip().splitlines()) == 1 and proc.stdout == ""


@pytest.mark.parametrize(
    "call, head",
    [
        (lambda body, tmp: rbi.sweep(body, spin=[1.0], duration=0.01, out=tmp / "runs.txt"), "out: "),
        (lambda body, tmp: rbi.sweep(body, spin=[1.0], duration=0.01, out=BODIES / "top.yaml"), "out: "),
        (lambda body, tmp: rbi.sweep(body, spin=[1.0], duration=0.01, dask="nohost:1"), "dask: 'nohost:1'"),
        (lambda body, tmp: rbi.show(body, tmp / "picture.txt"), "path: "),
    ],
)
def test_output_and_scheduler_arguments_are_named_as_the_api_spells_them(top, tmp_path, call, head):
    """``out=`` of sweep is ``out`` (it was ``path``), ``dask=`` is ``dask`` (it was ``--dask``):
    a ValueError, and nothing is written."""
    with pytest.raises(ValueError) as caught:
        call(top, tmp_path)
    assert str(caught.value).startswith(head) and "--" not in str(caught.value), str(caught.value)
    assert list(tmp_path.iterdir()) == []


def test_audit_out_and_validate_paths_are_named(tmp_path):
    path = tmp_path / "arm.urdf"
    path.write_text(ARM)
    with pytest.raises(ValueError, match="^out: .*cannot write '.txt'"):
        rbi.audit(path, fix=True, out=tmp_path / "fixed.txt")
    with pytest.raises(TypeError, match="^paths: expected a path"):
        rbi.validate(5)
    assert not (tmp_path / "fixed.txt").exists()


HUGE = 10**400  # a Python int no double can hold: float(HUGE) raises OverflowError

HUGE_ARGUMENTS = {
    "spin": lambda top: rbi.simulate(top, spin=HUGE, duration=0.01),
    "tilt_deg": lambda top: rbi.simulate(top, spin=1.0, tilt_deg=HUGE, duration=0.01),
    "duration": lambda top: rbi.simulate(top, spin=1.0, duration=HUGE),
    "gravity": lambda top: rbi.simulate(top, spin=1.0, gravity=HUGE, duration=0.01),
    "rtol": lambda top: rbi.simulate(top, spin=1.0, rtol=HUGE, duration=0.01),
    "omega": lambda top: rbi.simulate(top, omega=[0, 0, HUGE], duration=0.01),
    "spin_axis": lambda top: rbi.simulate(top, spin=1.0, spin_axis=[HUGE, 0, 0], duration=0.01),
    "about": lambda top: top.inertia(about=[HUGE, 0, 0]),
    "axes": lambda top: top.inertia(axes=[("x", HUGE)]),
    "axis": lambda top: top.moment_about_axis([HUGE, 0, 0]),
    "omega ": lambda top: top.momentum([0, 0, HUGE]),
    "velocity": lambda top: top.momentum([0, 0, 1], velocity=[HUGE, 0, 0]),
    "torque": lambda top: top.dynamics([0, 0, 1], torque=[HUGE, 0, 0]),
    "direction": lambda top: rbi.unit_vector([HUGE, 0, 0]),
    "spin ": lambda top: rbi.sweep(top, spin=HUGE, duration=0.01),
    "tilt_deg ": lambda top: rbi.sweep(top, spin=[1.0, 2.0], tilt_deg=[0, HUGE], duration=0.01),
    "vary": lambda top: rbi.sweep(top, vary={"parts.cone.mass": HUGE}, duration=0.01),
    "duration ": lambda top: rbi.sweep(top, spin=1.0, duration=HUGE),
    "start": lambda top: rbi.Grid(HUGE, 1.0, 3),
    "count": lambda top: rbi.Grid(0.0, 1.0, math.inf),
    "mean": lambda top: rbi.Normal(HUGE, 1.0),
    "low": lambda top: rbi.Uniform(HUGE, HUGE + 1),
    "density": lambda top: rbi.audit(BODIES / "two_link_arm.urdf", density=HUGE),
    "joints": lambda top: rbi.audit(BODIES / "two_link_arm.urdf", joints={"elbow": HUGE}),
}


@pytest.mark.parametrize("parameter", HUGE_ARGUMENTS)
def test_an_integer_no_double_holds_is_a_value_error_naming_the_parameter(top, parameter):
    """10**400 given to any numeric parameter is refused as a bad argument (ValueError naming it)
    in a message of one short line, not an OverflowError from float() deep inside."""
    with pytest.raises(ValueError) as caught:
        HUGE_ARGUMENTS[parameter](top)
    message = str(caught.value)
    assert not isinstance(caught.value, OverflowError)
    assert parameter.strip() in message, message
    assert "\n" not in message and len(message) < 300, message


BRACED = {
    "tilt_axis": lambda top: rbi.simulate(top, spin=1.0, tilt_axis={"a": 1}, duration=0.01),
    "method": lambda top: rbi.simulate(top, spin=1.0, method={"x"}, duration=0.01),
    "runs": lambda top: rbi.sweep(top, runs={"a": 1}, duration=0.01),
    "vary": lambda top: rbi.sweep(top, vary={"{x}": 1.0}, duration=0.01),
    "dask": lambda top: rbi.sweep(top, spin=1.0, dask={"a"}, duration=0.01),
}


@pytest.mark.parametrize("parameter", BRACED)
def test_a_value_with_braces_is_named_as_given(top, parameter):
    """A value holding braces (a dict, a set, a path '{x}') is shown as given after the
    parameter's name: it is not taken as a placeholder ('Space not allowed in string format
    specifier', 'got 'x'' for {'x'}, '{x}' printed as 'x') and not a TypeError of re."""
    with pytest.raises(ValueError) as caught:
        BRACED[parameter](top)
    message = str(caught.value)
    assert message.split(": ")[0].endswith(parameter) or f"{parameter}[" in message, message
    assert "{" in message and "format" not in message, message


@pytest.mark.parametrize(
    "call, parameter",
    [
        (lambda: rbi.audit(BODIES / "two_link_arm.urdf", package_paths={"p": 3}), "package_paths"),
        (lambda: rbi.audit(BODIES / "two_link_arm.urdf", package_paths=3), "package_paths"),
        (lambda: rbi.import_robot(BODIES / "two_link_arm.urdf", package_paths={"p": None}), "package_paths"),
        (lambda: rbi.import_robot(BODIES / "two_link_arm.urdf", links=[1]), "links"),
        (lambda: rbi.import_robot(BODIES / "two_link_arm.urdf", links=7), "links"),
    ],
)
def test_robot_arguments_of_the_wrong_type_are_named(call, parameter):
    """rbi.audit(package_paths={'p': 3}) raised os.fspath's 'expected str, bytes or os.PathLike
    object, not int' and rbi.import_robot(links=[1]) "'int' object is not iterable": neither named
    the parameter."""
    with pytest.raises((TypeError, ValueError), match=f"^{parameter}: "):
        call()


def test_one_link_name_given_as_text_is_that_link():
    """links='elbow' was read letter by letter ('no link named 'e'')."""
    one = rbi.import_robot(BODIES / "two_link_arm.urdf", links="forearm")
    assert [link.name for link in one.links] == ["forearm"]
    assert one.links[0].mass == pytest.approx(0.8)
