"""Time evolution of a rigid body: a heavy top on a fixed pivot, or a torque-free body. The
entry point is :func:`rbi.sim.api.simulate`; each module's docstring says what it holds.

Nothing here is imported by ``rbi inertia`` and friends: scipy and the kernel load only when a
simulation runs.
"""
