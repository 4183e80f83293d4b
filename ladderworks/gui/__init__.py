"""The PySide6 application: the ladder console and its PLC docks."""
