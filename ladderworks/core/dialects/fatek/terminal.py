"""The simulated ASCII terminal FUN 94 writes to: lines wrapped at its width, pages."""

from __future__ import annotations

from ladderworks.core.dialects.fatek.ascii_format import LINE_FEED, PAGE_FEED

DEFAULT_COLUMNS = 80  # 004:171-176: a printer has 80 or 132 columns


class AsciiTerminal:
    """What a printer or terminal on Port 1 shows: text from the top-left, a new line at `/`
    or past the last column, a new page at `\\` (004:171-176)."""

    def __init__(self, columns: int = DEFAULT_COLUMNS) -> None:
        self.columns = columns
        self._parts: list[str] = []
        self._column = 0
        self.writes = 0  # how many ASCWR outputs were received

    def write(self, text: str) -> None:
        """Receive one output of ASCWR."""
        self.writes += 1
        for char in text:
            if char in (LINE_FEED, PAGE_FEED):
                self._parts.append(char)
                self._column = 0
                continue
            if self._column == self.columns:
                self._parts.append(LINE_FEED)
                self._column = 0
            self._parts.append(char)
            self._column += 1

    def text(self) -> str:
        """Everything received, pages separated by a form feed."""
        return "".join(self._parts)

    def clear(self) -> None:
        """Forget what was shown (a new run)."""
        self._parts.clear()
        self._column = 0
        self.writes = 0
