"""PlcBridge: Modbus reads and writes applied to a PlcRun between two scans, through a map.

Every request runs whole under the engine's lock, which a scan holds from its start to its end:
a client never sees half a scan, and what it writes is there for the whole of the next one.
Coils and registers of the machine-side areas (X, F) are written as the machine would
(`PlcRun.set_bit`): on a forced bit the force wins and the value waits for its release; forced
bits of other areas are forced again at once, so a client always reads what the PLC uses.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import DiagnosticError
from ladderworks.core.modbus.cells import Cells, PmcCells, cells_for
from ladderworks.core.modbus.maps import MapRow, ModbusMap, Table, default_map
from ladderworks.core.plc.session import MACHINE_AREAS, PlcRun

ILLEGAL_ADDRESS = 2  # Modbus exception 02: outside the map, or a read-only element written
ILLEGAL_VALUE = 3  # Modbus exception 03: a value that does not fit its register
PMC_DEFAULT = default_map("seed")


class ModbusError(Exception):
    """A request the map refuses; `code` is the Modbus exception code to answer."""

    def __init__(self, code: int) -> None:
        super().__init__(f"Modbus exception {code:02d}")
        self.code = code


Chunk = tuple[MapRow, int, int]  # a row, the index of the first element, how many


def program_dialect(plc: PlcRun) -> str:
    """The dialect of the program loaded in `plc` ("seed", "fanuc", "delta", ...)."""
    loaded = plc.program if plc.program is not None else plc.binary
    return str(getattr(loaded, "dialect", "seed"))


def servable(modbus_map: ModbusMap, cells: Cells) -> ModbusMap:
    """The rows of `modbus_map` whose elements all exist in the dialect (`cells`): a default
    map may name devices a dialect does not have (Fatek R5000-R5998); a client asking for
    them gets exception 02, as for any address outside the map."""
    rows = []
    for row in modbus_map.rows:
        try:
            cells.check(row)
        except DiagnosticError:
            continue
        rows.append(row)
    if len(rows) == len(modbus_map.rows):
        return modbus_map
    return ModbusMap(modbus_map.name, tuple(rows))


class PlcBridge:
    """Reads and writes the Modbus tables of a map on the PLC of `plc`.

    The map is the loaded program's dialect's default unless one is given; its rows reach
    memory as that dialect spells its elements (`cells_for`)."""

    def __init__(self, plc: PlcRun, modbus_map: ModbusMap | None = None,
                 dialect: str | None = None) -> None:
        self.plc = plc
        self.map = PMC_DEFAULT
        self.cells: Cells = PmcCells()
        self.use(modbus_map, dialect)
        self.listeners: list[Callable[[], None]] = []  # told after every applied write

    def use(self, modbus_map: ModbusMap | None = None, dialect: str | None = None) -> None:
        """Serve `modbus_map` (default: the dialect's) with the elements of `dialect`
        (default: the loaded program's): after a program of another dialect is loaded."""
        name = dialect or program_dialect(self.plc)
        self.cells = cells_for(name)
        self.map = modbus_map or servable(default_map(name), self.cells)

    def _chunks(self, table: Table, address: int, count: int, write: bool) -> list[Chunk]:
        """The rows a request covers, or ModbusError 02 when an address is not mapped (or
        is read-only and written)."""
        chunks: list[Chunk] = []
        position, end = address, address + count
        while position < end:
            row = self.map.find(table, position)
            if row is None or (write and not row.writable):
                raise ModbusError(ILLEGAL_ADDRESS)
            taken = min(end, row.end) - position
            chunks.append((row, position - row.start, taken))
            position += taken
        return chunks

    # -- bits ------------------------------------------------------------------------------

    def read_bits(self, table: Table, address: int, count: int) -> list[bool]:
        """`count` coils or discrete inputs from `address`."""
        chunks = self._chunks(table, address, count, False)
        values: list[bool] = []
        areas = self.plc.memory.areas
        cells = self.cells
        with self.plc.lock():
            for row, first, taken in chunks:
                if isinstance(cells, PmcCells):  # one run of bits
                    start = cells.bit(row, first)
                    data = areas[start.area]
                    position = start.byte * 8 + (start.bit or 0)
                    values.extend(bool(data[p >> 3] >> (p & 7) & 1)
                                  for p in range(position, position + taken))
                    continue
                for index in range(first, first + taken):
                    bit = cells.bit(row, index)
                    values.append(bool(areas[bit.area][bit.byte] >> (bit.bit or 0) & 1))
        return values

    def write_bits(self, table: Table, address: int, values: Sequence[bool | int]) -> None:
        """Write coils from `address` (as a switch or the CNC would, for X and F)."""
        chunks = self._chunks(table, address, len(values), True)
        done = 0
        with self.plc.lock():
            for row, first, taken in chunks:
                for index in range(first, first + taken):
                    self.plc.set_bit(self.cells.bit(row, index), values[done])
                    done += 1
            self._reforce()
        self._told()

    # -- registers -------------------------------------------------------------------------

    def read_registers(self, table: Table, address: int, count: int) -> list[int]:
        """`count` holding or input registers from `address`."""
        chunks = self._chunks(table, address, count, False)
        values: list[int] = []
        areas = self.plc.memory.areas
        cells = self.cells
        with self.plc.lock():
            for row, first, taken in chunks:
                if isinstance(cells, PmcCells):  # one run of bytes
                    start = cells.register(row, first)
                    data = areas[start.area]
                    low = start.byte
                    if row.width == 1:
                        values.extend(data[low:low + taken])
                    else:
                        values.extend(data[b] | data[b + 1] << 8
                                      for b in range(low, low + 2 * taken, 2))
                    continue
                big = self.plc.memory.byteorder == "big"  # S7: %MW0 is %MB0 (high), %MB1
                for index in range(first, first + taken):
                    word = cells.register(row, index)
                    data = areas[word.area]
                    low, high = data[word.byte], data[word.byte + 1]
                    values.append(low << 8 | high if big else low | high << 8)
        return values

    def write_registers(self, table: Table, address: int, values: Sequence[int]) -> None:
        """Write holding registers from `address`; ModbusError 03 for a value too wide."""
        chunks = self._chunks(table, address, len(values), True)
        done = 0
        for row, _first, taken in chunks:
            if any(not 0 <= v < 1 << 8 * row.width for v in values[done:done + taken]):
                raise ModbusError(ILLEGAL_VALUE)
            done += taken
        done = 0
        engine = self.plc.engine
        with self.plc.lock():
            forced = engine.force_table.forced() if engine is not None else {}
            for row, first, taken in chunks:
                for index in range(first, first + taken):
                    self._write_register(self.cells.register(row, index), row.width,
                                         values[done], forced)
                    done += 1
            self._reforce()
        self._told()

    def _write_register(self, address: Address, width: int, value: int,
                        forced: dict[Address, bool]) -> None:
        """One register: bit by bit where the machine side holds a forced bit, else whole."""
        if address.area in MACHINE_AREAS and any(
                address.offset(k).with_bit(b) in forced for k in range(width) for b in range(8)):
            data = value.to_bytes(width, self.plc.memory.byteorder)
            for k in range(width):
                byte = address.offset(k)
                for bit in range(8):
                    self.plc.set_bit(byte.with_bit(bit), data[k] >> bit & 1)
        else:
            self.plc.write(address, value, width)

    def _reforce(self) -> None:
        """Forced bits stay forced: written over, they get their forced value back now."""
        engine = self.plc.engine
        if engine is not None:
            engine.force_table.apply(self.plc.memory)

    def _told(self) -> None:
        for listener in self.listeners:
            listener()
