"""Virtual plants: deterministic process models wired to the PLC's I/O (see ``base.py``)."""
