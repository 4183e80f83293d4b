"""The printed ladder: pages with a header and page numbers, whole networks, the cross reference.

Pages are planned first (so every footer can say `Page 3 / 12`), then painted on any paged
device (QPrinter, QPdfWriter) with the editor's own network items. The device is used at 96 dpi
so fonts keep their screen proportions; pages are scaled to fit a network of the editor's
standard width, and a wider network is drawn smaller on its own to fit the page.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from PySide6.QtCore import QCoreApplication, QRectF, Qt
from PySide6.QtGui import QColor, QFont, QFontMetricsF, QPagedPaintDevice, QPainter, QPen
from PySide6.QtWidgets import QStyleOptionGraphicsItem

from ladderworks.core.address import Address
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.il.program import Program
from ladderworks.core.ladder.model import DEFAULT_COLUMNS, LadderNetwork
from ladderworks.core.symbols import SymbolTable, describe
from ladderworks.core.xref import Access, CrossReference, Use, UseKind
from ladderworks.gui.editor.geometry import (
    LISTING_LINE_H,
    SPARE_ROWS,
    RowMetrics,
    grid_top,
    network_height,
    network_rows,
    network_width,
)
from ladderworks.gui.editor.label_text import CommentedAddresses, SignalLookup, shows_comment
from ladderworks.gui.editor.labelled_item import LabelledNetworkItem

translate = QCoreApplication.translate

PRINT_DPI = 96  # the editor's drawing units are screen pixels
HEADER_H = 44.0
FOOTER_H = 28.0
ROW_GAP = 4.0
INK = QColor("#1a1a1a")
GREY = QColor("#5b5b5b")
# The %@1 title items that name the program: machine-tool name, program number, edition.
TITLE_ITEMS = (2, 4, 5)


@dataclass(frozen=True, slots=True)
class PrintJob:
    """What is printed: the networks, how addresses are named, the program's title and file."""

    networks: Sequence[LadderNetwork]
    describe: SignalLookup
    symbols: SymbolTable | None
    title: str
    file_name: str
    dialect: str = "seed"
    printed: str = ""  # when it was printed, in the UI language's short date and time


@dataclass(frozen=True, slots=True)
class Placement:
    """Part of a network on a page: rows `top` .. `top + height` of its drawing, at page y."""

    network: int
    y: float
    top: float
    height: float
    scale: float = 1.0  # a network wider than the page is drawn smaller (top, height: on paper)


@dataclass(slots=True)
class Page:
    """One page: network parts, or cross-reference rows (with the appendix title first)."""

    networks: list[Placement] = field(default_factory=list)
    rows: list[int] = field(default_factory=list)  # indexes into the appendix rows
    appendix_title: bool = False


@dataclass(frozen=True, slots=True)
class AppendixRow:
    """One address of the cross reference: its symbol, where it is written and read."""

    address: Address
    symbol: str
    written: str
    read: str
    lines: int  # text lines the row needs


def program_title(program: Program) -> str:
    """The program's title from its `%@1` items (machine, program number, edition), or ""."""
    parts = [program.title.get(item, "").strip() for item in TITLE_ITEMS]
    return " · ".join(part for part in parts if part)


def print_height(network: LadderNetwork, rows: RowMetrics) -> float:
    """The network's height on paper (its rows are `rows`): as on screen, less the spare row
    the editor adds."""
    spare = SPARE_ROWS * rows.height if network.listing is None else 0.0
    return network_height(network, rows) - spare


def _row_cut(network: LadderNetwork, rows_: RowMetrics, scale: float, top: float,
             limit: float) -> float:
    """Where to cut a network continued on the next page: at the last row boundary (on
    paper) after `top` and not past `limit`; at `limit` when no row boundary fits."""
    first = grid_top(network)
    step = LISTING_LINE_H if network.listing is not None else rows_.height
    rows = int((limit / scale - first) // step)
    cut = (first + rows * step) * scale
    return cut if top < cut <= limit else limit


def _fonts() -> tuple[QFont, QFont, QFont]:
    header = QFont()
    header.setPointSizeF(11)
    header.setBold(True)
    small = QFont()
    small.setPointSizeF(8)
    bold = QFont(small)
    bold.setBold(True)
    return header, small, bold


def _network_list(uses: list[Use], access: Access) -> str:
    """`3 5(S) 9(R)`: the networks (1-based) of the uses with this access, SET/RST marked."""
    marks = {UseKind.SET: "(S)", UseKind.RESET: "(R)"}
    seen: dict[str, None] = {}
    for use in uses:
        if use.access is access or use.access is Access.READ_WRITE:
            seen.setdefault(f"{use.network + 1}{marks.get(use.kind, '')}", None)
    return " ".join(seen)


class LadderPages:
    """The plan of a print job on a page of a given size, and its painting."""

    def __init__(self, job: PrintJob, page_width: float, page_height: float) -> None:
        self.job = job
        self.commented = CommentedAddresses(job.describe)  # addresses with a comment shown
        standard = network_width(LadderNetwork(columns=DEFAULT_COLUMNS))
        self.scale = min(1.0, page_width / standard)
        self.width = page_width / self.scale  # the page in drawing units
        self.body = page_height / self.scale - HEADER_H - FOOTER_H
        self.header_font, self.small_font, self.bold_font = _fonts()
        self.metrics = QFontMetricsF(self.small_font)
        self.line_h = self.metrics.height() + 1
        self.title_h = 2 * self.line_h  # the appendix title
        self.heading_h = self.line_h + ROW_GAP  # the column headings
        self.rows = self._appendix_rows()
        self.pages: list[Page] = []
        self._plan_networks()
        self._plan_appendix()

    def network_rows(self, network: LadderNetwork) -> RowMetrics:
        """The rows `network` is drawn with (taller when an element has a comment shown)."""
        return network_rows(network, lambda net: shows_comment(net, self.commented))

    def _plan_networks(self) -> None:
        page = Page()
        y = 0.0
        for index, network in enumerate(self.job.networks):
            scale = min(1.0, self.width / network_width(network))
            rows = self.network_rows(network)
            height = print_height(network, rows) * scale
            if y > 0 and y + height > self.body:  # a network is not split when it fits a page
                self.pages.append(page)
                page, y = Page(), 0.0
            top = 0.0
            while height - top > self.body - y:  # taller than a page: continued on the next
                cut = _row_cut(network, rows, scale, top, top + self.body - y)
                page.networks.append(Placement(index, y, top, cut - top, scale))
                top = cut
                self.pages.append(page)
                page, y = Page(), 0.0
            page.networks.append(Placement(index, y, top, height - top, scale))
            y += height - top
        if page.networks:
            self.pages.append(page)

    def _appendix_rows(self) -> list[AppendixRow]:
        xref = CrossReference.from_ladder(self.job.networks, self.job.dialect)
        by_address: dict[Address, list[Use]] = {}
        for use in xref.sorted_uses():
            by_address.setdefault(use.address, []).append(use)
        text_width = self._list_width()
        other = spelling(self.job.dialect).dialect  # a Delta or Fatek program
        rows = []
        for address, uses in by_address.items():
            written = _network_list(uses, Access.WRITE)
            read = _network_list(uses, Access.READ)
            lines = max(self._line_count(written, text_width), self._line_count(read, text_width))
            symbol = "" if other else describe(address, self.job.symbols)  # no FANUC signals
            rows.append(AppendixRow(address, symbol, written, read, lines))
        return rows

    def _columns(self) -> tuple[float, float, float, float]:
        """x of the address, symbol, written-in and read-in columns."""
        rest = (self.width - 250) / 2
        return 0.0, 90.0, 250.0, 250.0 + rest

    def _list_width(self) -> float:
        return (self.width - 250) / 2 - 8

    def _line_count(self, text: str, width: float) -> int:
        rect = self.metrics.boundingRect(QRectF(0, 0, width, 10_000),
                                         int(Qt.TextFlag.TextWordWrap), text or "-")
        return max(1, round(rect.height() / self.metrics.lineSpacing()))

    def _plan_appendix(self) -> None:
        if not self.rows:
            return
        page = Page(appendix_title=True)
        y = self.title_h + self.heading_h
        for index, row in enumerate(self.rows):
            height = row.lines * self.line_h + ROW_GAP
            if y + height > self.body and page.rows:
                self.pages.append(page)
                page, y = Page(), self.heading_h  # the column headings again
            page.rows.append(index)
            y += height
        self.pages.append(page)

    # -- painting ------------------------------------------------------------------------

    def paint(self, painter: QPainter, device: QPagedPaintDevice,
              progress: Callable[[int], bool] | None = None,
              numbers: Sequence[int] | None = None) -> bool:
        """Paint pages `numbers` (1-based; all by default), each numbered `n / total` of the
        whole job (False when `progress(page)` asked to stop)."""
        wanted = range(1, len(self.pages) + 1) if numbers is None else numbers
        for count, number in enumerate(wanted):
            page = self.pages[number - 1]
            if count > 0:
                device.newPage()
            if progress is not None and not progress(number):
                return False
            painter.save()
            painter.scale(self.scale, self.scale)
            self._paint_frame(painter, number)
            painter.translate(0, HEADER_H)
            for placement in page.networks:
                self._paint_network(painter, placement)
            if page.rows:
                self._paint_rows(painter, page)
            painter.restore()
        return True

    def _paint_frame(self, painter: QPainter, number: int) -> None:
        painter.setPen(INK)
        painter.setFont(self.header_font)
        title = self.job.title or "LadderWorks"
        painter.drawText(QRectF(0, 0, self.width * 0.6, HEADER_H - 10),
                         Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter,
                         QFontMetricsF(self.header_font).elidedText(
                             title, Qt.TextElideMode.ElideRight, self.width * 0.6))
        painter.setFont(self.small_font)
        painter.drawText(QRectF(self.width * 0.6, 0, self.width * 0.4, HEADER_H - 10),
                         Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter,
                         self.metrics.elidedText(self.job.file_name, Qt.TextElideMode.ElideMiddle,
                                                 self.width * 0.4))
        painter.setPen(QPen(GREY, 1))
        painter.drawLine(0, int(HEADER_H - 6), int(self.width), int(HEADER_H - 6))
        bottom = HEADER_H + self.body
        painter.drawLine(0, int(bottom + 4), int(self.width), int(bottom + 4))
        painter.setPen(INK)
        printed, page = self.footer(number)
        painter.drawText(QRectF(0, bottom + 6, self.width, FOOTER_H - 6),
                         Qt.AlignmentFlag.AlignCenter, page)
        if printed:
            painter.drawText(QRectF(0, bottom + 6, self.width * 0.35, FOOTER_H - 6),
                             Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter,
                             self.metrics.elidedText(printed, Qt.TextElideMode.ElideRight,
                                                     self.width * 0.35))

    def footer(self, number: int) -> tuple[str, str]:
        """The footer of page `number`: when it was printed ("" if unknown), its number."""
        printed = translate("Print", "Printed {0}").format(self.job.printed) \
            if self.job.printed else ""
        return printed, translate("Print", "Page {0} / {1}").format(number, len(self.pages))

    def _paint_network(self, painter: QPainter, placement: Placement) -> None:
        network = self.job.networks[placement.network]
        item = LabelledNetworkItem(network, placement.network + 1, self.job.describe)
        item.spelling = spelling(self.job.dialect)  # a Delta program: Delta's spelling
        scale = placement.scale
        top, height = placement.top / scale, placement.height / scale  # in the item's units
        option = QStyleOptionGraphicsItem()
        option.exposedRect = QRectF(0, top, network_width(network), height)
        painter.save()
        painter.setClipRect(QRectF(0, placement.y, self.width, placement.height))
        painter.translate(0, placement.y)
        painter.scale(scale, scale)
        painter.translate(0, -top)
        item.paint(painter, option, None)
        painter.restore()

    def _paint_rows(self, painter: QPainter, page: Page) -> None:
        x_address, x_symbol, x_written, x_read = self._columns()
        width = self._list_width()
        y = 0.0
        if page.appendix_title:
            painter.setFont(self.header_font)
            painter.setPen(INK)
            painter.drawText(QRectF(0, y, self.width, self.title_h),
                             Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter,
                             translate("Print", "Cross reference"))
            y += self.title_h
        painter.setFont(self.bold_font)
        headings = ((x_address, translate("Print", "Address")),
                    (x_symbol, translate("Print", "Symbol")),
                    (x_written, translate("Print", "Written in networks")),
                    (x_read, translate("Print", "Read in networks")))
        for x, text in headings:
            painter.drawText(QRectF(x, y, width, self.line_h), Qt.AlignmentFlag.AlignLeft, text)
        y += self.heading_h
        painter.setFont(self.small_font)
        flags = int(Qt.AlignmentFlag.AlignLeft | Qt.TextFlag.TextWordWrap)
        spell = spelling(self.job.dialect)  # a Delta program's X0, not X0.0
        for index in page.rows:
            row = self.rows[index]
            height = row.lines * self.line_h
            painter.drawText(QRectF(x_address, y, 86, height), flags, spell.address(row.address))
            painter.drawText(QRectF(x_symbol, y, 156, height), flags, self.metrics.elidedText(
                row.symbol, Qt.TextElideMode.ElideRight, 156))
            painter.drawText(QRectF(x_written, y, width, height), flags, row.written or "-")
            painter.drawText(QRectF(x_read, y, width, height), flags, row.read or "-")
            y += height + ROW_GAP

