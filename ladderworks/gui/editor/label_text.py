"""Text under the ladder's elements: words wrapped to a cell's width, the last line elided."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QFontMetricsF


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
