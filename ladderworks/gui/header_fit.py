"""Column titles that fit their words in either language: widened again after a live switch
("Zaman (ms)", "Okunan" are longer than "Time (ms)", "Got")."""

from __future__ import annotations

from PySide6.QtWidgets import QHeaderView, QTableView, QTreeView


def fit_headers(view: QTreeView | QTableView) -> None:
    """Widen each column a user may size (all but a stretched last one) to at least its
    title's width; a column already wider for its contents keeps its width."""
    header = view.header() if isinstance(view, QTreeView) else view.horizontalHeader()
    last = header.count() - 1 if header.stretchLastSection() else header.count()
    for column in range(last):
        if (header.isSectionHidden(column)
                or header.sectionResizeMode(column) != QHeaderView.ResizeMode.Interactive):
            continue
        wanted = header.sectionSizeHint(column)
        if header.sectionSize(column) < wanted:
            header.resizeSection(column, wanted)
