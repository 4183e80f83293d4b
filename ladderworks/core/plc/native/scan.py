"""The native scan at run time: the compiled code called on the engine's own memory (the areas'
bytearrays, by address: no copies), with the engine's call-site states."""

from __future__ import annotations

import ctypes
from collections.abc import Collection
from typing import Any

from ladderworks.core.address import Area
from ladderworks.core.compiler.binary import Op
from ladderworks.core.compiler.checks import implementation_of
from ladderworks.core.plc.codegen_plan import JumpToMain, loop_stop
from ladderworks.core.plc.functions import FunctionImpl
from ladderworks.core.plc.native import layout, state_block
from ladderworks.core.plc.native.helpers import Grown, buffers, grow, move, put
from ladderworks.core.plc.native.ir_text import AREA_ORDER
from ladderworks.core.plc.native.jit import Compiled, compiled_scan

_ENTRY = ctypes.CFUNCTYPE(ctypes.c_int32, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p,
                          ctypes.c_void_p, ctypes.c_int32)
_CALLBACK = ctypes.CFUNCTYPE(ctypes.c_int32, ctypes.c_int32, ctypes.c_int32)
_INPUTS = [[tuple((bits >> k) & 1 for k in range(n)) for bits in range(1 << n)]
           for n in range(9)]


class NativeScan:
    """A compiled variant with the interface of GeneratedScan: `scan(ctx, M, full)`, the
    call sites' `states`, the power flow (`flow_into`), `source` (the IR)."""

    def __init__(self, compiled: Compiled, from_cache: bool, ops: tuple[Op, ...],
                 areas: dict[Area, bytearray], registry: dict[str, FunctionImpl],
                 states: list[dict[str, Any]]) -> None:
        program = compiled.program
        self.compiled = compiled
        self.from_cache = from_cache
        self.source = program.text
        self.count = len(ops)
        self.blocks = ()
        self._entry = _ENTRY(compiled.address)
        self._words = (ctypes.c_int32 * max(1, program.layout.words))()
        self._flow = bytearray(max(1, len(ops)))
        self._flow_view = (ctypes.c_char * len(self._flow)).from_buffer(self._flow)
        self._areas = areas
        self._bound: tuple[object, ...] = ()
        self._bases = (ctypes.c_void_p * len(AREA_ORDER))()
        self._views: list[ctypes.Array[ctypes.c_char]] = []
        self._bind()
        while len(states) < len(ops):
            states.append({})
        self.states = tuple(states[index] for index in program.calls)
        self._sites: list[tuple[FunctionImpl, dict[str, Any], tuple, list[tuple[int, ...]]]] = []
        for site, inputs in program.callbacks:
            index = program.calls[site]
            impl = implementation_of(ops[index].spec, registry)
            assert impl is not None
            self._sites.append((impl, self.states[site], ops[index].params, _INPUTS[inputs]))
        self.callbacks = [ops[program.calls[site]].spec.name for site, _ in program.callbacks]
        self._callback = _CALLBACK(self._call)
        self._ctx: Any = None
        self._error: BaseException | None = None
        self._loop = loop_stop(ops, program.units)
        self._labels = program.labels
        self._edge_keys = list(enumerate(program.edges, program.layout.edge_base))
        self._blocks = [(self.states[site], base) for site, base in program.blocks]
        self._block_of: dict[int, int] | None = None  # a block's base by id() of its dict
        self._dirty = program.layout.dirty
        self._marks = program.layout.marks
        places = program.layout
        self._first_block = places.block_base
        # the edge memories and state blocks: the state the skipper compares (skip_state)
        self._state_at = 4 * places.edge_base
        self._state_end = 4 * (places.block_base + state_block.BLOCK * places.stateful)
        words = self._words
        self._now, self._scan_ms, self._wake = (ctypes.c_int64.from_buffer(words, 4 * word)
                                                for word in (layout.NOW, layout.SCAN_MS,
                                                             layout.WAKE))
        self.stale = True  # the edge memories are to be read from `ctx.edges` before a scan
        self._unsynced = False  # scans changed state words not yet in the dicts (`sync`)
        self._grow_buffers: tuple[Any, Any] | None = None  # the skipper's (skip_growth)

    def _bind(self) -> None:
        """Take the areas' addresses (again when a buffer was replaced)."""
        buffers = tuple(self._areas[area] for area in AREA_ORDER)
        views = [(ctypes.c_char * len(data)).from_buffer(data) for data in buffers]
        for k, view in enumerate(views):
            self._bases[k] = ctypes.addressof(view)
        self._views = views  # they pin the buffers: an area cannot be resized under the code
        self._bound = buffers

    def _call(self, number: int, bits: int) -> int:
        try:
            impl, state, params, inputs = self._sites[number]
            return 1 if impl(self._ctx, state, inputs[bits], params) else 0  # type: ignore[arg-type]
        except BaseException as error:  # re-raised by scan() once the native code returned
            self._error = error
            self._words[layout.ABORT] = layout.FAILED
            return 2

    def scan(self, ctx: Any, M: object = None, full: bool = True) -> None:
        """One run of the program (level 1, and levels 2 and 3 when `full`)."""
        areas = self._areas
        bound = self._bound
        for k, area in enumerate(AREA_ORDER):
            if areas[area] is not bound[k]:
                self._bind()
                break
        self._ctx = ctx
        words = self._words
        if self.stale:
            self.stale = False
            edges = ctx.edges
            for word, key in self._edge_keys:
                words[word] = (2 | bool(edges[key])) if key in edges else 0
            for state, base in self._blocks:
                state_block.push(words, base, state)
            marks = self._marks
            for k in range(marks - len(self._edge_keys), marks + len(self._blocks)):
                words[k] = 0
            words[layout.DIRTY] = 0
        blocks = self._blocks
        if blocks:
            self._now.value = ctx.now_ms
            self._scan_ms.value = ctx.scan_ms
            self._wake.value = ctx.wake_ms
        code = self._entry(self._bases, words, self._flow_view, self._callback,
                           1 if full else 0)
        self._unsynced = self._unsynced or words[layout.DIRTY] > 0
        if blocks and self._wake.value < ctx.wake_ms:  # a call-back's timer may say earlier
            ctx.wake_ms = self._wake.value
        if code:
            self._raise(code)

    def _raise(self, code: int) -> None:
        words = self._words
        if code == layout.JUMP_MAIN:
            raise JumpToMain(words[layout.JUMP_LABEL])
        if code == layout.LOOPED:
            unit = words[layout.LOOP_UNIT]
            self._loop(unit, words[layout.LOOP_CHUNK], self._labels[unit])
        error, self._error = self._error, None
        if error is not None:
            raise error
        raise RuntimeError(f"native scan stopped with code {code}")

    def flow(self) -> bytes:
        return bytes(self._flow[:self.count])

    def flow_into(self, out: bytearray) -> None:
        out[:] = self._flow[:len(out)]

    def clear_flow(self) -> None:
        self._flow[:] = bytes(len(self._flow))

    def share_words(self, others: list[Any]) -> None:
        """Use the state words of another variant of the same layout (fast and monitored):
        switching between them then moves no state through the dicts."""
        program = self.compiled.program
        for other in others:
            if isinstance(other, NativeScan) and other is not self and \
                    other.compiled.program.layout == program.layout and \
                    other.compiled.program.blocks == program.blocks and \
                    other.compiled.program.edges == program.edges:
                self._words = other._words
                self._now, self._scan_ms, self._wake = other._now, other._scan_ms, other._wake
                return

    def adopt(self, previous: Any) -> None:
        """Go on from the states `previous` (the variant run before) left."""
        if previous is self:
            return
        if isinstance(previous, NativeScan) and previous._words is self._words:
            self.stale, self._unsynced = previous.stale, previous._unsynced
            self._ctx = previous._ctx
            return
        previous.sync()
        self.states_changed()

    def states_changed(self, moved: list[dict[str, Any]] | None = None) -> None:
        """The call sites' states or edge memories were changed outside a scan (what the
        scans changed since the last `sync` is dropped: the dicts now say). `moved`: only
        these call sites' states changed, right after a `sync` (the skipper moved their
        timers on): their blocks are written now, rather than every block and edge memory
        before the next scan."""
        self._unsynced = False
        if moved is None:
            self.stale = True
            return
        if self._block_of is None:
            self._block_of = {id(state): base for state, base in self._blocks}
        words, block_of = self._words, self._block_of
        for state in moved:
            base = block_of.get(id(state))
            if base is not None:  # else a call-back's state: read from its dict
                state_block.push(words, base, state)

    # -- the skipper's view (core/plc/skipping.py): the state words rather than the dicts ---

    def callback_states(self) -> tuple[dict[str, Any], ...]:
        """The states that live in their dicts while scans run (the call-backs' sites)."""
        return tuple(site[1] for site in self._sites)

    def skip_state(self) -> bytes:
        """The edge memories and state blocks as they stand: with memory and the call-backs'
        dicts, everything the next scan depends on."""
        return bytes(memoryview(self._words).cast("B")[self._state_at:self._state_end])

    def skip_growth(self, before: bytes, after: bytes) -> Grown | None:
        """What the time values (a timer's elapsed time, the scan a site last ran at) grew by
        from `before` to `after` (two `skip_state()`s), with the earliest wake of the timers
        that run; None when anything else differs (compared in native code)."""
        if self._grow_buffers is None:
            self._grow_buffers = buffers(len(self._blocks))
        return grow(before, after, len(self._edge_keys), len(self._blocks), self._grow_buffers)

    def skip_restore(self, state: bytes) -> None:
        """Put back the edge memories and state blocks a `skip_state()` gave; those that
        differed join the changed list (the next `sync` writes their dicts)."""
        put(self._words, state, len(self._edge_keys), len(self._blocks),
            self._state_at // 4, self._marks, self._dirty)
        self._unsynced = True

    def skip_move(self, growth: Grown, times: int) -> None:
        """Move the time values on by `times` times their growth (the skipped scans'), the
        blocks then in the changed list (the dicts get them at the next `sync`)."""
        if growth:
            move(self._words, growth, times, self._first_block, self._marks, self._dirty)
            self._unsynced = True

    def sync(self) -> None:
        """Write the call sites' states and the edge memories the scans changed since the last
        sync into their dicts (`ctx.edges`): the dicts are then the Python scan's."""
        if not self._unsynced or self._ctx is None:
            return
        self._unsynced = False
        words = self._words
        edges = self._ctx.edges
        changed = words[layout.DIRTY]
        blocks, dirty, edge_keys, marks = self._blocks, self._dirty, self._edge_keys, self._marks
        for k in range(changed):
            entry = words[dirty + k]
            words[marks + entry] = 0
            if entry >= 0:
                state, base = blocks[entry]
                state_block.pull(words, base, state)
            else:  # (an edge memory put back by a skip may be one not yet kept)
                word, key = edge_keys[-1 - entry]
                if words[word]:
                    edges[key] = bool(words[word] & 1)
                else:
                    edges.pop(key, None)
        words[layout.DIRTY] = 0


def native_variant(ops: tuple[Op, ...], dialect: str, areas: dict[Area, bytearray],
                   registry: dict[str, FunctionImpl], states: list[dict[str, Any]], *,
                   disabled: Collection[int] = (), monitored: bool = False) -> NativeScan:
    """The native scan of `ops` over `areas` and `states` (compiled, or from the cache)."""
    compiled, cached = compiled_scan(ops, dialect, registry, disabled, monitored)
    return NativeScan(compiled, cached, ops, areas, registry, states)
