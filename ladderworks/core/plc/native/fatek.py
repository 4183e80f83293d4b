"""Fatek FBs data boxes as native code (core/plc/functions/fatek_data.py): FUN 8 MOV, 11-14
(+ - x /), 15-16 (+1 -1), 17 CMP, each in its forms (`mode`: bit 0 the P form, run on EN's 0 -> 1;
bit 1 the D form, 32-bit). The call site's "en" and "fo0" are bits of its state block; a box
that does not run keeps its destination and FO, W1 = the last FO0. FUN 170-175 in series
(IN and Sa op Sb) have no state."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.fatek_data import DOUBLE, PULSE
from ladderworks.core.plc.native.builtins import Emitter, _fits, _load, _store
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import EN, FO0, HAS_EN, HAS_FO0, Block

_I32 = (-(1 << 31), (1 << 31) - 1)
# a box's work: (f, size) -> the FO bits (i1 each; none: MOV, no FO0 kept)
Work = Callable[[FunctionText], list[str]]


def _operand(value: object, size: int) -> Callable[[FunctionText], str] | None:
    """`operand_value` as an i64: a 32-bit constant, or `size` signed bytes at an address."""
    if isinstance(value, Address):
        if not _fits(value, size):
            return None
        return lambda f: f.value(f"sext i{8 * size} {_load(f, value, size)} to i64")
    if isinstance(value, int) and not isinstance(value, bool) and _I32[0] <= value <= _I32[1]:
        return lambda f: str(value)
    return None


def _wrapped(f: FunctionText, exact: str, size: int) -> str:
    return f.value(f"sext i{8 * size} {f.value(f'trunc i64 {exact} to i{8 * size}')} to i64")


def _store64(f: FunctionText, at: Address, value: str, size: int) -> None:
    _store(f, at, size, f.value(f"trunc i64 {value} to i{8 * size}") if size < 8 else value)


def _move(size: int, params: Sequence[object]) -> Work | None:
    source, destination = params
    read = _operand(source, size)
    if read is None or not (isinstance(destination, Address) and _fits(destination, size)):
        return None

    def work(f: FunctionText) -> list[str]:
        _store64(f, destination, read(f), size)
        return []

    return work


def _arithmetic(fun: int) -> Callable[[int, Sequence[object]], Work | None]:
    def prepare(size: int, params: Sequence[object]) -> Work | None:
        sa, sb, destination = params
        a_of, b_of = _operand(sa, size), _operand(sb, size)
        room = 2 * size if fun in (13, 14) else size
        if a_of is None or b_of is None or not (isinstance(destination, Address)
                                                and _fits(destination, room)):
            return None

        def work(f: FunctionText) -> list[str]:
            a, b = a_of(f), b_of(f)
            if fun == 13:
                product = f.value(f"mul i64 {a}, {b}")
                _store64(f, destination, product, 2 * size)
                return [f.value(f"icmp eq i64 {product}, 0")]
            if fun == 14:
                zero = f.value(f"icmp eq i64 {b}, 0")
                divide, done = f.label(), f.label()
                start = f.block
                f.add(f"br i1 {zero}, label %{done}, label %{divide}")
                f.start(divide)
                quotient = f.value(f"sdiv i64 {a}, {b}")
                _store64(f, destination, quotient, size)
                _store64(f, destination.offset(size), f.value(f"srem i64 {a}, {b}"), size)
                is_zero = f.value(f"icmp eq i64 {quotient}, 0")
                end = f.block
                f.add(f"br label %{done}")
                f.start(done)
                return [f.value(f"phi i1 [false, %{start}], [{is_zero}, %{end}]"),
                        f.value(f"phi i1 [true, %{start}], [false, %{end}]")]
            exact = f.value(f"{'add' if fun == 11 else 'sub'} i64 {a}, {b}")
            value = _wrapped(f, exact, size)
            _store64(f, destination, value, size)
            return [f.value(f"icmp eq i64 {value}, 0"), f.value(f"icmp sgt i64 {exact}, {value}"),
                    f.value(f"icmp slt i64 {exact}, {value}")]

        return work

    return prepare


def _step(amount: int) -> Callable[[int, Sequence[object]], Work | None]:
    def prepare(size: int, params: Sequence[object]) -> Work | None:
        (destination,) = params
        if not (isinstance(destination, Address) and _fits(destination, size)):
            return None

        def work(f: FunctionText) -> list[str]:
            read = f.value(f"sext i{8 * size} {_load(f, destination, size)} to i64")
            exact = f.value(f"add i64 {read}, {amount}")
            value = _wrapped(f, exact, size)
            _store64(f, destination, value, size)
            return [f.value(f"icmp ne i64 {value}, {exact}")]

        return work

    return prepare


def _compare(size: int, params: Sequence[object]) -> Work | None:
    """FUN 17 CMP: FO0 Sa = Sb, FO1 Sa > Sb, FO2 Sa < Sb."""
    sa, sb = params
    a_of, b_of = _operand(sa, size), _operand(sb, size)
    if a_of is None or b_of is None:
        return None

    def work(f: FunctionText) -> list[str]:
        a, b = a_of(f), b_of(f)
        return [f.value(f"icmp {test} i64 {a}, {b}") for test in ("eq", "sgt", "slt")]

    return work


def _contact(predicate: str) -> Emitter:
    """FUN 170-175 in series: IN and Sa op Sb (no state)."""

    def emit(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
        if len(params) != 3 or not inputs or not isinstance(params[0], int):
            return None
        size = 4 if params[0] & DOUBLE else 2
        a_of, b_of = _operand(params[1], size), _operand(params[2], size)
        if a_of is None or b_of is None:
            return None
        holds = f.value(f"icmp {predicate} i64 {a_of(f)}, {b_of(f)}")
        return f.value(f"and i8 {inputs[0]}, {f.value(f'zext i1 {holds} to i8')}")

    return emit


_CONTACTS = {"FBS.EQ": "eq", "FBS.GT": "sgt", "FBS.LT": "slt", "FBS.NE": "ne",
             "FBS.GE": "sge", "FBS.LE": "sle"}
_ROWS: dict[str, Callable[[int, Sequence[object]], Work | None]] = {
    "FBS.CMP": _compare,
    "FBS.MOV": _move, "FBS.ADD": _arithmetic(11), "FBS.SUB": _arithmetic(12),
    "FBS.MUL": _arithmetic(13), "FBS.DIV": _arithmetic(14), "FBS.INC": _step(1),
    "FBS.DEC": _step(-1),
}


def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str]) -> str | None:
    """The box's code: `runs` (EN, its P form), the work, FO written and FO0 kept."""
    prepare = BOXES[impl]
    if not inputs or not params or not isinstance(params[0], int):
        return None
    mode = params[0]
    has_fo = prepare is not _move
    fo = params[-1] if has_fo else None
    work = prepare(4 if mode & DOUBLE else 2, params[1:-1] if has_fo else params[1:])
    if work is None:
        return None
    return box(b, inputs[0], mode, fo, has_fo, lambda f: (work(f), "true"))


# a box's work as `box` runs it: (the FO bits, i1 each; an i1: they are written and FO0
# kept, else FO and FO0 stay as they were)
Outputs = Callable[[FunctionText], tuple[list[str], str]]


def box(b: Block, enable: str, mode: int, fo: object, has_fo: bool,
        work: Outputs, also: str = "false") -> str | None:
    """A box that runs while EN (`enable`, i8) is 1, or on its 0 -> 1 in the P form (its "en"
    in the block), or while `also` (i1: a pointer move's CLR) holds; `work` its code when it
    runs. A box with FO (`has_fo`) writes its FO byte (`fo`, or None) and keeps FO0 ("fo0",
    its W1 then); one without has W1 0."""
    if has_fo and fo is not None and not (isinstance(fo, Address) and _fits(fo, 1)):
        return None
    f = b.f
    flags = b.flags()
    enabled_now = f.truth(enable)
    was = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {EN}')}, 0")
    run = f.value(f"and i1 {enabled_now}, {f.value(f'xor i1 {was}, true')}") if mode & PULSE \
        else enabled_now
    enabled = f.value(f"or i32 {f.value(f'and i32 {flags}, {~EN}')}, {HAS_EN}")
    enabled = f.value(f"select i1 {enabled_now}, i32 {f.value(f'or i32 {enabled}, {EN}')}, "
                      f"i32 {enabled}")
    if also != "false":
        run = f.value(f"or i1 {run}, {also}")
    start = f.block
    body, done = f.label(), f.label()
    f.add(f"br i1 {run}, label %{body}, label %{done}")
    f.start(body)
    bits, written = work(f)
    ran = enabled
    if has_fo:
        fo0 = bits[0]
        if isinstance(fo, Address):
            byte = "0"
            for n, bit in enumerate(bits):
                wide = f.value(f"zext i1 {bit} to i8")
                byte = f.value(f"or i8 {byte}, {f.value(f'shl i8 {wide}, {n}')}")
            if written == "true":
                _store(f, fo, 1, byte)
            else:
                _, after = f.branch_if(written)
                _store(f, fo, 1, byte)
                f.join(after)
        kept = f.value(f"or i32 {f.value(f'and i32 {enabled}, {~FO0}')}, {HAS_FO0}")
        ran = f.value(f"select i1 {fo0}, i32 {f.value(f'or i32 {kept}, {FO0}')}, i32 {kept}")
        if written != "true":
            ran = f.value(f"select i1 {written}, i32 {ran}, i32 {enabled}")
    end = f.block
    f.add(f"br label %{done}")
    f.start(done)
    new = f.value(f"phi i32 [{enabled}, %{start}], [{ran}, %{end}]")
    b.set_flags(flags, new)
    if not has_fo:
        return "0"
    held = f.value(f"and i32 {new}, {FO0}")
    return f.value(f"zext i1 {f.value(f'icmp ne i32 {held}, 0')} to i8")


def _boxes() -> dict[FunctionImpl, Callable[[int, Sequence[object]], Work | None]]:
    load_all()
    return {REGISTRY[name]: prepare for name, prepare in _ROWS.items() if name in REGISTRY}


BOXES = _boxes()
EMITTERS: dict[FunctionImpl, Emitter] = {REGISTRY[name]: _contact(predicate)
                                        for name, predicate in _CONTACTS.items()
                                        if name in REGISTRY}
