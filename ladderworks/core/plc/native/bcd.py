"""The PMC's BCD rows as native code: ADD/SUB/MUL/DIV (an error output held as `held_output`
holds it: stateful.py gives the block), COMP/COIN, NUME and DEC; BYT (2 or 4 digits) is a
run-time input, so both widths are read and the one BYT names is used, exactly as
core/plc/functions' arithmetic.py, compare.py and decode.py do (an invalid digit or a
constant past the width: an error)."""

from __future__ import annotations

from collections.abc import Sequence

from ladderworks.core.address import Address
from ladderworks.core.instructions import FUNCTIONS, InstructionSpec, Operation
from ladderworks.core.plc.bcd import bcd_limit, int_to_bcd
from ladderworks.core.plc.functions import (
    REGISTRY,
    FunctionImpl,
    compare,
    decode,
    load_all,
)
from ladderworks.core.plc.functions import (
    arithmetic as _arithmetic,
)
from ladderworks.core.plc.native.builtins import Emitter, _fits, _load, _signed, _store, _when
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import Block, _held


def _bcd_code() -> object:
    load_all()
    spec = next(s for s in FUNCTIONS if not s.binary and s.operation is not Operation.NONE)
    return REGISTRY[spec.name].__code__


_BCD = _bcd_code()  # the code every BCD arithmetic implementation shares


def is_bcd_arithmetic(spec: InstructionSpec, impl: FunctionImpl | None) -> bool:
    """True for ADD/SUB/MUL/DIV (BCD), by their implementation's code."""
    return getattr(impl, "__code__", None) is _BCD and spec.operation is not Operation.NONE \
        and not spec.binary


def _usable(operand: object) -> bool:
    """An address whose 2 bytes lie in its area, or an integer constant."""
    if isinstance(operand, Address):
        return _fits(operand, 2)
    return isinstance(operand, int) and not isinstance(operand, bool)


def _read(f: FunctionText, operand: object, width: int) -> tuple[str, str]:
    """(the i64 value, i1 valid) of a BCD operand of `width` bytes (`read_bcd`), or of a
    constant (valid when 0 <= it <= the width's limit)."""
    if not isinstance(operand, Address):
        assert isinstance(operand, int)
        if 0 <= operand <= bcd_limit(width):
            return str(operand), "true"
        return "0", "false"
    raw = f.value(f"zext i{8 * width} {_load(f, operand, width)} to i64")
    total, valid = "0", "true"
    for digit in range(2 * width):
        nibble = f.value(f"and i64 {f.value(f'lshr i64 {raw}, {4 * digit}')}, 15")
        valid = f.value(f"and i1 {valid}, {f.value(f'icmp ule i64 {nibble}, 9')}")
        total = f.value(f"add i64 {total}, {f.value(f'mul i64 {nibble}, {10 ** digit}')}")
    return total, valid


def _either(f: FunctionText, wide: str, operand: object) -> tuple[str, str]:
    """The operand read as 4 digits when `wide` (i1), else as 2."""
    narrow_value, narrow_ok = _read(f, operand, 1)
    wide_value, wide_ok = _read(f, operand, 2)
    return (f.value(f"select i1 {wide}, i64 {wide_value}, i64 {narrow_value}"),
            f.value(f"select i1 {wide}, i1 {wide_ok}, i1 {narrow_ok}"))


def _encode(f: FunctionText, value: str, width: int) -> str:
    """The BCD bits of 0 <= `value` < 10 ** (2 * width), as i(8 * width)."""
    raw = "0"
    for digit in range(2 * width):
        place = f.value(f"urem i64 {f.value(f'udiv i64 {value}, {10 ** digit}')}, 10")
        raw = f.value(f"or i64 {raw}, {f.value(f'shl i64 {place}, {4 * digit}')}")
    return f.value(f"trunc i64 {raw} to i{8 * width}")


_OPS = {Operation.ADD: "add", Operation.SUBTRACT: "sub", Operation.MULTIPLY: "mul"}


def arithmetic(b: Block, operation: Operation, params: Sequence[object],
               inputs: list[str]) -> str | None:
    """ADD/SUB/MUL/DIV: RST clears W1, ACT = 0 keeps it, else W1 = 1 on an invalid operand,
    a division by zero or a result outside 0 .. 99 (9999), the result written otherwise."""
    if len(inputs) != 3 or len(params) != 4:
        return None
    _, first, second, result_at = params
    if not (isinstance(first, Address) and isinstance(result_at, Address)
            and _usable(first) and _usable(second) and _fits(result_at, 2)):
        return None
    f = b.f

    def compute() -> str:
        wide = f.truth(inputs[0])
        a, a_ok = _either(f, wide, first)
        c, c_ok = _either(f, wide, second)
        error = f.value(f"xor i1 {f.value(f'and i1 {a_ok}, {c_ok}')}, true")
        if operation is Operation.DIVIDE:
            zero = f.value(f"icmp eq i64 {c}, 0")
            result = f.value(f"udiv i64 {a}, {f.value(f'select i1 {zero}, i64 1, i64 {c}')}")
            error = f.value(f"or i1 {error}, {zero}")
        else:
            result = f.value(f"{_OPS[operation]} i64 {a}, {c}")
        limit = f.value(f"select i1 {wide}, i64 {bcd_limit(2)}, i64 {bcd_limit(1)}")
        inside = f.value(f"and i1 {f.value(f'icmp sge i64 {result}, 0')}, "
                         f"{f.value(f'icmp sle i64 {result}, {limit}')}")
        failed = f.value(f"or i1 {error}, {f.value(f'xor i1 {inside}, true')}")
        write, two, one, done = f.label(), f.label(), f.label(), f.label()
        f.add(f"br i1 {failed}, label %{done}, label %{write}")
        f.start(write)
        f.add(f"br i1 {wide}, label %{two}, label %{one}")
        for label, width in ((two, 2), (one, 1)):
            f.start(label)
            _store(f, result_at, width, _encode(f, result, width))
            f.add(f"br label %{done}")
        f.start(done)
        return failed

    return _held(b, inputs[1], inputs[2], compute)


def _compare(predicate: str) -> Emitter:
    """COMP (input <= data) / COIN (input = data): W1 while ACT = 1 and both valid BCD."""

    def emit(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
        if len(inputs) != 2 or len(params) != 3:
            return None
        _, value, other = params
        if not (_usable(value) and isinstance(other, Address) and _usable(other)):
            return None
        wide = f.truth(inputs[0])
        a, a_ok = _either(f, wide, value)
        c, c_ok = _either(f, wide, other)
        holds = f.value(f"and i1 {f.value(f'and i1 {a_ok}, {c_ok}')}, "
                        f"{f.value(f'icmp {predicate} i64 {a}, {c}')}")
        return f.value(f"and i8 {inputs[1]}, {f.value(f'zext i1 {holds} to i8')}")

    return emit


def _nume(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """NUME: ACT = 1 writes the constant as 2 (BYT = 0) or 4 BCD digits; one that does not
    fit: nothing."""
    if len(inputs) != 2 or len(params) != 2:
        return None
    constant, target = params
    if not (isinstance(constant, int) and isinstance(target, Address) and _fits(target, 2)):
        return None

    def body() -> None:
        two, one, done = f.label(), f.label(), f.label()
        f.add(f"br i1 {f.truth(inputs[0])}, label %{two}, label %{one}")
        for label, width in ((two, 2), (one, 1)):
            f.start(label)
            raw = int_to_bcd(constant, 2 * width)
            if raw is not None:
                _store(f, target, width, str(_signed(raw, width)))
            f.add(f"br label %{done}")
        f.start(done)

    _when(f, inputs[-1], body)
    return "0"


def _dec(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """DEC: W1 = ACT and the BCD byte matches the spec nnxx (`decode.decode_matches`, its
    digits chosen now)."""
    if len(inputs) != 1 or len(params) != 2:
        return None
    code, spec = params
    if not (isinstance(code, Address) and _fits(code, 1) and isinstance(spec, int)):
        return None
    number, digits = divmod(spec, 100)
    high, low = divmod(number, 10)
    masks = {1: (0x0F, low), 10: (0xF0, high << 4), 11: (0xFF, (high << 4) | low)}
    if digits not in masks or (high > 9 and digits != 1):
        return "0"
    mask, wanted = masks[digits]
    raw = f.value(f"zext i8 {_load(f, code, 1)} to i32")
    holds = f.value(f"icmp eq i32 {f.value(f'and i32 {raw}, {mask}')}, {wanted}")
    return f.value(f"and i8 {inputs[0]}, {f.value(f'zext i1 {holds} to i8')}")


EMITTERS: dict[FunctionImpl, Emitter] = {compare.comp: _compare("ule"),
                                        compare.coin: _compare("eq"),
                                        _arithmetic.nume: _nume, decode.dec: _dec}


def cod(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
    """COD: output = table[index] in BCD (2 or 4 digits by BYT); W1 = 1 when the index is not
    BCD or past the table, or the entry does not fit (nothing written)."""
    if len(inputs) != 3 or len(params) < 3:
        return None
    size, index, out = params[:3]
    table = params[3:]
    if not (isinstance(size, int) and isinstance(index, Address) and _fits(index, 1)
            and isinstance(out, Address) and _fits(out, 2)
            and all(isinstance(entry, int) for entry in table)):
        return None
    rows = [entry for entry in table[:max(0, min(size, len(table), 100))]
            if isinstance(entry, int)]
    f = b.f

    def compute() -> str:
        wide = f.truth(inputs[0])
        row, valid = _read(f, index, 1)
        bad, done = f.label(), f.label()
        cases = [f.label() for _ in rows]
        chosen = f.value(f"select i1 {valid}, i64 {row}, i64 -1")
        f.add(f"switch i64 {chosen}, label %{bad} [" +
              " ".join(f"i64 {k}, label %{label}" for k, label in enumerate(cases)) + "]")
        incoming = [("true", bad)]
        for entry, label in zip(rows, cases, strict=True):
            f.start(label)
            two, one = f.label(), f.label()
            f.add(f"br i1 {wide}, label %{two}, label %{one}")
            for start, width in ((two, 2), (one, 1)):
                f.start(start)
                raw = int_to_bcd(entry, 2 * width)
                if raw is not None:
                    _store(f, out, width, str(_signed(raw, width)))
                incoming.append(("false" if raw is not None else "true", start))
                f.add(f"br label %{done}")
        f.start(bad)
        f.add(f"br label %{done}")
        f.start(done)
        return f.value("phi i1 " + ", ".join(f"[{value}, %{label}]"
                                              for value, label in incoming))

    return _held(b, inputs[1], inputs[2], compute)
