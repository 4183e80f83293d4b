"""Prints ms to build the cross reference of each real FANUC program (../shared/real-programs)
from the parsed program and from the console's ladder grid, µs per query, and, with --pdf, the
seconds and pages of File › Export PDF of the whole program (offscreen).
Run from the repository root: python3 benchmarks/xref_real.py [--pdf]
"""

from __future__ import annotations

import os
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from real_files import NAMES, median_ms, real_folder  # noqa: E402

from ladderworks.core.il import parse_bytes  # noqa: E402
from ladderworks.core.ladder.convert import program_to_ladder  # noqa: E402
from ladderworks.core.xref import CrossReference  # noqa: E402


def _pdf(path: Path) -> tuple[float, int]:
    """Seconds and pages of Export PDF of the program, in an offscreen console."""
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QApplication

    from ladderworks.gui import print_actions
    from ladderworks.gui.main_window import MainWindow
    from ladderworks.gui.settings import Settings
    from ladderworks.gui.translation import UiLanguage

    app = QApplication.instance() or QApplication([])
    with tempfile.TemporaryDirectory() as folder:
        settings = Settings(QSettings(str(Path(folder) / "s.ini"), QSettings.Format.IniFormat))
        window = MainWindow(settings, UiLanguage())
        window.load(path)
        app.processEvents()
        start = time.perf_counter()
        pages = print_actions.export_pdf(window, Path(folder) / "out.pdf")
        seconds = time.perf_counter() - start
        window.editor.undo_stack.setClean()
        window.close()
    return seconds, pages


def main() -> int:
    """One line per program: steps, uses, build ms (program, grid), µs per query."""
    folder = real_folder()
    if folder is None:
        print("no ../shared/real-programs beside the repository", file=sys.stderr)
        return 1
    for name in NAMES:
        program = parse_bytes((folder / f"{name}.txt").read_bytes()).program
        networks = program_to_ladder(program).networks
        xref = CrossReference.from_program(program)
        from_program = median_ms(lambda p=program: CrossReference.from_program(p), 5)
        from_grid = median_ms(
            lambda n=networks, d=program.dialect: CrossReference.from_ladder(n, d), 5)
        addresses = xref.addresses()
        start = time.perf_counter()
        for address in addresses:
            xref.uses_of(address)
        query_us = (time.perf_counter() - start) * 1e6 / max(len(addresses), 1)
        sort_ms = median_ms(lambda u=xref.uses: CrossReference(u).sorted_uses(), 3)
        print(f"{name:24s} {program.step_count():6d} steps {len(xref):6d} uses "
              f"{len(addresses):6d} addresses  build {from_program:6.1f} ms (program) "
              f"{from_grid:6.1f} ms (grid)  query {query_us:5.1f} µs  "
              f"every use sorted {sort_ms:5.1f} ms")
        if "--pdf" in sys.argv:
            seconds, pages = _pdf(folder / f"{name}.txt")
            print(f"{'':24s} Export PDF: {pages} pages in {seconds:5.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
