"""A file's own text form (encoding, BOM, line ends): decoding bytes, encoding text back."""

from __future__ import annotations

import re
from dataclasses import dataclass

from ladderworks.core.diagnostics import Diagnostic, Severity

UTF8 = "utf-8"
CP1254 = "cp1254"
UTF16LE = "utf-16-le"
UTF16BE = "utf-16-be"

BOM_UTF8 = b"\xef\xbb\xbf"
BOM_UTF16LE = b"\xff\xfe"
BOM_UTF16BE = b"\xfe\xff"

# A UTF-8 file with at most this many invalid bytes (or bad lines up to 1 % of its lines) is
# read as UTF-8 with the bad bytes kept, unless it reads as cp1254 (Turkish letters and no
# valid multibyte UTF-8); more than that and it is read as cp1254.
FEW_BAD_BYTES = 16

_LINE_END = re.compile(r"\r\n|\r|\n")


@dataclass(frozen=True, slots=True)
class TextForm:
    """How a file's text is stored: codec name, BOM bytes, the line end for new lines."""

    encoding: str = UTF8
    bom: bytes = b""
    newline: str = "\n"
    final_newline: bool = True

    @property
    def label(self) -> str:
        """A short human name: `UTF-8`, `UTF-8 BOM`, `cp1254`, `UTF-16LE BOM`, plus CRLF."""
        names = {UTF8: "UTF-8", CP1254: "cp1254", UTF16LE: "UTF-16LE", UTF16BE: "UTF-16BE"}
        text = names.get(self.encoding, self.encoding) + (" BOM" if self.bom else "")
        return text + (" CRLF" if self.newline == "\r\n" else " CR" if self.newline == "\r"
                       else "")


class EncodeError(ValueError):
    """A character the file's encoding cannot hold; nothing was written."""

    def __init__(self, encoding: str, char: str, line: int, column: int) -> None:
        self.encoding = encoding
        self.char = char
        self.line = line
        self.column = column
        super().__init__(f"line {line}, column {column}: {char!r} (U+{ord(char):04X}) "
                         f"cannot be written in {encoding}")


def _errors(encoding: str) -> str:
    """The codec error handler that keeps undecodable bytes (and writes them back)."""
    return "surrogatepass" if encoding.startswith("utf-16") else "surrogateescape"


def split_lines(text: str) -> list[str]:
    """Lines split at `\\n`, `\\r\\n` and `\\r` only (not at the other breaks splitlines knows)."""
    lines = text.split("\n") if "\r" not in text else _LINE_END.split(text)
    if lines and lines[-1] == "":
        lines.pop()
    return lines


def split_with_ends(text: str) -> tuple[list[str], list[str]]:
    """Lines (without ends) and each line's own end (`""` for a last line without one)."""
    if "\r" not in text:
        lines = text.split("\n")
        ends = ["\n"] * (len(lines) - 1) + [""]
    else:
        lines = []
        ends = []
        start = 0
        for match in _LINE_END.finditer(text):
            lines.append(text[start:match.start()])
            ends.append(match.group())
            start = match.end()
        lines.append(text[start:])
        ends.append("")
    if lines[-1] == "":
        lines.pop()
        ends.pop()
    return lines, ends


def dominant_newline(ends: list[str]) -> str:
    """The line end most lines have (LF when there is none)."""
    crlf = ends.count("\r\n")
    cr = ends.count("\r")
    lf = len(ends) - crlf - cr - (1 if ends and ends[-1] == "" else 0)
    best = max((lf, "\n"), (crlf, "\r\n"), (cr, "\r"))
    return best[1] if best[0] else "\n"


def _is_bad(ch: str) -> bool:
    return "\udc80" <= ch <= "\udcff"


def _utf8_damage(text: str) -> tuple[int, list[tuple[int, int]], bool]:
    """For text decoded with surrogateescape: bad byte count, (line, count) per damaged line,
    and whether it reads better as cp1254 (no valid multibyte UTF-8, bad bytes mostly letters)."""
    bad = letters = 0
    valid_multibyte = False
    lines: list[tuple[int, int]] = []
    for number, line in enumerate(split_lines(text), start=1):
        if line.isascii():
            continue
        count = 0
        for ch in line:
            if _is_bad(ch):
                count += 1
                letters += bytes([ord(ch) - 0xDC00]).decode(CP1254, errors="ignore").isalpha()
            elif ch > "\x7f":
                valid_multibyte = True
        if count:
            bad += count
            lines.append((number, count))
    return bad, lines, not valid_multibyte and letters * 2 > bad


def decode_text(data: bytes) -> tuple[str, TextForm, list[Diagnostic]]:
    """Decode file bytes by BOM, else strict UTF-8, else (mostly) UTF-8 or cp1254.

    Bytes that cannot be decoded are kept as surrogates, so encoding writes them back; each
    line holding some gets an `invalid-bytes` warning."""
    text, form, diagnostics, _lines = decode_lines(data)
    return text, form, diagnostics


def decode_lines(data: bytes) -> tuple[str, TextForm, list[Diagnostic],
                                       tuple[list[str], list[str]]]:
    """decode_text, plus the text's lines and their ends (split_with_ends) found on the way."""
    diagnostics: list[Diagnostic] = []
    if data.startswith(BOM_UTF16LE) or data.startswith(BOM_UTF16BE):
        encoding = UTF16LE if data.startswith(BOM_UTF16LE) else UTF16BE
        bom, body = data[:2], data[2:]
        odd = len(body) % 2
        text = body[:len(body) - odd].decode(encoding, errors="surrogatepass")
        if odd:
            diagnostics.append(Diagnostic(  # the odd last byte is dropped
                "invalid-bytes", {"count": 1, "encoding": "UTF-16"},
                max(1, len(split_lines(text))), 1, Severity.WARNING))
    else:
        bom = BOM_UTF8 if data.startswith(BOM_UTF8) else b""
        body = data[len(bom):]
        encoding = UTF8
        try:
            text = body.decode(UTF8)
        except UnicodeDecodeError:
            text = body.decode(UTF8, errors="surrogateescape")
            bad, lines, turkish = _utf8_damage(text)
            line_count = max(1, body.count(b"\n") + 1)
            if bom or (not turkish and (bad <= FEW_BAD_BYTES or len(lines) * 100 <= line_count)):
                diagnostics.extend(
                    Diagnostic("invalid-bytes", {"count": count, "encoding": "UTF-8"}, n, 1,
                               Severity.WARNING) for n, count in lines)
            else:
                encoding = CP1254
                text = body.decode(CP1254, errors="surrogateescape")
    split = split_with_ends(text)
    ends = split[1]
    # without a CR every line end is LF: no need to count them
    newline = dominant_newline(ends) if "\r" in text else "\n"
    form = TextForm(encoding, bom, newline, not ends or ends[-1] != "")
    return text, form, diagnostics, split


def encode_text(text: str, form: TextForm) -> bytes:
    """Text as bytes in `form` (BOM first). Raises EncodeError for a character it cannot hold."""
    try:
        return form.bom + text.encode(form.encoding, errors=_errors(form.encoding))
    except UnicodeEncodeError as exc:
        before = text[:exc.start]
        line = len(split_lines(before + "x"))
        last_end = max(before.rfind("\n"), before.rfind("\r"))
        raise EncodeError(form.encoding, text[exc.start], line, exc.start - last_end) from None


def join_lines(lines: list[str], form: TextForm) -> str:
    """Lines joined with the form's line end (a final one if the form has it)."""
    text = form.newline.join(lines)
    return text + form.newline if lines and form.final_newline else text
