"""A network's logic as series/parallel blocks, its standard coding, and reading code back."""

from __future__ import annotations

from dataclasses import dataclass, field

from ladderworks.core.il.program import Instruction
from ladderworks.core.instructions import (
    BASIC,
    BY_NAME,
    Combine,
    InstructionSpec,
    Kind,
    StackOp,
    Write,
    lookup,
)
from ladderworks.core.ladder.model import Cell, Coil, Contact, FunctionBox
from ladderworks.core.ladder.row_contacts import contact_combine, row_for

MAX_PUSHES = 8  # ST0 plus ST1..ST8: at most eight values pushed under ST0


@dataclass(frozen=True, slots=True)
class Leaf:
    """One contact."""

    contact: Contact
    cell: tuple[int, int] | None = field(default=None, compare=False)  # where it is drawn


@dataclass(frozen=True, slots=True)
class Series:
    """Blocks in series, left to right (never directly holds another Series)."""

    items: tuple[Logic, ...]


@dataclass(frozen=True, slots=True)
class Parallel:
    """Blocks in parallel, top to bottom (never directly holds another Parallel)."""

    items: tuple[Logic, ...]


Logic = Leaf | Series | Parallel


def series(a: Logic, b: Logic) -> Series:
    """`a` then `b`, flattened."""
    left = a.items if isinstance(a, Series) else (a,)
    right = b.items if isinstance(b, Series) else (b,)
    return Series(left + right)


def parallel(a: Logic, b: Logic) -> Parallel:
    """`a` over `b`, flattened."""
    top = a.items if isinstance(a, Parallel) else (a,)
    bottom = b.items if isinstance(b, Parallel) else (b,)
    return Parallel(top + bottom)


# What a rung's outputs are: coils, and a dialect's output boxes (Delta's MOV among its coils)
Output = Coil | FunctionBox
# A stack branch: its block (None: on the branch point), its outputs, its own branches.
Branch = tuple["Logic | None", list[Output], list["Branch"]]


@dataclass(slots=True)
class Rung:
    """What a network means: logic feeding coils, or control inputs feeding a function box."""

    logic: Logic | None = None  # the coils' logic (None for a box network)
    # parallel outputs, top to bottom (box: its coils on W1); a dialect's output boxes among
    # them (`spec.output`); before `branches`: the outputs on their branch point (MPS after them)
    coils: list[Output] = field(default_factory=list)
    box: FunctionBox | None = None
    inputs: list[Logic] = field(default_factory=list)  # box control inputs, first to last
    # an output chain (coil networks): after the coils, each block is put in series with the
    # result so far and its own coils written (`WRT y / AND b / WRT z`)
    chain: list[tuple[Logic, list[Output]]] = field(default_factory=list)
    # where the box and the coils are drawn (coils in coding order: `coils`, then the chain's);
    # empty when the rung was read from text
    # a dialect's stack branches (Delta MPS / MRD / MPP): after `logic`, each branch's block
    # (None: its coils hang on the branch point), coils and branches of its own (a nested MPS
    # after its block: then it has no coils), first to last (at least two)
    branches: list[Branch] = field(default_factory=list)
    # a box's further output pins (Fatek's FO1, FO2 …): the contact reading each (`RD FO.1`),
    # the block in series after it (None: its outputs hang on the pin; `FO 1 / AND X3 / OUT Y1`)
    # and its outputs, written after the box's W1 coils
    pins: list[tuple[Contact, Logic | None, list[Output]]] = field(default_factory=list)
    box_cell: Cell | None = field(default=None, compare=False)
    coil_cells: list[Cell] = field(default_factory=list, compare=False)
    # the dialect whose stack rows code the branches ("" the first there is: Delta's MPS …),
    # and the parameters of those read, in order (Fatek's TR numbers: kept when coded again)
    stack_dialect: str = field(default="", compare=False)
    stack_params: list[tuple[StackOp, tuple]] = field(default_factory=list, compare=False)


def has_bare_branch(branches: list[Branch]) -> bool:
    """True when a branch (at any depth) has no block: its coils hang on the branch point."""
    return any(block is None or has_bare_branch(inner) for block, _coils, inner in branches)


def _basic(combine: Combine, write: Write, negated: bool, pushes: int, operand: bool
           ) -> InstructionSpec:
    """The basic instruction with this meaning (the table's fields, not its spelling)."""
    for spec in BASIC:
        if (spec.combine, spec.write, spec.negated, spec.pushes, spec.operand) == (
                combine, write, negated, pushes, operand):
            return spec
    raise KeyError((combine, write, negated, pushes))


def contact_spec(contact: Contact) -> InstructionSpec:
    """The contact's row of the table, read on its own: RD or RD.NOT."""
    return _basic(Combine.READ, Write.NONE, contact.negated, 0, True)


class ContactPlace(Exception):
    """A dialect's edge or comparison contact stands where its dialect has no row for it."""

    def __init__(self, contact: Contact, cell: Cell | None) -> None:
        super().__init__(contact.function)
        self.contact = contact
        self.cell = cell


def _contact_instruction(contact: Contact, combine: Combine, push: bool,
                         cell: Cell | None = None) -> Instruction:
    if contact.function:
        row = row_for(contact.function, combine, push)
        if row is None:
            raise ContactPlace(contact, cell)
        return Instruction(row.name, params=contact.params, comment=contact.comment,
                           lead=contact.lead)
    spec = _basic(combine, Write.NONE, contact.negated, 1 if push else 0, True)
    return Instruction(spec.name, contact.address, comment=contact.comment, lead=contact.lead)


def stack_row(op: StackOp, dialect: str = "") -> InstructionSpec | None:
    """The basic row that does `op` to the result stack (Delta's MPS/MRD/MPP), by its field;
    of `dialect` when given."""
    for spec in list(BY_NAME.values()):
        if spec.kind is Kind.BASIC and spec.stack is op and (not dialect
                                                              or spec.dialect == dialect):
            return spec
    return None


def _stack_instruction(combine: Combine) -> Instruction:
    return Instruction(_basic(combine, Write.NONE, False, -1, False).name)


def code_logic(logic: Logic, push: bool = False,
               cells: list[tuple[int, int] | None] | None = None) -> list[Instruction]:
    """The standard coding of a block: RD (RD.STK when `push`), AND/OR for single contacts,
    RD.STK … AND.STK / OR.STK for blocks (seed 002 rules). `cells`, if given, receives the
    drawn cell of each instruction (None for stack operations)."""
    if cells is None:
        cells = []
    if isinstance(logic, Leaf):
        cells.append(logic.cell)
        return [_contact_instruction(logic.contact, Combine.READ, push, logic.cell)]
    out = code_logic(logic.items[0], push, cells)
    combine = Combine.AND if isinstance(logic, Series) else Combine.OR
    for item in logic.items[1:]:
        if isinstance(item, Leaf):
            cells.append(item.cell)
            out.append(_contact_instruction(item.contact, combine, False, item.cell))
        else:
            out.extend(code_logic(item, True, cells))
            cells.append(None)
            out.append(_stack_instruction(combine))
    return out


def first_cell(logic: Logic) -> tuple[int, int]:
    """Top-most, then left-most drawn cell of a block (orders parallel branches)."""
    if isinstance(logic, Leaf):
        return logic.cell or (0, 0)
    return min(first_cell(item) for item in logic.items)


def coil_spec(coil: Coil) -> InstructionSpec:
    """The coil's row of the table: WRT, WRT.NOT, SET or RST; a dialect's own row it was read
    with (Fatek's OUT L) when it has one."""
    own = lookup(coil.row) if coil.row else None
    if own is not None and own.write is coil.write and own.negated == coil.negated:
        return own
    return _basic(Combine.NONE, coil.write, coil.negated and coil.write is Write.OUT, 0, True)


def coil_instruction(coil: Output) -> Instruction:
    """WRT / WRT.NOT / SET / RST of a coil, or an output box's instruction, with comments."""
    if isinstance(coil, FunctionBox):
        return box_instruction(coil)
    return Instruction(coil_spec(coil).name, coil.address, comment=coil.comment, lead=coil.lead)


def box_instruction(box: FunctionBox) -> Instruction:
    """The functional instruction of a box."""
    return Instruction(box.name, params=box.params, comment=box.comment, lead=box.lead)


def code_rung(rung: Rung, cells: list[tuple[int, int] | None] | None = None
              ) -> list[Instruction]:
    """The standard coding of a whole network. `cells`, if given, receives the drawn cell of
    each instruction: contacts, the box and the coils (when the rung was read from the grid);
    None for stack operations."""
    if cells is None:
        cells = []
    coil_cells = iter(rung.coil_cells)
    out: list[Instruction] = []

    def write(coils: list[Output]) -> None:
        for coil in coils:
            out.append(coil_instruction(coil))
            cells.append(next(coil_cells, None))

    if rung.box is not None:
        for index, logic in enumerate(rung.inputs):
            out.extend(code_logic(logic, index > 0, cells))
        out.append(box_instruction(rung.box))
        cells.append(rung.box_cell)
    elif rung.logic is not None:
        out.extend(code_logic(rung.logic, False, cells))
    write(rung.coils)
    for contact, block, coils in rung.pins:
        out.append(_contact_instruction(contact, Combine.READ, False))
        cells.append(rung.box_cell)
        if block is not None:
            _continue(block, out, cells)
        write(coils)

    kept = [params for op, params in rung.stack_params if op is StackOp.DUP]
    points = iter(kept if len(kept) == _levels(rung.branches) else [])
    fresh = iter(range(MAX_POINTS))

    def branches(each: list[Branch]) -> None:
        number = 0
        for index, (branch, coils, inner) in enumerate(each):
            op = StackOp.DUP if index == 0 else (
                StackOp.DROP if index == len(each) - 1 else StackOp.OVER)
            row = (rung.stack_dialect and stack_row(op, rung.stack_dialect)) or stack_row(op)
            assert row is not None, op
            params: tuple = ()
            if row.params:  # the branch point's number (Fatek's TR n), the same on each branch
                if index == 0:
                    number = next(points, (next(fresh),))[0]
                params = (number,)
            out.append(Instruction(row.name, params=params))
            cells.append(None)
            if branch is not None:
                _continue(branch, out, cells)
            branches(inner)
            write(coils)

    branches(rung.branches)
    for block, coils in rung.chain:
        _continue(block, out, cells)
        write(coils)
    return out


MAX_POINTS = 64  # branch points numbered afresh in one network


def _levels(each: list[Branch]) -> int:
    """How many branch points (MPS, Fatek's OUT TR n) the branches need."""
    return (1 if each else 0) + sum(_levels(inner) for _block, _coils, inner in each)


def _continue(block: Logic, out: list[Instruction], cells: list[Cell | None]) -> None:
    """A block in series with the result so far: AND b, or RD.STK … AND.STK."""
    for item in block.items if isinstance(block, Series) else (block,):
        if isinstance(item, Leaf):
            cells.append(item.cell)
            out.append(_contact_instruction(item.contact, Combine.AND, False, item.cell))
        else:
            out.extend(code_logic(item, True, cells))
            cells.append(None)
            out.append(_stack_instruction(Combine.AND))


def stack_depth(instructions: list[Instruction]) -> int:
    """Most values held under ST0 at any point (must be ≤ MAX_PUSHES)."""
    depth = deepest = 0
    for ins in instructions:
        spec = ins.spec
        if spec.kind is Kind.BASIC or contact_combine(spec) is not None:
            depth += spec.pushes
        elif spec.inputs:
            depth = 0
        deepest = max(deepest, depth)
    return deepest


def inverts(logic: Logic) -> bool:
    """True for a stack operation drawn as a contact (Delta's INV)."""
    if not isinstance(logic, Leaf) or not logic.contact.function:
        return False
    spec = lookup(logic.contact.function)
    return spec is not None and spec.stack is StackOp.INVERT


def inverted_inside(rung: Rung) -> Cell | None:
    """The cell of an INV drawn inside a parallel block (not on a line from the rail or the
    branch point, where it inverts all the power before it), or None."""
    blocks: list[Logic | None] = [rung.logic, *rung.inputs,
                                  *(block for block, _ in rung.chain)]
    todo = list(rung.branches)
    while todo:
        block, _outputs, inner = todo.pop()
        blocks.append(block)
        todo.extend(inner)

    def inside(logic: Logic, top: bool) -> Cell | None:
        if isinstance(logic, Leaf):
            return None if top or not inverts(logic) else (logic.cell or (0, 0))
        for item in logic.items:
            found = inside(item, top and isinstance(logic, Series))
            if found is not None:
                return found
        return None

    for block in blocks:
        found = None if block is None else inside(block, True)
        if found is not None:
            return found
    return None


def outputs_first(rung: Rung) -> Rung:
    """The rung with a first branch on the branch point (`MPS / OUT y / MRD …`) coded as the
    outputs before the MPS (`OUT y / MPS …`): the same drawing, the same logic."""
    if rung.coils or len(rung.branches) < 3 or rung.branches[0][0] is not None \
            or rung.branches[0][2]:
        return rung
    return Rung(logic=rung.logic, coils=list(rung.branches[0][1]), branches=rung.branches[1:],
                stack_dialect=rung.stack_dialect, stack_params=rung.stack_params)
