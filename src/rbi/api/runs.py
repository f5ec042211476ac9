"""Runs: `simulate` a body, its `Trajectory`."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from rbi.api.body import Body, loaded_body
from rbi.api.outputs import PLOT_FORMATS, as_parameter, checked_output, keywords_checked, out_and_plot
from rbi.core.validity import require_callable
from rbi.errors import ArgumentError
from rbi.files.output import Destination, OutputTarget, write_output
from rbi.reprs import Result, Rows, pandas_module
from rbi.runs.draws import input_uncertainty as spread
from rbi.runs.run import RunSettings, RunSummary, SimulationRun, prepare_run
from rbi.text import number, vector_text
from rbi.viz.labels import motion_title
from rbi.viz.plots import plot_trajectory


@dataclass(frozen=True, repr=False)
class Trajectory(SimulationRun, Result):
    """A simulated motion, sampled at equally spaced times (spec units).

    Attributes:
        t: (N,) time, s.
        q: (N, 4) unit quaternions [w, x, y, z] (scalar first), body → world.
        omega: (N, 3) angular velocity in the body frame, rad/s.
        tilt_deg: (N,) angle of the spin axis (body z unless ``spin_axis`` says otherwise) from
            the upward vertical, degrees.
        precession_deg: (N,) azimuth of that axis seen from above, degrees (unwrapped; NaN
            while the axis stands vertical).
        energy: (N,) total energy (kinetic + potential), mass·length²/s².
        summary: the run's figures, typed (`RunSummary`: initial and final state, tilt bounds,
            conserved quantities and their drift, error estimate, cost, stability);
            ``to_dict()`` is what ``rbi simulate --format json`` prints. None for a
            trajectory made by hand.
    """

    body: Body | None = field(default=None, compare=False)
    """The simulated `Body` (None for a trajectory made by hand)."""

    def plot(self, path: Destination) -> None:
        """Draw the run at ``path`` (``.png``, ``.svg`` or ``.pdf``; needs matplotlib), as ``rbi
        simulate --plot`` does: the path of the tip of the spin axis seen from above (world
        frame), its tilt against time (a free body: each principal axis's angle to the angular
        momentum), degrees; ω in body axes, rad/s; the energy's drift. The file is replaced
        atomically."""
        body, summary = self.body, self.summary
        if body is None or summary is None:
            raise ArgumentError("body", "plot needs the Body of the run: a Trajectory from rbi.simulate")
        free = (
            {"principal_axes": body.principal().axes, "inertia": body.inertia()} if body.pivot is None else {}
        )
        given = self.settings is not None and any(self.settings.omega or ())
        initial, axis = summary.initial, summary.spin_axis
        plot_trajectory(
            self.columns() if self.dense is None else self.dense,
            checked_output(path, PLOT_FORMATS, body),
            motion_title(
                body.name or body.path, initial["omega"], None if given else axis, initial["nudge_deg"]
            ),
            energy_unit=body.unit_labels["energy"],
            spin_axis=axis,
            **free,
        )

    def to_pandas(self) -> Any:
        """The trajectory's columns (``t``, ``qw`` … ``energy``) as a :class:`pandas.DataFrame`,
        one row a sample."""
        return pandas_module(self).DataFrame(self.columns())

    def to_dict(self) -> dict[str, Any]:
        """The summary as ``rbi simulate --format json`` prints it (JSON-ready)."""
        if self.summary is None:
            raise ArgumentError("summary", "a Trajectory made by hand has no summary")
        return self.summary.to_dict()

    def __repr__(self) -> str:
        method = "" if self.summary is None else self.summary.method
        return f"<rbi.Trajectory {self.t.size} samples over {number(self.t[-1])} s, {method}>"

    def rows(self) -> list[Rows]:
        """The motion (scene, method, final state, spin axis, tilt, precession) and the run's
        accuracy and cost, as (quantity, unit, value) rows: the tables of ``rbi simulate``."""
        s = self.summary
        name = self.body.name or self.body.path if self.body is not None else None
        title = f"{name or 'trajectory'} — simulate"
        if s is None:
            return [Rows.quantities(title, self._sample_rows())]
        labels = self.body.unit_labels if self.body is not None else s.units
        return [
            Rows.quantities(title, _motion_rows(s)),
            Rows.quantities("Accuracy and cost", _accuracy_rows(s, labels)),
        ]

    def _sample_rows(self) -> list[tuple[str, str, str]]:
        """The rows a trajectory made by hand can show: its samples' span and ends."""
        return [
            ("duration", "s", number(self.t[-1])),
            ("samples", "", str(self.t.size)),
            ("final q [w, x, y, z]", "", vector_text(self.q[-1], scale=0.0)),
            ("final ω (body axes)", "rad/s", vector_text(self.omega[-1], scale=0.0)),
            ("tilt min … max", "deg", f"{number(np.min(self.tilt_deg))} … {number(np.max(self.tilt_deg))}"),
        ]

    def with_input_uncertainty(self, draws: int, seed: int | None = None) -> Trajectory:
        """This run with the spread the inputs written with ± give (`input_uncertainty` of its
        body and settings) in its summary, beside the error estimate: ``rbi simulate --draws``."""
        if self.body is None or self.summary is None or self.settings is None:
            raise ArgumentError("body", "needs the Body of the run: a Trajectory from rbi.simulate")
        drawn = input_uncertainty(self.body, draws=draws, seed=seed, **vars(self.settings))
        warnings = [*self.summary.warnings, *drawn.pop("warnings")]  # with the body's
        return replace(self, summary=replace(self.summary, input_uncertainty=drawn, warnings=warnings))

    def notes(self) -> list[str]:
        """The sentences under the tables: integrator, stability, closed form."""
        s = self.summary
        if s is None:
            return []
        notes = [f"Integrator: {s.integrator}.", f"Stability: {s.stability['verdict']}."]
        facts = s.closed_form
        if facts and facts.get("kind") == "Lagrange top":
            notes.append(
                f"Closed form (Lagrange top): tilt between {number(facts['nutation_tilt_min_deg'])} and "
                f"{number(facts['nutation_tilt_max_deg'])} deg, nutation period {number(facts['nutation_period_s'])} s, "
                f"mean precession {number(facts['mean_precession_rate_deg_s'])} deg/s."
            )
        elif facts and facts.get("kind") == "asymmetric free body":
            flips = (
                f"; near the intermediate axis the body turns over every {number(facts['half_period_s'])} s"
                if s.stability.get("intermediate_axis")
                else ""
            )
            notes.append(
                f"Closed form (Euler–Poinsot): ω repeats every {number(facts['omega_period_s'])} s "
                f"(4K(m)/λ, m = {number(facts['elliptic_parameter'])}){flips}."
            )
        return notes


def _motion_rows(s: RunSummary) -> list[tuple[str, str, str]]:
    """(quantity, unit, value) rows of the motion: scene, method, final state, tilt, precession."""
    to_h = s.angle_to_h_deg or {}
    cone = (
        []
        if to_h.get("min") is None
        else [("spin axis to h: min … max", "deg", f"{number(to_h['min'])} … {number(to_h['max'])}")]
    )
    rate = s.mean_precession_rate_deg_s
    precession = "undefined (the axis was vertical)" if rate is None else number(rate)
    return [
        ("scene", "", s.scene),
        ("method", "", s.method),
        ("duration", "s", number(s.duration)),
        ("samples", "", str(s.samples)),
        ("final q [w, x, y, z]", "", vector_text(s.final["q"], scale=0.0)),
        ("final ω (body axes)", "rad/s", vector_text(s.final["omega"], scale=0.0)),
        ("spin axis (body axes)", "", vector_text(s.spin_axis, scale=0.0)),
        ("nudge at t=0 (--tilt)", "deg", number(s.initial["nudge_deg"])),
        (f"final tilt of {_axis_name(s.spin_axis)}", "deg", number(s.final["tilt_deg"])),
        ("tilt min … max (nutation)", "deg", f"{number(s.tilt_min_deg)} … {number(s.tilt_max_deg)}"),
        ("mean precession rate", "deg/s", precession),
        *cone,
    ]


CONSERVED_NAMES = {
    "energy": "energy",
    "h_vertical": "vertical h about pivot",
    "h_spin": "spin h·axis",
    "h_world": "h (world axes)",
}
"""How the tables name each conserved quantity."""


def _accuracy_rows(s: RunSummary, labels: dict[str, str]) -> list[tuple[str, str, str]]:
    """(quantity, unit, value) rows of the run's accuracy (conserved quantities' drift, error
    estimate) and cost (steps, evaluations, time); ``labels``: unit labels by kind."""
    accuracy = []
    for key, item in s.conserved.items():
        initial = item["initial"]
        shown = vector_text(initial, scale=0.0) if np.ndim(initial) else number(initial, 10)
        accuracy.append(
            (CONSERVED_NAMES[key], labels[item["unit"]], f"{shown}  (drift {number(item['drift'], 2)})")
        )
    accuracy.append(("| |q| − 1 | largest", "", number(s.quaternion_norm_error, 2)))
    estimate = s.error_estimate
    if estimate and estimate.get("orientation_deg") is None:
        accuracy.append(("error estimate", "", estimate["reference"]))
    elif estimate:
        accuracy.append(("error estimate: orientation", "deg", number(estimate["orientation_deg"], 2)))
        accuracy.append(("error estimate: ω", "rad/s", number(estimate["omega_rad_s"], 2)))
    spread = s.input_uncertainty
    if spread:
        accuracy += [
            ("inputs drawn (--draws)", "", f"{spread['draws']} ({spread['failed']} failed)"),
            ("± inputs: tilt max", "deg", number(spread["tilt_max_deg"], 2)),
            ("± inputs: final tilt", "deg", number(spread["final_tilt_deg"], 2)),
            ("± inputs: precession rate", "deg/s", number(spread["mean_precession_rate_deg_s"], 2)),
            ("± inputs: final ω", "rad/s", vector_text(spread["final_omega"], 2, scale=0.0)),
        ]
    accuracy += [
        ("steps (rejected)", "", f"{s.steps} ({s.rejected_steps})"),
        ("right-hand-side evaluations", "", str(s.rhs_evals)),
        ("integration wall time", "s", number(s.wall_seconds, 3)),
    ]
    if s.load_seconds > 0.05:
        accuracy.append(("loading the compiled kernel", "s", number(s.load_seconds, 3)))
    return accuracy


PLOT_SAMPLES = 8001
"""Samples a plot draws (`simulate`'s ``plot``): enough to show nutation loops and the wobble of
a fast top."""


@keywords_checked
def simulate(
    body: Body,
    *,
    spin: float | None = None,
    omega: Sequence[float] | None = None,
    tilt_deg: float = 0.0,
    tilt_axis: str = "y",
    duration: float = 4.0,
    samples: int = 481,
    gravity: float | None = None,
    method: str = "default",
    rtol: float | None = None,
    max_steps: int | None = None,
    error_estimate: bool = True,
    check_budget: bool = True,
    progress: Callable[[float], None] | None = None,
    spin_axis: str | Sequence[float] | None = None,
    out: Destination | None = None,
    plot: Destination | None = None,
    draws: int | None = None,
    seed: int | None = None,
) -> Trajectory:
    """Simulate the body: a heavy top on its pivot (a spec with ``pivot``) or a torque-free body about its
    centre of mass — the run ``rbi simulate`` makes with the same settings. Returns the `Trajectory`.

    Args:
        body: the `Body`.
        spin: initial spin about the spin axis, rad/s.
        omega: instead of ``spin``, the initial angular velocity (3,), body axes, rad/s, whose direction
            is then the spin axis (unless ``spin_axis`` is given).
        tilt_deg: the nudge: the body turned at t = 0 by this angle (degrees) about ``tilt_axis``. The
            tilt reported is the spin axis's from the vertical.
        tilt_axis: the world axis of the nudge, ``"x"`` or ``"y"``.
        duration: simulated time, s.
        samples: samples, equally spaced from t = 0 (1: only the end).
        gravity: m/s² (SI whatever the spec's units); 0 switches it off; None is 9.81.
        method: ``"default"`` (compiled adaptive DOP853), ``"rk45"``, ``"dop853"`` (scipy) or
            ``"exact"`` (closed forms, where they apply).
        rtol: integrator tolerance (None: 1e-12 for default, 1e-8 for the scipy methods).
        max_steps: most integration steps (None: rbi's `DEFAULT_MAX_STEPS`); they stop the run.
        check_budget: refuse a run estimated past ``max_steps`` before it starts.
        error_estimate: estimate the error with a second run 1000× tighter.
        progress: called now and then with the fraction done (0…1).
        spin_axis: the body-frame axis of ``spin`` and of the reported tilt and precession: ``"x"``,
            ``"y"``, ``"z"`` (``"-y"``: reversed) or a direction (3,); None for ``omega``'s direction,
            else the spec's ``spin_axis``, else `Body.spin_axis`'s default.
        out: also write the CSV (`Trajectory.to_csv`) at this path: ``rbi simulate --out``.
        plot: also draw the run at this path (`Trajectory.plot`, from the same integration sampled at
            8001 times): ``rbi simulate --plot``. Both are checked before the run, written after it.
        draws: for a spec with ±, the spread of that many runs with the inputs drawn, in the summary
            (`Trajectory.with_input_uncertainty`; ``seed``: the same draws again): ``rbi simulate --draws``.

    Raises:
        ValueError: a setting is out of range, named as this function's parameter (``duration: must
            be ...``), or the run is estimated to exceed ``max_steps``.
        SpecError: the run cannot be made (no mass, too many steps, overflow); ``out`` or ``plot`` not writable.
    """
    csv_file, picture = out_and_plot(out, plot, ("csv",), body)
    run = _simulated(body, RunSettings.of(locals()), progress, 0 if picture is None else PLOT_SAMPLES)
    return _written(run.with_input_uncertainty(draws, seed) if draws is not None else run, csv_file, picture)


def _written(
    trajectory: Trajectory, csv_file: OutputTarget | None, picture: OutputTarget | None
) -> Trajectory:
    """``trajectory``, its CSV written at ``csv_file`` and its plot drawn at ``picture`` (None: not asked for)."""
    if csv_file is not None:
        with as_parameter("out"):
            write_output(csv_file, trajectory.to_csv())
    if picture is not None:
        with as_parameter("plot"):
            trajectory.plot(picture)
    return trajectory


def input_uncertainty(
    body: Body, *, draws: int, seed: int | None = None, samples: int = 481, **run: Any
) -> dict[str, Any]:
    """The spread of `simulate`'s summary that the inputs written with ± give: the standard
    deviation of the tilt range, final tilt, mean precession rate and final ω over ``draws``
    runs with the inputs drawn (``seed``: the same draws again), integrated by the batched
    kernel in chunks of bounded memory; ``run``: `simulate`'s settings (``spin``, ``tilt_deg``,
    ``duration`` ...). What ``rbi simulate --draws`` adds to its JSON as ``"input_uncertainty"``,
    and ``warnings``: drawn parts the spec refuses, which it adds to the run's ``"warnings"``."""
    prepared = prepare_run(loaded_body(body, "body"), RunSettings(samples=samples, **run))
    return spread(prepared, prepared.settings.samples, draws, seed)


def _simulated(
    body: Body, settings: RunSettings, progress: Callable[[float], None] | None, dense: int
) -> Trajectory:
    """The `Trajectory` of ``body`` run with ``settings`` (sampled at ``dense`` more times for a plot)."""
    require_callable(progress=progress)
    run = prepare_run(loaded_body(body, "body"), settings).simulate(progress, dense)
    return Trajectory(**vars(run), body=body)


def _axis_name(axis: Any) -> str:
    """``body y`` for a coordinate axis of the body frame, else ``the spin axis``."""
    return next((f"body {name}" for name, value in zip("xyz", axis) if value == 1.0), "the spin axis")
