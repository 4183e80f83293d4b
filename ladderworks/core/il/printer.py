"""Printers from a Program back to text: canonical (`format`) and faithful (Save)."""

from __future__ import annotations

from difflib import SequenceMatcher
from typing import TYPE_CHECKING

from ladderworks.core import dialects
from ladderworks.core.diagnostics import Refused
from ladderworks.core.il.model_marker import head_lines, header_texts
from ladderworks.core.il.program import FANUC, Instruction, Network, ParamValue, Program, Section
from ladderworks.core.il.textform import encode_text
from ladderworks.core.instructions import InstructionSpec, Kind, ParamKind

if TYPE_CHECKING:
    from ladderworks.core.dialects.base import Dialect

MNEMONIC_WIDTH = 10  # LADDER-III pads a basic instruction's mnemonic to 10 characters + 1


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
    parts = [spec.text_name if spec.known else instruction.name]  # `SUB.219` for unknown SUB
    if instruction.operand is not None:
        parts.append(str(instruction.operand))
    parts.extend(format_params(spec, instruction.params))
    text = " ".join(parts)
    if instruction.comment:
        text += "  // " + instruction.comment
    return text


def instruction_lines(instruction: Instruction) -> list[str]:
    """An instruction in the canonical text: one line, or `SUB n` + its parameter lines for a
    SUB the table does not know (its one-line form would read as subtraction)."""
    spec = instruction.spec
    if spec.known or spec.sub is None:
        return [print_instruction(instruction)]
    lines = [f"SUB {spec.sub}", *format_params(spec, instruction.params)]
    if instruction.comment:
        lines[0] += "  // " + instruction.comment
    return lines


def fanuc_instruction_lines(instruction: Instruction) -> list[str]:
    """One instruction as LADDER-III writes it: `RD         X21.7`, or `SUB n` + a line a param."""
    spec = instruction.spec
    if spec.kind is Kind.BASIC:
        lines = [spec.name if instruction.operand is None
                 else f"{spec.name:<{MNEMONIC_WIDTH}} {instruction.operand}"]
    elif spec.sub is not None:
        lines = [f"SUB {spec.sub}", *format_params(spec, instruction.params)]
    else:
        lines = [print_instruction(instruction)]
        return [*(";" + text for text in instruction.lead), *lines]
    if instruction.comment:
        lines[0] += "  ; " + instruction.comment
    return [*(";" + text for text in instruction.lead), *lines]


def _comment_lines(comments: list[str] | tuple[str, ...], marker: str = "//") -> list[str]:
    return [marker + text for text in comments]


def _section_lines(section: Section) -> list[str]:
    return [section.title, *section.lines, "%"]


def print_program(program: Program) -> str:
    """The whole program as canonical text (LF line ends, final newline)."""
    other = dialects.of(program)
    if other is not None:  # a dialect's program: its own text, network after network
        lines = [line for n, network in enumerate(program.networks)
                 for line in other.network_lines(network, n == 0)]
        lines += _comment_lines(program.trailer, ";")
        lines += other.closing
        return "\n".join(lines) + "\n"
    out: list[str] = _comment_lines(header_texts(program))
    if program.framed:
        out.append("%@A")
    for section in program.before:
        out.extend(_section_lines(section))
    out.append("%@3")
    for index, network in enumerate(program.networks):
        if index:
            out.append("")
        out.extend(_comment_lines(network.comments))
        if network.label:
            out.append(network.label + ":")
        for instruction in network.instructions:
            out.extend(_comment_lines(instruction.lead))
            out.extend(instruction_lines(instruction))
    if program.trailer:
        if program.networks:
            out.append("")
        out.extend(_comment_lines(program.trailer))
    out.append("%")
    for section in program.after:
        out.extend(_section_lines(section))
    if program.framed:
        out.append("%@E")
    out.extend(_comment_lines(program.footer))
    return "\n".join(out) + "\n"


def _fresh_network(network: Network, fanuc: bool, first: bool,
                   dialect: Dialect | None = None, style: object = None) -> list[str]:
    """A new or changed network in the program's own style (LADDER-III, one-line, or its
    dialect's: Delta; `style`: the form its file is written in)."""
    if dialect is not None:
        return dialect.network_lines(network, first, style)
    if fanuc:
        out = _comment_lines(network.comments, ";")
        if network.label:
            out.append(network.label + ":")
        for instruction in network.instructions:
            out.extend(fanuc_instruction_lines(instruction))
        return out
    out = [] if first else [""]
    out.extend(_comment_lines(network.comments))
    if network.label:
        out.append(network.label + ":")
    for instruction in network.instructions:
        out.extend(_comment_lines(instruction.lead))
        out.extend(instruction_lines(instruction))
    return out


def _align(old: list[tuple[object, ...]], new: list[tuple[object, ...]]
           ) -> list[tuple[str, int, int, int, int]]:
    """difflib opcodes between the parsed and the current networks (common ends trimmed)."""
    head = 0
    limit = min(len(old), len(new))
    while head < limit and old[head] == new[head]:
        head += 1
    tail = 0
    while tail < limit - head and old[-1 - tail] == new[-1 - tail]:
        tail += 1
    codes: list[tuple[str, int, int, int, int]] = []
    if head:
        codes.append(("equal", 0, head, 0, head))
    middle = SequenceMatcher(None, old[head:len(old) - tail], new[head:len(new) - tail],
                             autojunk=False).get_opcodes()
    codes.extend((tag, i1 + head, i2 + head, j1 + head, j2 + head)
                 for tag, i1, i2, j1, j2 in middle)
    if tail:
        codes.append(("equal", len(old) - tail, len(old), len(new) - tail, len(new)))
    return codes


def print_faithful(program: Program) -> str:
    """The program as its file holds it: unchanged parts byte for byte, changed networks only
    rewritten (in the file's style); a program not read from a file prints canonically."""
    source = program.source
    if source is None or source.ladder_start < 0:
        newline = program.form.newline
        text = print_program(program)
        return text.replace("\n", newline) if newline != "\n" else text
    lines, ends, newline = source.lines, source.ends, source.form.newline
    fanuc = program.dialect == FANUC
    other = dialects.of(program)
    style = other.style_of(lines) if other is not None else None
    out: list[str] = []
    fresh_at: set[int] = set()  # the lines printed fresh, and where the file's own follow a
    joins: set[int] = set()  # change (a dialect's `finish` writes them in the file's form)
    last_stop = source.ladder_start

    def verbatim(start: int, stop: int) -> None:
        nonlocal last_stop
        if start != last_stop and start < stop:
            joins.add(len(out))
        last_stop = stop
        out.extend(lines[i] + ends[i] for i in range(start, stop))

    def fresh(texts: list[str]) -> None:
        fresh_at.update(range(len(out), len(out) + len(texts)))
        out.extend(text + newline for text in texts)

    # the lines before the ladder as read; the PMC model's marker as the program says
    out.extend(head_lines(program, lines[:source.ladder_start], ends[:source.ladder_start],
                          newline))
    new_keys = [network.key() for network in program.networks]
    if other is not None and other.refuse_changes and (
            new_keys != source.keys or tuple(program.trailer) != source.trailer
            or other.source_changed(program)):
        written = other.write_changed(program)
        if written is None:
            raise Refused(other.refuse_changes)
        return written
    last_fresh = False
    for tag, i1, i2, j1, j2 in _align(source.keys, new_keys):
        if tag == "equal":
            verbatim(source.spans[i1][0], source.spans[i2 - 1][1])
            last_fresh = False
            continue
        unused = list(range(i1, i2))
        for j in range(j1, j2):
            network = program.networks[j]
            # a changed network keeps the label and comment lines of the old one it replaces
            i = next((k for k in unused if source.keys[k][:2] == new_keys[j][:2]), None)
            if i is not None:
                unused.remove(i)
                verbatim(source.spans[i][0], source.heads[i])
                body = Network(network.instructions)
                fresh(_fresh_network(body, fanuc, True, other, style))
            else:
                fresh(_fresh_network(network, fanuc, j == 0, other, style))
            last_fresh = True
    if tuple(program.trailer) == source.trailer:
        verbatim(*source.trailer_span)
        last_fresh = last_fresh and source.trailer_span[0] == source.trailer_span[1]
    else:
        fresh(_comment_lines(program.trailer, ";" if fanuc or other else "//"))
        last_fresh = True
    verbatim(source.ladder_stop, len(lines))
    if other is not None:
        out = other.finish_lines(program, out, fresh_at, joins)
    text = "".join(out)
    if last_fresh and source.ladder_stop == len(lines) and not source.form.final_newline:
        text = text[:-len(newline)] if text.endswith(newline) else text
    return text


def encode_program(program: Program) -> bytes:
    """The bytes Save writes: the faithful text in the file's own encoding, BOM and line ends.

    Raises textform.EncodeError (line, column, character) when a character does not fit."""
    return encode_text(print_faithful(program), program.form)
