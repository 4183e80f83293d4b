"""CLI command `test`: run scenario files on a program headless, with a JUnit XML report."""

from __future__ import annotations

import argparse
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

from ladderworks.cli._programs import add_dialect_option
from ladderworks.cli.plc import _load_program_binary, _parameters, _symbols, dialect_of
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.plc.engine import DEFAULT_PERIOD_MS
from ladderworks.core.plc.parameters import PmcParameters
from ladderworks.core.plc.scenario import ScenarioResult, read_scenario, run_scenario
from ladderworks.core.plc.session import PlcRun


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add `test`."""
    test = subparsers.add_parser(
        "test", help="run scenario files (FANUC signal operations + EXPECT/WAITFOR) on a program")
    test.add_argument("file", metavar="PROGRAM")
    test.add_argument("scenarios", metavar="SCENARIO", nargs="+")
    add_dialect_option(test)
    test.add_argument("--junit", metavar="FILE", help="write a JUnit XML report to FILE")
    test.add_argument("--scan-period", type=int, default=DEFAULT_PERIOD_MS, metavar="MS",
                      help=f"scan period in ms (default {DEFAULT_PERIOD_MS})")
    test.add_argument("--params", metavar="PATH",
                      help="PMC parameter file (default: PROGRAM.prm beside PROGRAM, if any)")
    test.add_argument("-v", "--verbose", action="store_true", help="print every check")
    test.set_defaults(handler=_test)


def cold_run(binary: bytes | BinaryProgram, parameters: PmcParameters,
             period_ms: int = DEFAULT_PERIOD_MS) -> PlcRun:
    """A fresh PLC with the program loaded from a cold start, its PMC parameters applied."""
    plc = PlcRun(period_ms=period_ms)
    plc.set_parameters(parameters)
    problems = plc.load(binary)
    if problems:
        raise ValueError("; ".join(d.message() for d in problems))
    return plc


def _test(args: argparse.Namespace) -> int:
    if args.scan_period <= 0:
        print("ladderworks-cli: --scan-period must be at least 1 ms", file=sys.stderr)
        return 2
    binary = _load_program_binary(args.file)
    if binary is None:
        return 1
    parameters = _parameters(args.file, args.params)
    if parameters is None:
        return 2
    symbols = _symbols(args.file)
    dialect = dialect_of(args.file)
    results: list[ScenarioResult] = []
    for name in args.scenarios:
        scenario = read_scenario(name, symbols, dialect)
        try:
            plc = cold_run(binary, parameters.parameters, args.scan_period)
        except ValueError as error:
            print(f"{args.file}: {error}", file=sys.stderr)
            return 1
        result = run_scenario(plc, scenario)
        results.append(result)
        if args.verbose:
            for check in result.checks:
                print(check.message(name))
        for text in result.failures():
            print(text)
        state = "passed" if result.passed else "FAILED"
        speed = result.virtual_ms / 1000 / result.seconds if result.seconds > 0 else 0.0
        print(f"{name}: {state} ({len(result.checks)} checks, {result.virtual_ms} ms "
              f"in {result.seconds:.3f} s, {speed:.0f}x real time)")
    if args.junit:
        write_junit(Path(args.junit), args.file, results)
    failed = sum(not r.passed for r in results)
    print(f"{len(results) - failed} passed, {failed} failed")
    return 1 if failed else 0


def junit_xml(program: str, results: list[ScenarioResult]) -> ET.Element:
    """The JUnit report: one testsuite for the program, one testcase per scenario."""
    suites = ET.Element("testsuites")
    failures = sum(not r.passed and r.scenario.ok for r in results)
    errors = sum(not r.scenario.ok for r in results)
    total = sum(r.seconds for r in results)
    suite = ET.SubElement(suites, "testsuite", name=Path(program).name, tests=str(len(results)),
                          failures=str(failures), errors=str(errors), skipped="0",
                          time=f"{total:.3f}")
    for result in results:
        name = result.scenario.name
        case = ET.SubElement(suite, "testcase", classname=Path(program).stem,
                             name=Path(name).name, time=f"{result.seconds:.3f}")
        texts = result.failures()
        if not result.scenario.ok:
            error = ET.SubElement(case, "error", message=texts[0], type="scenario-file")
            error.text = "\n".join(texts)
        elif not result.passed:
            failure = ET.SubElement(case, "failure", message=texts[0], type="check")
            failure.text = "\n".join(texts)
        out = ET.SubElement(case, "system-out")
        out.text = "\n".join(c.message(name) for c in result.checks)
    return suites


def write_junit(path: Path, program: str, results: list[ScenarioResult]) -> None:
    """Write the JUnit XML report."""
    tree = ET.ElementTree(junit_xml(program, results))
    ET.indent(tree)
    tree.write(path, encoding="utf-8", xml_declaration=True)
