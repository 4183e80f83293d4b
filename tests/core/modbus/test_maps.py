"""The Modbus maps as data (PMC, Delta DVP, Fatek FBs) and the user's CSV map file."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.core.address import parse_address
from ladderworks.core.diagnostics import DiagnosticError
from ladderworks.core.modbus.cells import PMC_CELLS as cells
from ladderworks.core.modbus.map_file import parse_map, read_map
from ladderworks.core.modbus.maps import (
    DEFAULT_MAPS,
    DELTA_MAP,
    FATEK_MAP,
    PMC_MAP,
    S7_MAP,
    Access,
    ModbusMap,
    Table,
    default_map,
)


def element(modbus_map: ModbusMap, table: Table, address: int) -> str:
    """The PLC element (PMC spelling) a Modbus address reaches."""
    row = modbus_map.find(table, address)
    assert row is not None, (table, address)
    index = address - row.start
    if table.bits:
        return str(cells.bit(row, index))
    return str(cells.register(row, index))


def test_pmc_coil_8b_plus_n_is_bit_n_of_x_byte_b() -> None:
    assert element(PMC_MAP, Table.COILS, 0) == "X0.0"
    assert element(PMC_MAP, Table.COILS, 17) == "X2.1"
    assert element(PMC_MAP, Table.COILS, 19) == "X2.3"
    assert element(PMC_MAP, Table.COILS, 1023) == "X127.7"
    assert PMC_MAP.find(Table.COILS, 1024) is None


@pytest.mark.parametrize(("register", "address"), [
    (0, "X0"), (127, "X127"), (200, "X200"), (1000, "Y0"), (1005, "Y5"), (2000, "F0"),
    (3030, "G30"), (4000, "A0"), (5000, "K0"), (5900, "K900"), (6000, "T0"), (7000, "C0"),
    (10000, "R0"), (17999, "R7999"), (19000, "R9000"), (20000, "D0"), (29999, "D9999"),
    (30000, "E0"), (39999, "E9999"),
])
def test_pmc_holding_registers_are_one_pmc_byte_each(register: int, address: str) -> None:
    assert element(PMC_MAP, Table.HOLDING, register) == address


@pytest.mark.parametrize("register", [128, 199, 999, 1128, 2768, 4250, 5100, 6500, 7400, 9999,
                                      18000, 19500, 40000, 65535])
def test_pmc_holding_registers_between_the_areas_are_not_mapped(register: int) -> None:
    assert PMC_MAP.find(Table.HOLDING, register) is None


def test_pmc_outputs_and_cnc_commands_are_read_only() -> None:
    for register in (1000, 3000, 4000, 19000):
        row = PMC_MAP.find(Table.HOLDING, register)
        assert row is not None and row.access is Access.READ
    for register in (0, 2000, 5000, 6000, 7000, 10000, 20000, 30000):
        row = PMC_MAP.find(Table.HOLDING, register)
        assert row is not None and row.access is Access.READ_WRITE


def test_pmc_y_bits_are_discrete_inputs_and_r_bits_coils() -> None:
    assert element(PMC_MAP, Table.DISCRETE, 8 * 5 + 3) == "Y5.3"
    assert element(PMC_MAP, Table.COILS, 10000 + 8 * 102 + 6) == "R102.6"


def test_every_pmc_row_lies_in_its_area() -> None:
    for row in PMC_MAP.rows:
        cells.check(row)  # raises when a row runs past its area


@pytest.mark.parametrize("modbus_map", [PMC_MAP, DELTA_MAP, FATEK_MAP])
def test_no_two_rows_of_a_table_share_an_address(modbus_map: ModbusMap) -> None:
    for row in modbus_map.rows:
        assert row.end - 1 <= 0xFFFF
        others = ModbusMap("rest", tuple(r for r in modbus_map.rows if r is not row))
        assert others.overlap(row) is None, row


def test_the_map_of_each_dialect() -> None:
    assert default_map("seed") is PMC_MAP and default_map("fanuc") is PMC_MAP
    assert default_map("delta") is DELTA_MAP and default_map("fatek") is FATEK_MAP
    assert default_map("s7") is S7_MAP
    assert set(DEFAULT_MAPS) == {"seed", "fanuc", "delta", "fatek", "s7"}


def first(modbus_map: ModbusMap, table: Table, device: str) -> int:
    """The Modbus address of the row that starts at `device`."""
    found = [row.start for row in modbus_map.rows_of(table) if row.device == device]
    assert len(found) == 1, (table, device)
    return found[0]


def test_delta_dvp_map_is_the_manuals() -> None:
    # DVP-ES2/EX2/SS2/SA2/SX2/SE operation manual, 4.4 "PLC Device Address"
    assert first(DELTA_MAP, Table.COILS, "S0") == 0x0000
    assert first(DELTA_MAP, Table.DISCRETE, "X0") == 0x0400
    assert first(DELTA_MAP, Table.COILS, "Y0") == 0x0500
    assert first(DELTA_MAP, Table.COILS, "T0") == 0x0600
    assert first(DELTA_MAP, Table.HOLDING, "T0") == 0x0600
    assert first(DELTA_MAP, Table.COILS, "M0") == 0x0800
    assert first(DELTA_MAP, Table.COILS, "M1536") == 0xB000
    assert first(DELTA_MAP, Table.COILS, "C0") == 0x0E00
    assert first(DELTA_MAP, Table.COILS, "C200") == 0x0EC8
    assert first(DELTA_MAP, Table.HOLDING, "C0") == 0x0E00
    assert first(DELTA_MAP, Table.HOLDING, "C200") == 0x0700
    assert first(DELTA_MAP, Table.HOLDING, "D0") == 0x1000
    assert first(DELTA_MAP, Table.HOLDING, "D4096") == 0x9000
    # X/Y octal X0..X377: 256 inputs; M0..M1535 then M1536..M4095; D up to D9999
    assert DELTA_MAP.find(Table.DISCRETE, 0x04FF) is not None
    assert DELTA_MAP.find(Table.DISCRETE, 0x0500) is None
    assert DELTA_MAP.find(Table.COILS, 0x0DFF) is not None
    d_high = DELTA_MAP.find(Table.HOLDING, 0x9000 + 9999 - 4096)
    assert d_high is not None and DELTA_MAP.find(Table.HOLDING, 0x9000 + 9999 - 4096 + 1) is None
    assert all(row.width == 2 for row in DELTA_MAP.rows_of(Table.HOLDING))  # 16-bit words


def test_fatek_fbs_map_is_its_modbus_table() -> None:
    # Fatek's 1-based numbers minus one: 000001 Y0, 001001 X0, 002001 M0, 006001 S0,
    # 009001 T0, 009501 C0; 400001 R0, 405001 R5000, 406001 D0, 409001 T0, 409501 C0
    coils = {"Y0": 0, "X0": 1000, "M0": 2000, "S0": 6000, "T0": 9000, "C0": 9500}
    for device, start in coils.items():
        assert first(FATEK_MAP, Table.COILS, device) == start
    holding = {"R0": 0, "R5000": 5000, "D0": 6000, "T0": 9000, "C0": 9500, "C200": 9700}
    for device, start in holding.items():
        assert first(FATEK_MAP, Table.HOLDING, device) == start
    assert FATEK_MAP.find(Table.COILS, 2000 + 2001) is not None  # M2001
    assert FATEK_MAP.find(Table.COILS, 2000 + 2002) is None


GOOD = """\
# my HMI's map
table,start,count,plc,access,width
coils,0,16,X2.0,rw
discrete,0x10,8,Y0.0,r
holding,100,10,D0,rw,2
input,0,4,G30,r
"""


def test_a_map_file_gives_its_rows() -> None:
    own = parse_map(GOOD, "own.csv")
    assert len(own.rows) == 4
    assert element(own, Table.COILS, 3) == "X2.3"
    assert element(own, Table.DISCRETE, 0x11) == "Y0.1"
    assert element(own, Table.HOLDING, 101) == "D2"  # two bytes a register
    assert element(own, Table.INPUT, 0) == "G30"
    assert [row.line for row in own.rows] == [3, 4, 5, 6]


def test_each_bad_line_is_reported_at_its_line() -> None:
    text = ("coils,0,8,X0.0,rw\n"
            "holdings,0,1,D0,rw\n"  # 2: no such table
            "holding,0,1,D0,rw\n"
            "holding,0,1,D5,rw\n"  # 4: overlaps line 3
            "discrete,0,1,Y0.0,rw\n"  # 5: discrete inputs are read-only
            "holding,70000,1,D0,rw\n"  # 6: address past 65535
            "holding,10,2,D9999,rw\n"  # 7: past the end of D
            "coils,100,8,R5,rw\n"  # 8: a coil needs a bit address
            "holding,200,1,D0\n"  # 9: too few columns
            "holding,300,1,D0,w\n")  # 10: access
    with pytest.raises(DiagnosticError) as caught:
        parse_map(text, "bad.csv")
    found = {d.line: d.code for d in caught.value.diagnostics}
    assert found == {2: "modbus-map-table", 4: "modbus-map-overlap",
                     5: "modbus-map-read-only", 6: "modbus-map-number", 7: "modbus-map-area",
                     8: "bit-expected", 9: "modbus-map-columns", 10: "modbus-map-access"}
    assert "holdings" in caught.value.diagnostics[0].message()


def test_an_empty_map_file_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "empty.csv"
    path.write_text("# nothing\n", encoding="utf-8")
    with pytest.raises(DiagnosticError) as caught:
        read_map(path)
    assert caught.value.code == "modbus-map-empty"


def test_a_map_file_with_a_bom_reads(tmp_path: Path) -> None:
    path = tmp_path / "bom.csv"
    path.write_bytes("\ufeffcoils,0,8,X0.0,rw\r\n".encode())
    assert read_map(path).rows[0].device == "X0.0"
    assert cells.first(read_map(path).rows[0]) == parse_address("X0.0")


def test_a_fatek_map_file_reaches_the_registers_past_fatek_s_table() -> None:
    """R5999-R8071 and D2999-D4095 have no address in Fatek's table (docs/modbus.md): a map
    file serves them; R4168 (no such register in the FBs manual's map) is refused at its line."""
    own = parse_map("holding,10000,3072,R5000,rw,2\nholding,20000,4096,D0,rw,2\n", "f.csv",
                    "fatek")
    assert [(row.device, row.count) for row in own.rows] == [("R5000", 3072), ("D0", 4096)]
    with pytest.raises(DiagnosticError) as caught:
        parse_map("holding,0,1,R0,rw,2\nholding,10,1,R4168,rw,2\n"
                  "holding,100,3073,R5000,rw,2\nholding,9000,4097,D0,rw,2\n", "bad.csv", "fatek")
    assert [d.line for d in caught.value.diagnostics] == [2, 3, 4]  # R8072, D4096: past the end
