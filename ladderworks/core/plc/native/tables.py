"""CODB, XMOVB, DCNVB and the counters (CTR, CTRC, CTRB) as native code, their call-site states
in blocks of state words (state_block.py): exactly what core/plc/functions/ does."""

from __future__ import annotations

from collections.abc import Sequence

from ladderworks.core.address import AREA_SIZES, Address
from ladderworks.core.plc.functions import (
    FLAG_NEGATIVE,
    FLAG_OVERFLOW,
    FLAG_ZERO,
    RESULT_REGISTER,
    FunctionImpl,
    counters,
)
from ladderworks.core.plc.native.state_block import (
    ACT,
    CHANGED,
    ELAPSED,
    HAS_ACT,
    HAS_VALUE,
    Block,
    _fits,
    _held,
    _load,
    _store,
)

_I32 = (-(1 << 31), (1 << 31) - 1)


def _codb(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
    """CODB: output = table[index] (binary, 1/2/4 bytes); W1 = 1 past the table."""
    width, size, index, out = params[:4]
    table = params[4:]
    if len(inputs) != 2 or not (isinstance(width, int) and isinstance(size, int)):
        return None
    if width not in (1, 2, 4) or not (_fits(index, 1) and _fits(out, width)):
        return None
    if not all(isinstance(entry, int) for entry in table):
        return None
    assert isinstance(index, Address) and isinstance(out, Address)
    f = b.f
    rows = [(row, entry) for row, entry in enumerate(table[:max(0, min(size, len(table), 256))])
            if isinstance(entry, int) and -(1 << (8 * width - 1)) <= entry < 1 << (8 * width)]

    def compute() -> str:
        row = _load(f, index, 1)
        cases = [(number, entry, f.label()) for number, entry in rows]
        bad, done = f.label(), f.label()
        f.add(f"switch i8 {row}, label %{bad} [" +
              " ".join(f"i8 {_signed8(number)}, label %{label}" for number, _, label in cases)
              + "]")
        for _, entry, label in cases:
            f.start(label)
            raw = entry & ((1 << (8 * width)) - 1)
            _store(f, out, width, str(raw - (1 << (8 * width)) if raw >> (8 * width - 1)
                                      else raw))
            f.add(f"br label %{done}")
        f.start(bad)
        f.add(f"br label %{done}")
        f.start(done)
        return f.value("phi i1 " + ", ".join(
            [f"[false, %{label}]" for _, _, label in cases] + [f"[true, %{bad}]"]))

    return _held(b, inputs[0], inputs[1], compute)


def _xmovb(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
    """XMOVB: RW = 0 data = table[index], RW = 1 table[index] = data (1/2/4-byte entries,
    the index 4 bytes signed, the size a constant or 2 bytes signed at an address)."""
    width, size, table, data, index = params
    if len(inputs) != 3 or not (isinstance(width, int) and width in (1, 2, 4)):
        return None
    if not (isinstance(table, Address) and _fits(data, width) and _fits(index, 4)):
        return None
    if (isinstance(size, Address) and not _fits(size, 2)) or \
            not isinstance(size, Address | int) or isinstance(size, bool):
        return None
    if isinstance(size, int) and not _I32[0] <= size <= _I32[1]:
        return None
    assert isinstance(data, Address) and isinstance(index, Address)
    f = b.f
    bits = 8 * width
    limit = AREA_SIZES[table.area]

    def compute() -> str:
        count = (f.value(f"sext i16 {_load(f, size, 2)} to i64")
                 if isinstance(size, Address) else str(size))
        row = f.value(f"sext i32 {_load(f, index, 4)} to i64")
        inside = f.value(f"and i1 {f.value(f'icmp sge i64 {row}, 0')}, "
                         f"{f.value(f'icmp slt i64 {row}, {count}')}")
        byte = f.value(f"add i64 {f.value(f'mul i64 {row}, {width}')}, {table.byte}")
        fits = f.value(f"icmp sle i64 {f.value(f'add i64 {byte}, {width}')}, {limit}")
        good = f.value(f"and i1 {inside}, {fits}")
        move, done = f.label(), f.label()
        start = f.block
        f.add(f"br i1 {good}, label %{move}, label %{done}")
        f.start(move)
        entry = f.value(f"getelementptr i8, ptr {f.byte_ptr(table.area, 0)}, i64 {byte}")
        there = f.byte_ptr(data.area, data.byte)
        writes = f.truth(inputs[0])
        source = f.value(f"select i1 {writes}, ptr {there}, ptr {entry}")
        target = f.value(f"select i1 {writes}, ptr {entry}, ptr {there}")
        value = f.value(f"load i{bits}, ptr {source}, align 1")
        f.add(f"store i{bits} {value}, ptr {target}, align 1")
        f.add(f"br label %{done}")
        f.start(done)
        return f.value(f"phi i1 [true, %{start}], [false, %{move}]")

    return _held(b, inputs[1], inputs[2], compute)


def _counter(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
    """CTR, CTRC, CTRB: `counters.ring_count` on the value where each keeps it."""
    if len(inputs) != 4:
        return None
    f = b.f
    stored_at: Address | None
    if impl is counters.ctr:
        (number,) = params
        if not isinstance(number, int):
            return None
        preset_at, stored_at = (counters.counter_preset_address(number),
                                counters.counter_value_address(number))
        if not (_fits(preset_at, 2) and _fits(stored_at, 2)):
            return None
        preset = f.value(f"zext i16 {_load(f, preset_at, 2)} to i64")
    elif impl is counters.ctrc:
        preset_param, register = params
        if not (_fits(preset_param, 2) and _fits(register, 2)):
            return None
        assert isinstance(preset_param, Address) and isinstance(register, Address)
        stored_at = register
        raw = f.value(f"zext i16 {_load(f, preset_param, 2)} to i64")
        over = f.value(f"icmp sgt i64 {raw}, {counters.MAX_PRESET}")
        preset = f.value(f"select i1 {over}, i64 {counters.MAX_PRESET}, i64 {raw}")
    else:
        number, fixed = params
        if not (isinstance(number, int) and isinstance(fixed, int)
                and _I32[0] <= fixed <= _I32[1]):
            return None
        where = counters.ctrb_value_address(number)
        stored_at = where if _fits(where, 2) else None
        preset = str(min(fixed, counters.MAX_PRESET))
    flags = b.flags()
    cn0, down, rst, act = (f.truth(value) for value in inputs)
    if stored_at is not None:
        current = f.value(f"zext i16 {_load(f, stored_at, 2)} to i64")
    else:  # CTRB past the C area: the value kept in the call site ("value", else 0)
        has = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {HAS_VALUE}')}, 0")
        current = f.value(f"select i1 {has}, i64 {b.load64(ELAPSED)}, i64 0")
    low = f.value(f"zext i1 {cn0} to i64")
    top = f.value(f"select i1 {f.value(f'icmp slt i64 {preset}, {low}')}, i64 {low}, "
                  f"i64 {preset}")
    before = f.value(f"icmp eq i32 {f.value(f'and i32 {flags}, {HAS_ACT | ACT}')}, "
                     f"{HAS_ACT | ACT}")
    rising = f.value(f"and i1 {act}, {f.value(f'xor i1 {before}, true')}")
    down_value = f.value(f"select i1 {f.value(f'icmp sle i64 {current}, {low}')}, i64 {top}, "
                         f"i64 {f.value(f'sub i64 {current}, 1')}")
    up_value = f.value(f"select i1 {f.value(f'icmp sge i64 {current}, {top}')}, i64 {low}, "
                       f"i64 {f.value(f'add i64 {current}, 1')}")
    counted = f.value(f"select i1 {down}, i64 {down_value}, i64 {up_value}")
    counted = f.value(f"select i1 {rising}, i64 {counted}, i64 {current}")
    start = f.value(f"select i1 {down}, i64 {top}, i64 {low}")
    value = f.value(f"select i1 {rst}, i64 {start}, i64 {counted}")
    at_end = f.value(f"select i1 {down}, i1 {f.value(f'icmp sle i64 {value}, {low}')}, "
                     f"i1 {f.value(f'icmp sge i64 {value}, {top}')}")
    w1 = f.value(f"and i1 {f.value(f'xor i1 {rst}, true')}, {at_end}")
    if stored_at is not None:
        _store(f, stored_at, 2, f.value(f"trunc i64 {value} to i16"))
    new = f.value(f"or i32 {f.value(f'and i32 {flags}, {~ACT}')}, {HAS_ACT}")
    new = f.value(f"select i1 {act}, i32 {f.value(f'or i32 {new}, {ACT}')}, i32 {new}")
    if impl is counters.ctrb:  # state["value"] = value
        old = b.load64(ELAPSED)
        b.store64(ELAPSED, value)
        kept = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {HAS_VALUE}')}, 0")
        same = f.value(f"and i1 {kept}, {f.value(f'icmp eq i64 {old}, {value}')}")
        new = f.value(f"or i32 {new}, {HAS_VALUE}")
        new = f.value(f"select i1 {same}, i32 {new}, i32 {f.value(f'or i32 {new}, {CHANGED}')}")
    b.set_flags(flags, new)
    return f.value(f"zext i1 {w1} to i8")


def _signed8(value: int) -> int:
    return value - 256 if value >= 128 else value




def _dcnvb(b: Block, params: Sequence[object], inputs: list[str], dialect: str) -> str | None:
    """DCNVB: signed binary <-> BCD of 1/2/4 bytes (CNV = 1: BCD with SIN's sign to binary),
    R9000 the flags, W1 = 1 when it cannot (convert.dcnvb)."""
    width, source, target = params
    if len(inputs) != 4 or width not in (1, 2, 4) or dialect == "s7" or \
            not (_fits(source, width) and _fits(target, width) and _fits(RESULT_REGISTER, 1)):
        return None
    assert isinstance(width, int) and isinstance(source, Address) and \
        isinstance(target, Address)
    f = b.f
    sin, cnv, rst, act = inputs
    bits, digits = 8 * width, 2 * width

    def flags(value: str) -> str:
        zero = f.value(f"zext i1 {f.value(f'icmp eq i64 {value}, 0')} to i8")
        negative = f.value(f"zext i1 {f.value(f'icmp slt i64 {value}, 0')} to i8")
        return f.value(f"or i8 {f.value(f'mul i8 {zero}, {FLAG_ZERO}')}, "
                       f"{f.value(f'mul i8 {negative}, {FLAG_NEGATIVE}')}")

    def stored(ok: str, value: str, raw: str, overflow: str) -> str:
        """On `ok` the target gets `raw` and R9000 the flags of `value`, else R9000 gets
        `overflow`; the i1 error."""
        bad, good, done = f.label(), f.label(), f.label()
        f.add(f"br i1 {ok}, label %{good}, label %{bad}")
        f.start(bad)
        _store(f, RESULT_REGISTER, 1, overflow)
        f.add(f"br label %{done}")
        f.start(good)
        _store(f, target, width, f.value(f"trunc i64 {raw} to i{bits}"))
        _store(f, RESULT_REGISTER, 1, flags(value))
        f.add(f"br label %{done}")
        f.start(done)
        return f.value(f"xor i1 {ok}, true")

    def from_bcd() -> str:
        raw = f.value(f"zext i{bits} {_load(f, source, width)} to i64")
        ok, magnitude = "true", "0"
        for k in range(digits):
            digit = f.value(f"and i64 {f.value(f'lshr i64 {raw}, {4 * k}')}, 15")
            ok = f.value(f"and i1 {ok}, {f.value(f'icmp ule i64 {digit}, 9')}")
            magnitude = f.value(f"add i64 {magnitude}, {f.value(f'mul i64 {digit}, {10 ** k}')}")
        negated = f.value(f"sub i64 0, {magnitude}")
        value = f.value(f"select i1 {f.truth(sin)}, i64 {negated}, i64 {magnitude}")
        return stored(ok, value, value, str(FLAG_OVERFLOW))

    def to_bcd() -> str:
        value = f.value(f"sext i{bits} {_load(f, source, width)} to i64")
        negative = f.value(f"icmp slt i64 {value}, 0")
        size = f.value(f"select i1 {negative}, i64 {f.value(f'sub i64 0, {value}')}, "
                       f"i64 {value}")
        ok = f.value(f"icmp slt i64 {size}, {10 ** digits}")
        raw = "0"
        for k in range(digits):
            digit = f.value(f"urem i64 {f.value(f'udiv i64 {size}, {10 ** k}')}, 10")
            raw = f.value(f"or i64 {raw}, {f.value(f'shl i64 {digit}, {4 * k}')}")
        sign = f.value(f"select i1 {negative}, i8 {FLAG_OVERFLOW | FLAG_NEGATIVE}, "
                       f"i8 {FLAG_OVERFLOW}")
        return stored(ok, value, raw, sign)

    def compute() -> str:
        binary, bcd, joined = f.label(), f.label(), f.label()
        f.add(f"br i1 {f.truth(cnv)}, label %{binary}, label %{bcd}")
        f.start(binary)
        first = from_bcd()
        first_end = f.block
        f.add(f"br label %{joined}")
        f.start(bcd)
        second = to_bcd()
        second_end = f.block
        f.add(f"br label %{joined}")
        f.start(joined)
        return f.value(f"phi i1 [{first}, %{first_end}], [{second}, %{second_end}]")

    return _held(b, rst, act, compute)
