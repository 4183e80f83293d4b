"""Compiling the native scan's IR with llvmlite's MCJIT, and the compiled programs kept by the
hash of the binary (so a program loaded again, F9 of an unchanged program, a second engine or
a `-j` worker's next scenario, does not compile again)."""

from __future__ import annotations

import hashlib
import queue
import re
import struct
import threading
import time
from collections import OrderedDict
from collections.abc import Collection, Iterable
from dataclasses import dataclass
from typing import Any

from ladderworks.core.compiler.binary import Op
from ladderworks.core.plc.functions import FunctionImpl
from ladderworks.core.plc.native import disk_cache
from ladderworks.core.plc.native.generator import NativeProgram, generate_parts

# LLVM's code generator at level 0 (FastISel): for X22's 35k ops 1.5 s, against 12 s at level 1
# and 20 s at level 2 (SelectionDAG on the shared 2-core machine); the IR gets only the cheap
# passes (SROA for the dispatch loops' slots, CFG simplification): instcombine alone took 5 s.
CODEGEN_LEVEL = 0
PASSES = ("sroa", "simplify_cfg")
# the passes run on the functions with slots (a unit's dispatch loop) only: on the chunk
# functions they took 0.1-0.3 s of X22's cold compile and left the scan as fast (23 against
# 24 µs, one run); True runs them on every function (benchmarks/native_compile.py, "before")
CHUNK_PASSES = False
# LLVM's verifier on each module before code generation (0.05-0.08 s of X22's cold compile):
# the tests turn it on (tests/core/plc/conftest.py); the generator's IR is the same for a user
VERIFY = False
CACHED = 8  # compiled variants kept in memory
_SLOTTED = re.compile(r"^define \w+ @(\w+)\(.*\{\nentry:\n  %v0 = alloca", re.M)
_FUNCTIONS = re.compile(r"^define \w+ @(\w+)\(", re.M)
_lock = threading.Lock()
_cache: OrderedDict[tuple[str, bool, frozenset[int]], Compiled] = OrderedDict()
_ready: list[bool] = []


@dataclass
class Compiled:
    """A compiled scan: the execution engine that owns the code, the entry's address, the
    program's IR facts, and the seconds it took (IR, LLVM)."""

    engine: Any
    address: int
    program: NativeProgram
    ir_seconds: float
    llvm_seconds: float
    from_disk: bool = False  # loaded from the disk cache (no IR text then)


def _machine() -> Any:
    """A new target machine for the host (an execution engine owns and frees its own)."""
    import llvmlite.binding as llvm

    if not _ready:
        llvm.initialize_native_target()
        llvm.initialize_native_asmprinter()
        llvm.initialize_native_asmparser()
        _ready.append(True)
    target = llvm.Target.from_default_triple()
    return target.create_target_machine(opt=CODEGEN_LEVEL, jit=True)


def program_hash(ops: tuple[Op, ...], dialect: str) -> str:
    """The key of a binary: the SHA-256 of what its code depends on (each op's name, operand,
    parameters and network; the dialect), 0.15 s for X22 where encoding it took 0.4 s."""
    parts = [dialect]
    for op in ops:
        operand = op.operand
        where = f"{operand.area.value}{operand.byte}.{operand.bit}" if operand else ""
        parts.append(f"{op.name}|{where}|{op.params!s}|{op.source.network}")
    return hashlib.sha256("\n".join(parts).encode()).hexdigest()


def _object(machine: Any, text: str) -> bytes:
    """One module's IR compiled to object code (the units' functions get the passes)."""
    import llvmlite.binding as llvm

    module = llvm.parse_assembly(text)
    if VERIFY:
        module.verify()
    options = llvm.create_pipeline_tuning_options(speed_level=0)
    builder = llvm.create_pass_builder(machine, options)
    passes = llvm.create_new_function_pass_manager()
    for name in PASSES:
        getattr(passes, f"add_{name}_pass")()
    # by name, found in the text: a walk over the module's functions would take Python's
    # lock some 2,000 times from the thread making the IR (jit.compile_ir)
    names = _FUNCTIONS.findall(text) if CHUNK_PASSES else _SLOTTED.findall(text)
    for name in names:
        passes.run(module.get_function(name), builder)
    return bytes(machine.emit_object(module))


def compile_ir(parts: Iterable[str], keep: list[bytes] | None = None, entry: str = "scan"
               ) -> tuple[Any, int, float, float]:
    """JIT-compile the modules `parts` makes: each is parsed and compiled to object code on a
    worker thread while the next is made (llvmlite's calls release Python's lock, so LLVM
    works while Python writes IR), then the objects are linked in one execution engine;
    (engine, address of `scan`, seconds making the IR, seconds of LLVM's work). `keep` gets
    the object code (for the disk cache)."""
    machine = _machine()
    work: queue.Queue[str | None] = queue.Queue()
    objects: list[bytes] = []
    failed: list[BaseException] = []
    busy = [0.0]

    def compile_parts() -> None:
        while (text := work.get()) is not None:
            started = time.perf_counter()
            try:
                if not failed:
                    objects.append(_object(machine, text))
            except Exception as error:  # raised below, in the caller's thread
                failed.append(error)
            busy[0] += time.perf_counter() - started

    worker = threading.Thread(target=compile_parts, name="native-compile", daemon=True)
    worker.start()
    making = 0.0
    try:
        made = iter(parts)
        while True:
            started = time.perf_counter()
            text = next(made, None)
            making += time.perf_counter() - started
            if text is None:
                break
            work.put(text)
    finally:
        work.put(None)
        worker.join()
    if failed:
        raise failed[0]
    code = pack(objects)
    started = time.perf_counter()
    engine, address = load_object(code, entry)
    if keep is not None:
        keep.append(code)
    return engine, address, making, busy[0] + time.perf_counter() - started


def pack(objects: list[bytes]) -> bytes:
    """Object files as one stored blob: their count and sizes, then each."""
    head = struct.pack(f"<4sI{len(objects)}Q", b"LWNO", len(objects), *map(len, objects))
    return b"".join([head, *objects])


def unpack(code: bytes) -> list[bytes]:
    """The object files of a blob `pack` made."""
    magic, count = struct.unpack_from("<4sI", code)
    if magic != b"LWNO":
        raise ValueError("not a native scan's object code")
    sizes = struct.unpack_from(f"<{count}Q", code, 8)
    at, objects = 8 + 8 * count, []
    for size in sizes:
        objects.append(code[at:at + size])
        at += size
    if at != len(code):
        raise ValueError("the object code is cut short")
    return objects


def load_object(code: bytes, entry: str = "scan") -> tuple[Any, int]:
    """An execution engine running stored object code; (engine, address of `entry`)."""
    import llvmlite.binding as llvm

    engine = llvm.create_mcjit_compiler(llvm.parse_assembly(""), _machine())
    for part in unpack(code):
        engine.add_object_file(llvm.ObjectFileRef.from_data(part))
    engine.finalize_object()
    address = engine.get_function_address(entry)
    if not address:
        raise RuntimeError(f"the stored object has no {entry} function")
    return engine, address


def _host() -> tuple[str, str]:
    import llvmlite
    import llvmlite.binding as llvm

    _machine()
    return llvm.get_process_triple(), llvmlite.__version__


def compiled_scan(ops: tuple[Op, ...], dialect: str, registry: dict[str, FunctionImpl],
                  disabled: Collection[int], monitored: bool) -> tuple[Compiled, bool]:
    """The compiled variant of a program (from the cache when it holds it); (it, from cache)."""
    key = (program_hash(ops, dialect), monitored, frozenset(disabled))
    with _lock:
        found = _cache.get(key)
        if found is not None:
            _cache.move_to_end(key)
            return found, True
    name = disk_cache.file_key(key, *_host())
    stored = disk_cache.load(name)
    result: Compiled | None = None
    if stored is not None:
        started = time.perf_counter()
        try:
            engine, address = load_object(stored[0])
            result = Compiled(engine, address, stored[1], 0.0, time.perf_counter() - started,
                              from_disk=True)
        except Exception:  # a damaged file: compile
            result = None
    if result is None:
        parts, made = generate_parts(ops, registry, disabled=disabled, monitored=monitored,
                                     dialect=dialect)
        code: list[bytes] = []
        engine, address, ir_seconds, llvm_seconds = compile_ir(parts, code)
        program = made()
        result = Compiled(engine, address, program, ir_seconds, llvm_seconds)
        if code:
            disk_cache.store(name, code[0], program)
    with _lock:
        _cache[key] = result
        while len(_cache) > CACHED:
            _cache.popitem(last=False)
    return result, False


def clear_cache() -> None:
    """Forget every compiled program (tests, benchmarks measuring a cold compile)."""
    with _lock:
        _cache.clear()
