import pytest

from nasaq.headless.addresses import (
    AddressError,
    CounterAddress,
    TimerAddress,
    address_text,
    as_real,
    encode_value,
    parse_address,
    parse_number,
    signed,
)
from nasaq.ir import Area, Direct, Width


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("I0.0", Direct(Area.I, Width.BIT, 0, 0)),
        ("i 1.7", Direct(Area.I, Width.BIT, 1, 7)),
        ("E 2.3", Direct(Area.I, Width.BIT, 2, 3)),
        ("QB4", Direct(Area.Q, Width.BYTE, 4)),
        ("AW 6", Direct(Area.Q, Width.WORD, 6)),
        ("MD20", Direct(Area.M, Width.DWORD, 20)),
        ("DB1.DBX0.0", Direct(Area.DB, Width.BIT, 0, 0, db=1)),
        ("DB12.DBW 4", Direct(Area.DB, Width.WORD, 4, db=12)),
        ("db3.dbd8", Direct(Area.DB, Width.DWORD, 8, db=3)),
        ("T5", TimerAddress(5)),
        ("C 7", CounterAddress(7)),
        ("Z2", CounterAddress(2)),
    ],
)
def test_addresses_as_users_type_them(text: str, expected: object) -> None:
    assert parse_address(text) == expected


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("I0", "bit number"),
        ("I0.8", "0 to 7"),
        ("MW10.1", "only bit addresses"),
        ("DB0.DBW0", "no DB 0"),
        ("X1", "not an address"),
        ("", "not an address"),
    ],
)
def test_bad_addresses_say_why(text: str, reason: str) -> None:
    with pytest.raises(AddressError, match=reason):
        parse_address(text)


def test_canonical_spelling_round_trips() -> None:
    for text in ("I0.0", "QB4", "MW10", "MD20", "DB1.DBX0.1", "DB2.DBW4", "DB3.DBD8"):
        address = parse_address(text)
        assert isinstance(address, Direct)
        assert address_text(address) == text


@pytest.mark.parametrize(
    ("text", "value"),
    [("5", 5), ("-3", -3), ("16#FF", 255), ("-16#10", -16), ("2#1010", 10), ("2.5", 2.5)],
)
def test_numbers(text: str, value: float) -> None:
    assert parse_number(text) == value


def test_values_become_bit_patterns() -> None:
    word = Direct(Area.M, Width.WORD, 0)
    assert encode_value(word, -1) == 0xFFFF
    assert encode_value(word, "16#8000") == 0x8000
    dword = Direct(Area.M, Width.DWORD, 0)
    assert encode_value(dword, 2.5) == 0x40200000
    assert as_real(0x40200000) == 2.5
    assert signed(0xFFFE, Width.WORD) == -2
    with pytest.raises(AddressError, match="does not fit"):
        encode_value(word, 70000)
    with pytest.raises(AddressError, match="does not fit"):
        encode_value(Direct(Area.I, Width.BIT, 0, 0), 2)
    with pytest.raises(AddressError, match="doubleword"):
        encode_value(word, 1.5)
