"""Simulation sessions and online monitoring: a CPU per session in its own thread, breakpoints and
steps that hold it mid-scan, block status, watch, force and trend, streamed over a WebSocket
(``PROTOCOL.md``)."""
