"""Fixtures of the Modbus tests: the spindle-override example on a PLC, a server on loopback."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from pymodbus.client import ModbusTcpClient

from ladderworks.core.compiler import compile_program
from ladderworks.core.il import parse_file
from ladderworks.core.modbus.bridge import PlcBridge
from ladderworks.core.modbus.maps import PMC_MAP
from ladderworks.core.modbus.server import ModbusServer
from ladderworks.core.plc.session import PlcRun
from ladderworks.paths import EXAMPLES

SPINDLE = EXAMPLES / "spindle_override.LAD"  # X2.1, X2.3, X2.5 -> R102 -> G30 (%)
TIMEOUT = 3.0  # seconds a client waits for an answer
STOP = 30  # seconds a served process may take to stop on SIGTERM (a loaded machine)


def spindle_binary() -> bytes:
    """The compiled spindle-override example."""
    binary = compile_program(parse_file(SPINDLE).program).binary
    assert binary is not None
    return binary


@pytest.fixture
def plc() -> PlcRun:
    """The spindle-override example loaded and started on the virtual clock."""
    run = PlcRun()
    assert run.load(spindle_binary()) == []
    assert run.start()
    return run


@pytest.fixture
def live_plc() -> Iterator[PlcRun]:
    """The spindle-override example scanning on its real-time thread (8 ms)."""
    run = PlcRun(realtime=True)
    assert run.load(spindle_binary()) == []
    assert run.start()
    yield run
    run.stop()


@pytest.fixture
def server(live_plc: PlcRun) -> Iterator[ModbusServer]:
    """A Modbus server for the live PLC on a free loopback port."""
    served = ModbusServer(PlcBridge(live_plc, PMC_MAP), "127.0.0.1", 0)
    served.start()
    yield served
    served.stop()


def client_of(server: ModbusServer) -> ModbusTcpClient:
    """A connected pymodbus client of `server`."""
    client = ModbusTcpClient("127.0.0.1", port=server.port, timeout=TIMEOUT, retries=0)
    assert client.connect()
    return client


@pytest.fixture
def client(server: ModbusServer) -> Iterator[ModbusTcpClient]:
    """A pymodbus client connected to the server."""
    connected = client_of(server)
    yield connected
    connected.close()


def dialect_plc(path: Path, dialect: str, realtime: bool) -> PlcRun:
    """A dialect's example program loaded and started, at its dialect's scan period."""
    from ladderworks.core import dialects

    found = dialects.get(dialect)
    assert found is not None
    program = parse_file(path).program
    assert program.dialect == dialect
    binary = compile_program(program).binary
    assert binary is not None
    run = PlcRun(realtime=realtime, period_ms=found.period_ms)
    assert run.load(binary, program) == []
    assert run.start()
    return run
