"""Standard S7-300/400 layout rules (nasaq.lang.layout)."""

from __future__ import annotations

from nasaq.lang.layout import Layout
from nasaq.lang.types import ArrayType, BlockType, Elementary, Field, StringType, StructType

BOOL, BYTE, INT, DINT = (Elementary(name) for name in ("BOOL", "BYTE", "INT", "DINT"))


def _layout() -> Layout:
    udt = StructType((Field("a", BOOL), Field("b", INT)))
    return Layout(lambda block: udt if block == BlockType("UDT", 1) else None)


def _offsets(fields: list[Field]) -> list[tuple[str, float]]:
    return [(slot.name, slot.offset_bits / 8) for slot in _layout().place(fields)]


def test_bools_pack_bytes_align_and_words_are_even() -> None:
    fields = [
        Field("a", BOOL),
        Field("b", BOOL),
        Field("c", BYTE),
        Field("d", BYTE),
        Field("e", BOOL),
        Field("f", INT),
        Field("g", BYTE),
        Field("h", DINT),
    ]
    assert _offsets(fields) == [
        ("a", 0.0),
        ("b", 0.125),
        ("c", 1.0),
        ("d", 2.0),
        ("e", 3.0),
        ("f", 4.0),
        ("g", 6.0),
        ("h", 8.0),
    ]


def test_structured_types_start_even_and_occupy_whole_words() -> None:
    fields = [
        Field("a", BYTE),
        Field("s", StructType((Field("x", BOOL),))),
        Field("b", BYTE),
        Field("arr", ArrayType(((1, 3),), BYTE)),
        Field("c", BYTE),
        Field("txt", StringType(3)),
        Field("d", BYTE),
        Field("u", BlockType("UDT", 1)),
    ]
    assert _offsets(fields) == [
        ("a", 0.0),
        ("s", 2.0),
        ("b", 4.0),
        ("arr", 6.0),
        ("c", 10.0),
        ("txt", 12.0),
        ("d", 18.0),
        ("u", 20.0),
    ]


def test_array_strides_and_multi_dimensional_elements() -> None:
    layout = _layout()
    bools = ArrayType(((1, 10),), BOOL)
    words = ArrayType(((0, 1), (1, 3)), INT)
    assert layout.size_bits(bools) == 16
    assert layout.size_bits(words) == 6 * 16
    (slot,) = layout.place([Field("m", words)])
    element = layout.element(slot, [1, 2])
    assert element is not None
    assert element.offset_bits == (3 + 1) * 16
    assert layout.element(slot, [2, 1]) is None
    assert layout.element(slot, [1]) is None


def test_fb_instance_sections_in_order_each_starting_even() -> None:
    layout = _layout()
    slots, size = layout.instance(
        [
            ("STAT", [Field("s", INT)]),
            ("IN", [Field("i", BOOL)]),
            ("OUT", [Field("o", BOOL)]),
            ("IN_OUT", [Field("io", BOOL), Field("big", StructType((Field("x", INT),)))]),
        ]
    )
    assert [(slot.name, slot.section, slot.offset_bits) for slot in slots] == [
        ("i", "IN", 0),
        ("o", "OUT", 16),
        ("io", "IN_OUT", 32),
        ("big", "IN_OUT", 48),
        ("s", "STAT", 96),
    ]
    assert slots[3].by_reference
    assert slots[3].size_bits == 48
    assert size == 112


def test_struct_sizes_round_up_to_even() -> None:
    layout = _layout()
    assert layout.size_bits(StructType((Field("x", BOOL),))) == 16
    assert (
        layout.size_bits(StructType((Field("x", BYTE), Field("y", BYTE), Field("z", BYTE)))) == 32
    )
    assert layout.size_bits(BlockType("UDT", 1)) == 32
