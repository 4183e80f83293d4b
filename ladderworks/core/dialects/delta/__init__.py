"""The Delta DVP dialect: WPLSoft/ISPSoft instruction lists, Delta's devices and instructions.

docs/dialects.md says what it covers and where each choice comes from.
"""

from __future__ import annotations

from dataclasses import replace

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.base import Dialect
from ladderworks.core.dialects.delta.shown import ROWS as SHOWN_ROWS
from ladderworks.core.dialects.delta.sniff import score
from ladderworks.core.dialects.delta.table import FAMILIES, ROWS
from ladderworks.core.dialects.devices import Device, DeviceMap
from ladderworks.core.instructions import Combine, InstructionSpec, Kind

NAME = "delta"

# Where Delta's devices live in the memory image (docs/dialects.md, "Delta: memory layout").
S_BITS = 1000  # R area: M0..M4095 at bytes 0..511, S0..S1023 at bytes 1000..1127
T_BITS = 1000  # T area: T0..T255 contacts from byte 1000; their current values from byte 0
C_BITS = 2000  # C area: C0..C255 contacts from byte 2000; their current values from byte 0
C_STRIDE = 4  # every counter has 4 bytes (C200..C255 are 32-bit)
WIDE_COUNTERS = 200  # C200..C255: 32-bit up/down counters (DCNT)

X = Device("X", 0, 0o377, "input", base=8, bits=(Area.X, 0), read_only=True)
Y = Device("Y", 0, 0o377, "output", base=8, bits=(Area.Y, 0))
M = Device("M", 0, 4095, "auxiliary relay", bits=(Area.R, 0))
S = Device("S", 0, 1023, "step relay", bits=(Area.R, S_BITS))
T = Device("T", 0, 255, "timer", bits=(Area.T, T_BITS), words=(Area.T, 0))
C = Device("C", 0, 255, "counter", bits=(Area.C, C_BITS), words=(Area.C, 0), stride=C_STRIDE,
           wide_from=WIDE_COUNTERS)
D = Device("D", 0, 4999, "data register", words=(Area.D, 0))
D_HIGH = Device("D", 5000, 9999, "data register", words=(Area.E, 0))  # area D holds 5000 words
# A special module's control registers (FROM/TO): module m's CR#n is CR(100m + n), m 0-7,
# n 0-99, in area G (unused by Delta): shown and written as registers (docs/dialects.md) [LW]
CR = Device("CR", 0, 799, "special module register", words=(Area.G, 0))
MODULE_REGISTERS = 100  # CRs a module has a place for
DEVICES = DeviceMap((X, Y, M, S, T, C, D, D_HIGH, CR))


def relay(number: int) -> Address:
    """Where special relay M`number` lives."""
    return M.bit_address(number)


M1000 = relay(1000)  # on while the PLC runs
M1002 = relay(1002)  # on for the first scan after RUN
M1013 = relay(1013)  # 1 s clock: 0.5 s on, 0.5 s off
M1014 = relay(1014)  # 1 min clock: 30 s on, 30 s off
CLOCKS = ((M1013, 1000, 500), (M1014, 60_000, 30_000))  # (bit, period, time on), ms
M1028 = relay(1028)  # on: T64..T126 count in 10 ms
M1200 = relay(1200)  # M1200..M1255: C200..C255 count down when on


# the relays set before each scan, all in area R: (byte, mask) of M1000, M1002, M1013, M1014
_SCAN_RELAYS = tuple((address.byte, 1 << (address.bit or 0))
                     for address in (M1000, M1002, M1013, M1014))
_R = Area.R


def relays(areas: dict[Area, bytearray], now_ms: int, first: bool) -> None:
    """Delta's special relays, set before each scan (the engine calls this)."""
    data = areas[_R]
    (_, second, half), (_, minute, on) = CLOCKS
    states = (True, first, now_ms % second < half, now_ms % minute < on)
    for (byte, mask), on in zip(_SCAN_RELAYS, states, strict=True):
        data[byte] = data[byte] | mask if on else data[byte] & ~mask & 0xFF


def _outputs(rows: tuple[InstructionSpec, ...]) -> tuple[InstructionSpec, ...]:
    """Delta's boxes of one input (ACT) and no W1 are outputs, as WPLSoft draws them: among
    the coils, the rung's result flowing on past them (`LD X2 / OUT Y1 / MOV K5 D0 / OUT Y2`)."""
    return tuple(replace(row, output=True) if row.kind is Kind.FUNCTION and not row.w1
                 and row.inputs == ("ACT",) and row.combine is Combine.NONE else row
                 for row in rows)


DIALECT = Dialect(
    name=NAME, title="Delta DVP", title_tr="Delta DVP", code=2, devices=DEVICES,
    rows=_outputs(ROWS + SHOWN_ROWS),
    sniff=score, reader="ladderworks.core.dialects.delta.reader:read",
    printer="ladderworks.core.dialects.delta.printer:network_lines", relays=relays,
    clocks=CLOCKS,
    period_ms=10, extensions=(".dvp", ".il", ".txt", ".csv"),
    namer="ladderworks.core.dialects.delta.printer:mnemonic_of",
    spelling="ladderworks.core.dialects.delta.printer:spelling",
    tables="ladderworks.core.dialects.delta.tables:TABLES", families=FAMILIES,
    probe="ladderworks.core.dialects.delta.editing:probe_lines",
    finish="ladderworks.core.dialects.delta.csv_form:finish",
    codes={"sp-without-spe": "dvp-missing-sret", "spe-without-sp": "dvp-sret-alone",
           "outside-subprogram": "dvp-outside-subroutine", "label-missing": "dvp-pointer-missing",
           "call-missing": "dvp-call-missing", "no-logic": "dvp-no-logic",
           "sp-twice": "dvp-pointer-twice", "label-twice": "dvp-pointer-twice",
           "com-without-come": "dvp-range-open", "come-without-com": "dvp-range-end-alone"})
