"""Scenes a geometry fuzzer (each fixture's and starter's lengths, offsets and coordinates scaled one at a time, the
positions' count, start and plans changed, a point's `at`, a mass, an inertia or a load made tiny or huge, each run
in full in every language and on other sheets) found answered wrongly: each as the small scene it came down to,
and the answer a student should get instead."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from sheet_texts import flat

from graphplan.cli import main

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"

CENTRAL_SLIDER_CRANK = """
[scene]
title = "A central slider-crank, its crank's centre of mass typed {at} m out"
[frame]
link = 1
points = {{ O = [0.0, 0.0] }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.05
omega = 10.0
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.19
guide = {{ through = "O", angle = 0.0 }}
assembly = "forward"
[points]
S2 = {{ link = 2, from = "O", toward = "A", at = {at} }}
[links.2]
mass = 4.5
centre = "S2"
[positions]
count = 12
working = {{ link = 4, sense = "backward" }}
plans = [2]
"""


def _scene(tmp_path: Path, text: str) -> Path:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    return scene


def test_a_centre_of_mass_far_off_its_crank_leaves_the_piston_its_stroke(tmp_path, capsys) -> None:
    """A named point typed a billion metres out on the crank was counted in the size the working link's travel is
    weighed against: the piston, which travels 2r = 0.1 m whatever the crank's mass does, was refused as "does not
    move over the crank's turn: its travel is 0.1 m".  A centre of mass moves nothing; the scene is checked, its
    central slider-crank's strokes equal (K = 1), and the far point told at its own key."""
    assert main(["check", str(_scene(tmp_path, CENTRAL_SLIDER_CRANK.format(at=1e9)))]) == 0
    told = capsys.readouterr()
    assert "working φw = 180.00°, idle φi = 180.00°, K = φw/φi = 1.0000" in told.out
    assert "does not move" not in told.out + told.err
    assert "warning: points.S2.at = 1e+09 m" in told.out + told.err


def test_a_note_whose_reading_has_a_length_in_powers_of_ten_is_written(tmp_path, capsys) -> None:
    """The note writes each plan reading's factors with digits added until the printed arithmetic gives the printed
    result, reading them back as plain decimals: a link's length it writes 1·10⁹ ended the run in a ValueError
    (could not convert string to float: '1·10⁹') after the drawings were made.  The note is written, and its ω2
    read off the velocity plan is the crank's own ω = 10 rad/s."""
    out = tmp_path / "out"
    scene = _scene(tmp_path, CENTRAL_SLIDER_CRANK.format(at=1e9))
    assert main(["run", str(scene), "--out", str(out), "--only", "velocity,note"]) == 0
    note = (out / "note.md").read_text(encoding="utf-8")
    omega = [line for line in note.splitlines() if line.startswith("- ω2 = ")]
    assert omega and omega[0].endswith("/1·10⁹ = 10 rad/s, counter-clockwise"), omega


@pytest.mark.parametrize(("drawing", "drawn"), [
    ("velocity_pole = 100.0", "draws the velocity plan of position 2"),
    ("length_scale = 0.002", "draws the paths of the points"),
], ids=["velocity-pole", "length-scale"])
def test_a_point_typed_far_beyond_millimetres_is_refused_at_its_own_key(tmp_path, capsys, drawing, drawn) -> None:
    """A drawing a named point swells past any paper is refused at that point's `at` where the length is
    millimetres typed for metres; typed a billion metres out it was refused at the scale the scene gives instead
    (drawing.velocity_pole: "give 1 (a 150 mm plan)"), a key the student never got wrong, which drew the plan's
    every other vector as a dot.  The length that stands alone beyond the rest is still the one to change, and
    nothing is written."""
    scene = _scene(tmp_path, CENTRAL_SLIDER_CRANK.format(at=1e9) + f"[drawing]\n{drawing}\n")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    told = capsys.readouterr().err.strip().splitlines()[-1]
    assert told.startswith("graphplan: error: points.S2.at: puts S2 1e+09 m from O"), told
    assert drawn in told and "give it in metres" in told, told
    assert not out.exists()


def test_a_rod_pinned_at_a_named_point_that_reaches_no_guide_names_the_points_key(tmp_path, capsys) -> None:
    """The shaper's rod DE is pinned at D, a named point up the slotted lever (points.D, at = 0.65 m from C).
    Typed a digit short, 0.065, D stays within 0.065 m of C, at least 0.64 − 0.065 = 0.575 m below the ram's guide,
    which the 0.2 m rod cannot reach at any angle of the crank: the refusal said "check the lengths", none of which
    is wrong, and named no key.  It names the key that places D, with its value, after the rod that would reach
    (D's nearest to the guide, 0.575 m at the crank's 270°, where the lever stands nearest upright)."""
    starter = tmp_path / "shaper.toml"
    assert main(["new", "shaper", "--out", str(starter)]) == 0
    text = starter.read_text(encoding="utf-8")
    assert text.count('D  = { link = 4, from = "C", toward = "A", at = 0.65 }') == 1
    scene = _scene(tmp_path, text.replace("at = 0.65 }", "at = 0.065 }"))
    capsys.readouterr()
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    told = capsys.readouterr().err.strip().splitlines()[-1]
    assert told.startswith("graphplan: error: E cannot be assembled") and "assembles at no angle of link 2" in told
    assert told.endswith("D comes no nearer the guide than 0.575 m (at φ = 270°), farther than DE = 0.2 m: "
                         "groups[1].length from 0.5751 m up, or the guide nearer D, and where points.D places D: "
                         "at = 0.065 m from C toward A"), told
    assert not out.exists()


def test_a_force_polygon_lettered_in_russian_is_laid_out_on_its_sheets(tmp_path, capsys) -> None:
    """The force polygon's names were looked up among its arrows by the vector's name (Fu4) where the name as
    lettered is the locale's (Fи4 in Russian): with the triad-with-slider's S4 moved 5 % nearer C, the sheets laid
    out at a larger μl set Fи4 on a leader out of a sliver, and the run ended in KeyError: 'Fи4' (no file written).
    The sheets are drawn, and the polygon of the triad's position 8 names the inertia force of link 4 as Fи4."""
    fixture = FIXTURES / "triad_with_slider.toml"
    text = fixture.read_text(encoding="utf-8")
    typed = 'S4 = { link = 4, from = "C", toward = "D", at = 0.07 }'
    assert text.count(typed) == 1
    scene = _scene(tmp_path, text.replace(typed, typed.replace("0.07", f"{0.07 * 0.95:g}")))
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--locale", "ru", "--only", "sheets"]) == 0
    sheets = [flat(path.read_text(encoding="utf-8")) for path in sorted(out.glob("sheet_*.svg"))]
    assert sheets and any(">Fи4<" in sheet for sheet in sheets)
    assert not any(">Fu4<" in sheet for sheet in sheets)


def test_an_upright_flywheel_tangent_keeps_its_letter_by_the_diagram(tmp_path, capsys) -> None:
    """The shaper's slotted lever given J = 1e9 kg·m² (warned as g·mm² typed for kg·m²) makes the machine's own Je
    so large that the energy–mass diagram's tangents stand all but upright: its letter a, set above the tangent over
    the letter's width, went up with the tangent's slope far past where the tangent is drawn, to 17 881 201 mm, so
    that dynamics.svg was 17.9 km tall and the scene's A1 sheets were refused at drawing.sheet ("sheet = none"), a
    key that was right.  The letter stays by the tangent as drawn: the scene checks, and the drawing is less than an
    A1 sheet (841 mm) tall."""
    starter = tmp_path / "shaper.toml"
    assert main(["new", "shaper", "--out", str(starter)]) == 0
    text = starter.read_text(encoding="utf-8")
    assert text.count("inertia = 0.65") == 1
    scene = _scene(tmp_path, text.replace("inertia = 0.65", "inertia = 1.0e9"))
    assert main(["check", str(scene)]) == 0
    told = capsys.readouterr()
    assert "links.4.inertia = 1e+09 kg·m²" in told.out + told.err
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics"]) == 0
    head = (out / "dynamics.svg").read_text(encoding="utf-8")[:400]
    height = float(re.search(r'height="([0-9.]+)mm"', head).group(1))
    assert height < 841.0, height
