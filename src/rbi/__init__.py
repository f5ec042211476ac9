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

from rbi.names import PUBLIC

__version__ = "0.1.0"

__all__ = list(PUBLIC) + ["__version__"]  # a call: griffe reads no names here

_API_NAMES = frozenset(PUBLIC)


def __getattr__(name: str):
    if name in _API_NAMES:
        # names whose modules use the standard library only come without rbi.api (and numpy):
        # the CLI's start-up and its error lines stay cheap
        if name in ("SpecError", "ArgumentError"):
            from rbi import errors as module
        elif name == "outside_paths_allowed":
            from rbi.formats import paths as module
        elif name == "visible":
            from rbi import text as module
        else:
            # not at top level: `rbi --help` would load rbi.api too
            from rbi import api as module
        value = getattr(module, name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'rbi' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | _API_NAMES)
