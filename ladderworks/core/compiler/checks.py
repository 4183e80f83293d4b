"""Compile checks: the one set run by `check`, by `compile` and by the engine on a binary.

Everything the code generator could refuse is found here: stack use, control inputs, writes
to inputs, JMP/COM pairs, the program structure (levels, SP/SPE, CALL, labels), parameters and
implementations. Dispatch is on the instruction table's fields, never on spelling.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from itertools import compress, count
from operator import attrgetter
from typing import TYPE_CHECKING

from ladderworks.core.address import (
    AREA_RANGES,
    INPUT_AREAS,
    Address,
    AddressError,
    parse_address,
)
from ladderworks.core.collector import collector_paused
from ladderworks.core.compiler.implementations import cnc_stub as cnc_stub
from ladderworks.core.compiler.implementations import implementation_of as implementation_of
from ladderworks.core.compiler.structure import (
    FlowItem,
    Structure,
    analyse_flows,
    number_of,
)
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.il.model_check import model_address_problems
from ladderworks.core.il.program import Instruction, Program
from ladderworks.core.instructions import (
    Combine,
    Flow,
    InstructionSpec,
    Kind,
    Param,
    ParamAccess,
    ParamKind,
    StackOp,
    Write,
    spec_for,
    value_is_address,
    width_of,
)
from ladderworks.core.plc.families import IMPLEMENTED

if TYPE_CHECKING:
    from ladderworks.core.dialects.base import Dialect

MAX_PUSHES = 8  # ST0..ST8: eight levels above ST0

# Flows the code generator turns into control flow, not function calls.
CONTROL_FLOWS = frozenset(Flow) - {Flow.NONE}

# Enum members read on every instruction, as module constants: reading one as `Write.OUT`
# goes through the Enum metaclass (about 200 ns in Python 3.11), a global does not.
_OUT, _NO_WRITE = Write.OUT, Write.NONE
_NO_FLOW = Flow.NONE
_END = Kind.END
_WARNING, _ERROR = Severity.WARNING, Severity.ERROR
_STARTS = Combine.READ

# The accesses of a parameter the checks treat as a write (no input address there).
_OUTPUTS = frozenset({ParamAccess.WRITE, ParamAccess.READ_WRITE})


def dialect_of(program: object) -> str:
    """The program's dialect: "fanuc" for LADDER-III exports, else "seed"."""
    dialect = getattr(program, "dialect", "seed")
    return dialect if isinstance(dialect, str) else "seed"


# What the walk does at an instruction, by its table row (found once per name in a run).
_READ = 0  # a contact starting the logic (RD, RD.NOT)
_CONTACT = 1  # a contact joining the logic before it (AND, OR.NOT, ...): with _READ, most
_WRITE = 2  # a coil writing its operand (WRT, SET, ...)
_BASIC = 3  # any other basic instruction (the stack operations)
_OTHER = 4  # a functional instruction or END
_FLOW = 5  # a functional instruction or END with a part in the structure (Flow is not NONE)
_UNKNOWN = 6  # no row: an unknown instruction

# An instruction's step in the walk: its action, its row, and whether a unit (level or
# subprogram) starts there, closing the JMP/COM ranges of the one before.
_Step = tuple[int, InstructionSpec | None, bool]
_UNKNOWN_STEP: _Step = (_UNKNOWN, None, False)


def _step(spec: InstructionSpec | None) -> _Step:
    """The step of an instruction with row `spec` (None: unknown)."""
    if spec is None:
        return _UNKNOWN_STEP
    if spec.kind is not Kind.BASIC:
        return (_OTHER if spec.flow is Flow.NONE else _FLOW, spec, False)
    if not spec.operand or spec.pushes != 0:
        return (_BASIC, spec, False)
    reads, writes = spec.combine is Combine.READ, spec.write is not Write.NONE
    if reads and not writes:
        return (_READ, spec, False)
    if not reads:
        return (_WRITE if writes else _CONTACT, spec, False)
    return (_BASIC, spec, False)  # no such row: the walk's general path


_NAME = attrgetter("name")


# A fixed parameter as the checks read it: the row's Param; whether it holds a P/L number,
# may hold an address, is a VALUE, is an ADDRESS, is an output; its upper limit in the
# dialect; its width in bytes (None when a format parameter gives it).
_ParamPlan = tuple[Param, bool, bool, bool, bool, bool, int, int | None]

# A functional instruction's parameters as the checks read them (see _Checker.layout).
_Layout = tuple[tuple[_ParamPlan, ...], tuple[str, ...], Param | None, bool]

_NUMBER_OR_ADDRESS = (int, Address)  # what a parameter holds (a P/L reference aside)

# A diagnostic found once for the lines that share it: code, arguments, whether a warning.
_Own = tuple[str, dict[str, object], bool]


class _Checker:
    """Walks the program once, collecting diagnostics."""

    def __init__(self, program: Program, dialect: str | None, by_network: bool) -> None:
        self.out: list[Diagnostic] = []
        self.coils: dict[tuple[object, ...], tuple[Write, Instruction, int]] = {}  # see write
        self.by_network = by_network  # see check()
        self.dialect = dialect or dialect_of(program)
        self.program = program
        self.jumps: list[tuple[int, Instruction, int | None]] = []  # network, JMP, coils left
        self.commons: list[tuple[int, Instruction, int | None]] = []
        # the diagnostics a functional instruction gives whatever surrounds it (its
        # implementation, parameters and the addresses it writes), by the identity of its row
        # and of its parameter tuple (the parser shares one tuple among equal lines)
        self.own: dict[tuple[int, int], list[_Own]] = {}
        self.layouts: dict[int, _Layout] = {}  # by the identity of the row
        found = self.rules = dialect_rules(self.dialect)  # a dialect's (core/dialects), or None
        self.fits: Callable[[Address, int], bool] = _byte_data_fits if found is None \
            else found.devices.holds
        self.spell: Callable[[Address], str] = str if found is None else found.format_address

    def add(self, code: str, ins: Instruction, network: int, *,
            warning: bool = False, **args: object) -> None:
        self.report(code, ins, network, args, warning=warning)

    def report(self, code: str, ins: Instruction, network: int, args: dict[str, object], *,
               warning: bool = False) -> None:
        """A diagnostic at `ins` with `args` (its own dict: callers copy one they share)."""
        self.out.append(Diagnostic(
            code, args, ins.line, ins.column,
            _WARNING if warning else _ERROR, network))

    def steps(self) -> tuple[list[_Step], list[Instruction], Sequence[int], list[FlowItem]]:
        """The step of every instruction, every instruction, the index in them of each known
        instruction (of the structure's items), and the structure's flow items."""
        every: list[Instruction] = []
        for network in self.program.networks:
            every += network.instructions
        # map and compress run in C, where a Python loop over every instruction costs more
        names = list(map(_NAME, every))
        by_name: dict[str, _Step] = {}
        counted: set[str] = set()  # unknown SUBs: their row depends on the parameter count
        for name in set(names):
            spec = spec_for(name)
            if spec is None or spec.known:
                by_name[name] = _step(spec)
            else:
                counted.add(name)
        if counted:
            steps = [_step(spec_for(name, len(ins.params))) if name in counted
                     else by_name[name] for name, ins in zip(names, every, strict=True)]
        else:
            steps = list(map(by_name.__getitem__, names))
        unknown = {name for name, step in by_name.items() if step is _UNKNOWN_STEP}
        known: Sequence[int] = range(len(steps))
        if unknown:
            known = list(compress(count(), map((set(names) - unknown).__contains__, names)))
        flows: list[FlowItem] = []
        flow_names = {name for name, step in by_name.items() if step[0] == _FLOW}
        if flow_names:
            position = dict(zip(known, count())) if unknown else None
            for k in compress(count(), map(flow_names.__contains__, names)):
                spec = steps[k][1]
                assert spec is not None
                flows.append((k if position is None else position[k], spec, every[k].params))
        return steps, every, known, flows

    def mark_unit_starts(self, steps: list[_Step], structure: Structure,
                         known: Sequence[int]) -> None:
        """Mark the steps where a unit starts or the one before ends (the ranges of JMP n
        and COM n close there)."""
        for unit in structure.units():
            for position in (unit.start, unit.end):
                if position < len(known):
                    action, spec, _ = steps[known[position]]
                    steps[known[position]] = (action, spec, True)

    def operand_problem(self, ins: Instruction, network: int, spec: InstructionSpec) -> None:
        """An instruction that needs an address as its operand has none, or no address."""
        if ins.operand is None:
            self.add("missing-operand", ins, network, name=spec.name)
        else:
            self.add("bad-address", ins, network, text=str(ins.operand))

    def run(self) -> list[Diagnostic]:
        steps, every, known, flows = self.steps()
        structure = analyse_flows(len(known), flows)
        self.mark_unit_starts(steps, structure, known)
        add, write = self.add, self.write
        jumps, commons = self.jumps, self.commons
        previous_network = -1
        depth, logic = 0, False
        last: Instruction | None = None  # the last instruction checked
        dangles = False  # it is a basic instruction that is not a coil
        all_steps = iter(steps)
        for n, network in enumerate(self.program.networks):
            instructions = network.instructions
            if not instructions:
                continue
            if logic and dangles:
                self.dangling(last, previous_network)
            previous_network, depth, logic = n, 0, False
            # zip takes the instruction first: at the network's end it stops, taking no step
            walk = zip(instructions, all_steps)  # noqa: B905
            for ins, (action, spec, starts_unit) in walk:
                if starts_unit:
                    self.close_ranges()
                if action <= _CONTACT:
                    last, dangles = ins, True
                    if isinstance(ins.operand, Address) and (logic or action == _READ):
                        logic = True
                        continue
                    assert spec is not None
                    if not isinstance(ins.operand, Address):
                        self.operand_problem(ins, n, spec)
                    else:
                        add("no-logic", ins, n, name=spec.name)
                        logic = True
                    continue
                if spec is None:  # after an unknown instruction the network is not checked
                    add("unknown-instruction", ins, n, name=ins.name)
                    for ins, (_, rest_spec, rest_starts_unit) in walk:
                        if rest_spec is None:
                            add("unknown-instruction", ins, n, name=ins.name)
                        elif rest_starts_unit:
                            self.close_ranges()
                    break
                last = ins
                if action >= _OTHER:
                    dangles = False
                    depth, logic = self.other(n, ins, spec, depth, logic)
                    continue
                if action == _WRITE:
                    dangles = False
                    operand = ins.operand
                    if not isinstance(operand, Address):
                        self.operand_problem(ins, n, spec)
                        continue
                    if not logic:
                        add("no-logic", ins, n, name=spec.name)
                        logic = True
                    write(ins, n, spec.name, operand, spec.write)
                    if jumps or commons:
                        self.count_coil()
                    continue
                dangles = spec.write is _NO_WRITE
                if spec.operand and not isinstance(ins.operand, Address):
                    self.operand_problem(ins, n, spec)
                    continue
                depth, logic = self.basic(ins, n, spec, depth, logic)
        if logic and dangles:
            self.dangling(last, previous_network)
        self.close_ranges()
        if structure.problems:
            network_at = [n for n, network in enumerate(self.program.networks)
                          for _ in network.instructions]
            for problem in structure.problems:
                index = known[problem.index]
                self.report(problem.code, every[index], network_at[index],
                            dict(problem.args), warning=problem.warning)
        self.out.sort(key=lambda d: (d.line, d.column))
        if self.rules is not None:  # a dialect's program: its own words
            return [self.rules.localize(d) for d in self.out]
        return self.out

    def basic(self, ins: Instruction, n: int, spec: InstructionSpec, depth: int,
              logic: bool) -> tuple[int, bool]:
        """A basic instruction other than a contact or a coil with its operand: a push or pop
        of the stack, in general."""
        if spec.combine is _STARTS and spec.pushes == 0:
            return depth, True
        if not logic:
            self.add("no-logic", ins, n, name=spec.name)
            logic = True
        if spec.pushes > 0:
            depth += 1
            if depth > MAX_PUSHES:
                self.add("stack-depth", ins, n)
        elif spec.pushes < 0:
            if depth == 0:
                self.add("stack-underflow", ins, n, name=spec.name)
            else:
                depth -= 1
        elif spec.stack is StackOp.OVER and depth == 0:  # Delta MRD with no MPS before it
            self.add("stack-underflow", ins, n, name=spec.name)
        elif spec.write is not _NO_WRITE:
            assert ins.operand is not None
            self.write(ins, n, spec.name, ins.operand, spec.write)
            if self.jumps or self.commons:
                self.count_coil()
        return depth, logic

    def dangling(self, last: Instruction | None, network: int) -> None:
        """A network that ends in logic no coil takes."""
        assert last is not None
        self.add("dangling-logic", last, network, warning=True)

    def other(self, n: int, ins: Instruction, spec: InstructionSpec, depth: int,
              logic: bool) -> tuple[int, bool]:
        """A functional (or END) instruction: its inputs from the stack, then its own checks."""
        if spec.kind is _END:
            return depth, logic
        count = len(spec.inputs)
        if count:
            if not logic:
                self.add("no-logic", ins, n, name=spec.name)
            elif depth < count - 1:
                self.add("box-inputs", ins, n, name=spec.name, count=count)
            depth = max(0, depth - (count - 1))
        elif spec.pushes > 0:  # a contact-like box pushing a new value (Delta LD= in a rung)
            if not logic:
                self.add("no-logic", ins, n, name=spec.name)
            depth += spec.pushes
            if depth > MAX_PUSHES:
                self.add("stack-depth", ins, n)
        logic = spec.w1 or logic
        if spec.flow is not _NO_FLOW:
            self.flow(ins, spec, n)
        self.own_checks(ins, spec, n)
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
              kind: Write) -> None:
        """A coil's write: refused in an input area, a warning when the address has a coil."""
        # keyed by the fields: a tuple hashes in C, Address's dataclass hash is Python code
        key = (address.area, address.byte, address.bit)
        if self.rules is not None and self.rules.local_bits and self.rules.is_local(address):
            return  # a bit each network uses afresh (Fatek's TR points)
        before = self.coils.get(key)
        if before is None:  # an address in self.coils was found writable before
            problem = _write_problem(name, address, self.spell)
            if problem is not None:
                self.report(problem[0], ins, network, problem[1])
            else:
                self.coils[key] = (kind, ins, network)
            return
        if kind is _OUT and before[0] is _OUT:
            self.report("coil-twice", ins, network, {"address": self.spell(address)},
                        warning=True)
        elif (kind is _OUT) != (before[0] is _OUT):
            if before[1].line > 0 and not self.by_network:
                self.report("coil-mixed", ins, network,
                            {"address": self.spell(address), "line": before[1].line},
                            warning=True)
            else:  # no source line (drawn), or the console's: the network it is in
                self.report("coil-mixed-network", ins, network,
                            {"address": self.spell(address), "other": before[2] + 1},
                            warning=True)
        if kind is _OUT:
            self.coils[key] = (kind, ins, network)

    def flow(self, ins: Instruction, spec: InstructionSpec, network: int) -> None:
        """A functional instruction with a part in the structure: JMP/COM ranges, labels."""
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

    def own_checks(self, ins: Instruction, spec: InstructionSpec, network: int) -> None:
        """The checks of a functional instruction that depend on it alone (found once for
        the lines that share a row and a parameter tuple, then repeated at each)."""
        key = (id(spec), id(ins.params))
        found = self.own.get(key)
        if found is None:
            found = []
            if spec.flow is _NO_FLOW:
                if not spec.known:
                    found.append(("unknown-sub", {"number": spec.sub}, True))
                elif not spec.simulated:  # kept, drawn and saved; the scan passes it by
                    if not spec.cnc:  # a dialect's own FUN stub: its reader says so
                        found.append(("not-simulated", {"name": spec.text_name}, True))
                elif spec.name not in IMPLEMENTED:  # names only: `check` loads no functions
                    found.append(("not-implemented", {"name": spec.name}, False))
            found += self.params(spec, ins.params)
            self.own[key] = found
        for code, args, warning in found:
            self.report(code, ins, network, dict(args), warning=warning)

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
        """The fixed parameters of `spec` (as _ParamPlans), its table parameter, and whether
        the checks read parameters by name (a VALUE, a width given by a format, a table)."""
        found = self.layouts.get(id(spec))
        if found is None:
            fixed = spec.fixed_params()
            plans = tuple(
                (param, param.kind in (ParamKind.PROGRAM, ParamKind.LABEL),
                 param.allows_address(), param.kind is ParamKind.VALUE,
                 param.kind is ParamKind.ADDRESS, param.access in _OUTPUTS,
                 param.highest(self.dialect),
                 param.width if isinstance(param.width, int) else None)
                for param in fixed)
            table = spec.table_param()
            by_name = table is not None or any(
                plan[3] or plan[7] is None for plan in plans)
            found = (plans, tuple(p.name for p in fixed), table, by_name)
            self.layouts[id(spec)] = found
        return found

    def params(self, spec: InstructionSpec, raws: tuple[object, ...]) -> list[_Own]:
        """The diagnostics of parameters `raws` of an instruction of row `spec`."""
        plans, names, table, by_name = self.layouts.get(id(spec)) or self.layout(spec)
        name = spec.name
        # param_map(), built only for the rows that read it (zip's strict= costs a keyword call)
        values: dict[str, object] = dict(zip(names, raws)) if by_name else {}  # noqa: B905
        fixed = len(plans)
        expected = fixed
        if table is not None:
            values[table.name] = tuple(raws[fixed:])
            size = values.get(table.length_of)
            expected += size if isinstance(size, int) else 0
        if len(raws) != expected:
            return [("param-count", {"name": name, "expected": expected, "found": len(raws)},
                     False)]
        found: list[_Own] = []
        for number, plan in enumerate(plans, 1):
            param, target, may_address, is_value, is_address, output, hi, width = plan
            raw = raws[number - 1]
            value: int | Address
            if target:
                program_or_label = number_of(raw)
                if program_or_label is None:
                    found.append(("param-kind-number", {
                        "name": name, "index": number, "param": param.name, "text": "?"}, False))
                    continue
                value = program_or_label
            elif isinstance(raw, _NUMBER_OR_ADDRESS):
                value = raw
            else:  # a P/L reference where a number or an address belongs
                found.append(("param-kind-number", {
                    "name": name, "index": number, "param": param.name, "text": str(raw)},
                    False))
                continue
            chosen = value_is_address(spec, values) if is_value else None
            if isinstance(value, Address):
                if not may_address or chosen is False:
                    found.append(("param-kind-number", {
                        "name": name, "index": number, "param": param.name,
                        "text": str(value)}, False))
                    continue
                if width is None:
                    width = width_of(spec, param, values)
                if not self.fits(value, width):
                    if self.fits is not _byte_data_fits:  # a dialect's: no device there
                        found.append(("device-range", {"text": self.spell(value),
                                                       "first": "", "last": ""}, False))
                        continue
                    try:  # the parse of its spelling says why, as for a typed address
                        parse_address(str(value), want_bit=False, width=width)
                    except AddressError as exc:
                        found.append((exc.code, exc.args_map, False))
                        continue
                if output:
                    problem = _write_problem(name, value, self.spell)
                    if problem is not None:
                        found.append((*problem, False))
                continue
            if is_address or chosen is True:
                found.append(("param-kind-address", {
                    "name": name, "index": number, "param": param.name, "text": str(value)},
                    False))
            elif param.choices and value not in param.choices:
                found.append(("param-choice", {
                    "name": name, "index": number, "param": param.name, "value": value,
                    "choices": ", ".join(str(c) for c in param.choices)}, False))
            elif not param.lo <= value <= hi:
                found.append(("param-range", {
                    "name": name, "index": number, "param": param.name, "lo": param.lo,
                    "hi": hi, "value": value}, False))
        if table is not None:
            for offset, item in enumerate(raws[fixed:]):
                if not isinstance(item, int) or not table.lo <= item <= table.hi:
                    found.append(("param-range", {
                        "name": name, "index": fixed + offset + 1, "param": table.name,
                        "lo": table.lo, "hi": table.hi, "value": str(item)}, False))
        return found


def _byte_data_fits(address: Address, width: int) -> bool:
    """True when `address` is a byte address with room for `width` bytes: what parsing its
    spelling with want_bit=False accepts, found without formatting and parsing it."""
    byte = address.byte
    if address.bit is not None or type(byte) is not int:
        return False
    last = byte + max(width, 1) - 1
    for lo, hi in AREA_RANGES[address.area]:  # noqa: SIM110 (any() of a generator is slower)
        if lo <= byte and last <= hi:
            return True
    return False


def _write_problem(name: str, address: Address, spell: Callable[[Address], str] = str
                   ) -> tuple[str, dict[str, object]] | None:
    """Why instruction `name` may not write `address` (code and arguments), None if it may."""
    if address.area in INPUT_AREAS:
        return "write-input", {"name": name, "address": spell(address)}
    if address.is_result_register():
        return "write-result-register", {"name": name, "address": spell(address)}
    return None


def dialect_rules(name: str) -> Dialect | None:
    """The registered dialect called `name` (its devices rule the ranges), None for the PMC's."""
    if name in ("seed", "fanuc"):
        return None
    from ladderworks.core import dialects  # only a dialect's program loads the registry

    return dialects.get(name)


def check(program: Program, dialect: str | None = None, *,
          by_network: bool = False) -> list[Diagnostic]:
    """Every compile diagnostic of `program` (errors and warnings), in program order.

    `compile` runs exactly these; a program they pass always compiles and generates.
    `dialect` overrides the program's own ("seed" or "fanuc": the ranges of numbers).
    `by_network`: a message naming another place names its network, not its source line
    (the console, whose unchanged networks keep the lines they were read from).
    """
    # no cycle collection meanwhile: the checks make tens of thousands of objects and no
    # cycles, and a collection would walk the program's whole heap (as parse and xref do)
    with collector_paused():
        found = _Checker(program, dialect, by_network).run()
    # the addresses against the map of the program's model (a seed program: the seed's)
    return found + model_address_problems(program, dialect or dialect_of(program),
                                          by_network=by_network)
