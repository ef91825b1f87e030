"""The force sheets with friction, the note and forces.md name each pair with friction alike: by its joint (ρO, fC), or by
its links where two pairs with friction share the joint (the shaper's crank pin A in its block and the block in the
slot, ρ23 and f43).  The sheet wrote ρA and ρE where the note wrote ρ23 and ρ56.  A flat guide's coefficient is f as
given; only a V-guide's is the reduced f′ = f/sin θ (a flat guide was written f′E = 0.1).
"""

import math
import re

import pytest

from graphplan.analysis import analyse
from graphplan.render import forces as force_layout
from graphplan.render.drawings import at_length_scale, force_sheet
from graphplan.report.forces import markdown
from graphplan.report.note import note_markdown
from graphplan.scene import loads as scene_from_text
from graphplan.starters import starter

# Beside the starter's ram slide at E and crank journal at O: the crank pin A (2–3), the block in the slot (3–4),
# the lever's pivot C, its end D and the ram's pin E (5–6), each (f, radius); a radius of None is a slide.
MORE = {("A", (3, 4)): (0.12, None), ("A", (2, 3)): (0.1, 0.015), ("C", None): (0.1, 0.03), ("D", None): (0.1, 0.012),
        ("E", (5, 6)): (0.1, 0.012)}
NAME = r"(?<![A-Za-z])((?:ρ|f′?)(?:[A-Z]|\d\d))"


def shaper(groove: float | None = None):
    text = starter("shaper", "en")
    if groove is not None:
        text = text.replace("f     = 0.1\n", f"f     = 0.1\ngroove_half_angle = {groove}\n", 1)
    for (joint, links), (f, radius) in MORE.items():
        text += f'\n[[friction]]\njoint = "{joint}"\nf = {f}\n'
        text += f"links = [{links[0]}, {links[1]}]\n" if links else ""
        text += f"radius = {radius}\n" if radius else ""
    # At the μl a run chooses for the starter on its A1 (0.004 m/mm): choosing it lays every sheet out at each μl
    # tried, four fifths of the test's time, and the names and values read here are the scene's, not the drawing's.
    return at_length_scale(analyse(scene_from_text(text)), 0.004)


def expected_names(groove: float | None) -> dict[str, float]:
    """Each pair's name and its ρ (m) or f: a joint with one pair by its joint, else by the pair's links."""
    ram = "f′E" if groove is not None and groove != 90.0 else "fE"
    reduced = 0.1 / math.sin(math.radians(groove)) if groove is not None else 0.1
    # The ram's slide E (6 on the frame) shares its joint with the pin 5–6: both by their links.
    ram = ram.replace("E", "16")
    return {ram: reduced, "ρO": 0.08 * 0.02, "f43": 0.12, "ρ23": 0.1 * 0.015, "ρC": 0.1 * 0.03, "ρD": 0.1 * 0.012,
            "ρ56": 0.1 * 0.012}


@pytest.mark.parametrize("groove", [None, 30.0, 90.0])
def test_the_sheet_the_note_and_forces_md_name_each_pair_alike(groove):
    analysis = shaper(groove)
    wanted = expected_names(groove)
    note = note_markdown(analysis)
    table = markdown(analysis)
    for position in analysis.plans:
        layers = force_layout.layout(force_sheet(analysis, position, True))
        drawn = " ".join(item.text for layer in layers if layer.name.endswith("-caption") for item in layer.items)
        drawn = re.sub(r"= [\d.]+/sin [\d.]+° ", "", drawn)  # f′16 = 0.1/sin 30° = 0.2: the value it comes to
        on_sheet = dict(re.findall(rf"{NAME} = ([\d.]+)(?: mm)?(?:,|\s|$)", drawn))
        # The sheet writes ρ in mm.
        assert {name: float(value) / (1000.0 if name.startswith("ρ") else 1.0) for name, value in on_sheet.items()} \
            == pytest.approx(wanted, rel=1e-3)
    in_note = {name for name in re.findall(rf"^- {NAME}", note, flags=re.MULTILINE)}
    assert in_note == set(wanted)
    in_table = {name for name in re.findall(rf"\| {NAME} = ", table)}
    assert in_table == set(wanted)
    flat = groove is None or groove == 90.0
    assert ("f′" in " ".join(re.findall(rf"^- {NAME}.*$", note, flags=re.MULTILINE))) == (not flat)
