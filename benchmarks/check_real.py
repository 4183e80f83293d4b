"""`ladderworks-cli check` of the 37,883-step FANUC_STUDER_S41_F036: ms as a whole process, and
inside a fresh process (imports, then the check itself: the parse, then the compiler's checks);
run from the repository root.

The first figure is the command as a technician runs it: the wheel built from this checkout,
installed with pip into a fresh virtual environment (bytecode compiled at install, no
development .pth files at start-up). Each figure is the best and the median of RUNS fresh
processes (the machine may be shared). `--no-wheel` skips the wheel (it takes ~15 s to build)."""

from __future__ import annotations

import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from real_files import real_file

ROOT = Path(__file__).resolve().parent.parent
NAME = "FANUC_STUDER_S41_F036"
RUNS = 7
GOAL_MS = 300

# In a fresh interpreter: ms to import the CLI and ms for check itself (stdout discarded).
INSIDE = """
import io, sys, time, contextlib
began = time.perf_counter()
from ladderworks.cli import main
imported = time.perf_counter()
with contextlib.redirect_stdout(io.StringIO()):
    main(["check", sys.argv[1]])
done = time.perf_counter()
print(f"{(imported - began) * 1000:.1f} {(done - imported) * 1000:.1f}")
"""

# In a fresh interpreter: ms of the parse `check` runs (parse_for_check), then of the compiler's
# checks alone on its program.
PARTS = """
import sys, time
from ladderworks.core.compiler import check
from ladderworks.core.il import parse_for_check
began = time.perf_counter()
result = parse_for_check(sys.argv[1])
parsed = time.perf_counter()
check(result.program)
done = time.perf_counter()
print(f"{(parsed - began) * 1000:.1f} {(done - parsed) * 1000:.1f}")
"""


def _installed_cli(workdir: Path) -> Path | None:
    """`ladderworks-cli` of the wheel of this checkout installed in a fresh venv in `workdir`
    (without its dependencies: `check` imports none of them); None when pip cannot build it."""
    quiet = ["--quiet", "--disable-pip-version-check"]
    steps = [[sys.executable, "-m", "pip", "wheel", "--no-deps", *quiet, "--wheel-dir",
              str(workdir / "dist"), str(ROOT)],
             [sys.executable, "-m", "venv", "--without-pip", str(workdir / "venv")]]
    for step in steps:
        if subprocess.run(step, cwd=workdir, check=False).returncode != 0:
            return None
    bin_dir = workdir / "venv" / ("Scripts" if os.name == "nt" else "bin")
    wheels = [str(wheel) for wheel in (workdir / "dist").glob("ladderworks-*.whl")]
    install = [sys.executable, "-m", "pip", "--python", str(bin_dir / "python"), "install",
               "--no-deps", *quiet, *wheels]
    if subprocess.run(install, cwd=workdir, check=False).returncode != 0:
        return None
    return bin_dir / "ladderworks-cli"


def _command_ms(command: list[str], env: dict[str, str] | None = None) -> tuple[float, float]:
    """(wall ms, CPU ms) of one run of `command` from the repository root (stdout discarded)."""
    cpu = _children_cpu()
    start = time.perf_counter()
    subprocess.run(command, cwd=ROOT, stdout=subprocess.DEVNULL, check=False, env=env)
    return (time.perf_counter() - start) * 1000, (_children_cpu() - cpu) * 1000


def _children_cpu() -> float:
    """CPU seconds (user + system) of the finished child processes so far."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _process_ms(path: Path, env: dict[str, str] | None = None) -> tuple[float, float]:
    """(wall ms, CPU ms) of `python3 -m ladderworks.cli check FILE`, interpreter start
    included (CPU time is less disturbed by other work on the machine)."""
    return _command_ms([sys.executable, "-m", "ladderworks.cli", "check", str(path)], env)


def _inside_ms(path: Path, script: str = INSIDE) -> tuple[float, float]:
    """(import ms, check ms) measured inside a fresh interpreter (or the two figures `script`
    prints)."""
    done = subprocess.run([sys.executable, "-c", script, str(path)], cwd=ROOT,
                          capture_output=True, text=True, check=True)
    imported, checked = done.stdout.split()
    return float(imported), float(checked)


def _line(label: str, values: list[float], goal: str = "") -> str:
    return (f"{label:30s} best {min(values):6.0f} ms  median {statistics.median(values):6.0f} ms"
            + (f"  ({goal})" if goal else ""))


def main() -> int:
    """Run the measurement and print the figures."""
    path = real_file(NAME)
    if path is None:
        print(f"no ../shared/real-programs/{NAME}.txt beside the repository", file=sys.stderr)
        return 1
    installed: list[tuple[float, float]] = []
    empty_venv: list[float] = []
    if "--no-wheel" not in sys.argv:
        with tempfile.TemporaryDirectory() as workdir:
            cli = _installed_cli(Path(workdir))
            if cli is not None:
                _command_ms([str(cli), "check", str(path)])
                installed = [_command_ms([str(cli), "check", str(path)]) for _ in range(RUNS)]
                empty_venv = [_command_ms([str(cli.parent / "python"), "-c", "pass"])[0]
                              for _ in range(RUNS)]
    process = [_process_ms(path) for _ in range(RUNS)]
    with tempfile.TemporaryDirectory() as cache:
        # as an installed package runs: modules read from their bytecode cache, not compiled
        # (PYTHONDONTWRITEBYTECODE, if set here, makes every run compile them)
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        env["PYTHONPYCACHEPREFIX"] = cache
        _process_ms(path, env)
        cached = [_process_ms(path, env) for _ in range(RUNS)]
    inside = [_inside_ms(path) for _ in range(RUNS)]
    parts = [_inside_ms(path, PARTS) for _ in range(RUNS)]
    # an interpreter that does nothing: the floor under the process figure
    empty = [_command_ms([sys.executable, "-c", "pass"])[0] for _ in range(RUNS)]
    load = os.getloadavg()
    print(f"{NAME}: ladderworks-cli check, {RUNS} fresh processes each")
    if installed:
        print(_line("check, installed wheel:", [w for w, _c in installed],
                    f"goal under {GOAL_MS} ms"))
        print(_line("  its CPU time:", [c for _w, c in installed]))
        print(_line("  its python -c pass:", empty_venv))
    else:
        print("check, installed wheel:      not measured (--no-wheel, or pip could not build it)")
    print(_line("check, python3 -m (checkout):", [w for w, _c in process]))
    print(_line("  its CPU time:", [c for _w, c in process]))
    print(_line("  bytecode cached:", [w for w, _c in cached]))
    print(_line("  check in-process:", [c for _i, c in inside]))
    print(_line("    parse_for_check:", [p for p, _c in parts]))
    print(_line("    compiler checks alone:", [c for _p, c in parts]))
    print(_line("  importing the CLI:", [i for i, _c in inside]))
    print(_line("  python3 -c pass:", empty))
    print(f"load average: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} on {os.cpu_count()} cores")
    return 0


if __name__ == "__main__":
    sys.exit(main())
