"""The options of the commands that run a simulation (``simulate``, ``animate``, ``sweep``),
declared once; :func:`run_options` gives a command those of one run as ``rbi.simulate``'s
keywords, with ``rbi.simulate``'s defaults."""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable
from types import SimpleNamespace
from typing import Any

import rbi
from rbi.cli.option_values import run_settings
from rbi.cli.options import option

RUN_OPTIONS = {
    "spin": option(
        float | None,
        "--spin",
        "-s",
        metavar="W",
        help="Initial spin about the spin axis (see --spin-axis), rad/s.",
    ),
    "omega": option(
        str | None, "--omega", "-w", metavar="WX,WY,WZ", help="Initial angular velocity in body axes, rad/s."
    ),
    "tilt": option(
        float,
        "--tilt",
        metavar="DEG",
        help="Nudge at t=0: turn the body DEG degrees about the world y axis (see --tilt-axis). The tilt "
        "reported is the spin axis's angle from vertical.",
    ),
    "tilt_axis": option(
        str, "--tilt-axis", metavar="x|y", help="World axis the nudge (--tilt) turns the body about."
    ),
    "gravity": option(
        float | None,
        "--gravity",
        "-g",
        metavar="G",
        help="Gravity's magnitude in m/s² (SI, whatever the spec's units); 0 switches it off. Default 9.81.",
    ),
    "duration": option(float, "--duration", "-t", metavar="T", help="Simulated time, s."),
    "samples": option(
        int,
        "--samples",
        "-n",
        metavar="N",
        help="Samples of each run, equally spaced from t=0 to t=T (1: only the end); a sweep's "
        "summaries are taken over them.",
    ),
    "rtol": option(
        float | None,
        "--rtol",
        metavar="RTOL",
        help="Tolerance of the integrator (default 1e-12; 1e-8 for simulate --method rk45 or dop853): "
        "smaller is more accurate and slower.",
    ),
    "max_steps": option(
        int | None,
        "--max-steps",
        metavar="N",
        help="Most integration steps this run may take (default 1e+07, about ten seconds of the compiled "
        "integrator); a run estimated to need more is refused before it starts.",
    ),
    "yes": option(
        bool,
        "--yes",
        "-y",
        help="Run even when the run (or sweep) is estimated to exceed the step budget (the budget still "
        "stops each run).",
    ),
    "spin_axis": option(
        str | None,
        "--spin-axis",
        metavar="x|y|z|X,Y,Z",
        help="The body-frame axis --spin turns about, whose tilt from vertical and precession are reported. "
        "Default: the spec's spin_axis, else the body's symmetry axis (pointing from the pivot to the centre of "
        "mass), else z.",
    ),
}
"""The options of one run by parameter name; ``rbi.simulate`` names ``tilt`` ``tilt_deg`` and
takes ``--yes`` as ``check_budget=False`` (:func:`rbi.cli.option_values.run_settings`)."""
RUN = SimpleNamespace(**RUN_OPTIONS)
"""The same options by attribute, for a command that declares them itself: ``duration: RUN.duration``."""


def run_options(without: str | None = None) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """A command's decorator: the command takes the run options of :data:`RUN_OPTIONS` but
    ``without`` (after its first parameter, each defaulting to ``rbi.simulate``'s) and is given
    them as one ``settings``, ``rbi.simulate``'s keywords."""
    names = [name for name in RUN_OPTIONS if name != without]
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
