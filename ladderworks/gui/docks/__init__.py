"""The console's PLC utility docks; `plc_docks.build_plc_docks` puts them into the window."""
