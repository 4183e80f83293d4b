"""Errors and warnings as data (code, arguments, position); English texts marked for translation."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from enum import StrEnum

from ladderworks.core.dialect_messages import DIALECT_MESSAGES
from ladderworks.core.translate_mark import QT_TRANSLATE_NOOP


class Severity(StrEnum):
    """How bad a diagnostic is."""

    ERROR = "error"
    WARNING = "warning"


# English message templates by code, each marked once for translation (lupdate extracts them
# into the "Diagnostic" context; the GUI translates them at display). Arguments fill {names}.
MESSAGES: dict[str, str] = {
    # addresses
    "bad-address": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not an address (expected e.g. X2.1 or R100)"),
    "unknown-area": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}': unknown area '{area}' (use X, Y, F, G, R, A, D, T, C or K)"),
    "byte-range": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}': byte number out of range for area {area} ({ranges})"),
    "bit-range": QT_TRANSLATE_NOOP("Diagnostic", "'{text}': bit number must be 0 to 7"),
    "bit-expected": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}': a bit address is needed here (e.g. {text}.0)"),
    "byte-expected": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}': a byte address is needed here, without a bit"),
    "target-width": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}': the width after ':' must be 1, 2 or 4"),
    "bit-width": QT_TRANSLATE_NOOP("Diagnostic", "'{text}': a bit address takes no width"),
    # the text format
    "missing-start": QT_TRANSLATE_NOOP("Diagnostic", "the ladder section must begin with %@3"),
    "missing-end": QT_TRANSLATE_NOOP("Diagnostic", "the ladder section must end with a line '%'"),
    "unexpected-text": QT_TRANSLATE_NOOP("Diagnostic", "unexpected text '{text}'"),
    "text-outside-section": QT_TRANSLATE_NOOP("Diagnostic", "text outside any section: '{text}'"),
    "duplicate-section": QT_TRANSLATE_NOOP("Diagnostic", "section %@{number} appears twice"),
    "bad-section": QT_TRANSLATE_NOOP("Diagnostic", "unknown section {header}: kept as it is"),
    "unknown-instruction": QT_TRANSLATE_NOOP("Diagnostic", "unknown instruction '{name}'"),
    "missing-operand": QT_TRANSLATE_NOOP("Diagnostic", "{name} needs an address"),
    "extra-operand": QT_TRANSLATE_NOOP("Diagnostic", "{name} takes no operand, found '{text}'"),
    "param-count": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} needs {expected} parameters, found {found}"),
    "param-kind-number": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name}: parameter {index} ({param}) must be a number, found '{text}'"),
    "param-kind-address": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name}: parameter {index} ({param}) must be an address, found '{text}'"),
    "param-range": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name}: parameter {index} ({param}) must be {lo} to {hi}, found {value}"),
    "param-choice": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "{name}: parameter {index} ({param}) must be one of {choices},"
        " found {value}"),
    "param-mask": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "{name}: parameter {index} ({param}) must be up to 4 binary digits,"
        " found '{text}'"),
    "unknown-sub": QT_TRANSLATE_NOOP(
        "Diagnostic", "SUB {number} is not in the instruction table: kept with its parameters,"
        " drawn as a box, simulated as W1 = ACT"),
    "stray-parameter": QT_TRANSLATE_NOOP(
        "Diagnostic", "a parameter line '{text}' without a SUB instruction before it"),
    "bad-encoding": QT_TRANSLATE_NOOP(
        "Diagnostic", "the file is neither UTF-8 nor Turkish Windows (cp1254) text"),
    "syntax": QT_TRANSLATE_NOOP("Diagnostic", "syntax error at '{text}'"),
    "invalid-bytes": QT_TRANSLATE_NOOP(
        "Diagnostic", "{count} byte(s) here are not valid {encoding}; they are kept as they are"),
    "damaged-draft": QT_TRANSLATE_NOOP(
        "Diagnostic", "a saved drawing ({lines} line(s)) is damaged: it is kept as comment text"),
    "not-a-program": QT_TRANSLATE_NOOP(
        "Diagnostic", "this is not a ladder program (no %@ section and no instruction)"),
    "section-line": QT_TRANSLATE_NOOP(
        "Diagnostic", "line not understood in section {section}: '{text}'"),
    "param-kind-ref": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "{name}: parameter {index} ({param}) must be {letter} and a number,"
        " found '{text}'"),
    "number-too-long": QT_TRANSLATE_NOOP("Diagnostic", "'{text}': the number is too long"),
    # the ladder grid (network decomposition)
    "open-circuit": QT_TRANSLATE_NOOP(
        "Diagnostic", "open circuit: this element is not connected to the right side"),
    "not-connected": QT_TRANSLATE_NOOP("Diagnostic", "element not connected to the left rail"),
    "coil-not-right": QT_TRANSLATE_NOOP(
        "Diagnostic", "a coil must be at the right end of the network"),
    "coil-on-rail": QT_TRANSLATE_NOOP("Diagnostic", "a coil cannot sit straight on the left rail"),
    "bridge": QT_TRANSLATE_NOOP(
        "Diagnostic", "bridge circuit: a vertical link joins two branches in the middle"),
    "short-circuit": QT_TRANSLATE_NOOP("Diagnostic", "short circuit: a wire bypasses the element"),
    "stack-depth": QT_TRANSLATE_NOOP(
        "Diagnostic", "the logic needs more than 8 stack levels (ST8)"),
    "reverse-flow": QT_TRANSLATE_NOOP(
        "Diagnostic", "power would flow right to left here; ladder flows left to right only"),
    "empty-network": QT_TRANSLATE_NOOP("Diagnostic", "the network has no coil or function"),
    "box-inputs": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} needs its {count} control inputs connected"),
    "no-address": QT_TRANSLATE_NOOP("Diagnostic", "this element has no address yet"),
    "contact-place": QT_TRANSLATE_NOOP(
        "Diagnostic", "this edge or comparison contact has no form for this place in the "
        "dialect (put it in series after another contact)"),
    "coil-branch": QT_TRANSLATE_NOOP(
        "Diagnostic", "coils hang on different points of the logic; join them to one point"),
    "box-output": QT_TRANSLATE_NOOP("Diagnostic", "only coils may follow the output of {name}"),
    "box-twice": QT_TRANSLATE_NOOP(
        "Diagnostic", "one function box per network: put {name} in a network of its own"),
    # ladder edits (refused edits; nothing was changed)
    "edit-outside": QT_TRANSLATE_NOOP("Diagnostic", "cell ({row}, {col}) is outside the grid"),
    "edit-coil-column": QT_TRANSLATE_NOOP(
        "Diagnostic", "only coils go in the coil column (cell ({row}, {col}))"),
    "edit-box-room": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} does not fit here: a box needs two contact columns"),
    "edit-row-contact": QT_TRANSLATE_NOOP(
        "Diagnostic", "an edge or comparison contact has no normally closed form"),
    "edit-no-element": QT_TRANSLATE_NOOP(
        "Diagnostic", "there is no suitable element at cell ({row}, {col})"),
    "edit-no-pins": QT_TRANSLATE_NOOP(
        "Diagnostic", "no function box with FO outputs at cell ({row}, {col})"),
    "family-symbols": QT_TRANSLATE_NOOP(
        "Diagnostic", "the program's {count} symbols (%@2) have no place in that family's "
        "files: the program keeps its family"),
    "family-differs": QT_TRANSLATE_NOOP(
        "Diagnostic", "instruction {step} ({name}) has no counterpart in that family: the "
        "program keeps its family"),
    "edit-end-kept": QT_TRANSLATE_NOOP(
        "Diagnostic", "END ends the program and stays its last network: draw new networks "
        "above it"),
    "edit-line": QT_TRANSLATE_NOOP("Diagnostic", "a line must be horizontal or vertical"),
    "grid-text": QT_TRANSLATE_NOOP("Diagnostic", "the clipboard does not hold ladder elements"),
    # find and replace
    "replace-needs-address": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not an address or a symbol of the program: type one to "
        "replace it"),
    "replace-kind": QT_TRANSLATE_NOOP(
        "Diagnostic", "{found} and {replacement}: replace a bit with a bit, a byte with a byte"),
    "replace-same": QT_TRANSLATE_NOOP("Diagnostic", "{found} would be replaced with itself"),
    # the compiler
    "stack-underflow": QT_TRANSLATE_NOOP("Diagnostic", "{name} with nothing pushed on the stack"),
    "write-input": QT_TRANSLATE_NOOP("Diagnostic", "{name} writes to {address}, an input area"),
    "write-result-register": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} writes to {address}, part of the read-only R9000-R9005"),
    "jmp-without-jmpe": QT_TRANSLATE_NOOP("Diagnostic", "JMP without a matching JMPE"),
    "jmpe-without-jmp": QT_TRANSLATE_NOOP("Diagnostic", "JMPE without a JMP before it"),
    "com-without-come": QT_TRANSLATE_NOOP("Diagnostic", "COM without a matching COME"),
    "come-without-com": QT_TRANSLATE_NOOP("Diagnostic", "COME without a COM before it"),
    "no-logic": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} without a logic result before it (start with RD)"),
    "coil-twice": QT_TRANSLATE_NOOP("Diagnostic", "coil {address} is written more than once"),
    "dangling-logic": QT_TRANSLATE_NOOP(
        "Diagnostic", "logic at the end of the program is not written to any coil"),
    "bad-binary": QT_TRANSLATE_NOOP("Diagnostic", "not a LadderWorks binary: {reason}"),
    # program structure (levels, subprograms, labels)
    "coil-mixed": QT_TRANSLATE_NOOP(
        "Diagnostic", "coil {address} is written by WRT and by SET/RST (also on line {line})"),
    "coil-mixed-network": QT_TRANSLATE_NOOP(  # the drawing compiled: no line, its network
        "Diagnostic",
        "coil {address} is written by WRT and by SET/RST (also in network {other})"),
    "label-in-range": QT_TRANSLATE_NOOP("Diagnostic", "LBL inside a JMP or COM range"),
    "label-missing": QT_TRANSLATE_NOOP(
        "Diagnostic", "no LBL L{label} where this jump can reach it"),
    "label-twice": QT_TRANSLATE_NOOP(
        "Diagnostic", "label L{label} is defined twice in this program unit"),
    "jmpc-in-main": QT_TRANSLATE_NOOP("Diagnostic", "JMPC is only allowed inside a subprogram"),
    "call-missing": QT_TRANSLATE_NOOP("Diagnostic", "subprogram P{program} does not exist"),
    "call-recursion": QT_TRANSLATE_NOOP(
        "Diagnostic", "calling P{program} here makes a subprogram call itself"),
    "call-depth": QT_TRANSLATE_NOOP(
        "Diagnostic", "calls through P{program} nest deeper than {limit} subprograms"),
    "sp-without-spe": QT_TRANSLATE_NOOP("Diagnostic", "SP without a matching SPE"),
    "spe-without-sp": QT_TRANSLATE_NOOP("Diagnostic", "SPE without an SP before it"),
    "sp-twice": QT_TRANSLATE_NOOP("Diagnostic", "subprogram P{program} is defined twice"),
    "outside-subprogram": QT_TRANSLATE_NOOP(
        "Diagnostic", "only subprograms (SP ... SPE) may follow the first SP"),
    "level-end-order": QT_TRANSLATE_NOOP("Diagnostic", "{name} cannot end level {level}"),
    "after-end": QT_TRANSLATE_NOOP("Diagnostic", "instruction after END, the end of the program"),
    "endless-loop": QT_TRANSLATE_NOOP(
        "Diagnostic", "a backward jump to L{label} repeated more than {limit} times in one scan"),
    # the alarm message file (AlarmMsg.dat)
    "alarm-line": QT_TRANSLATE_NOOP(
        "Diagnostic", "not an alarm message line: '{text}' (expected 'NNN text' or 'A00.0 text')"),
    "alarm-number": QT_TRANSLATE_NOOP(
        "Diagnostic", "alarm number {number} is out of range (000 to 799)"),
    "alarm-address": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not an alarm bit (A0.0 to A99.7)"),
    "alarm-duplicate": QT_TRANSLATE_NOOP(
        "Diagnostic", "message {number} appears again; the one on line {first} is used"),
    "alarm-empty": QT_TRANSLATE_NOOP("Diagnostic", "message {number} has no text"),
    "not-implemented": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} is not implemented in the simulator yet"),
    # dialects (docs/dialects.md): devices and operands of a Delta or Fatek program
    "typed-other-row": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' cannot be the device of {name} here: with it the line reads as "
        "{other} (place {other} from the palette)"),
    "device-unknown": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not a device (use {letters} with a number)"),
    "device-octal": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}': {letter} is numbered in octal (digits 0 to 7)"),
    "device-range": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is out of range ({first} to {last})"),
    "device-bit-needed": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is not a bit device"),
    "device-word-needed": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is not a word device"),
    "device-not-in-table": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not listed in this table (use {letters})"),
    "device-range-order": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}': give a device or a range FIRST-LAST of at most {most} devices"),
    "dialect-operand": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name}: operand {index} must be one of {expected}, found '{text}'"),
    "dialect-constant": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is not a K or H constant"),
    "dialect-not-simulated": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} is a {dialect} instruction the simulator does not run"),
    "not-simulated": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} is kept and drawn but not simulated: the scan passes it by"),
    "run-skips": QT_TRANSLATE_NOOP(
        "Diagnostic", "{count} instructions are not simulated, the scan passes them by "
        "(line): {names}"),
    "inv-place": QT_TRANSLATE_NOOP(
        "Diagnostic", "INV inverts all the power before it: draw it on a line from the rail "
        "or a branch point, not inside a parallel block"),
    "dvp-missing-operand": QT_TRANSLATE_NOOP("Diagnostic", "{name}: operand {index} is missing"),
    "dvp-step-order": QT_TRANSLATE_NOOP(
        "Diagnostic", "step {step} is not after step {previous}: the step numbers must grow"),
    "dvp-missing-sret": QT_TRANSLATE_NOOP(
        "Diagnostic", "subroutine without its SRET (before the next pointer or END)"),
    "dvp-sret-alone": QT_TRANSLATE_NOOP(
        "Diagnostic", "SRET without a subroutine pointer (P n after FEND) before it"),
    "dvp-outside-subroutine": QT_TRANSLATE_NOOP(
        "Diagnostic", "after FEND only subroutines (P n ... SRET) and END may follow"),
    "dvp-pointer-missing": QT_TRANSLATE_NOOP(
        "Diagnostic", "no pointer P{label} where this jump can reach it"),
    "dvp-call-missing": QT_TRANSLATE_NOOP(
        "Diagnostic", "no subroutine P{program} after FEND for this CALL"),
    "dvp-no-logic": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} without a logic result before it (start with LD)"),
    "dvp-pointer-twice": QT_TRANSLATE_NOOP("Diagnostic", "this pointer P number is used twice"),
    # WPLSoft .dvp projects (docs/dialects.md, ".dvp projects"): byte offsets in the file
    "dvp-not-dvp": QT_TRANSLATE_NOOP(
        "Diagnostic", "not a WPLSoft .dvp project: it does not start with the bytes 57 01 01 00"),
    "dvp-truncated": QT_TRANSLATE_NOOP(
        "Diagnostic", "the .dvp file is cut short at byte {offset}: it does not end with the line"
        " <PrjectEnd> WPLSoft writes last"),
    "dvp-version": QT_TRANSLATE_NOOP(
        "Diagnostic", "byte {offset}: .dvp format version {version} is not one LadderWorks"
        " reads (214, 215 and 216 are)"),
    "dvp-bad-layout": QT_TRANSLATE_NOOP(
        "Diagnostic", "byte {offset}: the program memory of this .dvp project is not where"
        " WPLSoft puts it: the file is damaged"),
    "dvp-unknown-code": QT_TRANSLATE_NOOP(
        "Diagnostic", "byte {offset} (step {step}): instruction code {word} is not known to"
        " LadderWorks: kept as ?{word} with its operands"),
    "dvp-unknown-device": QT_TRANSLATE_NOOP(
        "Diagnostic", "byte {offset} (step {step}): the word {word} names no device LadderWorks"
        " knows: the file is damaged or uses a device not decoded yet"),
    "dvp-bad-operand": QT_TRANSLATE_NOOP(
        "Diagnostic", "byte {offset} (step {step}): the operand word {word} is neither a device"
        " nor a constant: the file is damaged"),
    "dvp-operand-count": QT_TRANSLATE_NOOP(
        "Diagnostic", "byte {offset} (step {step}): the operand words after {word} do not fit"
        " the instruction: the file is damaged"),
    "dvp-stray-operand": QT_TRANSLATE_NOOP(
        "Diagnostic", "byte {offset} (step {step}): the operand word {word} follows no"
        " instruction: the file is damaged"),
    "dvp-no-end": QT_TRANSLATE_NOOP(
        "Diagnostic", "byte {offset}: the program does not end with END: the file is damaged"),
    "dvp-after-end": QT_TRANSLATE_NOOP(
        "Diagnostic", "byte {offset} (step {step}): instructions after END: the file is"
        " damaged"),
    "dvp-bad-section": QT_TRANSLATE_NOOP(
        "Diagnostic", "byte {offset}: a text section of the .dvp project is damaged"),
    "dvp-bad-comment": QT_TRANSLATE_NOOP(
        "Diagnostic", "byte {offset}: a device comment line is not DEVICE$&text"),
    "dvp-no-program": QT_TRANSLATE_NOOP(
        "Diagnostic", "the project holds no program: no compiled instruction list and an empty"
        " ladder drawing"),
    "dvp-from-drawing": QT_TRANSLATE_NOOP(
        "Diagnostic", "the project was saved without compiling: its program is read from its"
        " ladder drawing"),
    "dvp-drawing-unread": QT_TRANSLATE_NOOP(
        "Diagnostic", "the project holds no compiled instruction list, and its ladder drawing"
        " has a cell LadderWorks does not read yet (byte {offset}: a branch, an edge contact"
        " ...): compile it in WPLSoft and save it again"),
    "dvp-save-refused": QT_TRANSLATE_NOOP(
        "Diagnostic", "LadderWorks does not write .dvp projects (the format is only partly"
        " known): save the program as a Delta instruction list (.il) instead"),
    "dvp-next-without-for": QT_TRANSLATE_NOOP("Diagnostic", "NEXT without a FOR before it"),
    "dvp-range-open": QT_TRANSLATE_NOOP(
        "Diagnostic", "MC or STL without its MCR or RET after it"),
    "dvp-range-end-alone": QT_TRANSLATE_NOOP(
        "Diagnostic", "MCR or RET without its MC or STL before it"),
    "dvp-for-without-next": QT_TRANSLATE_NOOP("Diagnostic", "FOR without its NEXT"),
    # scenario files (docs/scenarios.md)
    "scenario-header": QT_TRANSLATE_NOOP(
        "Diagnostic", "the first line must be 'PMC SIGNAL DATA'"),
    "scenario-command": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "unknown command '{text}'"
        " (use REMARK, PROGRAM, SET, EXPECT, WAITFOR, FORCE or RELEASE)"),
    "scenario-wait": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is not a wait in ms"),
    "scenario-negative": QT_TRANSLATE_NOOP("Diagnostic", "negative wait {text} ms"),
    "scenario-fields": QT_TRANSLATE_NOOP("Diagnostic", "{command} needs {expected}"),
    "scenario-address": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is neither an address nor a symbol of the program"),
    "scenario-value": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is not a value for {target}"),
    "scenario-type": QT_TRANSLATE_NOOP(
        "Diagnostic", "unknown type '{text}' (use BIT, BYTE, WORD or DWORD)"),
    "scenario-bit": QT_TRANSLATE_NOOP("Diagnostic", "'{text}': only bits can be forced"),
    "scenario-no-program": QT_TRANSLATE_NOOP(
        "Diagnostic", "the scenario names no program: add a line PROGRAM,path"
        " (relative to the scenario file) or give the program on the command line"),
    "scenario-program-twice": QT_TRANSLATE_NOOP(
        "Diagnostic", "a second PROGRAM line (the one on line {first} counts)"),
    "scenario-program": QT_TRANSLATE_NOOP(
        "Diagnostic", "the program '{path}' cannot be loaded: {reason}"),
    "scenario-other-program": QT_TRANSLATE_NOOP(
        "Diagnostic", "the scenario names the program '{path}'; it runs on the one loaded"
        " in the PLC"),
    # the PMC parameter file (PROGRAM.LAD.prm)
    "prm-line": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "not a parameter line: '{text}'"
        " (expected ADDRESS = VALUE, e.g. T0:4 = 1000)"),
    "prm-area": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}': PMC parameters are in the T, C, K and D areas only"),
    "prm-value": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is not a value for {width} byte(s)"),
    # values typed in the PMC tables (timers, counters, keep relays, data)
    "not-a-number": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is not a number"),
    "out-of-range": QT_TRANSLATE_NOOP("Diagnostic", "{value} is out of range ({low} to {high})"),
    "value-width": QT_TRANSLATE_NOOP("Diagnostic", "{value} bytes: a value has 1, 2 or 4 bytes"),
    "bit-pattern": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}': type up to 8 binary digits (0 and 1), bit 7 first"),
    "preset-fixed": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "TMRB {number}: its preset is fixed in the program and cannot be changed here"),
    # a Modbus map file (docs/modbus.md)
    "modbus-map-columns": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "expected TABLE,START,COUNT,PLC ADDRESS,ACCESS[,WIDTH], found {count} column(s)"),
    "modbus-map-table": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not a Modbus table (use coils, discrete, holding or input)"),
    "modbus-map-number": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not a number from {lo} to {hi}"),
    "modbus-map-end": QT_TRANSLATE_NOOP(
        "Diagnostic", "{count} addresses from {start} run past Modbus address 65535"),
    "modbus-map-access": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}': the access must be r (read) or rw (read and write)"),
    "modbus-map-read-only": QT_TRANSLATE_NOOP(
        "Diagnostic", "{table} cannot be written over Modbus: the access must be r"),
    "modbus-map-bit-width": QT_TRANSLATE_NOOP(
        "Diagnostic", "{table} are bits: a width is for registers only"),
    "modbus-map-area": QT_TRANSLATE_NOOP(
        "Diagnostic", "{count} elements from {device} run past the end of area {area} ({ranges})"),
    "modbus-map-overlap": QT_TRANSLATE_NOOP(
        "Diagnostic", "{table} {start}-{end} overlap the row on line {other}"),
    "modbus-map-empty": QT_TRANSLATE_NOOP("Diagnostic", "the map has no row"),
    "modbus-map-width": QT_TRANSLATE_NOOP(
        "Diagnostic", "{device}: a device's register is 16 bits: the width must be 2"),
    # the watch table (docs/plc-utilities.md, Watch table)
    "watch-unknown": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is neither a name of the program nor an address"),
    "watch-struct": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is a {type}: watch one of its members (e.g. {text}.Q)"),
    "watch-wide": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is a {type}: the watch table has no format for it"),
    "watch-date": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not a date from D#1990-01-01 to D#2169-06-06 "
        "(e.g. D#2024-01-31)"),
    "watch-tod": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not a time of day (e.g. TOD#12:30:00.000)"),
    "watch-long": QT_TRANSLATE_NOOP(
        "Diagnostic", "the value has {length} characters: at most {limit} are read"),
    "watch-empty": QT_TRANSLATE_NOOP("Diagnostic", "no modify value to write"),
    "watch-bool": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is not TRUE or FALSE (or 1, 0)"),
    "watch-number": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not a whole number (e.g. 12, -3, 16#FF, 2#0101)"),
    "watch-range": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is out of range: {low} to {high}"),
    "watch-real": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is not a real number (e.g. 1.5)"),
    "watch-time": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not a time (e.g. T#5S_300MS, T#1M30S or 1500 ms)"),
    "watch-char": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not one character of the Latin-1 set (e.g. 'A')"),
    "watch-latin1": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' has characters a string cannot hold (only the Latin-1 set)"),
    "watch-string": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is longer than the string's {length} characters"),
    "modbus-map-db": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{name}' is neither a map file nor a global DB of the program"
        " (its global DBs: {names})"),
}
MESSAGES.update(DIALECT_MESSAGES)  # the Fatek and S7 readers' (dialect_messages.py)


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

    def message(self, translate: Callable[[str, str], str] | None = None) -> str:
        """The message text: English, or through `translate(context, template)` (Qt's)."""
        template = MESSAGES.get(self.code, self.code)
        if translate is not None:
            template = translate("Diagnostic", template) or template
        try:
            return template.format(**self.args)
        except (KeyError, IndexError, ValueError):
            return f"{template} {self.args}"

    def located(self, filename: str) -> str:
        """`FILE:LINE:COL: CODE message`, the CLI's format."""
        return f"{filename}:{self.line}:{self.column}: {self.code} {self.message()}"


class DiagnosticError(Exception):
    """Raised where a caller wants an exception; carries the diagnostics (the first says why)."""

    def __init__(self, diagnostics: list[Diagnostic]) -> None:
        self.diagnostics = diagnostics
        super().__init__("; ".join(d.message() for d in diagnostics[:3]))

    @property
    def diagnostic(self) -> Diagnostic:
        """The (first) diagnostic: what the user is shown."""
        return self.diagnostics[0]

    @property
    def code(self) -> str:
        """The first diagnostic's code."""
        return self.diagnostic.code

    @property
    def args_map(self) -> dict[str, object]:
        """The first diagnostic's arguments (`args` is the exception's own tuple)."""
        return self.diagnostic.args


class Refused(DiagnosticError):
    """One diagnostic as an exception: a value, an address or an edit that was refused."""

    def __init__(self, code: str, **args: object) -> None:
        super().__init__([Diagnostic(code, dict(args))])


def has_errors(diagnostics: list[Diagnostic]) -> bool:
    """True when any diagnostic is an error."""
    return any(d.is_error for d in diagnostics)
