"""Nasaq: a self-hosted web IDE and CPU simulator for Siemens S7-300/400 style PLC programs."""

__version__ = "0.1.0"
