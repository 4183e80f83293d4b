"""Grid → program: decompose a drawn network into series/parallel blocks and code it."""

from __future__ import annotations

from collections.abc import Callable
from itertools import pairwise

from ladderworks.core.diagnostics import Diagnostic, has_errors
from ladderworks.core.il.program import Instruction
from ladderworks.core.instructions import Kind, StackOp
from ladderworks.core.ladder.grid_graph import Edge as _Edge
from ladderworks.core.ladder.grid_graph import cycle_edge as _cycle_edge
from ladderworks.core.ladder.grid_graph import joined as _joined
from ladderworks.core.ladder.grid_graph import reach as _reach
from ladderworks.core.ladder.grid_graph import reduce_block as _reduce
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.logic import (
    MAX_PUSHES,
    Branch,
    ContactPlace,
    Leaf,
    Logic,
    Output,
    Rung,
    code_rung,
    inverted_inside,
    outputs_first,
    stack_row,
)
from ladderworks.core.ladder.model import Cell, Coil, Contact, FunctionBox, LadderNetwork, Wire
from ladderworks.core.ladder.reading import Undrawable, read_rung
from ladderworks.core.ladder.row_contacts import contact_combine


class NodeNets:
    """Union-find over grid nodes: wires and vertical links join nodes into nets."""

    def __init__(self, network: LadderNetwork) -> None:
        self.width = network.columns + 2
        rows = network.used_rows()
        self.parent = list(range(rows * self.width))
        for r in range(1, rows):
            self.union((0, 0), (r, 0))
        for (r, c), element in network.cells.items():
            if isinstance(element, Wire) and c < network.columns:
                self.union((r, c), (r, c + 1))
        for r, k in network.links:
            if 0 <= k <= network.columns:
                self.union((r, k), (r + 1, k))

    def _find(self, i: int) -> int:
        while self.parent[i] != i:
            self.parent[i] = self.parent[self.parent[i]]
            i = self.parent[i]
        return i

    def union(self, a: Cell, b: Cell) -> None:
        """Join the nets of two nodes."""
        ra, rb = self.net(a), self.net(b)
        if ra != rb:
            self.parent[max(ra, rb)] = min(ra, rb)

    def net(self, node: Cell) -> int:
        """The net of node (row, k)."""
        return self._find(node[0] * self.width + node[1])


def read_grid(network: LadderNetwork, index: int | None = None, dialect: str = "seed",
              branches: bool = False) -> tuple[Rung | None, list[Diagnostic]]:
    """The network's meaning, or None with diagnostics at the cells (None, [] when empty).

    Box parameters are checked with the ranges of the program's `dialect` ("seed"/"fanuc").
    `branches`: coils on several points read as MPS/MRD/MPP branches even where they read
    as an output chain too (a branch whose coils hang on the branch point)."""
    rung, diags = _read_grid(network, index, dialect, branches)
    if rung is not None:
        inner = inverted_inside(rung)
        if inner is not None:  # INV in a block: its code would invert the block only
            diags.append(Diagnostic("inv-place", {}, network=index, cell=inner))
            return None, diags
        try:
            code_rung(rung)
        except ContactPlace as place:  # an edge/comparison contact its dialect cannot code
            diags.append(Diagnostic("contact-place", {}, network=index,
                                    cell=place.cell or (0, 0)))
            return None, diags
    return rung, diags


def _read_grid(network: LadderNetwork, index: int | None, dialect: str,
               branches: bool = False) -> tuple[Rung | None, list[Diagnostic]]:
    """read_grid without the check that each dialect contact can be coded where it stands."""
    diags: list[Diagnostic] = []

    def report(code: str, cell: Cell, **args: object) -> None:
        diags.append(Diagnostic(code, dict(args), network=index, cell=cell))

    nets = NodeNets(network)
    left = nets.net((0, 0))
    edges: list[_Edge] = []
    coils: list[tuple[Cell, Output, int]] = []
    boxes: list[tuple[Cell, FunctionBox]] = []
    for (r, c), element in network.elements():
        if isinstance(element, Contact | Coil) and element.address is None \
                and not (isinstance(element, Contact) and element.function):
            report("no-address", (r, c))
        if isinstance(element, Contact):
            src, dst = nets.net((r, c)), nets.net((r, c + 1))
            if src == dst:
                report("short-circuit", (r, c))
            else:
                edges.append(_Edge(src, dst, Leaf(element, (r, c)), (r, c)))
        elif isinstance(element, Coil):
            if c != network.coil_column:
                report("coil-not-right", (r, c))
            coils.append(((r, c), element, nets.net((r, c))))
        elif isinstance(element, FunctionBox):
            boxes.append(((r, c), element))
    if boxes and all(item.spec.output for _, item in boxes) and (coils or len(boxes) > 1):
        for (r, c), item in boxes:  # a dialect's output boxes among its coils: outputs too
            if c + item.width != network.columns:
                report("coil-not-right", (r, c))
            coils.append(((r, c), item, nets.net((r + (item.pins[0] if item.pins else 0), c))))
        boxes = []
    if not coils and not boxes:
        if network.cells:
            report("empty-network", min(network.cells))
        return None, diags
    if len(boxes) > 1:
        report("box-twice", boxes[1][0], name=boxes[1][1].name)
        return None, diags

    box_anchor, box = boxes[0] if boxes else ((0, 0), None)
    targets: list[int] = []
    output: int | None = None
    if box is not None:
        br, bc = box_anchor
        problems = _box_param_problems(box, dialect)
        for problem in problems:
            report(problem.code, box_anchor, **problem.args)
        targets = [nets.net((br + p, bc)) for p in box.pins]
        if box.has_output and bc + box.width <= network.columns:
            output = nets.net((br, bc + box.width))
        pin_nets = [nets.net((br + offset, bc + box.width)) for offset, _ in box.outputs]
        if len({output, *pin_nets}) < len(pin_nets) + 1:
            report("coil-branch", box_anchor)  # two output pins joined
        pin_blocks, pin_ends, edges = _pin_blocks(pin_nets, edges, coils, box_anchor, report)
        for cell, _, net in coils:
            if output is None and net not in pin_ends:
                report("box-output", cell, name=box.name)
            elif net != output and net not in pin_ends:
                report("coil-branch", cell)
        for i, target in enumerate(targets):
            if target == left:
                report("short-circuit", (br + box.pins[i], bc))
            if target in targets[:i]:
                report("short-circuit", (br + box.pins[i], bc))
        if output is not None or pin_nets:
            after = _reach({n for n in (output, *pin_nets) if n is not None}, edges, True)
            for e in edges:
                if e.src in after:
                    report("box-output", e.cell, name=box.name)
            edges = [e for e in edges if e.src not in after]
    else:
        coils.sort(key=lambda item: item[0])
        for cell, _, net in coils:
            if net == left:
                report("coil-on-rail", cell)
            elif net not in targets:
                targets.append(net)
        targets = targets or [left]

    fed = _reach({left}, edges, True)
    feeding = _reach(set(targets), edges, False)
    goal = set(targets)
    for e in edges:
        if e.src not in fed:
            code = "reverse-flow" if _joined(e.src, {left}, edges, e) else "not-connected"
            report(code, e.cell)
        elif e.dst not in feeding:
            code = "reverse-flow" if _joined(e.dst, goal, edges, e) else "open-circuit"
            report(code, e.cell)
    if box is None:
        for cell, _, net in coils:
            if net != left and net not in fed:
                report("not-connected", cell)
    else:
        missing = [t for t in targets if t not in fed or t == left]
        if missing:
            report("box-inputs", box_anchor, name=box.name, count=len(box.pins))
    if has_errors(diags):
        return None, diags

    useful = [e for e in edges if e.src in fed and e.dst in feeding]
    cycle = _cycle_edge(useful)
    if cycle is not None:
        report("reverse-flow", cycle.cell)
        return None, diags
    if box is None:
        if len(targets) > 1 and stack_row(StackOp.DUP, dialect) is not None:
            chain, _ = _read_chain(left, targets, useful, coils, lambda *a, **k: None, [])
            branched = (_read_branches(left, targets, useful, coils)
                        if chain is None or branches else None)
            if branched is not None:
                branched.stack_dialect = dialect
                _check_depth(branched, report)
                return (None if has_errors(diags) else branched), diags
        return _read_chain(left, targets, useful, coils, report, diags)
    blocks: list[Logic] = []
    owner: dict[int, int] = {}
    for i, target in enumerate(targets):
        part = [e for e in useful if e.dst in _reach({target}, useful, False)]
        for e in part:
            if id(e) in owner:
                report("bridge", e.cell)
                return None, diags
            owner[id(e)] = i
        result = _reduce(part, left, target)
        if isinstance(result, _Edge):
            report("bridge", result.cell)
            return None, diags
        blocks.append(result)
    own = [item for item in coils if item[2] not in pin_ends]
    pins = [(contact, block, [item for item in coils if item[2] == net])
            for (_, contact), block, net in zip(box.outputs, pin_blocks, pin_ends, strict=True)]
    rung = Rung(box=box, inputs=blocks, coils=[coil for _, coil, _ in own],
                pins=[(contact, block, [coil for _, coil, _ in items])
                      for contact, block, items in pins],
                box_cell=box_anchor,
                coil_cells=[cell for cell, _, _ in own]
                + [cell for _, _, items in pins for cell, _, _ in items])
    _check_depth(rung, report)
    if has_errors(diags):
        return None, diags
    return rung, diags


def _pin_blocks(pin_nets: list[int], edges: list[_Edge], coils: list, box_cell: Cell,
                report: Callable[..., None]
                ) -> tuple[list[Logic | None], list[int], list[_Edge]]:
    """Each output pin's block in series after it (None: its coils hang on the pin) and the
    net its coils hang on; the edges left for the box's inputs. A pin's contacts must all lead
    to one net of coils, and no other path may reach them."""
    blocks: list[Logic | None] = []
    ends: list[int] = []
    taken: set[int] = set()
    for pin in pin_nets:
        reach = _reach({pin}, edges, True)
        own = [e for e in edges if e.src in reach]
        taken.update(id(e) for e in own)
        if not own:
            blocks.append(None)
            ends.append(pin)
            continue
        hung = {net for _, _, net in coils if net in reach}
        if len(hung) != 1:
            report("open-circuit" if not hung else "coil-branch", own[0].cell)
            blocks.append(None)
            ends.append(pin)
            continue
        end = hung.pop()
        feeding = _reach({end}, own, False)
        for e in own:
            if e.dst not in feeding:
                report("open-circuit", e.cell)
        entering = [e for e in edges if e.dst in reach and e.src not in reach]
        if entering:
            report("bridge", entering[0].cell)  # other logic joins the pin's block
        result = _reduce([e for e in own if e.dst in feeding], pin, end)
        if isinstance(result, _Edge):
            report("bridge", result.cell)
            blocks.append(None)
        else:
            blocks.append(result)
        ends.append(end)
    if len(set(ends)) < len(ends):
        report("coil-branch", box_cell)  # two pins' blocks joined
    return blocks, ends, [e for e in edges if id(e) not in taken]


def _read_chain(left: int, outputs: list[int], useful: list[_Edge],
                coils: list[tuple[Cell, Output, int]], report: Callable[..., None],
                diags: list[Diagnostic]) -> tuple[Rung | None, list[Diagnostic]]:
    """Coil logic: one output net, or an output chain where each next output is reached only
    through the one before it (`WRT y / AND b / WRT z`)."""
    after = {o: _reach({o}, useful, True) for o in outputs}
    order = sorted(outputs, key=lambda o: -len(after[o] & set(outputs)))
    first_coil = {net: cell for cell, _, net in reversed(coils)}
    for a, b in pairwise(order):
        if b not in after[a]:
            report("coil-branch", first_coil[b])
            return None, diags
    blocks: list[Logic] = []
    covered: set[int] = set()
    start = left
    for target in order:
        into = _reach({target}, useful, False)
        out_of = _reach({start}, useful, True)
        part = [e for e in useful if e.src in out_of and e.dst in into]
        covered.update(id(e) for e in part)
        result = _reduce(part, start, target)
        if isinstance(result, _Edge):
            report("bridge", result.cell)
            return None, diags
        blocks.append(result)
        start = target
    stray = [e for e in useful if id(e) not in covered]
    if stray:
        report("coil-branch", first_coil[order[-1]])
        return None, diags
    groups = [[coil for _, coil, net in coils if net == o] for o in order]
    rung = Rung(logic=blocks[0], coils=groups[0], chain=list(zip(blocks[1:], groups[1:],
                                                                   strict=True)),
                coil_cells=[cell for o in order for cell, _, net in coils if net == o])
    _check_depth(rung, report)
    if has_errors(diags):
        return None, diags
    return rung, diags


def _read_branches(left: int, outputs: list[int], useful: list[_Edge],
                   coils: list[tuple[Cell, Output, int]]) -> Rung | None:
    """Coils on several branches from one point (a dialect with MPS/MRD/MPP): the logic from
    the rail to that point, then each branch's block and coils, top to bottom; outputs whose
    paths from the point share an edge are one branch with branches of its own (nested MPS),
    read the same way from that point. None when the drawing is not so (each edge must belong
    to the common part or to one branch, a branch's outputs on rows next to each other)."""
    back = {o: _reach({o}, useful, False) for o in outputs}
    common = set.intersection(*back.values()) - {left}
    if not common:
        return None
    point = min(common, key=lambda n: len(_reach({n}, useful, True)))
    after = _reach({point}, useful, True)
    into = _reach({point}, useful, False)
    first_row = {net: cell for cell, _, net in reversed(coils)}
    order = sorted(outputs, key=lambda o: first_row[o])
    shared = [e for e in useful if e.dst in into]
    parts = {o: [e for e in useful if e.src in after and e.dst in back[o]] for o in order}
    groups: list[list[int]] = []  # outputs whose paths share an edge, in row order
    for target in order:
        ids = {id(e) for e in parts[target]}
        joined = [g for g in groups if any(ids & {id(e) for e in parts[o]} for o in g)]
        if len(joined) > 1 or (joined and joined[0] is not groups[-1]):
            return None  # not a nesting: a branch's outputs must follow each other
        if joined:
            joined[0].append(target)
        else:
            groups.append([target])
    owner: dict[int, int] = {id(e): -1 for e in shared}
    branches: list[Branch] = []
    for index, group in enumerate(groups):
        part = list({id(e): e for o in group for e in parts[o]}.values())
        for e in part:
            if id(e) in owner:
                return None
            owner[id(e)] = index
        if len(group) > 1:
            inner = _read_branches(point, group, part, coils)
            if inner is None or inner.logic is None:
                return None
            branches.append((inner.logic, [], inner.branches))
            continue
        target = group[0]
        block = _reduce(part, point, target) if target != point else None
        if isinstance(block, _Edge) or (block is None and part):
            return None
        branches.append((block, [coil for _, coil, net in coils if net == target], []))
    logic = _reduce(shared, left, point)
    if isinstance(logic, _Edge) or len(owner) != len(useful):
        return None
    return Rung(logic=logic, branches=branches,
                coil_cells=[cell for o in order for cell, _, net in coils if net == o])


def _box_param_problems(box: FunctionBox, dialect: str = "seed") -> list[Diagnostic]:
    """The parser's complaints about a box's parameters (count, kinds, ranges); a dialect's
    box (Delta TMR) holds the values its reader made, which the compiler checks see."""
    if box.spec.dialect:
        return []
    from ladderworks.core.il.printer import print_instruction
    from ladderworks.core.ladder.edits import function_params

    words = print_instruction(Instruction(box.name, params=box.params)).split()
    return function_params(box.name, words[1:], dialect)[1]


def _check_depth(rung: Rung, report: Callable[..., None]) -> None:
    cells: list[Cell | None] = []
    depth = 0
    try:
        code = code_rung(rung, cells)
    except ContactPlace:  # read_grid reports it
        return
    for ins, cell in zip(code, cells, strict=True):
        joins = ins.spec.kind is Kind.BASIC or contact_combine(ins.spec) is not None
        depth += ins.spec.pushes if joins else 0
        if depth > MAX_PUSHES:
            report("stack-depth", cell or (0, 0))
            return
        if not joins:
            depth = 0


def network_to_instructions(network: LadderNetwork, index: int | None = None,
                            dialect: str = "seed"
                            ) -> tuple[list[Instruction] | None, list[Diagnostic]]:
    """The instruction list of a drawn network, or None with the diagnostics at the cells.

    A network kept as a listing gives its listing; a network read from text whose drawing still
    means exactly the same gives its original coding back."""
    if network.listing is not None:
        return list(network.listing), []
    if network.source is not None:
        drawn = layout_network(network.source, network.comments)
        if drawn.source is not None and drawn == network:  # still as drawn from its coding
            return list(network.source), []
    rung, diags = read_grid(network, index, dialect)
    if rung is None:
        return None, diags
    code = code_rung(rung)
    if network.source is not None:
        try:
            was = read_rung(network.source)
        except Undrawable:
            was = None
        original = code_rung(was) if was is not None else None
        if original == code:
            return list(network.source), diags
        if was is not None and was.branches and stack_row(StackOp.DUP, dialect) is not None:
            # read from MPS/MRD/MPP branches: a branch on the branch point reads as an output
            # chain too; the branches are kept (changed or not)
            branched, _ = read_grid(network, index, dialect, branches=True)
            if branched is not None:
                branched.stack_params = was.stack_params  # its branch points' numbers kept
                again = code_rung(branched)
                same = again == original or code_rung(outputs_first(branched)) == original
                return (list(network.source) if same else again), diags
    return code, diags

