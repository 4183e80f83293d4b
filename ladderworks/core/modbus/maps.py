"""Modbus maps as data: which Modbus table and address reaches which PLC element, by dialect.

A map is a list of rows (`MapRow`): a Modbus table, its first address and count, the PLC
element the first address reaches (in the dialect's own spelling) and the access. Element i of
a row is the i-th bit (coils, discrete inputs) or the i-th register (`width` bytes of PLC memory
each) from that first element. `DEFAULT_MAPS` holds one map per dialect; `docs/modbus.md`
shows them as tables, with the sources of the Delta and Fatek ones.
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass, field
from enum import StrEnum


class Table(StrEnum):
    """The four Modbus tables (data model), named as a map file names them."""

    COILS = "coils"  # function codes 1, 5, 15
    DISCRETE = "discrete"  # 2 (discrete inputs)
    HOLDING = "holding"  # 3, 6, 16, 22, 23 (holding registers)
    INPUT = "input"  # 4 (input registers)

    @property
    def bits(self) -> bool:
        """True for the bit tables (coils, discrete inputs)."""
        return self in (Table.COILS, Table.DISCRETE)

    @property
    def writable(self) -> bool:
        """True for the tables the protocol can write (coils, holding registers)."""
        return self in (Table.COILS, Table.HOLDING)


class Access(StrEnum):
    """What a client may do with a row: read only, or read and write."""

    READ = "r"
    READ_WRITE = "rw"


# the table each function code reads or writes
TABLE_OF_FUNCTION: dict[int, Table] = {
    1: Table.COILS, 5: Table.COILS, 15: Table.COILS, 2: Table.DISCRETE,
    3: Table.HOLDING, 6: Table.HOLDING, 16: Table.HOLDING, 22: Table.HOLDING,
    23: Table.HOLDING, 4: Table.INPUT,
}
LAST_ADDRESS = 0xFFFF


@dataclass(frozen=True, slots=True)
class MapRow:
    """Modbus addresses `start` .. `start + count - 1` of `table` = PLC elements from `device`."""

    table: Table
    start: int
    count: int
    device: str  # the first PLC element, as the dialect spells it: X0.0, R100, D0, M1536
    access: Access = Access.READ_WRITE
    width: int = 1  # bytes of PLC memory per register (1: a PMC byte; 2: a 16-bit word)
    line: int = 0  # the map file's line (0: a built-in map)

    @property
    def end(self) -> int:
        """One past the last Modbus address of the row."""
        return self.start + self.count

    @property
    def writable(self) -> bool:
        """True when clients may write the row."""
        return self.access is Access.READ_WRITE


@dataclass(frozen=True)
class ModbusMap:
    """The rows of a map, found by (table, address)."""

    name: str
    rows: tuple[MapRow, ...]
    _starts: dict[Table, list[int]] = field(init=False, repr=False, compare=False)
    _sorted: dict[Table, list[MapRow]] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        by_table: dict[Table, list[MapRow]] = {table: [] for table in Table}
        for row in self.rows:
            by_table[row.table].append(row)
        for rows in by_table.values():
            rows.sort(key=lambda row: row.start)
        object.__setattr__(self, "_sorted", by_table)
        object.__setattr__(self, "_starts", {t: [r.start for r in rs]
                                             for t, rs in by_table.items()})

    def rows_of(self, table: Table) -> list[MapRow]:
        """The rows of one table, by start address."""
        return list(self._sorted[table])

    def find(self, table: Table, address: int) -> MapRow | None:
        """The row holding `address` of `table`, or None (not mapped)."""
        index = bisect.bisect_right(self._starts[table], address) - 1
        if index < 0:
            return None
        row = self._sorted[table][index]
        return row if address < row.end else None

    def overlap(self, row: MapRow) -> MapRow | None:
        """A row of this map that shares a Modbus address with `row`, if any."""
        for other in self._sorted[row.table]:
            if other.start < row.end and row.start < other.end:
                return other
        return None


def _rows(*rows: tuple[str, int, int, str, str] | tuple[str, int, int, str, str, int]
          ) -> tuple[MapRow, ...]:
    """Rows from (table, start, count, device, access[, width]) tuples."""
    made = []
    for table, start, count, device, access, *width in rows:
        made.append(MapRow(Table(table), start, count, device, Access(access),
                           width[0] if width else 1))
    return tuple(made)


# PMC (seed and FANUC 30i): coils = X bits (8b + n is Xb.n), one holding register per byte
# (docs/modbus.md). X/Y have the I/O link ranges 0-127, 200-327, 400-527, 600-727 at their
# offsets; R9000-R9499 (system relays) read-only at 19000.
PMC_MAP = ModbusMap("pmc", _rows(
    ("coils", 0, 1024, "X0.0", "rw"),
    ("coils", 10000, 8000, "R0.0", "rw"),
    ("discrete", 0, 1024, "Y0.0", "r"),
    ("holding", 0, 128, "X0", "rw"), ("holding", 200, 128, "X200", "rw"),
    ("holding", 400, 128, "X400", "rw"), ("holding", 600, 128, "X600", "rw"),
    ("holding", 1000, 128, "Y0", "r"), ("holding", 1200, 128, "Y200", "r"),
    ("holding", 1400, 128, "Y400", "r"), ("holding", 1600, 128, "Y600", "r"),
    ("holding", 2000, 768, "F0", "rw"),
    ("holding", 3000, 768, "G0", "r"),
    ("holding", 4000, 250, "A0", "r"),
    ("holding", 5000, 100, "K0", "rw"), ("holding", 5900, 100, "K900", "rw"),
    ("holding", 6000, 500, "T0", "rw"),
    ("holding", 7000, 400, "C0", "rw"),
    ("holding", 10000, 8000, "R0", "rw"),
    ("holding", 19000, 500, "R9000", "r"),
    ("holding", 20000, 10000, "D0", "rw"),
    ("holding", 30000, 10000, "E0", "rw"),
))

# Delta DVP (ES2/EX2/SS2/SA2/SX2/SE manual, section 4.4 "PLC Device Address"): X and Y are
# numbered in octal (X0-X7, X10-X17 ...): element i of an X/Y row is the i-th input, i.e.
# X(oct(i)). Coils 0x0400 (X) are LadderWorks' own addition: writing one drives the input.
DELTA_MAP = ModbusMap("delta", _rows(
    ("coils", 0x0000, 1024, "S0", "rw"),
    ("discrete", 0x0400, 256, "X0", "r"),
    ("coils", 0x0400, 256, "X0", "rw"),
    ("coils", 0x0500, 256, "Y0", "rw"),
    ("coils", 0x0600, 256, "T0", "rw"),
    ("holding", 0x0600, 256, "T0", "rw", 2),
    ("holding", 0x0700, 112, "C200", "rw", 2),  # C200-C255: 32-bit, low word first
    ("coils", 0x0800, 1536, "M0", "rw"),
    ("coils", 0xB000, 2560, "M1536", "rw"),
    ("coils", 0x0E00, 200, "C0", "rw"),
    ("coils", 0x0EC8, 56, "C200", "rw"),
    ("holding", 0x0E00, 200, "C0", "rw", 2),
    ("holding", 0x1000, 4096, "D0", "rw", 2),
    ("holding", 0x9000, 5904, "D4096", "rw", 2),
))

# Fatek FBs (its Modbus table: 000001 Y0, 001001 X0, 002001 M0, 006001 S0, 009001 T0,
# 009501 C0; 400001 R0, 405001 R5000, 406001 D0, 409001 T0, 409501 C0, 409701 C200), here as
# 0-based protocol addresses. Writing coil 1000 + n drives Xn (the simulator's input).
FATEK_MAP = ModbusMap("fatek", _rows(
    ("coils", 0, 256, "Y0", "rw"),
    ("coils", 1000, 256, "X0", "rw"),
    ("coils", 2000, 2002, "M0", "rw"),
    ("coils", 6000, 1000, "S0", "rw"),
    ("coils", 9000, 256, "T0", "r"),
    ("coils", 9500, 256, "C0", "r"),
    ("holding", 0, 4168, "R0", "rw", 2),
    ("holding", 5000, 999, "R5000", "rw", 2),
    ("holding", 6000, 2999, "D0", "rw", 2),
    ("holding", 9000, 256, "T0", "rw", 2),
    ("holding", 9500, 200, "C0", "rw", 2),
    ("holding", 9700, 112, "C200", "rw", 2),  # C200-C255: 32-bit, low word first
))

# Siemens S7-1200 as its MB_SERVER instruction serves it (S7-1200 system manual, MB_SERVER:
# coils 00001-08192 the process image outputs %Q0.0-%Q1023.7, discrete inputs 10001-18192 the
# inputs %I0.0-%I1023.7, input registers 30001-30512 %IW0-%IW1022, holding registers 40001-
# where MB_HOLD_REG points: here its usual setup, the bit memory, register n = %MW(2n)),
# 0-based. Coils 10000-18191 driving %I are LadderWorks' own addition (docs/modbus.md).
S7_MAP = ModbusMap("s7", _rows(
    ("coils", 0, 8192, "%Q0.0", "rw"),
    ("coils", 10000, 8192, "%I0.0", "rw"),
    ("discrete", 0, 8192, "%I0.0", "r"),
    ("holding", 0, 4096, "%MW0", "rw", 2),
    ("input", 0, 512, "%IW0", "r", 2),
))

# The default map of each dialect (the program's `dialect`).
DEFAULT_MAPS: dict[str, ModbusMap] = {
    "seed": PMC_MAP, "fanuc": PMC_MAP, "delta": DELTA_MAP, "fatek": FATEK_MAP, "s7": S7_MAP,
}


def default_map(dialect: str) -> ModbusMap:
    """The map a program of `dialect` is served with (PMC for an unknown one)."""
    return DEFAULT_MAPS.get(dialect, PMC_MAP)
