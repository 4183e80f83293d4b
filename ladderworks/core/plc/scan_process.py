"""The scan process: the real-time PLC scanning in a process of its own (docs/engine.md).

A scan in the IDE's process shares one interpreter lock with the GUI: while a dock paints, a
due scan waits for it. Here the scan has an interpreter to itself. Memory lives in shared memory
(`SharedLayout`); each scan, under the lock both processes share, copies it in, runs the
program on the engine's own bytearrays and copies it back, with the scan count, the clock and
the power flow. What else a scan makes (A-area changes, trace samples, FUN 94 text) is sent
back on a pipe. `serve` is the process's main; `core/plc/process_runner.py` is the IDE's end.

Messages to the process: ("build", ident, binary, period, divisions, ASCII files, flow block
name, backend), ("run", ScanState, ScanSetup), then while running ("setup", ScanSetup), ("reset",)
and ("stop",); ("files", ASCII files) at any time; ("quit",). From it: ("ready", ident,
error or ""), ("out", alarm changes, trace ident, samples, texts) and ("stopped", ScanState,
trace position).
"""

from __future__ import annotations

import contextlib
import gc
import os
import struct
import sys
import time
from dataclasses import dataclass
from multiprocessing.connection import Connection
from multiprocessing.shared_memory import SharedMemory
from typing import Any

from ladderworks.core.address import Area
from ladderworks.core.compiler.binary import decode
from ladderworks.core.dialects import memory_sizes
from ladderworks.core.dialects.fatek.terminal import AsciiTerminal
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.functions.fatek_io import ASCII_FILES, ASCII_TERMINAL
from ladderworks.core.plc.runner import Figures
from ladderworks.core.plc.scan_state import ScanSetup, ScanState

# scan count, clock (ms), next start (perf_counter s), scanning (0/1), then the figures:
# scans, total s, min s, max s, overruns, CPU s, latest start s
HEADER = struct.Struct("<qqdqqdddqdd")
# the IDE's last request for a frame (a count it raises while a view monitors)
REQUEST = struct.Struct("<q")
REQUEST_AT = 96
# the frame: the request it answers, its scan count and clock
FRAME = struct.Struct("<qqq")
FRAME_AT = 104
HEADER_SIZE = 256


@dataclass(frozen=True, slots=True)
class SharedLayout:
    """Where each area's bytes are in the shared block: after the header, memory now, then
    the frame (memory as a monitored scan left it; its power flow is in the flow block)."""

    offsets: tuple[tuple[Area, int, int], ...]  # area, offset, size
    size: int

    @classmethod
    def make(cls) -> SharedLayout:
        """The layout of this build's memory map."""
        offsets, at = [], HEADER_SIZE
        for area, size in memory_sizes().items():
            offsets.append((area, at, size))
            at += size
        return cls(tuple(offsets), HEADER_SIZE + 2 * (at - HEADER_SIZE))

    def views(self, buffer: memoryview, frame: bool = False) -> dict[Area, memoryview]:
        """Each area's bytes in `buffer`: memory now, or the frame's."""
        shift = (self.size - HEADER_SIZE) // 2 if frame else 0
        return {area: buffer[at + shift:at + shift + size] for area, at, size in self.offsets}


def buffer(block: SharedMemory) -> memoryview:
    """A shared block's bytes."""
    data = block.buf
    assert data is not None, "the shared block is closed"
    return data


def attach(name: str) -> SharedMemory:
    """A shared block the IDE made and alone unlinks (a spawned process shares the IDE's
    resource tracker, so the block is registered once)."""
    return SharedMemory(name=name)


class SentTerminal(AsciiTerminal):
    """The process's FUN 94 terminal: what is written is also kept to be sent to the IDE."""

    def __init__(self) -> None:
        super().__init__()
        self.sent: list[str] = []

    def write(self, text: str) -> None:
        """Receive one output of ASCWR, and keep it for the IDE."""
        super().write(text)
        self.sent.append(text)


class Scanner:
    """The process's side: an engine of the loaded program, scanning on the wall clock."""

    def __init__(self, commands: Connection, outputs: Connection, lock: Any,
                 block: SharedMemory) -> None:
        self.commands, self.outputs, self.lock, self.block = commands, outputs, lock, block
        self.layout = SharedLayout.make()
        self.views = self.layout.views(buffer(block))
        self.frame = self.layout.views(buffer(block), frame=True)
        self.engine: ScanEngine | None = None
        self.terminal = SentTerminal()
        self.files: dict[Any, Any] = {}  # the engine's ASCII_FILES, changed in place
        self.flow_block: SharedMemory | None = None
        self.figures = Figures()

    def serve(self) -> None:
        """Build and run programs until told to quit (or the IDE is gone)."""
        while True:
            try:
                message = self.commands.recv()
                if message[0] == "build":
                    self.build(*message[1:])
                elif message[0] == "run" and self.engine is not None:
                    self.run(message[1], message[2])
                elif message[0] == "files":
                    self.use_files(message[1])
                elif message[0] == "quit":
                    break
            except (EOFError, OSError):  # the IDE is gone: so is its PLC
                break
        self.engine = None
        self.views.clear()
        self.frame.clear()
        if self.flow_block is not None:
            self.flow_block.close()
        self.block.close()

    def build(self, ident: int, data: bytes, period_ms: int, divisions: int,
              files: dict[Any, Any], flow_name: str, backend: str = "python") -> None:
        """Make the engine of a program (both variants: monitoring never waits for one), with
        the IDE engine's backend (native: from the disk cache when the IDE compiled it)."""
        self.engine = None
        gc.unfreeze()  # the last program's objects: collected again
        try:
            engine = ScanEngine(decode(data), period_ms=period_ms, divisions=divisions,
                                backend=backend)
            engine.monitored = True
            engine.monitored = False
        except Exception as error:
            self.outputs.send(("ready", ident, f"{type(error).__name__}: {error}"))
            return
        engine.extra[ASCII_TERMINAL] = self.terminal
        self.use_files(files)
        engine.extra[ASCII_FILES] = self.files
        if self.flow_block is not None:
            self.flow_block.close()
        self.flow_block = attach(flow_name)
        self.engine = engine
        # the program's objects (the engine, its code, the binary) live until the next
        # build: out of the collector's sight, a full collection no longer walks them all
        # during a run (one took up to 0.1 s: a scan ten periods late)
        gc.collect()
        gc.freeze()
        self.outputs.send(("ready", ident, ""))

    def run(self, state: ScanState, setup: ScanSetup) -> None:
        """Scan every period until told to stop; then send the state back."""
        engine = self.engine
        assert engine is not None and self.flow_block is not None
        engine.import_state(state)
        engine.use_setup(setup)
        self.figures = Figures()
        pairs = [(engine.memory.areas[area], view) for area, view in self.views.items()]
        frame = [(engine.memory.areas[area], view) for area, view in self.frame.items()]
        flow = buffer(self.flow_block)[:len(engine.program.ops)]
        block = buffer(self.block)
        period = engine.period_ms / 1000.0
        next_start = time.perf_counter()
        raise_priority()  # while it scans only: a build at that priority would stall the IDE
        try:
            self.scan_loop(engine, pairs, frame, flow, block, period, next_start)
        finally:
            normal_priority()
        flow.release()
        trace = engine.trace.spec() if engine.trace is not None else None
        self.outputs.send(("stopped", engine.export_state(), trace))

    def scan_loop(self, engine: ScanEngine, pairs: list[tuple[bytearray, memoryview]],
                  frame: list[tuple[bytearray, memoryview]], flow: memoryview,
                  block: memoryview, period: float, next_start: float) -> None:
        """Scan every period until told to stop."""
        served = 0
        pace = Pace()
        while self.wait(next_start):
            began = time.perf_counter()
            self.header_time(next_start, 1)
            cpu = time.thread_time()
            # the power flow only for a scan whose frame a view asked for: the scans between
            # run the faster variant (same memory and states: the same logic)
            with self.lock:
                if not self.answer():  # what the IDE sent holding the lock counts for this scan
                    break
                wanted = REQUEST.unpack_from(block, REQUEST_AT)[0]
                if engine.monitored != (wanted != served):
                    engine.monitored = wanted != served
                for mine, shared in pairs:
                    mine[:] = shared
                engine.scan()
                for mine, shared in pairs:
                    shared[:] = mine
                if wanted != served:
                    for mine, shared in frame:
                        shared[:] = mine
                    flow[:] = engine.power_flow
                    FRAME.pack_into(block, FRAME_AT, wanted, engine.scan_count, engine.now_ms)
                    served = wanted
                self.header_time(next_start, 1)  # the count and clock go with memory
            cpu = time.thread_time() - cpu
            due, next_start = next_start, next_start + period
            now = time.perf_counter()
            late = now > next_start
            self.figures.add(now - began, cpu, began - due, late)
            if late:
                next_start = now
            change = pace.after_scan(late, now - began > period)
            if change == "lower":  # the logic cannot keep up: scanning back to back at a
                normal_priority()  # real-time priority would starve the IDE
            elif change == "raise":
                raise_priority()
            self.header_time(next_start, 0)
            self.send_outputs(engine)

    def header_time(self, next_start: float, scanning: int) -> None:
        """The next start and whether a scan runs, with the figures so far."""
        engine = self.engine
        assert engine is not None
        HEADER.pack_into(buffer(self.block), 0, engine.scan_count, engine.now_ms, next_start,
                         scanning, *self.figures.values())

    def wait(self, next_start: float) -> bool:
        """Answer messages until the next scan is due; False when told to stop."""
        engine = self.engine
        assert engine is not None
        while True:
            wait = next_start - time.perf_counter()
            if not self.commands.poll(max(0.0, wait)):
                if time.perf_counter() >= next_start:
                    return True
                continue
            if not self.answer():
                return False

    def answer(self) -> bool:
        """Take every message waiting; False when one says stop."""
        engine = self.engine
        assert engine is not None
        while self.commands.poll():
            message = self.commands.recv()
            if message[0] == "stop":
                return False
            if message[0] == "setup":
                engine.use_setup(message[1])
            elif message[0] == "reset":
                self.figures = Figures()
            elif message[0] == "files":
                self.use_files(message[1])
        return True

    def use_files(self, files: dict[Any, Any]) -> None:
        """The ASCII files FUN 94 sends (a Fatek program's), as the IDE has them now."""
        self.files.clear()
        self.files.update(files)

    def send_outputs(self, engine: ScanEngine) -> None:
        """What the scan made besides memory: A-area changes, trace samples, FUN 94 text."""
        alarms = list(engine.alarm_log) if engine.alarm_log else []
        engine.alarm_log.clear()
        trace = engine.trace
        samples = trace.take() if trace is not None and len(trace) else []
        texts, self.terminal.sent = self.terminal.sent, []
        if alarms or samples or texts:
            self.outputs.send(("out", alarms, trace.ident if trace is not None else 0,
                               samples, texts))


RT_PRIORITY = 10  # SCHED_RR's priority: above every normal process, below the kernel's own
_NICE: list[int] = []  # the nice value before `raise_priority` lowered it
LONG_SCANS = 3  # scans in a row longer than the period: back to normal priority
ON_TIME_SCANS = 125  # then scans in a row on time (1 s at 8 ms): the raised priority again


class Pace:
    """When the scan process gives up its raised priority and takes it again: scans that run
    longer than their period back to back would starve the IDE at a real-time priority, so
    after `LONG_SCANS` of them in a row it goes back to normal; once `ON_TIME_SCANS` in a row
    started on time (a slow start, a long scan the program makes now and then), it raises it
    again, rather than running the rest of the run at normal priority."""

    def __init__(self) -> None:
        self.behind = self.on_time = 0
        self.lowered = False

    def after_scan(self, late: bool, long: bool) -> str | None:
        """"lower", "raise" or None, after a scan (`late`: it ended after the next was due;
        `long`: it took longer than the period)."""
        if late:
            self.on_time = 0
            self.behind += long
            if self.behind == LONG_SCANS and not self.lowered:
                self.lowered = True
                return "lower"
            return None
        self.behind = 0
        if self.lowered:
            self.on_time += 1
            if self.on_time >= ON_TIME_SCANS:
                self.lowered, self.on_time = False, 0
                return "raise"
        return None


def normal_priority() -> None:
    """Back to the priority the process started with (`raise_priority` undone)."""
    if sys.platform == "win32":
        import ctypes

        kernel = ctypes.windll.kernel32  # type: ignore[attr-defined]
        kernel.SetPriorityClass(kernel.GetCurrentProcess(), 0x20)  # NORMAL_PRIORITY_CLASS
        return
    if hasattr(os, "sched_setscheduler"):
        with contextlib.suppress(OSError):
            os.sched_setscheduler(0, os.SCHED_OTHER, os.sched_param(0))
    if _NICE:
        with contextlib.suppress(OSError):
            os.setpriority(os.PRIO_PROCESS, 0, _NICE[0])


def raise_priority() -> str:
    """Ask the system to run this process before the IDE and other programs, so that a due
    scan starts on time on a busy machine: round-robin real-time scheduling on Linux where
    the user may have it (root, or an RLIMIT_RTPRIO as audio users get), else a lower nice
    value where allowed; the high priority class on Windows (any user may). What it got.
    $LADDERWORKS_SCAN_PRIORITY=normal leaves it as it is."""
    if os.environ.get("LADDERWORKS_SCAN_PRIORITY", "") == "normal":
        return "normal"
    if sys.platform == "win32":
        import ctypes

        kernel = ctypes.windll.kernel32  # type: ignore[attr-defined]
        if kernel.SetPriorityClass(kernel.GetCurrentProcess(), 0x80):  # HIGH_PRIORITY_CLASS
            return "high priority class"
        return "normal"
    if hasattr(os, "sched_setscheduler"):
        try:
            os.sched_setscheduler(0, os.SCHED_RR, os.sched_param(RT_PRIORITY))
            return f"real-time (round-robin, priority {RT_PRIORITY})"
        except (OSError, ValueError):
            pass
    try:
        _NICE[:] = [os.getpriority(os.PRIO_PROCESS, 0)]
        os.setpriority(os.PRIO_PROCESS, 0, _NICE[0] - 5)
        return "nice -5"
    except OSError:
        return "normal"


def serve(commands: Connection, outputs: Connection, lock: Any, name: str) -> None:
    """The scan process's main (multiprocessing's target)."""
    Scanner(commands, outputs, lock, attach(name)).serve()
