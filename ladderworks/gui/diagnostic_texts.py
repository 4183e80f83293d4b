"""Diagnostic messages behind tr(): the GUI's translatable copy of the core's MESSAGES."""

from __future__ import annotations

from dataclasses import replace

from PySide6.QtCore import QCoreApplication

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.gui.translation import param_label

translate = QCoreApplication.translate


def diagnostic_templates() -> dict[str, str]:
    """Message templates by code in the current UI language ({names} filled from args)."""
    return {
        "bad-address": translate(
            "Diagnostic", "'{text}' is not an address (expected e.g. X2.1 or R100)"),
        "unknown-area": translate(
            "Diagnostic", "'{text}': unknown area '{area}' (use X, Y, F, G, R, A, D, T, C or K)"),
        "byte-range": translate(
            "Diagnostic", "'{text}': byte number out of range for area {area} ({ranges})"),
        "bit-range": translate("Diagnostic", "'{text}': bit number must be 0 to 7"),
        "bit-expected": translate(
            "Diagnostic", "'{text}': a bit address is needed here (e.g. {text}.0)"),
        "byte-expected": translate(
            "Diagnostic", "'{text}': a byte address is needed here, without a bit"),
        "missing-start": translate("Diagnostic", 'the ladder section must begin with %@3'),
        "missing-end": translate("Diagnostic", "the ladder section must end with a line '%'"),
        "unexpected-text": translate("Diagnostic", "unexpected text '{text}'"),
        "text-outside-section": translate("Diagnostic", "text outside any section: '{text}'"),
        "duplicate-section": translate("Diagnostic", 'section %@{number} appears twice'),
        "bad-section": translate(
            "Diagnostic", "unknown section {header}: kept as it is"),
        "unknown-instruction": translate("Diagnostic", "unknown instruction '{name}'"),
        "missing-operand": translate("Diagnostic", '{name} needs an address'),
        "extra-operand": translate("Diagnostic", "{name} takes no operand, found '{text}'"),
        "param-count": translate("Diagnostic", '{name} needs {expected} parameters, found {found}'),
        "param-kind-number": translate(
            "Diagnostic", "{name}: parameter {index} ({param}) must be a number, found '{text}'"),
        "param-kind-address": translate(
            "Diagnostic", "{name}: parameter {index} ({param}) must be an address, found '{text}'"),
        "param-range": translate(
            "Diagnostic",
            '{name}: parameter {index} ({param}) must be {lo} to {hi},'
            ' found {value}'),
        "param-choice": translate(
            "Diagnostic",
            '{name}: parameter {index} ({param}) must be one of'
            ' {choices}, found {value}'),
        "param-mask": translate(
            "Diagnostic",
            '{name}: parameter {index} ({param}) must be up to 4 binary'
            " digits, found '{text}'"),
        "unknown-sub": translate(
            "Diagnostic", "SUB {number} is not in the instruction table: kept with its"
            " parameters, drawn as a box, simulated as W1 = ACT"),
        "stray-parameter": translate(
            "Diagnostic", "a parameter line '{text}' without a SUB instruction before it"),
        "bad-encoding": translate(
            "Diagnostic", 'the file is neither UTF-8 nor Turkish Windows (cp1254) text'),
        "syntax": translate("Diagnostic", "syntax error at '{text}'"),
        "open-circuit": translate(
            "Diagnostic", 'open circuit: this element is not connected to the right side'),
        "not-connected": translate("Diagnostic", 'element not connected to the left rail'),
        "coil-not-right": translate("Diagnostic", 'a coil must be at the right end of the network'),
        "coil-on-rail": translate("Diagnostic", 'a coil cannot sit straight on the left rail'),
        "bridge": translate(
            "Diagnostic", 'bridge circuit: a vertical link joins two branches in the middle'),
        "short-circuit": translate("Diagnostic", 'short circuit: a wire bypasses the element'),
        "stack-depth": translate("Diagnostic", 'the logic needs more than 8 stack levels (ST8)'),
        "reverse-flow": translate(
            "Diagnostic", 'power would flow right to left here; ladder flows left to right only'),
        "empty-network": translate("Diagnostic", 'the network has no coil or function'),
        "box-inputs": translate("Diagnostic", '{name} needs its {count} control inputs connected'),
        "no-address": translate("Diagnostic", 'this element has no address yet'),
        "coil-branch": translate(
            "Diagnostic", 'coils hang on different points of the logic; join them to one point'),
        "box-output": translate("Diagnostic", 'only coils may follow the output of {name}'),
        "box-twice": translate(
            "Diagnostic", 'one function box per network: put {name} in a network of its own'),
        "edit-outside": translate("Diagnostic", 'cell ({row}, {col}) is outside the grid'),
        "edit-coil-column": translate(
            "Diagnostic", 'only coils go in the coil column (cell ({row}, {col}))'),
        "edit-box-room": translate(
            "Diagnostic", '{name} does not fit here: a box needs two contact columns'),
        "edit-no-element": translate(
            "Diagnostic", 'there is no suitable element at cell ({row}, {col})'),
        "edit-line": translate("Diagnostic", 'a line must be horizontal or vertical'),
        "grid-text": translate("Diagnostic", 'the clipboard does not hold ladder elements'),
        "stack-underflow": translate("Diagnostic", '{name} with nothing pushed on the stack'),
        "write-input": translate("Diagnostic", '{name} writes to {address}, an input area'),
        "write-result-register": translate(
            "Diagnostic", '{name} writes to {address}, part of the read-only R9000-R9005'),
        "jmp-without-jmpe": translate("Diagnostic", 'JMP without a matching JMPE'),
        "jmpe-without-jmp": translate("Diagnostic", 'JMPE without a JMP before it'),
        "com-without-come": translate("Diagnostic", 'COM without a matching COME'),
        "come-without-com": translate("Diagnostic", 'COME without a COM before it'),
        "no-logic": translate(
            "Diagnostic", '{name} without a logic result before it (start with RD)'),
        "coil-twice": translate("Diagnostic", 'coil {address} is written more than once'),
        "dangling-logic": translate(
            "Diagnostic", 'logic at the end of the program is not written to any coil'),
        "bad-binary": translate("Diagnostic", 'not a LadderWorks binary: {reason}'),
        "coil-mixed": translate(
            "Diagnostic", "coil {address} is written by WRT and by SET/RST (also on line {line})"),
        "label-in-range": translate("Diagnostic", "LBL inside a JMP or COM range"),
        "label-missing": translate("Diagnostic", "no LBL L{label} where this jump can reach it"),
        "label-twice": translate(
            "Diagnostic", "label L{label} is defined twice in this program unit"),
        "jmpc-in-main": translate("Diagnostic", "JMPC is only allowed inside a subprogram"),
        "call-missing": translate("Diagnostic", "subprogram P{program} does not exist"),
        "call-recursion": translate(
            "Diagnostic", "calling P{program} here makes a subprogram call itself"),
        "call-depth": translate(
            "Diagnostic", "calls through P{program} nest deeper than {limit} subprograms"),
        "sp-without-spe": translate("Diagnostic", "SP without a matching SPE"),
        "spe-without-sp": translate("Diagnostic", "SPE without an SP before it"),
        "sp-twice": translate("Diagnostic", "subprogram P{program} is defined twice"),
        "outside-subprogram": translate(
            "Diagnostic", "only subprograms (SP ... SPE) may follow the first SP"),
        "level-end-order": translate("Diagnostic", "{name} cannot end level {level}"),
        "after-end": translate("Diagnostic", "instruction after END, the end of the program"),
        "endless-loop": translate(
            "Diagnostic",
            "a backward jump to L{label} repeated more than {limit} times in one scan"),
        "alarm-line": translate(
            "Diagnostic",
            "not an alarm message line: '{text}' (expected 'NNN text' or"
            " 'A00.0 text')"),
        "alarm-number": translate(
            "Diagnostic", 'alarm number {number} is out of range (000 to 799)'),
        "alarm-address": translate("Diagnostic", "'{text}' is not an alarm bit (A0.0 to A99.7)"),
        "alarm-duplicate": translate(
            "Diagnostic", 'message {number} appears again; the one on line {first} is used'),
        "alarm-empty": translate("Diagnostic", 'message {number} has no text'),
        "invalid-bytes": translate(
            "Diagnostic",
            "{count} byte(s) here are not valid {encoding}; they are kept as they are"),
        "damaged-draft": translate(
            "Diagnostic",
            "a saved drawing ({lines} line(s)) is damaged: it is kept as comment text"),
        "not-a-program": translate(
            "Diagnostic",
            "this is not a ladder program (no %@ section and no instruction)"),
        "section-line": translate(
            "Diagnostic",
            "line not understood in section {section}: '{text}'"),
        "param-kind-ref": translate(
            "Diagnostic",
            "{name}: parameter {index} ({param}) must be {letter} and a number, found '{text}'"),
        "number-too-long": translate(
            "Diagnostic",
            "'{text}': the number is too long"),
        "not-implemented": translate(
            "Diagnostic", '{name} is not implemented in the simulator yet'),
        "prm-line": translate(
            "Diagnostic",
            "not a parameter line: '{text}' (expected ADDRESS = VALUE, e.g. T0:4 = 1000)"),
        "prm-area": translate(
            "Diagnostic", "'{text}': PMC parameters are in the T, C, K and D areas only"),
        "prm-value": translate("Diagnostic", "'{text}' is not a value for {width} byte(s)"),
    }


def diagnostic_text(diagnostic: Diagnostic) -> str:
    """The diagnostic's message in the current UI language (parameter names included)."""
    if "param" in diagnostic.args:
        args = {**diagnostic.args, "param": param_label(str(diagnostic.args["param"]))}
        diagnostic = replace(diagnostic, args=args)
    return diagnostic.message(diagnostic_templates())
