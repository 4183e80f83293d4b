"""Scenario files as a batch: each on its program (given, or its PROGRAM line), in processes.

`ladderworks-cli test` and the pytest plugin run scenarios through `run_job`; `run_jobs` runs
a list of jobs in worker processes and yields the outcomes in the order given. A program is
read, compiled and its parameter file read once per process (`load_program` keeps it while the
file is unchanged), so every worker pays for each program it meets once.
"""

from __future__ import annotations

import multiprocessing
import os
from collections.abc import Iterator, Sequence
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

from ladderworks.core import dialects
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import MAGIC, decode
from ladderworks.core.compiler.skipped import skipped, summary
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError
from ladderworks.core.il import parse_file
from ladderworks.core.il.textform import split_lines
from ladderworks.core.plc.engine import DEFAULT_PERIOD_MS
from ladderworks.core.plc.parameters import (
    ParameterFile,
    PmcParameters,
    parameters_beside,
    read_parameter_file,
)
from ladderworks.core.plc.scenario import HEADER, ScenarioResult, read_scenario, run_scenario
from ladderworks.core.plc.session import PlcRun
from ladderworks.core.symbols import SymbolTable


@dataclass(frozen=True, slots=True)
class ScenarioJob:
    """One scenario file to run; `program` (when given) wins over the file's PROGRAM line."""

    scenario: str
    program: str | None = None
    params: str | None = None  # a PMC parameter file for every program (else PROGRAM.prm)
    period_ms: int = DEFAULT_PERIOD_MS
    dialect: str | None = None  # read programs as this dialect (--dialect), else by content
    every_scan: bool = False  # run every scan (--every-scan), else skip a repeating state's
    backend: str = "python"  # the scan's code: "python" or "native" (--backend)


@dataclass(slots=True)
class LoadedProgram:
    """A program ready to run: its binary (None when it cannot be loaded and `reason` why)."""

    path: str
    binary: bytes | None
    symbols: SymbolTable | None = None
    parameters: PmcParameters = field(default_factory=PmcParameters)
    messages: list[str] = field(default_factory=list)  # FILE:LINE:COL: code message
    reason: str = ""
    dialect: str | None = None  # the program's dialect: its scenarios use its spelling


@dataclass(slots=True)
class ScenarioOutcome:
    """A job's result, the program it ran on and that program's own messages."""

    job: ScenarioJob
    program: str | None
    result: ScenarioResult
    messages: list[str] = field(default_factory=list)
    backend_reason: str | None = None  # why the Python scan ran when native was asked for
    backend_used: str | None = None  # the scan's code that ran ("native", "python"), if any


_PROGRAMS: dict[tuple[str, str | None, str | None, int, int], LoadedProgram] = {}


def load_program(path: str, params: str | None = None,
                 dialect: str | None = None) -> LoadedProgram:
    """Read, compile and find the parameters of a program file or binary (kept per process
    while the file's time and size are unchanged); never raises."""
    try:
        stat = os.stat(path)
    except OSError as error:
        return LoadedProgram(path, None, reason=error.strerror or str(error))
    key = (os.path.abspath(path), params, dialect, stat.st_mtime_ns, stat.st_size)
    if key not in _PROGRAMS:
        _PROGRAMS[key] = _load(path, params, dialect)
    return _PROGRAMS[key]


def _located(name: str, diagnostics: list[Diagnostic]) -> list[str]:
    return [d.located(name) for d in diagnostics]


def _load(path: str, params: str | None, dialect: str | None) -> LoadedProgram:
    try:
        data = Path(path).read_bytes()
        found: ParameterFile = read_parameter_file(params) if params else parameters_beside(path)
    except OSError as error:
        return LoadedProgram(path, None, reason=f"{error.filename}: {error.strerror or error}")
    messages = _located(str(found.path), found.diagnostics) if found.path is not None else []
    if data.startswith(MAGIC):
        try:
            spelled = decode(data).dialect
        except DiagnosticError as error:
            return LoadedProgram(path, None, messages=messages, reason=error.diagnostic.message())
        return LoadedProgram(path, data, None, found.parameters, messages, dialect=spelled)
    parsed = parse_file(path, dialect)
    if not parsed.ok:
        return LoadedProgram(path, None, messages=messages + _located(path, parsed.diagnostics),
                             reason="it does not parse")
    compiled = compile_program(parsed.program)
    messages += _located(path, compiled.diagnostics)
    skips = summary(skipped(parsed.program))  # the instructions the scan passes by
    messages += _located(path, [skips] if skips is not None else [])
    if compiled.binary is None:
        return LoadedProgram(path, None, messages=messages, reason="it does not compile")
    return LoadedProgram(path, compiled.binary, parsed.program.symbols, found.parameters,
                         messages, dialect=parsed.program.dialect)


def is_scenario_file(path: str) -> bool:
    """True when the file's first non-empty line is the scenario header (OSError if unreadable)."""
    with open(path, "rb") as file:
        head = file.read(4096).decode("utf-8-sig", errors="replace")
    first = next((line for line in split_lines(head) if line.strip()), "")
    return first.strip().strip(",").upper() == HEADER


def cold_run(loaded: LoadedProgram, period_ms: int, every_scan: bool = False,
             backend: str = "python") -> tuple[PlcRun, list[Diagnostic]]:
    """A fresh PLC with the program loaded from a cold start, its PMC parameters applied."""
    plc = PlcRun(period_ms=period_ms, every_scan=every_scan, backend=backend)
    plc.set_parameters(loaded.parameters)
    assert loaded.binary is not None
    return plc, plc.load(loaded.binary)


def run_job(job: ScenarioJob) -> ScenarioOutcome:
    """Read the scenario, load its program and play it (OSError if the file is unreadable)."""
    first = read_scenario(job.scenario)
    named = first.program_path()
    program = job.program or (str(named) if named is not None else None)
    if program is None:
        first.diagnostics.append(Diagnostic("scenario-no-program", {}, first.program_line, 1))
        return ScenarioOutcome(job, None, ScenarioResult(first))
    loaded = load_program(program, job.params, job.dialect)
    respelled = loaded.symbols is not None or dialects.get(loaded.dialect) is not None
    scenario = (read_scenario(job.scenario, loaded.symbols, loaded.dialect)
                if loaded.binary is not None and respelled else first)  # read again if it tells
    column = 1 if job.program else 2
    if loaded.binary is None:
        scenario.diagnostics.append(Diagnostic(
            "scenario-program", {"path": program, "reason": loaded.reason},
            scenario.program_line, column))
        return ScenarioOutcome(job, program, ScenarioResult(scenario), loaded.messages)
    plc, problems = cold_run(loaded, job.period_ms, job.every_scan, job.backend)
    if problems:
        scenario.diagnostics.append(Diagnostic(
            "scenario-program", {"path": program, "reason": problems[0].message()},
            scenario.program_line, column))
        return ScenarioOutcome(job, program, ScenarioResult(scenario), loaded.messages)
    engine = plc.engine
    reason, used = (engine.backend_reason, engine.backend_used) if engine is not None \
        else (None, None)
    return ScenarioOutcome(job, program, run_scenario(plc, scenario), loaded.messages, reason,
                           used)


def default_jobs() -> int:
    """The number of cores this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def run_jobs(jobs: Sequence[ScenarioJob], processes: int | None = None
             ) -> Iterator[ScenarioOutcome]:
    """Run jobs in `processes` worker processes (default: one per core; 1: in this process);
    the outcomes come in the order of `jobs`, each as soon as it and those before are done."""
    count = min(processes or default_jobs(), len(jobs))
    if count <= 1:
        for job in jobs:
            yield run_job(job)
        return
    # spawn: the same on every platform, and no fork of a process that may run threads
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=count, mp_context=context) as pool:
        yield from pool.map(run_job, jobs)
