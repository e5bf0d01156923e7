"""Source languages that lower to the STL IR (``nasaq.ir``).

``types`` and ``layout`` describe S7-300/400 data types and their memory layout; every language
(STL now, SCL later) declares variables with them. Each language has its own package
(``stl``: parse → resolve/check → lower).
"""
