"""The build backend: setuptools, plus the data the package reads, mapped in at build time.

pyproject.toml names this module as the PEP 517 backend (backend-path = tools) and its BuildPy
as setuptools' build_py. A wheel gets the checkout's `resources/`, the help pages
`docs/instructions*.md` and `translations/*.ts` compiled to `.qm` with PySide6's lrelease, in
the package folders that `ladderworks/paths.py` reads. An editable install maps nothing: the
package then reads the checkout's own folders.
"""

from __future__ import annotations

from pathlib import Path

from package_data import data_files, stage_data, translation_files
from setuptools import build_meta as _setuptools
from setuptools.command.build_py import build_py

CHECKOUT = Path(__file__).resolve().parent.parent
PACKAGE = "ladderworks"
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
