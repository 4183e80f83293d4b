"""LadderWorks: a FANUC-PMC-style ladder IDE and PLC simulator for CNC technicians."""

__version__ = "0.1.0"
