"""Scenario files: FANUC PMC simulator signal-operation files plus EXPECT and WAITFOR checks.

A file is `PMC SIGNAL DATA`, then one command a line (docs/scenarios.md):
`REMARK,text`, `SET,wait,ADDR,VALUE[,TYPE][,ADDR,VALUE[,TYPE]]...`, `EXPECT,wait,ADDR,VALUE[,TYPE]`,
`WAITFOR,timeout,ADDR,VALUE[,TYPE]`, `FORCE,wait,BIT,VALUE`, `RELEASE,wait,BIT` and
`PROGRAM,path` (the program it tests, relative to the file).
A wait is in ms after the previous line, rounded up to the scan period. A line at time T acts
at T: SET writes before the scan at T, EXPECT reads after it. `run_scenario` plays a parsed
scenario on a `PlcRun`, so the session policy is shared.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from ladderworks.core import dialects
from ladderworks.core.address import Address, AddressError
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError
from ladderworks.core.il.textform import split_lines
from ladderworks.core.plc.session import PlcRun
from ladderworks.core.symbols import SymbolTable, resolve
from ladderworks.core.tag_names import meaning, names_for, typed_text, typed_value

HEADER = "PMC SIGNAL DATA"
# TYPE column: the width in bytes (0: a bit); REAL and TIME are 4 bytes read as their type
TYPES: dict[str, int] = {"BIT": 0, "B": 1, "BYTE": 1, "1": 1, "WORD": 2, "W": 2, "2": 2,
                         "DWORD": 4, "D": 4, "4": 4, "REAL": 4, "TIME": 4}
# EXPECT / WAITFOR: a VALUE may start with a comparison (`>=T#5s`); "=" without one
COMPARISONS: dict[str, Callable[[float, float], bool]] = {
    ">=": lambda a, b: a >= b, "<=": lambda a, b: a <= b, "<>": lambda a, b: a != b,
    ">": lambda a, b: a > b, "<": lambda a, b: a < b, "=": lambda a, b: a == b}
COMMANDS = {"S": "SET", "SET": "SET", "R": "REMARK", "REMARK": "REMARK",
            "E": "EXPECT", "EXPECT": "EXPECT", "W": "WAITFOR", "WAITFOR": "WAITFOR",
            "FORCE": "FORCE", "RELEASE": "RELEASE", "PROGRAM": "PROGRAM"}

@dataclass(frozen=True, slots=True)
class Target:
    """An address as written in the file, with its width in bytes (1, 2, 4; 1 for a bit)."""

    text: str
    address: Address
    width: int = 1
    type_name: str = ""  # an S7 tag's type (`Time`, `Real`, `Int`): its values typed as such

    def shown(self, value: int) -> str:
        """A value as the file would type it (`T#5s`, `21.5`, `-3`; else the number)."""
        return typed_text(value, self.type_name, self.width) or str(value)

    def read(self, plc: PlcRun) -> int:
        """The value now."""
        if self.address.bit is not None:
            return plc.bit(self.address)
        return plc.read(self.address, self.width)

    def write(self, plc: PlcRun, value: int) -> None:
        """Store a value (the machine side: a forced X/F bit keeps it for its release)."""
        if self.address.bit is not None:
            plc.set_bit(self.address, value)
        else:
            plc.write(self.address, value, self.width)


@dataclass(frozen=True, slots=True)
class Step:
    """One command line: SET (`items` to write), EXPECT or WAITFOR (`items[0]` to check)."""

    line: int
    command: str
    wait_ms: int
    items: tuple[tuple[Target, int], ...] = ()
    compare: str = "="  # a check's comparison (COMPARISONS)

    def holds(self, got: int) -> bool:
        """True when a check's value `got` compares as the line asks with its VALUE."""
        target, expected = self.items[0]
        return COMPARISONS[self.compare](meaning(got, target.type_name, target.width),
                                         meaning(expected, target.type_name, target.width))


@dataclass(slots=True)
class Scenario:
    """A parsed file: its remark, steps and the problems found (errors mean it cannot run)."""

    name: str
    remark: str = ""
    steps: list[Step] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    program: str = ""  # the PROGRAM line's path as written ("" without one)
    program_line: int = 0  # its line (else the header's)

    def program_path(self) -> Path | None:
        """The program the file names: absolute, or relative to the file's folder."""
        if not self.program:
            return None
        path = Path(self.program).expanduser()
        return path if path.is_absolute() else Path(self.name).parent / path

    @property
    def ok(self) -> bool:
        """True when there is no error."""
        return not any(d.is_error for d in self.diagnostics)

    def error_texts(self) -> list[str]:
        """`NAME:LINE:COL: code message` of each problem."""
        return [f"{self.name}:{d.line}:{d.column}: {d.code} {d.message()}"
                for d in self.diagnostics]


@dataclass(frozen=True, slots=True)
class CheckResult:
    """The outcome of one EXPECT or WAITFOR: the value `got` at `time_ms`."""

    line: int
    command: str
    target: str
    expected: int
    got: int
    time_ms: int
    passed: bool
    shown: tuple[str, ...] = ()  # typed: (comparison, expected, got) as the file types

    def message(self, name: str) -> str:
        """`SCENARIO:LINE: expected ADDR=V, got W at T ms` (or `... passed`); a typed check's
        values as typed (`expected "T1".ET>=T#5s, got T#4s990ms`)."""
        op, expected, got = self.shown or ("=", str(self.expected), str(self.got))
        if self.passed:
            return f"{name}:{self.line}: {self.target}{op}{expected} at {self.time_ms} ms"
        return (f"{name}:{self.line}: expected {self.target}{op}{expected}, "
                f"got {got} at {self.time_ms} ms")


@dataclass(slots=True)
class ScenarioResult:
    """Every check's result, the virtual time run and the wall-clock seconds it took."""

    scenario: Scenario
    checks: list[CheckResult] = field(default_factory=list)
    virtual_ms: int = 0
    seconds: float = 0.0
    stopped: list[Diagnostic] = field(default_factory=list)  # a run-time stop of the engine

    @property
    def passed(self) -> bool:
        """True when the file parsed, the run did not stop and every check passed."""
        return (self.scenario.ok and not self.stopped
                and all(check.passed for check in self.checks))

    def failures(self) -> list[str]:
        """The messages of everything that failed."""
        texts = self.scenario.error_texts()
        texts += [f"{self.scenario.name}:{d.line}:{d.column}: {d.code} {d.message()}"
                  for d in self.stopped]
        texts += [c.message(self.scenario.name) for c in self.checks if not c.passed]
        return texts


# -- reading ---------------------------------------------------------------------------------


def _number(text: str) -> int:
    """A decimal or 0x-hexadecimal integer (ValueError otherwise)."""
    text = text.strip()
    if text.lower().lstrip("-").startswith("0x"):
        return int(text, 16)
    return int(text, 10)


class _Reader:
    """Turns lines into steps, collecting diagnostics with their line and column."""

    def __init__(self, symbols: SymbolTable | None, dialect: str | None = None) -> None:
        self.symbols = symbols
        self.dialect = dialect  # a Delta program's: addresses in its devices' spelling
        self.diagnostics: list[Diagnostic] = []

    def error(self, code: str, line: int, column: int, **args: object) -> None:
        self.diagnostics.append(Diagnostic(code, dict(args), line, column))

    def wait(self, text: str, line: int) -> int | None:
        try:
            value = _number(text)
        except ValueError:
            self.error("scenario-wait", line, 2, text=text)
            return None
        if value < 0:
            self.error("scenario-negative", line, 2, text=text)
            return None
        return value

    def target(self, text: str, type_text: str, line: int, column: int) -> Target | None:
        width = TYPES.get(type_text.strip().upper(), -1) if type_text.strip() else None
        if width == -1:
            self.error("scenario-type", line, column + 2, text=type_text)
            return None
        type_name = type_text.strip().upper() if type_text.strip().upper() in ("REAL", "TIME") \
            else ""
        names = names_for(self.symbols, self.dialect)
        if names.typed and width is None:  # an S7 tag: its type's width and meaning
            try:
                named = names.resolve(text)
            except AddressError:
                self.error("scenario-address", line, column, text=text)
                return None
            return Target(text.strip(), named.address, named.width, named.type_name)
        try:
            if dialects.get(self.dialect) is not None:
                want = None if width is None else "bit" if width == 0 else "word"
                address, size = _dialect_target(text.strip(), self.dialect, want,
                                                self.symbols)
                width = width or size
            else:
                address = resolve(text.strip(), self.symbols, width=width or 1)
        except AddressError:
            self.error("scenario-address", line, column, text=text)
            return None
        if address.bit is not None:
            return Target(text.strip(), address, 1)
        return Target(text.strip(), address, width or 1, type_name)

    def value(self, text: str, target: Target, line: int, column: int) -> int | None:
        typed = typed_value(text, target.type_name, target.width)
        if typed is not None:
            return typed
        try:
            value = _number(text)
        except ValueError:
            value = None
        limit = 2 if target.address.bit is not None else 1 << (8 * target.width)
        if value is None or not -limit // 2 <= value < limit or (
                target.address.bit is not None and value < 0):
            self.error("scenario-value", line, column, text=text, target=target.text)
            return None
        return value % limit

    def items(self, fields: list[str], line: int, first_column: int
              ) -> list[tuple[Target, int]] | None:
        """ADDR,VALUE[,TYPE] groups; a TYPE field that is no type starts the next group."""
        items: list[tuple[Target, int]] = []
        index = 0
        while index < len(fields):
            if index + 1 >= len(fields):
                return None
            type_text = ""
            if index + 2 < len(fields) and (not fields[index + 2].strip()
                                            or fields[index + 2].strip().upper() in TYPES):
                type_text = fields[index + 2]
                used = 3
            else:
                used = 2
            column = first_column + index
            target = self.target(fields[index], type_text, line, column)
            if target is None:
                return []
            value = self.value(fields[index + 1], target, line, column + 1)
            if value is None:
                return []
            items.append((target, value))
            index += used
        return items


def _dialect_target(text: str, dialect: str | None, want: str | None,
                    symbols: SymbolTable | None) -> tuple[Address, int]:
    """A device of the program's dialect, else one of its symbols (an S7 tag `Start`, a DB
    member `"DB".Wert`: 1 byte unless the line's TYPE says); AddressError."""
    try:
        return dialects.parse_target(text, dialect, want)
    except AddressError:
        found = symbols.address_of(text) if symbols is not None else None
        if found is None:
            raise
        return found, 1


_NEEDS = {"SET": "a wait and at least one ADDR,VALUE", "FORCE": "a wait, a bit and 0 or 1",
          "RELEASE": "a wait and a forced bit", "PROGRAM": "a program path",
          "EXPECT": "a wait, ADDR and VALUE", "WAITFOR": "a timeout, ADDR and VALUE"}


def parse_scenario(text: str, name: str = "scenario",
                   symbols: SymbolTable | None = None, dialect: str | None = None) -> Scenario:
    """Read a scenario file's text; addresses may be symbols of `symbols`, or in the spelling
    of the program's `dialect` (Delta's `X10`, `D0`; a T/C without a type is its value)."""
    scenario = Scenario(name)
    reader = _Reader(symbols, dialect)
    lines = split_lines(text)
    first = next((i for i, line in enumerate(lines) if line.strip()), None)
    scenario.program_line = (first or 0) + 1
    if first is None or lines[first].strip().strip(",").upper() != HEADER:
        reader.error("scenario-header", (first or 0) + 1, 1)
        scenario.diagnostics = reader.diagnostics
        return scenario
    for number, raw in enumerate(lines[first + 1:], start=first + 2):
        if not raw.strip() or raw.lstrip().startswith(("#", "//")):
            continue
        fields = [part.strip() for part in raw.split(",")]
        while fields and not fields[-1]:
            fields.pop()
        command = COMMANDS.get(fields[0].upper()) if fields else None
        if command is None:
            reader.error("scenario-command", number, 1, text=fields[0] if fields else raw)
            continue
        if command == "REMARK":
            if not scenario.remark:  # later REMARK lines are ignored, as the simulator does
                scenario.remark = raw.split(",", 1)[1].strip() if "," in raw else ""
            continue
        if command == "PROGRAM":
            path = raw.split(",", 1)[1].strip().strip('"') if "," in raw else ""
            if not path:
                reader.error("scenario-fields", number, 1, command=command,
                             expected=_NEEDS[command])
            elif scenario.program:
                reader.error("scenario-program-twice", number, 1,
                             first=scenario.program_line)
            else:
                scenario.program, scenario.program_line = path, number
            continue
        if command == "RELEASE" and len(fields) == 3:
            fields.append("0")  # RELEASE,wait,ADDR: read as an item with no value
        if len(fields) < 4:
            reader.error("scenario-fields", number, 1, command=command,
                         expected=_NEEDS[command])
            continue
        wait = reader.wait(fields[1], number)
        compare = next((op for op in COMPARISONS if fields[3].startswith(op)), "=") \
            if command in CHECKS else "="
        if command in CHECKS and fields[3].startswith(compare):
            fields[3] = fields[3][len(compare):].strip()
        items = reader.items(fields[2:], number, 3)
        if items is None or (command != "SET" and len(items) > 1):
            reader.error("scenario-fields", number, 3, command=command,
                         expected=_NEEDS[command])
            continue
        if wait is None or not items:
            continue
        if command in ("FORCE", "RELEASE") and items[0][0].address.bit is None:
            reader.error("scenario-bit", number, 3, text=items[0][0].text)
            continue
        scenario.steps.append(Step(number, command, wait, tuple(items), compare))
    scenario.diagnostics = reader.diagnostics
    return scenario


def read_scenario(path: str | Path, symbols: SymbolTable | None = None,
                  dialect: str | None = None) -> Scenario:
    """Read a scenario file (UTF-8, else Turkish Windows text)."""
    data = Path(path).read_bytes()
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        text = data.decode("cp1254", errors="replace")
    return parse_scenario(text, str(path), symbols, dialect)


def rounded(wait_ms: int, period_ms: int) -> int:
    """A wait rounded up to whole scan periods."""
    return -(-wait_ms // period_ms) * period_ms


# -- running ---------------------------------------------------------------------------------


CheckListener = Callable[[CheckResult], None]
CHECKS = ("EXPECT", "WAITFOR")


def _shown(step: Step, got: int) -> tuple[str, ...]:
    """A typed check's (comparison, expected, got) as the file types them; () when plain."""
    target, expected = step.items[0]
    if not target.type_name and step.compare == "=":
        return ()
    return step.compare, target.shown(expected), target.shown(got)


def run_scenario(plc: PlcRun, scenario: Scenario,
                 on_check: CheckListener | None = None) -> ScenarioResult:
    """Play the steps on a loaded `plc` from its current time (cold-start it first); the plc
    runs on the virtual clock (ValueError for a real-time one)."""
    result = ScenarioResult(scenario)
    engine = plc.engine
    if engine is None or not scenario.ok:
        return result
    plc.start()
    period = engine.period_ms
    began = time.perf_counter()
    start_ms = engine.now_ms
    at = start_ms

    def run_before(limit: int, until: Callable[[], bool] | None = None) -> None:
        """Run every scan due before `limit` ms (PlcRun.advance: the scans of a repeating
        state skipped, with the same result), or until `until()` holds after one."""
        if engine.now_ms < limit and not plc.advance(limit, until):
            raise ValueError("scenarios run on the virtual clock, not a real-time PlcRun")

    try:
        for step in scenario.steps:
            target_time = at + rounded(step.wait_ms, period)
            if step.command in ("SET", "FORCE", "RELEASE"):
                at = target_time
                run_before(at)
                for target, value in step.items:
                    if step.command == "FORCE":
                        plc.force(target.address, value)
                    elif step.command == "RELEASE":
                        plc.release(target.address)
                    else:
                        target.write(plc, value)
                continue
            target, expected = step.items[0]
            if step.command == "EXPECT":
                at = target_time
                run_before(at + 1)
                got = target.read(plc)
                check = CheckResult(step.line, step.command, target.text, expected, got,
                                    at - start_ms, step.holds(got), _shown(step, got))
            else:
                run_before(at + 1)
                got = target.read(plc)
                if not step.holds(got):  # the scans while the one before was before the timeout
                    run_before(target_time + period,
                               lambda: step.holds(target.read(plc)))  # noqa: B023
                    got = target.read(plc)
                at = seen = engine.now_ms - period
                check = CheckResult(step.line, step.command, target.text, expected, got,
                                    seen - start_ms, step.holds(got), _shown(step, got))
            result.checks.append(check)
            if on_check is not None:
                on_check(check)
    except DiagnosticError as error:
        result.stopped = list(error.diagnostics)
    result.virtual_ms = engine.now_ms - start_ms
    result.seconds = time.perf_counter() - began
    return result
