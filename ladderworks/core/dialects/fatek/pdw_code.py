"""The FBs program code in a .pdw's program image, decoded to WinProladder's mnemonic listing.

Each instruction is big-endian 16-bit words. What each code means was learned from a real
project and its printout (docs/dialects.md, ".pdw projects", lists the codes seen and the few
inferred); a code not listed stops the decoding with its byte offset (PdwError).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from ladderworks.core.dialects.fatek.pdw_records import PdwError


@dataclass(frozen=True, slots=True)
class Basic:
    """A basic instruction (the top 4 bits of its word; the low 12 its bit device)."""

    name: str
    negated: bool = False
    coil: bool = False  # OUT: a coil, no edge, no drawn line
    tr: bool = False  # LD and OUT take a TR point (LD TR n, OUT TR n); LD also an FO


BASIC: dict[int, Basic] = {
    0x4: Basic("ORG"), 0x5: Basic("ORG", True), 0x6: Basic("LD", tr=True),
    0x7: Basic("LD", True, tr=True), 0x8: Basic("AND"), 0x9: Basic("AND", True),
    0xA: Basic("OR"), 0xB: Basic("OR", True), 0xC: Basic("OUT", coil=True, tr=True),
    0xD: Basic("OUT", True, coil=True),  # 0xD (OUT NOT) inferred
}
EDGE = 0xE000  # before a contact: TU; before its NOT form: TD
# Bit devices by 12-bit address: (first address, last address, device letters, first number)
BIT_AREAS: tuple[tuple[int, int, str, int], ...] = (
    (0x000, 0x0FF, "X", 0), (0x100, 0x1FF, "Y", 0), (0x200, 0x2FF, "T", 0),
    (0x300, 0x3FF, "C", 0), (0x400, 0x427, "TR", 0), (0x428, 0x80F, "S", 0),
    (0x810, 0xFE1, "M", 0))
LINE_BITS = range(0xFE2, 0xFFC)  # a drawn line: SHORT (the contact) or OPEN (its NOT form)
FO_BITS = range(0xFFC, 0x1000)  # FO0-FO3, the last box's outputs (LD FOn)
# Word operands: 2 x the word address: (first, last number, device, first code)
WORD_AREAS: tuple[tuple[int, int, str, int], ...] = (
    (0, 255, "T", 0x390), (0, 199, "C", 0x590), (0, 4167, "R", 0xA00))
BIT, WORD, CONST = "bit", "word", "const"


@dataclass(frozen=True, slots=True)
class Code:
    """An extended instruction (first word 0xFxxx): its listing head and its operands."""

    head: str  # `SET( )`, `FUN 08 _.MOV`, `TIMER`, `ANDF 171_.>`
    kinds: tuple[str, ...]  # each operand word: BIT, WORD or CONST
    labels: tuple[str, ...] = ()  # the operand lines' labels; () puts them on the step line
    fixed: tuple[tuple[str, str], ...] = ()  # operand lines the code itself says (`Ps: 1`)


TIMER = "TIMER"
EXTENDED: dict[int, Code] = {
    0xFC82: Code("SET( )", (BIT,)),
    0xFCC4: Code("RST( )", (BIT,)),
    0xFDC4: Code("RST( )", (WORD,)),  # a timer's or counter's RST
    0xFC80: Code(TIMER, (WORD, WORD)),  # preset register, timer
    0xF4AC: Code("FUN 08 _.MOV", (WORD, WORD), ("S", "D")),
    0xF5AC: Code("FUN 08 _.MOV", (CONST, WORD), ("S", "D")),
    0xF496: Code("FUN 15 _.(+1)", (WORD,), ("",)),
    0xF51A: Code("FUN 140.HSPSO", (WORD, WORD), ("SR", "WR"), (("Ps", "1"),)),
    0xF1D0: Code("FUN 141.MPARA", (WORD,), ("SR",), (("Ps", "1"),)),
}
COMPARE_ESCAPE = 0x7F  # low byte of a comparison contact's first word; the FUN in the next
COMPARE_OPS = {0xF47F: "ANDF"}  # the first word without the constant flags
COMPARE_FIRST = 170  # FUN 170-175 (=, >, <, <>, >=, <=): index word 0x21-0x26
COMPARE_INDEX = 0x21
COMPARE_NAMES = ("=", ">", "<", "<>", ">=", "<=")
CONST_FLAGS = (0x100, 0x200)  # first word bits: operand 1 / 2 is a constant


def bit_device(address: int) -> tuple[str, int] | None:
    """The device letters and number of a 12-bit bit address, or None."""
    for first, last, letters, number in BIT_AREAS:
        if first <= address <= last:
            return letters, number + address - first
    return None


def word_device(code: int) -> str | None:
    """A word operand's device (`R1200`, `T10`, `C0`), or None."""
    for first, last, letters, base in WORD_AREAS:
        number, odd = divmod(code - base, 2)
        if not odd and first <= number <= last:
            return f"{letters}{number}"
    return None


def constant(code: int) -> str:
    """A 16-bit constant as WinProladder prints it (signed decimal)."""
    return str(code - 0x10000 if code & 0x8000 else code)


@dataclass(slots=True)
class Step:
    """One decoded instruction: its step line text, operand lines, byte offset in the file."""

    text: str
    operands: list[tuple[str, str]]
    offset: int


class Decoder:
    """Decodes a unit's words; `timer_base(n)` gives timer n's base as printed (`.01`)."""

    def __init__(self, words: list[int], offset: int, timer_base: Callable[[int], str]) -> None:
        self.words = words
        self.offset = offset  # the file offset of words[0]
        self.timer_base = timer_base
        self.at = 0
        self.done: list[Step] = []

    def where(self, index: int) -> int:
        """The file offset of word `index`."""
        return self.offset + 2 * index

    def take(self) -> int:
        """The next word; PdwError when the unit ends inside an instruction."""
        if self.at >= len(self.words):
            raise PdwError("pdw-cut", self.where(self.at))
        word = self.words[self.at]
        self.at += 1
        return word

    def run(self) -> list[Step]:
        """Every instruction up to the unit's end (or an erased word, 0xFFFF) into `done`."""
        while self.at < len(self.words) and self.words[self.at] != 0xFFFF:
            start = self.at
            self.done.append(Step(*self.step(), self.where(start)))
        return self.done

    def step(self) -> tuple[str, list[tuple[str, str]]]:
        """The next instruction's step text and operand lines."""
        start = self.at
        word = self.take()
        edge = ""
        if word == EDGE:
            edge, word = "TU", self.take()
        if word >> 12 in BASIC:
            return self.basic(word, edge, start), []
        if edge or word >> 12 != 0xF:
            raise PdwError("pdw-code", self.where(start), word=f"{word:04X}")
        if word & 0xFF == COMPARE_ESCAPE:
            return self.compare(word, start)
        code = EXTENDED.get(word)
        if code is None:
            raise PdwError("pdw-code", self.where(start), word=f"{word:04X}")
        values = [self.operand(kind, start) for kind in code.kinds]
        if code.head == TIMER:
            return self.timer(values, start), []
        if not code.labels:
            return f"{code.head} {' '.join(values)}", []
        return code.head, [*code.fixed, *zip(code.labels, values, strict=True)]

    def basic(self, word: int, edge: str, start: int) -> str:
        """A contact or coil: `ORG NOT X0`, `AND TU M310`, `OUT TR 0`, `AND SHORT`, `FO 1`."""
        basic = BASIC[word >> 12]
        name, negated = basic.name, basic.negated
        address = word & 0xFFF
        if address in LINE_BITS and not basic.coil and not edge:
            return f"{name} {'OPEN' if negated else 'SHORT'}"
        if address in FO_BITS and basic.tr and not basic.coil and not negated and not edge:
            return f"FO {address - FO_BITS[0]}"
        device = bit_device(address)
        if device is None:
            raise PdwError("pdw-operand", self.where(start), word=f"{word:04X}")
        letters, number = device
        if letters == "TR":
            if not basic.tr or negated or edge:
                raise PdwError("pdw-code", self.where(start), word=f"{word:04X}")
            return f"{name} TR {number}"
        if edge:
            if basic.coil:
                raise PdwError("pdw-code", self.where(start), word=f"{word:04X}")
            return f"{name} {'TD' if negated else 'TU'} {letters}{number}"
        return f"{name}{' NOT' if negated else ''} {letters}{number}"

    def operand(self, kind: str, start: int) -> str:
        """The next operand word as a device or constant."""
        code = self.take()
        if kind == CONST:
            return constant(code)
        text: str | None
        if kind == BIT:
            device = bit_device(code) if code < 0x1000 else None
            text = None if device is None or device[0] == "TR" else f"{device[0]}{device[1]}"
        else:
            text = word_device(code)
        if text is None:
            raise PdwError("pdw-operand", self.where(self.at - 1), word=f"{code:04X}")
        return text

    def timer(self, values: list[str], start: int) -> str:
        """`T30 .01 R8`: the timer, its base (from the project's timer allocation), preset."""
        preset, timer = values
        if not timer.startswith("T"):
            raise PdwError("pdw-operand", self.where(start + 2), word=timer)
        base = self.timer_base(int(timer[1:]))
        return f"{timer} {base} {preset}"

    def compare(self, word: int, start: int) -> tuple[str, list[tuple[str, str]]]:
        """`ANDF 171_.>` with its Sa and Sb lines."""
        kind = COMPARE_OPS.get(word & ~(CONST_FLAGS[0] | CONST_FLAGS[1]))
        if kind is None:
            raise PdwError("pdw-code", self.where(start), word=f"{word:04X}")
        index = self.take() - COMPARE_INDEX
        if not 0 <= index < len(COMPARE_NAMES):
            raise PdwError("pdw-code", self.where(start), word=f"{word:04X}")
        kinds = [CONST if word & flag else WORD for flag in CONST_FLAGS]
        values = [self.operand(k, start) for k in kinds]
        head = f"{kind} {COMPARE_FIRST + index}_.{COMPARE_NAMES[index]}"
        return head, [("Sa", values[0]), ("Sb", values[1])]
