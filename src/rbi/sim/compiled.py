"""Loading the compiled integrator of :mod:`rbi.sim.kernels`.

:func:`integrator` returns the compiled ``integrate`` function and says how it was obtained:

- ``numba-aot``: an extension module that numba compiled ahead of time (``numba.pycc``) into
  rbi's cache folder. Loading it takes about a millisecond and needs neither numba nor an
  LLVM start-up, which keeps a whole ``rbi simulate`` process well under a second. It is
  built on the first run (a few seconds, needs a C compiler) and reused while the kernel
  source, numba and Python stay the same.
- ``numba-jit``: numba's just-in-time compilation with its on-disk cache (``cache=True``).
  Used when the ahead-of-time module cannot be built (no C compiler, no ``numba.pycc``).
  A warm start costs about half a second of numba start-up.

Environment: ``RBI_KERNEL=auto|aot|jit`` (default auto: aot, falling back to jit);
``RBI_CACHE_DIR`` (default ``$XDG_CACHE_HOME/rbi`` or ``~/.cache/rbi``).
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import subprocess
import sys
import sysconfig
import tempfile
import time
from pathlib import Path
from typing import Callable, NamedTuple

import numpy as np

STATUS_DONE = 0
STATUS_MORE = 1  # max_steps reached: call again to continue
STATUS_STEP_TOO_SMALL = 2
STATUS_NOT_FINITE = 3

_SOURCES = ("kernels.py", "dop853_tableau.py", "compiled.py")


class Loaded(NamedTuple):
    integrate: Callable
    how: str  # "numba-aot" or "numba-jit"
    load_seconds: float


_LOADED: Loaded | None = None


def integrator() -> Loaded:
    """The compiled integrator, loaded (built on the first run) once per process."""
    global _LOADED
    if _LOADED is None:
        start = time.perf_counter()
        mode = os.environ.get("RBI_KERNEL", "auto").lower()
        integrate, how = None, "numba-jit"
        if mode in ("auto", "aot"):
            integrate = _ahead_of_time()
            how = "numba-aot"
            if integrate is None and mode == "aot":
                raise RuntimeError("RBI_KERNEL=aot: the ahead-of-time kernel could not be built "
                                   f"(see {_module_path().with_suffix('.failed')})")
        if integrate is None:
            from rbi.sim import kernels

            integrate, how = kernels.integrate, "numba-jit"
        _warm_up(integrate)
        _LOADED = Loaded(integrate, how, time.perf_counter() - start)
    return _LOADED


def cache_dir() -> Path:
    """Where the ahead-of-time module lives."""
    if os.environ.get("RBI_CACHE_DIR"):
        return Path(os.environ["RBI_CACHE_DIR"])
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "rbi"


def module_name() -> str:
    """Name of the ahead-of-time module: changes with the kernel source, numba and Python."""
    from importlib.metadata import version

    digest = hashlib.sha256()
    here = Path(__file__).parent
    for name in _SOURCES:
        digest.update((here / name).read_bytes())
    digest.update(f"{version('numba')} {version('numpy')} {sys.version} {sysconfig.get_platform()}".encode())
    return f"rbi_kernels_{digest.hexdigest()[:16]}"


def _module_path() -> Path:
    return cache_dir() / (module_name() + sysconfig.get_config_var("EXT_SUFFIX"))


def _ahead_of_time() -> Callable | None:
    """The ahead-of-time ``integrate``, building it first if needed; None when it cannot be
    had (the reason is kept in a ``.failed`` file beside it, so later runs do not retry)."""
    path = _module_path()
    failed = path.with_suffix(".failed")
    if not path.exists():
        if failed.exists():
            return None
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
        except OSError:
            return None
        if not os.access(path.parent, os.W_OK):
            return None  # nowhere to keep it: use the just-in-time route, without retrying each run
        print("rbi: compiling the simulation kernel (first run only, a few seconds) ...", file=sys.stderr)
        proc = subprocess.run([sys.executable, "-m", "rbi.sim.compiled", str(path)], capture_output=True, text=True)
        if proc.returncode != 0 or not path.exists():
            try:
                failed.write_text(proc.stdout + proc.stderr)
            except OSError:
                pass
            return None
    try:
        spec = importlib.util.spec_from_file_location(module_name(), path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
    except (ImportError, OSError):
        return None
    return module.integrate


def build(path: Path) -> None:
    """Compile :func:`rbi.sim.kernels.integrate` ahead of time into the extension module
    ``path`` (written to a temporary folder beside it, then renamed into place)."""
    import warnings

    warnings.simplefilter("ignore")
    from numba.pycc import CC

    from rbi.sim import kernels

    path = Path(path)
    name = path.name.split(".")[0]
    with tempfile.TemporaryDirectory(dir=path.parent, prefix=".build-") as folder:
        cc = CC(name)
        cc.output_dir = folder
        cc.verbose = False
        cc.export("integrate", kernels.INTEGRATE_SIGNATURE)(kernels.integrate.py_func)
        cc.compile()
        built = [p for p in Path(folder).iterdir() if p.name.startswith(name) and p.suffix in (".so", ".pyd")]
        os.replace(built[0], path)


def _warm_up(integrate: Callable) -> None:
    """One tiny run, so that compiling or loading from the cache happens here, not in a timed
    integration."""
    y = np.array([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0])
    eye = np.eye(3)
    integrate(y, np.zeros(9), np.array([0.0, 0.1]), np.empty((2, 7)), eye, eye, np.zeros(3),
              np.array([1e-6, 1.0]), np.zeros(4, dtype=np.int64), 100)


if __name__ == "__main__":
    build(Path(sys.argv[1]))
