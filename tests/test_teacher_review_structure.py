"""A teacher's review of the structural analysis: counted by hand from each scene's own tables, as a textbook counts.

Every fixture, every starter and scenes written here (six-bars with their two class II groups in series and in
parallel, each dyad kind, triads with turning, sliding and slotted legs, a slider driver, a rocking crank) are read
as TOML and counted without graphplan's structure code: n, the moving links; p5, every turning pair (a pin that
joins k links is k − 1 pairs) and every sliding pair (a slider block's pin and its slide are two); p4 = 0; then
W = 3n − 2p5 − p4.  Each group's class (II for a dyad, III where a ternary link carries three inner pairs), order
(its outer pairs), kind (the letters of its pairs outer–inner–outer, as Artobolevsky sets them) and the links it
attaches to are worked out from the same tables, and the structure formula is written from them: each arrow leads
from a unit to a group attached to it.  The console (`graphplan check`), results.json and the note's first section
in en, ru and zh must say the same, the note in each language's textbook terms.
"""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import pytest
from light_runs import notes_in_markdown_alone, on_no_sheet
from test_motion_against_finite_differences import _HUNG_ON_THE_RATCHET

from graphplan.cli import main

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
ROMAN = {1: "I", 2: "II", 3: "III"}
LOCALES = ("en", "ru", "zh")

# ---- the hand count -------------------------------------------------------------------------------------------


def _guide_link(guide, frame: int) -> int:
    """The link a guide is fixed on: a named frame line, or a table with no `link`, is on the frame."""
    return guide.get("link", frame) if isinstance(guide, dict) else frame


def hand_count(tables: dict) -> dict:
    """n, p5, the groups (class, order, kind, links, turning pairs, the earlier units attached to) and the formula."""
    frame = tables["frame"].get("link", 1)
    carrier = dict.fromkeys(tables["frame"]["points"], frame)
    carrier.update({name: spec["link"] for name, spec in tables.get("points", {}).items()})
    pins: dict[str, set[int]] = {}
    sliding = 0

    def pin(name: str, *links: int) -> None:
        pins.setdefault(name, set()).update(links)

    driver = tables["driver"]
    units = [{"links": [driver["link"]], "label": f"I({frame},{driver['link']})", "attached": set()}]
    if driver["kind"] == "crank":
        pin(driver["pivot"], driver["link"])
        units[0]["pins"] = [driver["pivot"]]
    else:  # a driving slider: its slide on the frame is its pair; its pin belongs to the group hung on it
        sliding += 1
        units[0]["pins"] = []
    carrier[driver["joint"]] = driver["link"]
    for group in tables.get("groups", []):
        kind, links, joints = group["kind"], group["links"], group["joints"]
        outer_on: list[int] = []  # the links the group's outer pairs join it to

        def outer_pin(name: str, link: int, outer_on=outer_on) -> None:
            pin(name, link)
            outer_on.append(carrier[name])

        if kind == "RRR":
            a, b = links
            outer_pin(joints[0], a)
            pin(joints[1], a, b)
            outer_pin(joints[2], b)
            letters, own_pins, klass = "RRR", [joints[0], joints[1], joints[2]], 2
        elif kind == "RRP":  # A pins a, B pins a to the slider b, which slides on its guide
            a, b = links
            outer_pin(joints[0], a)
            pin(joints[1], a, b)
            sliding += 1
            outer_on.append(_guide_link(group["guide"], frame))
            letters, own_pins, klass = "RRP", [joints[0], joints[1]], 2
        elif kind == "RPR":  # the block a pinned at A slides on the lever b, which turns about C
            a, b = links
            outer_pin(joints[0], a)
            sliding += 1
            outer_pin(joints[1], b)
            letters, own_pins, klass = "RPR", [joints[0], joints[1]], 2
        elif kind == "PRP":  # two sliders, each on its guide, pinned together at B
            a, b = links
            sliding += 2
            pin(joints[0], a, b)
            outer_on.extend(_guide_link(guide, frame) for guide in group["guides"])
            letters, own_pins, klass = "PRP", [joints[0]], 2
        elif kind == "RPP":  # the block a pinned at A slides in b's slot; b slides on its guide; B is only a point
            a, b = links
            outer_pin(joints[0], a)
            sliding += 2
            outer_on.append(_guide_link(group["guide"], frame))
            letters, own_pins, klass = "RPP", [joints[0]], 2
        else:  # the triad: legs a, b, c round the ternary link t
            *legs, ternary = links
            guides, slots = group.get("guides", {}), group.get("slots", {})
            own_pins = []
            for leg, outer, inner in zip(legs, joints[0::2], joints[1::2], strict=True):
                if inner in guides:  # a slider pinned to t at its inner joint, sliding on a guide through outer
                    pin(inner, leg, ternary)
                    sliding += 1
                    outer_on.append(_guide_link(guides[inner], frame))
                    own_pins.append(inner)
                elif inner in slots:  # a block pinned at outer, sliding in a slot of t through inner
                    outer_pin(outer, leg)
                    sliding += 1
                    own_pins.append(outer)
                else:
                    outer_pin(outer, leg)
                    pin(inner, leg, ternary)
                    own_pins += [outer, inner]
            letters, klass = "triad", 3
            own_pins = [name for name in joints if name in own_pins]
        for name in joints:
            carrier.setdefault(name, links[-1] if name not in pins else min(pins[name]))
        owner = {link: index for index, unit in enumerate(units) for link in unit["links"]}
        attached = {owner[link] for link in outer_on if link != frame}
        order = len(outer_on)
        label = f"{ROMAN[klass]}{order}({','.join(map(str, links))})"
        units.append({"links": list(links), "label": label, "attached": attached, "class": klass, "order": order,
                      "kind": letters, "pins": own_pins, "outer_on": outer_on})
    for name, links in pins.items():  # a pin joins the link its point is on, too
        links.add(carrier[name])
    turning = sum(len(links) - 1 for links in pins.values())
    n = sum(len(unit["links"]) for unit in units)
    p5, p4 = turning + sliding, 0
    # Each arrow leads from a unit to a group attached to it: a group not attached to the one written before it
    # starts a new branch from the latest unit it is attached to.
    formula, last = units[0]["label"], 0
    for index, unit in enumerate(units[1:], start=1):
        if last not in unit["attached"]:
            formula += f"; {units[max(unit['attached'])]['label']}"
        formula += f" → {unit['label']}"
        last = index
    return {"n": n, "p5": p5, "p4": p4, "W": 3 * n - 2 * p5 - p4, "units": units, "formula": formula,
            "class": max([1] + [unit["class"] for unit in units[1:]])}


# ---- the scenes -----------------------------------------------------------------------------------------------

_CRANK = """
[scene]
title = "A hand-counted mechanism"
gravity = 0.0
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.3, 0.0], F = [0.1, -0.35] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.08
omega = 10.0
"""
_FOUR_BAR = """
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.3, 0.25]
assembly = "left"
"""
OWN = {
    # The second dyad hangs on the rocker 4: I → II(3,4) → II(5,6).
    "six-bar-in-series": _CRANK + _FOUR_BAR + """
[[groups]]
kind = "RRR"
links = [5, 6]
joints = ["E", "G", "F"]
lengths = [0.3, 0.3]
assembly = "right"
[points]
E = { link = 4, from = "C", toward = "B", at = 0.12 }
""",
    # The second dyad hangs on the crank's pin A, which then joins three links (two pairs), and on a frame
    # guide: both dyads are attached to the crank, neither to the other.
    "six-bar-in-parallel": _CRANK + _FOUR_BAR + """
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["A", "D"]
length = 0.3
guide = { through = "O", angle = 180.0 }
assembly = "forward"
""",
    # The same, the second dyad at a point of the crank of its own.
    "six-bar-in-parallel-at-a-point": _CRANK + _FOUR_BAR + """
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["K", "D"]
length = 0.3
guide = { through = "O", angle = 180.0 }
assembly = "forward"
[points]
K = { link = 2, from = "O", toward = "A", at = 0.05 }
""",
    # The rocker turns about the crank's own pivot O: O joins the frame, the crank and the rocker, two pairs.
    "rocker-on-the-crank-pivot": _CRANK + _FOUR_BAR.replace('"C"]', '"O"]'),
    "RPR-then-PRP": _CRANK + """
[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
[[groups]]
kind = "PRP"
links = [5, 6]
joints = ["B"]
guides = [{ link = 4, through = "C", angle = 0.0 }, { through = [-0.1, 0.0], angle = 90.0 }]
offsets = [0.0, 0.0]
""",
    "RPP": _CRANK + """
[[groups]]
kind = "RPP"
links = [3, 4]
joints = ["A", "B"]
guide = { through = [0.0, 0.0], angle = 90.0 }
angle = 90.0
""",
    "RRP-slider-crank": _CRANK + """
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.3
guide = { through = "O", angle = 0.0 }
assembly = "forward"
""",
    "slider-driver": """
[scene]
title = "A piston driving a rocker"
gravity = 0.0
[frame]
link = 1
points = { G = [0.0, 0.0], C = [0.3, 0.15] }
[driver]
kind = "slider"
link = 2
joint = "A"
guide = { through = "G", angle = 0.0 }
travel = [0.0, 0.1]
velocity = 0.1
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.25, 0.2]
assembly = "right"
""",
    "rocking-crank": _CRANK.replace("omega = 10.0", "omega = 1.0\nswing = [10.0, 70.0]") + _FOUR_BAR,
}
# The ratchet's crank-rocker with a group hung on its rocker: an RRP, an RPP, a PRP, triads whose legs turn,
# slide on guides or slide in slots of the ternary link.
for name, group in _HUNG_ON_THE_RATCHET.items():
    OWN[name] = (FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8").replace(
        "\n[points]", group + "\n[points]")

STARTERS = ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad")


@pytest.fixture(scope="module")
def scenes(tmp_path_factory) -> dict[str, Path]:
    folder = tmp_path_factory.mktemp("scenes")
    paths = {f"fixture {path.stem}": path for path in sorted(FIXTURES.glob("*.toml"))}
    for kind in (*STARTERS, "flywheel", "rotor"):
        assert main(["new", kind, "--out", str(folder / f"{kind}.toml")]) == 0
        paths[f"starter {kind}"] = folder / f"{kind}.toml"
    for name, text in OWN.items():
        paths[name] = folder / f"{name}.toml"
        paths[name].write_text(text, encoding="utf-8")
    return paths


NAMES = ([f"fixture {path.stem}" for path in sorted(FIXTURES.glob("*.toml"))] + [f"starter {kind}" for kind in STARTERS]
         + list(OWN))


def _section(note: str) -> str:
    """The note's first section, the structural analysis."""
    start = note.index("\n## 1")
    return note[start:note.index("\n## ", start + 1)]


def _table_rows(section: str) -> list[list[str]]:
    rows = [[cell.strip() for cell in line.strip().strip("|").split("|")] for line in section.splitlines()
            if line.startswith("|")]
    return rows[2:]


# The column lists turning pairs alone (a sliding pair has no letter of its own), and says so.
PAIRS_COLUMN = {"en": "turning pairs", "ru": "вращательные пары", "zh": "转动副"}
CLASS_ORDER = {"en": "class {k}, order {o}", "ru": "класс {k}, порядок {o}", "zh": "{k} 级杆组（{o} 个外副）"}
TRIAD = {"en": "triad", "ru": "трёхповодковая группа", "zh": "III 级杆组"}
RUSSIAN_LETTERS = str.maketrans("RP", "ВП")
FORMULA = {"en": "Structure formula: {f}. The mechanism is of class {k}, the highest class of its groups.",
           "ru": "Формула строения механизма: {f}. Механизм {k} класса: класс механизма определяется высшим классом "
                 "входящих в него групп.",
           "zh": "机构的组成：{f}。所含杆组的最高级别为 {k} 级，故为 {k} 级机构。"}
COUNTS = {"en": ("n = {n} moving links", "p5 = {p5} lower kinematic pairs", "p4 = 0"),
          "ru": ("Число подвижных звеньев n = {n}", "p5 = {p5}", "p4 = 0"),
          "zh": ("活动构件数 n = {n}", "PL = {p5}", "PH = 0")}


def _kind_text(kind: str, locale: str) -> str:
    if kind == "triad":
        return TRIAD[locale]
    if locale == "ru":
        return f"{kind.translate(RUSSIAN_LETTERS)} ({kind})"
    return kind


@pytest.fixture(scope="module")
def runs(scenes, tmp_path_factory):
    """Each scene checked on the console and run for its note in each language: (console, results, notes)."""
    done = {}

    def run(name: str, capsys):
        if name not in done:
            path = on_no_sheet(scenes[name], tmp_path_factory.mktemp("light"))
            assert main(["check", str(path)]) == 0
            console = capsys.readouterr().out
            notes, results = {}, None
            for locale in LOCALES:
                out = tmp_path_factory.mktemp("out")
                with notes_in_markdown_alone():
                    assert main(["run", str(path), "--out", str(out), "--only", "note", "--locale", locale]) == 0
                notes[locale] = (out / "note.md").read_text(encoding="utf-8")
                results = json.loads((out / "results.json").read_text(encoding="utf-8"))
            capsys.readouterr()
            done[name] = console, results, notes
        return done[name]
    return run


@pytest.mark.parametrize("name", NAMES)
def test_the_console_and_results_json_count_as_the_hand_does(name, scenes, runs, capsys):
    counted = hand_count(tomllib.loads(scenes[name].read_text(encoding="utf-8")))
    assert counted["W"] == 1
    console, results, _ = runs(name, capsys)
    assert f"structure: {counted['formula']}\n" in console
    assert f"W = 3n − 2p5 − p4 = 3·{counted['n']} − 2·{counted['p5']} − 0 = 1\n" in console
    assert results["structure"] == counted["formula"]
    assert results["degrees_of_freedom"] == {"moving_links": counted["n"], "lower_pairs": counted["p5"], "W": 1}
    assert [group["kind"] for group in results["groups"]] == [unit["kind"] for unit in counted["units"][1:]]
    assert [group["links"] for group in results["groups"]] == [unit["links"] for unit in counted["units"][1:]]


@pytest.mark.parametrize("name", NAMES)
def test_the_notes_structural_analysis_counts_as_the_hand_does_in_each_language(name, scenes, runs, capsys):
    counted = hand_count(tomllib.loads(scenes[name].read_text(encoding="utf-8")))
    _, _, notes = runs(name, capsys)
    for locale in LOCALES:
        section = _section(notes[locale])
        for said in COUNTS[locale]:
            assert said.format(**counted) in section, (locale, said)
        numbers = re.search(r"= 3[·×](\d+) − 2[·×](\d+) − (\d+) = (\d+)", section)
        assert numbers and tuple(map(int, numbers.groups())) == (counted["n"], counted["p5"], 0, 1), locale
        rows = _table_rows(section)
        assert len(rows) == len(counted["units"])
        (driver, *groups) = counted["units"]
        assert rows[0][0] == driver["label"] and rows[0][2] == ", ".join(map(str, [1, *driver["links"]]))
        for row, unit in zip(rows[1:], groups, strict=True):
            roman = ROMAN[unit["class"]]
            assert row[0] == f"{roman}({','.join(map(str, unit['links']))})"
            assert row[1] == CLASS_ORDER[locale].format(k=roman, o=unit["order"]), (locale, row)
            assert row[2] == ", ".join(map(str, unit["links"]))
            assert row[4] == _kind_text(unit["kind"], locale), (locale, row)
        assert FORMULA[locale].format(f=counted["formula"], k=ROMAN[counted["class"]]) in section, locale


@pytest.mark.parametrize("name", NAMES)
def test_the_structure_table_lists_each_units_own_turning_pairs_under_that_name(name, scenes, runs, capsys):
    """The column was «joints» («кинематические пары», «运动副») and listed the crank's pin A under I(1,2) as well as
    under the group that closes the pair, an RPP's B (where its slot crosses the guide, no pair), a sliding leg's
    point on its guide and a slotted leg's inner joint: counted there, the pairs came out more than p5."""
    counted = hand_count(tomllib.loads(scenes[name].read_text(encoding="utf-8")))
    _, _, notes = runs(name, capsys)
    for locale in LOCALES:
        section = _section(notes[locale])
        header = next(line for line in section.splitlines() if line.startswith("|"))
        assert f"| {PAIRS_COLUMN[locale]} |" in header, (locale, header)
        rows = _table_rows(section)
        for row, unit in zip(rows, counted["units"], strict=True):
            assert row[3] == (", ".join(unit["pins"]) or "—"), (locale, row)


@pytest.mark.parametrize("name", [name for name in NAMES if "fixture" in name])
def test_the_notes_group_headings_name_each_kind_as_the_structure_table_does(name, scenes, runs, capsys):
    counted = hand_count(tomllib.loads(scenes[name].read_text(encoding="utf-8")))
    _, _, notes = runs(name, capsys)
    kinds = {f"{ROMAN[unit['class']]}({','.join(map(str, unit['links']))})": unit["kind"]
             for unit in counted["units"][1:]}
    heading = {"en": r"Group ({}), kind (.+?)\*", "ru": r"Группа ({}), вид: (.+?)\*", "zh": r"杆组 ({})，类型：(.+?)\*"}
    for locale in LOCALES:
        found = re.findall(heading[locale].format(r"I+\([\d,]+\)"), notes[locale])
        assert found, locale
        for label, kind in found:
            assert kind == _kind_text(kinds[label], locale), (locale, label, kind)


def test_the_russian_and_chinese_notes_use_the_textbooks_terms(scenes, runs, capsys):
    _, _, notes = runs("fixture triad_class_iii", capsys)
    russian, chinese = _section(notes["ru"]), _section(notes["zh"])
    for term in ("группы Ассура", "класс III, порядок 3", "| вид |", "формуле Чебышева", "Формула строения механизма",
                 "Механизм III класса"):
        assert term in russian, term
    for term in ("阿苏尔杆组", "III 级杆组（3 个外副）", "F = 3n − 2PL − PH", "III 级机构", "低副", "高副"):
        assert term in chinese, term


@pytest.mark.parametrize("kind", ["flywheel", "rotor"])
def test_a_machine_without_a_linkage_has_no_structural_analysis(kind, scenes, tmp_path, capsys):
    assert main(["check", str(scenes[f"starter {kind}"])]) == 0
    assert "structure:" not in capsys.readouterr().out
    assert main(["run", str(scenes[f"starter {kind}"]), "--out", str(tmp_path), "--only", "note"]) == 0
    results = json.loads((tmp_path / "results.json").read_text(encoding="utf-8"))
    assert "structure" not in results and "degrees_of_freedom" not in results
    note = (tmp_path / "note.md").read_text(encoding="utf-8")
    assert "Structural analysis" not in note and "Chebyshev" not in note


TRUSSES = {
    # Both outer joints on the crank: links 2, 3 and 4 make a rigid triangle, which turns as one link.
    "RRR on the crank alone": ("""
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "D"]
lengths = [0.3, 0.28]
assembly = "left"
[points]
D = { link = 2, from = "O", toward = "A", at = 0.04 }
""", ("groups[0].joints: joins link 2 alone (its outer joints A, D are points of link 2), so the group moves "
          "with link 2 as one rigid body, no Assur group")),
    # The block on the crank pin, its slot link on a guide fixed on the crank: the yoke cannot slide.
    "RPP on the crank alone": ("""
[[groups]]
kind = "RPP"
links = [3, 4]
joints = ["A", "B"]
guide = { link = 2, through = "O", angle = 90.0 }
angle = 90.0
""", ("groups[0].joints: joins link 2 alone (its outer joint A is a point of link 2 and its guide is on link 2), "
          "so the group moves with link 2 as one rigid body, no Assur group")),
}


@pytest.mark.parametrize("name", list(TRUSSES))
def test_a_group_joined_to_one_moving_link_alone_is_refused_as_a_truss(name, tmp_path, capsys):
    """An Assur group's outer pairs join at least two links: on one link alone the group and that link are a rigid
    truss (W = 0 for the group and the link's own motion for all), which Chebyshev's count cannot tell."""
    text, message = TRUSSES[name]
    tables = tomllib.loads(_CRANK + text)
    counted = hand_count(tables)
    assert counted["W"] == 1  # the formula alone passes it: the refusal is the structure's, not the count's
    assert {link for unit in counted["units"][1:] for link in unit["outer_on"]} == {2}
    scene = tmp_path / "truss.toml"
    scene.write_text(_CRANK + text, encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    printed = capsys.readouterr()
    assert message in printed.err and "Traceback" not in printed.err
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("locale", LOCALES)
def test_forces_md_ends_its_sentence_after_a_branched_formula(locale, tmp_path):
    """forces.md wrote «Structure {formula}; groups from the last…»: after a formula whose branches a «; » parts,
    the clause break read as one more branch."""
    text = OWN["six-bar-in-parallel"] + """
[links.3]
mass = 1.0
centre = "A"
[[loads]]
kind = "force"
link = 6
point = "D"
value = 100.0
angle = 180.0
[positions]
count = 8
plans = [2]
"""
    formula = hand_count(tomllib.loads(text))["formula"]
    assert formula == "I(1,2) → II2(3,4); I(1,2) → II2(5,6)"
    scene = tmp_path / "parallel.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "forces", "--locale", locale]) == 0
    forces = (out / "forces.md").read_text(encoding="utf-8")
    assert f"{formula}{'。' if locale == 'zh' else '. '}" in forces
    assert f"{formula};" not in forces and f"{formula}；" not in forces
