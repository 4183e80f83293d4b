"""The data files a wheel carries in the package, staged from the checkout (stdlib only).

The build backend (tools/ladderworks_build.py) calls stage_data(); the tests and the CI's
product check (tools/product_check.py) use the same names.
"""

from __future__ import annotations

import importlib.util
import shutil
import subprocess
from pathlib import Path

DATA_FOLDERS = ("resources", "help", "translations")  # the package folders made here


def data_files(checkout: Path) -> dict[str, Path]:
    """Package-relative name -> checkout file, for every data file copied as it is."""
    files: dict[str, Path] = {}
    resources = checkout / "resources"
    for source in sorted(resources.rglob("*")):
        relative = source.relative_to(resources)
        if source.is_file() and not any(part.startswith(".") for part in relative.parts):
            files[f"resources/{relative.as_posix()}"] = source
    for page in sorted((checkout / "docs").glob("instructions*.md")):
        files[f"help/{page.name}"] = page
    return files


def translation_files(checkout: Path) -> dict[str, Path]:
    """Package-relative `.qm` name -> the `.ts` it is compiled from."""
    return {f"translations/{ts.stem}.qm": ts
            for ts in sorted((checkout / "translations").glob("*.ts"))}


def lrelease() -> str:
    """PySide6's lrelease (or one on PATH); the build fails without it."""
    spec = importlib.util.find_spec("PySide6")
    if spec is not None and spec.origin is not None:
        for name in ("lrelease", "lrelease.exe"):
            bundled = Path(spec.origin).parent / name
            if bundled.exists():
                return str(bundled)
    found = shutil.which("pyside6-lrelease") or shutil.which("lrelease")
    if found is None:
        raise RuntimeError("lrelease not found: install PySide6-Essentials to build the wheel")
    return found


def stage_data(checkout: Path, package_dir: Path) -> list[Path]:
    """Copy the data files into `package_dir` and compile the translations; the files made."""
    for folder in DATA_FOLDERS:  # nothing left over from an earlier build of other files
        shutil.rmtree(package_dir / folder, ignore_errors=True)
    made: list[Path] = []
    for name, source in data_files(checkout).items():
        target = package_dir / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source, target)
        made.append(target)
    program = lrelease()
    for name, source in translation_files(checkout).items():
        target = package_dir / name
        target.parent.mkdir(parents=True, exist_ok=True)
        subprocess.run([program, "-silent", str(source), "-qm", str(target)],
                       check=True, timeout=120)
        if not target.exists():
            raise RuntimeError(f"lrelease made no {target}")
        made.append(target)
    return made
