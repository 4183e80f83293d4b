"""The scenario recorder: input changes and forces made during a run, as a scenario file."""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.plc.scenario import HEADER
from ladderworks.core.plc.session import PlcRun
from ladderworks.core.tag_names import names_for

_TYPES = {1: "BYTE", 2: "WORD", 4: "DWORD"}


@dataclass(frozen=True, slots=True)
class Recorded:
    """One change: at `time_ms` (the scan that first sees it), what and to which value."""

    time_ms: int
    kind: str  # "set", "write", "force" or "release"
    address: Address
    value: int
    width: int = 1

    def fields(self, spell: Callable[[Address], str] = str) -> list[str]:
        """The command's fields after the wait (addresses as `spell` writes them: a Delta
        program's devices)."""
        where = spell(self.address)
        if self.kind == "force":
            return [where, str(self.value)]
        if self.kind == "release":
            return [where]
        if self.address.bit is not None:
            return [where, str(self.value)]
        return [where, f"0x{self.value:X}", _TYPES.get(self.width, "BYTE")]


_COMMANDS = {"set": "SET", "write": "SET", "force": "FORCE", "release": "RELEASE"}


class ScenarioRecorder:
    """Listens to a PlcRun's input changes from `start()` to `stop()`; `text()` is the file."""

    def __init__(self, plc: PlcRun, remark: str = "", program: Path | None = None) -> None:
        self.plc = plc
        self.remark = remark
        self.program = program  # the loaded program's file, written as the PROGRAM line
        self.events: list[Recorded] = []
        self.start_ms = 0
        self.end_ms: int | None = None
        self.recording = False

    def _now(self) -> int:
        return self.plc.engine.now_ms if self.plc.engine is not None else 0

    def start(self) -> None:
        """Begin recording at the PLC's time now."""
        self.events = []
        self.start_ms = self._now()
        self.end_ms = None
        if not self.recording:
            self.plc.input_listeners.append(self._record)
            self.recording = True

    def stop(self) -> None:
        """Stop recording; the end time is the last scan run."""
        if self.recording:
            self.plc.input_listeners.remove(self._record)
            self.recording = False
        self.end_ms = self._now()

    def _record(self, kind: str, address: Address, value: int, width: int) -> None:
        self.events.append(Recorded(self._now(), kind, address, value, width))

    def text(self, expect: list[tuple[Address, int]] | None = None) -> str:
        """The scenario: one line per change, then an EXPECT of each (address, width) given
        (default: every Y byte that is not 0 at the end) at the last scan recorded."""
        spelled = spelling(self.plc.program_dialect)  # a Delta program: X10, D0
        program = self.plc.program
        names = names_for(program.symbols if program is not None else None,
                          self.plc.program_dialect)

        def spell(address: Address, width: int = 1) -> str:
            """An S7 program's place by its tag (`"Start"`) when it has one of that width."""
            name = names.name_of(address, width) if names.typed else ""
            kind = names.symbols.type_of(name) if name and names.symbols is not None else None
            fits = name and "," not in name and (address.bit is not None
                                                  or (kind is not None and kind[1] == width))
            return name if fits else spelled.address(address)

        lines = [HEADER]
        if self.program is not None:
            lines.append(f"PROGRAM,{Path(os.path.abspath(self.program)).as_posix()}")
        if self.remark:
            lines.append(f"REMARK,{self.remark}")
        last = self.start_ms
        for event in self.events:
            wait = max(event.time_ms - last, 0)
            width = event.width
            lines.append(",".join([_COMMANDS[event.kind], str(wait), *event.fields(
                lambda address: spell(address, width))]))  # noqa: B023 (called at once)
            last = event.time_ms
        end = self.end_ms if self.end_ms is not None else self._now()
        period = self.plc.period_ms if self.plc.engine is None else self.plc.engine.period_ms
        checked_at = max(end - period, last)
        if end > self.start_ms:
            targets = expect if expect is not None else self._outputs(bool(spelled.dialect))
            wait = checked_at - last
            for address, width in targets:
                value = (self.plc.bit(address) if address.bit is not None
                         else self.plc.read(address, width))
                kind = ",BIT" if address.bit is not None and spelled.dialect else \
                    "" if address.bit is not None else "," + _TYPES.get(width, "BYTE")
                lines.append(f"EXPECT,{wait},{spell(address, width)},{value}{kind}")
                wait = 0
        return "\n".join(lines) + "\n"

    def _outputs(self, bits: bool = False) -> list[tuple[Address, int]]:
        """Every Y byte that is not 0 (Y0 if none); `bits` (a Delta program, whose Y are
        bit devices): every Y bit that is on (Y0 if none)."""
        data = self.plc.memory.areas[Area.Y]
        if bits:
            on = [(Address(Area.Y, byte, bit), 1) for byte, value in enumerate(data) if value
                  for bit in range(8) if value >> bit & 1]
            return on or [(Address(Area.Y, 0, 0), 1)]
        found = [(Address(Area.Y, byte), 1) for byte, value in enumerate(data) if value]
        return found or [(Address(Area.Y, 0), 1)]


def relative_program(text: str, scenario_path: str | Path) -> str:
    """The scenario text with an absolute PROGRAM path made relative to the folder the file
    is saved in (so program and scenarios move together); as it is on another drive."""
    lines = text.split("\n")
    for index, line in enumerate(lines):
        if line.startswith("PROGRAM,"):
            program = Path(line.split(",", 1)[1])
            if program.is_absolute():
                folder = Path(os.path.abspath(scenario_path)).parent
                with contextlib.suppress(ValueError):  # Windows: on another drive
                    lines[index] = "PROGRAM," + Path(os.path.relpath(program, folder)).as_posix()
            break
    return "\n".join(lines)
