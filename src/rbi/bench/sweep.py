"""``rbi sweep`` throughput and memory (issue 10), each against a baseline measured in the same run.

- Throughput: a grid of ``rbi sweep bodies/top.yaml --spin 150:260:100 --tilt 0.01:1:100`` (10⁴
  runs of 4 s at the default rtol; 20 × 10 runs of 0.5 s in a quick run), run in this process
  as the command runs it (:func:`rbi.sweep`, rows streamed to a CSV), in runs per
  second. Baselines: the single-run in-process rate (``rbi.sim.api.simulate`` on one run after
  another, over an evenly spaced sample of the same grid points) times the number of cores
  (target ≥ 0.8), and a loop of ``rbi simulate FILE --spin S --tilt T`` processes over a sample
  of the same runs (target ≥ 300×).
- Memory: a child ``rbi sweep`` of 101,000 short runs (0.02 s, 2 samples; 10⁴ in a quick run),
  more than the 10⁵ rows ``rbi sweep`` keeps in memory to print, streaming to ``--out``; its
  resident memory is sampled while it runs, against the rows written so far, and its peak is
  its high-water mark (``VmHWM`` in ``/proc/PID/status``). A flat
  profile (the last quarter no higher than the first by more than a few MB) is what bounds a
  10⁶-run sweep; the target is 500 MB.
"""

from __future__ import annotations

import os
import subprocess
import time
from pathlib import Path

import rbi
from rbi.bench import Progress
from rbi.bench.paths import bodies_folder, rbi_command
from rbi.bench.timing import clocked, run_process
from rbi.runs.run import scene_of as body_scene
from rbi.sim.api import simulate
from rbi.sim.scene import initial_state
from rbi.spec.load import load_body
from rbi.sweeps.execute import available_cores
from rbi.sweeps.plan import Grid

TARGETS = {"ratio_to_cores_x_single": 0.8, "ratio_to_process_loop": 300.0, "peak_rss_mb": 500.0}


GRIDS = {
    True: {"spin": (150.0, 260.0, 20), "tilt": (0.01, 1.0, 10), "duration": 0.5},
    False: {"spin": (150.0, 260.0, 100), "tilt": (0.01, 1.0, 100), "duration": 4.0},
}
"""The grid of the throughput sweep: quick run, full run."""


def _axis_text(axis) -> str:
    return f"{axis[0]:g}:{axis[1]:g}:{axis[2]}"


def sample_runs(g: dict, count: int) -> list[tuple[float, float]]:
    """``count`` (spin, tilt) points spread evenly over the grid, in run order."""
    spins, tilts = (Grid(*g[axis]).values().tolist() for axis in ("spin", "tilt"))
    total = len(spins) * len(tilts)
    picks = sorted({int(round(i * (total - 1) / max(count - 1, 1))) for i in range(count)})
    return [(spins[k // len(tilts)], tilts[k % len(tilts)]) for k in picks]


def single_run_rate(spec: Path, runs: list[tuple[float, float]], duration: float) -> dict:
    """Runs per second of ``simulate`` called once per run, one after another, in this process
    (the body loaded once, as a sweep does)."""

    scene = body_scene(load_body(spec), None)
    samples = 481  # as rbi sweep and rbi simulate by default
    simulate(scene, *initial_state(runs[0][1], [0.0, 0.0, runs[0][0]]), duration, samples)  # warm
    seconds = clocked(
        lambda: [simulate(scene, *initial_state(t, [0.0, 0.0, w]), duration, samples) for w, t in runs]
    )[0]
    return _rate(len(runs), seconds)


def _rate(runs: int, seconds: float) -> dict:
    return {"runs": runs, "seconds": seconds, "runs_per_second": runs / seconds}


def process_loop_rate(spec: Path, runs: list[tuple[float, float]], duration: float) -> dict:
    """Runs per second of a shell loop of whole ``rbi simulate`` processes."""
    seconds = 0.0
    for spin, tilt in runs:
        words = ["simulate", str(spec), "--spin", repr(spin), "--tilt", repr(tilt), "--duration"]
        wall, _, proc = run_process(rbi_command() + words + [f"{duration:g}"])
        if proc.returncode != 0:
            raise RuntimeError(f"rbi simulate: exit {proc.returncode}: {proc.stderr.strip()[-200:]}")
        seconds += wall
    return _rate(len(runs), seconds)


def sweep_rate(spec: Path, g: dict, folder: Path) -> dict:
    out = folder / "sweep.csv"
    runs = g["spin"][2] * g["tilt"][2]
    grid = {"spin": Grid(*g["spin"]), "tilt_deg": Grid(*g["tilt"]), "duration": g["duration"]}
    seconds, cpu, _ = clocked(lambda: rbi.sweep(spec, **grid, check_budget=False, out=out))
    return {
        "command": f"rbi sweep bodies/top.yaml --spin {_axis_text(g['spin'])} --tilt {_axis_text(g['tilt'])} "
        f"--duration {g['duration']:g} --out FILE.csv --yes --format json",
        "runs": runs,
        "rows_written": _rows_in(out),
        "seconds": seconds,
        "runs_per_second": runs / seconds,
        # CPU time of every thread of this process over the wall time: how many cores the
        # sweep actually got (the machine's other work takes the rest)
        "cpu_seconds": cpu,
        "cores_used": cpu / seconds,
    }


def _rows_in(csv_path: Path) -> int:
    """Rows of a CSV file, its header not counted."""
    with open(csv_path, encoding="utf-8") as stream:
        return sum(1 for _ in stream) - 1


def memory_profile(spec: Path, quick: bool, folder: Path) -> dict:
    """Resident memory of a child sweep streaming to --out, sampled as the rows arrive."""
    # more runs than rbi sweep keeps in memory to print (MAX_ROWS_SHOWN, 10⁵): rows only streamed
    spins = 100 if quick else 1010
    out = folder / "memory.csv"
    command = (
        f"rbi sweep bodies/top.yaml --spin 150:260:{spins} --tilt 0.01:1:100 --duration 0.02 "
        "--samples 2 --out FILE.csv --yes"
    )
    paths = {"bodies/top.yaml": str(spec), "FILE.csv": str(out)}
    argv = rbi_command() + [paths.get(word, word) for word in command.split()[1:]]
    runs = spins * 100
    start = time.perf_counter()
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    samples = _sample_memory(proc, out, start)
    stderr = proc.communicate()[1]
    seconds = time.perf_counter() - start
    if proc.returncode != 0:
        return {"error": f"exit {proc.returncode}: {stderr.strip()[-200:]}"}
    quarter = max(1, len(samples) // 4)
    return {
        "command": command,
        "runs": runs,
        "rows_written": _rows_in(out),
        "seconds": seconds,
        # the child's high-water mark of resident memory (VmHWM) at the last sample: wait4's
        # ru_maxrss would also count the bench process's own memory at the fork
        "peak_rss_mb": max((s["peak_mb"] for s in samples), default=None),
        "rss_first_quarter_mb": max((s["rss_mb"] for s in samples[:quarter]), default=None),
        "rss_last_quarter_mb": max((s["rss_mb"] for s in samples[-quarter:]), default=None),
        "samples": samples[:: max(1, len(samples) // 40)],
    }


def run(quick: bool, progress: Progress, folder: Path) -> dict:

    spec = bodies_folder() / "top.yaml"
    g = GRIDS[quick]
    cores = available_cores()
    progress("sweep: the single-run in-process rate")
    single = single_run_rate(spec, sample_runs(g, 50 if quick else 500), g["duration"])
    progress("sweep: rbi sweep over the grid")
    sweep = sweep_rate(spec, g, folder)
    progress("sweep: a loop of rbi simulate processes")
    loop = process_loop_rate(spec, sample_runs(g, 3 if quick else 10), g["duration"])
    progress("sweep: memory while streaming")
    memory = memory_profile(spec, quick, folder)
    return {
        "grid": {"spin": list(g["spin"]), "tilt_deg": list(g["tilt"]), "duration": g["duration"]},
        "cores": cores,
        "single_run": single,
        "sweep": sweep,
        "process_loop": loop,
        "memory": memory,
        "ratio_to_cores_x_single": sweep["runs_per_second"] / (cores * single["runs_per_second"]),
        "ratio_to_single": sweep["runs_per_second"] / single["runs_per_second"],
        "ratio_to_process_loop": sweep["runs_per_second"] / loop["runs_per_second"],
        "targets": TARGETS,
    }


def _sample_memory(proc: subprocess.Popen, out: Path, start: float) -> list[dict]:
    """Resident memory (now and its high-water mark, MB) of the running child ``proc`` and the
    size of its output ``out``, every 0.1 s until it exits (its return code is set)."""
    samples = []
    status_file = Path(f"/proc/{proc.pid}/status")
    while not (waited := os.waitpid(proc.pid, os.WNOHANG))[0]:
        try:
            fields = dict(line.split(":", 1) for line in status_file.read_text().splitlines() if ":" in line)
            mb = {
                key: int(fields[name].split()[0]) / 1024
                for key, name in (("rss_mb", "VmRSS"), ("peak_mb", "VmHWM"))
            }
            size = out.stat().st_size if out.exists() else 0
            samples.append({"seconds": round(time.perf_counter() - start, 3)} | mb | {"csv_bytes": size})
        except (OSError, KeyError, ValueError):
            pass
        time.sleep(0.1)
    proc.returncode = os.waitstatus_to_exitcode(waited[1])
    return samples
