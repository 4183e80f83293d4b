"""Compile checks: stack use, writes to inputs, jump/common-line pairs, parameters, coils."""

from __future__ import annotations

from ladderworks.core.address import INPUT_AREAS, Address, AddressError, parse_address
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.il.program import Instruction, Program
from ladderworks.core.instructions import Kind, ParamKind, lookup, value_is_address, width_of
from ladderworks.core.plc.functions import load_all

MAX_PUSHES = 8  # ST0..ST8: eight levels above ST0

# Functional instructions the code generator turns into control flow, not REGISTRY calls.
CONTROL_FLOW = frozenset({"JMP", "JMPE", "COM", "COME"})

# Parameters a functional instruction writes to (its outputs), by name.
_OUTPUT_PARAMS = frozenset({"output", "result", "register"})


def output_params(name: str) -> frozenset[str]:
    """Names of the parameters instruction `name` writes to."""
    return _OUTPUT_PARAMS | {"data"} if name == "SFT" else _OUTPUT_PARAMS


class _Checker:
    """Walks the program once, collecting diagnostics."""

    def __init__(self) -> None:
        self.out: list[Diagnostic] = []
        self.coils: dict[Address, Instruction] = {}
        self.jumps: list[tuple[int, Instruction]] = []
        self.commons: list[tuple[int, Instruction]] = []
        self.registry = load_all()

    def add(self, code: str, ins: Instruction, network: int, *,
            warning: bool = False, **args: object) -> None:
        self.report(code, ins, network, args, warning=warning)

    def report(self, code: str, ins: Instruction, network: int, args: dict[str, object], *,
               warning: bool = False) -> None:
        self.out.append(Diagnostic(
            code, dict(args), ins.line, ins.column,
            Severity.WARNING if warning else Severity.ERROR, network))

    def run(self, program: Program) -> list[Diagnostic]:
        for index, network in enumerate(program.networks):
            self.network(index, network.instructions)
        for at, ins in self.jumps:
            self.add("jmp-without-jmpe", ins, at)
        for at, ins in self.commons:
            self.add("com-without-come", ins, at)
        return self.out

    def network(self, index: int, instructions: list[Instruction]) -> None:
        depth = 0
        logic = False
        for ins in instructions:
            spec = lookup(ins.name)
            if spec is None:
                self.add("unknown-instruction", ins, index, name=ins.name)
                return
            if spec.kind is Kind.BASIC:
                if spec.operand and ins.operand is None:
                    self.add("missing-operand", ins, index, name=spec.name)
                    continue
                if spec.operand and not isinstance(ins.operand, Address):
                    self.add("bad-address", ins, index, text=str(ins.operand))
                    continue
                if spec.name in ("RD", "RD.NOT"):
                    logic = True
                    continue
                if not logic:
                    self.add("no-logic", ins, index, name=spec.name)
                    logic = True
                if spec.pushes > 0:
                    depth += 1
                    if depth > MAX_PUSHES:
                        self.add("stack-depth", ins, index)
                elif spec.pushes < 0:
                    if depth == 0:
                        self.add("stack-underflow", ins, index, name=spec.name)
                    else:
                        depth -= 1
                elif spec.writes:
                    assert ins.operand is not None
                    self.write(ins, index, spec.name, ins.operand, coil=True)
                continue
            if spec.kind is Kind.END:
                continue
            count = len(spec.inputs)
            if count:
                if not logic:
                    self.add("no-logic", ins, index, name=spec.name)
                elif depth < count - 1:
                    self.add("box-inputs", ins, index, name=spec.name, count=count)
                depth = max(0, depth - (count - 1))
            logic = spec.w1 or logic
            self.function(ins, index)
        if instructions and logic:
            last = lookup(instructions[-1].name)
            if last is not None and last.kind is Kind.BASIC and not last.writes:
                self.add("dangling-logic", instructions[-1], index, warning=True)

    def write(self, ins: Instruction, network: int, name: str, address: Address, *,
              coil: bool) -> None:
        if address.area in INPUT_AREAS:
            self.add("write-input", ins, network, name=name, address=str(address))
        elif address.is_result_register():
            self.add("write-result-register", ins, network, name=name, address=str(address))
        elif coil:
            if address in self.coils:
                self.add("coil-twice", ins, network, warning=True, address=str(address))
            self.coils[address] = ins

    def function(self, ins: Instruction, network: int) -> None:
        spec = ins.spec
        if spec.name == "JMP":
            if ins.params and ins.params[0] == 0:  # JMP n > 0 ends after n coils, no JMPE
                self.jumps.append((network, ins))
        elif spec.name == "JMPE":
            if self.jumps:
                self.jumps.pop()
            else:
                self.add("jmpe-without-jmp", ins, network)
        elif spec.name == "COM":
            if ins.params and ins.params[0] == 0:  # COM n > 0 ends after n coils, no COME
                self.commons.append((network, ins))
        elif spec.name == "COME":
            if self.commons:
                self.commons.pop()
            else:
                self.add("come-without-com", ins, network)
        elif spec.name not in self.registry:
            self.add("not-implemented", ins, network, name=spec.name)
        self.params(ins, network)

    def params(self, ins: Instruction, network: int) -> None:
        spec = ins.spec
        fixed = spec.fixed_params()
        table = spec.table_param()
        values = ins.param_map()
        expected = len(fixed)
        if table is not None:
            size = values.get(table.length_of)
            expected += size if isinstance(size, int) else 0
        if len(ins.params) != expected:
            self.add("param-count", ins, network, name=spec.name, expected=expected,
                     found=len(ins.params))
            return
        outputs = output_params(spec.name)
        for number, (param, value) in enumerate(zip(fixed, ins.params, strict=False), 1):
            info: dict[str, object] = {"name": spec.name, "index": number, "param": param.name}
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
                    self.write(ins, network, spec.name, value, coil=False)
                continue
            if address_wanted:
                self.report("param-kind-address", ins, network, {**info, "text": str(value)})
            elif param.choices and value not in param.choices:
                self.report("param-choice", ins, network, {
                    **info, "value": value,
                    "choices": ", ".join(str(c) for c in param.choices)})
            elif not param.lo <= value <= param.hi:
                self.report("param-range", ins, network,
                            {**info, "lo": param.lo, "hi": param.hi, "value": value})
        if table is not None:
            for offset, value in enumerate(ins.params[len(fixed):]):
                if isinstance(value, Address) or not table.lo <= value <= table.hi:
                    self.add("param-range", ins, network, name=spec.name,
                             index=len(fixed) + offset + 1, param=table.name, lo=table.lo,
                             hi=table.hi, value=str(value))


def check(program: Program) -> list[Diagnostic]:
    """Every compile diagnostic of `program` (errors and warnings), in program order."""
    return _Checker().run(program)
