"""PLC › Compile (F9) of the 37,883-step FANUC_STUDER_S41_F036 in the console, as a technician
presses it: ms until the program is compiled, loaded into the simulated PLC and every dock has
taken it, and where the time goes; also Check (F7). Run from the repository root."""

from __future__ import annotations

import cProfile
import os
import pstats
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
RUNS = 3


def _ms(action: object) -> float:
    """Wall ms of triggering a QAction and handling the events it posted."""
    start = time.perf_counter()
    action.trigger()  # type: ignore[attr-defined]
    QApplication.processEvents()
    return (time.perf_counter() - start) * 1000


def main() -> int:
    """Open the program, press F7 and F9 RUNS times each; print the figures (`--profile`:
    the functions that take the time of one F9)."""
    path = real_file(NAME)
    if path is None:
        print(f"no ../shared/real-programs/{NAME}.txt beside the repository", file=sys.stderr)
        return 1
    app = QApplication.instance() or QApplication([])
    with tempfile.TemporaryDirectory() as folder:
        window = shown_console(Path(folder))
        window.load(path)
        window.editor.finish_loading()
        app.processEvents()
        check = [_ms(window.actions_by_name["action_check"]) for _ in range(RUNS)]
        compile_ = [_ms(window.actions_by_name["action_compile"]) for _ in range(RUNS)]
        message = window.statusBar().currentMessage()
        if "--profile" in sys.argv:
            profile = cProfile.Profile()
            profile.enable()
            window.actions_by_name["action_compile"].trigger()
            app.processEvents()
            profile.disable()
            pstats.Stats(profile).sort_stats("cumulative").print_stats(40)
        window.close()
    print(f"{NAME}: F7 / F9 in the console, {RUNS} times each")
    print(f"check (F7):    first {check[0]:7.0f} ms  best {min(check):7.0f} ms")
    print(f"compile (F9):  first {compile_[0]:7.0f} ms  best {min(compile_):7.0f} ms")
    print(f"status bar:    {message}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
