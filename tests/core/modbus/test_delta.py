"""A Delta DVP program served over Delta's own Modbus map, with a real client."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from pymodbus.client import ModbusTcpClient

from ladderworks.core import dialects
from ladderworks.core.diagnostics import DiagnosticError
from ladderworks.core.modbus.bridge import PlcBridge, servable
from ladderworks.core.modbus.cells import cells_for
from ladderworks.core.modbus.map_file import parse_map
from ladderworks.core.modbus.maps import DELTA_MAP, Access, MapRow, ModbusMap, Table
from ladderworks.core.modbus.server import ModbusServer
from ladderworks.core.plc.session import PlcRun
from ladderworks.paths import EXAMPLES
from tests.core.modbus.conftest import client_of, dialect_plc
from tests.core.modbus.test_server import wait_for

CMP_D10 = EXAMPLES / "delta" / "cmp_d10.txt"  # X0: CMP K20 D10 M0; M0..M2 -> Y0..Y2
DELTA = dialects.get("delta")
assert DELTA is not None
X0, Y0, M0, D0 = 0x0400, 0x0500, 0x0800, 0x1000


def delta_plc(realtime: bool) -> PlcRun:
    """The CMP example loaded and started."""
    return dialect_plc(CMP_D10, "delta", realtime)


@pytest.fixture
def delta_client() -> Iterator[tuple[ModbusTcpClient, PlcRun]]:
    """A client of a server for the CMP example scanning in real time."""
    run = delta_plc(realtime=True)
    served = ModbusServer(PlcBridge(run), "127.0.0.1", 0)
    assert served.bridge.map is DELTA_MAP
    served.start()
    client = client_of(served)
    yield client, run
    client.close()
    served.stop()
    run.stop()


def test_a_delta_hmi_connects_unchanged(delta_client: tuple[ModbusTcpClient, PlcRun]) -> None:
    client, run = delta_client
    assert not client.write_register(D0 + 10, 5).isError()  # D10 = 5
    assert not client.write_coil(X0, True).isError()  # X0 on: compare 20 with D10
    assert wait_for(lambda: client.read_coils(Y0, count=3).bits[:3] == [True, False, False])
    assert client.read_coils(M0, count=3).bits[:3] == [True, False, False]  # 20 > D10
    assert client.read_discrete_inputs(X0, count=1).bits[0]
    assert not client.write_register(D0 + 10, 20).isError()
    assert wait_for(lambda: client.read_coils(Y0, count=3).bits[:3] == [False, True, False])
    assert not client.write_register(D0 + 10, 30).isError()
    assert wait_for(lambda: client.read_coils(Y0, count=3).bits[:3] == [False, False, True])
    assert run.read(DELTA.devices.word("D10")[0], 2) == 30
    answer = client.read_discrete_inputs(X0 + 256, count=1)  # past X377
    assert answer.isError() and answer.exception_code == 2
    answer = client.read_holding_registers(0x0FFF, count=1)  # below D0
    assert answer.isError() and answer.exception_code == 2


def test_delta_elements_are_reached_through_its_devices() -> None:
    run = delta_plc(realtime=False)
    bridge = PlcBridge(run)
    devices = DELTA.devices
    bridge.write_bits(Table.COILS, X0 + 8, [True])  # the 9th input is X10 (octal)
    assert run.bit(devices.bit("X10")) == 1
    bridge.write_bits(Table.COILS, 0xB000, [True])  # M1536
    assert run.bit(devices.bit("M1536")) == 1
    bridge.write_registers(Table.HOLDING, 0x9000 + 903, [11, 12])  # D4999, D5000
    assert run.read(devices.word("D4999")[0], 2) == 11
    assert run.read(devices.word("D5000")[0], 2) == 12  # the next range, in area E
    bridge.write_registers(Table.HOLDING, 0x0700, [0x5678, 0x1234])  # C200: low word first
    assert run.read(devices.word("C200")[0], 4) == 0x12345678
    bridge.write_registers(Table.HOLDING, 0x0E00 + 1, [300])  # C1: 16-bit, 4 bytes apart
    assert run.read(devices.word("C1")[0], 2) == 300
    assert bridge.read_registers(Table.HOLDING, 0x0E00, 3) == [0, 300, 0]


def test_every_delta_row_reaches_delta_devices() -> None:
    cells = cells_for("delta")
    for row in DELTA_MAP.rows:
        cells.check(row)


def test_a_delta_map_file_names_delta_devices() -> None:
    own = parse_map("holding,0,10,D100,rw,2\ncoils,100,8,M0,rw\n", "own.csv", "delta")
    assert len(own.rows) == 2
    with pytest.raises(DiagnosticError) as caught:
        parse_map("coils,0,8,M0,rw\ncoils,8,8,X8,rw\nholding,0,1,D0,rw\n", "bad.csv", "delta")
    found = {d.line: d.code for d in caught.value.diagnostics}
    assert found == {2: "device-octal", 3: "modbus-map-width"}


def test_rows_naming_devices_the_dialect_lacks_are_not_served() -> None:
    good = MapRow(Table.HOLDING, 0, 10, "D0", Access.READ_WRITE, 2)
    past = MapRow(Table.HOLDING, 100, 10, "D9995", Access.READ_WRITE, 2)  # D10000 is none
    unknown = MapRow(Table.COILS, 0, 8, "Q0", Access.READ_WRITE)  # no Q in Delta
    served = servable(ModbusMap("mixed", (good, past, unknown)), cells_for("delta"))
    assert served.rows == (good,)
    assert servable(DELTA_MAP, cells_for("delta")) is DELTA_MAP
