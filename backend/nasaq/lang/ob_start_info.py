"""The start information of optimized organization blocks (S7-1200/1500), as TIA Portal declares
it: the inputs of an OB's event (``Initial_Call`` of "Main", ``LADDR`` of "Diagnostic error
interrupt" ...), which TIA puts into the OB's interface itself. A TIA export lists them in the
OB's VAR_INPUT; a source written by hand often leaves them out and still reads ``#LADDR``, as
TIA's editor shows them. So an optimized OB without a VAR_INPUT section gets its event's inputs
(``nasaq.lang.scl.bind``); a standard OB keeps STEP 7's 20 bytes of VAR_TEMP start information.

Types as Nasaq holds them: hardware identifiers (TIA's HW_IO, HW_ANY) are WORDs, as TIA bases
them; OB_ANY is an INT and DB_ANY a UINT (their TIA base types). The simulator has no hardware
events: Nasaq's CPU starts these inputs at 0/FALSE (COMPATIBILITY.md, "Organization blocks").
"""

from __future__ import annotations

from nasaq.lang.tia_names import EVENTS, FIRST_FREE_OB, ob_event

_ERROR_OB = (
    ("BlockNr", "UINT"),
    ("Reaction", "USINT"),
    ("Fault_ID", "BYTE"),
    ("BlockType", "USINT"),
    ("Area", "USINT"),
    ("DBNr", "UINT"),
    ("Csg_OBNr", "INT"),
    ("Csg_Prio", "USINT"),
    ("Width", "USINT"),
)
_MODULE_EVENT = (("LADDR", "WORD"), ("Event_Class", "BYTE"), ("Fault_ID", "BYTE"))

# Event key (``tia_names.EVENTS``) → the inputs TIA declares, in its order.
START_INFO: dict[str, tuple[tuple[str, str], ...]] = {
    "program_cycle": (("Initial_Call", "BOOL"), ("Remanence", "BOOL")),
    "startup": (("LostRetentive", "BOOL"), ("LostRTC", "BOOL")),
    "time_of_day": (("CaughtUp", "BOOL"), ("SecondTimes", "BOOL")),
    "time_delay": (("Sign", "WORD"),),
    "cyclic_interrupt": (("Initial_Call", "BOOL"), ("Event_Count", "INT")),
    "hardware_interrupt": (
        ("LADDR", "WORD"),
        ("USI", "WORD"),
        ("IChannel", "USINT"),
        ("EventType", "BYTE"),
    ),
    "time_error": (("fault_id", "BYTE"), ("csg_OBnr", "INT"), ("csg_prio", "UINT")),
    "diagnostic_error": (
        ("IO_state", "WORD"),
        ("LADDR", "WORD"),
        ("Channel", "UINT"),
        ("MultiError", "BOOL"),
    ),
    "pull_or_plug": _MODULE_EVENT,
    "rack_failure": _MODULE_EVENT,
    "programming_error": _ERROR_OB,
    "io_access_error": _ERROR_OB,
}


def start_info(name: str, number: int) -> tuple[tuple[str, str], ...]:
    """The start information of the OB called ``name`` with ``number``: by its event name
    ("Diagnostic error interrupt"), else by its number (OB82); () for an event without any."""
    event = ob_event(name)
    if event is None:
        event = next((e for e in EVENTS if number in e.s7_1500 or number in e.classic), None)
    if event is None and number >= FIRST_FREE_OB:  # a further program-cycle OB ("Main_1")
        return START_INFO["program_cycle"]
    return START_INFO.get(event.key, ()) if event is not None else ()
