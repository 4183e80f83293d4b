"""Alarm messages: the AlarmMsg.dat reader and the list of alarms the A area has raised."""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

from ladderworks.core.address import Address, AddressError, Area, parse_address
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.il.parser import decode
from ladderworks.core.il.program import Message
from ladderworks.core.il.textform import split_lines

A_BYTES = 100  # the alarm bits A0 .. A99 (the 30i's A area is larger; these are watched)
ALARM_COUNT = A_BYTES * 8  # messages 000 .. 799

_NUMBER_LINE = re.compile(r"^(\d+)(?:\s+(.*))?$")
_ADDRESS_LINE = re.compile(r"^([Aa]\d+\.\d+)(?:\s+(.*))?$")
_COMMENT_PREFIXES = ("//", ";")


def alarm_number(address: Address | str) -> int:
    """Message number of an A-area bit: byte×8+bit (`A21.0` -> 168). Raises AddressError."""
    where = address if isinstance(address, Address) else parse_address(address, want_bit=True)
    if where.area is not Area.A or where.bit is None:
        raise AddressError("bad-address", text=str(where))
    if where.byte >= A_BYTES:
        raise AddressError("byte-range", text=str(where), area="A", last=A_BYTES - 1)
    return where.byte * 8 + where.bit


def alarm_address(number: int) -> Address:
    """The A-area bit of message `number` (0 -> `A0.0`, 799 -> `A99.7`)."""
    if not 0 <= number < ALARM_COUNT:
        raise ValueError(f"alarm number {number} is not 0 to {ALARM_COUNT - 1}")
    return Address(Area.A, number // 8, number % 8)


def format_number(number: int) -> str:
    """The three-digit spelling the message file and the CNC screen use (`007`)."""
    return f"{number:03d}"


@dataclass(slots=True)
class AlarmTable:
    """Alarm message texts by number (0 .. 799)."""

    messages: dict[int, str] = field(default_factory=dict)
    numbers: dict[int, int] = field(default_factory=dict)  # %@4: alarm -> its message number

    @classmethod
    def from_messages(cls, messages: dict[Address, Message]) -> AlarmTable:
        """The table of a program's `%@4` messages: text `NNNN text` (message number first)."""
        table = cls()
        for address, message in messages.items():
            if address.area is Area.A and address.bit is not None and address.byte < A_BYTES:
                number = address.byte * 8 + address.bit
                table.messages[number] = f"{message.number} {message.text}".rstrip()
                table.numbers[number] = message.number
        return table

    def text_for(self, key: Address | str | int) -> str | None:
        """The message of a number, an A-area bit (`A21.0`, `A021.0`) or its text; None if none."""
        if isinstance(key, int):
            return self.messages.get(key)
        try:
            return self.messages.get(alarm_number(key))
        except AddressError:
            return None

    def __len__(self) -> int:
        return len(self.messages)

    def __contains__(self, number: object) -> bool:
        return number in self.messages

    def __iter__(self) -> Iterator[int]:
        return iter(sorted(self.messages))

    def to_text(self) -> str:
        """The table as AlarmMsg.dat text: one `NNN text` line per message, by number."""
        return "".join(f"{format_number(n)} {self.messages[n]}\n" for n in self)


def parse_alarm_text(text: str) -> tuple[AlarmTable, list[Diagnostic]]:
    """Read AlarmMsg.dat text. Bad lines become diagnostics with line numbers; never raises.

    Lines: `NNN text` (NNN = 0 .. 799, leading zeros allowed) or `A00.0 text`; blank lines
    and lines beginning with `//` or `;` are skipped. When a number appears twice the first
    line wins and the later one gets an `alarm-duplicate` warning.
    """
    table = AlarmTable()
    first_line: dict[int, int] = {}
    diagnostics: list[Diagnostic] = []
    for line_no, raw in enumerate(split_lines(text), start=1):
        stripped = raw.strip()
        if not stripped or stripped.startswith(_COMMENT_PREFIXES):
            continue
        column = len(raw) - len(raw.lstrip()) + 1
        parsed = _parse_line(stripped, line_no, column)
        if isinstance(parsed, Diagnostic):
            diagnostics.append(parsed)
            continue
        number, message = parsed
        if number in first_line:
            diagnostics.append(Diagnostic(
                "alarm-duplicate", {"number": format_number(number), "first": first_line[number]},
                line=line_no, column=column, severity=Severity.WARNING))
            continue
        if not message:
            diagnostics.append(Diagnostic(
                "alarm-empty", {"number": format_number(number)},
                line=line_no, column=column, severity=Severity.WARNING))
        first_line[number] = line_no
        table.messages[number] = message
    return table, diagnostics


def _parse_line(text: str, line: int, column: int) -> tuple[int, str] | Diagnostic:
    match = _NUMBER_LINE.match(text)
    if match:
        digits = match.group(1).lstrip("0")
        number = int(digits or "0") if len(digits) <= 6 else ALARM_COUNT
        if number >= ALARM_COUNT:
            return Diagnostic("alarm-number", {"number": match.group(1)}, line=line,
                              column=column)
        return number, (match.group(2) or "").rstrip()
    match = _ADDRESS_LINE.match(text)
    if match:
        try:
            number = alarm_number(parse_address(match.group(1), want_bit=True))
        except AddressError:
            return Diagnostic("alarm-address", {"text": match.group(1)}, line=line,
                              column=column)
        return number, (match.group(2) or "").rstrip()
    return Diagnostic("alarm-line", {"text": text[:40]}, line=line, column=column)


def read_alarm_bytes(data: bytes) -> tuple[AlarmTable, list[Diagnostic]]:
    """Read AlarmMsg.dat contents given as bytes (UTF-8 with or without BOM, or cp1254)."""
    text, _encoding = decode(data)
    return parse_alarm_text(text)


def load_alarm_file(path: str | Path) -> tuple[AlarmTable, list[Diagnostic]]:
    """Read an AlarmMsg.dat file; an unreadable file raises OSError as any file would."""
    return read_alarm_bytes(Path(path).read_bytes())


@dataclass(frozen=True, slots=True)
class ActiveAlarm:
    """A listed alarm: number, when its bit rose (ms), its text, and whether the bit is still 1."""

    number: int
    raised_ms: int
    text: str = ""
    active: bool = True

    @property
    def address(self) -> Address:
        """The A-area bit that raised it."""
        return alarm_address(self.number)


class ActiveAlarms:
    """The alarm list of the CNC screen, fed with the A-area bytes after each scan.

    Rules:
    - An alarm is raised when its A bit goes from 0 to 1 between two updates (before the first
      update every bit counts as 0). It goes to the top of the list with the update's time.
    - It stays on the list when its bit drops back to 0 (marked `active=False`) until `reset()`,
      as the manual's alarm stays on the screen until the reset key.
    - A bit that rises again while its alarm is still listed moves it to the top with the new time.
    - `reset()` (the CNC reset key) removes every alarm whose bit is 0. An alarm whose bit is
      still 1 stays (FANUC style: a live condition cannot be cleared away); after its bit drops it
      goes at the next reset, and it is raised again only when the bit rises again.
    """

    def __init__(self, table: AlarmTable | None = None) -> None:
        self.table = table if table is not None else AlarmTable()
        self._bits = bytes(A_BYTES)
        self._alarms: dict[int, ActiveAlarm] = {}

    def update(self, a_bytes: bytes | bytearray | memoryview, now_ms: int) -> list[ActiveAlarm]:
        """Take the A area (its first 100 bytes are used) at time `now_ms`; returns the alarms
        this update raised."""
        if len(a_bytes) < A_BYTES:
            raise ValueError(f"the A area has {A_BYTES} bytes, got {len(a_bytes)}")
        current = bytes(a_bytes[:A_BYTES])
        if current == self._bits:
            return []
        raised: list[ActiveAlarm] = []
        for byte, (old, new) in enumerate(zip(self._bits, current, strict=True)):
            if old == new:
                continue
            for bit in range(8):
                mask = 1 << bit
                if old & mask == new & mask:
                    continue
                number = byte * 8 + bit
                if new & mask:
                    alarm = ActiveAlarm(number, now_ms, self.table.text_for(number) or "")
                    self._alarms.pop(number, None)
                    self._alarms[number] = alarm
                    raised.append(alarm)
                elif number in self._alarms:
                    listed = self._alarms[number]
                    self._alarms[number] = ActiveAlarm(
                        listed.number, listed.raised_ms, listed.text, active=False)
        self._bits = current
        return raised

    def reset(self) -> None:
        """The reset key: drop every listed alarm whose bit is 0; those still on stay."""
        self._alarms = {n: a for n, a in self._alarms.items() if a.active}

    def clear(self) -> None:
        """Forget everything, bits included (the PLC was stopped or reloaded)."""
        self._bits = bytes(A_BYTES)
        self._alarms.clear()

    @property
    def alarms(self) -> list[ActiveAlarm]:
        """The listed alarms, newest first (raised in the same update: by number)."""
        return sorted(self._alarms.values(), key=lambda a: (-a.raised_ms, a.number))

    def is_raised(self, number: int) -> bool:
        """True when alarm `number` is on the list."""
        return number in self._alarms

    def __len__(self) -> int:
        return len(self._alarms)
