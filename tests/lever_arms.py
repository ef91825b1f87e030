"""Zhukovsky's lever's arms read back from a force sheet's SVG and from the note's table of the lever's moments, and
checked to agree: the same names for the same loads, each named arm as long in the note as it is drawn."""

from __future__ import annotations

import re
from pathlib import Path
from xml.etree import ElementTree

from lever_equation import unfactored

from graphplan.locale import load_symbol, strings
from graphplan.render.primitives import svg_id

SVG = "{http://www.w3.org/2000/svg}"
# A term of ΣMp multiplied out: a sign, a load's name, its arm (h3, hb, hу); a block's M·ω/μV has no arm.
SHEET_TERM = re.compile(r"[+−] ([^\s·]+)·(h[^\s·()=]+)")
# A length cell of the note's table, with the arm's name before it where the lever names one: ``h2 = 49.19`` (in
# Russian ``h2 = 49,19``).
NOTE_ARM = re.compile(r"^(?:(?P<arm>h\S*) = )?(?P<length>\d+(?:[.,]\d+)?)")
# The moves of a path as the SVG writes them: ``M25.002,530.163 L28.172,509.427``.
PATH_POINT = re.compile(r"[ML](-?[\d.]+),(-?[\d.]+)")


def sheet_arms(svg: Path, panel: str = "") -> tuple[dict[str, str], set[str], dict[str, float]]:
    """The arm ΣMp on the sheet's lever names for each load (Fb's among them), the arm names lettered on the lever or
    given under it, and the length (mm) of each arm drawn from the pole, by the id of its load's layer; on a course
    sheet, of the lever in its drawing ``panel`` (``forces-2-3``), whose name starts its layers' ids there."""
    root = ElementTree.parse(svg).getroot()
    start = f"{panel}-" if panel else ""
    layers = {layer.get("id").removeprefix(start): layer for layer in root.iter(f"{SVG}g")
              if (layer.get("id") or "").startswith(start)}
    caption = " ".join("".join(text.itertext()) for text in layers["lever-caption"].findall(f"{SVG}text"))
    equation = re.search(r"ΣMp: (.*?) = 0", caption)
    assert equation, f"{svg.name}: no ΣMp under the lever: {caption}"
    # Every term signed and its sign set apart, as the equation's later terms are: −G3·h1 leads it as − G3·h1.
    terms = equation.group(1)
    terms = f"{terms[0]} {terms[1:]}" if terms[0] in "+−" else f"+ {terms}"
    named = dict(SHEET_TERM.findall(unfactored(terms)))
    lettered = {"".join(text.itertext()) for text in layers["lever-labels"].findall(f"{SVG}text")}
    lettered = {name for name in lettered if re.fullmatch(r"h\w+", name)}
    lettered |= set(re.findall(r"(h\w+) = [\d.]+", caption))  # an arm too short or too crowded to letter on it
    (pole,) = [complex(float(dot.get("cx")), float(dot.get("cy")))
               for dot in layers["lever-points"].findall(f"{SVG}circle") if dot.get("r") == "0.7"]
    lengths = {}
    for layer_id, layer in layers.items():
        if not (layer_id or "").startswith("lever-arm-"):
            continue
        for path in layer.findall(f"{SVG}path"):  # the arm from the pole; a line run on to its foot starts elsewhere
            start, end = [complex(float(x), float(y)) for x, y in PATH_POINT.findall(path.get("d"))][:2]
            if abs(start - pole) <= 0.002:
                lengths[layer_id] = abs(end - start)
    return named, lettered, lengths


def note_arms(markdown: str, locale: str, table: str = "note_lever_table"
              ) -> dict[int, list[tuple[str, str | None, float]]]:
    """By position, each row of the note's table of the lever's moments (``table`` names its caption: the lever's
    with friction is another): the load, its arm's name (None where the row names none) and its length (mm)."""
    title = re.escape(strings(locale)[table]).replace(re.escape("{number}"), r"(\d+)") + r"$"
    found: dict[int, list[tuple[str, str | None, float]]] = {}
    number = None
    for line in markdown.splitlines():
        heading = re.search(title, line)
        if heading:
            number = int(heading.group(1))
            found[number] = []
        elif number is not None and line.startswith("| ") and not line.startswith("|---"):
            cells = [cell.strip() for cell in line.strip("|").split("|")]
            if cells[0] == strings(locale)["column_force"]:
                continue
            length = NOTE_ARM.match(cells[3])
            if length:  # a block's moment has no arm ("—")
                found[number].append((cells[0], length["arm"], float(length["length"].replace(",", "."))))
        elif number is not None and found[number] and not line.startswith("|"):
            number = None
    return found


def levers(made, friction: bool):
    """Each position's number, lever and the force sheet that draws it: the lever without friction on forces_N.svg,
    or (``friction``) the lever with the pairs' friction loads on forces_friction_N.svg, drawn where the construction
    with friction settled and does not lock."""
    for plan in made.analysis.plans:
        if not friction and plan.lever is not None:
            yield plan.number, plan.lever, f"forces_{plan.number}.svg"
        rubbing = plan.with_friction
        if friction and plan.lever_with_friction is not None and rubbing is not None and not rubbing.locked:
            yield plan.number, plan.lever_with_friction, f"forces_friction_{plan.number}.svg"


def check_arms_agree(folder: Path, made, locale: str, friction: bool = False) -> None:
    text = strings(locale)
    note = note_arms((folder / "note.md").read_text(encoding="utf-8"), locale,
                     "note_friction_lever_table" if friction else "note_lever_table")
    checked = 0
    for number, lever, drawing in levers(made, friction):
        latin = {load_symbol(term.name, text): term.name for term in lever.terms}
        named, lettered, lengths = sheet_arms(folder / drawing)
        # The note tables the loads, Fb's arm worked apart from them; the lever letters each arm ΣMp names, no other.
        assert named.pop(load_symbol("Fb", text)) == load_symbol("hb", text)
        assert lettered == {*named.values(), load_symbol("hb", text)}, f"position {number}: {lettered}, {named}"
        assert number in note, f"{drawing}: the note has no table of its lever's moments"
        rows = note[number]
        written = {name: arm for name, arm, _ in rows if arm is not None}
        assert written == named, (f"position {number}: the sheet's lever names the arms {named}, "
                                  f"the note's table {written}")
        # A shared arm's length is written once per row and drawn once, from its first load's point.
        for arm in set(named.values()):
            loads = [(name, length) for name, written_arm, length in rows if written_arm == arm]
            drawn = [lengths[key] for name, _ in loads if (key := svg_id("lever-arm", latin[name])) in lengths]
            assert len({length for _, length in loads}) == 1, f"position {number}: {arm} of {loads}"
            if drawn:
                assert abs(drawn[0] - loads[0][1]) <= 0.01, (f"position {number}: {arm} = {loads[0][1]} mm "
                                                             f"in the note, {drawn[0]:.3f} mm on the sheet")
        checked += len(named)
    assert checked > 0, "no lever names an arm"
