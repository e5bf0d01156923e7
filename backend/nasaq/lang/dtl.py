"""DTL, the S7-1200/1500 date and time (12 bytes), as a structure of the S7-1500 profile's
unsigned types, so its members read symbolically (``#now.YEAR``) and it is copied like any
STRUCT: YEAR UINT (1970-2262), MONTH, DAY, WEEKDAY (1 = Sunday), HOUR, MINUTE, SECOND USINT,
NANOSECOND UDINT. The initial value is TIA's ``DTL#1970-01-01-00:00:00`` (a Thursday).

A declaration of DTL under a classic profile is ``SCL500`` (the binder, ``nasaq.lang.scl.bind``).
"""

from __future__ import annotations

from nasaq.lang.scl.ast import Literal
from nasaq.lang.types import Elementary, Field, StructType

NAME = "DTL"
_UINT, _USINT, _UDINT = Elementary("UINT"), Elementary("USINT"), Elementary("UDINT")
MEMBERS = (
    ("YEAR", _UINT, 1970),
    ("MONTH", _USINT, 1),
    ("DAY", _USINT, 1),
    ("WEEKDAY", _USINT, 5),
    ("HOUR", _USINT, 0),
    ("MINUTE", _USINT, 0),
    ("SECOND", _USINT, 0),
    ("NANOSECOND", _UDINT, 0),
)
# initial values as a declaration's (``a : UINT := 1970``), so DBs and instances start with them
DTL = StructType(
    tuple(Field(name, kind, [Literal("INTEGER", str(first))]) for name, kind, first in MEMBERS)
)
# byte offsets of the members (YEAR is a word at 0, the bytes follow, NANOSECOND at 8)
OFFSETS = {"YEAR": 0, "MONTH": 2, "DAY": 3, "WEEKDAY": 4, "HOUR": 5, "MINUTE": 6, "SECOND": 7}
NANOSECOND_OFFSET = 8


def is_dtl(data_type: object) -> bool:
    return data_type == DTL
