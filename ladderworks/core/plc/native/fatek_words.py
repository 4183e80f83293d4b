"""Fatek FBs word and bit boxes as native code (core/plc/functions/fatek_words.py,
fatek_bits.py, fatek_convert.py): AND, OR, XOR, XNR, SQRT, NEG, ABS, EXT, SHFL, SHFR, ROTL,
ROTR, MOV/, TOGG, ZNCMP, BITRD, BITWR, BITMV, NBMV, BYMV, XCHG, SWAP, UNIT, DIST, →BCD, →BIN, DIV48;
and the FUNs not simulated (HSPSO, MPARA …: FO 0, no state).
Each runs in `fatek.box` ("en", the P form, FO and "fo0"); a row's `prepare(size, operands
(FO left out), inputs)` gives its work, or None (the op calls back)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.dialects.fatek.rows import NOT_SIMULATED
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.fatek_convert import from_bcd, to_bcd
from ladderworks.core.plc.functions.fatek_data import DOUBLE
from ladderworks.core.plc.native.bcd import _encode, _read
from ladderworks.core.plc.native.fatek import Outputs, _operand, box
from ladderworks.core.plc.native.fatek_timers import set_bit
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import Block, _fits, _load, _store

Prepared = Outputs | None
Prepare = Callable[[int, Sequence[object], list[str]], Prepared]  # (size, operands, inputs)
_NONE: tuple[list[str], str] = ([], "true")  # a box without FO


def _i(size: int) -> str:
    return f"i{8 * size}"


def _narrow(f: FunctionText, value: str, size: int) -> str:
    return f.value(f"trunc i64 {value} to {_i(size)}")


def _place(operand: object, size: int) -> Address | None:
    return operand if isinstance(operand, Address) and _fits(operand, size) else None


def _logic(operator: str, inverted: bool) -> Prepare:
    """FUN 18 AND, 19 OR, 35 XOR, 36 XNR: D := Sa op Sb; FO0 D = 0."""

    def prepare(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
        sa, sb, destination = operands
        a_of, b_of, d = _operand(sa, size), _operand(sb, size), _place(destination, size)
        if a_of is None or b_of is None or d is None:
            return None

        def work(f: FunctionText) -> tuple[list[str], str]:
            value = f.value(f"{operator} {_i(size)} {_narrow(f, a_of(f), size)}, "
                            f"{_narrow(f, b_of(f), size)}")
            if inverted:
                value = f.value(f"xor {_i(size)} {value}, -1")
            _store(f, d, size, value)
            return [f.value(f"icmp eq {_i(size)} {value}, 0")], "true"

        return work

    return prepare


def _isqrt(f: FunctionText, value: str, size: int) -> str:
    """The integer square root of 0 <= `value` < 2 ** (8 * size - 1) (i64), bit by bit."""
    rest, root = value, "0"
    bit = 1 << (8 * size - 2)
    while bit:
        trial = f.value(f"add i64 {root}, {bit}")
        fits = f.value(f"icmp sge i64 {rest}, {trial}")
        rest = f.value(f"select i1 {fits}, i64 {f.value(f'sub i64 {rest}, {trial}')}, "
                       f"i64 {rest}")
        half = f.value(f"lshr i64 {root}, 1")
        root = f.value(f"select i1 {fits}, i64 {f.value(f'add i64 {half}, {bit}')}, "
                       f"i64 {half}")
        bit >>= 2
    return root


def _sqrt(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
    """FUN 26 SQRT: D := isqrt(S); S < 0: FO0 ERR, D kept."""
    source, destination = operands
    s_of, d = _operand(source, size), _place(destination, size)
    if s_of is None or d is None:
        return None

    def work(f: FunctionText) -> tuple[list[str], str]:
        value = s_of(f)
        negative = f.value(f"icmp slt i64 {value}, 0")
        root = _isqrt(f, f.value(f"select i1 {negative}, i64 0, i64 {value}"), size)
        _store(f, d, size, f.value(f"select i1 {negative}, {_i(size)} {_load(f, d, size)}, "
                                   f"{_i(size)} {_narrow(f, root, size)}"))
        return [negative], "true"

    return work


def _unary(negate: bool) -> Prepare:
    """FUN 27 NEG (D := -D), 28 ABS (D := |D|), wrapped; no FO (W1 0)."""

    def prepare(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
        (destination,) = operands
        d = _place(destination, size)
        if d is None:
            return None

        def work(f: FunctionText) -> tuple[list[str], str]:
            value = _load(f, d, size)
            opposite = f.value(f"sub {_i(size)} 0, {value}")
            if not negate:
                below = f.value(f"icmp slt {_i(size)} {value}, 0")
                opposite = f.value(f"select i1 {below}, {_i(size)} {opposite}, "
                                   f"{_i(size)} {value}")
            _store(f, d, size, opposite)
            return _NONE

        return work

    return prepare


def _ext(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
    """FUN 29 EXT: the 16-bit D sign-extended into the 32-bit D (both forms)."""
    (destination,) = operands
    d = _place(destination, 4)
    if d is None:
        return None

    def work(f: FunctionText) -> tuple[list[str], str]:
        _store(f, d, 4, f.value(f"sext i16 {_load(f, d, 2)} to i32"))
        return _NONE

    return work


def _mover(left: bool, rotate: bool) -> Prepare:
    """FUN 51 SHFL, 52 SHFR (INB shifted in), 53 ROTL, 54 ROTR: D moved N bits, FO0 the last
    bit out; N outside 1 .. the width's bits: FO1 ERR, D kept."""

    def prepare(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
        destination, count = operands
        d, n_of = _place(destination, size), _operand(count, 2)
        if d is None or n_of is None or (not rotate and len(inputs) < 2):
            return None
        bits = 8 * size
        mask = (1 << bits) - 1

        def work(f: FunctionText) -> tuple[list[str], str]:
            n = n_of(f)
            valid = f.value(f"and i1 {f.value(f'icmp sge i64 {n}, 1')}, "
                            f"{f.value(f'icmp sle i64 {n}, {bits}')}")
            start = f.block
            _, after = f.branch_if(valid)
            value = f.value(f"zext {_i(size)} {_load(f, d, size)} to i64")
            back = f.value(f"sub i64 {bits}, {n}")
            ones = f.value(f"sub i64 {f.value(f'shl i64 1, {n}')}, 1")  # n fill bits
            if left:
                moved = f.value(f"shl i64 {value}, {n}")
                came = f.value(f"lshr i64 {value}, {back}") if rotate else ones
                out = f.value(f"lshr i64 {value}, {back}")
            else:
                moved = f.value(f"lshr i64 {value}, {n}")
                came = f.value(f"shl i64 {value if rotate else ones}, {back}")
                out = f.value(f"lshr i64 {value}, {f.value(f'sub i64 {n}, 1')}")
            if not rotate:
                came = f.value(f"select i1 {f.truth(inputs[1])}, i64 {came}, i64 0")
            result = f.value(f"and i64 {f.value(f'or i64 {moved}, {came}')}, {mask}")
            _store(f, d, size, _narrow(f, result, size))
            bit = f.value(f"trunc i64 {out} to i1")
            end = f.block
            f.join(after)
            return [f.value(f"phi i1 [false, %{start}], [{bit}, %{end}]"),
                    f.value(f"xor i1 {valid}, true")], "true"

        return work

    return prepare


def _movn(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
    """FUN 9 MOV/: D := ~S."""
    source, destination = operands
    s_of, d = _operand(source, size), _place(destination, size)
    if s_of is None or d is None:
        return None

    def work(f: FunctionText) -> tuple[list[str], str]:
        _store(f, d, size, f.value(f"xor {_i(size)} {_narrow(f, s_of(f), size)}, -1"))
        return _NONE

    return work


def _togg(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
    """FUN 10 TOGG: the bit D inverted; FO0 its new state."""
    (device,) = operands
    if not (isinstance(device, Address) and device.bit is not None and _fits(device, 1)):
        return None
    bit = device.bit

    def work(f: FunctionText) -> tuple[list[str], str]:
        on = f.value(f"icmp eq i8 {f.bit(device.area, device.byte, bit, False)}, 0")
        set_bit(f, device, on)
        return [on], "true"

    return work


def _zncmp(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
    """FUN 37 ZNCMP: FO0 SL <= S <= SU, FO1 S > SU, FO2 S < SL; SU < SL: FO3 ERR only."""
    read = [_operand(v, size) for v in operands]
    if any(r is None for r in read):
        return None

    def work(f: FunctionText) -> tuple[list[str], str]:
        s, su, sl = (r(f) for r in read if r is not None)
        error = f.value(f"icmp slt i64 {su}, {sl}")
        fine = f.value(f"xor i1 {error}, true")
        inside = f.value(f"and i1 {f.value(f'icmp sle i64 {sl}, {s}')}, "
                         f"{f.value(f'icmp sle i64 {s}, {su}')}")
        bits = [f.value(f"and i1 {fine}, {bit}") for bit in (
            inside, f.value(f"icmp sgt i64 {s}, {su}"), f.value(f"icmp slt i64 {s}, {sl}"))]
        return [*bits, error], "true"

    return work


def _in_range(f: FunctionText, n: str, size: int) -> str:
    """0 <= n < the width's bits (i1)."""
    return f.value(f"icmp ult i64 {n}, {8 * size}")


def _bitrd(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
    """FUN 40 BITRD: FO0 bit N of S; N outside the width: FO and FO0 kept."""
    source, number = operands
    s_of, n_of = _operand(source, size), _operand(number, 2)
    if s_of is None or n_of is None:
        return None

    def work(f: FunctionText) -> tuple[list[str], str]:
        n = n_of(f)
        inside = _in_range(f, n, size)
        shifted = f.value(f"ashr i64 {s_of(f)}, {f.value(f'and i64 {n}, 63')}")
        return [f.value(f"trunc i64 {shifted} to i1")], inside

    return work


def _bitwr(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
    """FUN 41 BITWR: bit N of D := INB; N outside the width: nothing."""
    destination, number = operands
    d, n_of = _place(destination, size), _operand(number, 2)
    if d is None or n_of is None or len(inputs) < 2:
        return None

    def work(f: FunctionText) -> tuple[list[str], str]:
        n = n_of(f)
        inside = _in_range(f, n, size)
        old = f.value(f"zext {_i(size)} {_load(f, d, size)} to i64")
        bit = f.value(f"shl i64 1, {f.value(f'and i64 {n}, 63')}")
        on = f.value(f"or i64 {old}, {bit}")
        off = f.value(f"and i64 {old}, {f.value(f'xor i64 {bit}, -1')}")
        new = f.value(f"select i1 {f.truth(inputs[1])}, i64 {on}, i64 {off}")
        _store(f, d, size, _narrow(f, f.value(f"select i1 {inside}, i64 {new}, i64 {old}"),
                                   size))
        return _NONE

    return work


def _part_move(bits: int) -> Prepare:
    """FUN 42 BITMV, 43 NBMV, 44 BYMV: part Nd of D := part Ns of S; a part number outside
    the width: nothing."""

    def prepare(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
        source, ns, destination, nd = operands
        s_of, a_of, b_of = _operand(source, size), _operand(ns, 2), _operand(nd, 2)
        d = _place(destination, size)
        if s_of is None or a_of is None or b_of is None or d is None:
            return None
        parts = 8 * size // bits
        mask = (1 << bits) - 1

        def work(f: FunctionText) -> tuple[list[str], str]:
            a, b = a_of(f), b_of(f)
            inside = f.value(f"and i1 {f.value(f'icmp ult i64 {a}, {parts}')}, "
                             f"{f.value(f'icmp ult i64 {b}, {parts}')}")
            at_a = f.value(f"mul i64 {f.value(f'and i64 {a}, 31')}, {bits}")
            at_b = f.value(f"mul i64 {f.value(f'and i64 {b}, 31')}, {bits}")
            part = f.value(f"and i64 {f.value(f'ashr i64 {s_of(f)}, {at_a}')}, {mask}")
            old = f.value(f"zext {_i(size)} {_load(f, d, size)} to i64")
            hole = f.value(f"xor i64 {f.value(f'shl i64 {mask}, {at_b}')}, -1")
            cleared = f.value(f"and i64 {old}, {hole}")
            new = f.value(f"or i64 {cleared}, {f.value(f'shl i64 {part}, {at_b}')}")
            _store(f, d, size, _narrow(f, f.value(f"select i1 {inside}, i64 {new}, "
                                                  f"i64 {old}"), size))
            return _NONE

        return work

    return prepare


def _xchg(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
    """FUN 45 XCHG: Da and Db exchanged (both read first, Da written first)."""
    first, second = (_place(v, size) for v in operands)
    if first is None or second is None:
        return None

    def work(f: FunctionText) -> tuple[list[str], str]:
        a, b = _load(f, first, size), _load(f, second, size)
        _store(f, first, size, b)
        _store(f, second, size, a)
        return _NONE

    return work


def _swap(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
    """FUN 46 SWAP: D's halves exchanged."""
    (destination,) = operands
    d = _place(destination, size)
    if d is None:
        return None
    half = 4 * size

    def work(f: FunctionText) -> tuple[list[str], str]:
        value = _load(f, d, size)
        _store(f, d, size, f.value(f"or {_i(size)} {f.value(f'shl {_i(size)} {value}, {half}')}"
                                   f", {f.value(f'lshr {_i(size)} {value}, {half}')}"))
        return _NONE

    return work


def _nibbles(unite: bool) -> Prepare:
    """FUN 47 UNIT, 48 DIST (16-bit): N (1-4) nibbles united or distributed; else FO0 ERR."""

    def prepare(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
        source, count, destination = operands
        n_of = _operand(count, 2)
        s = _place(source, 8) if unite else None
        s_of = None if unite else _operand(source, 2)
        d = _place(destination, 2 if unite else 8)
        if n_of is None or d is None or (s is None if unite else s_of is None):
            return None

        def work(f: FunctionText) -> tuple[list[str], str]:
            n = n_of(f)
            error = f.value(f"or i1 {f.value(f'icmp slt i64 {n}, 1')}, "
                            f"{f.value(f'icmp sgt i64 {n}, 4')}")
            if s is not None:
                value = "0"
                for k in range(4):
                    word = f.value(f"zext i16 {_load(f, s.offset(2 * k), 2)} to i64")
                    nibble = f.value(f"shl i64 {f.value(f'and i64 {word}, 15')}, {4 * k}")
                    taken = f.value(f"icmp slt i64 {k}, {n}")
                    value = f.value(f"or i64 {value}, "
                                    f"{f.value(f'select i1 {taken}, i64 {nibble}, i64 0')}")
                old = _load(f, d, 2)
                _store(f, d, 2, f.value(f"select i1 {error}, i16 {old}, i16 "
                                        f"{_narrow(f, value, 2)}"))
            else:
                assert s_of is not None
                word = s_of(f)
                for k in range(4):
                    at = d.offset(2 * k)
                    nibble = f.value(f"and i64 {f.value(f'ashr i64 {word}, {4 * k}')}, 15")
                    taken = f.value(f"and i1 {f.value(f'icmp slt i64 {k}, {n}')}, "
                                    f"{f.value(f'xor i1 {error}, true')}")
                    _store(f, at, 2, f.value(f"select i1 {taken}, i16 {_narrow(f, nibble, 2)}"
                                             f", i16 {_load(f, at, 2)}"))
            return [error], "true"

        return work

    return prepare


def _convert(to_code: bool) -> Prepare:
    """FUN 20 →BCD (0 .. 10 ** digits - 1 coded), 21 →BIN (a BCD code's value); else FO0
    ERR, D kept."""

    def prepare(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
        source, destination = operands
        d, s_of = _place(destination, size), _operand(source, size)
        if d is None or s_of is None:
            return None
        digits = 2 * size

        def work(f: FunctionText) -> tuple[list[str], str]:
            if not isinstance(source, Address):  # a constant: its result known now
                assert isinstance(source, int)
                known = to_bcd(source, digits) if to_code else from_bcd(source, digits)
                if known is not None:
                    _store(f, d, size, _narrow(f, str(known), size))
                return ["true" if known is None else "false"], "true"
            if to_code:
                value = s_of(f)
                valid = f.value(f"and i1 {f.value(f'icmp sge i64 {value}, 0')}, "
                                f"{f.value(f'icmp slt i64 {value}, {10 ** digits}')}")
                result = _encode(f, f.value(f"select i1 {valid}, i64 {value}, i64 0"), size)
            else:
                total, valid = _read(f, source, size)
                result = _narrow(f, total, size)
            _store(f, d, size, f.value(f"select i1 {valid}, {_i(size)} {result}, "
                                       f"{_i(size)} {_load(f, d, size)}"))
            return [f.value(f"xor i1 {valid}, true")], "true"

        return work

    return prepare


def _div48(size: int, operands: Sequence[object], inputs: list[str]) -> Prepared:
    """FUN 23 DIV48: the 48-bit Sa / Sb (U/S = 1 unsigned) in D; FO0 D=0, FO1 ERR Sb = 0."""
    places = [_place(v, 6) for v in operands]
    if any(p is None for p in places) or len(inputs) < 2:
        return None
    sa, sb, d = (p for p in places if p is not None)

    def work(f: FunctionText) -> tuple[list[str], str]:
        unsigned = f.truth(inputs[1])
        values = []
        for at in (sa, sb):
            raw = _load(f, at, 6)
            values.append(f.value(f"select i1 {unsigned}, i64 {f.value(f'zext i48 {raw} to i64')}"
                                  f", i64 {f.value(f'sext i48 {raw} to i64')}"))
        a, b = values
        zero = f.value(f"icmp eq i64 {b}, 0")
        safe = f.value(f"select i1 {zero}, i64 1, i64 {b}")
        quotient = f.value(f"select i1 {unsigned}, i64 {f.value(f'udiv i64 {a}, {safe}')}, "
                           f"i64 {f.value(f'sdiv i64 {a}, {safe}')}")
        narrow = f.value(f"trunc i64 {quotient} to i48")
        _store(f, d, 6, f.value(f"select i1 {zero}, i48 {_load(f, d, 6)}, i48 {narrow}"))
        is_zero = f.value(f"and i1 {f.value(f'icmp eq i48 {narrow}, 0')}, "
                          f"{f.value(f'xor i1 {zero}, true')}")
        return [is_zero, zero], "true"

    return work


# the rows: (has FO, its last parameter; prepare)
_ROWS: dict[str, tuple[bool, Prepare]] = {
    "FBS.AND": (True, _logic("and", False)), "FBS.OR": (True, _logic("or", False)),
    "FBS.XOR": (True, _logic("xor", False)), "FBS.XNR": (True, _logic("xor", True)),
    "FBS.SQRT": (True, _sqrt), "FBS.NEG": (False, _unary(True)),
    "FBS.ABS": (False, _unary(False)), "FBS.EXT": (False, _ext),
    "FBS.SHFL": (True, _mover(True, False)), "FBS.SHFR": (True, _mover(False, False)),
    "FBS.ROTL": (True, _mover(True, True)), "FBS.ROTR": (True, _mover(False, True)),
    "FBS.MOVN": (False, _movn), "FBS.TOGG": (True, _togg), "FBS.ZNCMP": (True, _zncmp),
    "FBS.BITRD": (True, _bitrd), "FBS.BITWR": (False, _bitwr),
    "FBS.BITMV": (False, _part_move(1)), "FBS.NBMV": (False, _part_move(4)),
    "FBS.BYMV": (False, _part_move(8)), "FBS.XCHG": (False, _xchg), "FBS.SWAP": (False, _swap),
    "FBS.UNIT": (True, _nibbles(True)), "FBS.DIST": (True, _nibbles(False)),
    "FBS.BCD": (True, _convert(True)), "FBS.BIN": (True, _convert(False)),
    "FBS.DIV48": (True, _div48),
}


def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str]) -> str | None:
    """A word box's code (`fatek.box`); None: it calls back."""
    if not inputs or not params or not isinstance(params[0], int):
        return None
    mode = params[0]
    has_fo, prepare = ROWS[impl]
    work = prepare(4 if mode & DOUBLE else 2, params[1:-1] if has_fo else params[1:], inputs)
    if work is None:
        return None
    return box(b, inputs[0], mode, params[-1] if has_fo else None, has_fo, work)


def _rows() -> dict[FunctionImpl, tuple[bool, Prepare]]:
    load_all()
    return {REGISTRY[name]: row for name, row in _ROWS.items() if name in REGISTRY}


def _not_simulated(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """A FUN kept and drawn but not simulated (HSPSO, MPARA …): its FO byte 0, W1 0."""
    fo = params[1] if len(params) > 1 else None
    if fo is not None and _place(fo, 1) is None:
        return None
    if isinstance(fo, Address):
        _store(f, fo, 1, "0")
    return "0"


ROWS = _rows()
STATEFUL = {impl: ("fatek box", emit) for impl in ROWS}
EMITTERS = {REGISTRY[name]: _not_simulated for name in NOT_SIMULATED if name in REGISTRY}
