"""Small native functions every program shares, compiled once per process: the skipper's
comparison of two copies of the state words (`grow`), its moving on of the time values it
found growing (`move`) and its putting back of a copy (`put`, `Areas`)."""

from __future__ import annotations

import ctypes
import threading
from typing import Any

from ladderworks.core.plc.functions import NEVER
from ladderworks.core.plc.native import layout
from ladderworks.core.plc.native.state_block import (
    AT,
    BLOCK,
    ELAPSED,
    ELAPSED_SET,
    HAS_AT,
    HAS_VALUE,
    HAS_WAKE,
)

# grow(before, after, edges, blocks, out, wake): two copies of the edge memories (`edges`
# words) and the state blocks (`blocks` blocks of 8 words: flags, pad, elapsed, at, wake).
# -1 when an edge memory, a block's flags or wake differ, or a time value that is not one (an
# elapsed time not set, CTRB's value, an `at` the dict has not); else the count of blocks
# whose time values grew, each as three i64 in `out`: the block, elapsed's and at's growth.
# wake[0] becomes the earliest wake of a block whose elapsed time grew (left as it was when
# none did), wake[1] 1 when such a block has no wake.
_GROW = f"""
define i32 @grow(ptr %a, ptr %b, i32 %edges, i32 %blocks, ptr %out, ptr %wake) {{
entry:
  br label %eloop
eloop:
  %i = phi i32 [0, %entry], [%i1, %enext]
  %edone = icmp eq i32 %i, %edges
  br i1 %edone, label %bstart, label %ebody
ebody:
  %pa = getelementptr i32, ptr %a, i32 %i
  %pb = getelementptr i32, ptr %b, i32 %i
  %va = load i32, ptr %pa, align 1
  %vb = load i32, ptr %pb, align 1
  %ne = icmp ne i32 %va, %vb
  br i1 %ne, label %fail, label %enext
enext:
  %i1 = add i32 %i, 1
  br label %eloop
bstart:
  %ba = getelementptr i32, ptr %a, i32 %edges
  %bb = getelementptr i32, ptr %b, i32 %edges
  br label %bloop
bloop:
  %k = phi i32 [0, %bstart], [%k1, %bnext]
  %c = phi i32 [0, %bstart], [%c1, %bnext]
  %bdone = icmp eq i32 %k, %blocks
  br i1 %bdone, label %done, label %bbody
bbody:
  %w = mul i32 %k, 8
  %qa = getelementptr i32, ptr %ba, i32 %w
  %qb = getelementptr i32, ptr %bb, i32 %w
  %fa = load i64, ptr %qa, align 1
  %fb = load i64, ptr %qb, align 1
  %qa6 = getelementptr i32, ptr %qa, i32 6
  %qb6 = getelementptr i32, ptr %qb, i32 6
  %wa = load i64, ptr %qa6, align 1
  %wb = load i64, ptr %qb6, align 1
  %fne = icmp ne i64 %fa, %fb
  %wne = icmp ne i64 %wa, %wb
  %bad = or i1 %fne, %wne
  br i1 %bad, label %fail, label %times
times:
  %qa2 = getelementptr i32, ptr %qa, i32 2
  %qb2 = getelementptr i32, ptr %qb, i32 2
  %ea = load i64, ptr %qa2, align 1
  %eb = load i64, ptr %qb2, align 1
  %qa4 = getelementptr i32, ptr %qa, i32 4
  %qb4 = getelementptr i32, ptr %qb, i32 4
  %ta = load i64, ptr %qa4, align 1
  %tb = load i64, ptr %qb4, align 1
  %de = sub i64 %eb, %ea
  %da = sub i64 %tb, %ta
  %flags = trunc i64 %fb to i32
  %eset = and i32 %flags, {ELAPSED_SET}
  %hval = and i32 %flags, {HAS_VALUE}
  %hat = and i32 %flags, {HAS_AT}
  %eok1 = icmp ne i32 %eset, 0
  %eok2 = icmp eq i32 %hval, 0
  %eok = and i1 %eok1, %eok2
  %enot = xor i1 %eok, true
  %denz = icmp ne i64 %de, 0
  %ebad = and i1 %denz, %enot
  %aok = icmp ne i32 %hat, 0
  %anot = xor i1 %aok, true
  %danz = icmp ne i64 %da, 0
  %abad = and i1 %danz, %anot
  %anybad = or i1 %ebad, %abad
  br i1 %anybad, label %fail, label %check
check:
  %grew = or i1 %denz, %danz
  br i1 %grew, label %keep, label %bnext
keep:
  %o = mul i32 %c, 3
  %po0 = getelementptr i64, ptr %out, i32 %o
  %k64 = sext i32 %k to i64
  store i64 %k64, ptr %po0
  %po1 = getelementptr i64, ptr %po0, i32 1
  store i64 %de, ptr %po1
  %po2 = getelementptr i64, ptr %po0, i32 2
  store i64 %da, ptr %po2
  %ck = add i32 %c, 1
  br i1 %denz, label %timed, label %bnext
timed:
  %hwake = and i32 %flags, {HAS_WAKE}
  %haswake = icmp ne i32 %hwake, 0
  br i1 %haswake, label %early, label %nowake
early:
  %least = load i64, ptr %wake
  %sooner = icmp slt i64 %wb, %least
  %lesser = select i1 %sooner, i64 %wb, i64 %least
  store i64 %lesser, ptr %wake
  br label %bnext
nowake:
  %pw1 = getelementptr i64, ptr %wake, i32 1
  store i64 1, ptr %pw1
  br label %bnext
bnext:
  %c1 = phi i32 [%c, %check], [%ck, %keep], [%ck, %early], [%ck, %nowake]
  %k1 = add i32 %k, 1
  br label %bloop
done:
  ret i32 %c
fail:
  ret i32 -1
}}
"""
# listed(words, mark word, entry, changed list): an edge memory (entry -1 - n) or a block
# (entry k) joins the changed list once: unless its mark word says it is there, the mark is
# set and the entry written at the list's end
_LISTED = f"""
define private void @listed(ptr %st, i32 %mark, i32 %item, i32 %dirty) {{
entry:
  %pm = getelementptr i32, ptr %st, i32 %mark
  %m = load i32, ptr %pm
  %unmarked = icmp eq i32 %m, 0
  br i1 %unmarked, label %list, label %done
list:
  store i32 1, ptr %pm
  %pc = getelementptr i32, ptr %st, i32 {layout.DIRTY}
  %c = load i32, ptr %pc
  %di = add i32 %dirty, %c
  %pd = getelementptr i32, ptr %st, i32 %di
  store i32 %item, ptr %pd
  %c1 = add i32 %c, 1
  store i32 %c1, ptr %pc
  br label %done
done:
  ret void
}}
"""
# move(words, growth, count, times, first block, marks, changed list): each block's time
# values grown `times` times their growth (`grow`'s triples), the block in the changed list
_MOVE = f"""
define void @move(ptr %st, ptr %g, i32 %count, i64 %times, i32 %first, i32 %marks,
                  i32 %dirty) {{
entry:
  br label %loop
loop:
  %k = phi i32 [0, %entry], [%k1, %body]
  %fin = icmp eq i32 %k, %count
  br i1 %fin, label %exit, label %body
body:
  %o = mul i32 %k, 3
  %p0 = getelementptr i64, ptr %g, i32 %o
  %b64 = load i64, ptr %p0
  %blk = trunc i64 %b64 to i32
  %p1 = getelementptr i64, ptr %p0, i32 1
  %de = load i64, ptr %p1
  %p2 = getelementptr i64, ptr %p0, i32 2
  %da = load i64, ptr %p2
  %w = mul i32 %blk, {BLOCK}
  %base = add i32 %first, %w
  %we = add i32 %base, {ELAPSED}
  %pe = getelementptr i32, ptr %st, i32 %we
  %e = load i64, ptr %pe, align 4
  %ge = mul i64 %de, %times
  %e2 = add i64 %e, %ge
  store i64 %e2, ptr %pe, align 4
  %wa = add i32 %base, {AT}
  %pa = getelementptr i32, ptr %st, i32 %wa
  %a = load i64, ptr %pa, align 4
  %ga = mul i64 %da, %times
  %a2 = add i64 %a, %ga
  store i64 %a2, ptr %pa, align 4
  %mi = add i32 %marks, %blk
  call void @listed(ptr %st, i32 %mi, i32 %blk, i32 %dirty)
  %k1 = add i32 %k, 1
  br label %loop
exit:
  ret void
}}
"""
# put(words, state, edges, blocks, first edge word, marks, changed list): the edge memories
# and state blocks of `state` (a copy `grow` compares) put back into the state words; each
# edge memory or block that differed joins the changed list once
_PUT = f"""
define void @put(ptr %st, ptr %src, i32 %edges, i32 %blocks, i32 %first, i32 %marks,
                 i32 %dirty) {{
entry:
  br label %eloop
eloop:
  %n = phi i32 [0, %entry], [%n1, %enext]
  %edone = icmp eq i32 %n, %edges
  br i1 %edone, label %bstart, label %ebody
ebody:
  %wi = add i32 %first, %n
  %pw = getelementptr i32, ptr %st, i32 %wi
  %ps = getelementptr i32, ptr %src, i32 %n
  %vw = load i32, ptr %pw
  %vs = load i32, ptr %ps, align 1
  %ediff = icmp ne i32 %vw, %vs
  br i1 %ediff, label %ecopy, label %enext
ecopy:
  store i32 %vs, ptr %pw
  %emi = sub i32 %marks, 1
  %emi2 = sub i32 %emi, %n
  %entry_e = sub i32 -1, %n
  call void @listed(ptr %st, i32 %emi2, i32 %entry_e, i32 %dirty)
  br label %enext
enext:
  %n1 = add i32 %n, 1
  br label %eloop
bstart:
  %bfirst = add i32 %first, %edges
  br label %bloop
bloop:
  %k = phi i32 [0, %bstart], [%k1, %bnext]
  %bdone = icmp eq i32 %k, %blocks
  br i1 %bdone, label %exit, label %bbody
bbody:
  %w = mul i32 %k, {BLOCK}
  %bw = add i32 %bfirst, %w
  %bsw = add i32 %edges, %w
  %pb = getelementptr i32, ptr %st, i32 %bw
  %psb = getelementptr i32, ptr %src, i32 %bsw
  %b0 = load i64, ptr %pb, align 4
  %s0 = load i64, ptr %psb, align 1
  %pb1 = getelementptr i64, ptr %pb, i32 1
  %psb1 = getelementptr i64, ptr %psb, i32 1
  %b1 = load i64, ptr %pb1, align 4
  %s1 = load i64, ptr %psb1, align 1
  %pb2 = getelementptr i64, ptr %pb, i32 2
  %psb2 = getelementptr i64, ptr %psb, i32 2
  %b2 = load i64, ptr %pb2, align 4
  %s2 = load i64, ptr %psb2, align 1
  %pb3 = getelementptr i64, ptr %pb, i32 3
  %psb3 = getelementptr i64, ptr %psb, i32 3
  %b3 = load i64, ptr %pb3, align 4
  %s3 = load i64, ptr %psb3, align 1
  %d0 = icmp ne i64 %b0, %s0
  %d1 = icmp ne i64 %b1, %s1
  %d2 = icmp ne i64 %b2, %s2
  %d3 = icmp ne i64 %b3, %s3
  %d01 = or i1 %d0, %d1
  %d23 = or i1 %d2, %d3
  %bdiff = or i1 %d01, %d23
  br i1 %bdiff, label %bcopy, label %bnext
bcopy:
  store i64 %s0, ptr %pb, align 4
  store i64 %s1, ptr %pb1, align 4
  store i64 %s2, ptr %pb2, align 4
  store i64 %s3, ptr %pb3, align 4
  %bmi = add i32 %marks, %k
  call void @listed(ptr %st, i32 %bmi, i32 %k, i32 %dirty)
  br label %bnext
bnext:
  %k1 = add i32 %k, 1
  br label %bloop
exit:
  ret void
}}
"""
# areas(targets, sizes, count, source): `count` buffers (their addresses and sizes) written
# from one copy of them all, end to end
_AREAS = """
declare void @llvm.memcpy.p0.p0.i64(ptr, ptr, i64, i1)
define void @areas(ptr %dst, ptr %sizes, i32 %count, ptr %src) {
entry:
  br label %loop
loop:
  %k = phi i32 [0, %entry], [%k1, %body]
  %at = phi i64 [0, %entry], [%at1, %body]
  %done = icmp eq i32 %k, %count
  br i1 %done, label %exit, label %body
body:
  %pd = getelementptr ptr, ptr %dst, i32 %k
  %d = load ptr, ptr %pd
  %pn = getelementptr i64, ptr %sizes, i32 %k
  %n = load i64, ptr %pn
  %s = getelementptr i8, ptr %src, i64 %at
  call void @llvm.memcpy.p0.p0.i64(ptr %d, ptr %s, i64 %n, i1 false)
  %at1 = add i64 %at, %n
  %k1 = add i32 %k, 1
  br label %loop
exit:
  ret void
}
"""
_AREAS_TYPE = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int32,
                               ctypes.c_char_p)
_PUT_TYPE = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int32,
                             ctypes.c_int32, ctypes.c_int32, ctypes.c_int32, ctypes.c_int32)
_MOVE_TYPE = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int32,
                              ctypes.c_int64, ctypes.c_int32, ctypes.c_int32, ctypes.c_int32)
_TYPE = ctypes.CFUNCTYPE(ctypes.c_int32, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_int32,
                         ctypes.c_int32, ctypes.c_void_p, ctypes.c_void_p)
_lock = threading.Lock()
_made: list[Any] = []  # the engine and the functions, once compiled


class Grown:
    """What `grow` found: the triples (block, elapsed's growth, at's growth) in a native
    buffer, their count, and the earliest wake of a block whose elapsed time grows (None:
    one of them has no wake; NEVER: none grows)."""

    __slots__ = ("buffer", "count", "wake")

    def __init__(self, buffer: Any, count: int, wake: int | None) -> None:
        self.buffer, self.count, self.wake = buffer, count, wake

    def __bool__(self) -> bool:
        return self.count > 0

    def triples(self) -> list[tuple[int, int, int]]:
        values = self.buffer[:3 * self.count]
        return [(values[k], values[k + 1], values[k + 2]) for k in range(0, 3 * self.count, 3)]


def buffers(blocks: int) -> tuple[Any, Any]:
    """The buffers `grow` writes, for `blocks` state blocks (a caller may keep them)."""
    return (ctypes.c_int64 * (3 * max(1, blocks)))(), (ctypes.c_int64 * 2)()


def grow(before: bytes, after: bytes, edges: int, blocks: int,
         kept: tuple[Any, Any] | None = None) -> Grown | None:
    """The blocks whose time values grew from `before` to `after` (two copies of `edges`
    edge words and `blocks` state blocks), kept natively for `move` (in `kept`, `buffers`'
    for as long as the result is used, or in new ones); None when anything else differs."""
    out, wake = kept or buffers(blocks)
    wake[0], wake[1] = NEVER, 0
    with _lock:
        _make()
        count = _made[1](before, after, edges, blocks, out, wake)
    if count < 0:
        return None
    return Grown(out, count, None if wake[1] else wake[0])


def grown(before: bytes, after: bytes, edges: int, blocks: int
          ) -> list[tuple[int, int, int]] | None:
    """`grow`'s triples as a list."""
    found = grow(before, after, edges, blocks)
    return None if found is None else found.triples()


def move(words: Any, growth: list[tuple[int, int, int]] | Grown, times: int, first: int,
         marks: int, dirty: int) -> None:
    """Move the time values of the blocks in `growth` (`grow`'s, or its triples) on by
    `times` times their growth in the state words `words` (blocks from word `first`), each
    block put in the changed list (`dirty`) unless its mark (`marks`) says it is there."""
    if isinstance(growth, Grown):
        flat, count = growth.buffer, growth.count
    else:
        flat = (ctypes.c_int64 * (3 * len(growth)))(*(v for entry in growth for v in entry))
        count = len(growth)
    with _lock:
        _make()
        _made[2](words, flat, count, times, first, marks, dirty)


def put(words: Any, state: bytes, edges: int, blocks: int, first: int, marks: int,
        dirty: int) -> None:
    """Put the edge memories and state blocks of `state` (a copy of `edges` edge words from
    word `first`, then `blocks` state blocks) back into the state words `words`, each one
    that differed put in the changed list (`dirty`) unless its mark (`marks`) says it is."""
    with _lock:
        _make()
        _made[3](words, state, edges, blocks, first, marks, dirty)


class Areas:
    """Memory's areas, pinned (they cannot be resized while this lives), to be written from
    one copy of them all end to end (`put`)."""

    def __init__(self, areas: tuple[bytearray, ...]) -> None:
        self._views = [(ctypes.c_char * len(data)).from_buffer(data) for data in areas]
        self._targets = (ctypes.c_void_p * len(areas))(*map(ctypes.addressof, self._views))
        self._sizes = (ctypes.c_int64 * len(areas))(*map(len, areas))
        self.size = sum(map(len, areas))

    def put(self, state: bytes) -> None:
        """Write every area from `state` (`size` bytes)."""
        assert len(state) == self.size
        with _lock:
            _make()
            _made[4](self._targets, self._sizes, len(self._views), state)


def _make() -> None:
    """Compile the helpers once (the lock held)."""
    if not _made:
        from ladderworks.core.plc.native.jit import compile_ir

        engine, address, _ir, _llvm = compile_ir([_GROW + _LISTED + _MOVE + _PUT + _AREAS],
                                               entry="grow")
        _made.extend((engine, _TYPE(address), _MOVE_TYPE(engine.get_function_address("move")),
                      _PUT_TYPE(engine.get_function_address("put")),
                      _AREAS_TYPE(engine.get_function_address("areas"))))
