"""SFT and PARI as native code (core/plc/functions/shift.py, parity.py). SFT: one shift of
16 bits per execution with ACT = 1, left or right (DIR), CONT keeping every 1 in place; W1
the bit shifted out, held in the call site's state as `held_output` holds an error output
(RST = 1: W1 = 0, no shift); PARI's W1 (the byte's parity against O.E) held the same way."""

from __future__ import annotations

from collections.abc import Sequence

from ladderworks.core.address import Address
from ladderworks.core.plc.native.builtins import _fits, _load, _store
from ladderworks.core.plc.native.state_block import Block, _held


def sft(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
    """SFT's code; None (a call-back) for an address without 2 bytes in its area."""
    if len(inputs) != 4 or len(params) != 1:
        return None
    (address,) = params
    if not (isinstance(address, Address) and _fits(address, 2)):
        return None
    f = b.f

    def compute() -> str:
        right = f.truth(inputs[0])
        data = _load(f, address, 2)
        out = f.value(f"select i1 {right}, i16 {f.value(f'and i16 {data}, 1')}, "
                      f"i16 {f.value(f'lshr i16 {data}, 15')}")
        shifted = f.value(f"select i1 {right}, i16 {f.value(f'lshr i16 {data}, 1')}, "
                          f"i16 {f.value(f'shl i16 {data}, 1')}")
        keep = f.value(f"sub i16 0, {f.value(f'zext i8 {inputs[1]} to i16')}")  # 0 or -1
        _store(f, address, 2, f.value(f"or i16 {shifted}, "
                                      f"{f.value(f'and i16 {data}, {keep}')}"))
        return f.value(f"icmp ne i16 {out}, 0")

    return _held(b, inputs[2], inputs[3], compute)


def pari(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
    """PARI: W1 = (the byte's count of 1-bits is odd) != O.E, held; RST = 1: W1 = 0."""
    if len(inputs) != 3 or len(params) != 1:
        return None
    (address,) = params
    if not (isinstance(address, Address) and _fits(address, 1)):
        return None
    f = b.f

    def compute() -> str:
        x = _load(f, address, 1)
        for step in (4, 2, 1):
            x = f.value(f"xor i8 {x}, {f.value(f'lshr i8 {x}, {step}')}")
        odd = f.value(f"and i8 {x}, 1")
        return f.value(f"icmp ne i8 {odd}, {inputs[0]}")

    return _held(b, inputs[1], inputs[2], compute)
