"""Delta DVP word logic and arithmetic as native code (core/plc/functions/delta_logic.py and
delta_math.py): WAND/WOR/WXOR, NEG, ROR/ROL, BCD/BIN, CML, RCR/RCL, BON, ABS, SWAP, GRY/GBIN,
BSET/BRST, each 16- and 32-bit (D forms) and their pulse forms, made as words.py makes MOV:
each row read from its action (rows_extra.ACTIONS) and its implementation's module; values in
i64 (the sources as `value` / `value32` read them), written as `Memory.write` / `store32`
does (a 32-bit output past its area's end calls back); an out-of-range count or value is the
operation error (M1067, M1068) with nothing written, as in Python."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.dialects.delta.rows_extra import ACTIONS
from ladderworks.core.instructions import lookup
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.dvp_data import M1022, M1067, M1068
from ladderworks.core.plc.native import words, words32
from ladderworks.core.plc.native.builtins import Emitter
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.words import Prepare, _bit, _place, _Refused, _row, _write

Body = Callable[[FunctionText], None]
Read = Callable[[FunctionText], str]
Write = Callable[[FunctionText, str], None]
FAMILY_MODULES = ("ladderworks.core.plc.functions.delta_logic",
                  "ladderworks.core.plc.functions.delta_math",
                  "ladderworks.core.plc.functions.delta_blocks",
                  "ladderworks.core.plc.functions.delta_words",
                  "ladderworks.core.plc.functions.delta_float",
                  "ladderworks.core.plc.functions.delta_modules")


def reader(operand: object, wide: bool) -> Read:
    """`value32` (wide) or `value` of a source operand as an i64."""
    return words32._source(operand) if wide else words._source(operand)


def writer(output: object, wide: bool) -> Write:
    """`store32` (wide: the operand's own width; past its area refused) or a 2-byte write."""
    if wide:
        place, width = words32._output(output)
    else:
        place, width = _place(output, 2), 2
    return lambda f, value: _write(f, place, value, width)


def error(f: FunctionText) -> None:
    """`operation_error`: M1067 and M1068 on."""
    _bit(f, M1067, "true")
    _bit(f, M1068, "true")


def checked(f: FunctionText, bad: str, body: Callable[[], None]) -> None:
    """The operation error when the i1 `bad`, else `body()` (emitting in its own blocks)."""
    wrong, good, after = f.label(), f.label(), f.label()
    f.add(f"br i1 {bad}, label %{wrong}, label %{good}")
    f.start(wrong)
    error(f)
    f.add(f"br label %{after}")
    f.start(good)
    body()
    f.join(after)


def outside(f: FunctionText, value: str, low: int, high: int) -> str:
    """An i1: `value` (i64) is not within low..high."""
    return f.value(f"or i1 {f.value(f'icmp slt i64 {value}, {low}')}, "
                   f"{f.value(f'icmp sgt i64 {value}, {high}')}")


def _errors_possible() -> None:
    _place(M1067, 1), _place(M1068, 1)


def _logic(operator: str, wide: bool) -> Prepare:
    def prepare(params: Sequence[object]) -> Body:
        s1, s2, output = params
        first, second, store = reader(s1, wide), reader(s2, wide), writer(output, wide)
        return lambda f: store(f, f.value(f"{operator} i64 {first(f)}, {second(f)}"))

    return prepare


def _unary(make: Callable[[FunctionText, str], str], wide: bool, source_at: int = 0
           ) -> Prepare:
    """A row writing `make(value)` of its source (params[source_at]) to its last operand."""
    def prepare(params: Sequence[object]) -> Body:
        read, store = reader(params[source_at], wide), writer(params[-1], wide)
        return lambda f: store(f, make(f, read(f)))

    return prepare


def _negate(f: FunctionText, value: str) -> str:
    return f.value(f"sub i64 0, {value}")


def _complement(f: FunctionText, value: str) -> str:
    return f.value(f"xor i64 {value}, -1")


def _absolute(f: FunctionText, value: str) -> str:
    negative = f.value(f"icmp slt i64 {value}, 0")
    return f.value(f"select i1 {negative}, i64 {_negate(f, value)}, i64 {value}")


def _swap(f: FunctionText, value: str) -> str:
    low = f.value(f"shl i64 {f.value(f'and i64 {value}, 16711935')}, 8")
    high = f.value(f"and i64 {f.value(f'ashr i64 {value}, 8')}, 16711935")
    return f.value(f"or i64 {low}, {high}")


def _count(params: Sequence[object], at: int, low: int, high: int
           ) -> tuple[Read, Callable[[FunctionText, str], str]]:
    """A count operand (`value`) and the i1 "outside low..high" of its value."""
    _errors_possible()
    return words._source(params[at]), lambda f, n: outside(f, n, low, high)


def _rotate(wide: bool, right: bool) -> Prepare:
    """ROR/ROL D n: rotated in 16 (32) bits; the last bit round is M1022."""
    bits = 32 if wide else 16
    mask = (1 << bits) - 1

    def prepare(params: Sequence[object]) -> Body:
        output, _count_at = params
        read, store = reader(output, wide), writer(output, wide)
        count, bad = _count(params, 1, 1, bits)
        _place(M1022, 1)

        def body(f: FunctionText) -> None:
            n = count(f)

            def run() -> None:
                raw = f.value(f"and i64 {read(f)}, {mask}")
                back = f.value(f"sub i64 {bits}, {n}")
                if right:
                    turned = f.value(f"or i64 {f.value(f'lshr i64 {raw}, {n}')}, "
                                     f"{f.value(f'shl i64 {raw}, {back}')}")
                else:
                    turned = f.value(f"or i64 {f.value(f'shl i64 {raw}, {n}')}, "
                                     f"{f.value(f'lshr i64 {raw}, {back}')}")
                rotated = f.value(f"and i64 {turned}, {mask}")
                carry = f.value(f"lshr i64 {rotated}, {bits - 1}") if right else rotated
                store(f, rotated)
                _bit(f, M1022, f.value(f"trunc i64 {carry} to i1"))

            checked(f, bad(f, n), run)

        return body

    return prepare


def _carry_rotate(wide: bool, right: bool) -> Prepare:
    """RCR/RCL D n: D and M1022 rotated together, as one word of 17 (33) bits."""
    bits = 32 if wide else 16
    whole = (1 << (bits + 1)) - 1

    def prepare(params: Sequence[object]) -> Body:
        output, _count_at = params
        read, store = reader(output, wide), writer(output, wide)
        count, bad = _count(params, 1, 1, bits)
        _place(M1022, 1)
        assert M1022.bit is not None

        def body(f: FunctionText) -> None:
            n = count(f)

            def run() -> None:
                word = f.value(f"and i64 {read(f)}, {(1 << bits) - 1}")
                carry = f.value(f"zext i8 {f.bit(M1022.area, M1022.byte, M1022.bit or 0, False)} "
                                f"to i64")
                joined = f.value(f"or i64 {word}, {f.value(f'shl i64 {carry}, {bits}')}")
                back = f.value(f"sub i64 {bits + 1}, {n}")
                first, second = ("lshr", "shl") if right else ("shl", "lshr")
                turned = f.value(f"or i64 {f.value(f'{first} i64 {joined}, {n}')}, "
                                 f"{f.value(f'{second} i64 {joined}, {back}')}")
                rotated = f.value(f"and i64 {turned}, {whole}")
                store(f, f.value(f"and i64 {rotated}, {(1 << bits) - 1}"))
                _bit(f, M1022, f.value(f"trunc i64 {f.value(f'lshr i64 {rotated}, {bits}')} "
                                       f"to i1"))

            checked(f, bad(f, n), run)

        return body

    return prepare


def _bit_on(wide: bool) -> Prepare:
    """BON S D n: bit D = bit n of S (n outside 0..bits-1: the operation error)."""
    def prepare(params: Sequence[object]) -> Body:
        source, output, _which = params
        read = reader(source, wide)
        place = _place(output, 1)
        if place.bit is None:
            raise _Refused
        count, bad = _count(params, 2, 0, 31 if wide else 15)

        def body(f: FunctionText) -> None:
            n = count(f)
            checked(f, bad(f, n), lambda: _bit(f, place, f.value(
                f"trunc i64 {f.value(f'ashr i64 {read(f)}, {n}')} to i1")))

        return body

    return prepare


def _bit_change(wide: bool, on: bool) -> Prepare:
    """BSET / BRST D n: bit n of D set / reset."""
    def prepare(params: Sequence[object]) -> Body:
        output, _which = params
        read, store = reader(output, wide), writer(output, wide)
        count, bad = _count(params, 1, 0, 31 if wide else 15)

        def body(f: FunctionText) -> None:
            n = count(f)

            def run() -> None:
                mask = f.value(f"shl i64 1, {n}")
                if on:
                    store(f, f.value(f"or i64 {read(f)}, {mask}"))
                else:
                    store(f, f.value(f"and i64 {read(f)}, {f.value(f'xor i64 {mask}, -1')}"))

            checked(f, bad(f, n), run)

        return body

    return prepare


def _gray(wide: bool, encode: bool) -> Prepare:
    """GRY / GBIN S D: a negative S is the operation error."""
    def prepare(params: Sequence[object]) -> Body:
        source, output = params
        read, store = reader(source, wide), writer(output, wide)
        _errors_possible()

        def body(f: FunctionText) -> None:
            number = read(f)

            def run() -> None:
                result = number
                for shift in (1,) if encode else (1, 2, 4, 8, 16, 32):
                    result = f.value(f"xor i64 {result}, "
                                     f"{f.value(f'lshr i64 {result}, {shift}')}")
                store(f, result)

            checked(f, f.value(f"icmp slt i64 {number}, 0"), run)

        return body

    return prepare


def _to_bcd(wide: bool) -> Prepare:
    """BCD S D: S (0-9999, DBCD 0-99999999) as BCD digits; outside: the operation error."""
    digits = 8 if wide else 4

    def prepare(params: Sequence[object]) -> Body:
        source, output = params
        read, store = reader(source, wide), writer(output, wide)
        _errors_possible()

        def body(f: FunctionText) -> None:
            number = read(f)

            def run() -> None:
                raw, rest = "0", number
                for k in range(digits):
                    digit = f.value(f"urem i64 {rest}, 10")
                    raw = f.value(f"or i64 {raw}, {f.value(f'shl i64 {digit}, {4 * k}')}")
                    rest = f.value(f"udiv i64 {rest}, 10")
                store(f, raw)

            checked(f, outside(f, number, 0, 10 ** digits - 1), run)

        return body

    return prepare


def _to_binary(wide: bool) -> Prepare:
    """BIN S D: S's BCD digits as a number; a digit above 9: the operation error."""
    digits = 8 if wide else 4

    def prepare(params: Sequence[object]) -> Body:
        source, output = params
        read, store = reader(source, wide), writer(output, wide)
        _errors_possible()

        def body(f: FunctionText) -> None:
            raw = read(f)
            number, bad = "0", "false"
            for k in range(digits):
                nibble = f.value(f"and i64 {f.value(f'lshr i64 {raw}, {4 * k}')}, 15")
                bad = f.value(f"or i1 {bad}, {f.value(f'icmp ugt i64 {nibble}, 9')}")
                number = f.value(f"add i64 {number}, {f.value(f'mul i64 {nibble}, {10 ** k}')}")
            checked(f, bad, lambda: store(f, number))

        return body

    return prepare


def _both(make: Callable[[bool], Prepare], name: str) -> dict[str, Prepare]:
    return {name: make(False), name + "32": make(True)}


PREPARE: dict[str, Prepare] = {
    **_both(lambda w: _logic("and", w), "and"), **_both(lambda w: _logic("or", w), "or"),
    **_both(lambda w: _logic("xor", w), "xor"),
    **_both(lambda w: _unary(_negate, w), "negate"),
    **_both(lambda w: _unary(_complement, w), "complement"),
    **_both(lambda w: _unary(_absolute, w), "absolute"),
    **_both(lambda w: _unary(_swap, w), "swap"),
    **_both(lambda w: _rotate(w, True), "rotate-right"),
    **_both(lambda w: _rotate(w, False), "rotate-left"),
    **_both(lambda w: _carry_rotate(w, True), "carry-right"),
    **_both(lambda w: _carry_rotate(w, False), "carry-left"),
    **_both(_bit_on, "bit-on"), **_both(lambda w: _bit_change(w, True), "bit-set"),
    **_both(lambda w: _bit_change(w, False), "bit-reset"),
    **_both(lambda w: _gray(w, True), "to-gray"), **_both(lambda w: _gray(w, False), "from-gray"),
    **_both(_to_bcd, "to-bcd"), **_both(_to_binary, "to-binary"),
}


def rows(prepare: dict[str, Prepare], pulse: bool) -> dict[FunctionImpl, Prepare]:
    """The Delta family rows (FAMILY_MODULES') whose action `prepare` has, by implementation
    (pulse forms or not)."""
    load_all()
    found: dict[FunctionImpl, Prepare] = {}
    for name, action in ACTIONS.items():
        impl, spec = REGISTRY.get(name), lookup(name)
        if impl is None or spec is None or spec.pulse != pulse or action not in prepare \
                or getattr(impl, "__module__", "") not in FAMILY_MODULES:
            continue
        found[impl] = prepare[action]
    return found


EMITTERS: dict[FunctionImpl, Emitter] = {impl: _row(p) for impl, p in rows(PREPARE, False).items()}
PULSES = rows(PREPARE, True)
