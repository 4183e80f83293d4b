"""A program's ASCII files for FUN 94: the `.ascii` file beside the listing, one section per
file, headed by the register it is stored from (`[R1000]`) (docs/dialects.md, Fatek)."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.fatek.ascii_format import AsciiFormat, parse_format
from ladderworks.core.dialects.fatek.devices import DeviceError, parse_device, word_address
from ladderworks.core.il.textform import split_lines

SUFFIX = ".ascii"
_HEADER = re.compile(r"^\s*\[\s*([A-Za-z]+\s*\d+)\s*\]\s*$")


@dataclass(slots=True)
class AsciiFiles:
    """The ASCII files by the engine address of their first register; the diagnostics."""

    files: dict[Address, AsciiFormat | None] = field(default_factory=dict)  # None: errors
    diagnostics: list[Diagnostic] = field(default_factory=list)


def read_ascii_files(text: str) -> AsciiFiles:
    """Every `[Rn]` section of the text parsed; a diagnostic at its line for each problem (a
    file with errors is kept as None: ASCWR then ends with ERR)."""
    result = AsciiFiles()
    sections: list[tuple[int, str, list[str]]] = []
    for number, line in enumerate(split_lines(text), start=1):
        header = _HEADER.match(line)
        if header is not None:
            sections.append((number, header.group(1), []))
        elif sections:
            sections[-1][2].append(line)
        elif line.strip():
            result.diagnostics.append(Diagnostic("fatek-ascii-section", {"text": line.strip()},
                                                 number))
    for number, register, body in sections:
        try:
            address = word_address(parse_device(register, bit=False))[0]
        except DeviceError:
            result.diagnostics.append(Diagnostic("fatek-ascii-section", {"text": register},
                                                 number))
            continue
        fmt, problems = parse_format("\n".join(body), first_line=number + 1)
        result.diagnostics.extend(problems)
        result.files[address] = None if problems else fmt
    return result


def ascii_path(program: Path) -> Path:
    """Where a program's ASCII files are: `PROGRAM.lst.ascii` beside it."""
    return program.with_name(program.name + SUFFIX)


def load_ascii_files(program: Path) -> AsciiFiles:
    """The ASCII files beside a program (none when it has no `.ascii` file)."""
    path = ascii_path(program)
    if not path.is_file():
        return AsciiFiles()
    return read_ascii_files(path.read_text(encoding="utf-8"))
