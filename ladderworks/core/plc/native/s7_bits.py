"""S7-1200's edge contacts and coils (P, N, P_COIL, N_COIL), P_TRIG / N_TRIG and SR / RS as
native code (core/plc/functions/s7_bits.py): their memory bits are in memory, so their state
blocks stay unused. Each bit is loaded and stored in Python's order (an operand that is its
own memory bit gives what Python gives)."""

from __future__ import annotations

from collections.abc import Sequence

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.native.builtins import _fits
from ladderworks.core.plc.native.s7_values import Emitter, big_endian, bit, set_bit
from ladderworks.core.plc.native.state_block import Block


def _bits(params: Sequence[object], count: int) -> bool:
    return len(params) == count and all(
        isinstance(p, Address) and p.bit is not None and _fits(p, 1) for p in params)


def _edge(b: Block, signal: str, memory_bit: Address, rising: bool) -> str:
    """`s7_bits._edge`: the memory bit takes `signal` (i8); the edge (i8)."""
    f = b.f
    before = bit(f, memory_bit)
    set_bit(f, memory_bit, f.truth(signal))
    if rising:
        return f.value(f"and i8 {signal}, {f.value(f'xor i8 {before}, 1')}")
    return f.value(f"and i8 {before}, {f.value(f'xor i8 {signal}, 1')}")


def _contact(rising: bool) -> Emitter:
    """-|P|- / -|N|-: IN AND the operand's edge."""

    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        if not _bits(params, 2) or not big_endian(b):
            return None
        operand, memory_bit = params
        assert isinstance(operand, Address) and isinstance(memory_bit, Address)
        edge = _edge(b, bit(b.f, operand), memory_bit, rising)
        return b.f.value(f"and i8 {edge}, {inputs[0]}")

    return emit


def _coil(rising: bool) -> Emitter:
    """-(P)- / -(N)-: the operand := IN's edge; W1 = IN."""

    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        if not _bits(params, 2) or not big_endian(b):
            return None
        operand, memory_bit = params
        assert isinstance(operand, Address) and isinstance(memory_bit, Address)
        edge = _edge(b, inputs[0], memory_bit, rising)
        set_bit(b.f, operand, b.f.truth(edge))
        return inputs[0]

    return emit


def _trig(rising: bool) -> Emitter:
    """P_TRIG / N_TRIG: IN's edge."""

    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        if not _bits(params, 1) or not big_endian(b):
            return None
        (memory_bit,) = params
        assert isinstance(memory_bit, Address)
        return _edge(b, inputs[0], memory_bit, rising)

    return emit


def _flip_flop(first_sets: bool) -> Emitter:
    """SR (S sets, R1 resets: reset dominant) / RS (R resets, S1 sets: set dominant); W1 =
    the operand."""

    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        if not _bits(params, 1) or len(inputs) != 2 or not big_endian(b):
            return None
        (operand,) = params
        assert isinstance(operand, Address)
        f = b.f
        first, second = (f.truth(value) for value in inputs)
        old = f.truth(bit(f, operand))
        dominant = "false" if first_sets else "true"  # what the second input writes
        other = "true" if first_sets else "false"
        by_first = f.value(f"select i1 {first}, i1 {other}, i1 {old}")
        set_bit(f, operand, f.value(f"select i1 {second}, i1 {dominant}, i1 {by_first}"))
        return bit(f, operand)

    return emit


load_all()
STATEFUL: dict[FunctionImpl, tuple[str, Emitter]] = {
    REGISTRY["S7.P"]: ("s7", _contact(True)),
    REGISTRY["S7.N"]: ("s7", _contact(False)),
    REGISTRY["S7.P_COIL"]: ("s7", _coil(True)),
    REGISTRY["S7.N_COIL"]: ("s7", _coil(False)),
    REGISTRY["S7.P_TRIG"]: ("s7", _trig(True)),
    REGISTRY["S7.N_TRIG"]: ("s7", _trig(False)),
    REGISTRY["S7.SR"]: ("s7", _flip_flop(True)),
    REGISTRY["S7.RS"]: ("s7", _flip_flop(False)),
}
"""S7's bit rows: implementation -> (kind, emitter)."""
