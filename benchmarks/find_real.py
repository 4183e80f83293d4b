"""Find and replace in the 37,883-step FANUC_STUDER_S41_F036: ms for the core's find, a
symbol, words, Find next in the window (also in comments and signal descriptions), Replace all
and its undo, and View › Fit width over every network; run from the repository root."""

from __future__ import annotations

import os
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from paint_watch import shown_console  # noqa: E402
from PySide6.QtWidgets import QApplication  # noqa: E402
from real_files import real_file  # noqa: E402

NAME = "FANUC_STUDER_S41_F036"


def _ms(began: float) -> float:
    return (time.perf_counter() - began) * 1000


def main() -> int:
    """Run the measurement and print the figures."""
    path = real_file(NAME)
    if path is None:
        print(f"no ../shared/real-programs/{NAME}.txt beside the repository", file=sys.stderr)
        return 1
    app = QApplication.instance() or QApplication(sys.argv)
    from ladderworks.core.il import parse_file
    from ladderworks.core.ladder import convert
    from ladderworks.core.ladder.find_replace import find, parse_query
    from ladderworks.gui.refcount_guard import guard_singletons

    guard_singletons()
    program = parse_file(path).program
    networks = convert.program_to_ladder(program).networks
    symbols = program.symbols
    steps = sum(len(n.instructions) for n in program.networks)
    print(f"{NAME}: {steps} steps, {len(networks)} networks, {len(symbols)} symbols")
    for text in ("R100", "X21.7", "ESP", "G8.4", "D"):
        query = parse_query(text, symbols)
        assert query is not None
        began = time.perf_counter()
        hits = find(networks, query, symbols)
        kind = "address" if query.address is not None else "words"
        print(f"core find {text!r:8} ({kind:7}): {len(hits):6} hits {_ms(began):7.1f} ms")
    with tempfile.TemporaryDirectory() as tmp:
        window = shown_console(Path(tmp))
        window.load(path)
        window.editor.finish_loading()
        app.processEvents()
        dialog = window.show_find(replacing=True)
        assert dialog is not None
        dialog.find_text.setText("R100")
        dialog.replace_text.setText("R7900")
        window.editor.move_cursor(0, 0, 0)
        began = time.perf_counter()
        dialog.find_next()
        app.processEvents()
        print(f"Find next (window, R100):         {_ms(began):7.1f} ms  {dialog.message.text()}")
        began = time.perf_counter()
        dialog.find_next()
        app.processEvents()
        print(f"Find next again (hits kept):      {_ms(began):7.1f} ms  {dialog.message.text()}")
        dialog.in_texts.setChecked(True)
        dialog.find_text.setText("spindle")
        began = time.perf_counter()
        dialog.find_next()
        app.processEvents()
        print(f"Find next in texts ('spindle'):   {_ms(began):7.1f} ms  {dialog.message.text()}")
        began = time.perf_counter()
        dialog.find_next()
        app.processEvents()
        print(f"again (texts' hits kept):         {_ms(began):7.1f} ms  {dialog.message.text()}")
        dialog.in_texts.setChecked(False)
        dialog.find_text.setText("R100")
        window.resize(1024, 600)
        app.processEvents()
        began = time.perf_counter()
        window.fit_width.set_enabled(True)
        app.processEvents()
        print(f"Fit width at 1024 px:             {_ms(began):7.1f} ms  zoom "
              f"{window.editor.zoom():.2f}, {window.fit_width.describe()}")
        window.fit_width.set_enabled(False)
        began = time.perf_counter()
        count = dialog.replace_all()
        app.processEvents()
        print(f"Replace all R100 -> R7900:        {_ms(began):7.1f} ms  {count} places, "
              f"{dialog.message.text()}")
        began = time.perf_counter()
        window.editor.undo_stack.undo()
        app.processEvents()
        print(f"its undo (one step):              {_ms(began):7.1f} ms")
        window.editor.undo_stack.setClean()
        window.close()
    load = os.getloadavg()
    print(f"load average: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} on {os.cpu_count()} cores")
    return 0


if __name__ == "__main__":
    sys.exit(main())
