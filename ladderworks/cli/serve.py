"""CLI command `serve`: run a program in real time and serve its PLC over Modbus/TCP."""

from __future__ import annotations

import argparse
import signal
import sys
import threading

from ladderworks.cli._programs import add_dialect_option
from ladderworks.cli.plc import _load_program, _parameters, _report
from ladderworks.core import dialects
from ladderworks.core.compiler.binary import decode
from ladderworks.core.diagnostics import DiagnosticError
from ladderworks.core.modbus.bridge import PlcBridge
from ladderworks.core.modbus.db_map import chosen_map
from ladderworks.core.modbus.server import (
    DEFAULT_HOST,
    DEFAULT_PORT,
    ModbusServer,
    exposure_warning,
    parse_endpoint,
)
from ladderworks.core.plc.engine import DEFAULT_PERIOD_MS
from ladderworks.core.plc.session import PlcRun


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add `serve`."""
    serve = subparsers.add_parser(
        "serve", help="run a program in real time and serve it over Modbus/TCP")
    serve.add_argument("file", metavar="PROGRAM")
    add_dialect_option(serve)
    serve.add_argument("--modbus", default=f"{DEFAULT_HOST}:{DEFAULT_PORT}", metavar="HOST:PORT",
                       help=f"where to listen (default {DEFAULT_HOST}:{DEFAULT_PORT}, this"
                       " computer only; 0.0.0.0:502 opens it to the network)")
    serve.add_argument("--map", metavar="FILE|DB",
                       help="a CSV Modbus map replacing the dialect's, or (S7) a global DB"
                       " whose bytes are the holding registers (docs/modbus.md)")
    serve.add_argument("--scan-period", type=int, metavar="MS",
                       help=f"scan period in ms (default: the dialect's, {DEFAULT_PERIOD_MS} for"
                       " PMC programs)")
    serve.add_argument("--params", metavar="PATH",
                       help="PMC parameter file (default: PROGRAM.prm beside it, if there is one)")
    serve.set_defaults(handler=_serve)


def _error(text: str) -> int:
    print(f"ladderworks-cli: {text}", file=sys.stderr)
    return 2


def scan_period(dialect: str) -> int:
    """The usual scan period of a dialect's programs (8 ms, the PMC's level 1, by default)."""
    found = dialects.get(dialect)
    return found.period_ms if found is not None else DEFAULT_PERIOD_MS


def _serve(args: argparse.Namespace) -> int:
    try:
        host, port = parse_endpoint(args.modbus)
    except ValueError as error:
        return _error(f"--modbus {error}")
    if args.scan_period is not None and args.scan_period <= 0:
        return _error("--scan-period must be at least 1 ms")
    binary, program = _load_program(args.file)
    if binary is None:
        return 1
    dialect = decode(binary).dialect
    try:
        own_map = chosen_map(args.map or "", dialect,
                             program.symbols if program is not None else None)
    except OSError as error:
        return _error(f"--map {args.map}: {error.strerror or error}")
    except DiagnosticError as error:
        if all(d.line == 0 for d in error.diagnostics):  # not a file's line: a DB's name
            return _error("--map " + "; ".join(d.message() for d in error.diagnostics))
        _report(args.map, error.diagnostics)
        return 2
    parameters = _parameters(args.file, args.params)
    if parameters is None:
        return 2
    plc = PlcRun(realtime=True, period_ms=args.scan_period or scan_period(dialect),
                 scan_process=True)  # scans in a process of their own (docs/engine.md)
    plc.set_parameters(parameters.parameters)
    problems = plc.load(binary)
    if problems:
        _report(args.file, problems)
        return 1
    bridge = PlcBridge(plc, own_map, dialect)
    server = ModbusServer(bridge, host, port)
    stop = threading.Event()
    previous = {number: signal.signal(number, lambda *_: stop.set())
                for number in (signal.SIGINT, signal.SIGTERM)}
    try:
        plc.start()
        try:
            server.start()
        except OSError as error:
            return _error(f"Modbus server on {host}:{port}: {error.strerror or error}")
        print(f"serving {args.file} ({dialect}, {plc.period_ms} ms scans) on"
              f" {server.host}:{server.port}, Modbus/TCP, any unit id, map {bridge.map.name};"
              " Ctrl+C stops", flush=True)
        warning = exposure_warning(server.host)
        if warning is not None:
            print(f"ladderworks-cli: warning: {warning}", file=sys.stderr, flush=True)
        while not stop.wait(0.2):
            plc.status()  # moves the scans into the scan process once it has built the program
    finally:
        server.stop()
        plc.close()  # stops, and ends the scan process
        for number, handler in previous.items():
            signal.signal(number, handler)
    print("stopped", flush=True)
    return 0
