"""The options of the commands that run a simulation (``simulate``, ``animate``, ``sweep``),
declared once, named as ``rbi.simulate`` and ``rbi.sweep`` name them and defaulting as the
one the command calls does."""

from __future__ import annotations

from typing import Any

from rbi.cli.option_values import parse_vector, spin_axis_option
from rbi.cli.options import option

RUN = {
    each.name: each
    for each in (
        option(
            float | None,
            "--spin",
            "-s",
            metavar="W",
            help="Initial spin about the spin axis (see --spin-axis), rad/s.",
        ),
        option(
            str | None,
            "--omega",
            "-w",
            metavar="WX,WY,WZ",
            parser=parse_vector,
            help="Initial angular velocity in body axes, rad/s.",
        ),
        option(
            float,
            "--tilt",
            name="tilt_deg",
            metavar="DEG",
            help="Nudge at t=0: turn the body DEG degrees about the world y axis (see --tilt-axis). The tilt "
            "reported is the spin axis's angle from vertical.",
        ),
        option(str, "--tilt-axis", metavar="x|y", help="World axis the nudge (--tilt) turns the body about."),
        option(
            float | None,
            "--gravity",
            "-g",
            metavar="G",
            help="Gravity's magnitude in m/s² (SI, whatever the spec's units); 0 switches it off. Default 9.81.",
        ),
        option(float, "--duration", "-t", metavar="T", help="Simulated time, s."),
        option(
            int,
            "--samples",
            "-n",
            metavar="N",
            help="Samples of each run, equally spaced from t=0 to t=T (1: only the end); a sweep's "
            "summaries are taken over them.",
        ),
        option(
            float | None,
            "--rtol",
            metavar="RTOL",
            help="Tolerance of the integrator (default 1e-12; 1e-8 for simulate --method rk45 or dop853): "
            "smaller is more accurate and slower.",
        ),
        option(
            int | None,
            "--max-steps",
            metavar="N",
            help="Most integration steps this run may take (default 1e+07, about ten seconds of the compiled "
            "integrator); a run estimated to need more is refused before it starts.",
        ),
        option(
            bool,
            "--yes",
            "-y",
            help="Run even when the estimated integration steps (of the run, of all its --draws, or of "
            "the whole sweep) exceed the step budget (the budget still stops each run).",
        ),
        option(
            str | None,
            "--spin-axis",
            metavar="x|y|z|X,Y,Z",
            parser=spin_axis_option,
            help="The body-frame axis --spin turns about, whose tilt from vertical and precession are reported. "
            "Default: the spec's spin_axis, else the body's symmetry axis (pointing from the pivot to the centre of "
            "mass), else z.",
        ),
    )
}
"""The options of one run by parameter name (``rbi.simulate``'s; ``--yes`` is ``yes``, the API's
``check_budget=False``: :func:`budget`)."""


def budget(settings: dict[str, Any]) -> dict[str, Any]:
    """``settings`` as the API takes them: ``--yes`` as ``check_budget=False``."""
    yes = settings.pop("yes")
    return settings | {"check_budget": not yes}
