"""An S7 block's graph (graph.py) as the engine's networks of instructions.

Power is followed from the rail through each part in the order of the wires: contacts, O
branches, comparisons and other pure tests become an expression on the engine's stack (RD /
AND / OR / RD.STK / AND.STK / OR.STK and the one-input boxes); every part that acts (a coil, a
box, a timer, a jump) is emitted where its inputs are known, as an engine network of its own,
and when its output feeds further parts it is kept in a LadderWorks relay (R8192-R8999) that
they read. A part the lowering cannot map gives a diagnostic at its network and part.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from ladderworks.core.address import Address, Area
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.dialects.s7 import boxes, calls, system_tags
from ladderworks.core.dialects.s7.graph import (
    Block,
    Operand,
    OperandKind,
    Part,
    S7Network,
)
from ladderworks.core.dialects.s7.layout import Layout, Place, constant_type, constant_value
from ladderworks.core.dialects.s7.stack import ALWAYS_OFF, ALWAYS_ON, Expr, PinGraph, emit_expr
from ladderworks.core.dialects.s7.starts import lreal_constant, start_values
from ladderworks.core.il.program import Instruction, LabelRef, Network, ParamValue
from ladderworks.core.plc import typed

SCRATCH_FIRST, SCRATCH_LAST = 8192, 8999  # R bytes LadderWorks keeps for a network's links
PURE = {"Eq": "S7.EQ", "Ne": "S7.NE", "Gt": "S7.GT", "Lt": "S7.LT", "Ge": "S7.GE", "Le": "S7.LE",
        "InRange": "S7.IN_RANGE", "OutRange": "S7.OUT_RANGE", "Ok": "S7.OK",
        "NotOk": "S7.NOT_OK"}
TIMERS = {"TP": "S7.TP", "TON": "S7.TON", "TOF": "S7.TOF", "TONR": "S7.TONR"}
COUNTERS = {"CTU": "S7.CTU", "CTD": "S7.CTD", "CTUD": "S7.CTUD"}
COILS = {"Coil": "WRT", "SCoil": "SET", "RCoil": "RST"}
_TEMPLATE_KEYS = ("srctype", "src_type", "time_type", "timetype", "counttype", "count_type",
                  "value_type", "valuetype", "type")
_MAIN_IN = ("in", "pre", "en", "cu", "cd", "s", "r", "clk")


class LoweringError(Exception):
    """A part that cannot be lowered; `diagnostic` names its network and part."""

    def __init__(self, diagnostic: Diagnostic) -> None:
        super().__init__(diagnostic.message())
        self.diagnostic = diagnostic


@dataclass(slots=True)
class Counters:
    """What every block lowered into one program shares: label numbers and relays used."""

    labels: int = 0
    relays: int = 0  # LadderWorks relays used so far (each written by one network only)


@dataclass(slots=True)
class BlockLowering:
    """One block's networks lowered in order; `labels` numbers its jump labels. `scope` is
    where its interface members live (layout.py); a called block is lowered inline with the
    scope of its instance (calls.py), `depth` calls deep."""

    block: Block
    layout: Layout
    diagnostics: list[Diagnostic] = field(default_factory=list)
    networks: list[Network] = field(default_factory=list)
    labels: dict[str, int] = field(default_factory=dict)
    end_label: int = 0
    counters: Counters = field(default_factory=Counters)
    scope: tuple[str, ...] = ()
    depth: int = 0
    eno: Address | None = None  # a called block's ENO, which RET's value sets (calls.py)
    shown: set[str] = field(default_factory=set)  # parts shown, not simulated (shown_only)
    # what the drawing maps back (drawing.py): each S7 network's engine networks, and each
    # part's result and the instructions it was lowered to, by (network index, part uid)
    spans: list[range] = field(default_factory=list)
    emitted: dict[tuple[int, str], tuple[Expr | None, tuple[Instruction, ...]]] = field(
        default_factory=dict)

    def lower_callee(self, callee: Block, scope: tuple[str, ...], eno: Address | None = None
                     ) -> tuple[list[Network], list[Diagnostic]]:
        """A called block's networks, lowered in `scope`, one call deeper (calls.py)."""
        child = BlockLowering(callee, self.layout, counters=self.counters, scope=scope,
                              depth=self.depth + 1, eno=eno)
        return child.run(), child.diagnostics

    def new_label(self) -> int:
        """A label number no other block of the program uses."""
        self.counters.labels += 1
        return self.counters.labels

    def run(self) -> list[Network]:
        """Every network of the block, then the label RET jumps to."""
        self.scope = self.scope or (f"#{self.block.name.lower()}",)
        for network in self.block.networks:
            for part in network.parts:
                if part.name == "Label" and part.label and part.label.lower() not in self.labels:
                    self.labels[part.label.lower()] = self.new_label()
        self.end_label = self.new_label()
        for section in ("Input", "Output", "InOut", "Static", "Temp"):  # its interface first
            for member in self.block.members(section):
                self.layout.local(self.block, (member.name,), self.scope)
        for network in self.block.networks:  # instances first: their members are read anywhere
            for part in network.parts:
                kind = "IEC_TIMER" if part.name in TIMERS else "IEC_COUNTER" \
                    if part.name in COUNTERS else ""
                if kind and part.instance is not None:
                    self.layout.resolve(self.block, part.instance, kind, self.scope)
                elif part.name == "Call":
                    calls.prepare(self, part)
        for index, network in enumerate(self.block.networks, start=1):
            before = len(self.networks)
            try:
                self.network(index, network)
            except LoweringError as error:  # left out, the others run: a warning [LW]
                del self.networks[before:]
                self.diagnostics.append(replace(error.diagnostic, severity=Severity.WARNING))
            if len(self.networks) > before:
                title = network.title or f"Network {index}"
                self.networks[before].comments = [title, *network.comment.splitlines()]
            self.spans.append(range(before, len(self.networks)))
        if any(ins.name == "S7.RET" and ins.params == (LabelRef(self.end_label),)
               for net in self.networks for ins in net.instructions):
            self.networks.append(Network([Instruction("S7.LABEL", None,
                                                      (LabelRef(self.end_label),))]))
        return self.networks

    # -- one network ----------------------------------------------------------------------
    def fail(self, index: int, where: Part | None, code: str, **args: object) -> LoweringError:
        return LoweringError(Diagnostic(code, {"network": index, **args},
                                        where.line if where is not None else 0, 1))

    def network(self, index: int, network: S7Network) -> None:
        if network.language.upper() not in ("LAD", "FBD"):
            self.diagnostics.append(Diagnostic("s7-not-simulated", {
                "network": index, "language": network.language}, network.line, 1,
                Severity.WARNING))
            return
        graph = PinGraph(network)
        graph.index = index
        self.shown = set()  # UIds are a network's own
        if graph.missing:
            uid = graph.missing[0]
            raise self.fail(index, None, "s7-wire", part=uid, why="a wire to a part that is not "
                            "there")
        for part in network.parts:
            if part.name == "Label":
                number = self.labels.get(part.label.lower())
                if number is not None:
                    self.emit([Instruction("S7.LABEL", None, (LabelRef(number),),
                                           line=part.line)])
        outputs: dict[str, Expr | None] = {}
        for part in graph.order(lambda uid: self.fail(index, network.part(uid), "s7-wire",
                                                      part=uid, why="a loop of wires")):
            before = len(self.networks)
            outputs[part.uid] = self.part(index, graph, part, outputs)
            self.emitted[(index, part.uid)] = (outputs[part.uid], tuple(
                ins for net in self.networks[before:] for ins in net.instructions))

    def shown_only(self, index: int, where: Part, power: Expr, code: str, **args: object
                   ) -> Expr:
        """A part not simulated, kept (a warning): ENO follows EN, nothing else is done [LW]."""
        self.shown.add(where.uid)
        self.diagnostics.append(Diagnostic(code, {"network": index, "uid": where.uid, **args},
                                           where.line, 1, Severity.WARNING))
        return power

    def emit(self, instructions: list[Instruction]) -> None:
        self.networks.append(Network(instructions))

    def power(self, graph: PinGraph, part: Part, pin: str, outputs: dict[str, Expr | None]
              ) -> Expr | None:
        """The power a part's input pin gets (None: no wire, no power)."""
        sources = graph.power_in.get((part.uid, pin), [])
        terms: list[Expr] = []
        for end in sources:
            if end.powerrail:
                terms.append(("on",))
            elif end.part in self.shown and end.pin not in ("out", "eno"):
                continue  # a shown-only part's other outputs give no power
            else:
                found = outputs.get(end.part)
                other = graph.parts.get(end.part)
                if other is not None and end.pin not in ("out", "eno", "q", "qu", ""):
                    found = graph.extra_out.get((end.part, end.pin))
                if found is not None:
                    terms.append(found)
        if not terms:
            operand = graph.operand_in.get((part.uid, pin))
            if operand is not None:
                return self.bit_expr(operand, False, graph.index, part)
            return None
        return terms[0] if len(terms) == 1 else ("or", terms)

    def main_power(self, graph: PinGraph, part: Part, outputs: dict[str, Expr | None]) -> Expr:
        for pin in _MAIN_IN:
            if (part.uid, pin) in graph.power_in:
                return self.power(graph, part, pin, outputs) or ("bit", ALWAYS_OFF, False)
        return ("bit", ALWAYS_OFF, False)

    def bit_expr(self, operand: Operand, negated: bool, index: int, part: Part) -> Expr:
        operand = system_tags.constant_of(self.layout.program, operand) or operand
        if operand.kind is OperandKind.CONSTANT:
            on = operand.text.upper() in ("TRUE", "1")
            return ("bit", ALWAYS_ON if on != negated else ALWAYS_OFF, False)
        place = self.place(index, part, operand, guess="Bool")
        if place.address.bit is None:
            raise self.fail(index, part, "s7-type", part=part.name, type=place.type_name)
        return ("bit", place.address, negated)

    def place(self, index: int, part: Part, operand: Operand, instance: str = "",
              guess: str = "") -> Place:
        found = self.layout.resolve(self.block, operand, instance, self.scope)
        undeclared = None if found else system_tags.declare(self.layout.program, operand, guess,
                                                             index, part)
        if undeclared is not None:  # a tag of a table, or a member of a DB, not exported [LW]
            self.diagnostics.append(undeclared)
            found = self.layout.resolve(self.block, operand, instance, self.scope)
        if found is None and self.layout.full:
            raise self.fail(index, part, "s7-memory-full", text=operand.display())
        if found is None:
            raise self.fail(index, part, "s7-operand-unknown", text=operand.display())
        return found

    def keep(self, graph: PinGraph, part: Part) -> Address | None:
        """A relay for the part's output when other parts read it."""
        if not graph.used(part.uid):
            return None
        return self.new_relay(graph.index, part)

    def statement(self, part: Part, inputs: list[Expr], tail: list[Instruction],
                  keep: Address | None) -> Expr | None:
        code: list[Instruction] = []
        for n, expr in enumerate(inputs):
            emit_expr(expr, n > 0, code, part.line)
        code += tail
        if keep is not None:
            code.append(Instruction("WRT", keep, line=part.line))
        self.emit(code)
        return ("bit", keep, False) if keep is not None else None

    # -- parts ----------------------------------------------------------------------------
    def part(self, index: int, graph: PinGraph, part: Part, outputs: dict[str, Expr | None]
             ) -> Expr | None:
        name = part.name
        if name == "Label":
            return None
        if name in ("O", "A", "X"):  # LAD's OR of branches; FBD's & / >=1 / X boxes
            return self.gate(graph, part, outputs)
        power = self.main_power(graph, part, outputs)
        line = part.line
        if name in ("Contact", "PContact", "NContact"):
            operand = graph.operand_in.get((part.uid, "operand"))
            if operand is None:
                raise self.fail(index, part, "s7-pin-missing", part=name, pin="operand")
            if name == "Contact":
                return ("and", power, self.bit_expr(operand, "operand" in part.negated, index,
                                                    part))
            memory = graph.operand_in.get((part.uid, "bit"))
            if memory is None:
                raise self.fail(index, part, "s7-pin-missing", part=name, pin="bit")
            row = "S7.P" if name == "PContact" else "S7.N"
            params = (self.bit_expr(operand, False, index, part)[1],
                      self.bit_expr(memory, False, index, part)[1])
            return self.statement(part, [power], [Instruction(row, None, params, line=line)],
                                  self.keep(graph, part))
        if name == "Not":
            return ("not", power)
        if name in PURE:
            return ("box", PURE[name], self.pure_params(index, graph, part), power)
        if name in COILS or name in ("PCoil", "NCoil"):
            return self.coil(index, graph, part, power)
        if name in TIMERS or name in ("PTCoil", "RTCoil"):
            return self.timer(index, graph, part, power, outputs)
        if name in COUNTERS:
            return self.counter(index, graph, part, power, outputs)
        if name in ("Sr", "Rs"):
            first, second = ("s", "r1") if name == "Sr" else ("r", "s1")
            operand = graph.operand_in.get((part.uid, "operand")) or part.instance
            if operand is None:
                raise self.fail(index, part, "s7-pin-missing", part=name, pin="operand")
            other = self.power(graph, part, second, outputs) or ("bit", ALWAYS_OFF, False)
            flip_flop = (self.bit_expr(operand, False, index, part)[1],)
            first_power = self.power(graph, part, first, outputs) or ("bit", ALWAYS_OFF, False)
            return self.statement(part, [first_power, other], [Instruction(
                "S7." + name.upper(), None, flip_flop, line=line)], self.keep(graph, part))
        if name in ("PTrig", "NTrig"):
            memory = graph.operand_in.get((part.uid, "bit"))
            if memory is None:
                raise self.fail(index, part, "s7-pin-missing", part=name, pin="bit")
            row = "S7.P_TRIG" if name == "PTrig" else "S7.N_TRIG"
            return self.statement(part, [power], [Instruction(
                row, None, (self.bit_expr(memory, False, index, part)[1],), line=line)],
                self.keep(graph, part))
        if name in ("Move", "Convert", "Inc", "Dec") or name in boxes.MATH:
            return boxes.box(self, index, graph, part, power)
        if name in ("Jump", "JumpN", "Return"):
            if name == "Return":
                target = self.end_label
            else:
                target = self.labels.get(part.label.lower(), 0)
                if not target:
                    raise self.fail(index, part, "s7-label-unknown", label=part.label)
            row = {"Jump": "S7.JMP", "JumpN": "S7.JMPN", "Return": "S7.RET"}[name]
            if name == "Return":
                calls.return_value(self, index, graph, part, power)
            return self.statement(part, [power], [Instruction(row, None, (LabelRef(target),),
                                                              line=line)], None)
        if name in ("JumpList", "Switch"):
            boxes.jump_table(self, index, graph, part, power)
            return None
        if name == "Call":
            return calls.lower_call(self, index, graph, part, power, outputs)
        return self.shown_only(index, part, power, "s7-part-unknown", part=name)

    def gate(self, graph: PinGraph, part: Part, outputs: dict[str, Expr | None]) -> Expr | None:
        """O (OR), A (AND), X (XOR of two) of the inputs in1 … inN, a negated pin inverted; an
        input wired to nothing is 0 (an operand wired to it is read)."""
        pins = sorted({pin for (uid, pin) in (*graph.power_in, *graph.operand_in)
                       if uid == part.uid and pin.startswith("in")}, key=lambda p: (len(p), p))
        terms: list[Expr] = []
        for pin in pins:
            term = self.power(graph, part, pin, outputs) or ("bit", ALWAYS_OFF, False)
            terms.append(("not", term) if pin in part.negated else term)
        if not terms:
            return None
        if part.name == "O" and len(terms) > 1:
            return ("or", terms)
        result = terms[0]
        for term in terms[1:]:
            result = ("and", result, term) if part.name == "A" else (
                "or", [("and", result, ("not", term)), ("and", ("not", result), term)])
        return result

    def value(self, index: int, part: Part, operand: Operand | None, vtype: typed.ValueType,
              pin: str) -> ParamValue:
        if operand is None:
            raise self.fail(index, part, "s7-pin-missing", part=part.name, pin=pin.upper())
        operand = system_tags.constant_of(self.layout.program, operand) or operand
        if operand.kind is OperandKind.CONSTANT:
            found: ParamValue | None = constant_value(operand.text, vtype)
            if found is None and vtype is typed.ValueType.LREAL:
                found = lreal_constant(self.layout, operand.text)
            if found is None:
                raise self.fail(index, part, "s7-operand-unknown", text=operand.text)
            return found
        return self.place(index, part, operand, guess=vtype.name).address

    def vtype(self, index: int, graph: PinGraph, part: Part, pins: tuple[str, ...]
              ) -> typed.ValueType:
        """The type a box works on: its template, else its operands' declared types, else
        a constant's spelling, else the width of an absolute address."""
        for key, text in part.template.items():
            if key.lower() in _TEMPLATE_KEYS:
                found = typed.type_of(text)
                if found is not None:
                    return found
                raise self.fail(index, part, "s7-type", part=part.name, type=text)
        guesses: list[typed.ValueType] = []
        for rank in (OperandKind.GLOBAL, OperandKind.LOCAL, OperandKind.CONSTANT,
                     OperandKind.ABSOLUTE):
            for pin in pins:
                operand = graph.operand_in.get((part.uid, pin)) or graph.operand_out.get(
                    (part.uid, pin), [None])[0]
                if operand is None or operand.kind is not rank:
                    continue
                if rank is OperandKind.CONSTANT:
                    found = constant_type(operand.text)
                else:
                    place = self.layout.resolve(self.block, operand, "", self.scope)
                    found = place.vtype if place is not None else None
                if found is not None:
                    guesses.append(found)
            if guesses:
                return guesses[0]
        return typed.ValueType.INT

    def pure_params(self, index: int, graph: PinGraph, part: Part) -> tuple[ParamValue, ...]:
        if part.name in ("Ok", "NotOk"):
            operand = graph.operand_in.get((part.uid, "operand")) or graph.operand_in.get(
                (part.uid, "in"))
            return (self.value(index, part, operand, typed.ValueType.REAL, "IN"),)
        pins = ("min", "val", "max") if part.name in ("InRange", "OutRange") else ("in1", "in2")
        vtype = self.vtype(index, graph, part, pins)
        values = []
        for pin in pins:
            operand = graph.operand_in.get((part.uid, pin))
            if operand is None and pin == "val":
                operand = graph.operand_in.get((part.uid, "in"))
            values.append(self.value(index, part, operand, vtype, pin))
        return (int(vtype), *values)

    def coil(self, index: int, graph: PinGraph, part: Part, power: Expr) -> Expr | None:
        operand = graph.operand_in.get((part.uid, "operand")) or next(
            iter(graph.operand_out.get((part.uid, "operand"), [])), None)
        if operand is None:
            raise self.fail(index, part, "s7-pin-missing", part=part.name, pin="operand")
        target = self.bit_expr(operand, False, index, part)[1]
        if part.name in ("PCoil", "NCoil"):
            memory = graph.operand_in.get((part.uid, "bit"))
            if memory is None:
                raise self.fail(index, part, "s7-pin-missing", part=part.name, pin="bit")
            row = "S7.P_COIL" if part.name == "PCoil" else "S7.N_COIL"
            tail = [Instruction(row, None, (target, self.bit_expr(memory, False, index, part)[1]),
                                line=part.line)]
        else:
            name = COILS[part.name] + (".NOT" if "operand" in part.negated else "")
            tail = [Instruction(name, target, line=part.line)]
        keep = self.keep(graph, part)
        if keep is None:
            return self.statement(part, [power], tail, None)
        self.statement(part, [power], [], keep)  # the power passes on as it came in
        self.statement(part, [("bit", keep, False)], tail, None)
        return ("bit", keep, False)

    def timer(self, index: int, graph: PinGraph, part: Part, power: Expr,
              outputs: dict[str, Expr | None]) -> Expr | None:
        instance = part.instance or graph.operand_in.get((part.uid, "timer")) or \
            graph.operand_in.get((part.uid, "operand"))
        if instance is None:
            raise self.fail(index, part, "s7-pin-missing", part=part.name, pin="instance")
        base = self.place(index, part, instance, "IEC_TIMER").address
        base = Address(base.area, base.byte)
        line = part.line
        if part.name == "RTCoil":
            return self.statement(part, [power], [Instruction("S7.RT", None, (base,), line=line)],
                                  self.keep(graph, part))
        pt = self.value(index, part, graph.operand_in.get((part.uid, "pt")), typed.ValueType.TIME,
                        "pt")
        if part.name == "PTCoil":
            return self.statement(part, [power], [Instruction("S7.PT", None, (base, pt),
                                                              line=line)], self.keep(graph, part))
        et_out = graph.operand_out.get((part.uid, "et"), [])
        et: ParamValue = self.place(index, part, et_out[0]).address if et_out else 0
        inputs = [power]
        if part.name == "TONR":
            inputs.append(self.power(graph, part, "r", outputs) or ("bit", ALWAYS_OFF, False))
        result = self.statement(part, inputs, [Instruction(TIMERS[part.name], None,
                                                           (base, pt, et), line=line)],
                                self.keep(graph, part) or self.q_keep(graph, part))
        self.q_operands(index, graph, part, result, "q")
        return result

    def q_keep(self, graph: PinGraph, part: Part) -> Address | None:
        """A relay for a box's Q when it is wired to operands only."""
        if not any(graph.operand_out.get((part.uid, pin)) for pin in ("q", "qu", "qd")):
            return None
        return self.new_relay(graph.index, part)

    def q_operands(self, index: int, graph: PinGraph, part: Part, result: Expr | None,
                   pin: str) -> None:
        for operand in graph.operand_out.get((part.uid, pin), []):
            if result is None:
                break
            target = self.bit_expr(operand, False, index, part)[1]
            self.statement(part, [result], [Instruction("WRT", target, line=part.line)], None)

    def counter(self, index: int, graph: PinGraph, part: Part, power: Expr,
                outputs: dict[str, Expr | None]) -> Expr | None:
        if part.instance is None:
            raise self.fail(index, part, "s7-pin-missing", part=part.name, pin="instance")
        base = self.place(index, part, part.instance, "IEC_COUNTER").address
        base = Address(base.area, base.byte)
        vtype = self.vtype(index, graph, part, ("pv", "cv"))
        pv = self.value(index, part, graph.operand_in.get((part.uid, "pv")), vtype, "pv")
        cv_out = graph.operand_out.get((part.uid, "cv"), [])
        cv: ParamValue = self.place(index, part, cv_out[0]).address if cv_out else 0
        off: Expr = ("bit", ALWAYS_OFF, False)
        if part.name == "CTU":
            inputs = [power, self.power(graph, part, "r", outputs) or off]
            params: tuple[ParamValue, ...] = (base, int(vtype), pv, cv)
        elif part.name == "CTD":
            inputs = [power, self.power(graph, part, "ld", outputs) or off]
            params = (base, int(vtype), pv, cv)
        else:
            inputs = [power, *(self.power(graph, part, pin, outputs) or off
                               for pin in ("cd", "r", "ld"))]
            qd_out = graph.operand_out.get((part.uid, "qd"), [])
            qd: ParamValue = self.bit_expr(qd_out[0], False, index, part)[1] if qd_out else 0
            params = (base, int(vtype), pv, cv, qd)
        result = self.statement(part, inputs, [Instruction(COUNTERS[part.name], None, params,
                                                           line=part.line)],
                                self.keep(graph, part) or self.q_keep(graph, part))
        self.q_operands(index, graph, part, result, "qu" if part.name == "CTUD" else "q")
        return result

    def new_relay(self, index: int, part: Part) -> Address:
        """A LadderWorks relay of its own for a link inside a network."""
        byte, bit = divmod(self.counters.relays, 8)
        self.counters.relays += 1
        if SCRATCH_FIRST + byte > SCRATCH_LAST:
            raise self.fail(index, part, "s7-wire", part=part.name, why="too many branches")
        return Address(Area.R, SCRATCH_FIRST + byte, bit)


def lower_block(block: Block, layout: Layout) -> tuple[list[Network], list[Diagnostic]]:
    """A block's networks for the engine (the start values first) and the diagnostics of the
    parts not lowered."""
    lowering = BlockLowering(block, layout)
    networks = lowering.run()
    first = start_values(layout)
    return ([first] if first is not None else []) + networks, lowering.diagnostics
