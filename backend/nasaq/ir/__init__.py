"""The STL intermediate representation: the one machine language every Nasaq language lowers to.

As in STEP 7, where LAD, FBD, SCL and Graph all become STL/MC7, the CPU simulator runs only this.
Operands arrive fully resolved (symbols, ``#locals`` and DB members are already addresses), every
instruction knows where it came from (:class:`Origin`), and mnemonics are the international set
whatever the source used.
"""

from nasaq.ir.operands import (
    Area,
    BlockKind,
    BlockRef,
    CallArg,
    CallInfo,
    Constant,
    ConstType,
    CounterRef,
    Direct,
    LabelRef,
    MemoryIndirect,
    MultiInstance,
    Operand,
    ParamRef,
    Register,
    RegisterIndirect,
    StatusCondition,
    TimerRef,
    Width,
)
from nasaq.ir.program import Block, Instruction, Network, Origin, Program, Variable

__all__ = [
    "Area",
    "Block",
    "BlockKind",
    "BlockRef",
    "CallArg",
    "CallInfo",
    "ConstType",
    "Constant",
    "CounterRef",
    "Direct",
    "Instruction",
    "LabelRef",
    "MemoryIndirect",
    "MultiInstance",
    "Network",
    "Operand",
    "Origin",
    "ParamRef",
    "Program",
    "Register",
    "RegisterIndirect",
    "StatusCondition",
    "TimerRef",
    "Variable",
    "Width",
]
