"""A WinProladder mnemonic listing (printed/exported, or seed 002's plain form) as records."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ladderworks.core.diagnostics import Diagnostic

# The instructions of a step line (docs/dialects.md, Fatek, the listing)
CONTACTS = ("ORG", "LD", "AND", "OR")  # 002:90-99
STACK_OPS = ("ANDLD", "ORLD")  # 002:243-301
COILS = ("OUT", "OUTS", "OUTR")  # OUT / OUT NOT / OUT L; OUTS set, OUTR reset
BOXES = ("TMR", "CTR", "RST")  # timers, counters, RST of a timer/counter (or a relay)
MODIFIERS = ("NOT", "TU", "TD")

MAX_STEP_DIGITS = 9  # a longer "step number" is not one (int() refuses thousands of digits)


@dataclass(frozen=True, slots=True)
class OperandLine:
    """A FUN box's operand line (`Sa: R0`, `D : R1`, `: C1`): its label and operand text."""

    line: int
    label: str
    text: str
    column: int = field(default=1, compare=False)  # of the operand text


@dataclass(slots=True)
class Record:
    """One instruction of the listing with what its line (and operand lines) said."""

    line: int  # 1-based line of the step
    mnemonic: str  # ORG LD AND OR ANDLD ORLD OUT OUTS OUTR TMR CTR RST FUN FO END, or ORGF …
    modifier: str = ""  # NOT, TU, TD (contacts); NOT, L (OUT); TR (OUT TR / LD TR)
    operand: str = ""  # the device as written, joined (`X0`, `TR0`), OPEN / SHORT, or ""
    step: int | None = None  # the step number, None in seed 002's plain form
    unit: str = ""  # the program unit's letter after the step number
    fun: int | None = None  # FUN n (and the comparison contacts' number)
    fun_name: str = ""  # MOV, (+), (=) … as written
    pulse: bool = False  # the P form: runs on the input's rising edge
    double: bool = False  # the D form: 32-bit operands
    args: tuple[str, ...] = ()  # further operands on the step line (TMR base and PV, …)
    operands: list[OperandLine] = field(default_factory=list)
    column: int = 1  # of the mnemonic

    @property
    def last_line(self) -> int:
        """The last line that belongs to the record."""
        return self.operands[-1].line if self.operands else self.line


@dataclass(slots=True)
class Listing:
    """The records of a listing, with its page header lines (their line numbers)."""

    records: list[Record]
    headers: list[int]


_HEADER_RE = re.compile(r"^\s*(Printed Item\s*:|Page\s+\d+\b)", re.I)
_STEP_RE = re.compile(r"^\s*(\d+)([A-Za-z]?)(?=\s)\s+(.*)$")
_OPERAND_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9]{0,3})?\s*:\s*(\S.*?)\s*$")
_FUN_RE = re.compile(r"^FUN\s*(\d+)\s*(D?)\s*(P?)\s*\.?\s*(.*)$", re.I)
_CMP_RE = re.compile(r"^(ORG|LD|AND|OR)F\s+(?:FUN\s*)?(\d+)\s*(D?)\s*(P?)\s*\.?\s*(.*)$", re.I)
_FO_RE = re.compile(r"^FO\s*(\d+)$", re.I)
_DEVICE_SPLIT_RE = re.compile(r"^([A-Za-z]{1,3})\s+(\d+)$")
_RST_RE = re.compile(r"^RST\s*\(\s*([A-Za-z]*\s*\d*)\s*\)", re.I)
_ANNOTATION = "←"  # the seed's margin notes (002:376-402)


def _strip_note(text: str) -> str:
    """The instruction without a margin note (`LD TR 0 ← 2. sıradan başlar`) or a `;` comment."""
    for mark in (_ANNOTATION, ";"):
        if mark in text:
            text = text[:text.index(mark)]
    return text.strip()


def _device(words: list[str]) -> str:
    """Device words joined: `X 0` (seed 002's columns) and `X0` both give `X0`."""
    text = " ".join(words)
    split = _DEVICE_SPLIT_RE.match(text)
    return split.group(1) + split.group(2) if split else text.replace(" ", "")


def _step_record(text: str, line: int, step: int | None, unit: str, column: int = 1
                 ) -> tuple[Record | None, Diagnostic | None]:
    """The record a step line's instruction part makes, or the diagnostic of a bad one."""
    record, problem = _step_kind(text, line, step, unit)
    if record is not None:
        record.column = column
    if problem is not None:
        problem = Diagnostic(problem.code, problem.args, problem.line, column)
    return record, problem


def _step_kind(text: str, line: int, step: int | None, unit: str
               ) -> tuple[Record | None, Diagnostic | None]:
    """_step_record without the column."""
    fun = _FUN_RE.match(text)
    if fun is not None:
        return Record(line, "FUN", step=step, unit=unit, fun=int(fun.group(1)),
                      double=bool(fun.group(2)), pulse=bool(fun.group(3)),
                      fun_name=fun.group(4).strip()), None
    cmp = _CMP_RE.match(text)
    if cmp is not None:
        return Record(line, cmp.group(1).upper() + "F", step=step, unit=unit,
                      fun=int(cmp.group(2)), double=bool(cmp.group(3)),
                      pulse=bool(cmp.group(4)), fun_name=cmp.group(5).strip()), None
    fo = _FO_RE.match(text)
    if fo is not None:
        return Record(line, "FO", operand=fo.group(1), step=step, unit=unit), None
    text = _RST_RE.sub(lambda m: f"RST {m.group(1)}", text)  # `RST( ) C0`, `RST(C0)`
    words = text.split()
    name = words[0].upper()
    rest = words[1:]
    record = Record(line, name, step=step, unit=unit)
    if name in CONTACTS or name in COILS:
        if rest and rest[0].upper() == "TR" and name in ("LD", "OUT"):
            record.modifier = "TR"
            record.operand = "TR" + "".join(rest[1:])
            return record, None
        first = rest[0].upper() if rest else ""
        latch = name == "OUT" and first == "L" and len(rest) > 1  # `OUT L` alone: no device
        if first in MODIFIERS or latch:
            record.modifier = first
            rest = rest[1:]
        if name in CONTACTS and rest and rest[0].upper() in ("OPEN", "SHORT") and len(rest) == 1:
            record.operand = rest[0].upper()
            return record, None
        record.operand = _device(rest)
        return record, None
    if name in STACK_OPS or name == "END":
        if rest:
            return None, Diagnostic("extra-operand", {"name": name, "text": " ".join(rest)},
                                    line)
        return record, None
    if name in BOXES:
        record.operand = rest[0] if rest else ""
        record.args = tuple(rest[1:])
        return record, None
    return None, Diagnostic("fatek-unknown-instruction", {"name": words[0]}, line)


def read_listing(lines: list[str], first_line: int = 1) -> tuple[Listing, list[Diagnostic]]:
    """The records of a listing's lines (without their line ends); page headers and blank lines
    skipped; an operand line joins the FUN, comparison, TMR or CTR record before it. Seed 002's
    `OUT` / `Y 0` printed over two lines (002:319-326) joins too."""
    records: list[Record] = []
    headers: list[int] = []
    diagnostics: list[Diagnostic] = []
    for index, raw in enumerate(lines):
        line = first_line + index
        text = _strip_note(raw)
        if not text:
            continue
        if _HEADER_RE.match(text):
            headers.append(line)
            continue
        operand = _OPERAND_RE.match(text)
        if operand is not None and not _STEP_RE.match(text):
            last = records[-1] if records else None
            if last is None or (last.fun is None and last.mnemonic not in BOXES):
                diagnostics.append(Diagnostic("fatek-stray-operand", {"text": text}, line,
                                              _column(raw, text)))
                continue
            last.operands.append(OperandLine(line, (operand.group(1) or "").strip(),
                                             operand.group(2),
                                             _column(raw, operand.group(2))))
            continue
        step_match = _STEP_RE.match(raw)
        step: int | None = None
        unit = ""
        if step_match is not None and not raw.lstrip()[0].isalpha() \
                and len(step_match.group(1)) <= MAX_STEP_DIGITS:  # int() refuses 4300 digits
            step = int(step_match.group(1))
            unit = step_match.group(2).upper()
            text = _strip_note(step_match.group(3))
            if not text:  # a step number alone (or with a margin note)
                continue
        if records and _continues(records[-1], text):
            records[-1].operand = _device(text.split())
            continue
        record, problem = _step_record(text, line, step, unit, _column(raw, text))
        if problem is not None:
            diagnostics.append(problem)
        if record is not None:
            records.append(record)
    return Listing(records, headers), diagnostics


def _continues(last: Record, text: str) -> bool:
    """True when `text` is the device of a coil printed alone before it (002:319-326)."""
    return (last.mnemonic in COILS and not last.operand and last.modifier != "TR"
            and _DEVICE_SPLIT_RE.match(text) is not None)


def _column(raw: str, text: str) -> int:
    """1-based column of `text` in the line (1 when it is not found as written)."""
    at = raw.find(text.split()[0]) if text.split() else -1
    if step := _STEP_RE.match(raw):
        found = raw.find(text.split()[0], step.start(3)) if text.split() else -1
        at = found if found >= 0 else at
    return at + 1 if at >= 0 else 1
