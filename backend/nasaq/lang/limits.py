"""The limits the compilers keep to protect themselves: every input gets diagnostics, never an
uncaught exception, a hang or gigabytes of memory.

These are not STEP 7's rules (those are checked where the language is, e.g. STL's 7 nesting
levels of ``A(``, STL2xx): each limit here is far above what STEP 7 or TIA Portal accept or any
program written by hand needs, and only stops what would otherwise exhaust Python's stack
(RecursionError), its integer conversions (``int`` ↔ ``str`` beyond 4,300 digits is a
ValueError), the memory of a data block image, or the patience of the user. A source over a
limit gets one diagnostic with a code of ``limits.csv`` (STL150-199, SCL150-199, LAD150-199) at
the place it is exceeded, and the part over the limit is not compiled further.

The nesting limits are counted in syntax-tree levels; the recursive passes behind the parsers
(binding, type checking, lowering, formatting, LAD's reader) use a handful of Python frames per
level, and Python's default limit is 1,000 frames, so they stay well under 100.
"""

from __future__ import annotations

# ---- sizes --------------------------------------------------------------------------------
# A source file: a whole-project export of a large plant is a few MB (STL111, checked before
# parsing; the parser takes about 7 µs per token).
MAX_SOURCE_CHARS = 4 * 1024 * 1024
# Lines of one source. A million short lines fit MAX_SOURCE_CHARS but would take the parser
# and checker minutes; 100,000 lines (about 5 s to compile on one core) is far more than any
# block STEP 7 can hold (an FC is at most 64 KB of MC7 on an S7-300). Refused before parsing
# (STL151) for STL, SCL, LAD/FBD and S7-Graph files.
MAX_SOURCE_LINES = 100_000

# The image of one data block (STL152). STEP 7 Classic's CPUs (S7-300 and S7-400, e.g. a CPU
# 315-2 PN/DP or 416-2) hold at most 64 KB per DB; an S7-1500 (CPU 1516-3 PN/DP) holds 5 MB in
# an optimized DB. The compiler builds a DB's image at its declared size, so a declared
# ARRAY[0..2000000000] would otherwise take gigabytes before anything is reported.
MAX_DB_BYTES_CLASSIC = 64 * 1024
MAX_DB_BYTES_S7_1500 = 5 * 1024 * 1024


def max_db_bytes(profile: str) -> int:
    """The largest data block the CPU family ``profile`` holds, in bytes."""
    return MAX_DB_BYTES_S7_1500 if profile == "S7-1500" else MAX_DB_BYTES_CLASSIC


# ---- nesting --------------------------------------------------------------------------------
# SCL control statements (IF, CASE, FOR, WHILE, REPEAT) inside each other (SCL150). S7-SCL's
# manual does not state a limit; real code rarely goes past 10.
MAX_STATEMENT_NESTING = 40
# SCL expression depth: parentheses, unary operators, operands of operators, indexes and call
# arguments inside each other (SCL151). A chain ``a + b + c + ...`` deepens the tree by one per
# operator, so this also bounds an expression's length in operators.
MAX_EXPRESSION_DEPTH = 60
# STRUCT inside STRUCT (and arrays of structs) in a declaration, in SCL (SCL152) and STL
# (STL150). STEP 7 allows 8 levels of nested structures in a block interface.
MAX_STRUCT_NESTING = 30
# LAD/FBD: parallel branches, logic pins (a box's input wired to a rung) and series inside each
# other (LAD150). The LAD editor draws at most a screen's width of them.
MAX_LAD_NESTING = 40

# Array bounds (STL153): STEP 7 Classic takes INT bounds, TIA Portal DINT ones on an S7-1500;
# a bound outside DINT is refused where the declaration is read, whatever the profile.
MIN_ARRAY_BOUND = -(2**31)
MAX_ARRAY_BOUND = 2**31 - 1

# Initial values of one declaration once repeat factors are expanded (``2147483648 (TRUE)``
# looped for minutes): a million, far more than an initial value list of any real source
# (an S7-300 DB holds 64 KB). Past it the expansion stops: an array longer than this keeps
# its default values beyond the first million.
MAX_INIT_VALUES = 1_000_000

# ---- lexing ---------------------------------------------------------------------------------
# Characters the lexer's fallback (naming a token the parser state does not expect) looks at
# after the current position: a rest-of-line token would otherwise be scanned again for every
# token of a long broken line, a quadratic error recovery.
LEX_FALLBACK_WINDOW = 128

# ---- numbers --------------------------------------------------------------------------------
# Digits in one number literal (SCL153, STL152, LAD151). The widest S7 value, an LWORD in
# binary, has 64 digits plus separators; 4,300 is Python's own int/str conversion limit.
MAX_NUMBER_DIGITS = 100
