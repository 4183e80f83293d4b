"""Where things are drawn: cell sizes, network heights and hit-testing of scene points."""

from __future__ import annotations

import bisect
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from enum import Enum

from ladderworks.core.ladder.model import LadderNetwork

CELL_W = 84.0
COMMENT_H = 20.0
LISTING_LINE_H = 18.0
LEFT = 72.0  # room for the network number left of the left rail: five digits (N10821, D10821)
GAP = 10.0  # space between networks
SPARE_ROWS = 1  # an empty row drawn under each network: clicking there adds a row


class NameDisplay(Enum):
    """What the ladder shows with each element (View › Element names)."""

    ADDRESS = "address"  # the address only
    SYMBOL = "symbol"  # the address and its symbol
    COMMENT = "comment"  # the address, its symbol and two lines of comment


@dataclass(frozen=True, slots=True)
class RowMetrics:
    """A grid row for one name display: its height and where its wire runs."""

    height: float
    wire: float  # y of the wire (and of the contacts' middle) inside the row
    symbol: bool  # a symbol line under the element
    comment_lines: int  # wrapped comment lines under the symbol


ROW_METRICS = {
    NameDisplay.ADDRESS: RowMetrics(48.0, 28.0, False, 0),
    NameDisplay.SYMBOL: RowMetrics(60.0, 30.0, True, 0),
    NameDisplay.COMMENT: RowMetrics(86.0, 30.0, True, 2),
}
DEFAULT_DISPLAY = NameDisplay.COMMENT
TALL_SCREEN = 900  # px of available screen height from which comments are shown by default
_shown = [DEFAULT_DISPLAY]  # one choice for every ladder view of the application


def default_display(screen_height: int) -> NameDisplay:
    """What is shown before the user chooses: everything on a tall screen; on a lower one
    (a 1024×600 shop-floor panel, a 768-pixel laptop) the address and symbol, so that more
    rows fit (View › Element names adds the comments)."""
    return DEFAULT_DISPLAY if screen_height >= TALL_SCREEN else NameDisplay.SYMBOL


def name_display() -> NameDisplay:
    """What the ladder views show with each element now."""
    return _shown[0]


def set_name_display(display: NameDisplay) -> None:
    """Choose what the ladder views show (views must lay out again: `relayout()`)."""
    _shown[0] = display


def row_metrics() -> RowMetrics:
    """The rows of the current name display."""
    return ROW_METRICS[_shown[0]]


def cell_h() -> float:
    """Height of the tallest grid row of the current display (a network whose elements have
    no comment to show has shorter rows: `network_rows`)."""
    return ROW_METRICS[_shown[0]].height


def wire_y() -> float:
    """Y of the wire inside the tallest row of the current display."""
    return ROW_METRICS[_shown[0]].wire


# Whether a network has an element comment to show (the views know the program's symbols).
CommentCheck = Callable[[LadderNetwork], bool]


def network_rows(network: LadderNetwork, commented: CommentCheck | None) -> RowMetrics:
    """The rows of one network: with comments shown, a network none of whose elements has a
    comment gets the shorter address-and-symbol rows (`commented` None: every network has)."""
    display = _shown[0]
    if display is NameDisplay.COMMENT and commented is not None and not commented(network):
        return ROW_METRICS[NameDisplay.SYMBOL]
    return ROW_METRICS[display]


def network_height(network: LadderNetwork, rows: RowMetrics) -> float:
    """Height of a network's drawing: comment lines plus its rows (or its kept listing)."""
    comments = len(network.comments) * COMMENT_H
    if network.listing is not None:
        return comments + max(len(network.listing), 1) * LISTING_LINE_H + 8
    return comments + (network.rows + SPARE_ROWS) * rows.height + GAP


def network_width(network: LadderNetwork) -> float:
    """Width of a network's drawing, rails included."""
    return LEFT + (network.columns + 1) * CELL_W + 8


def typical_width(networks: Sequence[LadderNetwork], share: float = 0.95) -> float:
    """The widest of the narrowest `share` of the networks' drawings (all of a small program):
    what a fitted zoom shows whole, leaving a few unusually wide networks to scroll."""
    widths = sorted(network_width(network) for network in networks)
    return widths[max(math.ceil(len(widths) * share) - 1, 0)] if widths else 0.0


def grid_top(network: LadderNetwork) -> float:
    """Y of the first row inside the network's item."""
    return len(network.comments) * COMMENT_H


def cell_origin(network: LadderNetwork, row: int, col: int,
                rows: RowMetrics) -> tuple[float, float]:
    """Top-left corner of a cell inside the network's item (its rows are `rows`)."""
    return LEFT + col * CELL_W, grid_top(network) + row * rows.height


def cell_centre(network: LadderNetwork, row: int, col: int,
                rows: RowMetrics) -> tuple[float, float]:
    """Centre of a cell inside the network's item."""
    x, y = cell_origin(network, row, col, rows)
    return x + CELL_W / 2, y + rows.height / 2


def node_point(network: LadderNetwork, row: int, node: int,
               rows: RowMetrics) -> tuple[float, float]:
    """A grid node (left edge of column `node`, middle of `row`) inside the network's item."""
    return LEFT + node * CELL_W, grid_top(network) + row * rows.height + rows.wire


@dataclass(frozen=True, slots=True)
class Hit:
    """What a scene point falls on: a network, and a cell / node or a comment line in it."""

    network: int
    row: int = 0
    col: int = 0
    node: int = 0
    comment_line: int | None = None  # index of the network comment line under the point


class Layout:
    """The vertical stacking of networks and each one's rows; maps scene points to cells.
    `commented` tells which networks have element comments to show (their rows are taller
    when comments are shown)."""

    def __init__(self, commented: CommentCheck | None = None) -> None:
        self.commented = commented
        self.tops: list[float] = []
        self.heights: list[float] = []
        self.rows: list[RowMetrics] = []
        # each network's rows, worked out once (a real program has 10,000 networks)
        self._known: dict[int, tuple[LadderNetwork, RowMetrics]] = {}

    def forget(self, network: LadderNetwork | None = None) -> None:
        """Work out `network`'s rows again (it changed), or every network's (None: the name
        display, the symbols or the language changed)."""
        if network is None:
            self._known.clear()
        else:
            self._known.pop(id(network), None)

    def _rows(self, network: LadderNetwork) -> RowMetrics:
        known = self._known.get(id(network))
        if known is not None and known[0] is network:
            return known[1]
        rows = network_rows(network, self.commented)
        self._known[id(network)] = (network, rows)
        return rows

    def rebuild(self, networks: list[LadderNetwork], start: int = 0) -> None:
        """Recompute rows, tops and heights from network `start` on."""
        del self.tops[start:]
        del self.heights[start:]
        del self.rows[start:]
        y = self.tops[-1] + self.heights[-1] if self.tops else 0.0
        for network in networks[start:]:
            rows = self._rows(network)
            height = network_height(network, rows)
            self.tops.append(y)
            self.heights.append(height)
            self.rows.append(rows)
            y += height

    def total_height(self) -> float:
        """Height of the whole document."""
        return self.tops[-1] + self.heights[-1] if self.tops else 0.0

    def network_at(self, y: float) -> int:
        """Index of the network whose band holds scene y (clamped)."""
        if not self.tops:
            return 0
        index = bisect.bisect_right(self.tops, y) - 1
        return min(max(index, 0), len(self.tops) - 1)

    def shown(self, top: float, bottom: float) -> range:
        """The networks whose bands the scene's ys `top` .. `bottom` reach (none when empty)."""
        if not self.tops:
            return range(0)
        return range(self.network_at(top), self.network_at(bottom) + 1)

    def hit(self, networks: list[LadderNetwork], x: float, y: float) -> Hit:
        """The network and cell (or comment line) under a scene point."""
        index = self.network_at(y)
        network = networks[index]
        local_y = y - self.tops[index]
        top = grid_top(network)
        col = int((x - LEFT) // CELL_W)
        col = min(max(col, 0), network.columns)
        node = round((x - LEFT) / CELL_W)
        node = min(max(node, 0), network.columns)
        if local_y < top:
            return Hit(index, 0, col, node, int(local_y // COMMENT_H))
        row = int((local_y - top) // self.rows[index].height)
        row = min(max(row, 0), network.rows - 1 + SPARE_ROWS)
        return Hit(index, row, col, node)
