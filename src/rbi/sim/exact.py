"""Closed-form solutions (work in progress: not available yet)."""

from __future__ import annotations


class NotIntegrable(ValueError):
    """The scene has no closed form that rbi implements."""


def solve(scene, q0, omega0):
    raise NotIntegrable("closed forms are not implemented yet")
