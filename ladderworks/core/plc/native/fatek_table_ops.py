"""Fatek FBs table boxes that search, keep and sort tables, as native code
(core/plc/functions/fatek_table_ops.py, fatek_convert.py's CRC16): R-T_S and T-T_C (the first
match from the start found in one pass over the table), QUEUE and STACK, SORT (each entry's
rank among the entries, read first into a buffer, gives its place) and CRC16; each runs in
`fatek.box` with fatek_tables' loops and entries."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.fatek_data import DOUBLE
from ladderworks.core.plc.native.fatek import _operand, box
from ladderworks.core.plc.native.fatek_tables import (
    _SIZES,
    Work,
    _i,
    entry,
    fits,
    load,
    loop,
    store,
)
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import Block, _fits, _load, _store

Prepare = Callable[[int, Sequence[object], list[str]], Work | None]


def _pointer(f: FunctionText, pointer: Address) -> str:
    return f.value(f"sext i16 {_load(f, pointer, 2)} to i64")


def _set_pointer(f: FunctionText, pointer: Address, value: str) -> None:
    _store(f, pointer, 2, f.value(f"trunc i64 {value} to i16"))


def _phis(f: FunctionText, error: list[str], errored: str, done: list[str], finished: str
          ) -> list[str]:
    """The FO bits after an ERR branch (`errored`) and the work's (`finished`)."""
    return [f.value(f"phi i1 [{a}, %{errored}], [{b}, %{finished}]")
            for a, b in zip(error, done, strict=True)]


def _guarded(f: FunctionText, ok: str, error: list[str],
             body: Callable[[], list[str]]) -> tuple[list[str], str]:
    """`body` (its FO bits) when `ok`, else the `error` FO bits and nothing done."""
    start = f.block
    _, after = f.branch_if(ok)
    bits = body()
    end = f.block
    f.join(after)
    return _phis(f, error, start, bits, end), "true"


def _search(pair: bool) -> Prepare:
    """FUN 105 R-T_S (Rs, Ts, L, Pr: Ts[k] = Rs), 106 T-T_C (Ta, Tb, L, Pr: Ta[k] ≠ Tb[k]
    when D/S = 1, = when 0): from the head (FHD, or Pr at L - 1) or after Pr, the first match
    sets Pr, FO0 FND (FO1 END at the last entry); none: Pr := L - 1, FO1 END; FO2 ERR."""

    def prepare(size: int, operands: Sequence[object], inputs: list[str]) -> Work | None:
        first, second, length, pointer = operands
        count_of = _operand(length, 2)
        value_of = None if pair else _operand(first, size)
        tables = [t for t in ((first, second) if pair else (second,))]
        if count_of is None or (not pair and value_of is None) or not _fits(pointer, 2) or \
                not all(isinstance(t, Address) for t in tables) or len(inputs) < (3 if pair
                                                                                  else 2):
            return None
        assert isinstance(pointer, Address) and isinstance(second, Address)

        def work(f: FunctionText) -> tuple[list[str], str]:
            count = count_of(f)
            at = _pointer(f, pointer)
            ok = f.value(f"and i1 {f.value(f'icmp sge i64 {at}, 0')}, "
                         f"{f.value(f'icmp slt i64 {at}, {count}')}")
            for t in tables:
                assert isinstance(t, Address)
                ok = f.value(f"and i1 {ok}, {fits(f, t, count, size)}")

            def body() -> list[str]:
                last = f.value(f"sub i64 {count}, 1")
                restart = f.value(f"or i1 {f.truth(inputs[1])}, "
                                  f"{f.value(f'icmp eq i64 {at}, {last}')}")
                start = f.value(f"select i1 {restart}, i64 0, "
                                f"i64 {f.value(f'add i64 {at}, 1')}")
                wanted = "" if pair else value_of(f) if value_of else ""

                def look(k: str, values: list[str]) -> list[str]:
                    here = load(f, entry(f, second, k, size), size)
                    if pair:
                        assert isinstance(first, Address)
                        other = load(f, entry(f, first, k, size), size)
                        differs = f.value(f"icmp ne i64 {other}, {here}")
                        match = f.value(f"icmp eq i1 {differs}, {f.truth(inputs[2])}")
                    else:
                        match = f.value(f"icmp eq i64 {here}, {wanted}")
                    take = f.value(f"and i1 {match}, {f.value(f'icmp sge i64 {k}, {start}')}")
                    take = f.value(f"and i1 {take}, {f.value(f'icmp slt i64 {values[0]}, 0')}")
                    return [f.value(f"select i1 {take}, i64 {k}, i64 {values[0]}")]

                (found,) = loop(f, count, look, ["-1"])
                hit = f.value(f"icmp sge i64 {found}, 0")
                _set_pointer(f, pointer, f.value(f"select i1 {hit}, i64 {found}, i64 {last}"))
                end = f.value(f"or i1 {f.value(f'xor i1 {hit}, true')}, "
                              f"{f.value(f'icmp eq i64 {found}, {last}')}")
                return [hit, end, "false"]

            return _guarded(f, ok, ["false", "false", "true"], body)

        return work

    return prepare


def _keeper(queue: bool) -> Prepare:
    """FUN 110 QUEUE, 111 STACK (IW, table, L, Pr, OW; I/O): a push (I/O = 1) or pop of one
    entry, Pr the count; FO0 EPT, FO1 FUL, FO2 ERR (Pr outside 0 .. L, nothing done)."""

    def prepare(size: int, operands: Sequence[object], inputs: list[str]) -> Work | None:
        incoming, table, length, pointer, outgoing = operands
        value_of, count_of = _operand(incoming, size), _operand(length, 2)
        if value_of is None or count_of is None or not isinstance(table, Address) or \
                not _fits(pointer, 2) or not _fits(outgoing, size) or len(inputs) < 2:
            return None
        assert isinstance(pointer, Address) and isinstance(outgoing, Address)

        def work(f: FunctionText) -> tuple[list[str], str]:
            count = count_of(f)
            at = _pointer(f, pointer)
            ok = f.value(f"and i1 {f.value(f'icmp sge i64 {at}, 0')}, "
                         f"{f.value(f'icmp sle i64 {at}, {count}')}")
            ok = f.value(f"and i1 {ok}, {fits(f, table, count, size)}")

            def body() -> list[str]:
                pushing, popping, joined = f.label(), f.label(), f.label()
                f.add(f"br i1 {f.truth(inputs[1])}, label %{pushing}, label %{popping}")
                f.start(pushing)
                room = f.value(f"icmp slt i64 {at}, {count}")
                _, pushed = f.branch_if(room)
                if queue:
                    f.add(f"call void @llvm.memmove.p0.p0.i64(ptr {entry(f, table, '1', size)}"
                          f", ptr {f.byte_ptr(table.area, table.byte)}, "
                          f"i64 {f.value(f'mul i64 {at}, {size}')}, i1 false)")
                store(f, entry(f, table, "0" if queue else at, size), size, value_of(f))
                f.join(pushed)
                after_push = f.value(f"add i64 {at}, {f.value(f'zext i1 {room} to i64')}")
                push_end = f.block
                f.add(f"br label %{joined}")
                f.start(popping)
                some = f.value(f"icmp sgt i64 {at}, 0")
                _, popped = f.branch_if(some)
                top = f.value(f"sub i64 {at}, 1")
                value = f.value(f"load {_i(size)}, ptr {entry(f, table, top, size)}, align 1")
                _store(f, outgoing, size, value)
                f.join(popped)
                after_pop = f.value(f"sub i64 {at}, {f.value(f'zext i1 {some} to i64')}")
                pop_end = f.block
                f.add(f"br label %{joined}")
                f.start(joined)
                now = f.value(f"phi i64 [{after_push}, %{push_end}], [{after_pop}, %{pop_end}]")
                _set_pointer(f, pointer, now)
                return [f.value(f"icmp eq i64 {now}, 0"), f.value(f"icmp eq i64 {now}, {count}"),
                        "false"]

            return _guarded(f, ok, ["false", "false", "true"], body)

        return work

    return prepare


_MOST = 127  # SORT's longest table
_BUFFER = _MOST * 4


def _sort(size: int, operands: Sequence[object], inputs: list[str]) -> Work | None:
    """FUN 113 SORT (S, D, L; A/D): S's L entries (2-127) sorted up (A/D = 1) or down into D;
    S read whole first (into a buffer); FO0 ERR."""
    source, target, length = operands
    count_of = _operand(length, 2)
    if count_of is None or not isinstance(source, Address) or \
            not isinstance(target, Address) or len(inputs) < 2:
        return None

    def work(f: FunctionText) -> tuple[list[str], str]:
        count = count_of(f)
        ok = f.value(f"and i1 {fits(f, source, count, size, 2, _MOST)}, "
                     f"{fits(f, target, count, size, 2, _MOST)}")

        def body() -> list[str]:
            buffer = f.tmp()
            f.entry.append(f"{buffer} = alloca [{_BUFFER} x i8]")
            f.add(f"call void @llvm.memmove.p0.p0.i64(ptr {buffer}, "
                  f"ptr {f.byte_ptr(source.area, source.byte)}, "
                  f"i64 {f.value(f'mul i64 {count}, {size}')}, i1 false)")
            up = f.truth(inputs[1])

            def at(k: str) -> str:
                offset = f.value(f"mul i64 {k}, {size}")
                return load(f, f.value(f"getelementptr i8, ptr {buffer}, i64 {offset}"), size)

            def place(k: str, values: list[str]) -> list[str]:
                mine = at(k)

                def rank(j: str, counted: list[str]) -> list[str]:
                    theirs = at(j)
                    below = f.value(f"icmp slt i64 {theirs}, {mine}")
                    above = f.value(f"icmp sgt i64 {theirs}, {mine}")
                    before = f.value(f"select i1 {up}, i1 {below}, i1 {above}")
                    tie = f.value(f"and i1 {f.value(f'icmp eq i64 {theirs}, {mine}')}, "
                                  f"{f.value(f'icmp slt i64 {j}, {k}')}")
                    ahead = f.value(f"zext i1 {f.value(f'or i1 {before}, {tie}')} to i64")
                    return [f.value(f"add i64 {counted[0]}, {ahead}")]

                (position,) = loop(f, count, rank, ["0"])
                store(f, entry(f, target, position, size), size, mine)
                return []

            loop(f, count, place)
            return ["false"]

        return _guarded(f, ok, ["true"], body)

    return work


def _crc16(size: int, operands: Sequence[object], inputs: list[str]) -> Work | None:
    """FUN 31 CRC16 (MD, S, N, D): the Modbus CRC16 of the N (1-256) registers' low bytes,
    its high byte in D, its low byte in D + 1; FO0 D=0, FO1 ERR (MD not 0, N outside, S past
    its area: nothing written)."""
    kind, source, number, destination = operands
    count_of = _operand(number, 2)
    if not isinstance(kind, int) or not isinstance(source, Address) or count_of is None or \
            not _fits(destination, 4):
        return None
    assert isinstance(destination, Address)
    room = (_SIZES[source.area] - source.byte) // 2

    def work(f: FunctionText) -> tuple[list[str], str]:
        count = count_of(f)
        ok = f.value(f"and i1 {f.value(f'icmp sge i64 {count}, 1')}, "
                     f"{f.value(f'icmp sle i64 {count}, {min(256, room)}')}")
        if kind != 0:
            ok = "false"

        def body() -> list[str]:
            def step(k: str, values: list[str]) -> list[str]:
                byte = f.value(f"load i8, ptr {entry(f, source, k, 2)}, align 1")
                crc = f.value(f"xor i64 {values[0]}, {f.value(f'zext i8 {byte} to i64')}")
                for _ in range(8):
                    odd = f.value(f"trunc i64 {crc} to i1")
                    half = f.value(f"lshr i64 {crc}, 1")
                    crc = f.value(f"select i1 {odd}, i64 {f.value(f'xor i64 {half}, 40961')}, "
                                  f"i64 {half}")
                return [crc]

            (crc,) = loop(f, count, step, ["65535"])
            _store(f, destination, 2, f.value(f"trunc i64 {f.value(f'lshr i64 {crc}, 8')} to i16"))
            _store(f, destination.offset(2), 2,
                   f.value(f"trunc i64 {f.value(f'and i64 {crc}, 255')} to i16"))
            return [f.value(f"icmp eq i64 {crc}, 0"), "false"]

        return _guarded(f, ok, ["false", "true"], body)

    return work


_ROWS: dict[str, Prepare] = {
    "FBS.R_T_S": _search(False), "FBS.T_T_C": _search(True), "FBS.QUEUE": _keeper(True),
    "FBS.STACK": _keeper(False), "FBS.SORT": _sort, "FBS.CRC16": _crc16,
}


def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str]) -> str | None:
    """A table box's code (`fatek.box`); None: it calls back."""
    if not inputs or len(params) < 2 or not isinstance(params[0], int):
        return None
    mode = params[0]
    work = ROWS[impl](4 if mode & DOUBLE else 2, params[1:-1], inputs)
    if work is None:
        return None
    return box(b, inputs[0], mode, params[-1], True, work)


def _rows() -> dict[FunctionImpl, Prepare]:
    load_all()
    return {REGISTRY[name]: prepare for name, prepare in _ROWS.items() if name in REGISTRY}


ROWS = _rows()
STATEFUL = {impl: ("fatek box", emit) for impl in ROWS}
