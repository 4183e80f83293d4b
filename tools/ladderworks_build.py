"""The build backend: setuptools, plus the data the package reads, mapped in at build time.

pyproject.toml names this module as the PEP 517 backend (backend-path = tools) and its BuildPy
as setuptools' build_py. A wheel gets the checkout's `resources/`, the help pages
`docs/instructions*.md` and `translations/*.ts` compiled to `.qm` with PySide6's lrelease, in
the package folders that `ladderworks/paths.py` reads. An editable install maps nothing: the
package then reads the checkout's own folders.
"""

from __future__ import annotations

import importlib.util
import shutil
import subprocess
from pathlib import Path

from setuptools import build_meta as _setuptools
from setuptools.command.build_py import build_py

CHECKOUT = Path(__file__).resolve().parent.parent
PACKAGE = "ladderworks"
DATA_FOLDERS = ("resources", "help", "translations")  # the package folders made here
# lrelease comes with PySide6: a wheel build needs it, an editable install does not.
LRELEASE_REQUIREMENT = "PySide6-Essentials>=6.6,!=6.12.0"

build_wheel = _setuptools.build_wheel
build_sdist = _setuptools.build_sdist
build_editable = _setuptools.build_editable
prepare_metadata_for_build_wheel = _setuptools.prepare_metadata_for_build_wheel
prepare_metadata_for_build_editable = _setuptools.prepare_metadata_for_build_editable
get_requires_for_build_sdist = _setuptools.get_requires_for_build_sdist
get_requires_for_build_editable = _setuptools.get_requires_for_build_editable


def get_requires_for_build_wheel(config_settings: dict[str, object] | None = None) -> list[str]:
    """setuptools' own build requirements plus PySide6 for lrelease."""
    return [*_setuptools.get_requires_for_build_wheel(config_settings), LRELEASE_REQUIREMENT]


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


class BuildPy(build_py):
    """build_py that also stages the data files into the built package (not when editable)."""

    def run(self) -> None:
        """Build the Python modules, then the data."""
        super().run()
        if not self.editable_mode:
            stage_data(CHECKOUT, Path(self.build_lib) / PACKAGE)

    def get_outputs(self, include_bytecode: bool = True) -> list[str]:
        """The modules' outputs and the staged data files."""
        outputs = list(super().get_outputs(include_bytecode))
        if not self.editable_mode:
            names = [*data_files(CHECKOUT), *translation_files(CHECKOUT)]
            outputs += [str(Path(self.build_lib) / PACKAGE / name) for name in names]
        return outputs
