"""Fatek FBs table boxes as native code (core/plc/functions/fatek_tables.py,
fatek_table_ops.py): SUM, MEAN, BT_M, T_SWP, T_FIL, T_SHF, T_ROT, BKCMP and the pointer moves
R→T, T→R, T→T. L is read when the box runs, so a table's fit in its area is tested then
(`fits`), its entries reached by index and loops; each runs in `fatek.box`."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.dialects import memory_sizes
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.fatek_data import DOUBLE
from ladderworks.core.plc.functions.fatek_tables import MAX_LENGTH
from ladderworks.core.plc.native.fatek import Outputs, _operand, box
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import Block, _fits, _load, _store

_SIZES = memory_sizes()
Read = Callable[[FunctionText], str]
Work = Outputs  # a box's code: its FO bits, and whether they are written


def _i(size: int) -> str:
    return f"i{8 * size}"


def fits(f: FunctionText, table: Address, count: str, size: int, low: int = 2,
         high: int = MAX_LENGTH) -> str:
    """`fatek_tables.fits` (i1): low <= L <= high and the L entries inside the area."""
    room = (_SIZES[table.area] - table.byte) // size
    top = min(high, room)
    return f.value(f"and i1 {f.value(f'icmp sge i64 {count}, {low}')}, "
                   f"{f.value(f'icmp sle i64 {count}, {top}')}")


def entry(f: FunctionText, table: Address, index: str, size: int) -> str:
    """The pointer to entry `index` (i64) of a table."""
    offset = f.value(f"mul i64 {index}, {size}")
    return f.value(f"getelementptr i8, ptr {f.byte_ptr(table.area, table.byte)}, i64 {offset}")


def load(f: FunctionText, pointer: str, size: int) -> str:
    """The signed entry at `pointer`, as i64."""
    return f.value(f"sext {_i(size)} {f.value(f'load {_i(size)}, ptr {pointer}, align 1')} "
                   f"to i64")


def store(f: FunctionText, pointer: str, size: int, value: str) -> None:
    """An i64 stored wrapped to `size` bytes."""
    f.add(f"store {_i(size)} {f.value(f'trunc i64 {value} to {_i(size)}')}, ptr {pointer}, "
          f"align 1")


def loop(f: FunctionText, stop: str, body: Callable[[str, list[str]], list[str]],
         carried: Sequence[str] = ()) -> list[str]:
    """for k in range(stop) (i64): `body(k, values)` gives the carried i64 values' next ones
    (`carried` their first); their values after the loop."""
    before = f.block
    head, run, latch, done = f.label(), f.label(), f.label(), f.label()
    k, k_next = f.tmp(), f.tmp()
    names = [f.tmp() for _ in carried]
    nexts = [f.tmp() for _ in carried]
    f.add(f"br label %{head}")
    f.start(head)
    f.add(f"{k} = phi i64 [0, %{before}], [{k_next}, %{latch}]")
    for first, name, after in zip(carried, names, nexts, strict=True):
        f.add(f"{name} = phi i64 [{first}, %{before}], [{after}, %{latch}]")
    f.add(f"br i1 {f.value(f'icmp slt i64 {k}, {stop}')}, label %{run}, label %{done}")
    f.start(run)
    results = body(k, names)
    f.add(f"br label %{latch}")
    f.start(latch)
    f.add(f"{k_next} = add i64 {k}, 1")
    for after, result in zip(nexts, results, strict=True):
        f.add(f"{after} = add i64 {result}, 0")
    f.add(f"br label %{head}")
    f.start(done)
    return names


def _checked(f: FunctionText, ok: str, body: Callable[[], None]) -> tuple[list[str], str]:
    """`body` when `ok` (the tables fit), FO0 ERR its inverse."""
    _, after = f.branch_if(ok)
    body()
    f.join(after)
    return [f.value(f"xor i1 {ok}, true")], "true"


def _table(operand: object) -> Address | None:
    return operand if isinstance(operand, Address) else None


def _sum(mean: bool) -> Callable[[int, Sequence[object]], Work | None]:
    """FUN 24 SUM, 25 MEAN (Ts, L, D): D := the sum (the mean, truncated toward 0)."""

    def prepare(size: int, operands: Sequence[object]) -> Work | None:
        table, length, destination = operands
        ts, count_of = _table(table), _operand(length, 2)
        if ts is None or count_of is None or not _fits(destination, size):
            return None
        assert isinstance(destination, Address)

        def work(f: FunctionText) -> tuple[list[str], str]:
            count = count_of(f)

            def body() -> None:
                (total,) = loop(f, count, lambda k, values: [
                    f.value(f"add i64 {values[0]}, {load(f, entry(f, ts, k, size), size)}")],
                                ["0"])
                value = f.value(f"sdiv i64 {total}, {count}") if mean else total
                _store(f, destination, size, f.value(f"trunc i64 {value} to {_i(size)}"))

            return _checked(f, fits(f, ts, count, size, 1), body)

        return work

    return prepare


def _block_move(size: int, operands: Sequence[object]) -> Work | None:
    """FUN 103 BT_M (Ts, Td, L): the L entries copied as read before any is written."""
    source, target, length = operands
    ts, td, count_of = _table(source), _table(target), _operand(length, 2)
    if ts is None or td is None or count_of is None:
        return None

    def work(f: FunctionText) -> tuple[list[str], str]:
        count = count_of(f)
        ok = f.value(f"and i1 {fits(f, ts, count, size)}, {fits(f, td, count, size)}")

        def body() -> None:
            f.add(f"call void @llvm.memmove.p0.p0.i64(ptr {f.byte_ptr(td.area, td.byte)}, "
                  f"ptr {f.byte_ptr(ts.area, ts.byte)}, "
                  f"i64 {f.value(f'mul i64 {count}, {size}')}, i1 false)")

        return _checked(f, ok, body)

    return work


def _apart(a: Address, b: Address, size: int) -> bool:
    """Two tables of up to MAX_LENGTH entries that cannot overlap."""
    span = MAX_LENGTH * size
    return a.area is not b.area or a.byte + span <= b.byte or b.byte + span <= a.byte


def _table_swap(size: int, operands: Sequence[object]) -> Work | None:
    """FUN 104 T_SWP (Ta, Tb, L): the entries exchanged; tables that may overlap are read
    whole first (into two buffers) and written entry by entry, Ta's before Tb's, as the Python
    code does."""
    first, second, length = operands
    ta, tb, count_of = _table(first), _table(second), _operand(length, 2)
    if ta is None or tb is None or count_of is None:
        return None
    apart = _apart(ta, tb, size)

    def work(f: FunctionText) -> tuple[list[str], str]:
        count = count_of(f)
        ok = f.value(f"and i1 {fits(f, ta, count, size)}, {fits(f, tb, count, size)}")
        buffers: list[str] = []

        def swap(k: str, values: list[str]) -> list[str]:
            at_a, at_b = entry(f, ta, k, size), entry(f, tb, k, size)
            if buffers:
                offset = f.value(f"mul i64 {k}, {size}")
                from_a, from_b = (f.value(f"getelementptr i8, ptr {buffer}, i64 {offset}")
                                  for buffer in buffers)
            else:
                from_a, from_b = at_a, at_b
            a = f.value(f"load {_i(size)}, ptr {from_a}, align 1")
            b = f.value(f"load {_i(size)}, ptr {from_b}, align 1")
            f.add(f"store {_i(size)} {b}, ptr {at_a}, align 1")
            f.add(f"store {_i(size)} {a}, ptr {at_b}, align 1")
            return []

        def body() -> None:
            if not apart:
                total = f.value(f"mul i64 {count}, {size}")
                for table in (ta, tb):
                    buffer = f.tmp()
                    f.entry.append(f"{buffer} = alloca [{MAX_LENGTH * 4} x i8]")
                    f.add(f"call void @llvm.memmove.p0.p0.i64(ptr {buffer}, "
                          f"ptr {f.byte_ptr(table.area, table.byte)}, i64 {total}, i1 false)")
                    buffers.append(buffer)
            loop(f, count, swap)

        return _checked(f, ok, body)

    return work


def _table_fill(size: int, operands: Sequence[object]) -> Work | None:
    """FUN 107 T_FIL (S, Td, L): every entry := S (read once)."""
    source, target, length = operands
    value_of, td, count_of = _operand(source, size), _table(target), _operand(length, 2)
    if value_of is None or td is None or count_of is None:
        return None

    def work(f: FunctionText) -> tuple[list[str], str]:
        count = count_of(f)

        def body() -> None:
            value = value_of(f)

            def fill(k: str, values: list[str]) -> list[str]:
                store(f, entry(f, td, k, size), size, value)
                return []

            loop(f, count, fill)

        return _checked(f, fits(f, td, count, size), body)

    return work


def _moving(shift: bool) -> Callable[[int, Sequence[object], list[str]], Work | None]:
    """FUN 108 T_SHF (IW, Ts, L, OW), 109 T_ROT (Ts, L): the table moved one entry toward
    its end (L/R = 1) or its start; the entry out to OW (T_SHF, IW coming in) or in at the
    other end (T_ROT)."""

    def prepare(size: int, operands: Sequence[object], inputs: list[str]) -> Work | None:
        fill_of: Read | None = None
        if shift:
            incoming, table, length, outgoing = operands
            fill_of = _operand(incoming, size)
            if fill_of is None or not _fits(outgoing, size):
                return None
        else:
            table, length = operands
        ts, count_of = _table(table), _operand(length, 2)
        if ts is None or count_of is None:
            return None

        def work(f: FunctionText) -> tuple[list[str], str]:
            count = count_of(f)
            left = f.truth(inputs[1]) if len(inputs) > 1 else "false"

            def body() -> None:
                last = f.value(f"sub i64 {count}, 1")
                out_at = f.value(f"select i1 {left}, i64 {last}, i64 0")
                out = f.value(f"load {_i(size)}, ptr {entry(f, ts, out_at, size)}, align 1")
                fill = f.value(f"trunc i64 {fill_of(f)} to {_i(size)}") if fill_of else out
                one = entry(f, ts, "1", size)
                start = f.byte_ptr(ts.area, ts.byte)
                target = f.value(f"select i1 {left}, ptr {one}, ptr {start}")
                source = f.value(f"select i1 {left}, ptr {start}, ptr {one}")
                f.add(f"call void @llvm.memmove.p0.p0.i64(ptr {target}, ptr {source}, "
                      f"i64 {f.value(f'mul i64 {last}, {size}')}, i1 false)")
                in_at = f.value(f"select i1 {left}, i64 0, i64 {last}")
                f.add(f"store {_i(size)} {fill}, ptr {entry(f, ts, in_at, size)}, align 1")
                if shift:
                    assert isinstance(outgoing, Address)
                    _store(f, outgoing, size, out)

            return _checked(f, fits(f, ts, count, size), body)

        return work

    return prepare


def _bkcmp(size: int, operands: Sequence[object]) -> Work | None:
    """FUN 112 BKCMP (Rs, Ts, L, D): bit k of the registers from D := Ts[2k] <= Rs <=
    Ts[2k + 1] for the L (1-128) zones; ERR: nothing written."""
    reference, table, length, target = operands
    value_of, ts, count_of, d = (_operand(reference, size), _table(table),
                                 _operand(length, 2), _table(target))
    if value_of is None or ts is None or count_of is None or d is None:
        return None
    words = (128 + 15) // 16

    def work(f: FunctionText) -> tuple[list[str], str]:
        count = count_of(f)
        registers = f.value(f"sdiv i64 {f.value(f'add i64 {count}, 15')}, 16")
        ok = f.value(f"and i1 {f.value(f'icmp sle i64 {count}, 128')}, "
                     f"{fits(f, ts, f.value(f'mul i64 {count}, 2'), size)}")
        ok = f.value(f"and i1 {ok}, {fits(f, d, registers, 2, 1)}")

        def zone(k: str, values: list[str]) -> list[str]:
            lower = load(f, entry(f, ts, f.value(f"mul i64 {k}, 2"), size), size)
            upper = load(f, entry(f, ts, f.value(f"add i64 {f.value(f'mul i64 {k}, 2')}, 1"),
                                  size), size)
            inside = f.value(f"and i1 {f.value(f'icmp sle i64 {lower}, {value}')}, "
                             f"{f.value(f'icmp sle i64 {value}, {upper}')}")
            bit = f.value(f"shl i64 {f.value(f'zext i1 {inside} to i64')}, "
                          f"{f.value(f'and i64 {k}, 15')}")
            word = f.value(f"lshr i64 {k}, 4")
            nexts = []
            for j in range(words):
                here = f.value(f"icmp eq i64 {word}, {j}")
                nexts.append(f.value(f"or i64 {values[j]}, "
                                     f"{f.value(f'select i1 {here}, i64 {bit}, i64 0')}"))
            return nexts

        value = ""

        def body() -> None:
            nonlocal value
            value = value_of(f)
            found = loop(f, count, zone, ["0"] * words)
            for j in range(words):
                _, after = f.branch_if(f.value(f"icmp sgt i64 {registers}, {j}"))
                store(f, entry(f, d, str(j), 2), 2, found[j])
                f.join(after)

        return _checked(f, ok, body)

    return work


def _pointer_move(kind: str) -> Callable[[int, Sequence[object], list[str]], Work | None]:
    """FUN 100 R→T (Rs, Td, L, Pr), 101 T→R (Ts, L, Pr, Rd), 102 T→T (Ts, Td, L, Pr); inputs
    EN, PIN, CLR: CLR = 1 sets Pr 0 (FO 0); else Td[Pr] := Rs, Rd := Ts[Pr] or Td[Pr] :=
    Ts[Pr], PIN moving Pr on up to L - 1; FO0 PEND Pr = L - 1, FO1 ERR (nothing moved)."""

    def prepare(size: int, operands: Sequence[object], inputs: list[str]) -> Work | None:
        if kind == "R->T":
            source, table, length, pointer = operands
            tables = [_table(table)]
        elif kind == "T->R":
            table, length, pointer, source = operands
            tables = [_table(table)]
        else:
            source, table, length, pointer = operands
            tables = [_table(source), _table(table)]
        count_of = _operand(length, 2)
        value_of = _operand(source, size) if kind == "R->T" else None
        if count_of is None or any(t is None for t in tables) or not _fits(pointer, 2) \
                or (kind == "R->T" and value_of is None) \
                or (kind == "T->R" and not _fits(source, size)) or len(inputs) < 3:
            return None
        assert isinstance(pointer, Address)
        td = _table(table)
        assert td is not None

        def work(f: FunctionText) -> tuple[list[str], str]:
            clearing, moving, done = f.label(), f.label(), f.label()
            f.add(f"br i1 {f.truth(inputs[2])}, label %{clearing}, label %{moving}")
            f.start(clearing)
            _store(f, pointer, 2, "0")
            f.add(f"br label %{done}")
            f.start(moving)
            count = count_of(f)
            at = f.value(f"sext i16 {_load(f, pointer, 2)} to i64")
            ok = f.value(f"and i1 {f.value(f'icmp sge i64 {at}, 0')}, "
                         f"{f.value(f'icmp slt i64 {at}, {count}')}")
            for t in tables:
                assert t is not None
                ok = f.value(f"and i1 {ok}, {fits(f, t, count, size)}")
            checked = f.block
            _, after = f.branch_if(ok)
            target = entry(f, td, at, size)
            if kind == "R->T":
                assert value_of is not None
                store(f, target, size, value_of(f))
            elif kind == "T->R":
                assert isinstance(source, Address)
                value = f.value(f"load {_i(size)}, ptr {target}, align 1")
                _store(f, source, size, value)
            else:
                from_table = _table(source)
                assert from_table is not None
                value = f.value(f"load {_i(size)}, ptr {entry(f, from_table, at, size)}, "
                                f"align 1")
                f.add(f"store {_i(size)} {value}, ptr {target}, align 1")
            last = f.value(f"sub i64 {count}, 1")
            under = f.value(f"icmp slt i64 {at}, {last}")
            step = f.value(f"and i1 {f.truth(inputs[1])}, {under}")
            moved = f.value(f"trunc i64 {f.value(f'add i64 {at}, 1')} to i16")
            _store(f, pointer, 2, f.value(f"select i1 {step}, i16 {moved}, "
                                          f"i16 {_load(f, pointer, 2)}"))
            pend = f.value(f"icmp eq i64 {at}, {last}")
            body_end = f.block
            f.join(after)
            pend = f.value(f"phi i1 [false, %{checked}], [{pend}, %{body_end}]")
            error = f.value(f"xor i1 {ok}, true")
            moving_end = f.block
            f.add(f"br label %{done}")
            f.start(done)
            return [f.value(f"phi i1 [false, %{clearing}], [{pend}, %{moving_end}]"),
                    f.value(f"phi i1 [false, %{clearing}], [{error}, %{moving_end}]")], "true"

        return work

    return prepare


# the rows: (has FO, prepare(size, operands without FO, inputs))
Prepare = Callable[[int, Sequence[object], list[str]], Work | None]


def _plain(prepare: Callable[[int, Sequence[object]], Work | None]) -> Prepare:
    return lambda size, operands, inputs: prepare(size, operands)


_ROWS: dict[str, Prepare] = {
    "FBS.SUM": _plain(_sum(False)), "FBS.MEAN": _plain(_sum(True)),
    "FBS.BT_M": _plain(_block_move), "FBS.T_SWP": _plain(_table_swap),
    "FBS.T_FIL": _plain(_table_fill), "FBS.T_SHF": _moving(True), "FBS.T_ROT": _moving(False),
    "FBS.BKCMP": _plain(_bkcmp), "FBS.R_T": _pointer_move("R->T"),
    "FBS.T_R": _pointer_move("T->R"), "FBS.T_T": _pointer_move("T->T"),
}
_CLEARED = ("FBS.R_T", "FBS.T_R", "FBS.T_T")  # CLR (the third input) runs them too


def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str]) -> str | None:
    """A table box's code (`fatek.box`); None: it calls back."""
    if not inputs or len(params) < 2 or not isinstance(params[0], int):
        return None
    mode = params[0]
    prepare, cleared = ROWS[impl]
    work = prepare(4 if mode & DOUBLE else 2, params[1:-1], inputs)
    if work is None or (cleared and len(inputs) < 3):
        return None
    also = b.f.truth(inputs[2]) if cleared else "false"
    return box(b, inputs[0], mode, params[-1], True, work, also)


def _rows() -> dict[FunctionImpl, tuple[Prepare, bool]]:
    load_all()
    return {REGISTRY[name]: (prepare, name in _CLEARED) for name, prepare in _ROWS.items()
            if name in REGISTRY}


ROWS = _rows()
STATEFUL = {impl: ("fatek box", emit) for impl in ROWS}
