"""Time evolution of a rigid body: a heavy top on a fixed pivot, or a torque-free body.

Modules: :mod:`~rbi.sim.scene` (what the simulation needs), :mod:`~rbi.sim.api`
(:func:`~rbi.sim.api.simulate`, :class:`~rbi.sim.api.Trajectory`, ``METHODS``),
:mod:`~rbi.sim._dop853` (the compiled right-hand side and DOP853, a Cython
extension built at install), :mod:`~rbi.sim.compiled` (importing it), :mod:`~rbi.sim.baselines` (the seed chapter's scipy set-up),
:mod:`~rbi.sim.exact` (closed forms), :mod:`~rbi.sim.diagnostics` (invariants, stability),
:mod:`~rbi.sim.summary` (the numbers a run reports).

Nothing here is imported by ``rbi inertia`` and friends: scipy and the kernel load only when a
simulation runs.
"""
