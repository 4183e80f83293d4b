"""A Fatek FBs program served over Fatek's own Modbus map, with a real client."""

from __future__ import annotations

import signal
from collections.abc import Iterator

import pytest
from pymodbus.client import ModbusTcpClient

from ladderworks.core import dialects
from ladderworks.core.modbus.bridge import PlcBridge
from ladderworks.core.modbus.cells import cells_for
from ladderworks.core.modbus.maps import FATEK_MAP, Table
from ladderworks.core.modbus.server import ModbusServer
from ladderworks.core.plc.session import PlcRun
from ladderworks.paths import EXAMPLES
from tests.core.modbus.conftest import STOP, client_of, dialect_plc
from tests.core.modbus.test_cli_serve import served
from tests.core.modbus.test_server import wait_for

# X0 start / X1 stop -> Y0 (self-holding); X6 rising: R1 = R0 + 7; M1924 (first scan): R2 = 100
CONVEYOR = EXAMPLES / "fatek" / "conveyor.lst"
FATEK = dialects.get("fatek")
assert FATEK is not None
Y0, X0, M0, R0, D0 = 0, 1000, 2000, 0, 6000


def fatek_plc(realtime: bool) -> PlcRun:
    """The conveyor example loaded and started."""
    return dialect_plc(CONVEYOR, "fatek", realtime)


@pytest.fixture
def fatek_client() -> Iterator[tuple[ModbusTcpClient, PlcRun]]:
    """A client of a server for the conveyor example scanning in real time."""
    run = fatek_plc(realtime=True)
    served = ModbusServer(PlcBridge(run), "127.0.0.1", 0)
    assert served.bridge.map.name == "fatek"
    served.start()
    client = client_of(served)
    yield client, run
    client.close()
    served.stop()
    run.stop()


def test_a_fatek_hmi_drives_inputs_and_reads_registers(
        fatek_client: tuple[ModbusTcpClient, PlcRun]) -> None:
    client, run = fatek_client
    devices = FATEK.devices
    assert wait_for(lambda: client.read_holding_registers(R0 + 2, count=1).registers
                    == [100])  # R2, moved at the first scan (M1924)
    assert not client.write_coil(X0, True).isError()  # start button X0
    assert wait_for(lambda: client.read_coils(Y0, count=1).bits[0])  # the conveyor Y0 runs
    assert run.bit(devices.bit("X0")) == 1
    assert not client.write_coil(X0, False).isError()
    assert not client.write_register(R0, 5).isError()  # R0 = 5
    assert not client.write_coil(X0 + 6, True).isError()  # X6 rising: R1 = R0 + 7
    assert wait_for(lambda: client.read_holding_registers(R0 + 1, count=1).registers == [12])
    assert client.read_coils(Y0, count=1).bits[0]  # still held (X1 not pressed)
    assert not client.write_coil(X0 + 1, True).isError()  # stop X1
    assert wait_for(lambda: not client.read_coils(Y0, count=1).bits[0])
    assert not client.write_register(D0 + 3, 1234).isError()  # D3
    assert run.read(devices.word("D3")[0], 2) == 1234
    answer = client.read_holding_registers(4168, count=1)  # no R4168-R4999 (FBs manual)
    assert answer.isError() and answer.exception_code == 2
    answer = client.write_coil(9000, True)  # timer status: read only
    assert answer.isError() and answer.exception_code == 2


def test_r5000_to_r5998_and_d_registers_are_served(
        fatek_client: tuple[ModbusTcpClient, PlcRun]) -> None:
    """Fatek's 405001-405999 (R5000-R5998) and 406001-408999 (D0-D2998), with a real client."""
    client, run = fatek_client
    devices = FATEK.devices
    assert not client.write_registers(5000, [4321, 65535]).isError()  # R5000, R5001 (-1)
    assert run.read(devices.word("R5000")[0], 2) == 4321
    assert run.read(devices.word("R5001")[0], 2) == 0xFFFF
    assert client.read_holding_registers(5000, count=2).registers == [4321, 65535]
    assert not client.write_register(5998, 7).isError()  # R5998, the table's last
    assert client.read_holding_registers(5998, count=1).registers == [7]
    assert run.read(devices.word("R5998")[0], 2) == 7
    assert not client.write_register(D0 + 2998, 99).isError()  # D2998
    assert run.read(devices.word("D2998")[0], 2) == 99
    assert client.read_holding_registers(D0 + 2998, count=1).registers == [99]
    answer = client.read_holding_registers(5999, count=1)  # past Fatek's table
    assert answer.isError() and answer.exception_code == 2
    # R5000 is a register of the program too: not R0's, not a counter's memory
    assert run.read(devices.word("R0")[0], 2) != 4321
    assert run.read(devices.word("C0")[0], 2) == 0


def test_every_fatek_row_reaches_fatek_devices() -> None:
    bridge = PlcBridge(fatek_plc(realtime=False))
    served = {(row.table, row.start) for row in bridge.map.rows}
    assert [row for row in FATEK_MAP.rows if (row.table, row.start) not in served] == []
    cells = cells_for("fatek")
    for row in bridge.map.rows:
        cells.check(row)


def test_fatek_timers_and_32_bit_counters_are_reached() -> None:
    run = fatek_plc(realtime=False)
    bridge = PlcBridge(run)
    devices = FATEK.devices
    bridge.write_registers(Table.HOLDING, 9700, [0x5678, 0x1234])  # C200: low word first
    assert run.read(devices.word("C200")[0], 4) == 0x12345678
    bridge.write_registers(Table.HOLDING, 9000 + 50, [17])  # T50's present value
    assert run.read(devices.word("T50")[0], 2) == 17
    bridge.write_bits(Table.COILS, M0 + 1924 - 1, [True])  # M1923
    assert run.bit(devices.bit("M1923")) == 1


def test_serve_a_fatek_program_until_sigterm() -> None:
    with served(CONVEYOR) as (process, first, client):
        assert "(fatek, " in first and "map fatek" in first, first
        assert not client.write_coil(X0, True).isError()
        assert wait_for(lambda: client.read_coils(Y0, count=1).bits[0])
        assert client.read_holding_registers(R0 + 2, count=1).registers == [100]
        client.close()
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=STOP) == 0
        out, err = process.communicate()
    assert "stopped" in out and err == ""
