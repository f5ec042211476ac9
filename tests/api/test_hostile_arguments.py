"""Arguments of the wrong type or shape given to a `Body`'s methods are refused as the
contract says: a ValueError or TypeError naming the parameter in the API's words, not
Python's or numpy's own message ("unhashable type: 'list'", "'float' object is not
iterable")."""

from __future__ import annotations

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES


@pytest.fixture(scope="module")
def top():
    return rbi.load(BODIES / "top.yaml")


@pytest.fixture(scope="module")
def toleranced():
    return rbi.load(BODIES / "top_bolted_toleranced.yaml")


@pytest.mark.parametrize(
    "call, parameter",
    [
        (lambda b: b.in_units(["mm"], "g"), "length"),
        (lambda b: b.in_units("mm", {"g": 1}), "mass"),
        (lambda b: b.inertia_report(products=["cad"]), "products"),
        (lambda b: b.export(["urdf"]), "to"),
    ],
)
def test_a_choice_given_as_a_list_or_dict_is_refused_naming_it(top, call, parameter):
    """b.in_units(['mm'], 'g') and b.inertia_report(products=['cad']) raised TypeError
    "unhashable type: 'list'" (a dict was asked whether it held the list)."""
    with pytest.raises(ValueError, match=rf"^{parameter}: expected one of .*, got [\[{{]"):
        call(top)


@pytest.mark.parametrize("axes", [1.5, 3, True, object()])
@pytest.mark.parametrize("method", ["inertia", "inertia_report", "standard_uncertainty"])
def test_axes_that_are_no_turns_nor_matrix_are_refused_naming_axes(toleranced, method, axes):
    """b.inertia(axes=1.5) raised TypeError "'float' object is not iterable"."""
    with pytest.raises(ValueError, match=r"^axes: expected a 3x3 rotation matrix or \(axis, degrees\) pairs"):
        getattr(toleranced, method)(axes=axes)


def test_no_turns_are_body_axes(top):
    np.testing.assert_array_equal(top.inertia(axes=[]), top.inertia())
    assert top.inertia_report(axes=[]).to_dict() == top.inertia_report().to_dict()


@pytest.mark.parametrize("axis", [[0, 0], [0, 0, 0], "z", object(), [1, None, 0]])
def test_a_bad_axis_of_the_inertia_report_is_named_axis(top, axis):
    """b.inertia_report(axis=[0, 0]) said 'direction: must be a non-zero finite vector' (the
    parameter of rbi.unit_vector, which it called), and axis=object() leaked float()'s TypeError."""
    with pytest.raises(ValueError, match=r"^axis: must be a non-zero finite vector \(x, y, z\), got "):
        top.inertia_report(axis=axis)


@pytest.mark.parametrize("axis", [object(), [1, None, 0], {"x": 1}])
def test_moment_about_an_axis_that_is_no_numbers_is_named_axis(top, axis):
    """b.moment_about_axis(object()) raised "float() argument must be a string or a real number,
    not 'object'" (the core caught an integer too large but not a value of no number)."""
    with pytest.raises(ValueError, match=r"^axis: must be a non-zero finite direction"):
        top.moment_about_axis(axis)


@pytest.mark.parametrize("of", [1.5, 3, True])
def test_uncertainty_of_a_value_that_is_no_name_is_refused_naming_of(toleranced, of):
    """b.uncertainty(of=1.5) raised TypeError "'float' object is not iterable"."""
    with pytest.raises(ValueError, match=r"^of: must name quantities such as mass"):
        toleranced.uncertainty(of=of)


@pytest.mark.parametrize("allowed", ["no", 0, 1.0, []])
def test_allow_outside_paths_is_true_false_or_none(allowed, tmp_path):
    """rbi.load(spec, allow_outside_paths="no") let the spec read files outside its folder: any
    truthy value was taken as True. Now TypeError naming allow_outside_paths (load, loads, audit)."""
    spec = tmp_path / "s.yaml"
    spec.write_text("parts: [{shape: point, mass: 1, position: [0, 0, 0]}]\n")
    for call in (
        lambda: rbi.load(spec, allow_outside_paths=allowed),
        lambda: rbi.loads(spec.read_text(), allow_outside_paths=allowed),
        lambda: rbi.audit(BODIES / "two_link_arm.urdf", allow_outside_paths=allowed),
    ):
        with pytest.raises(TypeError, match=r"^allow_outside_paths: must be True, False or None \(got "):
            call()
    assert (
        rbi.load(spec, allow_outside_paths=False).mass == rbi.load(spec, allow_outside_paths=None).mass == 1.0
    )


@pytest.mark.parametrize("name", [["link"], 3, {"a": 1}])
def test_export_name_that_is_no_text_is_refused(top, name):
    """b.export("urdf", name=["link"]) wrote <link name="['link']">."""
    with pytest.raises(TypeError, match=r"^name: must be text \(got "):
        top.export("urdf", name=name)
    assert '<link name="arm">' in top.inertial_xml("urdf", name="arm", document=True)


def test_a_step_budget_past_the_kernels_integers_is_refused_naming_max_steps(top):
    """rbi.sweep(body, max_steps=10**400) raised the compiled kernel's OverflowError "Python int
    too large to convert to C long" after the runs were set up."""
    for run in (rbi.simulate, rbi.sweep):
        with pytest.raises(ValueError, match=r"^max_steps: must be at least 1 and below 2\*\*63 \(got "):
            run(top, spin=10.0, duration=0.01, max_steps=10**400)
    with pytest.raises(ValueError, match=r"^max_steps: must be at least 1"):
        rbi.simulate(top, spin=10.0, duration=0.01, max_steps=0)


@pytest.mark.parametrize("body", [None, [], 1j])
def test_animate_names_a_body_that_is_no_body(body, tmp_path):
    """rbi.animate(None, "a.html") raised os.fspath's "expected str, bytes or os.PathLike object,
    not NoneType" (the output was checked against the body's files first)."""
    with pytest.raises(TypeError, match=r"^body: expected a Body from rbi.load"):
        rbi.animate(body, tmp_path / "a.html")


@pytest.mark.parametrize(
    "setting", [{"speed": []}, {"speed": "1"}, {"fps": 1j}, {"fps": None}, {"speed": True}]
)
def test_animate_names_a_speed_or_fps_that_is_no_number(top, setting, tmp_path):
    """rbi.animate(b, "a.gif", fps=1j) raised "'<=' not supported between instances of 'int' and
    'complex'"."""
    with pytest.raises(ValueError, match=rf"^{next(iter(setting))}: must be between .* \(got "):
        rbi.animate(top, tmp_path / "a.gif", spin=10.0, duration=0.01, **setting)


@pytest.mark.parametrize("out", [3, ["a.yaml"], True])
def test_import_robot_names_an_out_that_is_no_path(out):
    """rbi.import_robot(urdf, out=3) raised "expected str, bytes or os.PathLike object, not int"."""
    with pytest.raises(TypeError, match=r"^out: expected a path"):
        rbi.import_robot(BODIES / "two_link_arm.urdf", out=out)


def test_the_sweep_tables_plot_names_its_own_parameter(top):
    """table.plot("map") said "plot: map: cannot write no extension": the name of rbi.sweep's
    parameter, not the method's ``path``."""
    table = rbi.sweep(top, spin=[10.0, 20.0], duration=0.01, samples=3)
    with pytest.raises(ValueError, match=r"^path: map: cannot write no extension"):
        table.plot("map")


def test_a_sweeps_rtol_of_none_is_the_default_tolerance_as_simulates(top):
    """rbi.sweep(b, rtol=None) raised "float() argument must be a string or a real number, not
    'NoneType'"; rbi.simulate takes None as the method's own tolerance, and rtol is simulate's."""
    none, default = (rbi.sweep(top, spin=[10.0], duration=0.05, samples=3, rtol=r) for r in (None, 1e-12))
    np.testing.assert_array_equal(none["max_tilt_deg"], default["max_tilt_deg"])


@pytest.mark.parametrize("lengths", [1.5, ["a", "b", "c"], [[1, 0], [0, 1]], object()])
def test_from_spec_units_names_lengths_that_are_no_point(top, lengths):
    """b.from_spec_units(1.5) raised "'float' object is not iterable"."""
    with pytest.raises(ValueError, match=r"^lengths: expected 3 finite numbers, got "):
        top.from_spec_units(lengths)
    assert top.in_units("mm", "kg").from_spec_units([0.0, 0.0, 0.5]) == [0.0, 0.0, 500.0]


@pytest.mark.parametrize(
    "call, switch",
    [
        (lambda b, v: rbi.simulate(b, spin=10.0, duration=0.01, check_budget=v), "check_budget"),
        (lambda b, v: rbi.simulate(b, spin=10.0, duration=0.01, error_estimate=v), "error_estimate"),
        (lambda b, v: rbi.sweep(b, spin=10.0, duration=0.01, check_budget=v), "check_budget"),
        (lambda b, v: rbi.sweep(b, vary={"parts[0].mass": [1.0]}, mass_properties=v), "mass_properties"),
        (lambda b, v: rbi.sweep(b, spin=10.0, duration=0.01, resume=v), "resume"),
        (lambda b, v: rbi.audit(BODIES / "two_link_arm.urdf", fix=v), "fix"),
        (lambda b, v: rbi.audit(BODIES / "two_link_arm.urdf", mesh_repair=v), "mesh_repair"),
        (lambda b, v: b.export("mjcf", document=v), "document"),
        (lambda b, v: b.export("mjcf", diagonal=v), "diagonal"),
        (lambda b, v: b.parts(expand=v), "expand"),
    ],
)
@pytest.mark.parametrize("value", ["no", "false", None, 0])
def test_a_switch_is_true_or_false(top, call, switch, value):
    """rbi.audit(urdf, fix="no") planned the fix and b.export("mjcf", diagonal="false") wrote
    diaginertia: any truthy value was True, None and 0 False."""
    with pytest.raises(TypeError, match=rf"^{switch}: must be True or False \(got "):
        call(top, value)
    call(top, np.False_)


@pytest.mark.parametrize(
    "call",
    [
        lambda b, p, d: rbi.simulate(b, spin=10.0, duration=0.01, progress=p),
        lambda b, p, d: rbi.sweep(b, spin=10.0, duration=0.01, progress=p),
        lambda b, p, d: rbi.animate(b, d / "a.html", spin=10.0, duration=0.01, progress=p),
    ],
)
def test_a_progress_that_is_no_function_is_refused_before_the_run(top, call, tmp_path):
    """rbi.simulate(b, spin=10, progress="x") ran until its first report, then raised "'str'
    object is not callable"."""
    with pytest.raises(TypeError, match=r"^progress: must be a function or None \(got str 'x'\)"):
        call(top, "x", tmp_path)
    assert not (tmp_path / "a.html").exists()
