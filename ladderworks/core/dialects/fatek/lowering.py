"""A Fatek listing's records as engine networks: the branch logic (branches.py) plus TU/TD and
comparison contacts, timers, counters, RST, FUN boxes and their FO outputs."""

from __future__ import annotations

import itertools
import re

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.dialects.fatek.branch_points import (
    LAST,
    PUSH,
    READ,
    NoBranch,
)
from ladderworks.core.dialects.fatek.branches import (
    ALWAYS_OFF,
    ALWAYS_ON,
    EDGE_DEVICES,
    MAX_TR,
    BranchError,
    Lowered,
    StackLowering,
    bit_device,
    refused,
)
from ladderworks.core.dialects.fatek.devices import (
    Device,
    DeviceError,
    bit_address,
    fo_address,
    parse_constant,
    parse_device,
    timer_base_ms,
)
from ladderworks.core.dialects.fatek.fo_pins import on_the_box
from ladderworks.core.dialects.fatek.listing import Record
from ladderworks.core.dialects.fatek.operands import bit_operand, operand
from ladderworks.core.dialects.fatek.rows import (
    BY_FUN,
    FORMS,
    NOT_SIMULATED,
    ROWS,
    UNKNOWN_FUN,
    operand_label,
)
from ladderworks.core.dialects.fatek.tr_inputs import block_start, pushed_copy
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
        self.following: Record | None = None  # the record after the one being lowered
        self.ahead: list[Record] = []  # the records of its network
        self.index = 0  # the one being lowered
        self.used_tr: set[int] = set()  # the TR points the network's own records name
        self.pass_on: Record | None = None  # the box whose EN the next coil takes (no output)
        self.kept_tr = 0  # the TR point holding that EN
        self.chain_start = 0  # where the outputs on the current result began (this part)
        self.saved: dict[int, tuple[Lowered, list[Instruction]]] = {}  # TR n: part, block
        self.copied: dict[Address, int] = {}  # the TR points read as copies of their block
        self.saving = self.just_saved = -1  # the TR point this / the last record set
        self.branch_points: dict[int, int] = {}  # TR n read as a rung's branch point: its reads
        self.open_points: list[int] = []  # those pushed and not yet read for the last time

    def save_tr(self, record: Record) -> None:
        """OUT TR n, remembering the block it saved (copied where it is read as an input)."""
        if number_ok(record) and int(record.operand[2:]) in self.branch_points:
            self.push_point(record)
            return
        super().save_tr(record)
        self.saving = self.tr_number(record)
        instructions = self.current.instructions[:-1]
        start = block_start(instructions)
        number = self.tr_number(record)
        self.saved.pop(number, None)
        if start is not None:
            self.saved[number] = (self.current, instructions[start:])

    def load_tr(self, record: Record) -> None:
        """LD TR n: the saved block copied when it is pushed as one more value (a box's input,
        or a block ANDLD / ORLD joins), else the point read."""
        number = self.tr_number(record) if number_ok(record) else -1
        if number in self.branch_points:
            self.next_branch(record, number)
            return
        if number == self.just_saved and self.depth == 1:
            # `OUT TR n` then `LD TR n` (WinProladder never prints an empty branch): the rung
            # goes on from the point, as the lowering of a box's kept EN writes it
            self.new_part()
            self.emit(record, "RD", bit_address(Device("TR", number)))
            self.after_output = False
            return
        saved = self.saved.get(number)
        if saved is None or self.after_output or not self.depth or \
                saved[0] is not self.current or not self.box_input_next():
            super().load_tr(record)
            return
        self.current.instructions.extend(pushed_copy(saved[1], record.line, record.column))
        self.current.records.extend([record] * len(saved[1]))
        self.copied[bit_address(Device("TR", number))] = number
        self.depth += 1
        self.after_output = False

    def push_point(self, record: Record) -> None:
        """`OUT TR n` of a branch point: the result kept on the stack (branch_points.py)."""
        number = self.tr_number(record)
        if number in self.tr_points:
            raise refused(record, "fatek-tr-reused", number=number)
        if self.depth != 1:
            raise NoBranch
        self.tr_points.add(number)
        self.open_points.append(number)
        self.emit_box(record, ROW_OF_NAME[PUSH], (number,))

    def next_branch(self, record: Record, number: int) -> None:
        """`LD TR n` after a branch's outputs: the next branch from the point (its last read:
        the last branch, the point taken off the stack)."""
        if not self.after_output or self.depth != 1 or not self.open_points \
                or self.open_points[-1] != number:
            raise NoBranch
        self.branch_points[number] -= 1
        last = self.branch_points[number] == 0
        if last:
            self.open_points.pop()
        self.emit_box(record, ROW_OF_NAME[LAST if last else READ], (number,))
        self.after_output = False

    def box_input_next(self) -> bool:
        """Whether the value pushed now stays apart until a box takes it as an input (no
        ANDLD / ORLD or output joins it first)."""
        for record in itertools.islice(self.ahead, self.index + 1, None):
            if record.mnemonic in ("FUN", "TMR", "CTR"):
                return True
            if record.mnemonic not in ("AND", "OR", "ANDF", "ORF") or record.modifier == "TR":
                return False
        return False

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
            raise refused(record, "fatek-open-block", name=name_of(record),
                          count=self.depth - count)
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
        self.chain_start = len(self.current.instructions)
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
        """An edge or comparison contact in its place: starting the rung or a block (its READ
        row, `FBS.TU.ORG` / `.LD`), in series (the row itself: IN AND it), in parallel (`.OR`)."""
        kind = record.mnemonic.rstrip("F") if record.mnemonic.endswith("F") else record.mnemonic
        forms = FORMS[spec.name]
        if kind == "ORG" or (kind == "LD" and (not self.depth or self.after_output)):
            if kind == "LD" and self.after_output and self.current.instructions:
                self.new_part()
            self.emit_box(record, forms["ORG"], params)
            self.depth = 1
        elif kind == "LD":
            self.emit_box(record, forms["LD"], params)
            self.depth += 1
        else:
            if not self.depth:
                raise refused(record, "fatek-no-input", name=record.mnemonic)
            self.emit_box(record, spec if kind == "AND" else forms["OR"], params)
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
                    raise refused(record, "fatek-missing-operand", name=name_of(record),
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
                    raise refused(record, "fatek-missing-operand", name=name_of(record),
                                  param=label)
                params.append(bit_operand(line.text, line.line, label, line.column)
                              if param.kind is ParamKind.BIT else
                              operand(line.text, line.line, label,
                                      param.kind is ParamKind.VALUE, line.column))
        extra = next(operands, None)
        if extra is not None:
            raise BranchError(Diagnostic("fatek-extra-operand", {"text": extra.text,
                                                                 "name": name_of(record)},
                                         extra.line, extra.column))
        return tuple(params)

    def not_simulated(self, record: Record) -> None:
        """The warning that the record's function is kept but not simulated."""
        self.warnings.append(Diagnostic("fatek-not-simulated", {"name": name_of(record)},
                                        record.line, record.column, Severity.WARNING))

    def function(self, record: Record) -> None:
        """FUN n with its operand lines; a FUN the table has no row for is kept as the
        not-simulated box FBS.FUN (drawn, saved, run as nothing: its FO stay 0)."""
        spec = BY_FUN.get(record.fun or -1)
        if spec is not None and spec.inputs == ("IN",):
            raise refused(record, "fatek-unknown-fun", number=record.fun)
        if spec is None:  # every block before it is one of its inputs (up to four)
            spec = ROW_OF_NAME[UNKNOWN_FUN]
        self.inputs(record, len(spec.inputs))
        fo = self.next_fo() if any(p.name == "fo" for p in spec.params) else None
        kept = self.keep_en(record, spec)
        if spec.name in NOT_SIMULATED:
            self.not_simulated(record)
            self.emit_box(record, spec, (record.fun or 0, fo or ALWAYS_OFF), kept_text(record))
        else:
            self.emit_box(record, spec, self.box_params(record, spec, fo))
        self.after_box(spec, fo)
        if kept is not None:
            self.pass_on = kept

    def keep_en(self, record: Record, spec: InstructionSpec) -> Record | None:
        """A box with no output followed by a coil: WinProladder wires the coil to the box's
        EN. The EN is kept in a TR point the network does not use (`OUT TR n` before the box);
        the box and the coil each start an engine network from it (`LD TR n`): the record of
        the box, or None."""
        if spec.w1 or self.depth != 1 or not _takes_result(self.following):
            return None
        free = self.free_tr()
        if free is None:
            return None
        address = bit_address(Device("TR", free))
        self.emit(record, "WRT", address)
        self.new_part()  # the box drawn on a rung of its own, from the point
        self.emit(record, "RD", address)
        self.kept_tr = free
        return record

    def free_tr(self) -> int | None:
        """A TR point the network does not use, taken (the highest first), None if none."""
        free = [n for n in range(MAX_TR - 1, -1, -1)
                if n not in self.tr_points and n not in self.used_tr]
        if not free:
            return None
        self.tr_points.add(free[0])
        return free[0]

    def box_after_coils(self, record: Record) -> None:
        """A box after coils on the same result (`RST( ) S1` … `RST( ) C0`): WinProladder draws
        them in parallel. The result is kept in a free TR point before the first coil, and the
        box starts a new engine network from it (each drawn as a rung)."""
        if self.depth != 1:
            return
        free = self.free_tr()
        if free is None:
            return
        part = self.current
        at = min(self.chain_start, len(part.instructions))
        first = part.records[at] if at < len(part.records) else record
        part.instructions.insert(at, Instruction("WRT", bit_address(Device("TR", free)),
                                                 line=first.line, column=first.column))
        part.records.insert(at, first)
        self.kept_tr = free
        self.coil_after_box(record)

    def coil_after_box(self, record: Record) -> None:
        """The coil or box after a box with no output: a new engine network from the kept EN."""
        self.pass_on = None
        self.new_part()
        self.emit(record, "RD", bit_address(Device("TR", self.kept_tr)))
        self.depth = 1
        self.after_output = False

    def timer_or_counter(self, record: Record) -> None:
        """TMR Tn [base] PV / CTR Cn PV (PV on the line or on an operand line `PV: …`)."""
        kind = "T" if record.mnemonic == "TMR" else "C"
        try:
            device = parse_device(record.operand, bit=True)
        except DeviceError as error:
            if (error.code == "fatek-device-range"
                    and error.text.strip().upper().rstrip("0123456789 ") == kind):
                raise refused(record, "fatek-device-range", text=error.text,
                              range=error.detail) from None  # T300: the range, not "use T"
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
            kept = self.keep_en(record, spec)
            self.emit_box(record, spec, (0 if device.kind == "T" else 1, device.number))
            self.after_box(spec, None)
            self.pass_on = kept
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
        if not on_the_box(self.current.instructions, self.fo,
                          itertools.islice(self.ahead, self.index + 1, None)):
            self.new_part()  # drawn on a rung of its own
        self.emit(record, "RD", self.fo.with_bit(number))
        self.depth = 1
        self.after_output = False
        self.fresh_box = False

    def take_record(self, record: Record) -> None:
        """Lower one record of the network (a diagnostic by BranchError)."""
        kind = record.mnemonic
        if kind in ("OUT", "OUTS", "OUTR") and record.modifier != "TR":
            self.fresh_box = False
        self.just_saved, self.saving = self.saving, -1  # the TR point the record before set
        if not self.after_output:
            self.chain_start = len(self.current.instructions)
        if self.pass_on is not None and _takes_result(record):
            self.coil_after_box(record)
        elif self.after_output and _is_box(record):
            self.box_after_coils(record)
        self.pass_on = None
        if kind == "SET":
            record.mnemonic = "OUTS"
            try:
                self.coil(record)
            finally:
                record.mnemonic = "SET"
            return
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


def number_ok(record: Record) -> bool:
    """Whether a TR record's number is written as digits (its range checked later)."""
    return record.operand[2:].isdigit()


def _is_box(record: Record) -> bool:
    """Whether a record is a box that takes the result (FUN, TMR, CTR, RST of T/C)."""
    if record.mnemonic in ("FUN", "TMR", "CTR"):
        return True
    operand = record.operand.upper()
    return record.mnemonic == "RST" and operand[:1] in ("T", "C") and not operand.startswith("TR")


def _takes_result(record: Record | None) -> bool:
    """Whether a record takes the result before it: a coil (OUT, OUTS, OUTR, SET, RST) or a
    box (FUN, TMR, CTR); not a TR point, a contact or FO."""
    if record is None or record.modifier == "TR":
        return False
    return record.mnemonic in ("OUT", "OUTS", "OUTR", "SET", "RST", "FUN", "TMR", "CTR")


def kept_text(record: Record) -> str:
    """A not-simulated box's operand lines as its comment (`Ps: 1, SR: R1200`); an unknown
    FUN's number, forms and name as written go first (`FUN 60DP XYZ: S: R0`)."""
    lines = ", ".join(f"{o.label}: {o.text}".strip() for o in record.operands)
    if BY_FUN.get(record.fun or -1) is None:
        forms = ("D" if record.double else "") + ("P" if record.pulse else "")
        return f"{f'FUN {record.fun}{forms} {record.fun_name}'.rstrip()}: {lines}"
    return lines


def name_of(record: Record) -> str:
    """A record's name for a message: `FUN 11 (+)`, `TMR`."""
    if record.fun is not None:
        return f"FUN {record.fun} {record.fun_name}".strip()
    return record.mnemonic
