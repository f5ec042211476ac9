"""The options of the commands that run a simulation (``simulate``, ``animate``, ``sweep``),
declared once. Kept apart from :mod:`rbi.cli.options` because their help quotes the step
budget (``rbi.api.DEFAULT_MAX_STEPS``), which imports numpy (every command module that takes them
imports numpy anyway)."""

from __future__ import annotations

from typing import Annotated

import typer

from rbi.api import DEFAULT_MAX_STEPS

SpinOption = Annotated[
    float | None,
    typer.Option(
        "--spin", "-s", metavar="W", help="Initial spin about the spin axis (see --spin-axis), rad/s."
    ),
]
SpinAxisOption = Annotated[
    str | None,
    typer.Option(
        "--spin-axis",
        metavar="x|y|z|X,Y,Z",
        help="The body-frame axis --spin turns about, whose tilt from vertical and precession are reported. "
        "Default: the spec's spin_axis, else the body's symmetry axis (pointing from the pivot to the centre of "
        "mass), else z.",
    ),
]
OmegaOption = Annotated[
    str | None,
    typer.Option("--omega", "-w", metavar="WX,WY,WZ", help="Initial angular velocity in body axes, rad/s."),
]
TiltOption = Annotated[
    float,
    typer.Option(
        "--tilt",
        metavar="DEG",
        help="Nudge at t=0: turn the body DEG degrees about the world y axis "
        "(see --tilt-axis). The tilt reported is the spin axis's angle "
        "from vertical.",
    ),
]
TiltAxisOption = Annotated[
    str,
    typer.Option("--tilt-axis", metavar="x|y", help="World axis the nudge (--tilt) turns the body about."),
]
GravityOption = Annotated[
    float | None,
    typer.Option(
        "--gravity",
        "-g",
        metavar="G",
        help="Gravity's magnitude in m/s² (SI, whatever the spec's units); 0 switches it off. Default 9.81.",
    ),
]
DurationOption = Annotated[float, typer.Option("--duration", "-t", metavar="T", help="Simulated time, s.")]
RtolOption = Annotated[
    float | None,
    typer.Option(
        "--rtol",
        metavar="RTOL",
        help="Tolerance of the integrator (default 1e-12; 1e-8 for simulate --method rk45 or dop853): "
        "smaller is more accurate and slower.",
    ),
]
MaxStepsOption = Annotated[
    int | None,
    typer.Option(
        "--max-steps",
        metavar="N",
        help="Most integration steps this run may take (default "
        f"{DEFAULT_MAX_STEPS:.0e}); a run estimated to need more is refused "
        "before it starts.",
    ),
]
YesOption = Annotated[
    bool,
    typer.Option(
        "--yes",
        "-y",
        help="Run even when the run (or sweep) is estimated to exceed the step budget (the budget still "
        "stops each run).",
    ),
]
SamplesOption = Annotated[
    int,
    typer.Option(
        "--samples",
        "-n",
        metavar="N",
        help="Samples of each run, equally spaced from t=0 to t=T (1: only the end); a sweep's "
        "summaries are taken over them.",
    ),
]
