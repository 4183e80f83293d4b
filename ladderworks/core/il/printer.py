"""Printer from a Program back to canonical `.LAD` / `.MOD` text."""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.il.program import Instruction, Program, Section
from ladderworks.core.instructions import ParamKind


def print_instruction(instruction: Instruction) -> str:
    """One instruction in the one-line form, with its trailing comment."""
    spec = instruction.spec
    parts = [spec.name]
    if instruction.operand is not None:
        parts.append(str(instruction.operand))
    fixed = spec.fixed_params()
    for index, value in enumerate(instruction.params):
        param = fixed[index] if index < len(fixed) else None
        if param is not None and param.kind is ParamKind.MASK and isinstance(value, int):
            parts.append(f"{value:04b}")
        elif isinstance(value, Address):
            parts.append(str(value))
        else:
            parts.append(str(value))
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
