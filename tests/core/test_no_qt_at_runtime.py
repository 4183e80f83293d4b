"""Importing every core and CLI module loads no Qt (checked in a fresh interpreter)."""

from __future__ import annotations

import subprocess
import sys

from ladderworks.paths import CHECKOUT

SCRIPT = """
import importlib, pkgutil, sys
import ladderworks.cli, ladderworks.core
names = []
for package in (ladderworks.core, ladderworks.cli):
    for info in pkgutil.walk_packages(package.__path__, package.__name__ + "."):
        if info.name.rsplit(".", 1)[-1] != "__main__":  # __main__ would run the CLI
            importlib.import_module(info.name)
            names.append(info.name)
print(len(names))
loaded = sorted(m for m in sys.modules if m.split(".")[0] in ("PySide6", "pyqtgraph", "shiboken6"))
print(" ".join(loaded))
"""


def test_core_and_cli_modules_load_no_qt() -> None:
    done = subprocess.run([sys.executable, "-c", SCRIPT], cwd=CHECKOUT, capture_output=True,
                          text=True, timeout=120, check=True)
    count, loaded = [*done.stdout.splitlines(), "", ""][:2]
    assert int(count) > 40  # every module was imported, not just the packages
    assert loaded == "", f"Qt loaded by core/CLI modules: {loaded}"
