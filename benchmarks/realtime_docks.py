"""Real-time PLC with docks open: S41_F036 scanning at 8 ms in the main window (issue 30).

Opens the real program as a user does (File › Open, F9, START), then for each set of docks
runs the real-time PLC and prints, after the first second: the scans, the overruns (a scan
that ended after the next one was due), the worst scan, the share of the GUI thread's CPU
time and, in mode "process", the time from START until the scans ran in the scan process (a
thread scans while the process builds the program, which F9 began). Dock sets: none (the
alarm panel closed too), default (the window as it starts: the alarm panel), technician (PLC
diagnostic, bit display live on six bytes, time chart sampling six bits), busy (the
technician's docks, and the IDE checks the whole program every second, as F9 does before it
loads: about half a second of the GUI thread each time).

Each set runs in each mode, in one run. On a thread of the IDE's process, which shares the
interpreter's lock with the GUI: "before" (every dock updates on every snapshot, shown or
not: `snapshot_gate.UPDATE_ALWAYS`), "gate" (docks update only when shown, within the GUI
thread's share: `gui/docks/snapshot_gate.py`, `PACED` off), "paced" (as "gate", and an update
waits for the gap after a scan, the time chart redraws at most four times a second and sets
the span it follows itself: `snapshot_gate.PACED`) and "now" (as "paced", and the time chart
follows without the view's auto-range: `snapshot_gate.SPAN_SET`; each of its lanes and axes
lets a due scan run before it paints: `snapshot_gate.YIELD`). In a process of its own:
"process" (as "now", the scans in the scan process, core/plc/scan_process.py: the default).
Besides the wall-clock figures: the scan's CPU time per scan (the rest of a scan's time it
waited, for the interpreter's lock or a processor) and the latest start after a scan's due
time (waking up: the interpreter's lock held by the GUI thread, or the processors busy).

Run: python benchmarks/realtime_docks.py [SECONDS] [--fifo]
`--fifo` (Linux, root) runs the process at SCHED_FIFO priority so that other processes of a
busy machine do not show in the figures (the GUI and scan threads still share the GIL).
Environment, for experiments: SETS="technician" (the dock sets to run), SHARE=0.15 (the GUI
thread's share, `snapshot_gate.SHARE`), MODES="gate paced" (the modes to run), SWITCH_MS=1
(the interpreter's switch interval, `sys.setswitchinterval`), PROFILE=1 (cProfile of the GUI
thread per set), BACKEND=native (the scan's code: PLC › Native scan checked; python by default),
LADDERWORKS_SCAN_PRIORITY=normal (the scan process keeps its priority: `scan_process.
raise_priority`). The last column says how the system schedules the scan process while it runs.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PROGRAM = "FANUC_STUDER_S41_F036"
MODES = tuple(os.environ.get("MODES", "before gate paced now process").split())
SETS = tuple(os.environ.get("SETS", "none default technician busy").split())


def real_program() -> Path:
    """The real program beside the checkout (shared/real-programs)."""
    for base in ROOT.parents:
        path = base / "shared" / "real-programs" / f"{PROGRAM}.txt"
        if path.exists():
            return path
    raise SystemExit(f"{PROGRAM}.txt not found in shared/real-programs beside {ROOT}")


def measure(mode: str, seconds: float) -> None:
    """One process: open, compile, then each dock set for `seconds`; prints a line each."""
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    sys.path.insert(0, str(ROOT))
    from PySide6.QtCore import QEventLoop, QSettings, Qt, QTimer
    from PySide6.QtWidgets import QApplication

    from ladderworks.core.address import parse_address
    from ladderworks.core.compiler import compile_program
    from ladderworks.core.il import parse_file
    from ladderworks.core.plc.process_runner import ProcessRunner
    from ladderworks.core.plc.runner import RealTimeRunner
    from ladderworks.gui.docks import snapshot_gate
    from ladderworks.gui.main_window import MainWindow
    from ladderworks.gui.refcount_guard import guard_singletons
    from ladderworks.gui.settings import Settings
    from ladderworks.gui.translation import UiLanguage

    snapshot_gate.UPDATE_ALWAYS = mode == "before"
    snapshot_gate.PACED = mode in ("paced", "now", "process")
    snapshot_gate.SPAN_SET = snapshot_gate.YIELD = mode in ("now", "process")
    if os.environ.get("SWITCH_MS"):
        sys.setswitchinterval(float(os.environ["SWITCH_MS"]) / 1000)
    if os.environ.get("SHARE"):
        snapshot_gate.SHARE = float(os.environ["SHARE"])
    guard_singletons()
    app = QApplication.instance() or QApplication([])
    folder = tempfile.mkdtemp()
    settings = Settings(QSettings(str(Path(folder) / "s.ini"), QSettings.Format.IniFormat))
    settings.set_scan_backend(os.environ.get("BACKEND", "python"))  # PLC › Native scan
    language = UiLanguage()
    language.apply("en")
    window = MainWindow(settings, language)
    window.resize(1400, 900)
    window.show()
    window.load(real_program())
    while window.editor.loading:
        app.processEvents()
    if window.compile() is None:
        raise SystemExit("S41_F036 did not compile")
    docks = window.plc_docks
    session = docks.session
    session.run.scan_process = mode == "process"
    program = parse_file(real_program()).program
    inputs = [parse_address(f"X{byte}") for byte in (0, 1, 2, 3, 4, 8, 9, 10)]
    toggle = [0]

    def machine() -> None:  # inputs change as on a running machine
        toggle[0] ^= 0xFF
        for n, address in enumerate(inputs):
            session.write(address, toggle[0] ^ n)

    for name in SETS:
        technician = (docks.diagnostic, docks.bit_display, docks.time_chart)
        for dock in (*technician, docks.alarms):
            dock.hide()
        if name == "default":
            docks.alarms.show()
        watching = name in ("technician", "busy")
        if watching:  # all three in view: the diagnostic beside the bit display
            for dock in technician:
                dock.show()
            window.splitDockWidget(docks.diagnostic, docks.bit_display, Qt.Orientation.Vertical)
            for index, text in enumerate(("X0", "Y0", "R0", "F0", "G0", "R100")):
                docks.bit_display.set_address(index, text)
            docks.bit_display.start()
            docks.time_chart.signals_edit.setText("X0.0 Y0.0 R0.1 F0.0 G4.3 R100.0")
        app.processEvents()
        began = time.perf_counter()
        session.start()
        while mode == "process" and not isinstance(session.run._runner, ProcessRunner):
            app.processEvents()  # the publish timer's status() moves the scans there
            if session.run.process_error:
                raise SystemExit(f"the scan process failed: {session.run.process_error}")
        start_s = time.perf_counter() - began
        priority = ""
        if isinstance(session.run._runner, ProcessRunner) and hasattr(os, "sched_getscheduler"):
            pid = session.run._runner.process.process.pid
            priority = {os.SCHED_OTHER: f"nice {os.getpriority(os.PRIO_PROCESS, pid)}",
                        os.SCHED_RR: "round-robin", os.SCHED_FIFO: "FIFO"}.get(
                            os.sched_getscheduler(pid), "other")
        if watching:
            docks.time_chart.start()
        runner = session.run._runner
        assert runner is not None
        timer = QTimer()
        timer.timeout.connect(machine)
        timer.start(250)
        checks = QTimer()
        checks.timeout.connect(lambda: compile_program(program))
        if name == "busy":
            checks.start(1000)
        marks: list[tuple[float, float]] = []

        def first_second(runner: RealTimeRunner = runner,
                         marks: list[tuple[float, float]] = marks) -> None:
            runner.reset_stats()
            marks.append((time.perf_counter(), time.thread_time()))

        QTimer.singleShot(1000, lambda: first_second())
        loop = QEventLoop()  # not app.exec(): quitting the application hides the window
        QTimer.singleShot(int((seconds + 1) * 1000), loop.quit)
        if os.environ.get("PROFILE"):
            import cProfile
            import pstats
            profile = cProfile.Profile()
            profile.runcall(loop.exec)
            pstats.Stats(profile).sort_stats("tottime").print_stats(25)
        else:
            loop.exec()
        wall = time.perf_counter() - marks[0][0]
        gui = (time.thread_time() - marks[0][1]) / wall * 100
        stats = runner.stats()
        timer.stop()
        shown = [dock for dock in technician if dock.isVisible()]
        checks.stop()
        if watching:
            assert len(shown) == 3, [dock.objectName() for dock in shown]
            docks.time_chart.stop()
            docks.bit_display.stop()
        session.stop()
        print(f"{mode:6}  {name:10}  {stats.scans:6}  "
              f"{stats.overruns:8}  {stats.max_ms:8.1f}  {stats.avg_ms:6.2f}  "
              f"{stats.cpu_avg_ms:6.2f}  {stats.late_max_ms:8.1f}  {gui:5.0f} %  "
              f"{start_s:7.2f}  {priority}", flush=True)
    session.close()


def main() -> None:
    """Every mode, each in a fresh process, figures side by side."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("seconds", nargs="?", type=float, default=6.0,
                        help="seconds measured per dock set, after the first (default 6)")
    parser.add_argument("--fifo", action="store_true",
                        help="SCHED_FIFO priority (Linux, root): a busy machine's other "
                             "processes out of the figures")
    parser.add_argument("--mode", choices=MODES, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.mode:
        measure(args.mode, args.seconds)
        return
    if args.fifo:
        os.sched_setscheduler(0, os.SCHED_FIFO, os.sched_param(10))  # children inherit it
    print(f"{PROGRAM}: 8 ms scans on the wall clock, {args.seconds:.0f} s per dock set after "
          f"the first second{' (SCHED_FIFO)' if args.fifo else ''}")
    print("mode    docks        scans  overruns  worst ms  avg ms  cpu ms  late max  GUI thread"
          "  start s  scan process")
    for mode in MODES:
        subprocess.run([sys.executable, __file__, str(args.seconds), "--mode", mode],
                       check=True)


if __name__ == "__main__":
    main()
