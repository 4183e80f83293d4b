"""Fatek FBs (WinProladder) programs: listing, devices, branch logic, FUN 94 ASCII output."""
