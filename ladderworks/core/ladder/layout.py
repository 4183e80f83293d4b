"""Program → grid: lay a network's instructions out as a technician would draw them."""

from __future__ import annotations

from dataclasses import replace

from ladderworks.core.il.program import Instruction
from ladderworks.core.ladder.logic import (
    Branch,
    Leaf,
    Logic,
    Output,
    Rung,
    Series,
    code_rung,
    has_bare_branch,
)
from ladderworks.core.ladder.model import (
    BOX_WIDTH,
    DEFAULT_COLUMNS,
    MAX_COLUMNS,
    MAX_ROWS,
    WIRE,
    FunctionBox,
    LadderNetwork,
)
from ladderworks.core.ladder.reading import Undrawable, read_rung


def size(logic: Logic) -> tuple[int, int]:
    """(columns, rows) a block needs: series side by side, parallel branches stacked."""
    if isinstance(logic, Leaf):
        return 1, 1
    sizes = [size(item) for item in logic.items]
    if isinstance(logic, Series):
        return sum(w for w, _ in sizes), max(h for _, h in sizes)
    return max(w for w, _ in sizes), sum(h for _, h in sizes)


def place_logic(net: LadderNetwork, logic: Logic, row: int, col: int) -> None:
    """Draw a block with its entry at node (row, col) and its exit at (row, col + width)."""
    if isinstance(logic, Leaf):
        net.cells[(row, col)] = logic.contact
        return
    if isinstance(logic, Series):
        for item in logic.items:
            place_logic(net, item, row, col)
            col += size(item)[0]
        return
    width = size(logic)[0]
    top = row
    last = row
    for item in logic.items:
        w, h = size(item)
        place_logic(net, item, row, col)
        for c in range(col + w, col + width):  # a shorter branch runs on as a wire
            net.cells[(row, c)] = WIRE
        last = row
        row += h
    for r in range(top, last):
        if col:  # node 0 is the left rail: it needs no link
            net.links.add((r, col))
        net.links.add((r, col + width))


def draw_rung(rung: Rung, columns: int = DEFAULT_COLUMNS) -> LadderNetwork:
    """The natural picture of a network: logic from the left rail, coils right-aligned in the
    coil column (parallel coils below each other), a function box right-aligned before them
    with its control inputs' logic on its pin rows. The grid widens when the logic needs it."""
    if rung.box is not None:
        box = rung.box
        sizes = [size(logic) for logic in rung.inputs]
        if not rung.inputs:  # JMPE, COME, END…: a box on the left rail
            net = LadderNetwork(columns, 1)
            net.cells[(0, 0)] = box
            box_col = 0
        else:
            after = _pins_width(rung)
            need = max(w for w, _ in sizes) + BOX_WIDTH + after
            net = LadderNetwork(max(columns, need), 1)
            box_col = net.columns - BOX_WIDTH - after
            pins: list[int] = []
            row = 0
            for logic, (w, h) in zip(rung.inputs, sizes, strict=True):
                place_logic(net, logic, row, 0)
                for c in range(w, box_col):
                    net.cells[(row, c)] = WIRE
                pins.append(row)
                row += h
            height = max(1, row)
            net.cells[(0, box_col)] = FunctionBox(box.name, box.params, box.comment, box.lead,
                                                  tuple(pins), height)
            net.rows = height
        for c in range(box_col + BOX_WIDTH, net.columns):
            net.cells[(0, c)] = WIRE
    elif rung.branches:
        return _draw_branches(rung, columns)
    else:
        return _draw_chain(rung, columns)
    _draw_coils(net, 0, rung.coils)
    if rung.pins:
        _draw_pins(net, rung, box_col)
    return net


def _pins_width(rung: Rung) -> int:
    """Columns the blocks after a box's output pins need between the box and the coils."""
    return max((size(block)[0] for _pin, block, _coils in rung.pins if block is not None),
               default=0)


def _draw_pins(net: LadderNetwork, rung: Rung, box_col: int) -> None:
    """A box's further output pins on the rows below its W1 coils, each pin's block after it
    and its coils on its row and below it; the box grows to reach the last pin."""
    row = max(1, len(rung.coils))
    outputs = []
    for contact, block, coils in rung.pins:
        outputs.append((row, contact))
        for c in range(box_col + BOX_WIDTH, net.columns):
            net.cells[(row, c)] = WIRE
        height = 1
        if block is not None:
            height = size(block)[1]
            place_logic(net, block, row, box_col + BOX_WIDTH)
        _draw_coils(net, row, coils)
        row += max(height, len(coils))
    box = net.cells[(0, box_col)]
    assert isinstance(box, FunctionBox)
    net.cells[(0, box_col)] = replace(box, outputs=tuple(outputs),
                                      height=max(box.height, outputs[-1][0] + 1))
    net.rows = max(net.rows, row)


def _draw_coils(net: LadderNetwork, row: int, coils: list[Output]) -> None:
    """Parallel outputs from node (row, their column): coils in the coil column, a dialect's
    output boxes right-aligned before it (then every output hangs on the box's input node)."""
    column = net.columns - BOX_WIDTH if _has_box(coils) else net.coil_column
    for index, coil in enumerate(coils):
        if isinstance(coil, FunctionBox):
            for c in range(column, net.columns):
                net.cells.pop((row + index, c), None)
            net.cells[(row + index, column)] = coil
        else:
            for c in range(column, net.coil_column):
                net.cells[(row + index, c)] = WIRE
            net.cells[(row + index, net.coil_column)] = coil
        if index:
            net.links.add((row + index - 1, column))
    net.rows = max(net.rows, row + len(coils), 1)


def _has_box(coils: list[Output]) -> bool:
    return any(isinstance(coil, FunctionBox) for coil in coils)


def _outputs_width(rung: Rung) -> int:
    """Columns the output boxes need before the coil column (0 with coils only)."""
    groups = [rung.coils, *(coils for _block, coils in rung.chain)]
    todo = list(rung.branches)
    while todo:
        _block, coils, inner = todo.pop()
        groups.append(coils)
        todo.extend(inner)
    return BOX_WIDTH if any(_has_box(group) for group in groups) else 0


def _draw_chain(rung: Rung, columns: int) -> LadderNetwork:
    """Coil logic; an output chain continues from the end of the block before it, on the rows
    below that block's coils, joined to it by a vertical link."""
    assert rung.logic is not None
    segments = [(rung.logic, rung.coils), *rung.chain]
    places: list[tuple[int, int, int]] = []  # (row, entry column, exit column)
    row = col = 0
    for index, (block, coils) in enumerate(segments):
        w, h = size(block)
        places.append((row, col, col + w))
        if index + 1 < len(segments):
            below = row + max(h, len(coils))
            col += w
            row = below
    extra = _outputs_width(rung)
    net = LadderNetwork(max(columns, max(place[2] for place in places) + extra), 1)
    for index, ((block, coils), (row, entry, exit_)) in enumerate(
            zip(segments, places, strict=True)):
        place_logic(net, block, row, entry)
        if index:
            previous_row = places[index - 1][0]
            for r in range(previous_row, row):
                net.links.add((r, entry))
        for c in range(exit_, net.columns):
            net.cells[(row, c)] = WIRE
        net.rows = max(net.rows, row + size(block)[1])
        _draw_coils(net, row, coils)
    return net


def layout_network(instructions: list[Instruction] | tuple[Instruction, ...],
                   comments: list[str] | None = None,
                   columns: int = DEFAULT_COLUMNS) -> LadderNetwork:
    """The grid for one network's instructions.

    Code with no ladder picture, or too big for the grid, is kept as a listing. Code that is
    drawable but not in the standard coding (e.g. `RD a / RD.STK b / AND.STK`) is drawn, and
    its original coding kept in `source` (written back while the drawing means the same)."""
    comments = list(comments or [])
    try:
        rung = read_rung(instructions)
    except Undrawable:
        return LadderNetwork(columns, 1, comments=comments, listing=tuple(instructions))
    net = draw_rung(rung, columns)
    if net.columns > MAX_COLUMNS or net.rows > MAX_ROWS:
        return LadderNetwork(columns, 1, comments=comments, listing=tuple(instructions))
    net.comments = comments
    if code_rung(rung) != list(instructions) or has_bare_branch(rung.branches) \
            or (rung.coils and rung.branches) or _numbered_points(rung, instructions):
        net.source = tuple(instructions)  # a branch on its branch point reads as a chain too
    return net


def _numbered_points(rung: Rung, instructions: list[Instruction] | tuple[Instruction, ...]
                     ) -> bool:
    """Whether the branch points' numbers (Fatek's TR n) are not those a drawing is coded
    with afresh (then the coding is kept to write them again)."""
    if not any(params for _op, params in rung.stack_params):
        return False
    return code_rung(replace(rung, stack_params=[])) != list(instructions)


def _draw_branches(rung: Rung, columns: int) -> LadderNetwork:
    """Delta's MPS / MRD / MPP: the common logic from the rail, then each branch from its end
    (the branch point), one below the other, joined there by vertical links; a branch's own
    branches (nested MPS) from the end of its block, the same way."""
    assert rung.logic is not None
    common_w, common_h = size(rung.logic)
    net = LadderNetwork(max(columns, common_w + _branches_width(rung.branches)
                            + _outputs_width(rung)), 1)
    place_logic(net, rung.logic, 0, 0)
    # outputs before the MPS hang on the branch point, above the branches
    branches = [(None, rung.coils, []), *rung.branches] if rung.coils else rung.branches
    rows = _place_branches(net, branches, 0, common_w)
    net.rows = max(net.rows, rows, common_h)
    return net


def _branches_width(branches: list[Branch]) -> int:
    """Columns the branches need after their branch point."""
    return max((size(block)[0] if block is not None else 0) + _branches_width(inner)
               for block, _coils, inner in branches) if branches else 0


def _place_branches(net: LadderNetwork, branches: list[Branch], row: int, col: int) -> int:
    """Draw branches from the point at node (row, col), one below the other; the rows used."""
    start = last = row
    for block, coils, inner in branches:
        width, height = size(block) if block is not None else (0, 1)
        if block is not None:
            place_logic(net, block, row, col)
        if inner:
            height = max(height, _place_branches(net, inner, row, col + width))
        else:
            for c in range(col + width, net.columns):
                net.cells[(row, c)] = WIRE
            _draw_coils(net, row, coils)
            height = max(height, len(coils))
        last = row
        row += height
    for r in range(start, last):
        net.links.add((r, col))
    return row - start
