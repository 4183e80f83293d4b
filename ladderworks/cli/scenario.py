"""CLI command `test`: run scenario files headless (in processes), with a JUnit XML report."""

from __future__ import annotations

import argparse
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

from ladderworks.cli._programs import (
    add_backend_option,
    add_dialect_option,
    add_every_scan_option,
    backend_note,
    forced_dialect,
)
from ladderworks.core.plc.engine import DEFAULT_PERIOD_MS
from ladderworks.core.plc.scenario import ScenarioResult
from ladderworks.core.plc.scenario_batch import (
    ScenarioJob,
    ScenarioOutcome,
    is_scenario_file,
    load_program,
    run_jobs,
)


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add `test`."""
    test = subparsers.add_parser(
        "test", help="run scenario files (FANUC signal operations + EXPECT/WAITFOR) on a program",
        description="Run scenario files. PROGRAM may be left out when every scenario names its "
                    "program on a line PROGRAM,path; when given, it is used for every scenario.")
    test.add_argument("files", metavar="FILE", nargs="+",
                      help="[PROGRAM] SCENARIO...: the program to run every scenario on "
                           "(optional), then the scenario files")
    add_dialect_option(test)
    test.add_argument("--junit", metavar="FILE", help="write a JUnit XML report to FILE")
    test.add_argument("--scan-period", type=int, default=DEFAULT_PERIOD_MS, metavar="MS",
                      help=f"scan period in ms (default {DEFAULT_PERIOD_MS})")
    test.add_argument("--params", metavar="PATH",
                      help="PMC parameter file (default: PROGRAM.prm beside PROGRAM, if any)")
    test.add_argument("-j", "--jobs", type=int, default=None, metavar="N",
                      help="run the scenarios in N processes (default: one per core); results "
                           "are printed in the order given")
    test.add_argument("-v", "--verbose", action="store_true", help="print every check")
    add_every_scan_option(test)
    add_backend_option(test)
    test.set_defaults(handler=_test)


def _test(args: argparse.Namespace) -> int:
    if args.scan_period <= 0:
        print("ladderworks-cli: --scan-period must be at least 1 ms", file=sys.stderr)
        return 2
    if args.jobs is not None and args.jobs < 1:
        print("ladderworks-cli: -j must be at least 1", file=sys.stderr)
        return 2
    files: list[str] = args.files
    program: str | None = None
    if not is_scenario_file(files[0]):
        program, files = files[0], files[1:]
        if not files:
            print(f"ladderworks-cli: {program} is not a scenario file (PMC SIGNAL DATA) and no "
                  "scenario follows it", file=sys.stderr)
            return 2
    for name in files:  # unreadable: stop before running anything (OSError: exit code 2)
        Path(name).read_bytes()
    if args.params:
        try:
            Path(args.params).read_bytes()
        except OSError as error:
            print(f"ladderworks-cli: {args.params}: {error.strerror or error}", file=sys.stderr)
            return 2
    if program is not None:
        loaded = load_program(program, args.params, forced_dialect())
        for text in loaded.messages:
            print(text, file=sys.stderr)
        if loaded.binary is None:
            if not loaded.messages:
                print(f"ladderworks-cli: {program}: {loaded.reason}", file=sys.stderr)
            return 1
    jobs = [ScenarioJob(name, program, args.params, args.scan_period, forced_dialect(),
                        args.every_scan, args.backend or "python") for name in files]
    told = {program}
    said: set[str | None] = set()  # programs whose scan's code is said (--backend)
    outcomes: list[ScenarioOutcome] = []
    for outcome in run_jobs(jobs, args.jobs):
        outcomes.append(outcome)
        if outcome.program not in told:
            told.add(outcome.program)
            for text in outcome.messages:
                print(text, file=sys.stderr)
        note = backend_note(outcome.backend_used, outcome.backend_reason, args.backend)
        if note and outcome.program not in said:
            said.add(outcome.program)
            print(f"ladderworks-cli: {outcome.program}: {note}", file=sys.stderr)
        _print_result(outcome.job.scenario, outcome.result, args.verbose)
    if args.junit:
        write_junit(Path(args.junit), [(o.program, o.result) for o in outcomes])
    failed = sum(not o.result.passed for o in outcomes)
    print(f"{len(outcomes) - failed} passed, {failed} failed")
    return 1 if failed else 0


def _print_result(name: str, result: ScenarioResult, verbose: bool) -> None:
    if verbose:
        for check in result.checks:
            print(check.message(name))
    for text in result.failures():
        print(text)
    state = "passed" if result.passed else "FAILED"
    speed = result.virtual_ms / 1000 / result.seconds if result.seconds > 0 else 0.0
    print(f"{name}: {state} ({len(result.checks)} checks, {result.virtual_ms} ms "
          f"in {result.seconds:.3f} s, {speed:.0f}x real time)")


def junit_xml(runs: list[tuple[str | None, ScenarioResult]]) -> ET.Element:
    """The JUnit report: one testsuite per program (in order of first appearance), one
    testcase per scenario in the order given; scenarios without a program in `scenarios`."""
    suites = ET.Element("testsuites")
    by_program: dict[str | None, list[ScenarioResult]] = {}
    for program, result in runs:
        by_program.setdefault(program, []).append(result)
    for program, results in by_program.items():
        _suite(suites, program, results)
    return suites


def _suite(suites: ET.Element, program: str | None, results: list[ScenarioResult]) -> None:
    failures = sum(not r.passed and r.scenario.ok for r in results)
    errors = sum(not r.scenario.ok for r in results)
    total = sum(r.seconds for r in results)
    name = Path(program).name if program else "scenarios"
    classname = Path(program).stem if program else "scenarios"
    suite = ET.SubElement(suites, "testsuite", name=name, tests=str(len(results)),
                          failures=str(failures), errors=str(errors), skipped="0",
                          time=f"{total:.3f}")
    for result in results:
        name = result.scenario.name
        case = ET.SubElement(suite, "testcase", classname=classname,
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


def write_junit(path: Path, runs: list[tuple[str | None, ScenarioResult]]) -> None:
    """Write the JUnit XML report of (program, result) pairs."""
    tree = ET.ElementTree(junit_xml(runs))
    ET.indent(tree)
    tree.write(path, encoding="utf-8", xml_declaration=True)
