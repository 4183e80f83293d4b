"""The watch table (TIA Portal's watch table, for every family): names → places, values shown
and typed in a display format, rows kept per program. docs/plc-utilities.md, "Watch table"."""
