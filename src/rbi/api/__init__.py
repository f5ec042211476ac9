"""The public Python API of rbi: load a body, ask for its mass properties, simulate its motion.

```python
import rbi

body = rbi.load("bodies/top_bolted.yaml")
body.mass                      # kg (the spec's mass unit)
body.principal().moments       # ascending, kg·m² (the spec's units)
run = rbi.simulate(body, spin=200.0, tilt_deg=0.01, duration=2.0)
run.t, run.q, run.omega        # numpy arrays: s; [w, x, y, z] body → world; body frame rad/s
```

Every number is in the spec's own units (``body.units``) unless a name says otherwise: lengths in
``units["length"]``, masses in ``units["mass"]``, inertias in mass·length². Points and vectors are
in the body frame (the spec's coordinates) unless a name says ``world``. Bad input of any kind
raises `SpecError`, whose ``str()`` is the one line the CLI prints for the same mistake.

The modules: :mod:`~rbi.api.body` (load a spec, a `Body` and its results), :mod:`~rbi.api.runs`
(`simulate`), :mod:`~rbi.api.sweeps` (`sweep`), :mod:`~rbi.api.robots` (`audit`, `import_robot`),
:mod:`~rbi.api.pictures` (`show`, `animate`); :mod:`~rbi.api.outputs` checks where they write.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

from rbi.memory import collector_paused
from rbi.names import PUBLIC

if TYPE_CHECKING:  # served by __getattr__ on first use: `import rbi.api` loads none of them
    from rbi.api.body import Body as Body
    from rbi.api.body import load as load
    from rbi.api.body import loads as loads
    from rbi.api.body import spec_schema as spec_schema
    from rbi.api.body import unit_vector as unit_vector
    from rbi.api.body import validate as validate
    from rbi.api.pictures import Animation as Animation
    from rbi.api.pictures import animate as animate
    from rbi.api.pictures import show as show
    from rbi.api.results import Dynamics as Dynamics
    from rbi.api.results import Momentum as Momentum
    from rbi.api.results import Part as Part
    from rbi.api.results import Principal as Principal
    from rbi.api.robots import ImportedLink as ImportedLink
    from rbi.api.robots import RobotImport as RobotImport
    from rbi.api.robots import audit as audit
    from rbi.api.robots import import_robot as import_robot
    from rbi.api.runs import Trajectory as Trajectory
    from rbi.api.runs import input_uncertainty as input_uncertainty
    from rbi.api.runs import simulate as simulate
    from rbi.api.sweeps import SweepTable as SweepTable
    from rbi.api.sweeps import sweep as sweep
    from rbi.core.mass import MassProperties as MassProperties
    from rbi.errors import ArgumentError as ArgumentError
    from rbi.errors import SpecError as SpecError
    from rbi.formats.paths import outside_paths_allowed as outside_paths_allowed
    from rbi.reprs import Result as Result
    from rbi.robot.audit import AuditReport as AuditReport
    from rbi.spec.checks import Check as Check
    from rbi.sweeps.plan import Grid as Grid
    from rbi.sweeps.plan import Normal as Normal
    from rbi.sweeps.plan import Uniform as Uniform
    from rbi.text import visible as visible

__all__ = list(PUBLIC)  # a call: griffe reads no names here

_HOME = {
    **PUBLIC,
    # input_uncertainty: not a name of rbi, served for docs/uncertainty.md's rbi.api.input_uncertainty
    "input_uncertainty": "rbi.api.runs",
}
"""Where each name of rbi.api lives: its module is imported when the name is first asked for,
so `rbi inertia` loads neither the audit's modules nor the sweep's, and `import rbi.api` alone
loads none."""


def __getattr__(name: str) -> Any:
    home = _HOME.get(name)
    if home is None:
        raise AttributeError(f"module 'rbi.api' has no attribute {name!r}")
    with collector_paused():  # what a module builds as it is imported lives on: see _HOME
        value = getattr(import_module(home), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_HOME))
