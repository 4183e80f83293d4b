"""WinProladder's element comments as a Fatek program's symbols: its comment export
(`REF<TAB>COMMENT<TAB>DESCRIPTION`, a Windows code page; the description is the symbol's
comment) and a `.pdw` project's comments (device -> text) (docs/dialects.md)."""

from __future__ import annotations

import codecs
import re
import unicodedata
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.dialects.fatek.devices import (
    BIT_RANGES,
    DeviceError,
    bit_address,
    parse_device,
    word_address,
)
from ladderworks.core.symbols import Symbol, SymbolTable

if TYPE_CHECKING:
    from ladderworks.core.il.program import Program

HEADER = ("REF", "COMMENT", "DESCRIPTION")
# The Windows code pages tried, in the order a tie is decided (WinProladder writes the
# system's ANSI code page; the real export is cp1250)
CODE_PAGES = ("cp1250", "cp1254", "cp1252", "cp1257", "cp1251", "cp1253", "cp1255", "cp1256")
_WORD_RE = re.compile(r"\w+")
# the files beside a program read as its comment export (WinProladder's default name first)
COMPANIONS = ("{stem}_comment.txt", "{stem}.comment.txt", "comment.txt", "export/comment.txt")


# The letters each code page's languages write (a decoded letter among them counts once more):
# what tells Polish in cp1250 from Turkish in cp1254, whose bytes both decode as letters
_NATIVE = {
    "cp1250": "ąćęłńóśźżáčďéěíňřšťúůýžäĺľôŕöüőűăâîşţđ",  # Polish, Czech, Slovak, Hungarian …
    "cp1254": "çğıiöşüâîû",  # Turkish
    "cp1252": "àâäæçèéêëîïôœùûüÿßñáíóúãõåøý",  # French, German, Spanish, Nordic …
    "cp1257": "ąčęėįšųūžāēģīķļņōŗöäüõ",  # Baltic
}


def _script(char: str) -> str:
    """The script of a letter from its Unicode name (LATIN, CYRILLIC, GREEK …)."""
    return unicodedata.name(char, "?").split(" ")[0]


def plausibility(text: str) -> int:
    """How much a decoded text reads as words: letters beyond ASCII count up when they are of
    the same script as the word's other letters, down when they are symbols inside a word."""
    score = 0
    for word in _WORD_RE.findall(text):
        scripts = {_script(c) for c in word if c.isalpha()}
        for char in word:
            if ord(char) < 128:
                continue
            score += 1 if char.isalpha() and len(scripts) == 1 else -3
    for char in text:  # a symbol (¹ ³ ¿ …) where a letter was meant
        if ord(char) >= 128 and not char.isalpha() and not char.isspace():
            score -= 2
    return score


def decode(data: bytes) -> tuple[str, str, list[Diagnostic]]:
    """The text, its encoding and diagnostics: a BOM or valid UTF-8 first; else the Windows code
    page whose text reads best, with a warning when another one reads as well (never silent)."""
    for bom, name in ((codecs.BOM_UTF8, "utf-8-sig"), (codecs.BOM_UTF16_LE, "utf-16"),
                      (codecs.BOM_UTF16_BE, "utf-16")):
        if data.startswith(bom):
            try:
                return data.decode(name), name, []
            except UnicodeDecodeError as error:
                return "", name, [_bad_byte(data, error.start)]
    try:
        return data.decode("utf-8"), "utf-8", []
    except UnicodeDecodeError:
        pass
    scored: list[tuple[int, str, str]] = []
    first_bad = len(data)
    for name in CODE_PAGES:
        try:
            text = data.decode(name)
        except UnicodeDecodeError as error:
            first_bad = min(first_bad, error.start)
            continue
        native = _NATIVE.get(name, "")
        bonus = sum(1 for char in text.lower() if ord(char) >= 128 and char in native)
        scored.append((plausibility(text) + bonus, name, text))
    if not scored:
        return "", "", [_bad_byte(data, first_bad)]
    best = max(score for score, _, _ in scored)
    ties = [(name, text) for score, name, text in scored if score == best]
    name, text = ties[0]
    others = [other for other, other_text in ties[1:] if other_text != text]
    if not others:
        return text, name, []
    line = 1 + data[:next(i for i, b in enumerate(data) if b >= 0x80)].count(b"\n")
    return text, name, [Diagnostic("fatek-comment-codepage", {"chosen": name,
                                                              "others": ", ".join(others)},
                                   line, 1, Severity.WARNING)]


def _bad_byte(data: bytes, offset: int) -> Diagnostic:
    line = 1 + data[:offset].count(b"\n")
    column = offset - data.rfind(b"\n", 0, offset)
    return Diagnostic("fatek-comment-bytes", {"offset": offset, "byte": f"{data[offset]:02X}"},
                      line, column)


def read_comments(data: bytes) -> tuple[SymbolTable | None, list[Diagnostic]]:
    """The symbols of a comment export, and its diagnostics (None when it is not one)."""
    text, _encoding, diagnostics = decode(data)
    if any(d.is_error for d in diagnostics):
        return None, diagnostics
    lines = [line.removesuffix("\r") for line in text.split("\n")]  # the file's own lines
    head = tuple(part.strip().upper() for part in lines[0].split("\t")) if lines else ()
    if head[:2] != HEADER[:2]:
        return None, [*diagnostics, Diagnostic("fatek-comment-header", {}, 1, 1)]
    table = SymbolTable()
    for number, line in enumerate(lines[1:], start=2):
        if not line.strip():
            continue
        ref, _, rest = line.partition("\t")
        name, _, description = rest.partition("\t")
        comments = (description.strip(),) if description.strip() else ()
        if not _add(table, ref.strip(), Symbol(name.strip(), comments)):
            diagnostics.append(Diagnostic("fatek-comment-ref", {"text": ref.strip()[:24]},
                                          number, 1, Severity.WARNING))
    return table, diagnostics


def _add(table: SymbolTable, ref: str, symbol: Symbol) -> bool:
    """Put `symbol` on the device `ref` names: a bit device's bit, a register's first byte, a
    timer's or counter's both (its contact and its value); False when `ref` names none."""
    if len(ref) > 12:  # no device is spelled so long (and int() refuses 4300+ digits)
        return False
    added = False
    for bit in (True, False):
        try:
            device = parse_device(ref, bit=bit)
        except DeviceError:
            continue
        if bit and device.kind in BIT_RANGES:
            table.add(bit_address(device), symbol)
            added = True
        elif not bit:
            table.add(word_address(device)[0], symbol)
            added = True
    return added


def comment_symbols(comments: Mapping[str, str]) -> SymbolTable:
    """The symbol table of `comments` (`M300` -> `START`, a `.pdw` project's element comments):
    blank texts and spellings that are not Fatek devices are left out."""
    table = SymbolTable()
    for device_text, text in comments.items():
        if text.strip():
            _add(table, device_text, Symbol(text.strip()))
    return table


def read_comment_file(path: Path) -> tuple[SymbolTable | None, list[Diagnostic]]:
    """read_comments of a file (OSError when it cannot be read)."""
    return read_comments(path.read_bytes())


def attach_companions(path: Path, program: Program) -> None:
    """The comment export beside a program (COMPANIONS) as its symbols, when one reads without
    an error and the program has none."""
    if program.symbols is not None:
        return
    for pattern in COMPANIONS:
        candidate = path.parent / pattern.format(stem=path.stem)
        try:
            if not candidate.is_file() or candidate == path:
                continue
            table, diagnostics = read_comment_file(candidate)
        except OSError:
            continue
        if table is not None and not any(d.is_error for d in diagnostics):
            program.symbols = table
            return
