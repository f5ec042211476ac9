"""The options of the commands that run a simulation (``simulate``, ``animate``, ``sweep``),
declared once; :func:`run_options` gives a command those of one run as ``rbi.simulate``'s
keywords, with ``rbi.simulate``'s defaults."""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable
from typing import Annotated, Any

import typer

import rbi
from rbi.cli.option_values import run_settings

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
        help="Most integration steps this run may take (default 1e+07, about ten seconds of the compiled "
        "integrator); a run estimated to need more is refused before it starts.",
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

RUN_OPTIONS = {
    "spin": SpinOption,
    "omega": OmegaOption,
    "tilt": TiltOption,
    "tilt_axis": TiltAxisOption,
    "gravity": GravityOption,
    "duration": DurationOption,
    "samples": SamplesOption,
    "rtol": RtolOption,
    "max_steps": MaxStepsOption,
    "yes": YesOption,
    "spin_axis": SpinAxisOption,
}
"""The options of one run by parameter name; ``rbi.simulate`` names ``tilt`` ``tilt_deg`` and
takes ``--yes`` as ``check_budget=False`` (:func:`rbi.cli.option_values.run_settings`)."""


def run_options(*names: str) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """A command's decorator: the command takes the run options ``names`` (of
    :data:`RUN_OPTIONS`, after its first parameter, each defaulting to ``rbi.simulate``'s) and
    is given them as one ``settings``, ``rbi.simulate``'s keywords."""
    defaults = inspect.signature(rbi.simulate).parameters
    added = [
        inspect.Parameter(
            name,
            inspect.Parameter.KEYWORD_ONLY,
            annotation=RUN_OPTIONS[name],
            default=False if name == "yes" else defaults["tilt_deg" if name == "tilt" else name].default,
        )
        for name in names
    ]

    def decorate(command: Callable[..., Any]) -> Callable[..., Any]:
        signature = inspect.signature(command, eval_str=True)
        first, *own = (
            p.replace(kind=inspect.Parameter.KEYWORD_ONLY)
            for p in signature.parameters.values()
            if p.name != "settings"
        )

        @functools.wraps(command)
        def with_settings(**given: Any) -> Any:
            options = {name: given.pop(name) for name in names}
            return command(settings=run_settings(**options), **given)

        with_settings.__signature__ = signature.replace(parameters=[first, *added, *own])  # type: ignore[attr-defined]
        return with_settings

    return decorate
