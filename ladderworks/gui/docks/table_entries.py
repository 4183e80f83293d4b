"""The rows of the PLC tables: timers, counters, data table and keep relays, read and validated.

Qt-free: the tables dock shows these rows and sends the values it accepts to the PLC session.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from enum import StrEnum

from ladderworks.core.address import AREA_RANGES, AREA_SIZES, SEED_AREA_RANGES, Address, Area
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.diagnostics import Refused
from ladderworks.core.il.program import SEED
from ladderworks.core.instructions import InstructionSpec, Numbered
from ladderworks.core.plc.functions.counters import (
    MAX_PRESET,
    counter_preset_address,
    counter_value_address,
)
from ladderworks.core.plc.functions.timers import FAST_TICK_MS, effective_preset
from ladderworks.core.plc.timer_table import PRECISION_MS, TimerLayout

COUNTER_COUNT = 20
DATA_WIDTHS = (1, 2, 4)


class TableKind(StrEnum):
    """The four tables a PMC user edits, and the three of a Delta/Fatek program's devices."""

    TIMER = "timer"
    COUNTER = "counter"
    DATA = "data"
    KEEP = "keep"
    DEVICE_TIMERS = "device-timers"  # a Delta/Fatek program's (gui/docks/device_specs.py)
    DEVICE_COUNTERS = "device-counters"
    REGISTERS = "registers"


class TableError(Refused, ValueError):
    """A value the table refuses; its `diagnostic` says why (translated by the dock)."""


@dataclass(frozen=True, slots=True)
class TimerRow:
    """A timer: TMR presets live in the T table (editable), TMRB presets in the program (fixed).

    `preset` is in ms (seed) or ticks (fanuc); `precision` is the FANUC precision code."""

    number: int
    preset: int
    tick_ms: int
    delay_ms: int
    fixed: bool = False  # a TMRB: the preset is a parameter of the program
    precision: int = 0


def timer_row(layout: TimerLayout, number: int, preset: int, precision: int = 0) -> TimerRow:
    """A TMR row: its tick and real delay by the layout (dialect) of the program."""
    return TimerRow(number, preset, layout.tick_ms(number, precision),
                    layout.delay_ms(number, preset, precision), precision=precision)


def fixed_timer_row(number: int, preset_ms: int) -> TimerRow:
    """A TMRB row: the preset (ms) is in the program, 8 ms tick."""
    return TimerRow(number, preset_ms, FAST_TICK_MS, effective_preset(preset_ms, FAST_TICK_MS),
                    fixed=True)


@dataclass(frozen=True, slots=True)
class CounterRow:
    """A CTR counter: preset and current value, both in the C table."""

    number: int
    preset: int
    value: int


@dataclass(frozen=True, slots=True)
class DataRow:
    """A value of the data table: `width` bytes from D`byte`, signed binary, little-endian."""

    byte: int
    width: int
    value: int

    @property
    def address(self) -> Address:
        """The first byte."""
        return Address(Area.D, self.byte)


@dataclass(frozen=True, slots=True)
class KeepRow:
    """A keep-relay byte K`byte` and its 8 bits."""

    byte: int
    value: int

    @property
    def bits(self) -> str:
        """The byte as 8 binary digits, bit 7 first (as the bit display shows a byte)."""
        return f"{self.value:08b}"


@dataclass
class ProgramUse:
    """What the program uses of each table: rows listed even when their value is 0."""

    timers: set[int]
    fixed_timers: dict[int, int]  # TMRB number -> preset ms (the last TMRB of that number)
    counters: set[int]
    data: dict[int, int]  # D byte -> width
    keep: set[int]

    @classmethod
    def of(cls, program: BinaryProgram | None) -> ProgramUse:
        """Collect the timers, counters, D and K addresses a program refers to."""
        use = cls(set(), {}, set(), {}, set())
        if program is None:
            return use
        for op in program.ops:
            spec = op.spec
            numbered = spec.numbered
            if numbered is Numbered.TIMER and isinstance(op.params[0], int):
                use.timers.add(op.params[0])
            elif numbered is Numbered.FIXED_TIMER and all(
                    isinstance(p, int) for p in op.params[:2]):
                number, preset = op.params[0], op.params[1]
                assert isinstance(number, int) and isinstance(preset, int)
                use.fixed_timers[number] = preset
            elif numbered is Numbered.COUNTER and isinstance(op.params[0], int):
                use.counters.add(op.params[0])
            addresses = [op.operand, *op.params]
            for index, where in enumerate(addresses):
                if not isinstance(where, Address):
                    continue
                if where.area is Area.K:
                    use.keep.add(where.byte)
                elif where.area is Area.D:
                    width = 1 if where.bit is not None else _data_width(spec, index)
                    use.data[where.byte] = max(use.data.get(where.byte, 1), width)
        return use


def _data_width(spec: InstructionSpec, index: int) -> int:
    """The width to show a D address of a program with (`index` 0: the bit operand, then the
    parameters): a timer's or counter's preset (TMRC, CTRC) its own, else 1."""
    fixed = spec.fixed_params()
    param = fixed[index - 1] if 0 < index <= len(fixed) else None
    if param is not None and param.preset and isinstance(param.width, int):
        return param.width
    return 1


# -- reading ------------------------------------------------------------------------------

Areas = Mapping[Area, bytes | bytearray]  # a snapshot's areas or a Memory's


def _read(areas: Areas, address: Address, width: int, *, signed: bool = False) -> int:
    data = areas[address.area]
    return int.from_bytes(data[address.byte:address.byte + width], "little", signed=signed)



def timer_rows(areas: Areas, use: ProgramUse, listed: set[int],
               layout: TimerLayout) -> list[TimerRow]:
    """Every TMR the program uses, is listed or has a preset, then every TMRB, by number."""
    width = layout.width
    data = areas[Area.T]
    numbers = {n for n in set(use.timers) | set(listed) if 1 <= n <= layout.count}
    numbers |= {n for n in range(1, layout.count + 1) if any(data[(n - 1) * width:n * width])}
    rows = []
    for n in numbers:
        where = layout.precision_address(n)
        precision = _read(areas, where, 2) if where is not None else 0
        rows.append(timer_row(layout, n, _read(areas, layout.preset_address(n), width),
                              precision))
    rows += [fixed_timer_row(n, preset) for n, preset in use.fixed_timers.items()]
    return sorted(rows, key=lambda row: (row.number, row.fixed))


def counter_rows(areas: Areas, use: ProgramUse, listed: set[int]) -> list[CounterRow]:
    """Every CTR the program uses, is listed or has a non-zero preset or value, by number."""
    numbers = set(use.counters) | set(listed)
    data = areas[Area.C]
    numbers |= {n for n in range(1, COUNTER_COUNT + 1) if any(data[(n - 1) * 4:n * 4])}
    return [CounterRow(n, _read(areas, counter_preset_address(n), 2),
                       _read(areas, counter_value_address(n), 2)) for n in sorted(numbers)]


def data_rows(areas: Areas, use: ProgramUse, listed: dict[int, int]) -> list[DataRow]:
    """Every D value the program uses or the user listed, by address (listed width wins)."""
    widths = dict(use.data)
    widths.update(listed)
    return [DataRow(byte, width, _read(areas, Address(Area.D, byte), width, signed=True))
            for byte, width in sorted(widths.items())]


def keep_rows(areas: Areas, use: ProgramUse, listed: set[int]) -> list[KeepRow]:
    """Every K byte the program uses, is listed or is non-zero, by address."""
    data = areas[Area.K]
    numbers = set(use.keep) | set(listed) | {n for n, value in enumerate(data) if value}
    return [KeepRow(n, data[n]) for n in sorted(numbers)]


# -- validating ---------------------------------------------------------------------------


def parse_int(text: str) -> int:
    """A decimal number (or `0x` hex, `0b` binary) typed in a cell; raises TableError."""
    spelled = text.strip().replace("_", "")
    try:
        return int(spelled, 0) if spelled.lower().startswith(("0x", "0b")) else int(spelled)
    except ValueError:
        raise TableError("not-a-number", text=text.strip()) from None


def check_range(value: int, low: int, high: int) -> int:
    """`value` if low <= value <= high; raises TableError `range`."""
    if not low <= value <= high:
        raise TableError("out-of-range", value=value, low=low, high=high)
    return value


def timer_number(text: str, layout: TimerLayout) -> int:
    """A timer number 1..count (100 in seed programs)."""
    return check_range(parse_int(text), 1, layout.count)


def timer_preset(text: str, layout: TimerLayout) -> int:
    """A timer preset: ms 0..99,999,999 (seed) or ticks 0..32767 (fanuc)."""
    return check_range(parse_int(text), 0, layout.max_preset)


def timer_precision(text: str) -> int:
    """A FANUC timer precision code 0..5."""
    return check_range(parse_int(text), 0, max(PRECISION_MS))


def counter_number(text: str) -> int:
    """A counter number 1..20."""
    return check_range(parse_int(text), 1, COUNTER_COUNT)


def counter_value(text: str) -> int:
    """A counter preset or value, 0..32767."""
    return check_range(parse_int(text), 0, MAX_PRESET)


def in_model_map(area: Area, byte: int, width: int, dialect: str) -> int:
    """`byte` when bytes byte .. byte + width - 1 lie in one range of the area in the map of
    the program's model (seed: the seed's; else the 30i's); else TableError `byte-range`."""
    ranges = SEED_AREA_RANGES[area] if dialect == SEED else AREA_RANGES[area]
    last = byte + max(width, 1) - 1
    if not any(lo <= byte and last <= hi for lo, hi in ranges):
        raise TableError("byte-range", text=f"{area.value}{byte}", area=area.value,
                         last=ranges[-1][1] - max(width, 1) + 1,
                         ranges=", ".join(f"{lo}-{hi}" for lo, hi in ranges))
    return byte


def data_byte(text: str, width: int = 1, dialect: str = SEED) -> int:
    """A D address (`D10`, `10`) with room for `width` bytes."""
    spelled = text.strip().upper().removeprefix("D")
    byte = check_range(parse_int(spelled), 0, AREA_SIZES[Area.D] - width)
    return in_model_map(Area.D, byte, width, dialect)


def data_width(text: str) -> int:
    """A data width: 1, 2 or 4 bytes."""
    width = parse_int(text)
    if width not in DATA_WIDTHS:
        raise TableError("value-width", value=width)
    return width


def data_value(text: str, width: int) -> int:
    """A value for `width` bytes: signed or unsigned, -2^(8w-1) .. 2^(8w)-1."""
    bits = 8 * width
    return check_range(parse_int(text), -(1 << (bits - 1)), (1 << bits) - 1)


def keep_byte(text: str, dialect: str = SEED) -> int:
    """A K byte (`K5`, `5`): 0..99 (and the system's 900..999 in a FANUC 30i program)."""
    spelled = text.strip().upper().removeprefix("K")
    byte = check_range(parse_int(spelled), 0, AREA_SIZES[Area.K] - 1)
    return in_model_map(Area.K, byte, 1, dialect)


def keep_bits(text: str) -> int:
    """A keep-relay byte typed as up to 8 binary digits (bit 7 first)."""
    spelled = text.strip().replace(" ", "")
    if not spelled or len(spelled) > 8 or set(spelled) - {"0", "1"}:
        raise TableError("bit-pattern", text=text.strip())
    return int(spelled, 2)
