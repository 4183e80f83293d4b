"""Test help for the PLC utility docks: a PLC session on the virtual clock running a program."""

from __future__ import annotations

from ladderworks import paths
from ladderworks.core.il import ParseResult, parse, parse_file
from ladderworks.gui.plc_session import PlcSession


def _started(result: ParseResult) -> PlcSession:
    assert result.ok, result.diagnostics
    session = PlcSession(realtime=False)
    compiled = session.load_program(result.program)
    assert compiled.binary is not None, compiled.diagnostics
    assert session.start()
    return session


def running_session(example: str) -> PlcSession:
    """A session on the virtual clock with resources/examples/`example` loaded and started."""
    return _started(parse_file(paths.EXAMPLES / example))


def running_text(text: str) -> PlcSession:
    """A session on the virtual clock running the program `text` (instruction list)."""
    return _started(parse(text))
