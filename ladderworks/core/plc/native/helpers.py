"""Small native functions every program shares, compiled once per process: the skipper's
comparison of two copies of the state words (`grown`) and its moving on of the time values
it found growing (`move`)."""

from __future__ import annotations

import ctypes
import threading
from typing import Any

from ladderworks.core.plc.native import layout
from ladderworks.core.plc.native.state_block import (
    AT,
    BLOCK,
    ELAPSED,
    ELAPSED_SET,
    HAS_AT,
    HAS_MS,
    HAS_VALUE,
)

# grow(before, after, edges, blocks, out): two copies of the edge memories (`edges` words)
# and the state blocks (`blocks` blocks of 8 words: flags, pad, elapsed, at, wake). -1 when
# an edge memory, a block's flags or wake differ, or a time value that is not one (an
# elapsed time not set, CTRB's value, an `at` the dict has not; Delta TMR's "ms" is one);
# else the count of blocks whose time values grew, each as three i64 in `out`: the block,
# elapsed's and at's growth.
_GROW = f"""
define i32 @grow(ptr %a, ptr %b, i32 %edges, i32 %blocks, ptr %out) {{
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
  %eset = and i32 %flags, {ELAPSED_SET | HAS_MS}
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
  br label %bnext
bnext:
  %c1 = phi i32 [%c, %check], [%ck, %keep]
  %k1 = add i32 %k, 1
  br label %bloop
done:
  ret i32 %c
fail:
  ret i32 -1
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
  %k = phi i32 [0, %entry], [%k1, %next]
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
  %pm = getelementptr i32, ptr %st, i32 %mi
  %m = load i32, ptr %pm
  %unmarked = icmp eq i32 %m, 0
  br i1 %unmarked, label %list, label %next
list:
  store i32 1, ptr %pm
  %pc = getelementptr i32, ptr %st, i32 {layout.DIRTY}
  %c = load i32, ptr %pc
  %di = add i32 %dirty, %c
  %pd = getelementptr i32, ptr %st, i32 %di
  store i32 %blk, ptr %pd
  %c1 = add i32 %c, 1
  store i32 %c1, ptr %pc
  br label %next
next:
  %k1 = add i32 %k, 1
  br label %loop
exit:
  ret void
}}
"""
_MOVE_TYPE = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int32,
                              ctypes.c_int64, ctypes.c_int32, ctypes.c_int32, ctypes.c_int32)
_TYPE = ctypes.CFUNCTYPE(ctypes.c_int32, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_int32,
                         ctypes.c_int32, ctypes.c_void_p)
_lock = threading.Lock()
_made: list[Any] = []  # the engine and the functions, once compiled
_out: dict[int, Any] = {}  # an output buffer by its number of blocks


def grown(before: bytes, after: bytes, edges: int, blocks: int
          ) -> list[tuple[int, int, int]] | None:
    """The blocks whose time values grew from `before` to `after` (two copies of `edges`
    edge words and `blocks` state blocks), as (block, elapsed's growth, at's growth); None
    when anything else differs."""
    with _lock:
        _make()
        out = _out.get(blocks)
        if out is None:
            out = _out[blocks] = (ctypes.c_int64 * (3 * max(1, blocks)))()
        count = _made[1](before, after, edges, blocks, out)
        if count < 0:
            return None
        values = out[:3 * count]
    return [(values[k], values[k + 1], values[k + 2]) for k in range(0, 3 * count, 3)]


def move(words: Any, growth: list[tuple[int, int, int]], times: int, first: int, marks: int,
         dirty: int) -> None:
    """Move the time values of the blocks in `growth` (`grown`'s) on by `times` times their
    growth in the state words `words` (blocks from word `first`), each block put in the
    changed list (`dirty`) unless its mark (`marks`) says it is there."""
    flat = (ctypes.c_int64 * (3 * len(growth)))(*(v for entry in growth for v in entry))
    with _lock:
        _make()
        _made[2](words, flat, len(growth), times, first, marks, dirty)


def _make() -> None:
    """Compile the helpers once (the lock held)."""
    if not _made:
        from ladderworks.core.plc.native.jit import compile_ir

        engine, address, _ir, _llvm = compile_ir([_GROW + _MOVE], entry="grow")
        _made.extend((engine, _TYPE(address), _MOVE_TYPE(engine.get_function_address("move"))))
