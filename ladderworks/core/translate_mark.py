"""The translation mark of texts outside Qt code (lupdate finds Qt's name)."""


def QT_TRANSLATE_NOOP(context: str, text: str) -> str:
    """Mark `text` for translation in `context` (lupdate finds Qt's name); returns it."""
    return text
