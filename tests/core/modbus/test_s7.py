"""An S7-1200 program served as MB_SERVER serves it (coils %Q, discrete inputs %I, holding
registers %MW or a global DB, input registers %IW), with pymodbus's client."""

from __future__ import annotations

import signal
import struct
from collections.abc import Iterator
from pathlib import Path

import pytest
from pymodbus.client import ModbusTcpClient

from ladderworks.cli import main
from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.diagnostics import DiagnosticError
from ladderworks.core.il import parse_file
from ladderworks.core.il.program import Program
from ladderworks.core.modbus.bridge import PlcBridge
from ladderworks.core.modbus.cells import cells_for
from ladderworks.core.modbus.db_map import chosen_map, data_blocks, db_map
from ladderworks.core.modbus.map_file import parse_map
from ladderworks.core.modbus.maps import S7_MAP, Table
from ladderworks.core.modbus.server import ModbusServer
from ladderworks.core.plc.session import PlcRun
from ladderworks.core.plc.typed import real_bits
from ladderworks.paths import EXAMPLES
from tests.core.modbus.conftest import STOP, client_of
from tests.core.modbus.test_cli_serve import served
from tests.core.modbus.test_server import wait_for

# "Start" %I0.0 sets "Motor" %Q0.0, "Stop" %I0.1 resets it; "DB_Modbus".Komut -> "Hedef Hız"
# %MW10; "Analog" %IW2 -> "DB_Modbus".Durum; "Sıcaklık" %MD16 (Real) -> "DB_Modbus".Sicaklik
EXAMPLE = EXAMPLES / "s7" / "modbus"
I_COILS = 10000  # LadderWorks' coils driving %I (MB_SERVER has none)


def s7_program() -> tuple[Program, bytes]:
    """The Modbus example folder, read and compiled."""
    program = parse_file(EXAMPLE).program
    assert program.dialect == "s7"
    binary = compile_program(program).binary
    assert binary is not None
    return program, binary


def s7_plc(realtime: bool) -> tuple[PlcRun, Program]:
    """The example loaded and started at the S7's 10 ms scans."""
    program, binary = s7_program()
    run = PlcRun(realtime=realtime, period_ms=10)
    assert run.load(binary, program) == []
    assert run.start()
    return run, program


@pytest.fixture(params=["%MW", "DB"])
def s7_client(request: pytest.FixtureRequest
              ) -> Iterator[tuple[ModbusTcpClient, PlcRun, str]]:
    """A client of the example scanning in real time: holding registers %MW, or the DB."""
    run, program = s7_plc(realtime=True)
    own = db_map(program.symbols, "DB_Modbus") if request.param == "DB" else None
    server = ModbusServer(PlcBridge(run, own), "127.0.0.1", 0)
    server.start()
    client = client_of(server)
    yield client, run, request.param
    client.close()
    server.stop()
    run.stop()


def test_an_s7_hmi_drives_inputs_reads_outputs_and_words(
        s7_client: tuple[ModbusTcpClient, PlcRun, str]) -> None:
    client, run, holding = s7_client
    assert not client.write_coil(I_COILS + 0, True).isError()  # "Start" %I0.0
    assert wait_for(lambda: client.read_coils(0, count=1).bits[0])  # "Motor" %Q0.0 set
    assert client.read_discrete_inputs(0, count=2).bits[:2] == [True, False]  # %I0.0, %I0.1
    assert not client.write_coil(I_COILS + 0, False).isError()
    assert not client.write_coil(I_COILS + 1, True).isError()  # "Stop" %I0.1
    assert wait_for(lambda: not client.read_coils(0, count=1).bits[0])
    run.write(Address(Area.X, 2), -1234 & 0xFFFF, 2)  # "Analog" %IW2, big-endian
    assert run.read(Address(Area.X, 2)) == 0xFB  # %IB2 is the high byte
    assert client.read_input_registers(1, count=1).registers == [-1234 & 0xFFFF]  # %IW2
    if holding == "%MW":  # register n is %MW(2n): %MW10 is register 5, %MB10 its high byte
        assert not client.write_register(5, 0x1234).isError()
        assert run.read(Address(Area.R, 10)) == 0x12 and run.read(Address(Area.R, 11)) == 0x34
        run.write(Address(Area.R, 16), real_bits(21.5), 4)  # "Sıcaklık" %MD16, a Real
        high, low = client.read_holding_registers(8, count=2).registers
        assert struct.unpack(">f", struct.pack(">HH", high, low))[0] == 21.5
        assert client.read_holding_registers(4095, count=1).registers == [0]  # %MW8190
        answer = client.read_holding_registers(4096, count=1)  # past %MW8190
        assert answer.isError() and answer.exception_code == 2
        return
    # the DB: Komut (register 0) -> "Hedef Hız" %MW10; Durum (1) <- "Analog"; Sicaklik (2, 3)
    assert wait_for(lambda: client.read_holding_registers(1, count=1).registers
                    == [-1234 & 0xFFFF])
    assert not client.write_register(0, 300).isError()
    assert wait_for(lambda: run.read(Address(Area.R, 10), 2) == 300)
    run.write(Address(Area.R, 16), real_bits(-2.25), 4)
    assert wait_for(lambda: client.read_holding_registers(2, count=2).registers
                    == list(struct.unpack(">HH", struct.pack(">f", -2.25))))
    answer = client.read_holding_registers(4, count=1)  # the DB has 4 words
    assert answer.isError() and answer.exception_code == 2
    answer = client.write_register(1, 1, )  # Durum is the program's, yet writable as in TIA
    assert not answer.isError()


def test_the_s7_map_rows_reach_s7_memory() -> None:
    run, _program = s7_plc(realtime=False)
    bridge = PlcBridge(run)
    assert bridge.map is S7_MAP  # every row served
    cells = cells_for("s7")
    assert cells.bit(S7_MAP.find(Table.COILS, 17), 17) == Address(Area.Y, 2, 1)  # %Q2.1
    assert cells.register(S7_MAP.find(Table.HOLDING, 3), 3) == Address(Area.R, 6)  # %MW6
    assert cells.register(S7_MAP.find(Table.INPUT, 511), 511) == Address(Area.X, 1022)
    bridge.write_registers(Table.HOLDING, 1, [0xABCD])
    assert run.read(Address(Area.R, 2), 2) == 0xABCD and run.read(Address(Area.R, 2)) == 0xAB
    assert bridge.read_registers(Table.HOLDING, 1, 1) == [0xABCD]
    with pytest.raises(Exception) as refused:  # discrete inputs and %IW are read only
        bridge.write_registers(Table.INPUT, 0, [1])
    assert "02" in str(refused.value)


def test_the_db_map_and_its_errors() -> None:
    program, _binary = s7_program()
    assert data_blocks(program.symbols) == ['"DB_Modbus"']
    own = db_map(program.symbols, '"db_modbus"')  # TIA's names: any case, quoted or not
    holding = own.rows_of(Table.HOLDING)
    assert [(r.start, r.count, r.width) for r in holding] == [(0, 4, 2)]
    assert program.symbols is not None
    assert cells_for("s7").register(holding[0], 1) == program.symbols.address_of(
        '"DB_Modbus".Durum')
    assert {r.table for r in own.rows} == set(Table)  # coils, discrete, input stay
    with pytest.raises(DiagnosticError) as missing:
        db_map(program.symbols, "DB_Yok")
    assert missing.value.diagnostics[0].message() == (
        "'DB_Yok' is neither a map file nor a global DB of the program"
        ' (its global DBs: "DB_Modbus")')
    assert chosen_map("", "s7", program.symbols) is None


def test_an_s7_map_file(tmp_path: Path) -> None:
    own = parse_map("coils,0,16,%Q4.0,rw\nholding,100,2,%MW20,rw,2\ninput,0,1,%IW64,r,2\n",
                    dialect="s7")
    assert [r.device for r in own.rows] == ["%Q4.0", "%MW20", "%IW64"]
    with pytest.raises(DiagnosticError) as bad:
        parse_map("holding,0,1,%MW0,rw\ncoils,0,9,%Q1023.0,rw\nholding,5,1,Z9,rw,2\n",
                  dialect="s7")
    assert [(d.line, d.code) for d in bad.value.diagnostics] == [
        (1, "modbus-map-width"), (2, "modbus-map-area"), (3, "s7-address")]
    assert "run past the end of area Q (%Q0.0-%Q1023.7)" in bad.value.diagnostics[1].message()
    path = tmp_path / "hmi.csv"
    path.write_text("coils,0,8,%Q0.0,rw\n", encoding="utf-8")
    program, _binary = s7_program()
    found = chosen_map(str(path), "s7", program.symbols)  # a file wins over a DB's name
    assert found is not None and found.rows[0].device == "%Q0.0"


def test_serve_an_s7_folder_with_a_db_map_until_sigterm(
        capsys: pytest.CaptureFixture[str]) -> None:
    with served(EXAMPLE, "--map", "DB_Modbus") as (process, first, client):
        assert '(s7, 10 ms' in first and 'map s7 "DB_Modbus"' in first, first
        assert not client.write_register(0, 77).isError()  # Komut -> "Hedef Hız"
        assert not client.write_coil(I_COILS, True).isError()
        assert wait_for(lambda: client.read_coils(0, count=1).bits[0])
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=STOP) == 0
        client.close()
    assert main(["serve", str(EXAMPLE), "--map", "DB_Yok", "--modbus", "127.0.0.1:0"]) == 2
    assert "'DB_Yok' is neither a map file nor a global DB" in capsys.readouterr().err
