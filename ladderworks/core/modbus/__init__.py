"""The simulated PLC on the network: Modbus/TCP maps, the bridge to a PlcRun, the server."""
