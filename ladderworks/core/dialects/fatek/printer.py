"""Fatek text of a new or changed network: seed 002's plain form (no step numbers), one
instruction a line, a FUN box's operands on their own lines (docs/dialects.md, Fatek)."""

from __future__ import annotations

import re

from ladderworks.core.address import Address
from ladderworks.core.dialects.fatek.branches import ALWAYS_OFF, ALWAYS_ON
from ladderworks.core.dialects.fatek.devices import FO_AREA, device_at, word_device_at
from ladderworks.core.dialects.fatek.printed import PrintedStyle, printed_lines
from ladderworks.core.dialects.fatek.rows import SERIES_OF, SUB_BASE, UNKNOWN_FUN, operand_label
from ladderworks.core.dialects.spelling import Spelling
from ladderworks.core.il.program import Instruction, Network
from ladderworks.core.instructions import Combine, InstructionSpec, Kind, StackOp, Write

WIDTH = 9  # the mnemonic column, as WinProladder prints it
# an operand line's label where it is not the parameter's name (`D : R1`, `CV: C0`, `PV: 10`)
_CONTACT_BOXES = {"FBS.TU": "TU", "FBS.TD": "TD"}
_COMPARE_BOXES = frozenset(("FBS.EQ", "FBS.GT", "FBS.LT", "FBS.NE", "FBS.GE", "FBS.LE"))


def device_text(address: object) -> str:
    """A bit or register operand in Fatek's spelling, a constant as a number."""
    if isinstance(address, Address):
        if address == ALWAYS_ON:
            return "SHORT"
        if address == ALWAYS_OFF:
            return "OPEN"
        device = device_at(address) if address.bit is not None else word_device_at(address)
        return str(device) if device is not None else str(address)
    return str(address)


def mnemonic_of(spec: InstructionSpec) -> str:
    """A row's name as a Fatek listing writes it: ORG / LD for RD / RD.STK, ANDLD, ORLD, OUT,
    OUTS, OUTR, FUN n NAME for a box (the compiler's messages name instructions so)."""
    if spec.kind is Kind.BASIC and not spec.dialect:
        if spec.write is not Write.NONE:
            name = {Write.SET: "OUTS", Write.RESET: "OUTR"}.get(spec.write, "OUT")
            return name + (" NOT" if spec.negated and spec.write is Write.OUT else "")
        if not spec.operand:
            return "ANDLD" if spec.combine is Combine.AND else "ORLD"
        name = {Combine.READ: "LD" if spec.pushes else "ORG", Combine.AND: "AND",
                Combine.OR: "OR"}[spec.combine]
        return name + (" NOT" if spec.negated else "")
    sub = spec.sub or 0
    if spec.dialect and SUB_BASE <= sub < SUB_BASE + 1000:
        return f"FUN {sub - SUB_BASE} {spec.text_name}"
    return spec.text_name


def _line(mnemonic: str, operand: str = "") -> str:
    return f"{mnemonic:<{WIDTH}}{operand}".rstrip()


def _is_fo(address: Address | None) -> bool:
    area, first = FO_AREA
    return address is not None and address.area is area and address.byte >= first \
        and address.bit is not None and address.byte < 9000


_UNKNOWN_RE = re.compile(r"^FUN \d+([DP]*)(?: (.*?))?: (.*)$", re.S)


def unknown_parts(ins: Instruction) -> tuple[str, str, str]:
    """A box's name, forms (`DP`) and kept operand lines: an unknown FUN's comment says them as
    written, `FUN 60DP XYZ: S: R0, D: R1` (lowering.kept_text), shown so on its box."""
    found = _UNKNOWN_RE.match(ins.comment) if ins.spec.name == UNKNOWN_FUN else None
    if found is not None:
        return found.group(2) or "", found.group(1), found.group(3)
    return ins.spec.text_name, "", ins.comment


def _box_lines(ins: Instruction) -> list[str]:
    """A box's step line and its operand lines."""
    spec = ins.spec
    values = ins.param_map()
    if spec.name == "FBS.TMR":
        return [_line("TMR", f"T{values['timer']}  {device_text(values['preset'])}")]
    if spec.name == "FBS.CTR":
        return [_line("CTR", f"C{values['counter']}  {device_text(values['preset'])}")]
    if spec.name == "FBS.RST":
        return [_line("RST", f"{'T' if values['kind'] == 0 else 'C'}{values['number']}")]
    fun = values["fun"] if "fun" in values else (spec.sub or SUB_BASE) - SUB_BASE
    mode = values.get("mode", 0)
    forms = ("D" if isinstance(mode, int) and mode & 2 else "") + (
        "P" if isinstance(mode, int) and mode & 1 else "")
    name, kept_forms, kept = unknown_parts(ins)
    head = _line(f"FUN {fun}{forms or kept_forms}", name)
    lines = [head]
    if spec.cnc or not spec.simulated:  # not simulated: its operand lines kept as the comment
        lines.extend(f"    {text.strip()}" for text in kept.split(", ") if text.strip())
        return lines
    for param in spec.params:
        if param.name in ("mode", "fo", "fun"):
            continue
        label = operand_label(param.name)  # Fatek's D, PV
        lines.append(f"    {label:<2}: {device_text(values[param.name])}")
    return lines


def instruction_lines(instructions: list[Instruction], index: int, first: bool
                      ) -> tuple[list[str], int]:
    """The lines of the instruction at `index` (with the ones it takes along: an edge or a
    comparison contact is `RD SHORT` + its box), and the index after them."""
    ins = instructions[index]
    spec = ins.spec
    following = instructions[index + 1] if index + 1 < len(instructions) else None
    if spec.kind is Kind.BASIC:
        operand = ins.operand
        if spec.stack is not StackOp.NONE:  # a branch point: OUT TR n, LD TR n
            return [_line(spec.text_name, str(ins.params[0]) if ins.params else "")], index + 1
        if spec.write is not Write.NONE:
            if spec.dialect:  # Fatek's own coil row: OUT L
                return [_line(spec.text_name, device_text(operand))], index + 1
            if spec.write is Write.SET:
                return [_line("OUTS", device_text(operand))], index + 1
            if spec.write is Write.RESET:
                return [_line("OUTR", device_text(operand))], index + 1
            text = device_text(operand)
            if text.startswith("TR"):
                return [_line("OUT TR", text[2:])], index + 1
            return [_line("OUT NOT" if spec.negated else "OUT", text)], index + 1
        if not spec.operand:
            return [_line("ANDLD" if spec.combine is Combine.AND else "ORLD")], index + 1
        if spec.combine is Combine.READ:
            if operand in (ALWAYS_ON, ALWAYS_OFF) and following is not None \
                    and following.spec.kind is Kind.FUNCTION:
                follow_spec = following.spec
                if follow_spec.inputs == ("IN",):
                    mnemonic = "ORG" if spec.pushes == 0 else "LD"
                    if spec.pushes and index + 2 < len(instructions) and \
                            instructions[index + 2].name == "OR.STK":
                        mnemonic = "OR"
                        lines = _contact_box(following, mnemonic)
                        return lines, index + 3
                    return _contact_box(following, mnemonic), index + 2
                return [], index + 1  # a box's input not coded (on the rail, or 0)
            text = device_text(operand)
            if text.startswith("TR"):
                return [_line("LD TR", text[2:])], index + 1
            if _is_fo(operand):
                assert operand is not None
                return [_line("FO", str(operand.bit))], index + 1
            mnemonic = "ORG" if spec.pushes == 0 and first else "LD"
            return [_line(mnemonic + (" NOT" if spec.negated else ""), text)], index + 1
        mnemonic = "AND" if spec.combine is Combine.AND else "OR"
        return [_line(mnemonic + (" NOT" if spec.negated else ""),
                      device_text(operand))], index + 1
    if spec.combine is not Combine.NONE:  # an edge or comparison contact in its place
        if spec.combine is Combine.OR:
            mnemonic = "OR"
        else:
            mnemonic = "ORG" if spec.pushes == 0 and first else "LD"
        return _contact_box(ins, mnemonic), index + 1
    if spec.inputs == ("IN",):  # an edge or comparison contact in series (AND)
        return _contact_box(ins, "AND"), index + 1
    lines = _box_lines(ins)
    if spec.w1 and following is not None and following.spec.is_coil:
        lines.append(_line("FO", "0"))
    return lines, index + 1


def _contact_box(ins: Instruction, mnemonic: str) -> list[str]:
    """An edge contact (`ORG TU X2`) or a comparison contact (`ANDF 170 (=)` + Sa, Sb)."""
    series = SERIES_OF.get(ins.spec.name, ins.spec)
    name = series.name
    if name in _CONTACT_BOXES:
        return [_line(f"{mnemonic} {_CONTACT_BOXES[name]}", device_text(ins.params[0]))]
    values = ins.param_map()
    fun = (series.sub or SUB_BASE) - SUB_BASE
    mode = values.get("mode", 0)
    forms = "D" if isinstance(mode, int) and mode & 2 else ""
    return [_line(f"{mnemonic}F {fun}{forms}", ins.spec.text_name),
            f"    Sa: {device_text(values['Sa'])}", f"    Sb: {device_text(values['Sb'])}"]


def network_lines(network: Network, first: bool, style: PrintedStyle | None = None
                  ) -> list[str]:
    """A network's lines (a network that goes on from the one before, after `LD TR n` or
    `FO n`, starts with that line); in WinProladder's printed form when its file is."""
    out: list[str] = []
    index = 0
    instructions = network.instructions
    while index < len(instructions):
        lines, index = instruction_lines(instructions, index, index == 0)
        out.extend(lines)
    if style is not None:
        return printed_lines(out, style, network.line)
    return out


_HIDDEN = ("mode", "fo", "fun")


def params_text(spec: InstructionSpec, values: tuple) -> list[str]:
    """A box's parameters as its drawing shows them: `T50`, `30`, `R0` (its forms and FO byte
    are not operands)."""
    texts: list[str] = []
    named = dict(zip((p.name for p in spec.params), values, strict=False))
    for param in spec.params:
        if param.name in _HIDDEN or param.name not in named:
            continue
        value = named[param.name]
        if param.name in ("timer", "counter"):
            texts.append(f"{'T' if param.name == 'timer' else 'C'}{value}")
        elif param.name == "kind":
            texts.append("T" if value == 0 else "C")
        elif param.name == "number" and texts and texts[-1] in ("T", "C"):
            texts[-1] += str(value)
        else:
            texts.append(device_text(value))
    return texts


def labelled_params_text(spec: InstructionSpec, values: tuple) -> list[str]:
    """A FUN box's operands as the drawing shows them, labelled as WinProladder draws them
    (`S:C0`, `D:R100`, `Sa:R6`: one word each); a timer's, counter's or RST's bare (`T10`)."""
    texts = params_text(spec, values)
    if not (spec.sub or 0) < SUB_BASE + 1000 or spec.inputs == ("IN",):
        return texts  # TMR, CTR, RST (21000 …); a contact's operands above and below it
    labels = [operand_label(p.name) for p in spec.params if p.name not in _HIDDEN]
    return [f"{label.strip()}:{text}" for label, text in zip(labels, texts, strict=False)]


def instruction_text(instruction: Instruction) -> str:
    """One instruction on one line, as a listing in the console shows it: `ORG X0`,
    `FUN 11 (+) Sa: R0 Sb: 7 D: R1`."""
    spec = instruction.spec
    name = mnemonic_of(spec)
    if spec.kind is Kind.BASIC:
        operand = "" if instruction.operand is None else " " + device_text(instruction.operand)
        if spec.stack is not StackOp.NONE and instruction.params:  # OUT TR n, LD TR n
            operand = f" {instruction.params[0]}"
        return (name + operand).strip()
    if spec.cnc:
        fun_name, forms, kept = unknown_parts(instruction)
        if spec.name == UNKNOWN_FUN:
            name = f"FUN {instruction.params[0]}{forms} {fun_name}".strip()
        return f"{name} {kept}".strip()
    texts = params_text(spec, instruction.params)
    labels = [operand_label(p.name) for p in spec.params
              if p.name not in _HIDDEN]
    if name.startswith("FUN"):
        return " ".join([name, *(f"{label}: {text}" for label, text in
                                 zip(labels, texts, strict=False))])
    return " ".join([name, *texts])


def spelling() -> Spelling:
    """Fatek's display texts (core/dialects/spelling.py)."""
    from ladderworks.core.dialects.fatek import DIALECT

    def address_text(address: Address) -> str:
        """An address as Fatek writes it; OPEN and SHORT for the always-0/1 relays."""
        if address in (ALWAYS_ON, ALWAYS_OFF):
            return "SHORT" if address == ALWAYS_ON else "OPEN"
        return DIALECT.format_address(address)

    return Spelling(DIALECT.name, address_text, labelled_params_text, instruction_text,
                    mnemonic_of)
