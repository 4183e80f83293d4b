"""PlcBridge on the virtual clock: the map, exceptions, forces, and requests between scans."""

from __future__ import annotations

import threading

import pytest

from ladderworks.core.address import parse_address
from ladderworks.core.modbus.bridge import ILLEGAL_ADDRESS, ILLEGAL_VALUE, ModbusError, PlcBridge
from ladderworks.core.modbus.map_file import parse_map
from ladderworks.core.modbus.maps import PMC_MAP, Table
from ladderworks.core.plc.session import PlcRun

G30 = 3030  # holding register of G30
X2_1, X2_3, X2_5 = 17, 19, 21  # coils of the rotary switch's three inputs


def code_of(call: object, *args: object) -> int:
    """The Modbus exception code a bridge call raises."""
    with pytest.raises(ModbusError) as caught:
        call(*args)  # type: ignore[operator]
    return caught.value.code


def test_coils_drive_the_switch_and_g30_follows(plc: PlcRun) -> None:
    bridge = PlcBridge(plc, PMC_MAP)
    bridge.write_bits(Table.COILS, X2_1, [True, False, True])  # X2.1 and X2.3 on
    plc.run_scans(1)
    assert plc.bit(parse_address("X2.1")) == 1 and plc.bit(parse_address("X2.3")) == 1
    assert bridge.read_registers(Table.HOLDING, G30, 1) == [60]
    assert bridge.read_bits(Table.COILS, 16, 8) == [False, True, False, True] + [False] * 4
    assert bridge.read_registers(Table.HOLDING, 10102, 1) == [1 << 3]  # R102.3: position 3


def test_outside_the_map_is_exception_02(plc: PlcRun) -> None:
    bridge = PlcBridge(plc, PMC_MAP)
    assert code_of(bridge.read_registers, Table.HOLDING, 900, 1) == ILLEGAL_ADDRESS
    assert code_of(bridge.read_registers, Table.HOLDING, 120, 10) == ILLEGAL_ADDRESS  # X128
    assert code_of(bridge.read_bits, Table.COILS, 1020, 8) == ILLEGAL_ADDRESS
    assert code_of(bridge.read_registers, Table.INPUT, 0, 1) == ILLEGAL_ADDRESS
    assert code_of(bridge.write_registers, Table.HOLDING, 40000, [1]) == ILLEGAL_ADDRESS


def test_writing_read_only_data_is_exception_02_and_changes_nothing(plc: PlcRun) -> None:
    bridge = PlcBridge(plc, PMC_MAP)
    assert code_of(bridge.write_registers, Table.HOLDING, G30, [5]) == ILLEGAL_ADDRESS
    assert code_of(bridge.write_registers, Table.HOLDING, 1000, [1]) == ILLEGAL_ADDRESS  # Y0
    # a write that reaches a read-only register is refused whole
    assert code_of(bridge.write_registers, Table.HOLDING, 767 + 2000, [1, 2]) == ILLEGAL_ADDRESS
    assert plc.read(parse_address("F767")) == 0


def test_a_value_wider_than_its_register_is_exception_03(plc: PlcRun) -> None:
    bridge = PlcBridge(plc, PMC_MAP)
    assert code_of(bridge.write_registers, Table.HOLDING, 20000, [256]) == ILLEGAL_VALUE
    bridge.write_registers(Table.HOLDING, 20000, [255, 7])
    assert plc.read(parse_address("D0"), 2) == 0x07FF


def test_registers_of_two_bytes_read_and_write_words() -> None:
    own = parse_map("holding,0,10,D100,rw,2\n")
    run = PlcRun()
    bridge = PlcBridge(run, own)
    bridge.write_registers(Table.HOLDING, 1, [0x1234, 65535])
    assert run.read(parse_address("D102"), 2) == 0x1234
    assert bridge.read_registers(Table.HOLDING, 0, 3) == [0, 0x1234, 0xFFFF]
    assert code_of(bridge.write_registers, Table.HOLDING, 0, [65536]) == ILLEGAL_VALUE


def test_a_forced_input_stays_forced_and_gets_the_written_value_when_released(
        plc: PlcRun) -> None:
    bridge = PlcBridge(plc, PMC_MAP)
    x21 = parse_address("X2.1")
    plc.force(x21, 0)
    bridge.write_bits(Table.COILS, X2_1, [True])
    bridge.write_registers(Table.HOLDING, 2, [0xFF])  # the whole byte X2
    plc.run_scans(1)
    assert bridge.read_bits(Table.COILS, X2_1, 1) == [False]  # the force wins
    assert bridge.read_registers(Table.HOLDING, 2, 1) == [0xFD]
    plc.release(x21)
    assert bridge.read_bits(Table.COILS, X2_1, 1) == [True]  # what the client wrote


def test_a_forced_relay_stays_forced_when_its_byte_is_written(plc: PlcRun) -> None:
    bridge = PlcBridge(plc, PMC_MAP)
    plc.force(parse_address("R500.0"), 1)
    bridge.write_registers(Table.HOLDING, 10500, [0x00])
    assert bridge.read_registers(Table.HOLDING, 10500, 1) == [0x01]
    bridge.write_bits(Table.COILS, 10000 + 8 * 500, [False, True])
    assert bridge.read_registers(Table.HOLDING, 10500, 1) == [0x03]


def test_writes_are_told_to_the_input_listeners(plc: PlcRun) -> None:
    heard: list[tuple[str, str, int]] = []
    plc.input_listeners.append(lambda kind, address, value, _w: heard.append(
        (kind, str(address), value)))
    bridge = PlcBridge(plc, PMC_MAP)
    bridge.write_bits(Table.COILS, X2_1, [True])
    bridge.write_registers(Table.HOLDING, 20001, [9])
    assert heard == [("set", "X2.1", 1), ("write", "D1", 9)]


def test_a_request_waits_for_the_scan_to_end(plc: PlcRun) -> None:
    bridge = PlcBridge(plc, PMC_MAP)
    assert plc.engine is not None
    scanning = threading.Event()
    finish = threading.Event()

    def long_scan() -> None:  # holds the lock as a scan does, from its start to its end
        assert plc.engine is not None
        with plc.engine.lock:
            plc.write(parse_address("D0"), 1)
            scanning.set()
            finish.wait(5)
            plc.write(parse_address("D1"), 1)

    answers: list[list[int]] = []
    scan = threading.Thread(target=long_scan)
    scan.start()
    assert scanning.wait(5)
    reader = threading.Thread(
        target=lambda: answers.append(bridge.read_registers(Table.HOLDING, 20000, 2)))
    reader.start()
    reader.join(0.2)
    assert reader.is_alive() and not answers  # not in the middle of the scan
    finish.set()
    reader.join(5)
    scan.join(5)
    assert answers == [[1, 1]]  # the whole scan or none of it
