"""A `.dvp` project as a Program: its instruction list read by the Delta reader, its comments as
symbols (a damaged project: its error, and the instructions read before the damage to show);
and where a program read from one may not be saved (LadderWorks writes no `.dvp`)."""

from __future__ import annotations

from pathlib import Path

from ladderworks.core.address import AddressError
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.delta import DEVICES, DIALECT, NAME
from ladderworks.core.dialects.delta.dvp_codes import DvpInstruction
from ladderworks.core.dialects.delta.dvp_file import DvpError, DvpProject, is_dvp, read_dvp
from ladderworks.core.il.parser import ParseResult
from ladderworks.core.il.program import Program
from ladderworks.core.il.textform import TextForm, split_with_ends
from ladderworks.core.symbols import Symbol, SymbolTable

SUFFIX = ".dvp"


def instruction_text(instructions: list[DvpInstruction]) -> str:
    """Instructions as a Delta instruction list, one a line (`LD X0`)."""
    return "".join(each.text() + "\n" for each in instructions)


def symbol_table(comments: dict[str, str]) -> SymbolTable:
    """The device comments as the program's symbols (a comment, no symbol name): T and C by
    their contact and their value, D by its word, X/Y/M/S by their bit."""
    table = SymbolTable()
    for device, text in comments.items():
        entry = Symbol("", (text,) if text else ())
        for want in ("bit", "word"):
            try:
                address, _width = DEVICES.target(device, want)
            except AddressError:
                continue
            table.add(address, entry)
    return table


def _read_list(instructions: list[DvpInstruction]) -> tuple[Program, list[Diagnostic]]:
    """The instructions as a Delta instruction list (LF lines), read by the Delta reader."""
    text = instruction_text(instructions)
    lines, ends = split_with_ends(text)
    return DIALECT.read(text, TextForm(), lines, ends)


def parse_dvp(data: bytes) -> ParseResult:
    """The Program a `.dvp` project holds, with its diagnostics: the file's own error (with its
    byte offset) and nothing else when it cannot be read."""
    try:
        project: DvpProject = read_dvp(data)
    except DvpError as error:  # shown with the instructions read before the damage, if any
        program = _read_list(error.read)[0] if error.read else Program(dialect=NAME)
        return ParseResult(program, [error.diagnostic(len(error.read) + 1)])
    program, diagnostics = _read_list(project.instructions)
    program.symbols = symbol_table(project.comments)
    found = sorted(diagnostics, key=lambda d: (d.line, d.column))
    return ParseResult(program, [*project.warnings, *found])


def save_refused(path: str | Path, read_from_dvp: bool = False) -> Diagnostic | None:
    """The reason a program may not be written to `path`, or None: the file there is a `.dvp`
    project, or the name ends with .dvp and the program was read from one."""
    target = Path(path)
    try:
        with open(target, "rb") as file:
            binary = is_dvp(file.read(4))
    except OSError:
        binary = False
    if binary or (read_from_dvp and target.suffix.lower() == SUFFIX):
        return Diagnostic("dvp-save-refused", {"path": str(target)})
    return None
