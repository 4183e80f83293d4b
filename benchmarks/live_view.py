"""Live view benchmark: a 2,000-network program scanning at 8 ms with PLC TEŞHİS open.

Prints the achieved scan period (median, p99), the GUI repaint rate and CPU use.
Run: xvfb-run -a python3 benchmarks/live_view.py [seconds]   (or QT_QPA_PLATFORM=offscreen)
"""

from __future__ import annotations

import itertools
import os
import statistics
import sys
import time

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication, QMainWindow

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse
from ladderworks.gui.docks.diagnostic import DiagnosticDock
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.refcount_guard import guard_singletons

NETWORKS = 2000


def program_text(networks: int = NETWORKS) -> str:
    """A program of `networks` rungs: contacts in series and parallel, coils, some timers."""
    lines = ["%@3"]
    for n in range(networks):
        a, b, c = f"X{n % 100}.{n % 8}", f"R{n % 900}.{(n + 3) % 8}", f"R{(n + 7) % 900}.1"
        if n % 10 == 9:
            lines += [f"RD {a}", f"TMRB {n % 100 + 1} {80 + n % 5 * 8}", f"WRT R{1000 + n}.0"]
        else:
            lines += [f"RD {a}", f"OR {b}", f"AND.NOT {c}", f"WRT R{1000 + n}.{n % 8}"]
    lines.append("%")
    return "\n".join(lines) + "\n"


def main(seconds: float = 5.0) -> None:
    """Run the benchmark and print the figures."""
    guard_singletons()  # PySide6 6.12.0 loses references to None/True (see the module)
    app = QApplication.instance() or QApplication([])
    window = QMainWindow()
    session = PlcSession(window, realtime=True, period_ms=8, publish_ms=40)
    dock = DiagnosticDock(session, window)
    window.setCentralWidget(dock)
    window.resize(1200, 900)
    window.show()
    parsed = parse(program_text())
    assert parsed.ok, parsed.diagnostics[:3]
    result = session.load_program(parsed.program)
    assert result.ok, result.diagnostics[:3]
    app.processEvents()
    starts: list[float] = []
    engine = session.run.engine
    scan = engine.scan

    def timed_scan() -> None:
        starts.append(time.perf_counter())
        scan()

    engine.scan = timed_scan  # type: ignore[method-assign]
    toggle = [0]

    def machine() -> None:  # inputs change as on a running machine
        toggle[0] ^= 0xFF
        for byte in range(0, 100, 3):
            session.write(parse_address(f"X{byte}"), toggle[0] ^ byte)
        dock.view.verticalScrollBar().setValue(
            (dock.view.verticalScrollBar().value() + 37) % max(dock.view.verticalScrollBar()
                                                               .maximum(), 1))

    inputs = QTimer()
    inputs.timeout.connect(machine)
    inputs.start(250)
    paints0 = dock.view.paints
    repaints0 = dock.view.live.repaints
    cpu0 = time.process_time()
    wall0 = time.perf_counter()
    session.start()
    end = wall0 + seconds
    while time.perf_counter() < end:
        app.processEvents()
        time.sleep(0.002)
    session.stop()
    wall = time.perf_counter() - wall0
    cpu = time.process_time() - cpu0
    periods = [(b - a) * 1e3 for a, b in itertools.pairwise(starts)]
    periods.sort()
    status = session.run.status()
    print(f"program: {NETWORKS} networks, {len(session.run.binary.ops)} ops; "
          f"period {session.run.period_ms} ms")
    print(f"scans: {status.scan_count} in {wall:.1f} s; scan time min/avg/max "
          f"{status.min_ms:.3f}/{status.avg_ms:.3f}/{status.max_ms:.3f} ms; "
          f"overruns {status.overruns}")
    if periods:
        p99 = periods[min(len(periods) - 1, int(len(periods) * 0.99))]
        print(f"achieved scan period: median {statistics.median(periods):.2f} ms, "
              f"p99 {p99:.2f} ms (target 8 ms)")
    print(f"GUI: {(dock.view.paints - paints0) / wall:.1f} repaints/s of the diagnostic view, "
          f"{(dock.view.live.repaints - repaints0) / wall:.1f} network overlays changed/s")
    print(f"CPU: {cpu / wall * 100:.0f}% of one core (process, scan thread + GUI)")


if __name__ == "__main__":
    main(float(sys.argv[1]) if len(sys.argv) > 1 else 5.0)
