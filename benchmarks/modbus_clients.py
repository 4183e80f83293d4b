"""Modbus/TCP: requests a second and the scan period's jitter with four clients polling.

The spindle-override example scans in real time (8 ms); the server listens on a free loopback
port. Phase 1 measures the scan period with no client; phase 2 with four pymodbus clients
polling as fast as answers come, each in its own process as an HMI would be (one switches the
rotary switch through its coils, one reads the R102 relays, two read G30). The scan thread's
start times are taken by wrapping the engine's `scan` (this benchmark only). Prints figures;
asserts nothing. `--seconds S` sets each phase's length (default 2). Last, the time one
request's bridge call takes (the engine lock is held for most of it: the longest a request can
delay a scan's start). Run from the checkout: `python -m benchmarks.modbus_clients`.
`--process`: the scans in the scan process, as `ladderworks-cli serve` and the IDE run them
(docs/engine.md); each phase then prints the process's own figures (scans, overruns, worst
scan, latest start after a due time) instead of the period's jitter.
"""

from __future__ import annotations

import argparse
import itertools
import multiprocessing
import statistics
import sys
import time
from multiprocessing.sharedctypes import Synchronized

from pymodbus.client import ModbusTcpClient

from ladderworks.core.compiler import compile_program
from ladderworks.core.il import parse_file
from ladderworks.core.modbus.bridge import PlcBridge
from ladderworks.core.modbus.maps import Table
from ladderworks.core.modbus.server import ModbusServer
from ladderworks.core.plc.process_runner import ProcessRunner
from ladderworks.core.plc.session import PlcRun
from ladderworks.paths import EXAMPLES

CLIENTS = 4


def period_figures(starts: list[float], period_ms: int) -> str:
    """Mean, standard deviation and worst deviation of the intervals between scan starts."""
    gaps = [(b - a) * 1e3 for a, b in itertools.pairwise(starts)]
    if len(gaps) < 2:
        return "too few scans"
    worst = max(abs(gap - period_ms) for gap in gaps)
    return (f"{len(gaps) + 1} scans, period mean {statistics.fmean(gaps):.3f} ms,"
            f" jitter (stdev) {statistics.pstdev(gaps):.3f} ms, worst {worst:.3f} ms off")


def poll(number: int, port: int, seconds: float, done: Synchronized) -> None:  # type: ignore[type-arg]
    """One client (its own process, as an HMI is): requests for `seconds`, counted in `done`."""
    client = ModbusTcpClient("127.0.0.1", port=port, timeout=3, retries=0)
    client.connect()
    turn = 0
    end = time.perf_counter() + seconds
    while time.perf_counter() < end:
        if number == 0:
            client.write_coils(17, [bool(turn & 1), bool(turn & 2), bool(turn & 4)])
        elif number == 1:
            client.read_coils(10000 + 8 * 102, count=8)
        else:
            client.read_holding_registers(3030, count=1)
        turn += 1
    client.close()
    done.value = turn


def bridge_figures(binary: bytes, calls: int = 5000) -> str:
    """Microseconds per bridge call (a virtual-clock PLC, no network): read, read, write."""
    plc = PlcRun()
    plc.load(binary)
    plc.start()
    bridge = PlcBridge(plc)
    figures = []
    for name, call in (
            ("read 1 register", lambda: bridge.read_registers(Table.HOLDING, 3030, 1)),
            ("read 8 coils", lambda: bridge.read_bits(Table.COILS, 10816, 8)),
            ("write 3 coils", lambda: bridge.write_bits(Table.COILS, 17, [True, False, True]))):
        began = time.perf_counter()
        for _ in range(calls):
            call()
        figures.append(f"{name} {(time.perf_counter() - began) / calls * 1e6:.1f} us")
    return ", ".join(figures)


def figures(plc: PlcRun, starts: list[float], period_ms: int) -> str:
    """The period's jitter from the scans' starts (a thread), or the scan process's own
    figures since the last call (the process's scans are not timed one by one here)."""
    runner = plc._runner  # a benchmark reads the runner's figures
    if not isinstance(runner, ProcessRunner):
        return period_figures(starts, period_ms)
    stats = runner.stats()
    runner.reset_stats()
    return (f"{stats.scans} scans in the scan process, {stats.overruns} overruns, worst "
            f"{stats.max_ms:.3f} ms, latest start {stats.late_max_ms:.3f} ms after due")


def main() -> None:
    """Run both phases and print their figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=2.0)
    parser.add_argument("--switch-ms", type=float, default=None,
                        help="the interpreter's thread switch interval (default: Python's 5 ms)")
    parser.add_argument("--process", action="store_true",
                        help="scan in the scan process (as serve does)")
    args = parser.parse_args()
    seconds = args.seconds
    if args.switch_ms is not None:
        sys.setswitchinterval(args.switch_ms / 1000)
    print(f"switch interval {sys.getswitchinterval() * 1000:g} ms")
    binary = compile_program(parse_file(EXAMPLES / "spindle_override.LAD").program).binary
    assert binary is not None
    plc = PlcRun(realtime=True, scan_process=args.process)
    plc.load(binary)
    engine = plc.engine
    assert engine is not None
    starts: list[float] = []
    scan = engine.scan

    def timed_scan() -> None:
        starts.append(time.perf_counter())
        scan()

    engine.scan = timed_scan  # type: ignore[method-assign]
    server = ModbusServer(PlcBridge(plc), "127.0.0.1", 0)
    server.start()
    plc.start()
    time.sleep(seconds)
    alone = list(starts)
    print(f"no client:   {figures(plc, alone, engine.period_ms)}")
    starts.clear()
    done = [multiprocessing.Value("i", 0) for _ in range(CLIENTS)]
    clients = [multiprocessing.Process(target=poll, args=(n, server.port, seconds, done[n]))
               for n in range(CLIENTS)]
    began = time.perf_counter()
    for client in clients:
        client.start()
    for client in clients:
        client.join()
    took = time.perf_counter() - began
    counts = [value.value for value in done]
    busy = list(starts)
    clients_figures = figures(plc, busy, engine.period_ms)
    plc.close()
    server.stop()
    print(f"{CLIENTS} clients:   {clients_figures}")
    total = sum(counts)
    print(f"requests:    {total} in {took:.2f} s = {total / took:.0f} a second"
          f" ({', '.join(f'{c / took:.0f}' for c in counts)} per client)")
    status = plc.status()
    print(f"scan time:   min {status.min_ms:.3f} avg {status.avg_ms:.3f}"
          f" max {status.max_ms:.3f} ms, {status.overruns} overruns")
    print(f"bridge call: {bridge_figures(binary)}")


if __name__ == "__main__":
    main()
