"""The IDE's end of the scan process (core/plc/scan_process.py): `ScanProcess` and its runner.

`ScanProcess` starts the process (spawned: no Qt, no thread of the IDE's in it), sends it each
program loaded and keeps a thread that takes what it sends back. `ProcessRunner` has the face
of `RealTimeRunner`: `start()` moves the engine's memory into shared memory and its state into
the process, `stop()` brings both back. Meanwhile the IDE's engine scans nothing: its lock
(a `ScanLock`) also takes the process's lock, so whatever reads or writes memory between two
scans still does; a change of its setup (forces, disabled elements, monitoring, trace) is sent
to the process at once (`send_setup`).
"""

from __future__ import annotations

import contextlib
import multiprocessing
import queue
import sys
import threading
import time
import weakref
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from multiprocessing.shared_memory import SharedMemory
from typing import Any

from ladderworks.core.compiler.binary import encode
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.functions.fatek_io import ASCII_TERMINAL
from ladderworks.core.plc.plc_status import PlcSnapshot
from ladderworks.core.plc.runner import ScanStats, stats_of
from ladderworks.core.plc.scan_process import (
    FRAME,
    FRAME_AT,
    HEADER,
    REQUEST,
    REQUEST_AT,
    SharedLayout,
    buffer,
    serve,
)
from ladderworks.core.plc.scan_state import ScanLock, ScanState, TraceSpec

FRESH_SCANS = 8  # a monitored snapshot's frame is at most this many scans old (64 ms at 8 ms)
ASK_SCANS = 4  # a snapshot asks for a new frame once the last is this many scans old
START_TIMEOUT_S = 120.0  # a program's build in the process (S41_F036: about 2 s)


class ScanProcessError(RuntimeError):
    """The scan process could not build or run a program (the IDE then scans itself)."""


class ScanProcess:
    """A process that scans: spawned once, sent each program, run and stopped on demand."""

    def __init__(self) -> None:
        context = multiprocessing.get_context("spawn")
        self.layout = SharedLayout.make()
        self.block = SharedMemory(create=True, size=self.layout.size)
        self.views = self.layout.views(buffer(self.block))
        self.frame_views = self.layout.views(buffer(self.block), frame=True)
        self._wanted = 0  # the last frame asked for
        self.lock = context.RLock()
        child_commands, self._commands = context.Pipe(duplex=False)
        self._outputs, child_outputs = context.Pipe(duplex=False)
        self.process = context.Process(
            target=serve, name="ladderworks-scan", daemon=True,
            args=(child_commands, child_outputs, self.lock, self.block.name))
        with _main_not_imported():
            self.process.start()
        child_commands.close()
        child_outputs.close()
        self._replies: queue.Queue[tuple[Any, ...]] = queue.Queue()
        # what a scan made besides memory: (alarm changes, trace ident, samples, texts)
        self.on_output: Callable[[list[tuple[int, bytes]], int, list[Any], list[str]],
                                 None] | None = None
        self._flow: SharedMemory | None = None
        self._old_flows: list[SharedMemory] = []
        self._ident = 0
        self.built: object = None  # the engine whose program the process has (or builds)
        self._ready: tuple[int, str] | None = None
        self._reader = threading.Thread(target=self._read, name="scan-process-reader",
                                        daemon=True)
        self._reader.start()

    @property
    def alive(self) -> bool:
        """True while the process runs."""
        return self.process.is_alive()

    def _read(self) -> None:
        while True:
            try:
                message = self._outputs.recv()
            except (EOFError, OSError):
                self._replies.put(("gone",))
                return
            if message[0] == "out":
                if self.on_output is not None:
                    self.on_output(*message[1:])
            else:
                self._replies.put(message)

    def _reply(self, kinds: tuple[str, ...]) -> tuple[Any, ...]:
        while True:
            try:
                message = self._replies.get(timeout=START_TIMEOUT_S)
            except queue.Empty as error:
                raise ScanProcessError("the scan process does not answer") from error
            if message[0] == "gone":
                raise ScanProcessError("the scan process has ended")
            if message[0] in kinds:
                return message

    def build(self, engine: ScanEngine, data: bytes | None,
              files: dict[Any, Any]) -> None:
        """Send the process `engine`'s program to build (it answers when ready)."""
        if data is None:
            data = encode(engine.program.ops, engine.program.dialect)
        self._ident += 1
        if self._flow is not None:
            self._old_flows.append(self._flow)
        self._flow = SharedMemory(create=True, size=max(1, len(engine.program.ops)))
        self._ready = None
        self.built = engine
        self._commands.send(("build", self._ident, data, engine.period_ms, engine.divisions,
                             dict(files), self._flow.name))

    def wait_ready(self) -> None:
        """Wait until the last program sent is built; ScanProcessError if it was not."""
        while self._ready is None or self._ready[0] != self._ident:
            message = self._reply(("ready",))
            self._ready = (message[1], message[2])
        for old in self._old_flows:
            _free(old)
        self._old_flows.clear()
        if self._ready[1]:
            raise ScanProcessError(self._ready[1])

    def is_ready(self) -> bool:
        """True when the last program sent is built, without waiting; ScanProcessError if its
        build failed or the process has ended."""
        while self._ready is None or self._ready[0] != self._ident:
            try:
                message = self._replies.get_nowait()
            except queue.Empty:
                return False
            if message[0] == "gone":
                raise ScanProcessError("the scan process has ended")
            if message[0] == "ready":
                self._ready = (message[1], message[2])
        self.wait_ready()  # at once now: frees the old flow blocks, raises a build's error
        return True

    def flow(self, count: int) -> memoryview:
        """The power flow of the last monitored scan, `count` ops (a view: copy it)."""
        assert self._flow is not None
        return buffer(self._flow)[:count]

    def run(self, state: ScanState, setup: Any) -> None:
        """Start scanning from `state` with `setup`."""
        self._commands.send(("run", state, setup))

    def send(self, *message: Any) -> None:
        """A message for the running scan ("setup", "reset"); lost if the process is gone."""
        with contextlib.suppress(OSError):
            self._commands.send(message)

    def stop(self) -> tuple[ScanState, TraceSpec | None]:
        """Stop scanning; the engine's state and the trace's position the last scan left."""
        try:
            self._commands.send(("stop",))
        except OSError as error:
            raise ScanProcessError("the scan process has ended") from error
        message = self._reply(("stopped",))
        return message[1], message[2]

    def ask_frame(self, first: bool = False) -> None:
        """Ask for the power flow and memory of the next scan (`first`: a new run's first)."""
        block = buffer(self.block)
        if first:
            self._wanted = 0
            FRAME.pack_into(block, FRAME_AT, 0, 0, 0)
        self._wanted += 1
        REQUEST.pack_into(block, REQUEST_AT, self._wanted)

    def fresh_frame(self, within: int, timeout_s: float = 0.05) -> None:
        """Wait (without the lock) until the last frame is at most `within` scans old,
        asking for one if none is asked for; gives up after `timeout_s`."""
        block = buffer(self.block)
        end = time.perf_counter() + timeout_s
        while True:
            served, scan_count = FRAME.unpack_from(block, FRAME_AT)[:2]
            if served and HEADER.unpack_from(block, 0)[0] - scan_count <= within:
                return
            if served == self._wanted:
                self.ask_frame()
            if time.perf_counter() > end or not self.alive:
                return
            time.sleep(0.001)

    def frame(self, ops: int) -> tuple[int, int, dict[Any, bytes], bytes] | None:
        """The last frame (scan count, clock, memory, power flow), under the lock; None if no
        scan has answered a request yet."""
        served, scan_count, now_ms = FRAME.unpack_from(buffer(self.block), FRAME_AT)
        if not served:
            return None
        flow = self.flow(ops)
        frame = (scan_count, now_ms, {area: bytes(view)
                                      for area, view in self.frame_views.items()}, bytes(flow))
        flow.release()
        return frame

    def header(self) -> tuple[Any, ...]:
        """The shared header: scan count, clock, next start, scanning, then the figures."""
        return HEADER.unpack_from(buffer(self.block), 0)

    def close(self) -> None:
        """End the process and free the shared memory."""
        if self.process.is_alive():
            with contextlib.suppress(OSError):
                self._commands.send(("quit",))
            self.process.join(5)
            if self.process.is_alive():
                self.process.kill()
                self.process.join(5)
        self._commands.close()
        self.views.clear()
        self.frame_views.clear()
        for block in (*self._old_flows, self._flow, self.block):
            if block is not None:
                _free(block)
        self._old_flows.clear()
        self._flow = None


@contextmanager
def _main_not_imported() -> Iterator[None]:
    """Spawn without the IDE's main module: a spawned process imports it first (by path or
    by name), which starts the IDE again from a script with no `__main__` guard. The scan
    process needs only its target's module."""
    main = sys.modules["__main__"]
    saved: dict[str, Any] = {name: main.__dict__[name] for name in ("__file__", "__spec__")
             if name in main.__dict__}
    main.__dict__.pop("__file__", None)
    main.__dict__["__spec__"] = None
    try:
        yield
    finally:
        main.__dict__.pop("__spec__", None)
        main.__dict__.update(saved)


def _free(block: SharedMemory) -> None:
    """Close and remove a shared block (a view still held keeps its memory until dropped)."""
    with contextlib.suppress(BufferError):
        block.close()
    with contextlib.suppress(FileNotFoundError):
        block.unlink()


class ProcessSlot:
    """The scan process of one PLC run: spawned when first needed, kept for the next loads and
    starts, replaced when it has ended, closed with the run (or when the run is collected)."""

    def __init__(self) -> None:
        self.process: ScanProcess | None = None
        self._closer: weakref.finalize | None = None

    def build(self, engine: ScanEngine, data: bytes | None, files: dict[Any, Any]) -> None:
        """A program loaded: the process, if there is one, builds it in the background."""
        if self.process is not None and self.process.alive:
            self.process.build(engine, data, files)

    def send_files(self, files: dict[Any, Any]) -> None:
        """The ASCII files changed: the process's FUN 94 sends these from now."""
        if self.process is not None and self.process.alive:
            self.process.send("files", dict(files))

    def runner(self, owner: object, engine: ScanEngine, data: bytes | None,
               files: dict[Any, Any], lock: ScanLock, wait: bool) -> ProcessRunner | None:
        """A runner for `engine` in the process (spawned and built as needed); not `wait`ing,
        None while the build goes on. OSError or ScanProcessError if it cannot be had."""
        if self.process is not None and not self.process.alive:
            self.close()
        if self.process is None:
            self.process = ScanProcess()
            self._closer = weakref.finalize(owner, self.process.close)  # ends with the run
        if self.process.built is not engine:
            self.process.build(engine, data, files)
        if wait:
            self.process.wait_ready()
        elif not self.process.is_ready():
            return None
        return ProcessRunner(engine, self.process, lock)

    def close(self) -> None:
        """End the process (once)."""
        if self._closer is not None:
            self._closer()
        self.process = self._closer = None


class ProcessRunner:
    """Scans `engine`'s program in `process` every period of wall-clock time until `stop()`
    (RealTimeRunner's face: its figures, overruns and due time come from the process)."""

    def __init__(self, engine: ScanEngine, process: ScanProcess, lock: ScanLock) -> None:
        self.engine, self.process, self.lock = engine, process, lock
        self._saved: dict[Any, bytearray] = {}
        self._running = False
        self.error = ""  # why the last stop could not bring the state back

    @property
    def running(self) -> bool:
        """True while the process scans."""
        return self._running

    @property
    def lost(self) -> bool:
        """True when the process ended while scanning (killed, out of memory)."""
        return self._running and not self.process.alive

    def start(self) -> None:
        """Move memory and state into the process and start scanning there."""
        if self._running:
            return
        engine, memory = self.engine, self.engine.memory
        self.process.on_output = self._output
        with self.lock:
            for area, view in self.process.views.items():
                data = memory.areas[area]
                view[:] = data
                self._saved[area] = data
                memory.areas[area] = view  # type: ignore[assignment]
            engine.force_table.forget_memory()
            engine.parked = True
            self.lock.shared = self.process.lock
            self.process.ask_frame(first=True)
            self.process.run(engine.export_state(), engine.setup())
        self._running = True

    def send_setup(self) -> None:
        """The engine's setup changed: the process takes it before its next scan."""
        if self._running:
            self.process.send("setup", self.engine.setup())

    def stop(self, safe: bool = True) -> None:
        """Stop scanning and bring memory and state back (`safe`: every Y = 0)."""
        if not self._running:
            return
        self._running = False
        try:
            state, trace = self.process.stop()
        except ScanProcessError as error:  # gone: memory is its last scan's, states lost
            state, trace, self.error = None, None, str(error)
            self.lock.shared = None  # it may have ended holding its lock
        engine, memory = self.engine, self.engine.memory
        with self.lock:
            for area, data in self._saved.items():
                data[:] = memory.areas[area]
                memory.areas[area] = data
            self._saved.clear()
            engine.force_table.forget_memory()
            engine.parked = False
            if state is not None:
                engine.import_state(state)
                flow = self.process.flow(len(engine.program.ops))
                engine.adopt_clock(state.scan_count, state.now_ms, flow)
                flow.release()
            if trace is not None and engine.trace is not None and \
                    engine.trace.ident == trace.ident:
                engine.trace.go_on(trace.next_ms, trace.seq)
            self.lock.shared = None
        self.process.on_output = None
        if safe:
            engine.stop()

    def sync(self) -> None:
        """The IDE's engine takes the last scan's count and clock (under the lock)."""
        if self._running:
            self.engine.scan_count, self.engine.now_ms = self.process.header()[:2]

    def snapshot(self) -> PlcSnapshot:
        """Memory and power flow between two scans. Monitored, the last frame's: the process
        records the power flow only of a scan asked for (the others run the faster variant);
        this asks for the next one once the last is `ASK_SCANS` old (several views' snapshots
        of one moment share a frame), and waits for one when the last is older than
        `FRESH_SCANS`."""
        engine = self.engine
        if engine.monitored and self._running:
            self.process.fresh_frame(FRESH_SCANS)
        with self.lock:
            self.sync()
            disabled = engine.force_table.disabled
            if engine.monitored and self._running:
                frame = self.process.frame(len(engine.program.ops))
                if frame is None or engine.scan_count - frame[0] >= ASK_SCANS:
                    self.process.ask_frame()
                if frame is not None:
                    return PlcSnapshot(*frame, True, disabled, engine.memory.byteorder)
            return PlcSnapshot(engine.scan_count, engine.now_ms, engine.memory.snapshot(),
                               bytes(engine.power_flow), engine.monitored, disabled,
                               engine.memory.byteorder)

    def _output(self, alarms: list[tuple[int, bytes]], ident: int, samples: list[Any],
                texts: list[str]) -> None:
        engine = self.engine
        with self.lock.local:  # the IDE's own: the scan process need not wait for this
            if alarms:
                engine.alarm_log.extend(alarms)
                engine.alarm_changes += len(alarms)
            if samples and engine.trace is not None and engine.trace.ident == ident:
                engine.trace.extend(samples)
            terminal = engine.extra.get(ASCII_TERMINAL)
            for text in texts:
                if terminal is not None:
                    terminal.write(text)

    def due_in(self) -> float:
        """Seconds until the process's next scan: 0 while one runs or is late."""
        _count, _now, next_start, scanning = self.process.header()[:4]
        if scanning:
            return 0.0
        return max(0.0, next_start - time.perf_counter())

    def stats(self) -> ScanStats:
        """The process's scan figures so far."""
        return stats_of(*self.process.header()[4:])

    def reset_stats(self) -> None:
        """Start the figures afresh."""
        self.process.send("reset")
