"""LLVM IR as text, one function at a time: blocks, the stack levels' slots, memory bytes.

Every function of the native scan has the same four arguments: `%b` (the areas' base
addresses, one pointer per area in `AREA_ORDER`), `%st` (the scan's state words: layout.py),
`%fl` (the power flow, one byte per op) and `%cb` (the call-back into Python). Stack levels
are SSA values tracked by the generator (i8 0/1); the dispatch loops keep two `alloca` slots.
"""

from __future__ import annotations

import re

from ladderworks.core.address import Area

AREA_ORDER: tuple[Area, ...] = tuple(Area)
AREA_INDEX: dict[Area, int] = {area: k for k, area in enumerate(AREA_ORDER)}
ARGS = "ptr noalias %b, ptr noalias %st, ptr noalias %fl, ptr %cb"
PASS = "ptr %b, ptr %st, ptr %fl, ptr %cb"
_CALLED = re.compile(r"call (void|i32) @([Uc]\d+)\(")
_DEFINED = re.compile(r"^define (?:void|i32) @(\w+)\(", re.M)


def module(functions: list[str], declarations: list[str]) -> str:
    """A module of `functions`, declaring the units and chunks they call that another module
    defines (every function has external linkage: the modules' object code is linked in one
    execution engine)."""
    text = "\n".join(functions)
    defined = set(_DEFINED.findall(text))
    called = {name: kind for kind, name in _CALLED.findall(text) if name not in defined}
    head = ["declare void @llvm.memset.p0.i64(ptr, i8, i64, i1)", *declarations]
    head += [f"declare {kind} @{name}(ptr, ptr, ptr, ptr)" for name, kind in called.items()]
    return "\n".join([*head, text])


class FunctionText:
    """The text of one IR function being written; `finish()` gives it whole."""

    def __init__(self, name: str, returns: str = "i32", slots: int = 0) -> None:
        self.name = name
        self.returns = returns
        self.slots = slots  # i32 alloca slots %v0.. (the dispatch loops')
        self.block = "body"  # the block being written
        self.body: list[str] = []
        self.count = 0
        self.bases: set[int] = set()
        self.entry: list[str] = []  # lines of the entry block after the slots
        self.pointers: dict[tuple[int, int], str] = {}  # this block's memory byte pointers

    def tmp(self) -> str:
        self.count += 1
        return f"%t{self.count}"

    def label(self) -> str:
        self.count += 1
        return f"L{self.count}"

    def add(self, line: str) -> None:
        self.body.append("  " + line)

    def start(self, label: str) -> None:
        self.body.append(f"{label}:")
        self.block = label
        self.pointers = {}

    def value(self, line: str) -> str:
        """A new temporary `= line`; its name (`tmp` written out: 200k calls for X22)."""
        self.count = count = self.count + 1
        self.body.append(f"  %t{count} = {line}")
        return f"%t{count}"

    # -- state words, slots and memory ---------------------------------------------------

    def word_ptr(self, word: int) -> str:
        found = self.pointers.get((-1, word))
        if found is None:
            found = self.pointers[-1, word] = self.value(
                f"getelementptr i32, ptr %st, i64 {word}")
        return found

    def load_word(self, word: int) -> str:
        return self.value(f"load i32, ptr {self.word_ptr(word)}")

    def store_word(self, word: int, value: str) -> None:
        self.add(f"store i32 {value}, ptr {self.word_ptr(word)}")

    def get(self, slot: int) -> str:
        return self.value(f"load i32, ptr %v{slot}")

    def put(self, slot: int, value: str) -> None:
        self.add(f"store i32 {value}, ptr %v{slot}")

    def byte_ptr(self, area: Area, byte: int) -> str:
        """The address of a memory byte (one per byte and block: the loads and stores of a
        block share it; LLVM folds it into their addressing)."""
        index = AREA_INDEX[area]
        found = self.pointers.get((index, byte))
        if found is None:
            self.bases.add(index)
            found = self.pointers[index, byte] = self.value(
                f"getelementptr i8, ptr %a{index}, i64 {byte}")
        return found

    def bit(self, area: Area, byte: int, bit: int, inverted: bool) -> str:
        """0/1 (i8) of a memory bit, or of its inverse."""
        raw = self.value(f"load i8, ptr {self.byte_ptr(area, byte)}")
        if bit:
            raw = self.value(f"lshr i8 {raw}, {bit}")
        value = self.value(f"and i8 {raw}, 1")
        return self.value(f"xor i8 {value}, 1") if inverted else value

    def truth(self, value: str, kind: str = "i8") -> str:
        """An i1 of a 0/1 value."""
        return self.value(f"icmp ne {kind} {value}, 0")

    def branch(self, condition: str, kind: str = "i8") -> tuple[str, str]:
        """`br` on a 0/1 value: the labels (then, after); the then-block is started."""
        return self.branch_if(self.truth(condition, kind))

    def branch_if(self, test: str) -> tuple[str, str]:
        """`br` on an i1: the labels (then, after); the then-block is started."""
        then, after = self.label(), self.label()
        self.add(f"br i1 {test}, label %{then}, label %{after}")
        self.start(then)
        return then, after

    def join(self, after: str) -> None:
        self.add(f"br label %{after}")
        self.start(after)

    def finish(self, prelude: list[str], result: str, extra: str = "") -> str:
        """The whole function: slots, `prelude` (loads before the body), body, `ret result`;
        `extra` arguments after the four (the entry's)."""
        args = f"{ARGS}, {extra}" if extra else ARGS
        head = [f"define {self.returns} @{self.name}({args}) {{", "entry:"]
        head += [f"  %v{k} = alloca i32" for k in range(self.slots)]
        head += [f"  store i32 0, ptr %v{k}" for k in range(self.slots)]
        for index in sorted(self.bases):
            head.append(f"  %ap{index} = getelementptr ptr, ptr %b, i64 {index}")
            head.append(f"  %a{index} = load ptr, ptr %ap{index}")
        head += ["  " + line for line in self.entry]
        head += ["  " + line for line in prelude]
        head.append("  br label %body")
        head.append("body:")
        tail = [f"  ret {self.returns} {result}" if result else f"  ret {self.returns}", "}", ""]
        return "\n".join([*head, *self.body, *tail])
