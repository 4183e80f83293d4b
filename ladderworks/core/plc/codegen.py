"""The scan's code generator: Python source from a binary's ops, compiled once per variant.

Every stack level ST0..ST8 is a local variable (its depth is known at each op), every area a
local bytearray, and each contact a shift-and-mask on a constant byte index. In fast mode a run
of contacts becomes one expression; in monitored mode each op's result is stored in `M[op]`.
"""

from __future__ import annotations

from collections.abc import Callable, Collection
from dataclasses import dataclass
from typing import Any

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler.binary import BinaryFormatError, Op
from ladderworks.core.compiler.checks import MAX_PUSHES
from ladderworks.core.instructions import Kind
from ladderworks.core.plc.functions import FunctionContext, FunctionImpl

ScanFunction = Callable[[FunctionContext, bytearray], None]

_AREA_NAMES = tuple(area.value for area in Area)
_MAX_NESTING = 40  # parentheses per expression before it is stored in its variable
_MAX_TERMS = 64  # operators per expression (Python's compiler recurses on long chains)
_CONTACTS = frozenset({"RD", "RD.NOT", "AND", "AND.NOT", "OR", "OR.NOT", "RD.STK",
                       "RD.NOT.STK"})


@dataclass(slots=True)
class GeneratedScan:
    """The generated source and the compiled scan function `scan(ctx, M)`."""

    source: str
    scan: ScanFunction


@dataclass(slots=True)
class _Range:
    """An open JMP or COM range: COM's gate variable and the coils left (None: up to the end
    instruction, JMPE or COME)."""

    variable: str
    left: int | None


def _count_coil(ranges: list[_Range]) -> bool:
    """Count one coil in the innermost of `ranges`; True when it was that range's last coil.

    A coil counts only for the innermost open range (JMP and COM alike): a counted range
    nested inside another counts its own coils, and the outer one goes on counting after it.
    """
    if not ranges or ranges[-1].left is None:
        return False
    ranges[-1].left -= 1
    if ranges[-1].left > 0:
        return False
    ranges.pop()
    return True


def _counted(coils: object) -> int | None:
    """A range's coil count from the instruction's parameter: None for 0 (up to the end)."""
    return coils if isinstance(coils, int) and coils > 0 else None


class _Value:
    """The Python expression for one stack level, and how it was built."""

    __slots__ = ("expr", "nesting", "terms", "top")

    def __init__(self, expr: str, top: str = "", nesting: int = 0, terms: int = 1) -> None:
        self.expr = expr
        self.top = top  # top-level operator: "", "&" or "|"
        self.nesting = nesting
        self.terms = terms


def _bit_expr(address: Address, inverted: bool) -> str:
    assert address.bit is not None
    byte = f"{address.area.value}[{address.byte}]"
    if inverted:
        byte = "~" + byte
    if address.bit:
        return f"({byte} >> {address.bit} & 1)"
    return f"({byte} & 1)"


class _Generator:
    def __init__(self, ops: tuple[Op, ...], registry: dict[str, FunctionImpl],
                 disabled: Collection[int], monitored: bool) -> None:
        self.ops = ops
        self.registry = registry
        self.disabled = disabled
        self.monitored = monitored
        self.lines: list[str] = []
        self.indent = 1
        self.values: list[_Value] = [_Value("0")]
        self.impls: list[FunctionImpl] = []
        self.calls: list[int] = []  # op index of each function call
        self.commons: list[_Range] = []
        self.common_vars = 0
        self.jumps: list[_Range] = []  # each an `if not act:` block of the scan code
        self.jump_ended = False  # the op just generated was the last coil of a JMP n range
        self.max_depth = 0

    def emit(self, line: str) -> None:
        self.lines.append("    " * self.indent + line)

    def var(self, depth: int) -> str:
        return f"s{depth}"

    def store(self, depth: int) -> str:
        """Make stack level `depth` a plain variable (emitting its assignment if pending)."""
        value = self.values[depth]
        name = self.var(depth)
        if value.expr != name:
            self.emit(f"{name} = {value.expr}")
            self.values[depth] = _Value(name)
        return name

    def store_all(self) -> None:
        for depth in range(len(self.values)):
            self.store(depth)

    def fail(self, index: int, reason: str) -> BinaryFormatError:
        return BinaryFormatError(f"{reason} at op {index}")

    def run(self) -> str:
        previous_network = -1
        for index, op in enumerate(self.ops):
            if op.source.network != previous_network:
                previous_network = op.source.network
                self.values = [_Value("0")]
            self.op(index, op)
            if self.monitored and op.name != "JMP":  # JMP records its ACT before the jump
                self.store_all()
                self.emit(f"M[{index}] = {self.var(len(self.values) - 1)}")
            if self.jump_ended:
                self.end_counted_jump(index)
        if any(jump.left is None for jump in self.jumps):
            raise self.fail(len(self.ops), "JMP without JMPE")
        # a JMP n with fewer than n coils after it skips to the end of the program
        head = [f"def scan(ctx, M, {', '.join(f'{a}={a}' for a in _AREA_NAMES)}, "
                "FN=FN, ST=ST, PA=PA):"]
        depths = [self.var(d) for d in range(self.max_depth + 1)]
        head.append("    " + " = ".join(depths) + " = 0")
        if self.common_vars:
            head.append("    " + " = ".join(f"cm{k}" for k in range(self.common_vars)) + " = 1")
        if self.monitored:
            head.append("    M[:] = ZERO")
        return "\n".join([*head, *self.lines, "    return None", ""])

    def live_after(self, index: int) -> bool:
        """Whether the op after `index` goes on using this network's stack values."""
        nxt = self.ops[index + 1] if index + 1 < len(self.ops) else None
        return (nxt is not None and nxt.source.network == self.ops[index].source.network
                and nxt.name not in ("RD", "RD.NOT"))

    def end_counted_jump(self, index: int) -> None:
        """Close the block of a JMP n after its n-th coil (op `index`).

        When the network goes on after that coil, its stack values read 0 if the jump was
        taken (the skipped contacts were not evaluated).
        """
        self.jump_ended = False
        live = self.live_after(index)
        if live:
            self.store_all()
        self.indent -= 1
        if live:
            self.emit("else:")
            self.emit("    " + " = ".join(self.var(d) for d in range(len(self.values))) + " = 0")

    def count_coil(self) -> None:
        """Count a coil (written or disabled) in the innermost COM and JMP ranges."""
        _count_coil(self.commons)
        if _count_coil(self.jumps):
            self.jump_ended = True

    def op(self, index: int, op: Op) -> None:
        spec = op.spec
        off = index in self.disabled
        name = spec.name
        if spec.kind is Kind.BASIC:
            if name in _CONTACTS:
                assert op.operand is not None
                term = "0" if off else _bit_expr(op.operand, ".NOT" in name)
                if off and name.startswith("OR"):
                    return
                if name.endswith(".STK"):
                    if len(self.values) > MAX_PUSHES:
                        raise self.fail(index, "stack deeper than ST8")
                    self.values.append(_Value(term))
                    self.max_depth = max(self.max_depth, len(self.values) - 1)
                elif name.startswith("RD"):
                    self.values[-1] = _Value(term)
                elif name.startswith("AND"):
                    self.values[-1] = self.combine(self.values[-1], "&", _Value(term))
                else:
                    self.values[-1] = self.combine(self.values[-1], "|", _Value(term))
                return
            if name in ("AND.STK", "OR.STK"):
                if len(self.values) < 2:
                    raise self.fail(index, f"{name} with nothing pushed")
                top = self.values.pop()
                operator = "&" if name == "AND.STK" else "|"
                self.values[-1] = self.combine(self.values[-1], operator, top)
                return
            assert op.operand is not None
            self.write(index, op.operand, name == "WRT.NOT", off)
            return
        if spec.kind is Kind.END:
            return
        self.function(index, op, off)

    def combine(self, left: _Value, operator: str, right: _Value) -> _Value:
        left_expr, right_expr = left.expr, right.expr
        nesting = max(left.nesting, right.nesting)
        if operator == "&":
            if left.top == "|":
                left_expr, nesting = f"({left_expr})", nesting + 1
            if right.top == "|":
                right_expr, nesting = f"({right_expr})", nesting + 1
        value = _Value(f"{left_expr} {operator} {right_expr}", operator, nesting,
                       left.terms + right.terms)
        if nesting > _MAX_NESTING or value.terms > _MAX_TERMS:
            depth = len(self.values) - 1
            self.emit(f"{self.var(depth)} = {value.expr}")
            value = _Value(self.var(depth))
        return value

    def write(self, index: int, address: Address, inverted: bool, off: bool) -> None:
        if off:
            self.count_coil()  # a disabled coil still counts in a COM or JMP range
            return
        depth = len(self.values) - 1
        for lower in range(depth):
            self.store(lower)
        value = self.values[depth]
        live = self.live_after(index)
        byte = f"{address.area.value}[{address.byte}]"
        assert address.bit is not None
        mask = 1 << address.bit
        if self.commons:
            condition = self.store(depth)
            if inverted:
                condition = f"({condition} ^ 1)"
            condition = f"{self.commons[-1].variable} & {condition}"
            inverted = False
        elif value.expr == self.var(depth):
            condition = value.expr
        elif live or self.monitored:
            condition = f"({self.var(depth)} := {value.expr})"
            self.values[depth] = _Value(self.var(depth))
        else:
            condition = value.expr
        on, off_line = f"{byte} |= {mask}", f"{byte} &= {0xFF ^ mask}"
        if inverted:
            on, off_line = off_line, on
        self.emit(f"if {condition}:")
        self.emit(f"    {on}")
        self.emit("else:")
        self.emit(f"    {off_line}")
        self.count_coil()

    def function(self, index: int, op: Op, off: bool) -> None:
        spec = op.spec
        count = len(spec.inputs)
        if count and len(self.values) < count:
            raise self.fail(index, f"{spec.name} needs {count} control inputs")
        self.store_all()
        first = len(self.values) - count if count else len(self.values) - 1
        inputs = [self.var(d) for d in range(first, len(self.values))]
        name = spec.name
        if name == "JMP":
            if self.monitored:
                self.emit(f"M[{index}] = {inputs[-1]}")
            self.emit(f"if not {inputs[-1]}:" if not off else "if 1:")
            self.indent += 1
            self.emit("pass")
            self.jumps.append(_Range("", _counted(op.params[0] if op.params else 0)))
        elif name == "JMPE":
            # ends the innermost JMP 0, and any JMP n opened inside it that is still counting
            while self.jumps and self.jumps[-1].left is not None:
                self.jumps.pop()
                self.indent -= 1
            if not self.jumps:
                raise self.fail(index, "JMPE without JMP")
            self.jumps.pop()
            self.indent -= 1
        elif name == "COM":
            variable = f"cm{self.common_vars}"
            self.common_vars += 1
            act = "1" if off else inputs[-1]
            if self.commons:
                act = f"{act} & {self.commons[-1].variable}"
            self.emit(f"{variable} = {act}")
            self.commons.append(_Range(variable, _counted(op.params[0] if op.params else 0)))
        elif name == "COME":
            for k in range(len(self.commons) - 1, -1, -1):
                if self.commons[k].left is None:
                    del self.commons[k]
                    break
        else:
            impl = self.registry.get(name)
            if impl is None:
                raise BinaryFormatError(f"{name} at op {index} is not implemented")
            call = len(self.impls)
            self.impls.append(impl)
            self.calls.append(index)
            target = self.var(first)
            if off:
                self.emit(f"{target} = 0")
            else:
                self.emit(f"{target} = FN[{call}](ctx, ST[{call}], ({', '.join(inputs)},), "
                          f"PA[{call}])")
        del self.values[first + 1:]
        if name in ("JMP", "JMPE", "COM", "COME"):
            self.values[first] = _Value("0")
        else:
            self.values[first] = _Value(self.var(first))


def generate(ops: tuple[Op, ...], areas: dict[Area, bytearray],
             registry: dict[str, FunctionImpl], states: list[dict[str, Any]] | None = None, *,
             disabled: Collection[int] = (), monitored: bool = False) -> GeneratedScan:
    """Generate and compile the scan function for `ops`.

    `states` holds one dict per function call in program order and is shared between the
    variants of one program (so switching mode or disabling keeps timers and edges).
    """
    generator = _Generator(ops, registry, frozenset(disabled), monitored)
    source = generator.run()
    if states is None:
        states = []
    while len(states) < len(ops):
        states.append({})
    namespace: dict[str, Any] = {area.value: data for area, data in areas.items()}
    namespace["FN"] = tuple(generator.impls)
    namespace["ST"] = tuple(states[index] for index in generator.calls)
    namespace["PA"] = tuple(ops[index].params for index in generator.calls)
    namespace["ZERO"] = bytes(len(ops))
    code = compile(source, "<ladder scan>", "exec")
    exec(code, namespace)
    return GeneratedScan(source, namespace["scan"])
