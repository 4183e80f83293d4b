"""Test help for the PLC utility docks: a PLC session on the virtual clock running an example."""

from __future__ import annotations

from ladderworks import paths
from ladderworks.core.il import parse_file
from ladderworks.gui.plc_session import PlcSession


def running_session(example: str) -> PlcSession:
    """A session on the virtual clock with resources/examples/`example` loaded and started."""
    result = parse_file(paths.EXAMPLES / example)
    assert result.ok, result.diagnostics
    session = PlcSession(realtime=False)
    compiled = session.load_program(result.program)
    assert compiled.binary is not None, compiled.diagnostics
    assert session.start()
    return session
