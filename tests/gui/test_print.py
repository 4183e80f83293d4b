"""File › Export PDF… and File › Print…: the ladder's pages, header, numbers, xref appendix."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from PySide6.QtCore import QDate
from PySide6.QtPrintSupport import QPrintDialog, QPrinter
from PySide6.QtWidgets import QDialog, QProgressDialog
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.ladder.model import Contact, LadderNetwork
from ladderworks.gui import file_dialogs, print_actions
from ladderworks.gui.editor.geometry import network_width
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.print_pages import LadderPages, PrintJob, print_height
from tests.real_programs import real_bytes

EXAMPLES = Path(__file__).resolve().parents[2] / "resources" / "examples"


def _page_count(data: bytes) -> int:
    """Page objects in a PDF (`/Type /Page`, not `/Type /Pages`)."""
    return len(re.findall(rb"/Type\s*/Page(?![a-zA-Z])", data))


def _plan(window: MainWindow) -> LadderPages:
    """The plan the export makes, on the same page (A4 landscape, 10 mm margins, 96 dpi)."""
    printer = print_actions.new_printer()
    layout = printer.pageLayout()
    rect = layout.paintRectPixels(print_actions.PRINT_DPI)
    return LadderPages(print_actions.print_job(window), rect.width(), rect.height())


def test_export_pdf_of_a_seed_example(qtbot: QtBot, window: MainWindow, tmp_path: Path,
                                      monkeypatch: pytest.MonkeyPatch) -> None:
    assert window.load(EXAMPLES / "spindle_override.LAD")
    target = tmp_path / "spindle"
    monkeypatch.setattr(file_dialogs, "save_file_name",
                        lambda *_args, **_kwargs: str(target))
    window.actions_by_name["action_export_pdf"].trigger()
    pdf = tmp_path / "spindle.pdf"  # the extension is added
    data = pdf.read_bytes()
    assert data.startswith(b"%PDF")
    plan = _plan(window)
    networks = [p.network for page in plan.pages for p in page.networks]
    assert sorted(set(networks)) == list(range(16))  # every network is printed
    assert len(networks) == 16  # none is split: each fits a page
    appendix = [page for page in plan.pages if page.rows]
    assert appendix and appendix[0].appendix_title
    assert sum(len(page.rows) for page in appendix) == len(plan.rows)
    assert {str(row.address) for row in plan.rows} >= {"X2.1", "R102.7", "G30.7"}
    assert _page_count(data) == len(plan.pages) >= 3
    assert "pages written to" in window.statusBar().currentMessage()


def test_export_pdf_of_a_real_fragment_has_its_title_labels_and_pages(
        qtbot: QtBot, window: MainWindow, tmp_path: Path) -> None:
    source = tmp_path / "dressing.LAD"
    source.write_bytes(real_bytes("FANUC_X22_FRAG_fc62224_DRESSING"))
    assert window.load(source)
    pdf = tmp_path / "dressing.pdf"
    count = print_actions.export_pdf(window, pdf)
    data = pdf.read_bytes()
    assert data.startswith(b"%PDF") and _page_count(data) == count
    plan = _plan(window)
    assert count == len(plan.pages)
    body = plan.body
    for page in plan.pages:  # whole networks on a page, within its body
        for placement in page.networks:
            network = plan.job.networks[placement.network]
            assert placement.top == 0
            rows = plan.network_rows(network)
            assert placement.height == print_height(network, rows) * placement.scale
            assert placement.y + placement.height <= body
    rows = {str(row.address): row for row in plan.rows}
    assert "D1602.1" in rows and "(R)" in rows["D1602.1"].written


def test_a_network_taller_than_a_page_is_continued_on_the_next() -> None:
    tall = LadderNetwork(rows=30, cells={(r, 0): Contact(parse_address(f"R{r}.0"))
                                         for r in range(30)})
    job = PrintJob([LadderNetwork(cells={(0, 0): Contact(parse_address("X0.0"))}), tall],
                   lambda _a: None, None, "T", "f.LAD")
    plan = LadderPages(job, 1000, 700)
    parts = [p for page in plan.pages for p in page.networks if p.network == 1]
    assert len(parts) >= 3 and parts[0].y == 0  # starts on a fresh page, then continues
    rows = plan.network_rows(tall)
    assert sum(p.height for p in parts) == print_height(tall, rows)
    assert [p.top for p in parts] == sorted(p.top for p in parts)
    for part in parts[1:]:  # cut between rows, not through a contact
        assert part.top % rows.height == 0  # whole rows: the network has no comment lines


def test_print_sends_the_pages_to_the_printer_the_dialog_chose(
        qtbot: QtBot, window: MainWindow, tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    assert window.load(EXAMPLES / "timer_relay.LAD")
    out = tmp_path / "printed.pdf"

    def accept(dialog: QPrintDialog) -> int:  # the user picks "print to file"
        printer = dialog.printer()
        printer.setOutputFormat(QPrinter.OutputFormat.PdfFormat)
        printer.setOutputFileName(str(out))
        return QDialog.DialogCode.Accepted.value

    monkeypatch.setattr(QPrintDialog, "exec", accept)
    window.actions_by_name["action_print"].trigger()
    data = out.read_bytes()
    assert data.startswith(b"%PDF") and _page_count(data) == len(_plan(window).pages) == 2
    assert "pages sent to the printer" in window.statusBar().currentMessage()


def test_a_network_wider_than_the_page_alone_is_drawn_smaller() -> None:
    narrow = LadderNetwork(cells={(0, 0): Contact(parse_address("X0.0"))})
    wide = LadderNetwork(columns=30, cells={(0, c): Contact(parse_address(f"R{c}.0"))
                                            for c in range(30)})
    job = PrintJob([narrow, wide, narrow], lambda _a: None, None, "T", "f.LAD")
    plan = LadderPages(job, 1047, 718)  # A4 landscape less 10 mm margins, at 96 dpi
    scales = {p.network: p.scale for page in plan.pages for p in page.networks}
    assert scales[0] == scales[2] == 1.0 and plan.scale == 1.0
    assert 0 < scales[1] < 1
    assert network_width(wide) * scales[1] <= plan.width


def test_cancelling_a_long_export_leaves_no_pdf(qtbot: QtBot, window: MainWindow, tmp_path: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    rungs = "".join(f"RD X0.{k % 8}\nOR R{k}.0\nOR R{k}.1\nWRT R{k}.2\n" for k in range(80))
    source = tmp_path / "long.LAD"
    source.write_text(f"%@3\n{rungs}%\n", "utf-8")
    assert window.load(source)
    assert len(_plan(window).pages) >= print_actions.PROGRESS_FROM_PAGES
    asked: list[int] = []
    original = QProgressDialog.wasCanceled

    def cancel_at_page_3(self: QProgressDialog) -> bool:
        asked.append(self.value())
        return self.value() >= 3

    monkeypatch.setattr(QProgressDialog, "wasCanceled", cancel_at_page_3)
    pdf = tmp_path / "long.pdf"
    assert print_actions.export_pdf(window, pdf) == 0
    assert not pdf.exists() and asked[-1] == 3
    monkeypatch.setattr(QProgressDialog, "wasCanceled", original)
    assert print_actions.export_pdf(window, pdf) == len(_plan(window).pages)
    assert _page_count(pdf.read_bytes()) == len(_plan(window).pages)


def test_print_honours_the_page_range_of_the_dialog(qtbot: QtBot, window: MainWindow,
                                                   tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    assert window.load(EXAMPLES / "spindle_override.LAD")
    out = tmp_path / "pages-2-3.pdf"

    def pages_2_to_3(dialog: QPrintDialog) -> int:
        printer = dialog.printer()
        printer.setOutputFormat(QPrinter.OutputFormat.PdfFormat)
        printer.setOutputFileName(str(out))
        printer.setPrintRange(QPrinter.PrintRange.PageRange)
        printer.setFromTo(2, 3)
        return QDialog.DialogCode.Accepted.value

    monkeypatch.setattr(QPrintDialog, "exec", pages_2_to_3)
    window.actions_by_name["action_print"].trigger()
    assert _page_count(out.read_bytes()) == 2 < len(_plan(window).pages)
    assert window.statusBar().currentMessage().startswith("2 pages sent to the printer")


def test_every_page_footer_says_when_it_was_printed_in_the_ui_language(
        window: MainWindow) -> None:
    assert window.load(EXAMPLES / "spindle_override.LAD")
    today = QDate.currentDate()
    plan = _plan(window)
    printed, page = plan.footer(2)
    assert printed.startswith("Printed ") and str(today.year() % 100) in printed
    assert page == f"Page 2 / {len(plan.pages)}"
    window.set_language("tr")
    printed, page = _plan(window).footer(1)
    # Turkish dates put the day first: 24.11.2026
    assert printed.startswith("Yazdırıldı: "), printed
    assert today.toString("dd.MM.yyyy") in printed, printed
    assert page.startswith("Sayfa 1 / ")
