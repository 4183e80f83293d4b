"""The native scan's IR, op by op: the same walk over a binary's ops as core/plc/codegen.py.

Each level and subprogram is a function `U<n>` calling its chunk functions `c<k>` (a chunk
starts at a network when the last one reached CHUNK_OPS ops, at every label, and anywhere after
MAX_CHUNK_OPS ops, the stack values then carried in state words). Stack levels and COM gates
are SSA values (`slots`: the generator does mem2reg itself, with a phi where a guarded run of
ops ends), JMP ranges a guard on the unit's jump id (as the Python scan's `sk`), COM gates a
value per chunk loaded from its state word, a unit with labels a dispatch loop over its
chunks. A functional instruction is native code when builtins.py has it, else a call-back into
its Python implementation with the same call-site state.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Generator, Iterator
from dataclasses import dataclass, field

from ladderworks.core.address import Address
from ladderworks.core.compiler.binary import BinaryFormatError, Op
from ladderworks.core.compiler.checks import MAX_PUSHES, implementation_of
from ladderworks.core.compiler.structure import Unit, analyse, number_of
from ladderworks.core.instructions import Combine, Flow, Kind, StackOp, Write
from ladderworks.core.plc.codegen_plan import chunk_plan as plan_chunks
from ladderworks.core.plc.codegen_values import Range, count_in_innermost, counted
from ladderworks.core.plc.functions import FunctionImpl
from ladderworks.core.plc.native import builtins, layout, state_block, stateful, units
from ladderworks.core.plc.native.ir_text import PASS, FunctionText, module
from ladderworks.core.plc.native.layout import Layout

CHUNK_OPS = 48  # a network starts a new chunk function once the chunk has this many ops
MAX_CHUNK_OPS = 2000  # a giant network is cut anywhere after this many
PART_CHARS = 1_000_000  # a module of IR text this long is compiled while the next is made
_FLOW_ACT = (Flow.JUMP, Flow.LABEL_JUMP, Flow.LABEL_JUMP_MAIN, Flow.CALL)


@dataclass
class NativeProgram:
    """The IR of a scan and what the run-time needs to call it."""

    text: str
    layout: Layout
    calls: list[int] = field(default_factory=list)  # op index of each function call site
    callbacks: list[tuple[int, int]] = field(default_factory=list)  # (call site, inputs)
    edges: list[tuple[str, int]] = field(default_factory=list)  # DIFU/DIFD memories, by word
    blocks: list[tuple[int, int]] = field(default_factory=list)  # (call site, first word)
    units: list[Unit] = field(default_factory=list)
    labels: list[dict[int, int]] = field(default_factory=list)  # per unit: label -> chunk


def chunk_plan(ops: tuple[Op, ...], unit: Unit) -> tuple[set[int], dict[int, int]]:
    """Where a unit's chunks start, and the chunk each of its labels starts (the Python
    scan's plan with the native sizes)."""
    return plan_chunks(ops, unit, MAX_CHUNK_OPS, CHUNK_OPS)


class _Generator:
    def __init__(self, ops: tuple[Op, ...], registry: dict[str, FunctionImpl],
                 disabled: Collection[int], monitored: bool, dialect: str) -> None:
        self.ops = ops
        self.dialect = dialect  # the program's (ctx.dialect): TMR reads its preset by it
        self.registry = registry
        self.disabled = disabled
        self.monitored = monitored
        self.specs = [op.spec for op in ops]
        self.structure = analyse([(spec, op.params)
                                  for spec, op in zip(self.specs, ops, strict=True)])
        self.unit_list = self.structure.units()
        self.unit_numbers = {u.name: n for n, u in enumerate(self.unit_list)}
        commons = sum(1 for spec in self.specs if spec.flow is Flow.COMMON)
        self.edge_words: dict[tuple[str, int], int] = {}
        candidates = 0
        for spec, op in zip(self.specs, ops, strict=True):
            if spec.kind is not Kind.FUNCTION:
                continue
            impl = implementation_of(spec, registry)
            key = builtins.edge_key(spec, impl, op.params)
            if key is not None and key not in self.edge_words:
                self.edge_words[key] = len(self.edge_words)
            candidates += stateful.kind(spec, impl) is not None
        self.layout = Layout(len(self.unit_list), commons, len(self.edge_words), candidates)
        self.blocks: list[tuple[int, int]] = []  # (call site, first word) of each state block
        self.out: list[str] = []  # functions not yet in a module
        self.done: list[str] = []  # the modules made
        self.program: NativeProgram | None = None
        self.calls: list[int] = []
        self.callbacks: list[tuple[int, int]] = []
        self.common_count = 0
        self.chunk_count = 0
        self.labels: list[dict[int, int]] = []
        self.depth = 1  # len(values) of the Python generator: stack levels in use
        self.guarded = False  # inside a run of ops guarded by the unit's jump id
        self.slots: dict[str, str] = {}  # stack levels s0.. and COM gates cm<k>: SSA values
        self.jumps: list[Range] = []
        self.commons: list[Range] = []

    # -- guards and chunks -----------------------------------------------------------------

    def guard(self) -> None:
        """Code that follows runs only while no JMP of the unit is being taken."""
        if self.jumps and not self.guarded:
            sk = self.f.load_word(self.layout.jump_base + self.unit_number)
            self.guard_from = self.f.block
            self.guard_slots = dict(self.slots)
            _, after = self.f.branch_if(self.f.value(f"icmp eq i32 {sk}, 0"))
            self.guard_end = after
            self.guarded = True

    def unguard(self) -> None:
        """End a guarded run of ops: each slot it changed is a phi of before and after."""
        if self.guarded:
            f = self.f
            end = f.block
            f.join(self.guard_end)
            before = self.guard_slots
            for key, value in self.slots.items():
                old = before.get(key, "1" if key.startswith("cm") else "0")
                if value != old:
                    self.slots[key] = f.value(
                        f"phi i8 [{value}, %{end}], [{old}, %{self.guard_from}]")
            self.guarded = False

    def get(self, depth: int) -> str:
        return self.slots[f"s{depth}"]

    def put(self, depth: int, value: str) -> None:
        self.slots[f"s{depth}"] = value

    def start_chunk(self, carried: int) -> None:
        self.f = FunctionText(f"c{self.chunk_count}")
        self.chunk_count += 1
        self.guarded = False
        self.carried = carried
        self.depth = carried or 1
        self.slots = {f"s{d}": f"%carried{d}" if d < carried else "0" for d in range(10)}
        self.loaded = [r.ident for r in self.commons]  # the gates loaded at the chunk's start
        for ident in self.loaded:
            self.slots[f"cm{ident}"] = f"%cmi{ident}"

    def cm(self, ident: int) -> str:
        return self.slots[f"cm{ident}"]

    def end_chunk(self, mid_network: bool, result: str) -> str:
        f = self.f
        self.unguard()
        if mid_network:
            for d in range(self.depth):
                f.store_word(layout.CARRIED + d, f.value(f"zext i8 {self.get(d)} to i32"))
        prelude: list[str] = []
        words = [(f"%carried{d}", layout.CARRIED + d) for d in range(self.carried)]
        words += [(f"%cmi{ident}", self.layout.common_base + ident) for ident in self.loaded]
        for name, word in words:
            ptr, value = f.tmp(), f.tmp()
            prelude += [f"{ptr} = getelementptr i32, ptr %st, i64 {word}",
                        f"{value} = load i32, ptr {ptr}", f"{name} = trunc i32 {value} to i8"]
        self.out.append(f.finish(prelude, result))
        return f.name

    def abort_check(self) -> None:
        """After a call: leave the chunk when the scan is unwinding (JMPC, an error)."""
        f = self.f
        state = f.load_word(layout.ABORT)
        _, after = f.branch(state, "i32")
        f.add("ret i32 -1")
        f.start(after)

    # -- the program -------------------------------------------------------------------------

    def parts(self) -> Iterator[str]:
        """The IR as modules of whole functions, each yielded once it has PART_CHARS
        characters (jit.py compiles one while the next is made); `program` after the last."""
        numbers: list[int] = []
        for unit in self.unit_list:
            numbers.append((yield from self.unit(unit)))
        levels = self.structure.levels
        entries = {level: numbers[self.unit_numbers[unit.name]] for level, unit in levels.items()}
        first = levels.get(1)
        self.out.append(units.scan_function(entries, (first.start, first.end) if first else None,
                                            len(self.ops) if self.monitored else 0))
        yield from self.flush(0)
        edges = sorted(self.edge_words, key=self.edge_words.__getitem__)
        self.program = NativeProgram("\n".join(self.done), self.layout, self.calls,
                                     self.callbacks, edges, self.blocks, self.unit_list,
                                     self.labels)

    def flush(self, least: int = PART_CHARS) -> Iterator[str]:
        """The functions made so far as a module, once they have `least` characters."""
        if self.out and sum(map(len, self.out)) >= least:
            text = module(self.out, builtins.declarations())
            self.done.append(text)
            self.out = []
            yield text

    def unit(self, unit: Unit) -> Generator[str, None, int]:
        number = self.unit_numbers[unit.name]
        self.unit_number = number
        self.jumps, self.commons, self.jump_ids = [], [], 0
        labelled = bool(unit.labels)
        starts, chunk_of_label = chunk_plan(self.ops, unit)
        self.chunk_of_label = chunk_of_label
        self.labels.append(chunk_of_label)
        label_starts = set(unit.labels.values())
        chunks: list[str] = []
        first_common = self.common_count
        self.start_chunk(0)
        previous = -1
        for index in range(unit.start, unit.end):
            op = self.ops[index]
            new_network = op.source.network != previous
            previous = op.source.network
            at_label = index in label_starts
            if index in starts and index != unit.start:
                mid = not new_network and not at_label
                depth = self.depth if mid else 0
                result = str(len(chunks) + 1) if labelled else "0"
                chunks.append(self.end_chunk(mid, result))
                yield from self.flush()
                self.start_chunk(depth)
            if new_network and not at_label:
                self.depth = 1
                self.put(0, "0")
            self.op(index, op, labelled)
        result = str(len(chunks) + 1) if labelled else "0"
        chunks.append(self.end_chunk(False, result))
        self.out.append(units.unit_function(
            number, unit, chunks, range(first_common, self.common_count), self.jump_ids > 0,
            labelled, self.layout, self.chunk_of_label))
        yield from self.flush()
        return number

    # -- ops -------------------------------------------------------------------------------

    def live_after(self, index: int) -> bool:
        nxt = self.ops[index + 1] if index + 1 < len(self.ops) else None
        if nxt is None or nxt.source.network != self.ops[index].source.network:
            return False
        spec = self.specs[index + 1]
        return not (spec.combine is Combine.READ and spec.pushes == 0 and spec.operand)

    def close_jumps(self, ended: list[Range], index: int, live: bool) -> None:
        """End JMP ranges: the taken one stops skipping; after a counted range ending inside a
        network, its stack values read 0 if it was taken."""
        self.unguard()
        f = self.f
        low = min(r.ident for r in ended)
        word = self.layout.jump_base + self.unit_number
        sk = f.load_word(word)
        test = f.value(f"icmp {'eq' if len(ended) == 1 else 'sge'} i32 {sk}, {low}")
        f.store_word(word, f.value(f"select i1 {test}, i32 0, i32 {sk}"))
        if live:
            for d in range(self.depth):
                self.put(d, f.value(f"select i1 {test}, i8 0, i8 {self.get(d)}"))

    def op(self, index: int, op: Op, labelled: bool) -> None:
        spec = self.specs[index]
        off = index in self.disabled
        ended: list[Range] = []
        if spec.kind is Kind.BASIC:
            if spec.write is not Write.NONE:
                assert op.operand is not None
                ended = self.write(index, op.operand, spec.write, spec.negated, off)
            else:
                self.logic(index, op, off)
        elif spec.kind is Kind.FUNCTION:
            ended = self.function(index, op, off, labelled)
        if self.monitored and spec.flow not in _FLOW_ACT:
            self.guard()
            self.flow(index, self.get(self.depth - 1))
        if ended:
            self.close_jumps(ended, index, self.live_after(index))

    def flow(self, index: int, value: str) -> None:
        f = self.f
        ptr = f.value(f"getelementptr i8, ptr %fl, i64 {index}")
        f.add(f"store i8 {value}, ptr {ptr}")

    def push(self, index: int, value: str) -> None:
        if self.depth > MAX_PUSHES:
            raise BinaryFormatError(f"stack deeper than ST8 at op {index}")
        self.put(self.depth, value)
        self.depth += 1

    def logic(self, index: int, op: Op, off: bool) -> None:
        spec = self.specs[index]
        f = self.f
        if spec.operand:
            assert op.operand is not None and op.operand.bit is not None
            if off and spec.combine is Combine.OR and spec.pushes <= 0:
                return
            self.guard()
            term = "0" if off else f.bit(op.operand.area, op.operand.byte, op.operand.bit,
                                         spec.negated)
            if spec.pushes > 0:
                self.push(index, term)
            elif spec.combine is Combine.READ:
                self.put(self.depth - 1, term)
            else:
                operator = "and" if spec.combine is Combine.AND else "or"
                top = self.depth - 1
                self.put(top, f.value(f"{operator} i8 {self.get(top)}, {term}"))
            return
        if spec.stack is not StackOp.NONE:
            self.stack_op(index, spec.stack)
            return
        if self.depth < 2:
            raise BinaryFormatError(f"{spec.name} with nothing pushed at op {index}")
        self.guard()
        operator = "and" if spec.combine is Combine.AND else "or"
        self.depth -= 1
        top = self.depth - 1
        self.put(top, f.value(f"{operator} i8 {self.get(top)}, {self.get(self.depth)}"))

    def stack_op(self, index: int, op: StackOp) -> None:
        f = self.f
        top = self.depth - 1
        self.guard()
        if op is StackOp.INVERT:
            self.put(top, f.value(f"xor i8 {self.get(top)}, 1"))
        elif op is StackOp.DUP:
            self.push(index, self.get(top))
        elif top < 1:
            raise BinaryFormatError(f"stack operation with nothing pushed at op {index}")
        elif op is StackOp.OVER:
            self.put(top, self.get(top - 1))
        else:
            self.depth -= 1

    def count_coil(self) -> list[Range]:
        count_in_innermost(self.commons)
        ended = count_in_innermost(self.jumps)
        return [ended] if ended is not None else []

    def write(self, index: int, address: Address, kind: Write, inverted: bool,
              off: bool) -> list[Range]:
        if off:
            return self.count_coil()
        assert address.bit is not None
        f = self.f
        self.guard()
        condition = self.get(self.depth - 1)
        if self.commons:
            if inverted:
                condition = f.value(f"xor i8 {condition}, 1")
            condition = f.value(f"and i8 {self.cm(self.commons[-1].ident)}, {condition}")
            inverted = False
        # branch-free (an i8 select is a branch in LLVM's fast code generator): the 0/1
        # condition shifted to the bit, or-ed in (OUT: into the byte with the bit cleared)
        if inverted:
            condition = f.value(f"xor i8 {condition}, 1")
        ptr = f.byte_ptr(address.area, address.byte)
        old = f.value(f"load i8, ptr {ptr}")
        bit = f.value(f"shl i8 {condition}, {address.bit}") if address.bit else condition
        if kind is Write.RESET:
            new = f.value(f"and i8 {old}, {f.value(f'xor i8 {bit}, -1')}")
        else:
            if kind is Write.OUT:
                old = f.value(f"and i8 {old}, {0xFF ^ (1 << address.bit)}")
            new = f.value(f"or i8 {old}, {bit}")
        f.add(f"store i8 {new}, ptr {ptr}")
        return self.count_coil()

    def function(self, index: int, op: Op, off: bool, labelled: bool) -> list[Range]:
        spec = self.specs[index]
        f = self.f
        count = len(spec.inputs)
        if count and self.depth < count:
            raise BinaryFormatError(f"{spec.name} needs {count} control inputs at op {index}")
        self.guard()
        if spec.pushes > 0:
            self.push(index, "0")
        first = self.depth - count if count else self.depth - 1
        inputs = [self.get(d) for d in range(first, self.depth)]
        gating = next((r for r in reversed(self.commons) if r.gates_boxes), None)
        if gating is not None and count and spec.flow is Flow.NONE:
            inputs[-1] = f.value(f"and i8 {self.cm(gating.ident)}, {inputs[-1]}")
        act = inputs[-1] if inputs else "1"
        flow = spec.flow
        ended: list[Range] = []
        if flow in _FLOW_ACT and self.monitored:
            self.flow(index, act)
        if spec.negated and flow in _FLOW_ACT:  # a flow taken when its input is 0 (S7's JMPN)
            act = f.value(f"xor i8 {act}, 1")
        target = number_of(op.params[0]) if op.params else None
        result = "0"
        if flow is Flow.JUMP:
            self.jump_ids += 1
            if not off:
                word = self.layout.jump_base + self.unit_number
                sk = f.load_word(word)
                taken = f.value(f"select i1 {f.truth(act)}, i32 {self.jump_ids}, i32 {sk}")
                f.store_word(word, taken)
            self.unguard()
            self.jumps.append(Range(self.jump_ids, counted(op.params[0] if op.params else 0)))
        elif flow is Flow.JUMP_END:
            while self.jumps and self.jumps[-1].left is not None:
                ended.append(self.jumps.pop())
            if not self.jumps:
                raise BinaryFormatError(f"JMPE without JMP at op {index}")
            ended.append(self.jumps.pop())
        elif flow is Flow.COMMON:
            ident = self.common_count
            self.common_count += 1
            gate = "1" if off else act
            if self.commons:
                gate = f.value(f"and i8 {gate}, {self.cm(self.commons[-1].ident)}")
            self.slots[f"cm{ident}"] = gate
            f.store_word(self.layout.common_base + ident, f.value(f"zext i8 {gate} to i32"))
            self.commons.append(Range(ident, counted(op.params[0] if op.params else 0),
                                      spec.gates_boxes))
        elif flow is Flow.COMMON_END:
            for k in range(len(self.commons) - 1, -1, -1):
                if self.commons[k].left is None:
                    del self.commons[k]
                    break
        elif flow in (Flow.CALL, Flow.CALL_ALWAYS):
            if not off and target in self.structure.subprograms:
                callee = self.unit_numbers[self.structure.subprograms[target].name]
                after = ""
                if flow is Flow.CALL:
                    _, after = f.branch(act)
                f.add(f"call void @U{callee}({PASS})")
                self.abort_check()
                if after:
                    f.join(after)
        elif flow is Flow.LABEL_JUMP:
            if not off and target is not None and labelled and target in self.chunk_of_label:
                _, after = f.branch(act)
                f.add(f"ret i32 {self.chunk_of_label[target]}")
                f.start(after)
        elif flow is Flow.LABEL_JUMP_MAIN:
            if not off and target is not None:
                _, after = f.branch(act)
                f.store_word(layout.JUMP_LABEL, str(target))
                f.store_word(layout.ABORT, str(layout.JUMP_MAIN))
                f.add("ret i32 -1")
                f.start(after)
        elif flow is Flow.NONE:
            result = self.call(index, op, off, inputs)
        self.depth = first + 1
        self.put(first, result)
        return ended

    def call(self, index: int, op: Op, off: bool, inputs: list[str]) -> str:
        """A functional instruction's W1: native code, or the call-back into Python."""
        spec = self.specs[index]
        impl = implementation_of(spec, self.registry)
        if impl is None:
            raise BinaryFormatError(f"{spec.name} at op {index} is not implemented")
        site = len(self.calls)
        self.calls.append(index)
        if off:
            return "0"
        f = self.f
        native = builtins.emit(f, spec, impl, op.params, inputs, self.edge_words, self.layout)
        if native is not None:
            return native
        if stateful.kind(spec, impl) is not None:
            base = self.layout.block_base + state_block.BLOCK * len(self.blocks)
            native = stateful.emit(f, spec, impl, op.params, inputs, base, len(self.blocks),
                                   self.layout.dirty, self.layout.marks, self.dialect)
            if native is not None:
                self.blocks.append((site, base))
                return native
        number = len(self.callbacks)
        self.callbacks.append((site, len(inputs)))
        bits = "0"
        for k, value in enumerate(inputs):
            wide = f.value(f"zext i8 {value} to i32")
            shifted = f.value(f"shl i32 {wide}, {k}") if k else wide
            bits = f.value(f"or i32 {bits}, {shifted}")
        result = f.value(f"call i32 %cb(i32 {number}, i32 {bits})")
        failed = f.value(f"icmp ugt i32 {result}, 1")
        leave, going = f.label(), f.label()
        f.add(f"br i1 {failed}, label %{leave}, label %{going}")
        f.start(leave)
        f.add("ret i32 -1")
        f.start(going)
        return f.value(f"trunc i32 {result} to i8")


def generate_parts(ops: tuple[Op, ...], registry: dict[str, FunctionImpl], *,
                   disabled: Collection[int] = (), monitored: bool = False,
                   dialect: str = "seed") -> tuple[Iterator[str], Callable[[], NativeProgram]]:
    """The native scan's IR as modules made one by one, and what gives the program's facts
    once the last is made."""
    generator = _Generator(ops, registry, frozenset(disabled), monitored, dialect)

    def program() -> NativeProgram:
        assert generator.program is not None, "the parts were not all made"
        return generator.program

    return generator.parts(), program
