"""G3 (the course's example 1: N, S and R) through the lowering: the STL users see with
``--emit stl`` has a titled network per step and per transition with N/S/R as one line each,
and the compiled FB runs the sequencer on the CPU."""

from __future__ import annotations

from graph_lower_support import SCENARIOS, Plant

from nasaq.lang.graph.compile import lower_file

G3 = (SCENARIOS / "g03_nsr.graph").read_text(encoding="utf-8")


def _networks(stl: str) -> dict[str, list[str]]:
    """The instruction lines of each network, by title."""
    found: dict[str, list[str]] = {}
    lines = stl.split("\n")
    for k, line in enumerate(lines):
        if line == "NETWORK":
            title = lines[k + 1].removeprefix("TITLE = ")
            body: list[str] = []
            for rest in lines[k + 2 :]:
                if rest in ("NETWORK", "END_FUNCTION_BLOCK"):
                    break
                body.append(rest)
            found[title] = body
    return found


def test_one_titled_network_per_step_and_transition() -> None:
    lowered = lower_file("g03.graph", G3)
    assert not [d for d in lowered.diagnostics if d.severity == "error"]
    titles = list(_networks(lowered.stl))
    for wanted in (
        "S5 Step5",
        "S6 Step6",
        "S7 Step7",
        "T3 Trans3: Step5 -> Step6",
        "T4 Trans4: Step6 -> Step7",
        "T5 Trans5: Step7 -> Step5",
    ):
        assert titles.count(wanted) == 1, titles


def _words(line: str) -> list[str]:
    """An instruction line without its label."""
    words = line.split()
    return words[1:] if words and words[0].endswith(":") else words


def test_n_s_r_are_one_line_each_after_the_step_check() -> None:
    networks = {
        t: [_words(line) for line in body]
        for t, body in _networks(lower_file("g03.graph", G3).stl).items()
    }
    step5 = networks["S5 Step5"]
    assert step5[0] == ["A", "#Step5.X"]
    assert step5[1][0] == "JCN"
    assert step5[2] == ["=", "Q", "0.0"]
    assert networks["S6 Step6"][2] == ["S", "M", "0.0"]
    assert networks["S7 Step7"][2] == ["R", "Q", "0.1"]
    # the N bit is reset when its step is left; S and R bits stay as they are
    assert step5.count(["=", "Q", "0.0"]) == 2
    assert sum(words[-2:] == ["M", "0.0"] for words in networks["S6 Step6"]) == 1
    assert sum(words[-2:] == ["Q", "0.1"] for words in networks["S7 Step7"]) == 1


def test_g3_runs_on_the_cpu() -> None:
    plant = Plant(G3)
    plant.set("Q 0.1", 1)
    plant.scan()
    assert (plant.db("Step5.X"), plant.db("Step6.X"), plant.db("Step7.X")) == (
        True,
        False,
        False,
    )
    assert plant.db("Step5.S1") is True
    assert plant.bit("Q 0.0") == 1
    plant.scan(I0_0=1)
    assert plant.db("Trans3.TT") is True
    assert (plant.db("Step5.X"), plant.db("Step6.X")) == (False, True)
    assert plant.bit("Q 0.0") == 0
    assert plant.bit("M 0.0") == 1
    plant.scan(I0_0=0)
    assert plant.db("Step6.S1") is False  # the event is raised in one call only
    plant.scan(I0_1=1)
    assert plant.db("Step7.X") is True
    assert plant.bit("Q 0.1") == 0
    assert plant.bit("M 0.0") == 1  # S stays after its step was left
    plant.scan(5, I0_1=0)
    assert plant.db("Step7.T") > 0
    plant.scan(I0_3=1)
    assert plant.db("Step5.X") is True
    assert plant.db("Step5.T") == 0
    assert plant.bit("Q 0.0") == 1
    assert plant.db("S_NO") == 5
