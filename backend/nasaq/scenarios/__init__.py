"""PLC unit tests: scenario files (format in README.md beside this module) run against a fresh
CPU. ``model`` reads and validates a file, ``runner`` runs one, ``report`` is ``nasaq test``."""
