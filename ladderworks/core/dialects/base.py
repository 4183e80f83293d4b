"""What a dialect is: rows of the instruction table, an address map and a reader per file form."""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

from ladderworks.core.address import Address, Area
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.devices import DeviceMap
from ladderworks.core.instructions import InstructionSpec, lookup

if TYPE_CHECKING:
    from pathlib import Path

    from ladderworks.core.dialects.device_tables import DeviceTables
    from ladderworks.core.il.program import Network, Program
    from ladderworks.core.il.textform import TextForm

# (text, form, lines, line ends) -> (program, diagnostics): a reader of one file form
Reader = Callable[[str, "TextForm", list[str], list[str]], "tuple[Program, list[Diagnostic]]"]
# (network, first) -> the lines of a new or changed network in the dialect's own text
NetworkPrinter = Callable[["Network", bool], list[str]]
# (memory areas, now in ms, first scan after RUN) -> None: the special relays before a scan
Relays = Callable[[dict[Area, bytearray], int, bool], None]


@dataclass(frozen=True, slots=True)
class Dialect:
    """One PLC family's programs: how they are recognised, read, spelled, printed and run.

    There is one engine: a dialect's program is the same `Program` (networks of
    `Instruction`s) as a PMC one, run by the same checks, compiler, code generator and scan.
    `reader` and `printer` name functions (`module:function`) imported when first used, so
    registering a dialect loads no parser."""

    name: str  # "delta": Program.dialect, `--dialect NAME`
    title: str  # English: "Delta DVP"
    title_tr: str  # Turkish
    code: int  # its number in a binary's header flags (bits 8-15); unique, never reused
    devices: DeviceMap
    rows: tuple[InstructionSpec, ...]  # its rows of the instruction table (core/instructions)
    sniff: Callable[[str], int]  # a score 0..100: how much a text looks like this dialect
    reader: str  # "module:function", a Reader
    printer: str  # "module:function", a NetworkPrinter
    relays: Relays | None = None  # its special relays, set by the engine before each scan
    # its clock relays: (bit, period, time on), ms; `relays` changes nothing else after the
    # first scan (the engine skips no scan across a clock's edge: core/plc/skipping.py)
    clocks: tuple[tuple[Address, int, int], ...] = ()
    period_ms: int = 10  # its usual scan period (the CLI's and the session's default)
    extensions: tuple[str, ...] = ()  # file name endings its files use (".dvp")
    byteorder: str = "little"  # its multi-byte values in memory ("big": S7); plc/memory.py
    # the watch table's display format of a word address the program gives no type (S7: TIA's
    # Hex; the PMC's, Delta's and Fatek's screens show a signed decimal): core/watch/values.py
    untyped_format: str = "sdec"
    # "module:function": (path, bytes or None) -> (Program, diagnostics, encoding): opens a
    # file with its companions or a folder of them as one program (S7 exports); "" for none
    opener: str = ""
    # a diagnostic code: Save refuses a changed program of this dialect with it (S7: writing
    # its blocks is not done yet); "" when changed networks are written by `printer`
    refuse_changes: str = ""
    # "module:function": (program) -> the text Save writes for a changed program in its file's
    # own form, or None when the changes are not known to it (then `refuse_changes` refuses)
    writer: str = ""
    # "module:function": (program) -> True when the program differs from its file in what its
    # engine networks do not show (S7: an operand written another way for the same address);
    # Save then asks `writer` though the networks are as read
    changed: str = ""
    # "module:function": (program, path) -> {file: bytes} Save writes beside the program's file
    # `path` (S7: the `.s7res` texts of changed network titles); {} for none
    save_companions: str = ""
    namer: str = ""  # "module:function": a row's name in the dialect's text (LD for RD)
    spelling: str = ""  # "module:function" making its dialects.spelling.Spelling (display)
    # the rows each module of core/plc/functions implements for it (plc/families.py merges them)
    families: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    # the compiler checks' codes said in the dialect's words (sp-without-spe: its SRET)
    codes: Mapping[str, str] = field(default_factory=dict)
    tables: str = ""  # "module:NAME", its device_tables.DeviceTables (the PLC tables dock)
    # "module:function": (row, typed operand texts) -> the lines of the dialect's text that read
    # as that row with those operands (the function dialog checks them so: dialects/functions)
    probe: str = ""
    # "module:function": (row, params) -> the texts the function dialog shows, one an operand
    operand_texts: str = ""
    # "module:function": (row, params, the program's other boxes as (row, params)) -> the
    # params of a box placed in the editor (Fatek: an FO byte no other box has)
    placed: str = ""
    # "module:function": (program, the faithful Save's lines with their ends, the indices of the
    # lines printed fresh, the indices where the file's own lines follow a change) -> the lines
    # in the file's own form (Delta: WPLSoft's export, its separators and step numbers)
    finish: str = ""
    # (area, first byte, last byte): bits each network uses afresh (Fatek's TR points); their
    # coils in several networks are not "written twice"
    local_bits: tuple[tuple[Area, int, int], ...] = ()
    # "module:function": (the file's lines) -> the style the printer writes a changed network in
    # (the file's own form); "" when the dialect has one form
    style: str = ""
    # "module:function": (program's path, program) -> None: files beside a program read with it
    # (Fatek's comment export as its symbols)
    companions: str = ""
    # the lines a program not read from a file ends with, after its last network (Fatek's END:
    # WinProladder's listing closes so; a read file keeps its own last lines)
    closing: tuple[str, ...] = ()

    def read(self, text: str, form: TextForm, lines: list[str],
             ends: list[str]) -> tuple[Program, list[Diagnostic]]:
        """Read a text of this dialect: the program and its diagnostics."""
        reader: Reader = _function(self.reader)  # type: ignore[assignment]
        return reader(text, form, lines, ends)

    def open_path(self, path: object, data: bytes | None
                  ) -> tuple[Program, list[Diagnostic], str]:
        """A file with its companion files, or a folder, as one program (`opener`)."""
        opener: Callable[[object, bytes | None], tuple[Program, list[Diagnostic], str]] = \
            _function(self.opener)  # type: ignore[assignment]
        return opener(path, data)

    def finish_lines(self, program: Program, out: list[str], fresh: set[int],
                     joins: set[int]) -> list[str]:
        """The faithful Save's lines in the file's own form (`finish`), as they are without."""
        if not self.finish:
            return out
        finish = _function(self.finish)
        lines = finish(program, out, fresh, joins)
        assert isinstance(lines, list)
        return lines

    def write_changed(self, program: Program) -> str | None:
        """The text of a changed program as `writer` writes it; None when it cannot."""
        if not self.writer:
            return None
        text = _function(self.writer)(program)
        assert text is None or isinstance(text, str)
        return text

    def companion_files(self, program: Program, path: Path) -> dict[Path, bytes]:
        """The files Save writes beside `path` for `program` (`save_companions`), else {}."""
        if not self.save_companions:
            return {}
        found = _function(self.save_companions)(program, path)
        assert isinstance(found, dict)
        return found

    def source_changed(self, program: Program) -> bool:
        """True when `changed` says the program differs from its file beyond its networks."""
        return bool(self.changed) and bool(_function(self.changed)(program))

    def network_lines(self, network: Network, first: bool, style: object = None) -> list[str]:
        """A new or changed network as this dialect's text (Save, format), in `style` (what
        `style_of` found in its file) when it has one."""
        printer: Callable[..., list[str]] = _function(self.printer)  # type: ignore[assignment]
        return printer(network, first) if style is None else printer(network, first, style)

    def style_of(self, lines: list[str]) -> object:
        """The form a file's lines are written in, for its changed networks (None: the one)."""
        return _function(self.style)(lines) if self.style else None

    def is_local(self, address: Address) -> bool:
        """Whether a bit is one each network uses afresh (`local_bits`)."""
        return any(address.area is area and first <= address.byte <= last
                   for area, first, last in self.local_bits)

    def instruction_name(self, spec: InstructionSpec) -> str:
        """A row's name as this dialect writes it (`LD` for RD, `TMR` for DVP.TMR)."""
        if not self.namer:
            return spec.text_name
        namer: Callable[[InstructionSpec], str] = _function(self.namer)  # type: ignore[assignment]
        return namer(spec)

    def localize(self, diagnostic: Diagnostic) -> Diagnostic:
        """A compiler check's diagnostic in this dialect's words: its code (`codes`) and the
        instruction it names."""
        code = self.codes.get(diagnostic.code, diagnostic.code)
        args = diagnostic.args
        name = args.get("name")
        spec = lookup(name) if isinstance(name, str) else None
        if spec is not None:
            args = {**args, "name": self.instruction_name(spec)}
        if code == diagnostic.code and args is diagnostic.args:
            return diagnostic
        return replace(diagnostic, code=code, args=args)

    def device_tables(self) -> DeviceTables | None:
        """Its device monitor tables (timers, counters, registers), None when it has none."""
        if not self.tables:
            return None
        return _function(self.tables)  # type: ignore[return-value]

    @staticmethod
    def function(path: str) -> Callable[..., object]:
        """The function `module:name` one of the dialect's paths names."""
        return _function(path)

    def format_address(self, address: Address) -> str:
        """An address in this dialect's spelling (the PMC's when no device lives there)."""
        return self.devices.format(address) or str(address)

    def memory_sizes(self) -> dict[Area, int]:
        """The bytes each memory area needs for this dialect's devices."""
        return self.devices.bytes_needed()


def _function(path: str) -> Callable[..., object]:
    """The function `module:name` (a Reader or a NetworkPrinter)."""
    module, _, name = path.partition(":")
    found: Callable[..., object] = getattr(importlib.import_module(module), name)
    return found
