"""The PMC's DCNV (binary <-> BCD), DSCH / DSCHB (table search) and XMOV (BCD-indexed table
access) as native code, exactly as core/plc/functions/convert.py, search.py and transfer.py do:
an error output held as `held_output` holds it (state_block._held). BYT (1 or 2 bytes) is a
run-time input: the code of both widths is made and BYT picks one. A search is a loop over
the table as far as the PMC's map of its area reaches (`search.find`). Values little-endian:
not in a big-endian program (S7), where they call back.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core import dialects
from ladderworks.core.address import AREA_SIZES, Address
from ladderworks.core.plc.functions import FunctionImpl, convert, search, transfer
from ladderworks.core.plc.native.builtins import _fits, _load, _store
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import Block, _held

Emitter = Callable[[Block, FunctionImpl, Sequence[object], list[str]], str | None]


def _little(b: Block) -> bool:
    found = dialects.get(b.dialect)
    return found is None or found.byteorder != "big"


def _by_width(f: FunctionText, byt: str, body: Callable[[int], str]) -> str:
    """`body(width)`'s i1 for BYT = 0 (1 byte) and BYT = 1 (2 bytes), the one BYT picks."""
    one, two, joined = f.label(), f.label(), f.label()
    f.add(f"br i1 {f.truth(byt)}, label %{two}, label %{one}")
    results = []
    for label, width in ((one, 1), (two, 2)):
        f.start(label)
        results.append((body(width), f.block))
        f.add(f"br label %{joined}")
    f.start(joined)
    return f.value("phi i1 " + ", ".join(f"[{value}, %{block}]" for value, block in results))


def _bcd_value(f: FunctionText, raw: str, digits: int) -> tuple[str, str]:
    """(valid: every nibble ≤ 9, its value) of i64 `raw` (`bcd_to_int`)."""
    ok, value = "true", "0"
    for k in range(digits):
        digit = f.value(f"and i64 {f.value(f'lshr i64 {raw}, {4 * k}')}, 15")
        ok = f.value(f"and i1 {ok}, {f.value(f'icmp ule i64 {digit}, 9')}")
        value = f.value(f"add i64 {value}, {f.value(f'mul i64 {digit}, {10 ** k}')}")
    return ok, value


def _bcd_of(f: FunctionText, value: str, digits: int) -> str:
    """The BCD bits of 0 ≤ `value` < 10**digits (`int_to_bcd`), i64."""
    raw = "0"
    for k in range(digits):
        digit = f.value(f"urem i64 {f.value(f'udiv i64 {value}, {10 ** k}')}, 10")
        raw = f.value(f"or i64 {raw}, {f.value(f'shl i64 {digit}, {4 * k}')}")
    return raw


def _stored_if(f: FunctionText, ok: str, target: Address, width: int, value: str) -> str:
    """Store i64 `value` in `width` bytes when `ok`; the i1 error (not ok)."""
    good, done = f.label(), f.label()
    f.add(f"br i1 {ok}, label %{good}, label %{done}")
    f.start(good)
    _store(f, target, width, f.value(f"trunc i64 {value} to i{8 * width}"))
    f.add(f"br label %{done}")
    f.start(done)
    return f.value(f"xor i1 {ok}, true")


def _dcnv(b: Block, impl: FunctionImpl, params: Sequence[object],
          inputs: list[str]) -> str | None:
    """DCNV: CNV = 1 BCD -> binary, CNV = 0 binary -> BCD, of 1 (BYT = 0) or 2 bytes."""
    if len(params) != 2 or len(inputs) != 4 or not _little(b) or \
            not all(_fits(p, 2) for p in params):
        return None
    source, target = params
    assert isinstance(source, Address) and isinstance(target, Address)
    f = b.f
    byt, cnv, rst, act = inputs

    def width_body(width: int) -> str:
        raw = f.value(f"zext i{8 * width} {_load(f, source, width)} to i64")
        to_binary, to_bcd, joined = f.label(), f.label(), f.label()
        f.add(f"br i1 {f.truth(cnv)}, label %{to_binary}, label %{to_bcd}")
        f.start(to_binary)
        ok, value = _bcd_value(f, raw, 2 * width)
        first = (_stored_if(f, ok, target, width, value), f.block)
        f.add(f"br label %{joined}")
        f.start(to_bcd)
        fits = f.value(f"icmp ult i64 {raw}, {10 ** (2 * width)}")
        second = (_stored_if(f, fits, target, width, _bcd_of(f, raw, 2 * width)), f.block)
        f.add(f"br label %{joined}")
        f.start(joined)
        return f.value(f"phi i1 [{first[0]}, %{first[1]}], [{second[0]}, %{second[1]}]")

    return _held(b, rst, act, lambda: _by_width(f, byt, width_body))


def _find(f: FunctionText, table: Address, width: int, count: str, wanted: str) -> str:
    """`search.find`: the first row < `count` (i64, ≥ 0) whose entry equals `wanted`
    (i{8·width}), else -1 (i64)."""
    start = f.block
    base = f.byte_ptr(table.area, table.byte)
    loop, body, step, done = f.label(), f.label(), f.label(), f.label()
    f.add(f"br label %{loop}")
    f.start(loop)
    row = f.tmp()
    ended = f.value(f"icmp sge i64 {row}, {count}")
    f.add(f"br i1 {ended}, label %{done}, label %{body}")
    f.start(body)
    entry = f.value(f"getelementptr i8, ptr {base}, i64 {f.value(f'mul i64 {row}, {width}')}")
    equal = f.value(f"icmp eq i{8 * width} {f.value(f'load i{8 * width}, ptr {entry}, align 1')}"
                    f", {wanted}")
    f.add(f"br i1 {equal}, label %{done}, label %{step}")
    f.start(step)
    following = f.value(f"add i64 {row}, 1")
    f.add(f"br label %{loop}")
    index = f.body.index(f"{loop}:")
    f.body.insert(index + 1, f"  {row} = phi i64 [0, %{start}], [{following}, %{step}]")
    f.start(done)
    return f.value(f"phi i64 [-1, %{loop}], [{row}, %{body}]")


def _room(table: Address, width: int) -> int:
    return (AREA_SIZES[table.area] - table.byte) // width


def _dsch(b: Block, impl: FunctionImpl, params: Sequence[object],
          inputs: list[str]) -> str | None:
    """DSCH: the BCD index of the first entry equal to the (BCD) search data; W1 = 1 when
    the data is not BCD, nothing is found or the index does not fit."""
    if len(params) != 4 or len(inputs) != 3 or not _little(b):
        return None
    size, table, wanted_at, result = params
    if not (isinstance(size, int) and isinstance(table, Address) and _fits(wanted_at, 2)
            and _fits(result, 2)) or isinstance(size, bool):
        return None
    assert isinstance(wanted_at, Address) and isinstance(result, Address)
    f = b.f
    byt, rst, act = inputs

    def width_body(width: int) -> str:
        wanted = _load(f, wanted_at, width)
        valid, _ = _bcd_value(f, f.value(f"zext i{8 * width} {wanted} to i64"), 2 * width)
        look, done = f.label(), f.label()
        checked = f.block
        f.add(f"br i1 {valid}, label %{look}, label %{done}")
        f.start(look)
        row = _find(f, table, width, str(max(0, min(size, _room(table, width)))), wanted)
        found = f.value(f"and i1 {f.value(f'icmp sge i64 {row}, 0')}, "
                        f"{f.value(f'icmp slt i64 {row}, {10 ** (2 * width)}')}")
        error = _stored_if(f, found, result, width, _bcd_of(f, row, 2 * width))
        looked = f.block
        f.add(f"br label %{done}")
        f.start(done)
        return f.value(f"phi i1 [true, %{checked}], [{error}, %{looked}]")

    return _held(b, rst, act, lambda: _by_width(f, byt, width_body))


def _dschb(b: Block, impl: FunctionImpl, params: Sequence[object],
           inputs: list[str]) -> str | None:
    """DSCHB: the table size (4 bytes signed) at an address, the index 4 bytes binary."""
    if len(params) != 5 or len(inputs) != 2 or not _little(b):
        return None
    width, size_at, table, wanted_at, result = params
    if not (isinstance(width, int) and width in (1, 2, 4) and isinstance(table, Address)
            and _fits(size_at, 4) and _fits(wanted_at, width) and _fits(result, 4)):
        return None
    assert isinstance(size_at, Address) and isinstance(wanted_at, Address)
    assert isinstance(result, Address)
    f = b.f

    def compute() -> str:
        size = f.value(f"sext i32 {_load(f, size_at, 4)} to i64")
        room = _room(table, width)
        count = f.value(f"select i1 {f.value(f'icmp slt i64 {size}, {room}')}, i64 {size}, "
                        f"i64 {room}")
        row = _find(f, table, width, count, _load(f, wanted_at, width))
        return _stored_if(f, f.value(f"icmp sge i64 {row}, 0"), result, 4, row)

    return _held(b, inputs[0], inputs[1], compute)


def _xmov(b: Block, impl: FunctionImpl, params: Sequence[object],
          inputs: list[str]) -> str | None:
    """XMOV: RW = 0 data = table[index], RW = 1 table[index] = data; the index BCD."""
    if len(params) != 4 or len(inputs) != 4 or not _little(b):
        return None
    size, table, data, index_at = params
    if not (isinstance(size, int) and isinstance(table, Address) and _fits(data, 2)
            and _fits(index_at, 2)) or isinstance(size, bool):
        return None
    assert isinstance(data, Address) and isinstance(index_at, Address)
    f = b.f
    byt, rw, rst, act = inputs

    def width_body(width: int) -> str:
        raw = f.value(f"zext i{8 * width} {_load(f, index_at, width)} to i64")
        valid, row = _bcd_value(f, raw, 2 * width)
        inside = f.value(f"and i1 {valid}, {f.value(f'icmp slt i64 {row}, {size}')}")
        byte = f.value(f"add i64 {f.value(f'mul i64 {row}, {width}')}, {table.byte}")
        fits = f.value(f"icmp sle i64 {f.value(f'add i64 {byte}, {width}')}, "
                       f"{AREA_SIZES[table.area]}")
        good = f.value(f"and i1 {inside}, {fits}")
        move, done = f.label(), f.label()
        start = f.block
        f.add(f"br i1 {good}, label %{move}, label %{done}")
        f.start(move)
        entry = f.value(f"getelementptr i8, ptr {f.byte_ptr(table.area, 0)}, i64 {byte}")
        there = f.byte_ptr(data.area, data.byte)
        writes = f.truth(rw)
        source = f.value(f"select i1 {writes}, ptr {there}, ptr {entry}")
        target = f.value(f"select i1 {writes}, ptr {entry}, ptr {there}")
        value = f.value(f"load i{8 * width}, ptr {source}, align 1")
        f.add(f"store i{8 * width} {value}, ptr {target}, align 1")
        f.add(f"br label %{done}")
        f.start(done)
        return f.value(f"phi i1 [true, %{start}], [false, %{move}]")

    return _held(b, rst, act, lambda: _by_width(f, byt, width_body))


STATEFUL: dict[FunctionImpl, tuple[str, Emitter]] = {
    convert.dcnv: ("dcnv", _dcnv),
    search.dsch: ("dsch", _dsch),
    search.dschb: ("dschb", _dschb),
    transfer.xmov: ("xmov", _xmov),
}
"""The PMC's last four: implementation -> (kind, emitter)."""
