"""Shared set-up for the dialect tests: Delta programs from text, devices by their spelling."""

from __future__ import annotations

from pathlib import Path

from ladderworks.core import dialects
from ladderworks.core.address import Address
from ladderworks.core.compiler import compile
from ladderworks.core.dialects.delta import DEVICES
from ladderworks.core.il import Program
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine

EXAMPLES = Path(__file__).resolve().parents[3] / "resources" / "examples" / "delta"


def delta(text: str) -> Program:
    """A Delta program read from its text (it must have no diagnostic error)."""
    result = parse_bytes(text.encode("utf-8"), "delta")
    assert result.ok, [d.located("t") for d in result.diagnostics]
    return result.program


def engine(text: str, *, monitored: bool = False, period_ms: int = 10) -> ScanEngine:
    """An engine running a Delta program."""
    plc = ScanEngine(compile(delta(text)), period_ms=period_ms)
    plc.monitored = monitored
    return plc


def bit_of(text: str) -> Address:
    """A Delta bit device's address (X17, M1000, T0's contact)."""
    return DEVICES.bit(text)


def word_of(text: str) -> Address:
    """A Delta word device's address (D10, T0's value)."""
    return DEVICES.word(text)[0]


def get(plc: ScanEngine, text: str, dialect: str = "delta") -> int:
    """A device's value: a bit (X, Y, M, S) or a word (T, C, D: signed; `D4:4` 32-bit)."""
    address, width = dialects.parse_target(text, dialect)
    if address.bit is not None:
        return plc.memory.bit(address)
    return plc.memory.read(address, width, signed=True)


def put(plc: ScanEngine, text: str, value: int, dialect: str = "delta") -> None:
    """Set a device (an input bit, as the machine would, or a word)."""
    address, width = dialects.parse_target(text, dialect)
    if address.bit is not None:
        plc.memory.set_bit(address, value)
    else:
        plc.memory.write(address, value, width)
