"""Siemens S7-1200 (TIA Portal): the graph both readers build, the lowering, the dialect."""
