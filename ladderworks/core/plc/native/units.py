"""The native scan's frame functions: a unit's function `U<n>` (its chunks in order, or a
dispatch loop over them when it has labels) and the monitored scan's power-flow reset."""

from __future__ import annotations

from ladderworks.core.address import Area
from ladderworks.core.compiler.structure import LOOP_LIMIT, Unit
from ladderworks.core.plc.native import layout
from ladderworks.core.plc.native.ir_text import PASS, FunctionText
from ladderworks.core.plc.native.layout import Layout


def unit_function(number: int, unit: Unit, chunks: list[str], commons: range, jumps: bool,
                  labelled: bool, places: Layout, chunk_of_label: dict[int, int]) -> str:
    """The function `U<n>` of a unit: its JMP id and COM gates reset, then its chunks in
    order, or (with labels) a dispatch loop over them that counts backward jumps and catches
    a JMPC of its level."""
    f = FunctionText(f"U{number}", "void", slots=2 if labelled else 0)
    if jumps:
        f.store_word(places.jump_base + number, "0")
    for ident in commons:
        f.store_word(places.common_base + ident, "1")
    if not labelled:
        for name in chunks:
            result = f.value(f"call i32 @{name}({PASS})")
            stop = f.value(f"icmp slt i32 {result}, 0")
            go = f.label()
            f.add(f"br i1 {stop}, label %leave, label %{go}")
            f.start(go)
        f.add("br label %leave")
        f.start("leave")
        return f.finish([], "")
    # the dispatch loop: pc in %v0, backward jumps counted in %v1
    loop, body, done = f.label(), f.label(), "leave"
    f.add(f"br label %{loop}")
    f.start(loop)
    pc = f.get(0)
    more = f.value(f"icmp slt i32 {pc}, {len(chunks)}")
    f.add(f"br i1 {more}, label %{body}, label %{done}")
    f.start(body)
    cases = [f.label() for _ in chunks]
    joined = f.label()
    f.add(f"switch i32 {pc}, label %{done} [" +
          " ".join(f"i32 {k}, label %{case}" for k, case in enumerate(cases)) + "]")
    results = []
    for case, name in zip(cases, chunks, strict=True):
        f.start(case)
        results.append((f.value(f"call i32 @{name}({PASS})"), case))
        f.add(f"br label %{joined}")
    f.start(joined)
    nxt = f.value("phi i32 " + ", ".join(f"[{v}, %{c}]" for v, c in results))
    stop = f.value(f"icmp slt i32 {nxt}, 0")
    unwinding, going = f.label(), f.label()
    f.add(f"br i1 {stop}, label %{unwinding}, label %{going}")
    f.start(unwinding)
    if unit.level > 0 and chunk_of_label:
        state = f.load_word(layout.ABORT)
        is_jump = f.value(f"icmp eq i32 {state}, {layout.JUMP_MAIN}")
        catch = f.label()
        f.add(f"br i1 {is_jump}, label %{catch}, label %{done}")
        f.start(catch)
        label = f.load_word(layout.JUMP_LABEL)
        targets = [(lb, ch, f.label()) for lb, ch in sorted(chunk_of_label.items())]
        f.add(f"switch i32 {label}, label %{done} [" +
              " ".join(f"i32 {lb}, label %{blk}" for lb, _, blk in targets) + "]")
        for _, chunk, blk in targets:
            f.start(blk)
            f.store_word(layout.ABORT, "0")
            f.put(0, str(chunk))
            f.add(f"br label %{loop}")
    else:
        f.add(f"br label %{done}")
    f.start(going)
    back = f.value(f"icmp sle i32 {nxt}, {pc}")
    count, on = f.label(), f.label()
    f.add(f"br i1 {back}, label %{count}, label %{on}")
    f.start(count)
    n = f.value(f"add i32 {f.get(1)}, 1")
    f.put(1, n)
    over = f.value(f"icmp sgt i32 {n}, {LOOP_LIMIT}")
    stop_loop = f.label()
    f.add(f"br i1 {over}, label %{stop_loop}, label %{on}")
    f.start(stop_loop)
    f.store_word(layout.ABORT, str(layout.LOOPED))
    f.store_word(layout.LOOP_UNIT, str(number))
    f.store_word(layout.LOOP_CHUNK, nxt)
    f.add(f"br label %{done}")
    f.start(on)
    f.put(0, nxt)
    f.add(f"br label %{loop}")
    f.start(done)
    return f.finish([], "")


def flow_reset(f: FunctionText, level1: tuple[int, int] | None, count: int) -> None:
    """The monitored scan's first code: every op's power flow 0, or level 1's only in a scan
    that runs level 1 only (`%full` 0)."""
    if level1 is None:
        f.add(f"call void @llvm.memset.p0.i64(ptr %fl, i8 0, i64 {count}, i1 false)")
        return
    start, end = level1
    _, other = f.branch("%full", "i32")
    f.add(f"call void @llvm.memset.p0.i64(ptr %fl, i8 0, i64 {count}, i1 false)")
    done = f.label()
    f.add(f"br label %{done}")
    f.start(other)
    ptr = f.value(f"getelementptr i8, ptr %fl, i64 {start}")
    f.add(f"call void @llvm.memset.p0.i64(ptr {ptr}, i8 0, i64 {end - start}, i1 false)")
    f.join(done)


SYSTEM_RELAY = 9091  # R9091: bits 2-4 say which level runs
_LEVEL_BITS = {1: 4, 2: 8, 3: 16}


def scan_function(entries: dict[int, int], level1: tuple[int, int] | None,
                  monitored_ops: int) -> str:
    """The module's entry `scan(..., i32 %full)`: each level's unit (`entries`: level ->
    unit number) with R9091's level bits set, levels 2 and 3 only when `%full`; in the
    monitored scan (`monitored_ops` > 0) the power flow reset first."""
    f = FunctionText("scan")
    f.add(f"store i32 0, ptr {f.word_ptr(layout.ABORT)}")
    if monitored_ops:
        flow_reset(f, level1, monitored_ops)
    for level in sorted(entries):
        after = ""
        if level > 1:
            _, after = f.branch("%full", "i32")
        relay = f.byte_ptr(Area.R, SYSTEM_RELAY)
        old = f.value(f"load i8, ptr {relay}")
        new = f.value(f"and i8 {old}, 227")
        new = f.value(f"or i8 {new}, {_LEVEL_BITS.get(level, 0)}")
        f.add(f"store i8 {new}, ptr {relay}")
        f.add(f"call void @U{entries[level]}({PASS})")
        state = f.load_word(layout.ABORT)
        _, cont = f.branch(state, "i32")
        f.add(f"ret i32 {state}")
        f.start(cont)
        if after:
            f.join(after)
    relay = f.byte_ptr(Area.R, SYSTEM_RELAY)
    old = f.value(f"load i8, ptr {relay}")
    f.add(f"store i8 {f.value(f'and i8 {old}, 227')}, ptr {relay}")
    return f.finish([], "0", "i32 %full")
