"""Program structure: levels 1-3, subprograms (SP/SPE), calls and labels, from the table's flow.

One analysis for the checks and the code generator: both see the same units, so every program
the checks pass can be generated, and every structural error is found by `check`.
"""

from __future__ import annotations

from bisect import bisect_left
from collections.abc import Sequence
from dataclasses import dataclass, field
from operator import itemgetter

from ladderworks.core.instructions import Flow, InstructionSpec, ParamKind

MAX_NESTING = 8  # subprogram calls nest up to 8 deep (FANUC PMC)
LOOP_LIMIT = 10_000  # backward label jumps allowed per unit run in one scan


@dataclass(frozen=True, slots=True)
class Problem:
    """A structural error (or warning) at item `index`."""

    code: str
    index: int
    args: dict[str, object] = field(default_factory=dict, hash=False)
    warning: bool = False


@dataclass(slots=True)
class Unit:
    """A level's main program or a subprogram: the items `start`..`end` (end exclusive)."""

    name: str  # "L1", "L2", "L3" or "P5"
    level: int  # 1..3 for a level's main program, 0 for a subprogram
    program: int  # the P number of a subprogram (0 for a level)
    start: int
    end: int
    labels: dict[int, int] = field(default_factory=dict)  # label number -> index of its LBL
    calls: list[tuple[int, int]] = field(default_factory=list)  # (index of CALL, P number)


@dataclass(slots=True)
class Structure:
    """The units of a program, the unit of every item, and the structural problems."""

    levels: dict[int, Unit]
    subprograms: dict[int, Unit]
    unit_of: list[Unit | None]  # None for items outside every unit (stray, after END)
    problems: list[Problem]

    def units(self) -> list[Unit]:
        """Every unit: the levels in order, then the subprograms in program order."""
        return [*(self.levels[k] for k in sorted(self.levels)),
                *sorted(self.subprograms.values(), key=lambda u: u.start)]

    def callers(self) -> dict[int, set[int]]:
        """For each subprogram, the levels whose scan can reach it."""
        reach: dict[int, set[int]] = {p: set() for p in self.subprograms}
        for level, unit in self.levels.items():
            stack = [p for _, p in unit.calls]
            while stack:
                p = stack.pop()
                if p in reach and level not in reach[p]:
                    reach[p].add(level)
                    stack += [q for _, q in self.subprograms[p].calls]
        return reach


# The flows (and kinds) as module constants: reading an Enum member from its class (`Flow.LABEL`)
# goes through the Enum metaclass, about 200 ns in Python 3.11; a global does not.
_CALL = Flow.CALL
_CALL_ALWAYS = Flow.CALL_ALWAYS
_LABEL = Flow.LABEL
_LABEL_JUMP = Flow.LABEL_JUMP
_LABEL_JUMP_MAIN = Flow.LABEL_JUMP_MAIN
_LEVEL_END = Flow.LEVEL_END
_MAIN_END = Flow.MAIN_END
_NONE = Flow.NONE
_PROGRAM_END = Flow.PROGRAM_END
_SUBPROGRAM = Flow.SUBPROGRAM
_SUBPROGRAM_END = Flow.SUBPROGRAM_END
_NUMBERED = (ParamKind.PROGRAM, ParamKind.LABEL)  # the kinds of a P or L number


def number_of(value: object) -> int | None:
    """The number of a PROGRAM/LABEL parameter (`P5` -> 5), None if it holds none."""
    if isinstance(value, int):
        return value
    number = getattr(value, "number", None)
    return number if isinstance(number, int) else None


_index = itemgetter(0)  # a FlowItem's index: the key the label jumps are bisected by


def _target(spec: InstructionSpec, params: Sequence[object]) -> int | None:
    for param, value in zip(spec.params, params, strict=False):
        if param.kind in _NUMBERED:
            return number_of(value)
    return None


# An item whose flow is not Flow.NONE: its index among the items, its row and its parameters.
FlowItem = tuple[int, InstructionSpec, Sequence[object]]


class _Builder:
    def __init__(self, count: int, flows: Sequence[FlowItem]) -> None:
        self.count = count
        self.flows = flows
        self.problems: list[Problem] = []
        self.levels: dict[int, Unit] = {}
        self.subprograms: dict[int, Unit] = {}
        self.unit_of: list[Unit | None] = [None] * count
        self.label_jumps: list[FlowItem] = []  # the items jumping to a label, in order

    def place_plain(self, start: int, end: int, current: Unit | None, ended: bool) -> None:
        """Items `start`..`end` (end exclusive), whose flow is NONE: in the current unit."""
        if start >= end:
            return
        if ended:
            self.problems += [Problem("after-end", index) for index in range(start, end)]
        elif current is None:
            self.problems += [Problem("outside-subprogram", index)
                              for index in range(start, end)]
        else:
            self.unit_of[start:end] = [current] * (end - start)

    def build(self) -> Structure:
        first_end = next((spec.level for _, spec, _ in self.flows
                          if spec.flow is _LEVEL_END), None)
        level = 1 if first_end == 1 else 2  # no END1 first: the program is level 2
        current: Unit | None = Unit(f"L{level}", level, 0, 0, 0)
        sub_area = False
        ended = False
        placed = 0  # the items before it are placed
        for item in self.flows:
            index, spec, params = item
            self.place_plain(placed, index, current, ended)
            placed = index + 1
            flow = spec.flow
            if flow is _LABEL_JUMP or flow is _LABEL_JUMP_MAIN:
                self.label_jumps.append(item)
            if ended:
                self.problems.append(Problem("after-end", index))
                continue
            if flow is _SUBPROGRAM:
                if current is not None and current.level == 0:
                    self.problems.append(Problem("sp-without-spe", current.start))
                    self.close(current, index)
                elif current is not None:
                    self.close(current, index)
                sub_area = True
                number = _target(spec, params) or 0
                current = Unit(f"P{number}", 0, number, index, 0)
                if number in self.subprograms:
                    self.problems.append(Problem("sp-twice", index, {"program": number}))
                self.unit_of[index] = current
                continue
            if current is None:
                if flow is _PROGRAM_END:
                    ended = True
                elif flow is _SUBPROGRAM_END:
                    self.problems.append(Problem("spe-without-sp", index))
                else:
                    self.problems.append(Problem("outside-subprogram", index))
                continue
            self.unit_of[index] = current
            if flow is _SUBPROGRAM_END:
                if current.level == 0:
                    self.close(current, index + 1)
                    current = None
                else:
                    self.problems.append(Problem("spe-without-sp", index))
                continue
            if flow is _MAIN_END:  # Delta FEND: the main program ends, subroutines follow
                if current.level == 0 or sub_area:
                    self.problems.append(Problem("outside-subprogram", index))
                    continue
                self.close(current, index + 1)
                current = None
                sub_area = True
                continue
            if flow is _LEVEL_END:
                if current.level == 0 or sub_area:
                    self.problems.append(Problem("outside-subprogram", index))
                    continue
                if spec.level != current.level:
                    self.problems.append(Problem("level-end-order", index, {
                        "name": spec.name, "level": current.level}))
                self.close(current, index + 1)
                current = Unit(f"L{spec.level + 1}", spec.level + 1, 0, index + 1, 0)
                continue
            if flow is _PROGRAM_END:
                if current.level == 0:
                    self.problems.append(Problem("sp-without-spe", current.start))
                self.close(current, index + 1)
                current = None
                ended = True
                continue
            if flow is _LABEL:
                label = _target(spec, params)
                if label is not None:
                    if label in current.labels:
                        self.problems.append(Problem("label-twice", index, {"label": label}))
                    else:
                        current.labels[label] = index
            elif flow in (_CALL, _CALL_ALWAYS):
                called = _target(spec, params)
                if called is not None:
                    current.calls.append((index, called))
        self.place_plain(placed, self.count, current, ended)
        if current is not None:
            if current.level == 0:
                self.problems.append(Problem("sp-without-spe", current.start))
            self.close(current, self.count)
        structure = Structure(self.levels, self.subprograms, self.unit_of, self.problems)
        self.check_calls(structure)
        self.check_labels(structure)
        return structure

    def close(self, unit: Unit, end: int) -> None:
        unit.end = end
        if unit.level:
            if unit.end > unit.start or unit.level not in self.levels:
                self.levels[unit.level] = unit
        elif unit.program not in self.subprograms:
            self.subprograms[unit.program] = unit

    def check_calls(self, structure: Structure) -> None:
        subs = structure.subprograms
        for unit in structure.units():
            for index, number in unit.calls:
                if number not in subs:
                    self.problems.append(Problem("call-missing", index, {"program": number}))
        depth: dict[int, int] = {}
        visiting: set[int] = set()
        cyclic: set[int] = set()

        def depth_of(number: int) -> int:
            if number in depth:
                return depth[number]
            visiting.add(number)
            deepest = 0
            for index, callee in subs[number].calls:
                if callee not in subs:
                    continue
                if callee in visiting:
                    if index not in cyclic:
                        cyclic.add(index)
                        self.problems.append(Problem("call-recursion", index,
                                                     {"program": callee}))
                    continue
                deepest = max(deepest, depth_of(callee))
            visiting.discard(number)
            depth[number] = deepest + 1
            return depth[number]

        called = {p for unit in structure.units() for _, p in unit.calls}
        for unit in structure.units():
            root = unit.level > 0 or unit.program not in called
            if not root:
                continue
            base = 0 if unit.level else 1
            if unit.level == 0:
                depth_of(unit.program)
            for index, callee in unit.calls:
                if callee in subs and base + depth_of(callee) > MAX_NESTING:
                    self.problems.append(Problem("call-depth", index, {
                        "program": callee, "limit": MAX_NESTING}))
        for number in subs:  # subprograms only reachable through a cycle
            depth_of(number)

    def check_labels(self, structure: Structure) -> None:
        reach = structure.callers()
        jumps = self.label_jumps
        for unit in structure.units():
            for index, spec, params in jumps[bisect_left(jumps, unit.start, key=_index):
                                             bisect_left(jumps, unit.end, key=_index)]:
                if spec.flow is _LABEL_JUMP:
                    label = _target(spec, params)
                    if label is not None and label not in unit.labels:
                        self.problems.append(Problem("label-missing", index, {"label": label}))
                elif spec.flow is _LABEL_JUMP_MAIN:
                    label = _target(spec, params)
                    if label is None:
                        continue
                    if unit.level:
                        self.problems.append(Problem("jmpc-in-main", index))
                        continue
                    levels = reach.get(unit.program) or set(structure.levels)
                    if not any(label in structure.levels[k].labels for k in levels
                               if k in structure.levels) or any(
                            label not in structure.levels[k].labels for k in levels
                            if k in structure.levels):
                        self.problems.append(Problem("label-missing", index, {"label": label}))


def analyse(items: Sequence[tuple[InstructionSpec, Sequence[object]]]) -> Structure:
    """The units of a program given as (spec, params) per instruction, in program order."""
    plain = _NONE
    return analyse_flows(len(items), [(index, spec, params)
                                      for index, (spec, params) in enumerate(items)
                                      if spec.flow is not plain])


def analyse_flows(count: int, flows: Sequence[FlowItem]) -> Structure:
    """The units of a program of `count` items, given only the items whose flow is not
    Flow.NONE, in program order (the others are read by no part of the analysis)."""
    return _Builder(count, flows).build()
