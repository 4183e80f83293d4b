"""CLI command `serve`: run a program in real time and serve its PLC over Modbus/TCP."""

from __future__ import annotations

import argparse
import signal
import sys
import threading

from ladderworks.cli.plc import _load_program_binary, _parameters, _report
from ladderworks.core.diagnostics import DiagnosticError
from ladderworks.core.modbus.bridge import PlcBridge
from ladderworks.core.modbus.map_file import read_map
from ladderworks.core.modbus.maps import ModbusMap, default_map
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
    serve.add_argument("--modbus", default=f"{DEFAULT_HOST}:{DEFAULT_PORT}", metavar="HOST:PORT",
                       help=f"where to listen (default {DEFAULT_HOST}:{DEFAULT_PORT}, this"
                       " computer only; 0.0.0.0:502 opens it to the network)")
    serve.add_argument("--map", metavar="FILE",
                       help="a CSV Modbus map replacing the dialect's (docs/modbus.md)")
    serve.add_argument("--scan-period", type=int, default=DEFAULT_PERIOD_MS, metavar="MS",
                       help=f"scan period in ms (default {DEFAULT_PERIOD_MS})")
    serve.add_argument("--params", metavar="PATH",
                       help="PMC parameter file (default: PROGRAM.prm beside it, if there is one)")
    serve.set_defaults(handler=_serve)


def _error(text: str) -> int:
    print(f"ladderworks-cli: {text}", file=sys.stderr)
    return 2


def _map(name: str | None) -> ModbusMap | None:
    """The --map file's map (None: none given); DiagnosticError / OSError pass through."""
    return read_map(name) if name else None


def _serve(args: argparse.Namespace) -> int:
    try:
        host, port = parse_endpoint(args.modbus)
    except ValueError as error:
        return _error(f"--modbus {error}")
    if args.scan_period <= 0:
        return _error("--scan-period must be at least 1 ms")
    try:
        own_map = _map(args.map)
    except DiagnosticError as error:
        _report(args.map, error.diagnostics)
        return 2
    binary = _load_program_binary(args.file)
    if binary is None:
        return 1
    parameters = _parameters(args.file, args.params)
    if parameters is None:
        return 2
    plc = PlcRun(realtime=True, period_ms=args.scan_period)
    plc.set_parameters(parameters.parameters)
    problems = plc.load(binary)
    if problems:
        _report(args.file, problems)
        return 1
    modbus_map = own_map or default_map(plc.dialect)
    server = ModbusServer(PlcBridge(plc, modbus_map), host, port)
    stop = threading.Event()
    previous = {number: signal.signal(number, lambda *_: stop.set())
                for number in (signal.SIGINT, signal.SIGTERM)}
    try:
        plc.start()
        try:
            server.start()
        except OSError as error:
            return _error(f"Modbus server on {host}:{port}: {error.strerror or error}")
        print(f"serving {args.file} ({plc.dialect}, {plc.period_ms} ms scans) on"
              f" {server.host}:{server.port}, Modbus/TCP, any unit id, map {modbus_map.name};"
              " Ctrl+C stops", flush=True)
        warning = exposure_warning(server.host)
        if warning is not None:
            print(f"ladderworks-cli: warning: {warning}", file=sys.stderr, flush=True)
        while not stop.wait(0.2):
            pass
    finally:
        server.stop()
        plc.stop()
        for number, handler in previous.items():
            signal.signal(number, handler)
    print("stopped", flush=True)
    return 0
