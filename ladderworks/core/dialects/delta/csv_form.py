"""WPLSoft's exported instruction lists: `000012,MPS`, `000100,TMR,T0,K50` (docs/dialects.md).

A step number (6 digits as WPLSoft writes it), the mnemonic and its operands separated by
commas (or `;`, or tabs), some files with a separator at each line's end; or the same without
step numbers (`LD,M0`). `detect` finds a text's form from its first lines; `fields` splits a
line; `steps` is an instruction's size in program steps (WPLSoft numbers each line by the steps
before it); `finish` writes the lines Save made fresh in the file's own form, with the step
numbers WPLSoft would give.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ladderworks.core.dialects.delta import instructions as rows
from ladderworks.core.dialects.delta import table

if TYPE_CHECKING:
    from ladderworks.core.il.program import Program

SAMPLE = 50  # code lines looked at to find the form
_NUMBERED = re.compile(r'^[ \t]*"?(\d{1,8})"?[ \t]*([,;\t])')
_PLAIN = re.compile(r'^[ \t]*"?[A-Za-z][A-Za-z0-9=<>&|^]*"?[ \t]*([,;])')
_ALONE = re.compile(r"^[ \t]*[A-Za-z][A-Za-z0-9]*[ \t]*([,;]?)[ \t]*$")  # MPS, END, ANB,
_POINTER = re.compile(r"^[Pp]\d+:?$")


@dataclass(frozen=True, slots=True)
class CsvForm:
    """How a file writes its instruction lines."""

    separator: str  # ",", ";" or a tab
    numbered: bool  # a step number first
    digits: int = 6  # the step number's width
    trailing: bool = False  # a separator at the end of each line
    quoted: bool = False  # each field in double quotes (`"000012","MPS"`)

    def comment(self, text: str) -> bool:
        """True if the line is a comment line (`// text`; `; text` unless `;` separates)."""
        stripped = text.lstrip()
        return stripped.startswith("//") or (self.separator != ";" and stripped[:1] == ";")


def detect(lines: list[str]) -> CsvForm | None:
    """The export form of a text's lines, None for WPLSoft's instruction mode text (spaces)."""
    separators: dict[str, int] = {}
    numbered = plain = trailing = seen = quoted = 0
    digits = 6
    for line in lines:
        if not line.strip() or line.lstrip()[:2] == "//":
            continue
        seen += 1
        found = _NUMBERED.match(line)
        if found is not None:
            numbered += 1
            digits = len(found.group(1))
            separator = found.group(2)
        else:
            found = _PLAIN.match(line) or _ALONE.match(line)
            if found is None or (found.re is _ALONE and not found.group(1)):
                if seen >= SAMPLE:
                    break
                continue
            plain += 1
            separator = found.group(1)
        separators[separator] = separators.get(separator, 0) + 1
        quoted += line.lstrip().startswith('"')
        trailing += line.rstrip(" \r").endswith(separator)
        if seen >= SAMPLE:
            break
    if not separators or (numbered + plain) * 2 < seen:
        return None
    separator = max(separators, key=lambda key: separators[key])
    if separator == "\t" and not numbered:
        return None  # tabs without step numbers: the instruction mode text reads it
    return CsvForm(separator, numbered * 2 >= seen, digits, trailing * 2 >= numbered + plain,
                   quoted * 2 >= numbered + plain)


def fields(line: str, separator: str) -> list[tuple[str, int]]:
    """The non-empty fields of a line up to the last, each with its column (1-based); an empty
    field between two others is kept as "" (a missing operand)."""
    out: list[tuple[str, int]] = []
    at = 0
    for part in line.split(separator):
        text = part.strip()
        column = at + len(part) - len(part.lstrip()) + 1
        if len(text) >= 2 and text[0] == text[-1] == '"':  # a quoted field
            text, column = text[1:-1].strip(), column + 1
        out.append((text, column))
        at += len(part) + len(separator)
    while out and not out[-1][0]:
        out.pop()
    return out


_OPERAND = re.compile(r"^[A-Za-z]+[-+]?[0-9][0-9A-Za-z.]*$")  # X0, K-5, H0, K4M0, D0E


def is_header(form: CsvForm, words: list[str]) -> bool:
    """True for a column header line of a numbered export (`Step,Instruction,Operand`): words
    only, no step number, no digit anywhere."""
    return form.numbered and len(words) > 1 and not any(
        char.isdigit() for word in words for char in word)


def trailing_comment(words: list[str]) -> str:
    """Take the fields after the mnemonic that are not operands (text: `Start button`,
    `Motor`) off the end of `words`; they are the line's comment."""
    taken: list[str] = []
    while len(words) > 2 and words[-1] and _OPERAND.match(words[-1]) is None:
        taken.append(words.pop())
    return ", ".join(reversed(taken))


def _double(mnemonic: str) -> bool:
    """A 32-bit form: D before a 16-bit mnemonic (DMOV, DADD, DLD=; not DIV, DECO, DI)."""
    rest = mnemonic[1:]
    base = rest[:-1] if rest.endswith("P") else rest
    return mnemonic[:1] == "D" and any(
        name in rows.SPELLINGS or name in table.NOT_SIMULATED for name in (rest, base))


# program steps of the basic instructions that are not 1 step (WPLSoft's export of a real
# program numbers its lines so, docs/dialects.md "WPLSoft's export")
_BASIC_STEPS = {"LDP": 3, "LDF": 3, "ANDP": 3, "ANDF": 3, "ORP": 3, "ORF": 3, "PLS": 3,
                "PLF": 3, "RST": 3, "MC": 3, "MCR": 3, "TMR": 4, "CNT": 4, "DCNT": 6}
_ONE_STEP = frozenset(("LD", "LDI", "AND", "ANI", "OR", "ORI", "ANB", "ORB", "MPS", "MRD",
                       "MPP", "INV", "OUT", "SET", "NOP", "END", "FEND", "SRET", "IRET", "STL",
                       "RET", "EI", "DI"))


def steps(mnemonic: str, operands: int) -> int:
    """The program steps an instruction takes: a basic one 1 (edge contacts, PLS/PLF, RST, MC,
    MCR 3; TMR, CNT 4; DCNT 6), an applied one 1 and 2 per operand (a 32-bit D form 4), a
    pointer 1."""
    name = mnemonic.upper()
    if name in _BASIC_STEPS:
        return _BASIC_STEPS[name]
    if name in _ONE_STEP or _POINTER.match(name):
        return 1
    return 1 + (4 if _double(name) else 2) * operands


def finish(program: Program, out: list[str], fresh: set[int], joins: set[int]) -> list[str]:
    """The faithful Save's lines (each with its end) in the file's form: the lines in `fresh`
    (the printer's) written with the file's separator and step numbers; from each line in
    `joins` (the file's own lines that follow a changed or deleted part) on, the file's step
    numbers moved to follow the steps before them (each instruction's size: `steps`)."""
    source = program.source
    form = detect(source.lines[:SAMPLE * 2]) if source is not None else None
    if form is None or not (fresh or joins):
        return out
    result: list[str] = []
    step = 0  # the step of the next instruction line
    shift = 0  # steps added (or taken) by the changes so far
    moved = False  # a change came since the last of the file's own numbered lines
    for index, line in enumerate(out):
        body = line.rstrip("\r\n")
        end = line[len(body):]
        moved = moved or index in joins
        if index in fresh:
            stripped = body.strip()
            if stripped[:1] == ";" or stripped[:2] == "//" or not stripped:
                text = stripped.lstrip(";/").strip()
                result.append(f"// {text}{end}" if stripped else line)
                continue
            words = stripped.split(";")[0].split()  # an element's comment is not kept here
            fields_out = [f"{step:0{form.digits}d}"] * form.numbered + words
            if form.quoted:
                fields_out = [f'"{field}"' for field in fields_out]
            text = form.separator.join(fields_out) + (form.separator if form.trailing else "")
            result.append(text + end)
            step += steps(words[0], len(words) - 1)
            moved = True
            continue
        found = _NUMBERED.match(body) if form.numbered else None
        if found is None:
            result.append(line)
            continue
        own = int(found.group(1))
        if moved:
            shift, moved = step - own, False
        number = own + shift
        result.append(f"{body[:found.start(1)]}{number:0{len(found.group(1))}d}"
                      f"{body[found.end(1):]}{end}" if shift else line)
        words = [text for text, _column in fields(body[found.end():], form.separator)]
        step = number + steps(words[0] if words else "", max(len(words) - 1, 0))
    return result
