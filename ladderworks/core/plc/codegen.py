"""The scan's code generator: Python source from a binary's ops, compiled once per variant.

Every stack level ST0..ST8 is a local variable (its depth is known at each op), every area a
local bytearray, and each contact a shift-and-mask on a constant byte index. In fast mode a run
of contacts becomes one expression; in monitored mode each op's result is stored in its place
of a 256-op list (`m3[17]`, codegen_flow.py). `flow_by_op` stores it in `M[op]` instead, one
flat list, as the generator did before (kept for benchmarks/scan_speed.py and the tests).

The code is flat by construction: a JMP range is a guard `if not sk:` over its ops (`sk` is the
id of the jump being taken, one variable per program unit), never a nested block, so any number
of nested JMP/COM ranges generates. Each level and each subprogram is its own function, cut
into chunk functions of at most CHUNK_OPS ops; a unit with labels (LBL) runs its chunks from a
small dispatch loop, so JMPB can go backward. Dispatch is on the instruction table's fields.
"""

from __future__ import annotations

from collections.abc import Collection
from typing import Any

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler.binary import BinaryFormatError, Op
from ladderworks.core.compiler.checks import MAX_PUSHES, implementation_of
from ladderworks.core.compiler.structure import LOOP_LIMIT, Unit, analyse, number_of
from ladderworks.core.instructions import Combine, Flow, Kind, StackOp, Write
from ladderworks.core.plc.codegen_flow import GeneratedScan as GeneratedScan
from ladderworks.core.plc.codegen_flow import flow_blocks, flow_reset, flow_slot
from ladderworks.core.plc.codegen_plan import CHUNK_OPS as CHUNK_OPS
from ladderworks.core.plc.codegen_plan import JumpToMain as JumpToMain
from ladderworks.core.plc.codegen_plan import ScanLoopError as ScanLoopError
from ladderworks.core.plc.codegen_plan import chunk_plan, loop_stop
from ladderworks.core.plc.codegen_plan import compiled as compiled
from ladderworks.core.plc.codegen_values import (
    Range,
    Value,
    bit_expr,
    count_in_innermost,
    counted,
)
from ladderworks.core.plc.functions import FunctionImpl

_AREA_NAMES = tuple(area.value for area in Area)
_MAX_NESTING = 40  # parentheses per expression before it is stored in its variable
_MAX_TERMS = 64  # operators per expression (Python's compiler recurses on long chains)
SYSTEM_RELAY = 9091  # R9091.2/.3/.4: level 1/2/3 running
_LEVEL_BITS = {1: 4, 2: 8, 3: 16}


_DEFAULTS = ", ".join(f"{a}={a}" for a in _AREA_NAMES) + \
    ", FN=FN, ST=ST, PA=PA, SK=SK, CM=CM, SV=SV"


class _Generator:
    def __init__(self, ops: tuple[Op, ...], registry: dict[str, FunctionImpl],
                 disabled: Collection[int], monitored: bool, flow_by_op: bool = False) -> None:
        self.ops = ops
        self.registry = registry
        self.disabled = disabled
        self.monitored = monitored
        self.by_op = flow_by_op
        # each op's table row, looked up once (Op.spec looks it up by name on every read)
        self.specs = [op.spec for op in ops]
        self.structure = analyse([(spec, op.params)
                                  for spec, op in zip(self.specs, ops, strict=True)])
        self.out: list[str] = []  # every finished function
        self.lines: list[str] = []  # the chunk being generated
        self.values: list[Value] = [Value("0")]
        self.impls: list[FunctionImpl] = []
        self.calls: list[int] = []  # op index of each function call
        self.jumps: list[Range] = []
        self.commons: list[Range] = []
        self.common_count = 0
        self.unit_count = 0
        self.chunk_count = 0
        self.guarded = False
        self.chunk_depth = 0  # the deepest stack level the chunk uses
        self.unit_numbers = {u.name: n for n, u in enumerate(self.structure.units())}
        self.unit_number = 0
        self.chunk_of_label: dict[int, int] = {}

    # -- emitting --------------------------------------------------------------------------

    def emit(self, line: str) -> None:
        """A line of an op's code: inside the `if not sk:` guard when a JMP range is open."""
        if self.jumps and not self.guarded:
            self.lines.append("    if not sk:")
            self.guarded = True
            self.uses_sk = True
        self.lines.append(("        " if self.guarded else "    ") + line)

    def emit_base(self, line: str) -> None:
        """A line outside any guard (range ends)."""
        self.guarded = False
        self.lines.append("    " + line)

    def slot(self, index: int) -> str:
        """Where the generated code stores op `index`'s power flow."""
        if self.by_op:
            return f"M[{index}]"
        block, place = flow_slot(index)
        self.chunk_blocks.add(block)
        return place

    def var(self, depth: int) -> str:
        self.chunk_depth = max(self.chunk_depth, depth)
        return f"s{depth}"

    def store(self, depth: int) -> str:
        """Make stack level `depth` a plain variable (emitting its assignment if pending)."""
        value = self.values[depth]
        name = self.var(depth)
        if value.expr != name:
            self.emit(f"{name} = {value.expr}")
            self.values[depth] = Value(name)
        return name

    def store_all(self) -> None:
        for depth in range(len(self.values)):
            self.store(depth)

    def fail(self, index: int, reason: str) -> BinaryFormatError:
        return BinaryFormatError(f"{reason} at op {index}")

    # -- chunks and units ------------------------------------------------------------------

    def start_chunk(self, carried: int) -> None:
        """Begin a chunk function; `carried` stack levels come from the previous chunk."""
        self.lines = []
        self.guarded = False
        self.uses_sk = bool(self.jumps)
        self.chunk_depth = 0
        self.chunk_commons: set[int] = {r.ident for r in self.commons}
        self.chunk_opened: set[int] = set()
        self.chunk_blocks: set[int] = set()  # the power flow lists the chunk writes
        self.carried = carried
        self.values = [Value(self.var(d)) for d in range(carried)] or [Value("0")]

    def end_chunk(self, unit: int, mid_network: bool, result: str) -> str:
        """Finish the chunk: its prelude, body and return; the function's name."""
        if mid_network:
            self.store_all()
            self.guarded = False
            names = ", ".join(self.var(d) for d in range(len(self.values)))
            self.lines.append(f"    SV[0] = ({names},)")
        name = f"c{self.chunk_count}"
        self.chunk_count += 1
        blocks = "".join(f", m{k}=FB[{k}]" for k in sorted(self.chunk_blocks))
        head = [f"def {name}(ctx, M, {_DEFAULTS}{blocks}):"]
        head.append("    " + " = ".join(f"s{d}" for d in range(self.chunk_depth + 1)) + " = 0")
        if self.carried:
            head.append("    " + ", ".join(f"s{d}" for d in range(self.carried)) + ", = SV[0]")
        if self.uses_sk:
            head.append(f"    sk = SK[{unit}]")
        for ident in sorted(self.chunk_commons):
            head.append(f"    cm{ident} = 1" if ident in self.chunk_opened
                        else f"    cm{ident} = CM[{ident}]")
        self.out += [*head, *self.lines, f"    return {result}", ""]
        return name

    def run(self) -> str:
        units: dict[str, int] = {}
        for unit in self.structure.units():
            units[unit.name] = self.unit(unit)
        body = ["def scan(ctx, M, full=True, R=R):"]
        levels = self.structure.levels
        first = levels.get(1)
        if self.monitored:
            body += flow_reset((first.start, first.end) if first else None, len(self.ops),
                               self.by_op)
        for level in sorted(levels):
            indent = "    " if level == 1 else "        "
            if level > 1:
                body.append("    if full:")
            body.append(f"{indent}R[{SYSTEM_RELAY}] = R[{SYSTEM_RELAY}] & 227 | "
                        f"{_LEVEL_BITS.get(level, 0)}")
            body.append(f"{indent}U{units[levels[level].name]}(ctx, M)")
        body.append(f"    R[{SYSTEM_RELAY}] &= 227")
        return "\n".join([*self.out, *body, ""])

    def unit(self, unit: Unit) -> int:
        """Generate a unit's chunks and its function `U<n>`; returns n."""
        number = self.unit_numbers[unit.name]
        self.unit_number = number
        self.current_unit = unit
        self.unit_count = max(self.unit_count, number + 1)
        self.jumps, self.commons, self.jump_ids = [], [], 0
        labelled = bool(unit.labels)
        starts, chunk_of_label = chunk_plan(self.ops, unit)
        self.chunk_of_label = chunk_of_label
        label_starts = set(unit.labels.values())
        chunks: list[str] = []
        first_common = self.common_count
        self.start_chunk(0)
        previous = -1
        for index in range(unit.start, unit.end):
            op = self.ops[index]
            new_network = op.source.network != previous
            previous = op.source.network
            at_label = index in label_starts
            if index in starts and index != unit.start:
                mid = not new_network and not at_label
                depth = len(self.values) if mid else 0
                result = str(len(chunks) + 1) if labelled else "None"
                chunks.append(self.end_chunk(number, mid, result))
                self.start_chunk(depth)
            if at_label:
                self.values = [Value(self.var(d)) for d in range(len(self.values))]
            elif new_network:
                self.values = [Value("0")]
            self.op(index, op, labelled)
        result = str(len(chunks) + 1) if labelled else "None"
        chunks.append(self.end_chunk(number, False, result))
        head = [f"def U{number}(ctx, M, SK=SK, CM=CM, ONES=ONES):"]
        if self.jump_ids:
            head.append(f"    SK[{number}] = 0")
        if self.common_count > first_common:
            head.append(f"    CM[{first_common}:{self.common_count}] = "
                        f"ONES[{first_common}:{self.common_count}]")
        if not labelled:
            self.out += [*head, *(f"    {name}(ctx, M)" for name in chunks), ""]
            return number
        table = f"CH{number}"
        labels = f"LB{number}"
        self.out.append(f"{table} = ({', '.join(chunks)},)")
        self.out.append(f"{labels} = {chunk_of_label!r}")
        catch = unit.level > 0
        self.out += [*head, "    pc = 0", "    n = 0", f"    while pc < {len(chunks)}:"]
        pad = "            " if catch else "        "
        if catch:
            self.out.append("        try:")
        self.out += [f"{pad}while pc < {len(chunks)}:",
                     f"{pad}    nxt = {table}[pc](ctx, M)",
                     f"{pad}    if nxt <= pc:",
                     f"{pad}        n += 1",
                     f"{pad}        if n > {LOOP_LIMIT}:",
                     f"{pad}            LOOP({number}, nxt, {labels})",
                     f"{pad}    pc = nxt"]
        if catch:
            self.out += ["        except JM as jump:", f"            pc = {labels}[jump.label]"]
        self.out.append("")
        return number

    # -- ops -------------------------------------------------------------------------------

    def live_after(self, index: int) -> bool:
        """Whether the op after `index` goes on using this network's stack values."""
        nxt = self.ops[index + 1] if index + 1 < len(self.ops) else None
        if nxt is None or nxt.source.network != self.ops[index].source.network:
            return False
        spec = self.specs[index + 1]
        return not (spec.combine is Combine.READ and spec.pushes == 0 and spec.operand)

    def close_jumps(self, ended: list[Range], index: int, live: bool) -> None:
        """End JMP ranges (the lowest id first opened): the taken one stops skipping; after a
        counted range ending inside a network, its stack values read 0 if it was taken."""
        if live:
            self.store_all()
        low = min(r.ident for r in ended)
        test = f"sk == {low}" if len(ended) == 1 else f"sk >= {low}"
        self.emit_base(f"if {test}:")
        self.lines.append(f"        sk = SK[{self.unit_number}] = 0")
        if live:
            self.lines.append("        " + " = ".join(
                self.var(d) for d in range(len(self.values))) + " = 0")

    def op(self, index: int, op: Op, labelled: bool) -> None:
        spec = self.specs[index]
        off = index in self.disabled
        ended: list[Range] = []
        if spec.kind is Kind.BASIC:
            if spec.write is not Write.NONE:
                assert op.operand is not None
                ended = self.write(index, op.operand, spec.write, spec.negated, off)
            else:
                self.logic(index, op, off)
        elif spec.kind is Kind.FUNCTION:
            ended = self.function(index, op, off, labelled)
        if self.monitored and spec.flow not in (Flow.JUMP, Flow.LABEL_JUMP,
                                                Flow.LABEL_JUMP_MAIN, Flow.CALL):
            top = len(self.values) - 1
            for depth in range(top):
                self.store(depth)
            name = self.var(top)
            value = self.values[top].expr
            self.emit(f"{self.slot(index)} = {name}" if value == name
                      else f"{self.slot(index)} = {name} = {value}")
            self.values[top] = Value(name)
        if ended:
            self.close_jumps(ended, index, self.live_after(index))

    def logic(self, index: int, op: Op, off: bool) -> None:
        spec = self.specs[index]
        if spec.operand:
            assert op.operand is not None
            term = "0" if off else bit_expr(op.operand, spec.negated)
            if spec.pushes > 0:
                if len(self.values) > MAX_PUSHES:
                    raise self.fail(index, "stack deeper than ST8")
                self.values.append(Value(term))
                self.var(len(self.values) - 1)
            elif spec.combine is Combine.READ:
                self.values[-1] = Value(term)
            elif off and spec.combine is Combine.OR:
                return
            else:
                operator = "&" if spec.combine is Combine.AND else "|"
                self.values[-1] = self.combine(self.values[-1], operator, Value(term))
            return
        if spec.stack is not StackOp.NONE:
            self.stack_op(index, spec.stack)
            return
        if len(self.values) < 2:
            raise self.fail(index, f"{spec.name} with nothing pushed")
        top = self.values.pop()
        operator = "&" if spec.combine is Combine.AND else "|"
        self.values[-1] = self.combine(self.values[-1], operator, top)

    def stack_op(self, index: int, op: StackOp) -> None:
        """A dialect's stack operation (Delta MPS, MRD, MPP, INV) on the stack values."""
        top = len(self.values) - 1
        for depth in range(top):  # a lower level may name s<top>, which is assigned below
            self.store(depth)
        if op is StackOp.INVERT:
            self.values[top] = Value(f"(1 ^ {self.store(top)})")
        elif op is StackOp.DUP:
            if len(self.values) > MAX_PUSHES:
                raise self.fail(index, "stack deeper than ST8")
            self.values.append(Value(self.store(top)))
            self.var(top + 1)
        elif top < 1:
            raise self.fail(index, "stack operation with nothing pushed")
        elif op is StackOp.OVER:
            self.values[top] = Value(self.store(top - 1))
        else:  # DROP
            self.values.pop()

    def combine(self, left: Value, operator: str, right: Value) -> Value:
        left_expr, right_expr = left.expr, right.expr
        nesting = max(left.nesting, right.nesting)
        if operator == "&":
            if left.top == "|":
                left_expr, nesting = f"({left_expr})", nesting + 1
            if right.top == "|":
                right_expr, nesting = f"({right_expr})", nesting + 1
        value = Value(f"{left_expr} {operator} {right_expr}", operator, nesting,
                       left.terms + right.terms)
        if nesting > _MAX_NESTING or value.terms > _MAX_TERMS:
            depth = len(self.values) - 1
            self.emit(f"{self.var(depth)} = {value.expr}")
            value = Value(self.var(depth))
        return value

    def count_coil(self) -> list[Range]:
        """Count a coil (written or disabled) in the innermost COM and JMP ranges; the JMP
        range it ended, if any."""
        count_in_innermost(self.commons)
        ended = count_in_innermost(self.jumps)
        return [ended] if ended is not None else []

    def write(self, index: int, address: Address, kind: Write, inverted: bool,
              off: bool) -> list[Range]:
        if off:
            return self.count_coil()  # a disabled coil still counts in a COM or JMP range
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
            condition = f"cm{self.commons[-1].ident} & {condition}"
            inverted = False
        elif value.expr == self.var(depth):
            condition = value.expr
        elif live or self.monitored:
            condition = f"({self.var(depth)} := {value.expr})"
            self.values[depth] = Value(self.var(depth))
        else:
            condition = value.expr
        on, off_line = f"{byte} |= {mask}", f"{byte} &= {0xFF ^ mask}"
        if kind is Write.RESET:
            on = off_line
        if inverted:
            on, off_line = off_line, on
        self.emit(f"if {condition}:")
        self.emit(f"    {on}")
        if kind is Write.OUT:
            self.emit("else:")
            self.emit(f"    {off_line}")
        return self.count_coil()

    def function(self, index: int, op: Op, off: bool, labelled: bool) -> list[Range]:
        spec = self.specs[index]
        count = len(spec.inputs)
        if count and len(self.values) < count:
            raise self.fail(index, f"{spec.name} needs {count} control inputs")
        if spec.pushes > 0:  # a contact-like box starting a new value (Delta LD= in a rung)
            if len(self.values) > MAX_PUSHES:
                raise self.fail(index, "stack deeper than ST8")
            self.values.append(Value("0"))
            self.var(len(self.values) - 1)
        self.store_all()
        first = len(self.values) - count if count else len(self.values) - 1
        inputs = [self.var(d) for d in range(first, len(self.values))]
        gating = next((r for r in reversed(self.commons) if r.gates_boxes), None)
        if gating is not None and count and spec.flow is Flow.NONE:  # Delta MC off: input off
            inputs[-1] = f"(cm{gating.ident} & {inputs[-1]})"
        act = inputs[-1] if inputs else "1"
        flow = spec.flow
        ended: list[Range] = []
        if flow in (Flow.JUMP, Flow.LABEL_JUMP, Flow.LABEL_JUMP_MAIN, Flow.CALL) \
                and self.monitored:
            self.emit(f"{self.slot(index)} = {act}")
        if spec.negated and flow in (Flow.JUMP, Flow.LABEL_JUMP, Flow.LABEL_JUMP_MAIN, Flow.CALL):
            act = f"(not {act})"  # a flow taken when its input is 0 (S7's JMPN)
        target = number_of(op.params[0]) if op.params else None
        if flow is Flow.JUMP:
            self.jump_ids += 1
            if not off:
                self.emit(f"if {act}:")
                self.emit(f"    sk = SK[{self.unit_number}] = {self.jump_ids}")
                self.uses_sk = True
            self.guarded = False  # the ops after the JMP test `sk` afresh
            self.jumps.append(Range(self.jump_ids, counted(op.params[0] if op.params else 0)))
        elif flow is Flow.JUMP_END:
            # ends the innermost JMP 0, and any JMP n opened inside it that is still counting
            while self.jumps and self.jumps[-1].left is not None:
                ended.append(self.jumps.pop())
            if not self.jumps:
                raise self.fail(index, "JMPE without JMP")
            ended.append(self.jumps.pop())
        elif flow is Flow.COMMON:
            ident = self.common_count
            self.common_count += 1
            self.chunk_commons.add(ident)
            self.chunk_opened.add(ident)
            gate = "1" if off else act
            if self.commons:
                gate = f"{gate} & cm{self.commons[-1].ident}"
            self.emit(f"cm{ident} = CM[{ident}] = {gate}")
            self.commons.append(Range(ident, counted(op.params[0] if op.params else 0),
                                       spec.gates_boxes))
        elif flow is Flow.COMMON_END:
            for k in range(len(self.commons) - 1, -1, -1):
                if self.commons[k].left is None:
                    del self.commons[k]
                    break
        elif flow in (Flow.CALL, Flow.CALL_ALWAYS):
            if not off and target in self.structure.subprograms:
                callee = self.structure.subprograms[target]
                name = f"U{self.unit_numbers[callee.name]}"
                self.emit(f"if {act}:" if flow is Flow.CALL else "if 1:")
                self.emit(f"    {name}(ctx, M)")
        elif flow is Flow.LABEL_JUMP:
            if not off and target is not None and labelled and target in self.chunk_of_label:
                self.emit(f"if {act}:")
                self.emit(f"    return {self.chunk_of_label[target]}")
        elif flow is Flow.LABEL_JUMP_MAIN:
            if not off and target is not None:
                self.emit(f"if {act}:")
                self.emit(f"    raise JM({target})")
        elif flow is Flow.NONE:
            impl = implementation_of(spec, self.registry)
            if impl is None:
                raise BinaryFormatError(f"{spec.name} at op {index} is not implemented")
            call = len(self.impls)
            self.impls.append(impl)
            self.calls.append(index)
            out = self.var(first)
            if off:
                self.emit(f"{out} = 0")
            else:
                self.emit(f"{out} = FN[{call}](ctx, ST[{call}], ({', '.join(inputs)},), "
                          f"PA[{call}])")
        del self.values[first + 1:]
        if flow is Flow.NONE:
            self.values[first] = Value(self.var(first))
        else:
            self.values[first] = Value("0")
        return ended



def generate(ops: tuple[Op, ...], areas: dict[Area, bytearray],
             registry: dict[str, FunctionImpl], states: list[dict[str, Any]] | None = None, *,
             disabled: Collection[int] = (), monitored: bool = False,
             flow_by_op: bool = False) -> GeneratedScan:
    """Generate and compile the scan function for `ops`.

    `states` holds one dict per function call in program order and is shared between the
    variants of one program (so switching mode or disabling keeps timers and edges).
    `flow_by_op` (monitored): the power flow into the flat list `M`, as before the blocks.
    """
    generator = _Generator(ops, registry, frozenset(disabled), monitored,
                           monitored and flow_by_op)
    source = generator.run()
    if states is None:
        states = []
    while len(states) < len(ops):
        states.append({})
    namespace: dict[str, Any] = {area.value: data for area, data in areas.items()}
    namespace["FN"] = tuple(generator.impls)
    namespace["ST"] = tuple(states[index] for index in generator.calls)
    namespace["PA"] = tuple(ops[index].params for index in generator.calls)
    namespace["ZERO"] = [0] * len(ops) if monitored and flow_by_op else []
    blocks = flow_blocks(len(ops)) if monitored and not flow_by_op else ()
    namespace["FB"] = blocks
    namespace["Z"] = [0] * len(blocks[0]) if blocks else []
    namespace["SK"] = [0] * max(1, generator.unit_count)
    namespace["CM"] = [1] * max(1, generator.common_count)
    namespace["ONES"] = [1] * max(1, generator.common_count)
    namespace["SV"] = [()]
    namespace["JM"] = JumpToMain
    namespace["LOOP"] = loop_stop(ops, generator.structure.units())
    exec(compiled(source), namespace)
    return GeneratedScan(source, namespace["scan"], blocks, len(ops), namespace["ST"])

