"""Shared set-up for the engine tests: build an engine from program text or an example."""

from __future__ import annotations

from pathlib import Path

from ladderworks.core.address import Address, parse_address
from ladderworks.core.compiler import compile
from ladderworks.core.il import parse, parse_file
from ladderworks.core.plc.engine import ScanEngine

EXAMPLES = Path(__file__).resolve().parents[3] / "resources" / "examples"


def at(text: str) -> Address:
    """An address from its spelling."""
    return parse_address(text)


def engine_for(text: str, **options: object) -> ScanEngine:
    """An engine running the program written as ladder-section lines."""
    result = parse("%@3\n" + text.strip() + "\n%\n")
    assert result.ok, [d.message() for d in result.diagnostics]
    return ScanEngine(compile(result.program), **options)  # type: ignore[arg-type]


def engine_for_example(name: str) -> ScanEngine:
    """An engine running one of resources/examples/*.LAD."""
    result = parse_file(EXAMPLES / name)
    assert result.ok
    return ScanEngine(compile(result.program))


def bit(engine: ScanEngine, text: str) -> int:
    """The value of a bit."""
    return engine.memory.bit(at(text))


def set_bit(engine: ScanEngine, text: str, value: int) -> None:
    """Set an input bit (as the machine would)."""
    engine.memory.set_bit(at(text), value)
