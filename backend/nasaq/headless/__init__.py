"""Headless use of the CPU: ``nasaq run`` (N scans, final state as JSON) and the address syntax
shared with ``nasaq test`` scenarios."""
