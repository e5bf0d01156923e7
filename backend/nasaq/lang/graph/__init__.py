"""S7-Graph: sequencers in a function block, compiled to an FB that runs on the CPU.

As the other languages: parse (``text.py``, ``grammars/graph.lark``) → check (``check.py``) →
lower to STL (``lower.py``), which the STL compiler compiles with the project's other sources
(``compile.py``, as LAD/FBD files are). The model is ``model.py``; what one call of the compiled
FB does, and the instance DB it keeps its state in, is ``SEMANTICS.md``.
"""
