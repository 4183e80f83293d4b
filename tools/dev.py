"""The README's commands in a project-local environment: `python3 tools/dev.py run|test|...`.

Standard library only, so any Python >= 3.11 can start it (Debian's own, pyenv's, macOS's,
Windows' `py`). It creates `.venv` with `python -m venv` when missing, installs the project in
editable mode there only when pyproject.toml changed since the last install (`run` installs
what the app needs, `test` adds the test tools), then runs the command with `.venv`'s Python.
"""

from __future__ import annotations

import hashlib
import importlib.util
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

CHECKOUT = Path(__file__).resolve().parent.parent
VENV = CHECKOUT / ".venv"
STAMP_NAME = "ladderworks-install.json"
LINTED = ("ladderworks", "tests", "benchmarks", "tools")
MINIMUM = (3, 11)
EXTRAS = {"run": (), "test": ("test",), "lint": ("test",), "bench": (), "product": ()}


def venv_python(venv: Path) -> Path:
    """The interpreter inside `venv`."""
    if os.name == "nt":
        return venv / "Scripts" / "python.exe"
    return venv / "bin" / "python"


def fail(message: str) -> int:
    """Print `message` on stderr; the exit code 1."""
    print(f"tools/dev.py: {message}", file=sys.stderr)
    return 1


def venv_problem() -> str | None:
    """Why this Python cannot make a virtual environment with pip, or None."""
    if sys.version_info < MINIMUM:
        return (f"LadderWorks needs Python >= {MINIMUM[0]}.{MINIMUM[1]}; this is "
                f"{sys.version.split()[0]} ({sys.executable})")
    if importlib.util.find_spec("venv") is None or importlib.util.find_spec("ensurepip") is None:
        minor = f"python3.{sys.version_info.minor}-venv"
        return ("this Python cannot create virtual environments (no venv/ensurepip). "
                f"On Debian or Ubuntu: sudo apt-get install python3-venv (or {minor})")
    return None


def create_venv(venv: Path) -> str | None:
    """Create `venv` with this Python; the problem when it cannot."""
    problem = venv_problem()
    if problem is not None:
        return problem
    print(f"Creating {venv.name} with {sys.executable} ...", flush=True)
    result = subprocess.run([sys.executable, "-m", "venv", str(venv)])
    if result.returncode != 0 or not venv_python(venv).exists():
        shutil.rmtree(venv, ignore_errors=True)
        return "python -m venv failed (on Debian or Ubuntu: sudo apt-get install python3-venv)"
    return None


def wanted_install(checkout: Path, extras: tuple[str, ...]) -> dict[str, object]:
    """The stamp an install of `extras` from the current pyproject.toml leaves."""
    digest = hashlib.sha256((checkout / "pyproject.toml").read_bytes()).hexdigest()
    return {"pyproject": digest, "extras": sorted(extras)}


def needs_install(stamp: Path, wanted: dict[str, object]) -> bool:
    """True unless the last install used the same pyproject.toml and covered the extras."""
    try:
        done = json.loads(stamp.read_text("utf-8"))
    except (OSError, ValueError):
        return True
    if not isinstance(done, dict) or done.get("pyproject") != wanted["pyproject"]:
        return True
    done_extras, wanted_extras = done.get("extras"), wanted["extras"]
    if not isinstance(done_extras, list) or not isinstance(wanted_extras, list):
        return True
    return not set(wanted_extras) <= set(done_extras)


def install(checkout: Path, venv: Path, extras: tuple[str, ...]) -> str | None:
    """Install the project (editable) with `extras` when needed; the problem when it fails."""
    stamp = venv / STAMP_NAME
    wanted = wanted_install(checkout, extras)
    if not needs_install(stamp, wanted):
        return None
    target = f".[{','.join(extras)}]" if extras else "."
    print(f"Installing LadderWorks{target[1:]} into {venv.name} "
          "(first run, or pyproject.toml changed) ...", flush=True)
    command = [str(venv_python(venv)), "-m", "pip", "install", "--quiet",
               "--disable-pip-version-check", "--editable", target]
    if subprocess.run(command, cwd=checkout).returncode != 0:
        stamp.unlink(missing_ok=True)
        return "pip install failed (see above)"
    stamp.write_text(json.dumps(wanted), "utf-8")
    return None


def commands(python: Path, name: str, args: list[str]) -> list[list[str]]:
    """The command lines `name` runs with the environment's `python`."""
    py = str(python)
    if name == "run":
        return [[py, "-m", "ladderworks", *args]]
    if name == "lint":
        return [[py, "-m", "ruff", "check", *LINTED]]
    if name == "test":
        return [[py, "-m", "ruff", "check", *LINTED], [py, "-m", "mypy", "ladderworks"],
                [py, "-m", "pytest", "-q", "-n", "auto", *args]]
    if name == "bench":
        return [[py, str(script), *args]
                for script in sorted((CHECKOUT / "benchmarks").glob("*.py"))]
    return [[py, str(CHECKOUT / "tools" / "product_check.py"), *args]]


def main(argv: list[str]) -> int:
    """`run [ARGS]` the IDE, `test [PYTEST ARGS]`, `lint`, `bench` or `product` (the CI check)."""
    if not argv or argv[0] not in EXTRAS:
        return fail("usage: python3 tools/dev.py run|test|lint|bench|product [ARGS...]")
    name, args = argv[0], argv[1:]
    if not venv_python(VENV).exists():
        problem = create_venv(VENV)
        if problem is not None:
            return fail(problem)
    problem = install(CHECKOUT, VENV, EXTRAS[name])
    if problem is not None:
        return fail(problem)
    env = dict(os.environ)
    if name == "test":
        env["QT_QPA_PLATFORM"] = "offscreen"
    for command in commands(venv_python(VENV), name, args):
        code = subprocess.run(command, cwd=CHECKOUT, env=env).returncode
        if code != 0:
            return code
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except KeyboardInterrupt:
        sys.exit(130)
