"""Diagnostic messages behind tr(): the GUI's translatable copy of the core's MESSAGES."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from ladderworks.core.diagnostics import Diagnostic


def diagnostic_templates() -> dict[str, str]:
    """Message templates by code in the current UI language ({names} filled from args)."""
    return {
        "bad-address": QCoreApplication.translate(
            "Diagnostic", "'{text}' is not an address (expected e.g. X2.1 or R100)"),
        "unknown-area": QCoreApplication.translate(
            "Diagnostic", "'{text}': unknown area '{area}' (use X, Y, F, G, R, A, D, T, C or K)"),
        "byte-range": QCoreApplication.translate(
            "Diagnostic", "'{text}': byte number out of range for area {area} (0 to {last})"),
        "bit-range": QCoreApplication.translate(
            "Diagnostic", "'{text}': bit number must be 0 to 7"),
        "bit-expected": QCoreApplication.translate(
            "Diagnostic", "'{text}': a bit address is needed here (e.g. {text}.0)"),
        "byte-expected": QCoreApplication.translate(
            "Diagnostic", "'{text}': a byte address is needed here, without a bit"),
        "missing-start": QCoreApplication.translate(
            "Diagnostic", 'the ladder section must begin with %@3'),
        "missing-end": QCoreApplication.translate(
            "Diagnostic", "the ladder section must end with a line '%'"),
        "unexpected-text": QCoreApplication.translate("Diagnostic", "unexpected text '{text}'"),
        "text-outside-section": QCoreApplication.translate(
            "Diagnostic", "text outside any section: '{text}'"),
        "duplicate-section": QCoreApplication.translate(
            "Diagnostic", 'section %@{number} appears twice'),
        "bad-section": QCoreApplication.translate(
            "Diagnostic", 'unknown section %@{number} (FANUC sections are %@0 to %@5)'),
        "unknown-instruction": QCoreApplication.translate(
            "Diagnostic", "unknown instruction '{name}'"),
        "missing-operand": QCoreApplication.translate("Diagnostic", '{name} needs an address'),
        "extra-operand": QCoreApplication.translate(
            "Diagnostic", "{name} takes no operand, found '{text}'"),
        "param-count": QCoreApplication.translate(
            "Diagnostic", '{name} needs {expected} parameters, found {found}'),
        "param-kind-number": QCoreApplication.translate(
            "Diagnostic", "{name}: parameter {index} ({param}) must be a number, found '{text}'"),
        "param-kind-address": QCoreApplication.translate(
            "Diagnostic", "{name}: parameter {index} ({param}) must be an address, found '{text}'"),
        "param-range": QCoreApplication.translate(
            "Diagnostic", '{name}: parameter {index} ({param}) must be {lo} to {hi}, found {value}'),  # noqa: E501
        "param-choice": QCoreApplication.translate(
            "Diagnostic", '{name}: parameter {index} ({param}) must be one of {choices}, found {value}'),  # noqa: E501
        "param-mask": QCoreApplication.translate(
            "Diagnostic", "{name}: parameter {index} ({param}) must be up to 4 binary digits, found '{text}'"),  # noqa: E501
        "unknown-sub": QCoreApplication.translate(
            "Diagnostic", 'no functional instruction has the number SUB {number}'),
        "stray-parameter": QCoreApplication.translate(
            "Diagnostic", "a parameter line '{text}' without a SUB instruction before it"),
        "bad-encoding": QCoreApplication.translate(
            "Diagnostic", 'the file is neither UTF-8 nor Turkish Windows (cp1254) text'),
        "syntax": QCoreApplication.translate("Diagnostic", "syntax error at '{text}'"),
        "open-circuit": QCoreApplication.translate(
            "Diagnostic", 'open circuit: this element is not connected to the right side'),
        "not-connected": QCoreApplication.translate(
            "Diagnostic", 'element not connected to the left rail'),
        "coil-not-right": QCoreApplication.translate(
            "Diagnostic", 'a coil must be at the right end of the network'),
        "coil-on-rail": QCoreApplication.translate(
            "Diagnostic", 'a coil cannot sit straight on the left rail'),
        "bridge": QCoreApplication.translate(
            "Diagnostic", 'bridge circuit: a vertical link joins two branches in the middle'),
        "short-circuit": QCoreApplication.translate(
            "Diagnostic", 'short circuit: a wire bypasses the element'),
        "stack-depth": QCoreApplication.translate(
            "Diagnostic", 'the logic needs more than 8 stack levels (ST8)'),
        "reverse-flow": QCoreApplication.translate(
            "Diagnostic", 'power would flow right to left here; ladder flows left to right only'),
        "empty-network": QCoreApplication.translate(
            "Diagnostic", 'the network has no coil or function'),
        "box-inputs": QCoreApplication.translate(
            "Diagnostic", '{name} needs its {count} control inputs connected'),
        "stack-underflow": QCoreApplication.translate(
            "Diagnostic", '{name} with nothing pushed on the stack'),
        "write-input": QCoreApplication.translate(
            "Diagnostic", '{name} writes to {address}, an input area'),
        "write-result-register": QCoreApplication.translate(
            "Diagnostic", '{name} writes to {address}, part of the read-only R9000-R9005'),
        "jmp-without-jmpe": QCoreApplication.translate("Diagnostic", 'JMP without a matching JMPE'),
        "jmpe-without-jmp": QCoreApplication.translate(
            "Diagnostic", 'JMPE without a JMP before it'),
        "com-without-come": QCoreApplication.translate("Diagnostic", 'COM without a matching COME'),
        "come-without-com": QCoreApplication.translate(
            "Diagnostic", 'COME without a COM before it'),
        "no-logic": QCoreApplication.translate(
            "Diagnostic", '{name} without a logic result before it (start with RD)'),
        "coil-twice": QCoreApplication.translate(
            "Diagnostic", 'coil {address} is written more than once'),
        "dangling-logic": QCoreApplication.translate(
            "Diagnostic", 'logic at the end of the program is not written to any coil'),
        "bad-binary": QCoreApplication.translate(
            "Diagnostic", 'not a LadderWorks binary: {reason}'),
    }


def diagnostic_text(diagnostic: Diagnostic) -> str:
    """The diagnostic's message in the current UI language."""
    return diagnostic.message(diagnostic_templates())
