"""CLI commands of the PLC: `compile`, `disasm` and `run` (headless simulation)."""

from __future__ import annotations

import argparse
import re
import sys
from dataclasses import dataclass
from pathlib import Path

from ladderworks.cli._programs import (
    add_backend_option,
    add_dialect_option,
    add_every_scan_option,
    backend_note,
    parsed,
)
from ladderworks.core.address import Address, AddressError
from ladderworks.core.compiler import compile_program, disassemble
from ladderworks.core.compiler.binary import MAGIC, decode
from ladderworks.core.compiler.skipped import summary
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError
from ladderworks.core.dialects import typed_target
from ladderworks.core.il import Program, print_program
from ladderworks.core.plc.engine import DEFAULT_PERIOD_MS, ScanEngine
from ladderworks.core.plc.parameters import ParameterFile, parameters_beside, read_parameter_file
from ladderworks.core.plc.session import PlcRun
from ladderworks.core.symbols import SymbolTable

_SET_RE = re.compile(r"^([^=@]+)=(-?\w+)(?:@(\d+))?$")
_NUMBER_PAIR_RE = re.compile(r"^(\d+)=(\d+)$")


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add `compile`, `disasm` and `run`."""
    comp = subparsers.add_parser("compile", help="compile a program to a PLC binary")
    comp.add_argument("file", metavar="FILE")
    comp.add_argument("-o", "--output", metavar="OUT", required=True)
    add_dialect_option(comp)
    comp.set_defaults(handler=_compile)
    dis = subparsers.add_parser("disasm", help="print the program held in a PLC binary")
    dis.add_argument("file", metavar="OUT")
    dis.set_defaults(handler=_disasm)
    run = subparsers.add_parser("run", help="run a program or binary on the simulated PLC")
    run.add_argument("file", metavar="FILE|BIN")
    add_dialect_option(run)
    length = run.add_mutually_exclusive_group()
    length.add_argument("--ms", type=int, metavar="T", help="run T ms of virtual time")
    length.add_argument("--scans", type=int, metavar="N", help="run N scans (default 1)")
    run.add_argument("--scan-period", type=int, default=DEFAULT_PERIOD_MS, metavar="MS",
                     help=f"scan period in ms (default {DEFAULT_PERIOD_MS})")
    run.add_argument("--divisions", type=int, default=1, metavar="N",
                     help="level-2 divisions: level 1 runs N times per pass of levels 2 and 3")
    run.add_argument("--set", action="append", default=[], metavar="ADDR=VALUE[@MS]",
                     help="set a bit or byte (ADDR:2, ADDR:4 for wider values) at time MS")
    run.add_argument("--timer", action="append", default=[], metavar="N=MS",
                     help="preset of timer N in ms")
    run.add_argument("--counter", action="append", default=[], metavar="N=PRESET",
                     help="preset of counter N")
    run.add_argument("--params", metavar="PATH",
                     help="PMC parameter file (default: FILE.prm beside FILE, if there is one)")
    run.add_argument("--print", action="append", default=[], metavar="ADDR,...",
                     dest="print_", help="print ADDR = VALUE lines at the end (repeatable)")
    run.add_argument("--trace", metavar="ADDR,...", help="print a CSV trace of these")
    add_every_scan_option(run)
    add_backend_option(run)
    run.add_argument("--ascii-out", metavar="FILE",
                     help="write what a Fatek FUN 94 ASCWR sent to the terminal (UTF-8)")
    run.add_argument("--period", type=int, default=DEFAULT_PERIOD_MS, metavar="MS",
                     help="trace sampling period in ms")
    run.set_defaults(handler=_run)


def _error(text: str) -> int:
    print(f"ladderworks-cli: {text}", file=sys.stderr)
    return 2


def _report(name: str, diagnostics: list[Diagnostic]) -> None:
    for diagnostic in diagnostics:
        print(diagnostic.located(name), file=sys.stderr)


def _load_program_binary(name: str) -> bytes | None:
    """The binary of FILE: read as is when it is one, else parsed and compiled (None on error)."""
    return _load_program(name)[0]


def _load_program(name: str) -> tuple[bytes | None, Program | None]:
    """The binary of FILE and the program it was compiled from (None for a binary file)."""
    path = Path(name)
    data = path.read_bytes() if not path.is_dir() else b""  # a folder: an S7 export's
    if data.startswith(MAGIC):
        return data, None
    result = parsed(name)
    if not result.ok:
        _report(name, result.diagnostics)
        return None, None
    compiled = compile_program(result.program)
    _report(name, compiled.diagnostics)
    return compiled.binary, result.program


def _compile(args: argparse.Namespace) -> int:
    result = parsed(args.file)
    if not result.ok:
        _report(args.file, result.diagnostics)
        return 1
    compiled = compile_program(result.program)
    _report(args.file, compiled.diagnostics)
    if compiled.binary is None:
        return 1
    Path(args.output).write_bytes(compiled.binary)
    return 0


def _disasm(args: argparse.Namespace) -> int:
    try:
        program = disassemble(Path(args.file).read_bytes())
    except DiagnosticError as error:
        _report(args.file, error.diagnostics)
        return 1
    sys.stdout.write(print_program(program))
    return 0


@dataclass(frozen=True, slots=True)
class _Target:
    """An address with a width, as written on the command line (`D10:2`)."""

    text: str
    address: Address
    width: int

    def read(self, engine: ScanEngine) -> int:
        if self.address.bit is not None:
            return engine.memory.bit(self.address)
        return engine.memory.read(self.address, self.width)

    def write(self, engine: ScanEngine, value: int) -> None:
        if self.address.bit is not None:
            engine.memory.set_bit(self.address, value)
        else:
            engine.memory.write(self.address, value, self.width)


def _symbols(name: str) -> SymbolTable | None:
    """The symbol table of program FILE (None for a binary or an unreadable file)."""
    if Path(name).read_bytes().startswith(MAGIC):
        return None
    return parsed(name).program.symbols


def dialect_of(name: str) -> str | None:
    """The dialect of program or binary FILE ("seed", "fanuc", "delta"), None if unreadable."""
    path = Path(name)
    data = path.read_bytes() if not path.is_dir() else b""  # a folder: an S7 export's
    if data.startswith(MAGIC):
        try:
            return decode(data).dialect
        except DiagnosticError:
            return None
    return parsed(name).program.dialect


def _target(text: str, file: str | None = None) -> _Target:
    """ADDR[:WIDTH], ADDR an address or a symbol of program `file` (`ESKIP`, `*ESP:1`)."""

    def address_of(name: str) -> Address | None:
        symbols = _symbols(file) if file is not None else None
        return symbols.address_of(name) if symbols is not None else None

    try:
        target = typed_target(text, address_of, dialect_of(file) if file is not None else None)
    except AddressError as error:
        raise ValueError(error.diagnostic.message()) from None
    return _Target(target.text, target.address, target.width)


def _run(args: argparse.Namespace) -> int:
    try:
        sets = []
        for item in args.set:
            match = _SET_RE.match(item.strip())
            if not match:
                raise ValueError(f"--set '{item}': expected ADDR=VALUE or ADDR=VALUE@MS")
            sets.append((int(match.group(3) or 0), _target(match.group(1), args.file),
                         _number(match.group(2), item)))
        timers = [_pair(item, "--timer", 1, 100) for item in args.timer]
        counters = [_pair(item, "--counter", 1, 20) for item in args.counter]
        prints = [_target(text, args.file) for item in args.print_ for text in item.split(",")]
        traced = ([_target(text, args.file) for text in args.trace.split(",")]
                  if args.trace else [])
        if args.period <= 0 or args.scan_period <= 0:
            raise ValueError("periods must be at least 1 ms")
        if args.divisions < 1:
            raise ValueError("--divisions must be at least 1")
    except ValueError as error:
        return _error(str(error))
    binary, program = _load_program(args.file)
    if binary is None:
        return 1
    parameters = _parameters(args.file, args.params)
    if parameters is None:
        return 2
    plc = PlcRun(period_ms=args.scan_period, divisions=args.divisions,
                 every_scan=args.every_scan, backend=args.backend or "python")
    plc.set_parameters(parameters.parameters)
    _use_ascii_files(plc, args.file)
    problems = plc.load(binary, program)
    if problems or plc.engine is None:
        _report(args.file, problems)
        return 1
    skips = summary(plc.skipped)  # the instructions the scan passes by, named once more
    if skips is not None:
        _report(args.file, [skips])
    engine = plc.engine
    note = backend_note(engine.backend_used, engine.backend_reason, args.backend)
    if note:
        print(f"ladderworks-cli: {note}", file=sys.stderr)
    for number, value in timers:  # options win over the parameter file
        plc.set_timer_preset(number, value)
    for number, preset in counters:
        plc.set_counter_preset(number, preset)
    plc.start()
    trace = (engine.start_trace([t.address for t in traced], args.period,
                                widths=[t.width for t in traced]) if traced else None)
    sets.sort(key=lambda item: item[0])
    pending = list(sets)
    end_ms = args.ms  # or N scans (default 1): up to the time after the last
    if end_ms is None:
        end_ms = engine.now_ms + (args.scans if args.scans is not None else 1) * engine.period_ms
    stopped = False
    while engine.now_ms < end_ms:
        while pending and pending[0][0] <= engine.now_ms:
            _, target, value = pending.pop(0)
            target.write(engine, value)
        until = min(end_ms, pending[0][0]) if pending else end_ms  # up to the next --set
        try:
            plc.advance(until)
        except DiagnosticError as error:  # a run-time stop (an endless label loop)
            _report(args.file, error.diagnostics)
            stopped = True
            break
    if trace is not None:
        print("time_ms," + ",".join(t.text for t in traced))
        for sample in trace.take():
            print(f"{sample.time_ms}," + ",".join(str(v) for v in sample.values))
    for target in prints:
        print(f"{target.text} = {target.read(engine)}")
    if args.ascii_out:
        Path(args.ascii_out).write_text(plc.ascii_terminal.text(), encoding="utf-8",
                                        newline="")
    return 1 if stopped else 0


def _use_ascii_files(plc: PlcRun, program: str) -> None:
    """The ASCII files of a Fatek program (`PROGRAM.ascii` beside it) for FUN 94; their
    problems are reported, a file with errors makes its ASCWR end with ERR."""
    from ladderworks.core.dialects.fatek.ascii_files import ascii_path, load_ascii_files

    files = load_ascii_files(Path(program))
    _report(str(ascii_path(Path(program))), files.diagnostics)
    plc.use_ascii_files(files.files)


def _parameters(program: str, named: str | None) -> ParameterFile | None:
    """The PMC parameters for `run`: the named file, else the one beside the program (problems
    are reported as warnings); None when a named file cannot be read."""
    try:
        found = read_parameter_file(named) if named else parameters_beside(program)
    except OSError as error:
        print(f"ladderworks-cli: {named}: {error.strerror or error}", file=sys.stderr)
        return None
    if found.path is not None:
        _report(str(found.path), found.diagnostics)
    return found


def _number(text: str, item: str) -> int:
    """A decimal or 0x-hexadecimal value."""
    try:
        if text.lower().lstrip("-").startswith("0x"):
            return int(text, 16)
        return int(text, 10)
    except ValueError:
        raise ValueError(f"--set '{item}': '{text}' is not a number") from None


def _pair(item: str, option: str, lo: int, hi: int) -> tuple[int, int]:
    match = _NUMBER_PAIR_RE.match(item.strip())
    if not match:
        raise ValueError(f"{option} '{item}': expected N=VALUE")
    number, value = int(match.group(1)), int(match.group(2))
    if not lo <= number <= hi:
        raise ValueError(f"{option} '{item}': number must be {lo} to {hi}")
    return number, value
