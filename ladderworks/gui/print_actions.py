"""File › Print… and File › Export PDF…: the ladder with symbols and comments, and its xref."""

from __future__ import annotations

from pathlib import Path
from typing import Protocol

from PySide6.QtCore import QCoreApplication, QDateTime, QLocale, QMarginsF, QObject, Qt
from PySide6.QtGui import (
    QAction,
    QKeySequence,
    QPagedPaintDevice,
    QPageLayout,
    QPageSize,
    QPainter,
    QPdfWriter,
)
from PySide6.QtPrintSupport import QPrintDialog, QPrinter, QPrintPreviewDialog
from PySide6.QtWidgets import QDialog, QMainWindow, QProgressDialog, QWidget

from ladderworks.core.il import Program
from ladderworks.gui import file_dialogs
from ladderworks.gui.console_menus import ConsoleMenus
from ladderworks.gui.editor.view import LadderEditor
from ladderworks.gui.print_pages import PRINT_DPI, LadderPages, PrintJob, program_title

translate = QCoreApplication.translate

MARGIN_MM = 10.0
PROGRESS_FROM_PAGES = 20  # a longer job shows a progress dialog that can cancel it


class Console(Protocol):
    """What printing reads of the ladder console (`main_window.MainWindow`)."""

    editor: LadderEditor
    program_info: Program  # the program as opened: its title

    @property
    def path(self) -> Path | None:
        """The program's file (None: untitled)."""

    def window(self) -> QWidget:
        """The window its dialogs sit on."""


def print_job(window: Console) -> PrintJob:
    """The console's program as a print job (a large program still laying out is finished)."""
    editor = window.editor
    path = window.path
    return PrintJob(
        networks=editor.model.ladder_document().networks, describe=editor.describe_address,
        symbols=editor.model.symbols, title=program_title(window.program_info),
        file_name=Path(path).name if path is not None else translate("Print", "Untitled"),
        dialect=editor.model.dialect,
        printed=QLocale().toString(QDateTime.currentDateTime(), QLocale.FormatType.ShortFormat))


def _page_layout() -> QPageLayout:
    return QPageLayout(QPageSize(QPageSize.PageSizeId.A4), QPageLayout.Orientation.Landscape,
                       QMarginsF(MARGIN_MM, MARGIN_MM, MARGIN_MM, MARGIN_MM),
                       QPageLayout.Unit.Millimeter)


def render(job: PrintJob, device: QPagedPaintDevice, parent: QWidget | None = None) -> int:
    """Paint the job on a paged device; the number of pages (0 when cancelled or failed)."""
    painter = QPainter()
    if not painter.begin(device):
        return 0
    pages = LadderPages(job, device.width(), device.height())
    numbers = list(range(1, len(pages.pages) + 1))
    if isinstance(device, QPrinter) and device.printRange() is QPrinter.PrintRange.PageRange:
        first, last = max(device.fromPage(), 1), device.toPage() or len(pages.pages)
        numbers = numbers[first - 1:last]  # the pages the print dialog asked for
    if not numbers:
        painter.end()
        return 0
    progress: QProgressDialog | None = None
    if parent is not None and len(numbers) >= PROGRESS_FROM_PAGES:
        progress = QProgressDialog(translate("Print", "Printing the ladder…"),
                                   translate("Print", "Cancel"), 0, numbers[-1], parent)
        progress.setObjectName("print_progress")
        progress.setWindowModality(Qt.WindowModality.WindowModal)
        progress.setMinimumDuration(500)

    def step(page: int) -> bool:
        if progress is None:
            return True
        progress.setValue(page)
        return not progress.wasCanceled()

    done = pages.paint(painter, device, step, numbers)
    painter.end()
    if progress is not None:
        progress.close()
    return len(numbers) if done else 0


def export_pdf(console: Console, path: str | Path) -> int:
    """Write the console's ladder to a PDF file; the number of pages (0 when it failed)."""
    writer = QPdfWriter(str(path))
    writer.setResolution(PRINT_DPI)
    writer.setPageLayout(_page_layout())
    job = print_job(console)
    writer.setTitle(job.title or Path(job.file_name).name)
    writer.setCreator("LadderWorks")
    count = render(job, writer, console.window())
    del writer  # the file is complete once the writer is gone
    if count == 0:
        Path(path).unlink(missing_ok=True)
    return count


def print_ladder(console: Console, printer: QPrinter) -> int:
    """Print the console's ladder on a printer set up by the print dialog."""
    return render(print_job(console), printer, console.window())


def new_printer() -> QPrinter:
    """A printer at the editor's resolution, A4 landscape by default."""
    printer = QPrinter(QPrinter.PrinterMode.ScreenResolution)
    printer.setPageLayout(_page_layout())
    return printer


class PrintActions(QObject):
    """File › Print… (Ctrl+P), Print preview… and Export PDF…, before Program properties, for
    the ladder of `console` with dialogs on `window`. Not a widget: the window's
    `retranslate()` calls this one's."""

    def __init__(self, window: QMainWindow, console: Console, menus: ConsoleMenus) -> None:
        super().__init__(window)
        self.window = window
        self.console = console
        self.preview_printer: QPrinter | None = None  # the printer of the open print preview
        self.print_action = QAction(window)
        self.print_action.setObjectName("action_print")
        self.print_action.setShortcut(QKeySequence(QKeySequence.StandardKey.Print))
        self.print_action.triggered.connect(self.print_dialog)
        self.preview_action = QAction(window)
        self.preview_action.setObjectName("action_print_preview")
        self.preview_action.triggered.connect(self.preview_dialog)
        self.pdf_action = QAction(window)
        self.pdf_action.setObjectName("action_export_pdf")
        self.pdf_action.triggered.connect(self.pdf_dialog)
        for action in (self.print_action, self.preview_action, self.pdf_action):
            menus.insert_before("menu_file", action, "action_program_properties")
            window.addAction(action)
        self.retranslate()

    def print_dialog(self) -> None:
        """File › Print…: the system's print dialog, then the pages."""
        printer = new_printer()
        dialog = QPrintDialog(printer, self.window)
        dialog.setObjectName("print_dialog")
        dialog.setMinMax(1, 99_999)  # the dialog offers a page range; pages are counted after
        if dialog.exec() == QDialog.DialogCode.Accepted:
            _report(self.window, print_ladder(self.console, printer), None)

    def make_preview(self) -> QPrintPreviewDialog:
        """The print preview of the console's program (A4 landscape; it can print)."""
        self.preview_printer = new_printer()  # the dialog does not own it: kept alive here
        dialog = QPrintPreviewDialog(self.preview_printer, self.window)
        dialog.setObjectName("print_preview")
        dialog.setWindowTitle(translate("Print", "Print preview"))
        dialog.paintRequested.connect(  # a long program: a progress dialog that can cancel
            lambda printer: render(print_job(self.console), printer, self.window))
        screen = self.window.screen().availableGeometry()
        dialog.resize(min(1000, screen.width()), min(760, screen.height()))
        return dialog

    def preview_dialog(self) -> None:
        """File › Print preview…: the pages as they will print."""
        dialog = self.make_preview()
        dialog.exec()
        dialog.deleteLater()

    def pdf_dialog(self) -> None:
        """File › Export PDF…: a file name, then the pages."""
        path = self.console.path
        suggested = str(Path(path).with_suffix(".pdf")) if path is not None else ""
        name = file_dialogs.save_file_name(
            self.window, translate("Print", "Export PDF"), suggested,
            translate("Print", "PDF files (*.pdf)"))
        if name:
            if not name.lower().endswith(".pdf"):
                name += ".pdf"
            _report(self.window, export_pdf(self.console, name), name)

    def retranslate(self) -> None:
        """The actions' texts in the UI language."""
        self.print_action.setText(translate("Print", "&Print..."))
        self.preview_action.setText(translate("Print", "Print pre&view..."))
        self.pdf_action.setText(translate("Print", "Export P&DF..."))


def _report(window: QMainWindow, pages: int, path: str | None) -> None:
    """Say in the status bar how it went."""
    if pages == 0:
        text = translate("Print", "Printing was cancelled or failed")
    elif path is not None:
        text = translate("Print", "{0} pages written to {1}").format(pages, path)
    else:
        text = translate("Print", "{0} pages sent to the printer").format(pages)
    window.statusBar().showMessage(text, 8000)
