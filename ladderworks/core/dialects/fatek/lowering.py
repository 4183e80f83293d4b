"""A Fatek listing's records as engine networks: the branch logic (branches.py) plus TU/TD and
comparison contacts, timers, counters, RST, FUN boxes and their FO outputs."""

from __future__ import annotations

import re

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.dialects.fatek.branches import (
    ALWAYS_OFF,
    ALWAYS_ON,
    EDGE_DEVICES,
    BranchError,
    Lowered,
    StackLowering,
    bit_device,
    refused,
    split_networks,
)
from ladderworks.core.dialects.fatek.devices import (
    Device,
    DeviceError,
    bit_address,
    fo_address,
    parse_constant,
    parse_device,
    timer_base_ms,
    word_address,
)
from ladderworks.core.dialects.fatek.listing import Record
from ladderworks.core.dialects.fatek.rows import (
    BY_FUN,
    NOT_SIMULATED,
    ROWS,
    operand_label,
    unknown_fun,
)
from ladderworks.core.il.program import Instruction, ParamValue
from ladderworks.core.instructions import InstructionSpec, ParamKind

ROW_OF_NAME: dict[str, InstructionSpec] = {spec.name: spec for spec in ROWS}
_BASE_RE = re.compile(r"^(\d+(?:\.\d+)?)S$", re.I)


class ProgramLowering(StackLowering):
    """One Fatek network's records as engine networks; `boxes` counts the boxes of the whole
    program (each gets its FO byte)."""

    def __init__(self, boxes: int, warnings: list[Diagnostic]) -> None:
        super().__init__()
        self.boxes = boxes
        self.warnings = warnings
        self.fo: Address | None = None  # the last box's FO byte in this network
        self.fresh_box = False  # the last record was a box with W1 (its FO0 is ST0)

    def emit_box(self, record: Record, spec: InstructionSpec, params: tuple[ParamValue, ...],
                 comment: str = "") -> None:
        """Append a box of row `spec` with its parameters (and comment)."""
        self.current.instructions.append(
            Instruction(spec.name, None, params, comment, line=record.line, column=record.column))
        self.current.records.append(record)

    def inputs(self, record: Record, count: int) -> None:
        """Bring the stack to the box's `count` control inputs: none before it is a box on the
        rail (EN always 1); an input not coded is 0 (docs/dialects.md)."""
        if self.depth > count:
            raise refused(record, "fatek-open-block", name=_name(record), count=self.depth - count)
        if count and not self.depth:
            self.emit(record, "RD", ALWAYS_ON)
            self.depth = 1
        while self.depth < count:
            self.emit(record, "RD.STK", ALWAYS_OFF)
            self.depth += 1

    def after_box(self, spec: InstructionSpec, fo: Address | None) -> None:
        """After a box: its W1 (FO0) is the result, an output was made."""
        self.depth = 1 if spec.w1 else 0
        self.after_output = True
        self.fo = fo
        self.fresh_box = spec.w1

    def next_fo(self) -> Address:
        """The FO byte of the next box of the program."""
        address = fo_address(self.boxes)
        self.boxes += 1
        return address

    def edge(self, record: Record) -> None:
        """ORG / LD / AND / OR with TU or TD: an edge box in series with what comes before."""
        device = bit_address(bit_device(record, EDGE_DEVICES))
        spec = ROW_OF_NAME["FBS.TU" if record.modifier == "TU" else "FBS.TD"]
        self.contact_box(record, spec, (device,))

    def contact_box(self, record: Record, spec: InstructionSpec,
                    params: tuple[ParamValue, ...]) -> None:
        """A contact made of a box with one input IN: IN AND the box's condition."""
        kind = record.mnemonic.rstrip("F") if record.mnemonic.endswith("F") else record.mnemonic
        if kind == "ORG" or (kind == "LD" and (not self.depth or self.after_output)):
            if kind == "LD" and self.depth:
                self.new_part()
            self.emit(record, "RD", ALWAYS_ON)
            self.depth = 1
            self.emit_box(record, spec, params)
        elif kind == "LD":
            self.emit(record, "RD.STK", ALWAYS_ON)
            self.depth += 1
            self.emit_box(record, spec, params)
        elif kind == "AND":
            if not self.depth:
                raise refused(record, "fatek-no-input", name=record.mnemonic)
            self.emit_box(record, spec, params)
        else:
            if not self.depth:
                raise refused(record, "fatek-no-input", name=record.mnemonic)
            self.emit(record, "RD.STK", ALWAYS_ON)
            self.emit_box(record, spec, params)
            self.emit(record, "OR.STK")
        self.after_output = False
        self.fresh_box = False

    def compare_contact(self, record: Record) -> None:
        """ORGF / LDF / ANDF / ORF with FUN 170-175 (and its Sa, Sb lines)."""
        spec = BY_FUN.get(record.fun or -1)
        if spec is not None and spec.name in NOT_SIMULATED:
            self.not_simulated(record)
            self.contact_box(record, ROW_OF_NAME["FBS.EQ"], (0, 0, 1))  # 0 = 1: never passes
            return
        if spec is None or spec.inputs != ("IN",):
            raise refused(record, "fatek-unknown-fun", number=record.fun)
        self.contact_box(record, spec, self.box_params(record, spec, None))

    def box_params(self, record: Record, spec: InstructionSpec, fo: Address | None
                   ) -> tuple[ParamValue, ...]:
        """The row's parameters from the record: its forms, then one operand line each."""
        operands = iter(record.operands)
        params: list[ParamValue] = []
        for param in spec.params:
            if param.name == "mode":
                params.append((1 if record.pulse else 0) | (2 if record.double else 0))
            elif param.name == "fo":
                assert fo is not None
                params.append(fo)
            elif param.name == "fun":
                params.append(record.fun or 0)
            elif param.name == "MD":
                line = next(operands, None)
                if line is None:
                    raise refused(record, "fatek-missing-operand", name=_name(record),
                                param=param.name)
                value = parse_constant(line.text)
                if value is None or not 0 <= value <= 255:
                    raise BranchError(Diagnostic("fatek-operand", {"text": line.text,
                                                                   "param": param.name},
                                                 line.line, line.column))
                params.append(value)
            else:
                label = operand_label(param.name)  # Fatek's D, PV
                line = next(operands, None)
                if line is None:
                    raise refused(record, "fatek-missing-operand", name=_name(record),
                                  param=label)
                params.append(operand(line.text, line.line, label,
                                      param.kind is ParamKind.VALUE, line.column))
        extra = next(operands, None)
        if extra is not None:
            raise BranchError(Diagnostic("fatek-extra-operand", {"text": extra.text,
                                                                 "name": _name(record)},
                                         extra.line, extra.column))
        return tuple(params)

    def not_simulated(self, record: Record) -> None:
        """The warning that the record's function is kept but not simulated."""
        self.warnings.append(Diagnostic("fatek-not-simulated", {"name": _name(record)},
                                        record.line, record.column, Severity.WARNING))

    def function(self, record: Record) -> None:
        """FUN n with its operand lines."""
        spec = BY_FUN.get(record.fun or -1)
        if spec is None and record.fun is not None and 0 <= record.fun <= MAX_FUN:
            spec = unknown_fun(record.fun, self.depth, record.fun_name.upper())  # checks warn
        if spec is None or spec.inputs == ("IN",):
            raise refused(record, "fatek-unknown-fun", number=record.fun)
        self.inputs(record, len(spec.inputs))
        fo = self.next_fo() if any(p.name == "fo" for p in spec.params) else None
        if spec.name in NOT_SIMULATED or not spec.simulated:
            if spec.simulated:
                self.not_simulated(record)
            lines = ", ".join(f"{o.label}: {o.text}".strip() for o in record.operands)
            self.emit_box(record, spec, (record.fun or 0, fo or ALWAYS_OFF), lines)
        else:
            self.emit_box(record, spec, self.box_params(record, spec, fo))
        self.after_box(spec, fo)

    def timer_or_counter(self, record: Record) -> None:
        """TMR Tn [base] PV / CTR Cn PV (PV on the line or on an operand line `PV: …`)."""
        kind = "T" if record.mnemonic == "TMR" else "C"
        try:
            device = parse_device(record.operand, bit=True)
        except DeviceError:
            device = Device("", -1)
        if device.kind != kind:
            raise refused(record, "fatek-device-kind", text=record.operand or "?",
                        name=record.mnemonic, kinds=kind)
        args = list(record.args)
        if args and _BASE_RE.match(args[0]):
            base = round(float(_BASE_RE.match(args[0]).group(1)) * 1000)  # type: ignore[union-attr]
            if kind != "T" or base != timer_base_ms(device.number):
                raise refused(record, "fatek-timer-base", text=args[0], name=str(device),
                            base=f"{timer_base_ms(device.number) / 1000:g}S")
            args.pop(0)
        texts = [(text, record.line) for text in args] + [
            (o.text, o.line) for o in record.operands]
        if len(texts) != 1:
            if not texts:
                raise refused(record, "fatek-missing-operand", name=record.mnemonic, param="PV")
            raise BranchError(Diagnostic("fatek-extra-operand", {"text": texts[1][0],
                                                                 "name": record.mnemonic},
                                         texts[1][1]))
        preset = operand(texts[0][0], texts[0][1], "PV", True)
        spec = ROW_OF_NAME["FBS.TMR" if kind == "T" else "FBS.CTR"]
        self.inputs(record, len(spec.inputs))
        fo = self.next_fo()
        self.emit_box(record, spec, (device.number, preset, fo))
        self.after_box(spec, fo)

    def reset(self, record: Record) -> None:
        """RST Tn / Cn (a box), RST of a relay (the reset coil, as OUTR)."""
        if record.operand[:1].upper() in ("T", "C") and not record.operand.upper().startswith(
                "TR"):
            device = bit_device(record, ("T", "C"))
            spec = ROW_OF_NAME["FBS.RST"]
            self.inputs(record, 1)
            self.emit_box(record, spec, (0 if device.kind == "T" else 1, device.number))
            self.after_box(spec, None)
            return
        record.mnemonic = "OUTR"
        try:
            self.coil(record)
        finally:
            record.mnemonic = "RST"

    def function_output(self, record: Record) -> None:
        """FO n: the last box's output n as the new result."""
        number = int(record.operand) if record.operand.isdigit() else -1
        if self.fo is None or not 0 <= number <= 7:
            raise refused(record, "fatek-fo", text=record.operand)
        if number == 0 and self.fresh_box:
            self.fresh_box = False
            return  # FO0 is the box's W1, already the result
        self.new_part()
        self.emit(record, "RD", self.fo.with_bit(number))
        self.depth = 1
        self.after_output = False
        self.fresh_box = False

    def take_record(self, record: Record) -> None:
        """Lower one record of the network (a diagnostic by BranchError)."""
        kind = record.mnemonic
        if kind in ("OUT", "OUTS", "OUTR") and record.modifier != "TR":
            self.fresh_box = False
        if self.take(record):
            return
        if kind in ("ORG", "LD", "AND", "OR") and record.modifier in ("TU", "TD"):
            self.edge(record)
        elif kind in ("ORGF", "LDF", "ANDF", "ORF"):
            self.compare_contact(record)
        elif kind == "FUN":
            self.function(record)
        elif kind in ("TMR", "CTR"):
            self.timer_or_counter(record)
        elif kind == "RST":
            self.reset(record)
        elif kind == "FO":
            self.function_output(record)
        elif kind != "END":
            raise refused(record, "fatek-unknown-instruction", name=kind)


MAX_FUN = 399  # a FUN number above is not a function (the FBs manual numbers them below 400)


def _name(record: Record) -> str:
    if record.fun is not None:
        return f"FUN {record.fun} {record.fun_name}".strip()
    return record.mnemonic


def operand(text: str, line: int, param: str, constant: bool, column: int = 1) -> ParamValue:
    """A box operand: a constant (where one may be) or a register's byte address."""
    value = parse_constant(text)
    if value is not None:
        if not constant:
            raise BranchError(Diagnostic("fatek-operand", {"text": text, "param": param}, line,
                                         column))
        return value
    try:
        device = parse_device(text, bit=False)
    except DeviceError:
        raise BranchError(Diagnostic("fatek-operand", {"text": text, "param": param},
                                     line, column)) from None
    return word_address(device)[0]


def lower_program(records: list[Record]) -> tuple[list[Lowered], list[Diagnostic]]:
    """Every network of the listing as engine networks, and the diagnostics (one error per
    network at most, at the record that caused it; warnings for what is not simulated)."""
    parts: list[Lowered] = []
    diagnostics: list[Diagnostic] = []
    boxes = 0
    for network in split_networks(records):
        warnings: list[Diagnostic] = []
        lowering = ProgramLowering(boxes, warnings)
        try:
            for record in network:
                if record.mnemonic == "END":
                    break
                lowering.take_record(record)
            if lowering.depth > 1:
                last = network[-1]
                raise refused(last, "fatek-open-block", name=_name(last), count=lowering.depth - 1)
        except BranchError as error:
            diagnostics.append(error.diagnostic)
        diagnostics.extend(warnings)
        boxes = lowering.boxes
        parts.extend(part for part in lowering.parts if part.instructions)
    return parts, diagnostics
