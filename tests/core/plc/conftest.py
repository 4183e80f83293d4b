"""Shared set-up for the engine tests: build an engine from program text or an example."""

from __future__ import annotations

import random
from collections.abc import Callable
from pathlib import Path

from ladderworks.core.address import Address, Area, parse_address
from ladderworks.core.compiler import compile
from ladderworks.core.il import Instruction, Network, Program, parse, parse_file
from ladderworks.core.il.program import ParamValue
from ladderworks.core.instructions import Combine, Kind, spec_for
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.native import jit

jit.VERIFY = True  # LLVM's verifier on every module the native tests compile

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


def stack_step(stack: list[int], name: str, value: int) -> None:
    """One basic logic instruction on a reference stack (`value`: the operand bit, NOT applied
    here); for the reference interpreters the generated scan code is checked against."""
    if ".NOT" in name:
        value ^= 1
    if name in ("RD", "RD.NOT"):
        stack[-1] = value
    elif name in ("RD.STK", "RD.NOT.STK"):
        stack.append(value)
    elif name in ("AND", "AND.NOT"):
        stack[-1] &= value
    elif name in ("OR", "OR.NOT"):
        stack[-1] |= value
    elif name in ("AND.STK", "OR.STK"):
        top = stack.pop()
        stack[-1] = stack[-1] & top if name == "AND.STK" else stack[-1] | top
    else:
        raise ValueError(f"not a logic instruction: {name}")


def assert_matches_reference(text: str, reference_scan: Callable[[ScanEngine], None],
                             rng: random.Random, monitored: bool) -> None:
    """Four scans on random R0..R2 bytes: the generated code and the reference give the same."""
    engine = engine_for(text)
    engine.monitored = monitored
    reference = engine_for(text)
    for _ in range(4):
        data = bytes(rng.randrange(256) for _ in range(3))
        engine.memory.areas[Area.R][0:3] = data
        reference.memory.areas[Area.R][0:3] = data
        engine.scan()
        reference_scan(reference)
        assert engine.memory.areas[Area.R][0:3] == reference.memory.areas[Area.R][0:3], text


def build(text: str) -> Program:
    """A Program built in code from lines `NAME [operand | params...]` (`P5`, `L3` are numbers).

    Needed while the parser does not read P/L parameters. A new network starts at each RD and
    at each instruction without control inputs (SP, SPE, LBL, CALLU, END1 ...).
    """
    networks: list[Network] = []
    for line_number, line in enumerate(text.strip().splitlines(), 1):
        words = line.split()
        if not words:
            continue
        name, args = words[0], words[1:]
        spec = spec_for(name, len(args))
        assert spec is not None, name
        operand = None
        params: list[ParamValue] = []
        if spec.kind is Kind.BASIC:
            operand = parse_address(args[0]) if args else None
        else:
            for word in args:
                if word[0] in "PL" and word[1:].isdigit():
                    params.append(int(word[1:]))
                elif word.lstrip("-").isdigit():
                    params.append(int(word))
                else:
                    params.append(parse_address(word))
        new = (spec.kind is Kind.BASIC and spec.combine is Combine.READ and spec.pushes == 0) \
            or (spec.kind is not Kind.BASIC and not spec.inputs)
        if new or not networks:
            networks.append(Network())
        networks[-1].instructions.append(
            Instruction(name, operand, tuple(params), line=line_number, column=1))
    return Program(networks=networks)


def engine_of(text: str, **options: object) -> ScanEngine:
    """An engine running the program `build(text)`."""
    return ScanEngine(compile(build(text)), **options)  # type: ignore[arg-type]
