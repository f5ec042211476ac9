"""rbi: a rigid-body calculator — mass properties, principal axes, momentum and motion of a body
described in a YAML spec, as a command-line tool (``rbi``) and a Python library.

```python
import rbi

body = rbi.load("top.yaml")              # or rbi.loads(text), rbi.load({...})
print(body.mass, body.center_of_mass, body.principal().moments)
run = rbi.simulate(body, spin=200.0, tilt_deg=0.01, duration=2.0)
```

The public names are those in ``__all__``; everything else (the subpackages included) is
private and may change. ``import rbi`` alone is cheap: :mod:`rbi.api` (and numpy) are imported
on first use of a public name.

Layers (each imports only those below it): ``formats`` (readers of outside files) ←
``spec`` (YAML, units, validation) ← ``core`` (pure numpy physics) ← ``sim``, ``sweeps``,
``viz``, ``robot``, ``bench``, ``runs`` ← ``api`` (the public Python API) ← ``cli`` (typer
commands and rendering).
"""

from importlib import import_module

from rbi.names import PUBLIC

__version__ = "0.1.0"

__all__ = list(PUBLIC) + ["__version__"]  # a call: griffe reads no names here

_API_NAMES = frozenset(PUBLIC)


def __getattr__(name: str):
    if name in _API_NAMES:
        # rbi.api imports each name's module on first use: the CLI's error lines and `rbi --help`
        # load neither numpy nor the spec's modules
        value = getattr(import_module("rbi.api"), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'rbi' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | _API_NAMES)
