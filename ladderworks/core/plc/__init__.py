"""The PLC runtime: memory image, scan engine, timers, counters, functions, forcing, tracing."""
