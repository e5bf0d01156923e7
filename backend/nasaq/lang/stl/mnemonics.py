"""The two STL mnemonic sets and which one a file uses.

IR ops are always the international spelling. The SIMATIC (German) set renames some
instructions, and two of the renamings cross: German ``SE`` is international ``SD`` (on-delay)
and German ``SV`` is international ``SE`` (extended pulse), so a file's set must be known
before any timer instruction means anything. A file is German when its German-only evidence
(mnemonics such as U/UN/SPA/AUF, areas E/A/Z/PE/PA) outweighs its international-only evidence
(A/AN/JU/OPN, areas I/Q/C/PI/PQ); a file with neither defaults to international.
"""

from __future__ import annotations

from collections.abc import Iterable

INTERNATIONAL = frozenset(
    [
        "A",
        "AN",
        "O",
        "ON",
        "X",
        "XN",
        "A(",
        "AN(",
        "O(",
        "ON(",
        "X(",
        "XN(",
        ")",
        "=",
        "S",
        "R",
        "SET",
        "CLR",
        "NOT",
        "SAVE",
        "FP",
        "FN",
        "SP",
        "SE",
        "SD",
        "SS",
        "SF",
        "FR",
        "CU",
        "CD",
        "L",
        "LC",
        "T",
        "TAK",
        "PUSH",
        "POP",
        "ENT",
        "LEAVE",
        "INC",
        "DEC",
        "+",
        "CAW",
        "CAD",
        "+I",
        "-I",
        "*I",
        "/I",
        "+D",
        "-D",
        "*D",
        "/D",
        "MOD",
        "+R",
        "-R",
        "*R",
        "/R",
        "ABS",
        "SQR",
        "SQRT",
        "EXP",
        "LN",
        "SIN",
        "COS",
        "TAN",
        "ASIN",
        "ACOS",
        "ATAN",
        "==I",
        "<>I",
        ">I",
        "<I",
        ">=I",
        "<=I",
        "==D",
        "<>D",
        ">D",
        "<D",
        ">=D",
        "<=D",
        "==R",
        "<>R",
        ">R",
        "<R",
        ">=R",
        "<=R",
        "BTI",
        "ITB",
        "BTD",
        "DTB",
        "ITD",
        "DTR",
        "INVI",
        "INVD",
        "NEGI",
        "NEGD",
        "NEGR",
        "RND",
        "RND+",
        "RND-",
        "TRUNC",
        "AW",
        "OW",
        "XOW",
        "AD",
        "OD",
        "XOD",
        "SSI",
        "SSD",
        "SLW",
        "SRW",
        "SLD",
        "SRD",
        "RLD",
        "RRD",
        "RLDA",
        "RRDA",
        "JU",
        "JC",
        "JCN",
        "JCB",
        "JNB",
        "JBI",
        "JNBI",
        "JO",
        "JOS",
        "JZ",
        "JN",
        "JP",
        "JM",
        "JPZ",
        "JMZ",
        "JUO",
        "JL",
        "LOOP",
        "MCR(",
        ")MCR",
        "MCRA",
        "MCRD",
        "CALL",
        "UC",
        "CC",
        "BE",
        "BEC",
        "BEU",
        "OPN",
        "CDB",
        "LAR1",
        "LAR2",
        "TAR1",
        "TAR2",
        "CAR",
        "+AR1",
        "+AR2",
        "NOP",
        "BLD",
    ]
)

TEST_OPS = frozenset(
    [
        "__ASSERT==",
        "__ASSERT<>",
        "__ASSERT<",
        "__ASSERT<=",
        "__ASSERT>",
        "__ASSERT>=",
        "__ASSERT==R",
        "__STWRST",
        "__SLEEP",
        "__FEATURE",
    ]
)

GERMAN_TO_INTERNATIONAL = {
    "U": "A",
    "UN": "AN",
    "U(": "A(",
    "UN(": "AN(",
    "SI": "SP",
    "SV": "SE",
    "SE": "SD",
    "SA": "SF",
    "ZV": "CU",
    "ZR": "CD",
    "TAW": "CAW",
    "TAD": "CAD",
    "UW": "AW",
    "UD": "AD",
    "SPA": "JU",
    "SPB": "JC",
    "SPBN": "JCN",
    "SPBB": "JCB",
    "SPBNB": "JNB",
    "SPBI": "JBI",
    "SPBIN": "JNBI",
    "SPO": "JO",
    "SPS": "JOS",
    "SPZ": "JZ",
    "SPN": "JN",
    "SPP": "JP",
    "SPM": "JM",
    "SPPZ": "JPZ",
    "SPMZ": "JMZ",
    "SPU": "JUO",
    "SPL": "JL",
    "AUF": "OPN",
    "TDB": "CDB",
    "BEB": "BEC",
    "BEA": "BEU",
    "TAR": "CAR",
}
_RENAMED = frozenset(GERMAN_TO_INTERNATIONAL.values())
GERMAN = frozenset(INTERNATIONAL - _RENAMED) | frozenset(GERMAN_TO_INTERNATIONAL) | {"SE"}
_GERMAN_ONLY = GERMAN - INTERNATIONAL
_INTERNATIONAL_ONLY = INTERNATIONAL - GERMAN

NAMES = {"en": "international", "de": "SIMATIC (German)"}


def to_international(mnemonic: str, language: str) -> str | None:
    """The IR op for ``mnemonic`` (upper case) in the file's set, or None if the set lacks it."""
    if language == "de":
        if mnemonic in GERMAN_TO_INTERNATIONAL:
            return GERMAN_TO_INTERNATIONAL[mnemonic]
        return mnemonic if mnemonic in GERMAN else None
    return mnemonic if mnemonic in INTERNATIONAL else None


def other_language(mnemonic: str, language: str) -> str | None:
    """The other set's name when only that set knows ``mnemonic`` (for a helpful message)."""
    if language == "de" and mnemonic in INTERNATIONAL and mnemonic not in GERMAN:
        return "en"
    if language == "en" and mnemonic in GERMAN and mnemonic not in INTERNATIONAL:
        return "de"
    return None


def detect(mnemonics: Iterable[str], area_languages: Iterable[str | None]) -> str:
    """``"de"`` or ``"en"`` from the upper-case mnemonics and the address areas of one file."""
    german = international = 0
    for mnemonic in mnemonics:
        if mnemonic in _GERMAN_ONLY:
            german += 1
        elif mnemonic in _INTERNATIONAL_ONLY:
            international += 1
    for language in area_languages:
        if language == "de":
            german += 1
        elif language == "en":
            international += 1
    return "de" if german > international else "en"
