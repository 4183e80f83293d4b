"""Delta text of a new or changed network: one instruction a line, Delta's spelling."""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.dialects.delta import DEVICES
from ladderworks.core.dialects.delta.rows_extra import (
    LOOP_BACK_ROW,
    LOOP_ROW,
    LOOP_TEST_ROW,
    PULSED,
    STEP_MOVE_ROWS,
    STEP_NEXT_ROW,
    STEP_ROW,
)
from ladderworks.core.dialects.spelling import Spelling
from ladderworks.core.il.program import Instruction, LabelRef, Network, ProgramRef
from ladderworks.core.instructions import Combine, Flow, InstructionSpec, Kind, ParamKind, Write


def mnemonic_of(spec: InstructionSpec) -> str:
    """Delta's mnemonic of a row of the table (`LD` for RD, `TMR` for DVP.TMR)."""
    return _basic_name(spec) if spec.kind is Kind.BASIC and not spec.dialect else spec.text_name


def _basic_name(spec: InstructionSpec) -> str:
    """Delta's mnemonic of a basic row of the table, read from its fields."""
    if spec.write is Write.SET:
        return "SET"
    if spec.write is Write.RESET:
        return "RST"
    if spec.write is Write.OUT:
        return "OUT"
    if spec.combine is Combine.READ:
        return "LDI" if spec.negated else "LD"
    if spec.combine is Combine.AND:
        return ("ANI" if spec.negated else "AND") if spec.operand else "ANB"
    if spec.combine is Combine.OR:
        return ("ORI" if spec.negated else "OR") if spec.operand else "ORB"
    return spec.text_name


def operand_text(value: object) -> str:
    """An operand in Delta's spelling: a device, `K10`, `P1`."""
    if isinstance(value, Address):
        return DEVICES.format(value) or str(value)
    if isinstance(value, LabelRef | ProgramRef):
        return f"P{value.number}"
    return f"K{value}"


def instruction_lines(instruction: Instruction) -> list[str]:
    """The lines of one instruction (an inverted coil is INV, OUT, INV)."""
    spec = instruction.spec
    comment = f"  ; {instruction.comment}" if instruction.comment else ""
    if spec.kind is Kind.BASIC and not spec.dialect:
        name = _basic_name(spec)
        operand = "" if instruction.operand is None else "\t" + operand_text(instruction.operand)
        if spec.write is Write.OUT and spec.negated:
            return ["INV", f"OUT{operand}{comment}", "INV"]
        return [f"{name}{operand}{comment}"]
    if spec.name == LOOP_ROW.name:  # FOR n (its label is the reader's)
        return [f"{spec.text_name}\t{operand_text(instruction.params[-1])}{comment}"]
    if spec.name == LOOP_TEST_ROW.name:
        return [spec.text_name + comment]
    if spec.flow in (Flow.LABEL, Flow.SUBPROGRAM):
        return [" ".join(operand_text(p) for p in instruction.params) + comment]
    if spec.name in (STEP_NEXT_ROW.name, LOOP_BACK_ROW.name):  # written by STL, NEXT
        return []
    if spec.name == STEP_ROW.name or spec.name in STEP_MOVE_ROWS.values():  # STL Sn, SET Sm
        step = instruction.params[-1 if spec.name == STEP_ROW.name else 0]
        return [f"{spec.text_name}\t{operand_text(step)}{comment}"]
    return ["\t".join([spec.text_name, *params_text(spec, instruction.params)]) + comment]


def params_text(spec: InstructionSpec, values: tuple[object, ...]) -> list[str]:
    """A functional instruction's operands as Delta writes them (MC's `coils` 0 left out; a
    shown-only instruction's as it was written)."""
    if spec.operand_texts:
        return list(spec.operand_texts)
    params = list(values)
    if spec.flow is Flow.COMMON:
        params = params[1:]
    if spec.name in STEP_MOVE_ROWS.values():  # SET Sm (the step it leaves is the reader's)
        params = params[:1]
    if spec.name == LOOP_ROW.name:  # FOR n (its label is the reader's)
        params = params[1:]
    texts = []
    for param, value in zip(spec.params[-len(params):] if params else (), params, strict=False):
        texts.append(f"N{value}" if param.kind is ParamKind.NUMBER and param.name == "nest"
                     else operand_text(value))
    return texts


def instruction_text(instruction: Instruction) -> str:
    """One instruction on one line (a listing in the console): `LD= T0 K5`."""
    return " / ".join(line.replace("\t", " ") for line in instruction_lines(instruction))


def network_lines(network: Network, first: bool) -> list[str]:
    """A network's lines: its comment lines (`; text`), then its instructions."""
    out = [f"; {text}" for text in network.comments]
    instructions = network.instructions
    for index, instruction in enumerate(instructions):
        if _step_read(instructions, index) or _pulse_part(instructions, index):
            continue
        out.extend(instruction_lines(instruction))
    return out


def _pulse_part(instructions: list[Instruction], index: int) -> bool:
    """True for the MPS, CJ/CALL and MPP the reader put around a CJP/CALLP (its line says it)."""
    for offset in (-1, 1, 2):
        at = index - offset
        if 0 <= at < len(instructions) and instructions[at].name in PULSED:
            return True
    return False


def _step_read(instructions: list[Instruction], index: int) -> bool:
    """True for the LD Sn the reader put before and after a STL Sn (its line says it)."""
    here = instructions[index]
    for other in (index - 1, index + 1):
        if 0 <= other < len(instructions) and instructions[other].name == STEP_ROW.name \
                and instructions[other].params[-1] == here.operand \
                and here.spec.kind is Kind.BASIC and here.spec.combine is Combine.READ:
            return True
    return False


def spelling() -> Spelling:
    """Delta's display texts (core/dialects/spelling.py)."""
    from ladderworks.core.dialects.delta import DIALECT

    return Spelling(DIALECT.name, DIALECT.format_address, params_text, instruction_text,
                    mnemonic_of)
