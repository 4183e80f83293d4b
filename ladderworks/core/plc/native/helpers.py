"""Small native functions every program shares, compiled once per process: the skipper's
comparison of two copies of the state words (`differing`)."""

from __future__ import annotations

import ctypes
import threading
from typing import Any

# the 32-bit words at which two buffers of n words differ, written to `out`; their count
_DIFF = """
define i32 @differ(ptr %a, ptr %b, ptr %out, i32 %n) {
entry:
  br label %loop
loop:
  %i = phi i32 [0, %entry], [%i1, %next]
  %c = phi i32 [0, %entry], [%c1, %next]
  %done = icmp eq i32 %i, %n
  br i1 %done, label %exit, label %body
body:
  %pa = getelementptr i32, ptr %a, i32 %i
  %pb = getelementptr i32, ptr %b, i32 %i
  %va = load i32, ptr %pa, align 1
  %vb = load i32, ptr %pb, align 1
  %ne = icmp ne i32 %va, %vb
  br i1 %ne, label %keep, label %next
keep:
  %po = getelementptr i32, ptr %out, i32 %c
  store i32 %i, ptr %po
  %ck = add i32 %c, 1
  br label %next
next:
  %c1 = phi i32 [%c, %body], [%ck, %keep]
  %i1 = add i32 %i, 1
  br label %loop
exit:
  ret i32 %c
}
"""
_TYPE = ctypes.CFUNCTYPE(ctypes.c_int32, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_void_p,
                         ctypes.c_int32)
_lock = threading.Lock()
_made: list[Any] = []  # the engine and the function, once compiled
_out: dict[int, Any] = {}  # an output buffer by its length in words


def differing(before: bytes, after: bytes) -> list[int]:
    """The indexes of the 32-bit words at which two equally long buffers differ."""
    if before == after:
        return []
    words = len(after) // 4
    with _lock:
        if not _made:
            from ladderworks.core.plc.native.jit import compile_ir

            engine, address, _ir, _llvm = compile_ir([_DIFF], entry="differ")
            _made.extend((engine, _TYPE(address)))
        out = _out.get(words)
        if out is None:
            out = _out[words] = (ctypes.c_int32 * words)()
        count = _made[1](before, after, out, words)
        return out[:count]
