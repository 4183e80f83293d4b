"""Diagnostics: errors and warnings as data (code, arguments, position), with English texts."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import StrEnum


class Severity(StrEnum):
    """How bad a diagnostic is."""

    ERROR = "error"
    WARNING = "warning"


# English message templates by code. The GUI holds the same templates behind tr() so they are
# translated; tests check that every code here has a GUI text. Arguments fill the {names}.
MESSAGES: dict[str, str] = {
    # addresses
    "bad-address": "'{text}' is not an address (expected e.g. X2.1 or R100)",
    "unknown-area": "'{text}': unknown area '{area}' (use X, Y, F, G, R, A, D, T, C or K)",
    "byte-range": "'{text}': byte number out of range for area {area} ({ranges})",
    "bit-range": "'{text}': bit number must be 0 to 7",
    "bit-expected": "'{text}': a bit address is needed here (e.g. {text}.0)",
    "byte-expected": "'{text}': a byte address is needed here, without a bit",
    # the text format
    "missing-start": "the ladder section must begin with %@3",
    "missing-end": "the ladder section must end with a line '%'",
    "unexpected-text": "unexpected text '{text}'",
    "text-outside-section": "text outside any section: '{text}'",
    "duplicate-section": "section %@{number} appears twice",
    "bad-section": "unknown section {header}: kept as it is",
    "unknown-instruction": "unknown instruction '{name}'",
    "missing-operand": "{name} needs an address",
    "extra-operand": "{name} takes no operand, found '{text}'",
    "param-count": "{name} needs {expected} parameters, found {found}",
    "param-kind-number": "{name}: parameter {index} ({param}) must be a number, found '{text}'",
    "param-kind-address": "{name}: parameter {index} ({param}) must be an address, found '{text}'",
    "param-range": "{name}: parameter {index} ({param}) must be {lo} to {hi}, found {value}",
    "param-choice": "{name}: parameter {index} ({param}) must be one of {choices}, found {value}",
    "param-mask":
        "{name}: parameter {index} ({param}) must be up to 4 binary digits, found '{text}'",
    "unknown-sub": ("SUB {number} is not in the instruction table: kept with its parameters,"
                    " drawn as a box, simulated as W1 = ACT"),
    "stray-parameter": "a parameter line '{text}' without a SUB instruction before it",
    "bad-encoding": "the file is neither UTF-8 nor Turkish Windows (cp1254) text",
    "syntax": "syntax error at '{text}'",
    "invalid-bytes": "{count} byte(s) here are not valid {encoding}; they are kept as they are",
    "damaged-draft": "a saved drawing ({lines} line(s)) is damaged: it is kept as comment text",
    "not-a-program": "this is not a ladder program (no %@ section and no instruction)",
    "section-line": "line not understood in section {section}: '{text}'",
    "param-kind-ref":
        "{name}: parameter {index} ({param}) must be {letter} and a number, found '{text}'",
    "number-too-long": "'{text}': the number is too long",
    # the ladder grid (network decomposition)
    "open-circuit": "open circuit: this element is not connected to the right side",
    "not-connected": "element not connected to the left rail",
    "coil-not-right": "a coil must be at the right end of the network",
    "coil-on-rail": "a coil cannot sit straight on the left rail",
    "bridge": "bridge circuit: a vertical link joins two branches in the middle",
    "short-circuit": "short circuit: a wire bypasses the element",
    "stack-depth": "the logic needs more than 8 stack levels (ST8)",
    "reverse-flow": "power would flow right to left here; ladder flows left to right only",
    "empty-network": "the network has no coil or function",
    "box-inputs": "{name} needs its {count} control inputs connected",
    "no-address": "this element has no address yet",
    "coil-branch": "coils hang on different points of the logic; join them to one point",
    "box-output": "only coils may follow the output of {name}",
    "box-twice": "one function box per network: put {name} in a network of its own",
    # ladder edits (refused edits; nothing was changed)
    "edit-outside": "cell ({row}, {col}) is outside the grid",
    "edit-coil-column": "only coils go in the coil column (cell ({row}, {col}))",
    "edit-box-room": "{name} does not fit here: a box needs two contact columns",
    "edit-no-element": "there is no suitable element at cell ({row}, {col})",
    "edit-line": "a line must be horizontal or vertical",
    "grid-text": "the clipboard does not hold ladder elements",
    # the compiler
    "stack-underflow": "{name} with nothing pushed on the stack",
    "write-input": "{name} writes to {address}, an input area",
    "write-result-register": "{name} writes to {address}, part of the read-only R9000-R9005",
    "jmp-without-jmpe": "JMP without a matching JMPE",
    "jmpe-without-jmp": "JMPE without a JMP before it",
    "com-without-come": "COM without a matching COME",
    "come-without-com": "COME without a COM before it",
    "no-logic": "{name} without a logic result before it (start with RD)",
    "coil-twice": "coil {address} is written more than once",
    "dangling-logic": "logic at the end of the program is not written to any coil",
    "bad-binary": "not a LadderWorks binary: {reason}",
    # program structure (levels, subprograms, labels)
    "coil-mixed": "coil {address} is written by WRT and by SET/RST (also on line {line})",
    "label-in-range": "LBL inside a JMP or COM range",
    "label-missing": "no LBL L{label} where this jump can reach it",
    "label-twice": "label L{label} is defined twice in this program unit",
    "jmpc-in-main": "JMPC is only allowed inside a subprogram",
    "call-missing": "subprogram P{program} does not exist",
    "call-recursion": "calling P{program} here makes a subprogram call itself",
    "call-depth": "calls through P{program} nest deeper than {limit} subprograms",
    "sp-without-spe": "SP without a matching SPE",
    "spe-without-sp": "SPE without an SP before it",
    "sp-twice": "subprogram P{program} is defined twice",
    "outside-subprogram": "only subprograms (SP ... SPE) may follow the first SP",
    "level-end-order": "{name} cannot end level {level}",
    "after-end": "instruction after END, the end of the program",
    "endless-loop": "a backward jump to L{label} repeated more than {limit} times in one scan",
    # the alarm message file (AlarmMsg.dat)
    "alarm-line": "not an alarm message line: '{text}' (expected 'NNN text' or 'A00.0 text')",
    "alarm-number": "alarm number {number} is out of range (000 to 799)",
    "alarm-address": "'{text}' is not an alarm bit (A0.0 to A99.7)",
    "alarm-duplicate": "message {number} appears again; the one on line {first} is used",
    "alarm-empty": "message {number} has no text",
    "not-implemented": "{name} is not implemented in the simulator yet",
    # the PMC parameter file (PROGRAM.LAD.prm)
    "prm-line": "not a parameter line: '{text}' (expected ADDRESS = VALUE, e.g. T0:4 = 1000)",
    "prm-area": "'{text}': PMC parameters are in the T, C, K and D areas only",
    "prm-value": "'{text}' is not a value for {width} byte(s)",
}


@dataclass(frozen=True, slots=True)
class Diagnostic:
    """One error or warning with its position (1-based line/column; network/row/col if known)."""

    code: str
    args: dict[str, object] = field(default_factory=dict, hash=False)
    line: int = 0
    column: int = 0
    severity: Severity = Severity.ERROR
    network: int | None = None
    cell: tuple[int, int] | None = None

    @property
    def is_error(self) -> bool:
        """True for errors (not warnings)."""
        return self.severity is Severity.ERROR

    def message(self, templates: dict[str, str] | None = None) -> str:
        """The message text, from `templates` (a translated table) or the English one."""
        table = templates if templates is not None else MESSAGES
        template = table.get(self.code) or MESSAGES.get(self.code) or self.code
        try:
            return template.format(**self.args)
        except (KeyError, IndexError, ValueError):
            return f"{template} {self.args}"

    def located(self, filename: str) -> str:
        """`FILE:LINE:COL: CODE message`, the CLI's format."""
        return f"{filename}:{self.line}:{self.column}: {self.code} {self.message()}"


class DiagnosticError(Exception):
    """Raised where a caller wants an exception; carries the diagnostics."""

    def __init__(self, diagnostics: list[Diagnostic]) -> None:
        self.diagnostics = diagnostics
        super().__init__("; ".join(d.message() for d in diagnostics[:3]))


def has_errors(diagnostics: list[Diagnostic]) -> bool:
    """True when any diagnostic is an error."""
    return any(d.is_error for d in diagnostics)
