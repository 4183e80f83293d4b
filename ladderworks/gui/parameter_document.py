"""The PMC parameters of the open program: read beside it, saved with it, modified or not."""

from __future__ import annotations

import os
from pathlib import Path

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.plc.parameters import (
    PmcParameters,
    format_parameters,
    parameter_path,
    parameters_beside,
)
from ladderworks.gui.files import atomic_write
from ladderworks.gui.plc_session import PlcSession


class ParameterDocument:
    """Keeps the session's parameters and the ones last read or saved, to tell a change."""

    def __init__(self, session: PlcSession) -> None:
        self.session = session
        self.saved = PmcParameters()

    @property
    def modified(self) -> bool:
        """True when the parameters differ from the file's (or from the defaults)."""
        return self.session.run.parameters != self.saved

    def reset(self) -> None:
        """A new program: the defaults."""
        self.saved = PmcParameters()
        self.session.set_parameters(self.saved)

    def open(self, program_path: Path) -> list[Diagnostic]:
        """Read the parameter file beside a program (the defaults when there is none); its
        problems. Raises OSError when it exists but cannot be read."""
        found = parameters_beside(program_path)
        self.saved = found.parameters.copy()
        self.session.set_parameters(found.parameters)
        return found.diagnostics

    def save(self, program_path: Path, dialect: str) -> None:
        """Write the parameters beside the program atomically (none set: no file). OSError."""
        path = parameter_path(program_path)
        parameters = self.session.run.parameters.copy()
        if parameters:
            atomic_write(path, format_parameters(parameters, dialect), "utf-8")
        elif path.exists():
            os.unlink(path)  # every value is back to its default
        self.saved = parameters

