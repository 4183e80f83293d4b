"""Text under the ladder's elements: words wrapped to a cell's width, the last line elided."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import Qt
from PySide6.QtGui import QFontMetricsF

from ladderworks.core.ladder.model import FunctionBox, LadderNetwork, Wire

# Describes an address for the drawing: (signal name, description) or None.
SignalLookup = Callable[[object], tuple[str, str] | None]


def wrapped(text: str, metrics: QFontMetricsF, width: float, lines: int) -> list[str]:
    """`text` broken at spaces into at most `lines` lines no wider than `width`; a word longer
    than a line is broken inside; what does not fit ends the last line with an ellipsis."""
    words = text.split()
    result: list[str] = []
    line = ""
    while words and len(result) < lines:
        word = words[0]
        candidate = f"{line} {word}" if line else word
        if metrics.horizontalAdvance(candidate) <= width:
            line = candidate
            words.pop(0)
            continue
        if not line:  # one word wider than the line: break it
            cut = len(word)
            while cut > 1 and metrics.horizontalAdvance(word[:cut]) > width:
                cut -= 1
            line, words[0] = word[:cut], word[cut:]
        result.append(line)
        line = ""
    if line and len(result) < lines:
        result.append(line)
        line = ""
    rest = " ".join(words)
    if rest and result:
        last = result[-1] + " " + rest
        result[-1] = metrics.elidedText(last, Qt.TextElideMode.ElideRight, width)
    return result


def shows_comment(network: LadderNetwork, commented: Callable[[object], bool]) -> bool:
    """True when an element of `network` has a comment to show under it: its own, a box's,
    or one its address has (`commented`: the program's comment or the manual's text)."""
    for element in network.cells.values():
        if isinstance(element, Wire):
            continue
        if element.comment:
            return True
        if (not isinstance(element, FunctionBox) and element.address is not None
                and commented(element.address)):
            return True
    return False


class CommentedAddresses:
    """Which addresses have a comment to show (`describe` gives one), remembered per address:
    a 10,000-network program asks about the same few thousand addresses again and again.
    `forget()` when the symbols or the UI language change."""

    def __init__(self, describe: SignalLookup) -> None:
        self.describe = describe
        self.known: dict[object, bool] = {}

    def __call__(self, address: object) -> bool:
        """True when `address` has a comment (program's or manual's) to show."""
        known = self.known.get(address)
        if known is None:
            described = self.describe(address)
            known = self.known[address] = described is not None and bool(described[1])
        return known

    def forget(self) -> None:
        """Ask `describe` again from now on."""
        self.known.clear()
