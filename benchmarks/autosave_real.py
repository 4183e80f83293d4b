"""An autosave of the 37,883-step FANUC_STUDER_S41_F036 after one edit: ms the console is busy
for each copy (the program's text made again, then written), and ms of a full walk of the
cycle collector with the program laid out; run from the repository root."""

from __future__ import annotations

import gc
import os
import statistics
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
COPIES = 8


def main() -> int:
    """Open, edit one network, autosave COPIES times; print the figures."""
    path = real_file(NAME)
    if path is None:
        print(f"no ../shared/real-programs/{NAME}.txt beside the repository", file=sys.stderr)
        return 1
    app = QApplication.instance() or QApplication([])
    with tempfile.TemporaryDirectory() as folder:
        window = shown_console(Path(folder))
        window.load(path)
        window.editor.finish_loading()
        window.editor.move_cursor(0, 0, 0)
        window.editor.invert_at_cursor()  # one edit: the copy is of unsaved work
        app.processEvents()
        copies = []
        for _ in range(COPIES):
            start = time.perf_counter()
            window.autosaver.save_now()
            copies.append((time.perf_counter() - start) * 1000)
        start = time.perf_counter()
        gc.collect()
        walk = (time.perf_counter() - start) * 1000
        frozen = gc.get_freeze_count()
        window.recovery.remove()
        window.editor.model.mark_saved()
        window.close()
    print(f"{NAME}: autosave after one edit, {COPIES} copies")
    print(f"one copy:        median {statistics.median(copies):6.0f} ms  worst "
          f"{max(copies):6.0f} ms")
    print(f"full collection: {walk:6.1f} ms  ({frozen:,} objects frozen after the layout)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
