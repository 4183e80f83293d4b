"""Printer from a Program back to canonical `.LAD` / `.MOD` text."""

from __future__ import annotations

from ladderworks.core.il.program import Instruction, ParamValue, Program, Section
from ladderworks.core.instructions import InstructionSpec, ParamKind


def format_params(spec: InstructionSpec, params: tuple[ParamValue, ...]) -> list[str]:
    """Each parameter as written in the text (addresses canonical, MOVE masks as 4 digits)."""
    fixed = spec.fixed_params()
    out: list[str] = []
    for index, value in enumerate(params):
        param = fixed[index] if index < len(fixed) else None
        if param is not None and param.kind is ParamKind.MASK and isinstance(value, int):
            out.append(f"{value:04b}")
        else:
            out.append(str(value))
    return out


def print_instruction(instruction: Instruction) -> str:
    """One instruction in the one-line form, with its trailing comment."""
    spec = instruction.spec
    parts = [spec.name]
    if instruction.operand is not None:
        parts.append(str(instruction.operand))
    parts.extend(format_params(spec, instruction.params))
    text = " ".join(parts)
    if instruction.comment:
        text += "  // " + instruction.comment
    return text


def _comment_lines(comments: list[str] | tuple[str, ...]) -> list[str]:
    return ["//" + text for text in comments]


def _section_lines(section: Section) -> list[str]:
    return [f"%@{section.number}", *section.lines, "%"]


def print_program(program: Program) -> str:
    """The whole program as canonical text (LF line ends, final newline)."""
    out: list[str] = _comment_lines(program.header)
    for section in program.before:
        out.extend(_section_lines(section))
    out.append("%@3")
    for index, network in enumerate(program.networks):
        if index:
            out.append("")
        out.extend(_comment_lines(network.comments))
        for instruction in network.instructions:
            out.extend(_comment_lines(instruction.lead))
            out.append(print_instruction(instruction))
    if program.trailer:
        if program.networks:
            out.append("")
        out.extend(_comment_lines(program.trailer))
    out.append("%")
    for section in program.after:
        out.extend(_section_lines(section))
    out.extend(_comment_lines(program.footer))
    return "\n".join(out) + "\n"
