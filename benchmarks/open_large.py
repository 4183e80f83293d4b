"""Open a generated 2,000-network program in the console and print the ms from open to painted."""

from __future__ import annotations

import os
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

from paint_watch import PaintWatch, shown_console
from PySide6.QtWidgets import QApplication

NETWORKS = 2000


def generate(count: int) -> str:
    """A program of `count` networks in the styles of the seed examples (series, OR, NOT, TMR)."""
    lines = ["%@3"]
    for n in range(count):
        byte, bit = divmod(n, 8)
        lines.append(f"// NETWORK {n + 1}")
        kind = n % 4
        if kind == 0:
            lines += [f"RD X{byte % 100}.{bit}", f"AND.NOT R{byte}.{bit}",
                      f"WRT R{1000 + byte}.{bit}"]
        elif kind == 1:
            lines += [f"RD F{byte % 700}.{bit}", f"AND R{byte}.{bit}", f"OR R{2000 + byte}.{bit}",
                      f"AND.NOT X{byte % 100}.{bit}", f"WRT R{2000 + byte}.{bit}"]
        elif kind == 2:
            lines += [f"RD.NOT X{byte % 100}.{bit}", f"RD.STK R{byte}.{bit}",
                      f"AND R{3000 + byte}.{bit}", "OR.STK", f"WRT.NOT Y{byte % 100}.{bit}"]
        else:
            lines += [f"RD R{byte}.{bit}", f"TMR {n % 100 + 1}", f"WRT R{4000 + byte}.{bit}"]
        lines.append("")
    lines.append("%")
    return "\n".join(lines) + "\n"


def main() -> int:
    """Run the measurement and print the figures."""
    app = QApplication.instance() or QApplication(sys.argv)
    from ladderworks.gui.refcount_guard import guard_singletons

    guard_singletons()

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "large.LAD"
        path.write_text(generate(NETWORKS), encoding="utf-8")
        window = shown_console(Path(tmp))
        watch = PaintWatch()
        window.editor.viewport().installEventFilter(watch)
        watch.painted = False
        start = time.perf_counter()
        window.load(path)
        window.editor.viewport().update()
        while not watch.painted:
            app.processEvents()
        painted = time.perf_counter() - start
        count = len(window.editor.networks) - 1
        start = time.perf_counter()
        window.editor.verticalScrollBar().setValue(window.editor.verticalScrollBar().maximum())
        watch.painted = False
        while not watch.painted:
            app.processEvents()
        scrolled = time.perf_counter() - start
        window.editor.undo_stack.setClean()
        window.close()
    print(f"networks opened: {count}")
    print(f"open to painted: {painted * 1000:.0f} ms (goal under 1000 ms)")
    print(f"scroll to the end and paint: {scrolled * 1000:.0f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
