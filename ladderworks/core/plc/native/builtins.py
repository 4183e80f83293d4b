"""Functional instructions as native code, keyed by their Python implementation (the others
call back into it). Each does exactly what its implementation in core/plc/functions/ does,
with the parameters known when the IR is made; where a parameter makes the Python code do
something unusual (an address whose data runs past its area, a width it does not know) the
op calls back instead. Values of 2 and 4 bytes are loaded and stored as little-endian
integers (the machine's order: `unavailable()` refuses a big-endian one).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.dialects import memory_sizes
from ladderworks.core.instructions import InstructionSpec
from ladderworks.core.plc.functions import (
    FLAG_NEGATIVE,
    FLAG_ZERO,
    RESULT_REGISTER,
    FunctionImpl,
    cnc,
    compare,
    decode,
    edges,
    logic,
    transfer,
)
from ladderworks.core.plc.functions import arithmetic as _arithmetic
from ladderworks.core.plc.native import layout
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.layout import Layout

_SIZES = memory_sizes()
_I64 = (-(1 << 63), (1 << 63) - 1)

Emitter = Callable[[FunctionText, Sequence[object], list[str]], str | None]
_LIBM = ("sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "exp", "log")


def declarations() -> list[str]:
    """The IR declarations the native functions use."""
    return ["declare void @llvm.memmove.p0.p0.i64(ptr, ptr, i64, i1)",
            *(f"declare i{n} @llvm.bswap.i{n}(i{n})" for n in (16, 32, 64)),  # S7's values
            "declare double @llvm.sqrt.f64(double)",  # Delta's DESQR
            "declare double @llvm.fabs.f64(double)", "declare double @pow(double, double)",
            *(f"declare double @{n}(double)" for n in _LIBM)]  # Delta's float functions


def _fits(address: object, width: int) -> bool:
    return isinstance(address, Address) and width > 0 and \
        address.byte + width <= _SIZES[address.area]


def _load(f: FunctionText, address: Address, width: int) -> str:
    return f.value(f"load i{8 * width}, ptr {f.byte_ptr(address.area, address.byte)}, align 1")


def _store(f: FunctionText, address: Address, width: int, value: str) -> None:
    f.add(f"store i{8 * width} {value}, ptr {f.byte_ptr(address.area, address.byte)}, align 1")


def _when(f: FunctionText, act: str, body: Callable[[], None]) -> None:
    """`body`'s code runs only when `act` (i8) is 1."""
    _, after = f.branch(act)
    body()
    f.join(after)


def _copy(width_of: Callable[[Sequence[object]], object], source_at: int,
          target_at: int) -> Emitter:
    """MOVB/MOVW/MOVN/MOVD: copy while ACT = 1, nothing when either side runs past its area."""

    def emit(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
        width = width_of(params)
        source, target = params[source_at], params[target_at]
        if not isinstance(width, int):
            return None
        if not (_fits(source, width) and _fits(target, width)):
            return "0"
        assert isinstance(source, Address) and isinstance(target, Address)

        def body() -> None:
            if width in (1, 2, 4, 8):
                _store(f, target, width, _load(f, source, width))
            else:
                f.add(f"call void @llvm.memmove.p0.p0.i64(ptr "
                      f"{f.byte_ptr(target.area, target.byte)}, ptr "
                      f"{f.byte_ptr(source.area, source.byte)}, i64 {width}, i1 false)")

        _when(f, inputs[-1], body)
        return "0"

    return emit


def _numeb(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    width, constant, target = params
    if not (isinstance(width, int) and isinstance(constant, int) and width in (1, 2, 4, 8)):
        return None
    if not -(1 << (8 * width - 1)) <= constant < 1 << (8 * width):
        return "0"  # out of the width's range: nothing written
    if not _fits(target, width):
        return None
    assert isinstance(target, Address)
    raw = constant & ((1 << (8 * width)) - 1)
    _when(f, inputs[-1], lambda: _store(f, target, width, str(_signed(raw, width))))
    return "0"


def _signed(raw: int, width: int) -> int:
    """The IR constant of `raw` in `width` bytes (LLVM prints integers signed)."""
    half = 1 << (8 * width - 1)
    return raw - (half << 1) if raw >= half else raw


def _compb(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    fmt, value, other = params
    if not isinstance(fmt, int):
        return None
    width = fmt % 10
    if width not in (1, 2, 4) or not _fits(other, width) or not _fits(RESULT_REGISTER, 1):
        return None
    if not isinstance(value, Address) and not (isinstance(value, int)
                                               and _I64[0] <= value <= _I64[1]):
        return None
    if isinstance(value, Address) and not _fits(value, width):
        return None
    assert isinstance(other, Address)

    def body() -> None:
        if isinstance(value, Address):
            first = f.value(f"sext i{8 * width} {_load(f, value, width)} to i64")
        else:
            first = str(value)
        second = f.value(f"sext i{8 * width} {_load(f, other, width)} to i64")
        equal = f.value(f"zext i1 {f.value(f'icmp eq i64 {first}, {second}')} to i8")
        less = f.value(f"zext i1 {f.value(f'icmp slt i64 {first}, {second}')} to i8")
        flags = f.value(f"or i8 {f.value(f'mul i8 {equal}, {FLAG_ZERO}')}, "
                        f"{f.value(f'mul i8 {less}, {FLAG_NEGATIVE}')}")
        _store(f, RESULT_REGISTER, 1, flags)

    _when(f, inputs[-1], body)
    return "0"


def _logic(operator: str) -> Emitter:
    """LOGAND/LOGOR/EOR: out = in op operand (a constant wrapped to the width, or an address)."""

    def emit(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
        fmt, source, value, target = params
        if not (isinstance(source, Address) and isinstance(target, Address)):
            return None
        width = logic._width(fmt) if isinstance(fmt, int) else None
        if width is None or not (_fits(source, width) and _fits(target, width)):
            return "0"
        if isinstance(value, Address) and not _fits(value, width):
            return "0"
        if not isinstance(value, Address | int):
            return None
        assert isinstance(source, Address) and isinstance(target, Address)

        def body() -> None:
            if isinstance(value, Address):
                operand = _load(f, value, width)
            else:
                operand = str(_signed(value & ((1 << (8 * width)) - 1), width))
            result = f.value(f"{operator} i{8 * width} {_load(f, source, width)}, {operand}")
            _store(f, target, width, result)

        _when(f, inputs[-1], body)
        return "0"

    return emit


def _not(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    fmt, source, target = params
    width = fmt if fmt in logic.WIDTHS else None
    if not isinstance(width, int) or not (_fits(source, width) and _fits(target, width)):
        return "0"
    assert isinstance(source, Address) and isinstance(target, Address)
    _when(f, inputs[-1], lambda: _store(
        f, target, width, f.value(f"xor i{8 * width} {_load(f, source, width)}, -1")))
    return "0"


def _move(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    high, low, source, target = params
    if not (isinstance(high, int) and isinstance(low, int) and _fits(source, 1)
            and _fits(target, 1)):
        return None
    assert isinstance(source, Address) and isinstance(target, Address)
    mask = _signed(((high << 4) | low) & 0xFF, 1)
    _when(f, inputs[-1], lambda: _store(
        f, target, 1, f.value(f"and i8 {_load(f, source, 1)}, {mask}")))
    return "0"


def _movor(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    source, other, target = params
    if not (_fits(source, 1) and _fits(other, 1) and _fits(target, 1)):
        return None
    assert isinstance(source, Address) and isinstance(other, Address)
    assert isinstance(target, Address)
    _when(f, inputs[-1], lambda: _store(
        f, target, 1, f.value(f"or i8 {_load(f, source, 1)}, {_load(f, other, 1)}")))
    return "0"


def _range(width: int) -> Emitter:
    """RNGB/RNGW/RNGD: W1 = ACT and the input between the limits (either order)."""

    def emit(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
        values: list[str] = []
        for param in params:
            if isinstance(param, Address):
                if not _fits(param, width):
                    return None
                values.append(f.value(f"sext i{8 * width} {_load(f, param, width)} to i64"))
            elif isinstance(param, int):  # wrapped to the width (65535 in 2 bytes is -1)
                values.append(str(_signed(param & ((1 << (8 * width)) - 1), width)))
            else:
                return None
        if len(values) != 3:
            return None
        first, second, data = values
        low = f.value(f"select i1 {f.value(f'icmp slt i64 {first}, {second}')}, "
                      f"i64 {first}, i64 {second}")
        high = f.value(f"select i1 {f.value(f'icmp slt i64 {first}, {second}')}, "
                       f"i64 {second}, i64 {first}")
        inside = f.value(f"and i1 {f.value(f'icmp sle i64 {low}, {data}')}, "
                         f"{f.value(f'icmp sle i64 {data}, {high}')}")
        return f.value(f"and i8 {inputs[-1]}, {f.value(f'zext i1 {inside} to i8')}")

    return emit


def _decb(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """DECB: result bit i = (code = first + i); ACT = 0 clears the result byte."""
    width, code, first, result = params
    if not (isinstance(width, int) and width in (1, 2, 4) and isinstance(first, int)
            and _I64[0] <= first <= _I64[1] and _fits(code, width) and _fits(result, 1)):
        return None
    assert isinstance(code, Address) and isinstance(result, Address)
    value = f.value(f"zext i{8 * width} {_load(f, code, width)} to i64")
    offset = f.value(f"sub i64 {value}, {first}")
    inside = f.value(f"icmp ult i64 {offset}, 8")  # 0 <= offset < 8
    bit = f.value(f"trunc i64 {f.value(f'shl i64 1, {offset}')} to i8")
    decoded = f.value(f"select i1 {inside}, i8 {bit}, i8 0")
    _store(f, result, 1, f.value(f"select i1 {f.truth(inputs[-1])}, i8 {decoded}, i8 0"))
    return "0"


def _axctl(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """AXCTL without a CNC: W1 = ACT and not RST."""
    if len(inputs) != 2:
        return None
    return f.value(f"and i8 {inputs[1]}, {f.value(f'xor i8 {inputs[0]}, 1')}")


def _act(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """EXIN (and a `SUB n` the table does not know) without a CNC: W1 = ACT."""
    return inputs[-1] if inputs else "0"


def _nothing(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """DISPB: no W1, nothing written."""
    return "0"


def _window(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """WINDR/WINDW without a CNC: ACT = 1 writes completion code 0; W1 = ACT."""
    if not params or not isinstance(params[0], Address):
        return None
    completion = params[0].offset(cnc.COMPLETION_OFFSET)
    if _fits(completion, 2):
        _when(f, inputs[-1], lambda: _store(f, completion, 2, "0"))
    return inputs[-1]


def _edge(rising: bool) -> Callable[..., str | None]:
    """DIFU/DIFD: the edge memory in a state word (bit 0 its value, bit 1 set once written:
    a key of `ctx.edges`; its mark word says it is in the changed list), written back into
    `ctx.edges` when read (scan.py)."""

    def emit(f: FunctionText, word: int, number: int, places: Layout, inputs: list[str]) -> str:
        act = inputs[-1]
        ptr = f.word_ptr(word)
        old = f.value(f"load i32, ptr {ptr}")
        before = f.value(f"trunc i32 {f.value(f'and i32 {old}, 1')} to i8")
        wide = f.value(f"or i32 {f.value(f'zext i8 {act} to i32')}, 2")
        differs = f.value(f"icmp ne i32 {wide}, {old}")
        mark_ptr = f.word_ptr(places.marks - 1 - number)
        marked = f.value(f"load i32, ptr {mark_ptr}")
        first = f.value(f"and i1 {differs}, {f.value(f'icmp eq i32 {marked}, 0')}")
        f.add(f"store i32 {wide}, ptr {ptr}")
        step = f.value(f"zext i1 {first} to i32")
        f.add(f"store i32 {f.value(f'or i32 {marked}, {step}')}, ptr {mark_ptr}")
        count_ptr = f.word_ptr(layout.DIRTY)
        count = f.value(f"load i32, ptr {count_ptr}")
        entry = f.value(f"getelementptr i32, ptr {f.word_ptr(places.dirty)}, i32 {count}")
        f.add(f"store i32 {-1 - number}, ptr {entry}")
        f.add(f"store i32 {f.value(f'add i32 {count}, {step}')}, ptr {count_ptr}")
        if rising:
            return f.value(f"and i8 {act}, {f.value(f'xor i8 {before}, 1')}")
        return f.value(f"and i8 {before}, {f.value(f'xor i8 {act}, 1')}")

    return emit


EMITTERS: dict[FunctionImpl, Emitter] = {
    transfer.movb: _copy(lambda p: 1, 0, 1),
    transfer.movw: _copy(lambda p: 2, 0, 1),
    transfer.movd: _copy(lambda p: 4, 0, 1),
    transfer.movn: _copy(lambda p: p[0], 1, 2),
    transfer.move: _move,
    transfer.movor: _movor,
    _arithmetic.numeb: _numeb,
    compare.compb: _compb,
    compare.rngb: _range(1),
    compare.rngw: _range(2),
    compare.rngd: _range(4),
    logic.logand: _logic("and"),
    logic.logor: _logic("or"),
    logic.eor: _logic("xor"),
    logic.lognot: _not,
    decode.decb: _decb,
    cnc.axctl: _axctl,
    cnc.windr: _window,
    cnc.windw: _window,
    cnc.exin: _act,
    cnc.dispb: _nothing,
    cnc.unknown_sub: _act,
}
EDGES: dict[FunctionImpl, Callable[..., str | None]] = {
    edges.difu: _edge(True),
    edges.difd: _edge(False),
}


def edge_key(spec: InstructionSpec, impl: FunctionImpl | None,
             params: Sequence[object]) -> tuple[str, int] | None:
    """The `ctx.edges` key of a DIFU/DIFD op (its implementation's kind is its row's name)."""
    if impl in EDGES and len(params) == 1 and isinstance(params[0], int):
        return spec.name, params[0]
    return None


def emit(f: FunctionText, spec: InstructionSpec, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str], edge_words: dict[tuple[str, int], int],
         places: Layout) -> str | None:
    """Emit the op's code into `f`; its W1 (an i8 0/1 value), or None when not native."""
    key = edge_key(spec, impl, params)
    if key is not None:
        number = edge_words[key]
        return EDGES[impl](f, places.edge_base + number, number, places, inputs)
    emitter = EMITTERS.get(impl)
    if emitter is None:
        return None
    try:
        return emitter(f, params, inputs)
    except (ValueError, TypeError, IndexError):  # parameters of another shape: call back
        return None
