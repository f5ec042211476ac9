"""The closed form of bodies/flange.step (see docs/scripts/make_flange_step.py), in millimetres
and grams at steel's density (7.85e-3 g/mm³): a disc and a hub (cylinders) with a bore and six
bolt holes (cylinders) taken away, each moved to the flange's centre of mass by the
parallel-axis theorem. docs/step.md prints it beside `rbi inertia`'s numbers.

Run from the project root: python docs/scripts/flange_closed_form.py
"""

from __future__ import annotations

import math

import numpy as np

DENSITY = 7.85e-3  # g/mm³ (steel, rbi's built-in value 7850 kg/m³)


def cylinder(radius: float, z0: float, height: float, x: float = 0.0, y: float = 0.0):
    """(mass g, centre mm, inertia about its centre g·mm²) of a solid cylinder along z."""
    mass = DENSITY * math.pi * radius**2 * height
    across = mass * (3 * radius**2 + height**2) / 12
    return mass, np.array([x, y, z0 + height / 2]), np.diag([across, across, mass * radius**2 / 2])


def flange():
    """Disc Ø120 × 12, hub Ø60 × 30 on it, bore Ø40 through both, six Ø14 holes on Ø90."""
    pieces = [(+1, cylinder(60, 0, 12)), (+1, cylinder(30, 12, 30)), (-1, cylinder(20, 0, 42))]
    for k in range(6):
        angle = 2 * math.pi * k / 6
        pieces.append((-1, cylinder(7, 0, 12, 45 * math.cos(angle), 45 * math.sin(angle))))
    mass = sum(sign * m for sign, (m, _, _) in pieces)
    com = sum(sign * m * c for sign, (m, c, _) in pieces) / mass
    inertia = np.zeros((3, 3))
    for sign, (m, c, own) in pieces:
        d = c - com
        inertia += sign * (own + m * (d @ d * np.eye(3) - np.outer(d, d)))
    return mass, com, inertia


if __name__ == "__main__":
    mass, com, inertia = flange()
    print(f"mass            {mass:.13g} g")
    print(f"centre of mass  z = {com[2]:.13g} mm")
    print(f"Ixx = Iyy       {inertia[0, 0]:.13g} g·mm²")
    print(f"Izz             {inertia[2, 2]:.13g} g·mm²")
