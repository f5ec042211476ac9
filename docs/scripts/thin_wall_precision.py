"""Thin wall by subtraction (cylinder minus cylinder) vs the tube shape, against mpmath (50 digits).

Run: .venv/bin/python docs/scripts/thin_wall_precision.py   (quoted in docs/spec.md)
"""

# needs: mpmath
import mpmath as mp

from rbi.core import shapes
from rbi.core.mass import MassProperties


def cylinder(mass: float, radius: float, length: float) -> MassProperties:
    """A solid cylinder along z from the origin: its closed forms, as rbi's spec path builds one."""
    moments = shapes.cylinder_moments(mass, radius, length)
    return MassProperties(mass, [0, 0, 0.5 * length], shapes.axisymmetric_inertia(*moments, [0, 0, 1]))


def err(got, ref) -> float:
    """Relative error of ``got`` against the high-precision ``ref``."""
    return float(abs((mp.mpf(got) - ref) / ref))


mp.mp.dps = 50
R, L, rho = 1.0, 2.0, 7.85
print("wall/R    subtraction: mass  Izz  Ixx  |  tube shape: mass  Izz  Ixx   (relative errors)")
for wall in [1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-9]:
    r = R - wall
    Rm, rm = mp.mpf(R), mp.mpf(r)  # r as stored in double
    m = rho * mp.pi * (Rm**2 - rm**2) * L
    izz = m * (Rm**2 + rm**2) / 2
    ixx = m * (3 * (Rm**2 + rm**2) + L**2) / 12
    outer = cylinder(rho * shapes.cylinder_volume(R, L), R, L)
    inner = cylinder(rho * shapes.cylinder_volume(r, L), r, L)
    sub = MassProperties.sum(
        [outer, MassProperties(-inner.mass, inner.center_of_mass, -inner.inertia_about_com)]
    )
    tube = shapes.tube(rho * shapes.tube_volume(R, r, L), R, r, [0, 0, 0], [0, 0, L])
    print(
        f"{wall:7.0e}   {err(sub.mass, m):9.1e} {err(sub.inertia_about_com[2, 2], izz):9.1e} {err(sub.inertia_about_com[0, 0], ixx):9.1e}"
        f"   |   {err(tube.mass, m):9.1e} {err(tube.inertia_about_com[2, 2], izz):9.1e} {err(tube.inertia_about_com[0, 0], ixx):9.1e}"
    )
