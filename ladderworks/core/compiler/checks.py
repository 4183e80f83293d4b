"""Compile checks: the one set run by `check`, by `compile` and by the engine on a binary.

Everything the code generator could refuse is found here: stack use, control inputs, writes
to inputs, JMP/COM pairs, the program structure (levels, SP/SPE, CALL, labels), parameters and
implementations. Dispatch is on the instruction table's fields, never on spelling.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ladderworks.core.address import INPUT_AREAS, Address, AddressError, parse_address
from ladderworks.core.compiler.structure import analyse, number_of
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.il.program import Instruction, Program
from ladderworks.core.instructions import (
    Combine,
    Flow,
    InstructionSpec,
    Kind,
    Param,
    ParamKind,
    Write,
    spec_for,
    value_is_address,
    width_of,
)
from ladderworks.core.plc.families import IMPLEMENTED

if TYPE_CHECKING:
    from ladderworks.core.plc.functions import FunctionImpl

MAX_PUSHES = 8  # ST0..ST8: eight levels above ST0

# Flows the code generator turns into control flow, not function calls.
CONTROL_FLOWS = frozenset(Flow) - {Flow.NONE}

# Parameters a functional instruction writes to (its outputs), by name.
_OUTPUT_PARAMS = frozenset({"output", "result", "register"})


def output_params(name: str) -> frozenset[str]:
    """Names of the parameters instruction `name` writes to."""
    return _OUTPUT_PARAMS | {"data"} if name == "SFT" else _OUTPUT_PARAMS


def cnc_stub(ctx: object, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """A CNC-side or unknown instruction with no CNC: W1 = ACT (docs/instructions.md)."""
    return bool(inputs[-1]) if inputs else False


def implementation_of(spec: InstructionSpec,
                      registry: dict[str, FunctionImpl]) -> FunctionImpl | None:
    """The implementation of a functional instruction: the registry's, else `impl_for`'s (the
    functions package's generic entry, when it has one), else the CNC stub for an unknown SUB."""
    impl = registry.get(spec.name)
    if impl is not None:
        return impl
    from ladderworks.core.plc import functions  # loaded with the engine, never by `check`

    impl_for: Callable[[InstructionSpec], Any] | None = getattr(functions, "impl_for", None)
    if impl_for is not None and (spec.cnc or not spec.known):
        try:
            found = impl_for(spec)
        except (KeyError, LookupError):
            found = None
        if found is not None:
            return found
    return cnc_stub if not spec.known else None


def dialect_of(program: object) -> str:
    """The program's dialect: "fanuc" for LADDER-III exports, else "seed"."""
    dialect = getattr(program, "dialect", "seed")
    return dialect if isinstance(dialect, str) else "seed"


# What the checks need of an instruction table row, found once per name in a run: the row,
# whether it is BASIC, takes an operand, is a plain read (RD-like, no push), its pushes and
# its write.
_Shape = tuple[InstructionSpec, bool, bool, bool, int, Write]


def _shape(spec: InstructionSpec) -> _Shape:
    """The fields of `spec` the walk reads for every instruction."""
    return (spec, spec.kind is Kind.BASIC, spec.operand,
            spec.combine is Combine.READ and spec.pushes == 0, spec.pushes, spec.write)


# A functional instruction's parameters as the checks read them (see _Checker.layout).
_Layout = tuple[tuple[Param, ...], tuple[str, ...], Param | None, frozenset[str]]


class _Checker:
    """Walks the program once, collecting diagnostics."""

    def __init__(self, program: Program, dialect: str | None) -> None:
        self.out: list[Diagnostic] = []
        self.coils: dict[Address, tuple[Write, Instruction, int]] = {}
        self.implemented = IMPLEMENTED  # names only: `check` loads no implementation
        self.dialect = dialect or dialect_of(program)
        self.program = program
        self.jumps: list[tuple[int, Instruction, int | None]] = []  # network, JMP, coils left
        self.commons: list[tuple[int, Instruction, int | None]] = []
        # the diagnostics a functional instruction gives whatever surrounds it (its
        # implementation, parameters and the addresses it writes), by the identity of its row
        # and of its parameter tuple (the parser shares one tuple among equal lines)
        self.own: dict[tuple[int, int], list[tuple[str, dict[str, object], bool]]] = {}
        self.layouts: dict[int, _Layout] = {}  # by the identity of the row

    def add(self, code: str, ins: Instruction, network: int, *,
            warning: bool = False, **args: object) -> None:
        self.report(code, ins, network, args, warning=warning)

    def report(self, code: str, ins: Instruction, network: int, args: dict[str, object], *,
               warning: bool = False) -> None:
        self.out.append(Diagnostic(
            code, dict(args), ins.line, ins.column,
            Severity.WARNING if warning else Severity.ERROR, network))

    def specs(self) -> tuple[list[_Shape | None], list[Instruction],
                             list[tuple[InstructionSpec, tuple[object, ...]]]]:
        """The table row (as a _Shape, None if unknown) of every instruction, every instruction,
        and (row, parameters) of the known ones: the structure's items."""
        shapes: dict[str, _Shape | None] = {}
        found: list[_Shape | None] = []
        every: list[Instruction] = []
        items: list[tuple[InstructionSpec, tuple[object, ...]]] = []
        append, item = found.append, items.append
        for network in self.program.networks:
            instructions = network.instructions
            every += instructions
            for ins in instructions:
                name = ins.name
                try:
                    shape = shapes[name]
                except KeyError:
                    spec = spec_for(name, len(ins.params))
                    shape = None if spec is None else _shape(spec)
                    if spec is None or spec.known:  # an unknown SUB's row depends on the count
                        shapes[name] = shape
                append(shape)
                if shape is not None:
                    item((shape[0], ins.params))
        return found, every, items

    def run(self) -> list[Diagnostic]:
        shapes, every, items = self.specs()
        structure = analyse(items)
        bounds = {k for unit in structure.units() for k in (unit.start, unit.end)}
        add = self.add
        basic_write = self.basic_write
        previous_network = -1
        depth, logic = 0, False
        last: Instruction | None = None
        last_spec: InstructionSpec | None = None
        position = 0  # index among the known instructions (the structure's items)
        flat = 0  # index among every instruction
        for n, network in enumerate(self.program.networks):
            instructions = network.instructions
            if not instructions:
                continue
            self.end_network(previous_network, last, last_spec, logic)
            previous_network, depth, logic = n, 0, False
            broken = False  # after an unknown instruction the network is not checked further
            for ins in instructions:
                shape = shapes[flat]
                flat += 1
                if shape is None:
                    add("unknown-instruction", ins, n, name=ins.name)
                    broken = True
                    continue
                if position in bounds:
                    self.close_ranges()
                position += 1
                if broken:
                    continue
                spec, is_basic, needs_operand, plain_read, pushes, writes = shape
                last, last_spec = ins, spec
                if not is_basic:
                    depth, logic = self.other(n, ins, spec, depth, logic)
                    continue
                if needs_operand:
                    operand = ins.operand
                    if operand is None:
                        add("missing-operand", ins, n, name=spec.name)
                        continue
                    if not isinstance(operand, Address):
                        add("bad-address", ins, n, text=str(operand))
                        continue
                if plain_read:
                    logic = True
                    continue
                if not logic:
                    add("no-logic", ins, n, name=spec.name)
                    logic = True
                if pushes > 0:
                    depth += 1
                    if depth > MAX_PUSHES:
                        add("stack-depth", ins, n)
                elif pushes < 0:
                    if depth == 0:
                        add("stack-underflow", ins, n, name=spec.name)
                    else:
                        depth -= 1
                elif writes is not Write.NONE:
                    assert ins.operand is not None
                    basic_write(ins, n, spec.name, ins.operand, writes)
        self.end_network(previous_network, last, last_spec, logic)
        self.close_ranges()
        if structure.problems:
            known = [k for k, shape in enumerate(shapes) if shape is not None]
            network_at = [n for n, network in enumerate(self.program.networks)
                          for _ in network.instructions]
            for problem in structure.problems:
                index = known[problem.index]
                self.report(problem.code, every[index], network_at[index], problem.args,
                            warning=problem.warning)
        self.out.sort(key=lambda d: (d.line, d.column))
        return self.out

    def basic_write(self, ins: Instruction, network: int, name: str, address: Address,
                    kind: Write) -> None:
        """A coil: its write, then it counts for the open JMP n / COM n ranges."""
        self.write(ins, network, name, address, kind)
        if self.jumps or self.commons:
            self.count_coil()

    def end_network(self, network: int, ins: Instruction | None,
                    spec: InstructionSpec | None, logic: bool) -> None:
        if network < 0 or not logic or ins is None:
            return
        if spec is not None and spec.kind is Kind.BASIC and spec.write is Write.NONE:
            self.add("dangling-logic", ins, network, warning=True)

    def other(self, n: int, ins: Instruction, spec: InstructionSpec, depth: int,
              logic: bool) -> tuple[int, bool]:
        """A functional (or END) instruction: its inputs from the stack, then its own checks."""
        if spec.kind is Kind.END:
            return depth, logic
        count = len(spec.inputs)
        if count:
            if not logic:
                self.add("no-logic", ins, n, name=spec.name)
            elif depth < count - 1:
                self.add("box-inputs", ins, n, name=spec.name, count=count)
            depth = max(0, depth - (count - 1))
        logic = spec.w1 or logic
        self.function(ins, spec, n)
        return depth, logic

    def count_coil(self) -> None:
        """A coil counts for the innermost JMP n and COM n ranges (as the generated code)."""
        for ranges in (self.jumps, self.commons):
            if ranges and ranges[-1][2] is not None:
                network, ins, left = ranges[-1]
                assert left is not None
                if left <= 1:
                    ranges.pop()
                else:
                    ranges[-1] = (network, ins, left - 1)

    def write(self, ins: Instruction, network: int, name: str, address: Address,
              kind: Write | None) -> None:
        before = None if kind is None else self.coils.get(address)
        if before is None:  # an address in self.coils was found writable before
            if address.area in INPUT_AREAS:
                self.add("write-input", ins, network, name=name, address=str(address))
            elif address.is_result_register():
                self.add("write-result-register", ins, network, name=name,
                         address=str(address))
            elif kind is not None:
                self.coils[address] = (kind, ins, network)
            return
        if kind is Write.OUT and before[0] is Write.OUT:
            self.add("coil-twice", ins, network, warning=True, address=str(address))
        elif (kind is Write.OUT) != (before[0] is Write.OUT):
            if before[1].line > 0:
                self.add("coil-mixed", ins, network, warning=True,
                         address=str(address), line=before[1].line)
            else:  # compiled from the drawing: no line 0, the network it is in
                self.add("coil-mixed-network", ins, network, warning=True,
                         address=str(address), other=before[2] + 1)
        if kind is Write.OUT:
            self.coils[address] = (kind, ins, network)

    def function(self, ins: Instruction, spec: InstructionSpec, network: int) -> None:
        flow = spec.flow
        coils = ins.params[0] if ins.params and isinstance(ins.params[0], int) else 0
        if flow is Flow.JUMP:
            self.jumps.append((network, ins, coils if coils > 0 else None))
        elif flow is Flow.JUMP_END:
            while self.jumps and self.jumps[-1][2] is not None:
                self.jumps.pop()
            if self.jumps:
                self.jumps.pop()
            else:
                self.add("jmpe-without-jmp", ins, network)
        elif flow is Flow.COMMON:
            self.commons.append((network, ins, coils if coils > 0 else None))
        elif flow is Flow.COMMON_END:
            for k in range(len(self.commons) - 1, -1, -1):
                if self.commons[k][2] is None:
                    del self.commons[k]
                    break
            else:
                self.add("come-without-com", ins, network)
        elif flow is Flow.LABEL and (self.jumps or self.commons):
            self.add("label-in-range", ins, network)
        self.own_checks(ins, spec, network)

    def own_checks(self, ins: Instruction, spec: InstructionSpec, network: int) -> None:
        """The checks of a functional instruction that depend on it alone (found once for
        the lines that share a row and a parameter tuple, then repeated at each)."""
        key = (id(spec), id(ins.params))
        found = self.own.get(key)
        if found is None:
            out, self.out = self.out, []
            if spec.flow is Flow.NONE:
                if not spec.known:
                    self.add("unknown-sub", ins, network, warning=True, number=spec.sub)
                elif spec.name not in self.implemented:
                    self.add("not-implemented", ins, network, name=spec.name)
            self.params(ins, spec, network)
            found = [(d.code, d.args, d.severity is Severity.WARNING) for d in self.out]
            self.own[key] = found
            self.out = out
        for code, args, warning in found:
            self.report(code, ins, network, args, warning=warning)

    def close_ranges(self) -> None:
        """At the end of a unit: its JMP 0 / COM 0 ranges must be closed."""
        for network, ins, left in self.jumps:
            if left is None:
                self.add("jmp-without-jmpe", ins, network)
        for network, ins, left in self.commons:
            if left is None:
                self.add("com-without-come", ins, network)
        self.jumps.clear()
        self.commons.clear()

    def layout(self, spec: InstructionSpec) -> _Layout:
        """The fixed parameters of `spec`, its table parameter and its outputs' names."""
        found = self.layouts.get(id(spec))
        if found is None:
            fixed = spec.fixed_params()
            found = (fixed, tuple(p.name for p in fixed), spec.table_param(),
                     output_params(spec.name))
            self.layouts[id(spec)] = found
        return found

    def params(self, ins: Instruction, spec: InstructionSpec, network: int) -> None:
        fixed, names, table, outputs = self.layout(spec)
        values: dict[str, object] = dict(zip(names, ins.params, strict=False))  # param_map()
        if table is not None:
            values[table.name] = tuple(ins.params[len(fixed):])
        expected = len(fixed)
        if table is not None:
            size = values.get(table.length_of)
            expected += size if isinstance(size, int) else 0
        if len(ins.params) != expected:
            self.add("param-count", ins, network, name=spec.name, expected=expected,
                     found=len(ins.params))
            return
        for number, (param, raw) in enumerate(zip(fixed, ins.params, strict=False), 1):
            info: dict[str, object] = {"name": spec.name, "index": number, "param": param.name}
            value: int | Address
            if param.kind in (ParamKind.PROGRAM, ParamKind.LABEL):
                target = number_of(raw)
                if target is None:
                    self.report("param-kind-number", ins, network, {**info, "text": "?"})
                    continue
                value = target
            elif isinstance(raw, int | Address):
                value = raw
            else:  # a P/L reference where a number or an address belongs
                self.report("param-kind-number", ins, network, {**info, "text": str(raw)})
                continue
            address_wanted = param.kind is ParamKind.ADDRESS or (
                param.kind is ParamKind.VALUE and value_is_address(spec, values) is True)
            if isinstance(value, Address):
                if not param.allows_address() or (
                        param.kind is ParamKind.VALUE
                        and value_is_address(spec, values) is False):
                    self.report("param-kind-number", ins, network, {**info, "text": str(value)})
                    continue
                width = width_of(spec, param, values)
                try:
                    parse_address(str(value), want_bit=False, width=width)
                except AddressError as exc:
                    self.report(exc.code, ins, network, exc.args_map)
                    continue
                if param.name in outputs:
                    self.write(ins, network, spec.name, value, None)
                continue
            hi = param.highest(self.dialect)
            if address_wanted:
                self.report("param-kind-address", ins, network, {**info, "text": str(value)})
            elif param.choices and value not in param.choices:
                self.report("param-choice", ins, network, {
                    **info, "value": value,
                    "choices": ", ".join(str(c) for c in param.choices)})
            elif not param.lo <= value <= hi:
                self.report("param-range", ins, network,
                            {**info, "lo": param.lo, "hi": hi, "value": value})
        if table is not None:
            for offset, item in enumerate(ins.params[len(fixed):]):
                if not isinstance(item, int) or not table.lo <= item <= table.hi:
                    self.add("param-range", ins, network, name=spec.name,
                             index=len(fixed) + offset + 1, param=table.name, lo=table.lo,
                             hi=table.hi, value=str(item))


def check(program: Program, dialect: str | None = None) -> list[Diagnostic]:
    """Every compile diagnostic of `program` (errors and warnings), in program order.

    `compile` runs exactly these; a program they pass always compiles and generates.
    `dialect` overrides the program's own ("seed" or "fanuc": the ranges of numbers).
    """
    return _Checker(program, dialect).run()
