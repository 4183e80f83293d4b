"""Open the 37,883-step FANUC_STUDER_S41_F036 in the console: ms to parse, lay out and paint,
resident memory (`ladderworks-cli check` of it: benchmarks/check_real.py); run from the
repository root. An argument chooses View › Element names (`address`, `symbol`, `comment`;
default: the screen's)."""

from __future__ import annotations

import os
import resource
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from paint_watch import PaintWatch, shown_console  # noqa: E402
from PySide6.QtWidgets import QApplication  # noqa: E402
from real_files import real_file  # noqa: E402

NAME = "FANUC_STUDER_S41_F036"


def _rss_mb() -> float:
    """The current resident set size in MB (from /proc, else the peak)."""
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def main() -> int:
    """Run the measurement and print the figures."""
    path = real_file(NAME)
    if path is None:
        print(f"no ../shared/real-programs/{NAME}.txt beside the repository", file=sys.stderr)
        return 1
    app = QApplication.instance() or QApplication(sys.argv)
    from ladderworks.core.il import parse_bytes, parse_file
    from ladderworks.gui.refcount_guard import guard_singletons

    guard_singletons()
    import ladderworks.gui.document as document  # the window reads through ProgramDocument

    parsed: list[float] = []

    def timed_parse(data: bytes) -> object:
        began = time.perf_counter()
        found = parse_bytes(data)
        parsed.append(time.perf_counter() - began)
        return found

    document.parse_bytes = timed_parse  # type: ignore[assignment]
    start = time.perf_counter()
    result = parse_file(path)
    parse_ms = (time.perf_counter() - start) * 1000
    steps = sum(len(n.instructions) for n in result.program.networks)
    del result
    with tempfile.TemporaryDirectory() as tmp:
        window = shown_console(Path(tmp), sys.argv[1] if len(sys.argv) > 1 else None)
        watch = PaintWatch()
        window.editor.viewport().installEventFilter(watch)
        watch.painted = False
        start = time.perf_counter()
        window.load(path)
        loaded = time.perf_counter() - start
        window.editor.viewport().update()
        while not watch.painted:
            app.processEvents()
        painted = time.perf_counter() - start
        while window.editor.loading:  # the rest is laid out in the background
            app.processEvents()
        laid_out = time.perf_counter() - start
        rss = _rss_mb()
        names = window.names_menu.group.checkedAction().objectName().removeprefix("action_names_")
        height = window.editor.layout_.total_height()
        count = len(window.editor.networks) - 1
        made = window.editor.network_items.made_count()
        start = time.perf_counter()
        bar = window.editor.verticalScrollBar()
        bar.setValue(bar.maximum() // 2)
        watch.painted = False
        while not watch.painted:
            app.processEvents()
        scrolled = time.perf_counter() - start
        window.editor.undo_stack.setClean()
        window.close()
    load = os.getloadavg()
    print(f"{NAME}: {steps} steps, {count} networks ({made} graphics items made)")
    print(f"element names: {names}; document height {height:.0f} px")
    print(f"parse alone (first):    {parse_ms:7.0f} ms")
    print(f"open to painted:        {painted * 1000:7.0f} ms (goal under 500 ms)")
    print(f"  parse inside open:    {parsed[0] * 1000:7.0f} ms")
    print(f"  GUI (lay out, items, paint): {(painted - parsed[0]) * 1000:4.0f} ms "
          f"(load() returned after {loaded * 1000:.0f} ms)")
    print(f"all laid out (background): {laid_out * 1000:4.0f} ms")
    print(f"scroll to the middle:   {scrolled * 1000:7.0f} ms")
    print(f"resident memory open:   {rss:7.0f} MB (goal under 400 MB)")
    print(f"load average:           {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} "
          f"on {os.cpu_count()} cores")
    return 0


if __name__ == "__main__":
    sys.exit(main())
