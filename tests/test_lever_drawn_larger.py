"""Zhukovsky's lever is drawn larger than its velocity plan where the plan's points crowd round the pole.

A similar figure at any scale gives the same balancing load, so the lever may be drawn at its own μV. Where
two points of the plan stand closer than 15 mm, or than 3 mm for each load drawn at either (a friction lever's
forces of couples put five at a point), the loads, their arms and their names ran together at the plan's size
(the triad's lever: b, d, f, s4, s5, s6 all within 21 mm of p, with a 125 mm from it); the lever is then drawn
at the standard μV that makes its longest ray at most 250 mm. On a sheet it gives that room back, a standard
step at a time, before the force sheet would be cut into more parts.

The scales are found here from the plans' own numbers and the standard series, and read back off the
drawings: the caption's μV, and the rays, which must be the velocities at that μV.
"""

import dataclasses
import math
import re
from pathlib import Path

import pytest
from sheet_texts import flat
from test_sheets import STANDARD, analyses_of, with_drawing

from graphplan.locale import load_symbol, strings
from graphplan.render import force_lever
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet
from graphplan.render.formats import holds
from graphplan.render.numerals import significant
from graphplan.render.plans import ZERO_MM
from graphplan.render.primitives import Polyline, Text, bounds
from graphplan.render.sheet import force_panels
from graphplan.render.title_block import form_of
from graphplan.report.note import note_markdown

SCENES = ["ratchet_crank_rocker", "engine_slider_crank", "quick_return_slotted_lever", "shaper_six_bar",
          "scotch_yoke", "double_rocker_swing", "triad_class_iii"]
CROWDED_MM = 15.0
ROOM_PER_LOAD_MM = 3.0
LONGEST_RAY_MM = 250.0
# A force this small beside the lever's largest is rounding, not drawn.
ROUNDING_SHARE = 1e-9

_analyses = {}


def analysis_of(name):
    if name not in _analyses:
        _analyses[name] = analyses_of(name)
    return _analyses[name]


def crowded(velocity, lever=None):
    """Whether two of the plan's points (those less than ZERO_MM apart counted as one) stand closer than 15 mm, or
    than 3 mm for each of ``lever``'s load arrows (the balancing force's among them) at the two."""
    spots = []
    for value in velocity.points.values():
        where = value / velocity.scale
        if all(abs(where - spot) >= ZERO_MM for spot in spots):
            spots.append(where)
    loads = [0] * len(spots)
    if lever is not None:
        drawn = [(term.image, term.force) for term in lever.terms if term.image]
        drawn.append((lever.balancing_image, lever.balancing_force))
        largest = max(abs(force) for _, force in drawn)
        for image, force in drawn:
            if abs(force) > ROUNDING_SHARE * largest:
                where = velocity.points[image] / velocity.scale
                loads[min(range(len(spots)), key=lambda k: abs(spots[k] - where))] += 1

    def room(i, j):
        return max(CROWDED_MM, ROOM_PER_LOAD_MM * (loads[i] + loads[j]))

    return any(abs(spots[i] - spots[j]) < room(i, j) for i in range(len(spots)) for j in range(i + 1, len(spots)))


def expected_scale(velocity, lever=None):
    """The plan's μV, or the smallest standard one at which the longest ray is at most 250 mm where that is
    larger and the plan crowds."""
    if not crowded(velocity, lever):
        return velocity.scale
    longest = max(abs(value) for value in velocity.points.values())
    larger = min(value for value in STANDARD if longest / value <= LONGEST_RAY_MM * (1 + 1e-12))
    return min(larger, velocity.scale)


def drawn_scale(layers, velocity):
    """μV of the lever as its caption gives it, checked against its rays: each is a velocity at that scale."""
    caption = " ".join(item.text for layer in layers if layer.name.endswith("lever-caption")
                       for item in layer.items if isinstance(item, Text))
    written = float(re.search(r"μV = ([\d.]+) ", caption).group(1))
    scale = velocity.scale if written == pytest.approx(velocity.scale, rel=1e-3) else written
    rays = [item for layer in layers if layer.name.endswith("lever-plan") for item in layer.items
            if isinstance(item, Polyline) and len(item.points) == 2 and item.stroke.width == 0.25]
    images = {letter for letter in velocity.images.values() if letter != "p"}
    velocities = sorted(abs(velocity.points[letter]) for letter in images
                        if abs(velocity.points[letter]) / scale >= ZERO_MM)
    assert sorted(math.dist(*ray.points) * scale for ray in rays) == pytest.approx(velocities, rel=1e-6)
    return scale, caption


@pytest.mark.parametrize("name", SCENES)
def test_the_lever_is_drawn_larger_exactly_where_its_plan_crowds(name):
    analysis = analysis_of(name)
    for position in analysis.plans:
        if position.lever is None:
            continue
        layers = force_layout.layout(force_sheet(analysis, position))
        scale, caption = drawn_scale(layers, position.velocity)
        assert scale == pytest.approx(expected_scale(position.velocity, position.lever), rel=1e-12), \
            (name, position.number)
        # Drawn at any scale, the lever finds the same balancing moment.
        symbol = load_symbol("Mb", strings(analysis.scene.locale))  # the Russian ratchet's Mу
        assert caption.count(f"{symbol} = {significant(position.lever.balancing)} ") == 2  # the lever's, the polygons'


def test_the_fixtures_have_levers_drawn_larger_and_levers_left_at_the_plans_size():
    kinds = {expected_scale(position.velocity, position.lever) < position.velocity.scale
             for name in SCENES for position in analysis_of(name).plans if position.lever is not None}
    assert kinds == {True, False}


def test_the_triads_lever_is_two_and_a_half_times_the_plan_whose_points_crowd_within_21_mm_of_the_pole():
    # Position 8: pa = 125 mm at μV = 0.004 (m/s)/mm, and every other point of the plan but s2 and s3 within
    # 21.1 mm of p; 250 mm for va = 0.5 m/s is μV = 0.002, a standard value, so pa is drawn 250 mm long.
    analysis = analysis_of("triad_class_iii")
    position = next(position for position in analysis.plans if position.number == 8)
    assert position.velocity.scale == pytest.approx(0.004)
    sheet = force_sheet(analysis, position)
    assert sheet.lever_scale == pytest.approx(0.002, rel=1e-12)
    assert abs(position.velocity.points["a"]) / sheet.lever_scale == pytest.approx(250.0, rel=1e-9)


def stands_whole_on_an_a1(sheet):
    """Whether an empty A1 holds the force sheet whole, its rows in one column or in two."""
    rows = force_layout.rows(sheet)
    for count in (1, 2):
        x0, y0, x1, y1 = bounds(rows.arranged(rows.in_columns(count)).layers)
        if holds("A1", form_of(sheet.mechanism.scene.locale), x1 - x0, y1 - y0):
            return True
    return False


def test_on_a1_an_enlarged_lever_steps_back_only_as_far_as_the_sheet_needs_and_costs_no_part(monkeypatch):
    analysis = analysis_of("triad_class_iii")
    panels = force_panels(analysis, "A1")
    stepped_back = kept = 0
    for position in analysis.plans:
        holding = [panel for panel in panels if re.fullmatch(rf"forces-{position.number}(-\d+)?", panel.name)
                   and any(layer.name.endswith("lever-caption") for layer in panel.layers)]
        assert len(holding) == 1
        scale, _ = drawn_scale(holding[0].layers, position.velocity)
        enlarged = expected_scale(position.velocity, position.lever)
        assert enlarged < position.velocity.scale, "the triad's plans crowd"
        assert scale in STANDARD and enlarged - 1e-15 <= scale < position.velocity.scale
        sheet = force_sheet(analysis, position)
        assert stands_whole_on_an_a1(dataclasses.replace(sheet, lever_scale=scale))
        if scale > enlarged:  # one standard step larger would not have stood whole
            larger = max(value for value in STANDARD if value < scale * (1 - 1e-12))
            assert not stands_whole_on_an_a1(dataclasses.replace(sheet, lever_scale=larger))
            stepped_back += 1
        else:
            kept += 1
    assert stepped_back and kept, "position 2 steps back (pa 250 mm is too long beside its group), 8 does not"
    # Drawn at the plan's size, the force sheets stand in as many parts.
    monkeypatch.setattr(force_lever, "enlarged_lever_scale", lambda velocity, lever=None: None)
    assert [panel.name for panel in force_panels(analysis, "A1")] == [panel.name for panel in panels]


@pytest.mark.parametrize("name", ["triad_class_iii", "scotch_yoke"])
def test_the_note_works_the_lever_on_the_drawing_it_stands_beside(name):
    # The note's pa and arms h are the drawn lever's (mm at the μV its caption gives), and it says so where
    # that μV is not the plan's.
    analysis = analysis_of(name)
    note = note_markdown(analysis)
    drawn = []
    for position in analysis.plans:
        layers = force_layout.layout(force_sheet(analysis, position))
        drawn.append(drawn_scale(layers, position.velocity)[0])
    pas = [float(value) for value in re.findall(r"Fb = \|Σ\(F·h\)\|/pa = [^/]+/([\d.]+) = ", note)]
    assert len(pas) == len(analysis.plans)
    for pa, scale, position in zip(pas, drawn, analysis.plans, strict=True):
        driver = analysis.mechanism.driver.joint
        assert pa == pytest.approx(abs(position.velocity.points[position.velocity.images[driver]]) / scale, abs=0.006)
    said = re.findall(r"The lever is drawn larger than the velocity plan, at μV = ([\d.]+) \(m/s\)/mm", note)
    assert [float(value) for value in said] == [scale for scale, position in zip(drawn, analysis.plans, strict=True)
                                                  if scale != position.velocity.scale]


def test_a_force_sheet_cut_into_parts_all_the_same_keeps_a_larger_lever_on_its_part(monkeypatch):
    # The offset slider-crank's force sheets stand on A4 in parts whatever the lever's size; the lever of
    # position 3 then keeps a larger μV on its own part, as no more parts come of it.  (On A3, since the lever
    # letters arms it gave under it before, with a shorter caption, every lever there stands at its plan's μV.)
    analysis = with_drawing(analysis_of("offset_slider_crank"), sheet="A4")
    panels = force_panels(analysis, "A4")
    drawn = {}
    for position in analysis.plans:
        holding = [panel for panel in panels if re.fullmatch(rf"forces-{position.number}(-\d+)?", panel.name)
                   and any(layer.name.endswith("lever-caption") for layer in panel.layers)]
        drawn[position.number] = drawn_scale(holding[0].layers, position.velocity)[0]
    larger = [position for position in analysis.plans if drawn[position.number] < position.velocity.scale]
    assert larger, "some lever stands larger on its part"
    for position in larger:
        assert expected_scale(position.velocity, position.lever) - 1e-15 <= drawn[position.number]
    monkeypatch.setattr(force_lever, "enlarged_lever_scale", lambda velocity, lever=None: None)
    assert [panel.name for panel in force_panels(analysis, "A4")] == [panel.name for panel in panels]


def test_on_a_small_sheet_the_note_works_the_lever_at_the_mu_v_its_figure_is_drawn_at(tmp_path):
    """On A3 the shaper's lever of position 3 is drawn a step smaller than its enlarged μV (0.005 against 0.004
    (m/s)/mm) to fit; the note worked pa and the arms at 0.004, so they were not the figure's beside it. The figure
    beside the note is the force drawing on its own, which keeps the enlarged μV whatever the sheets draw."""
    from graphplan.analysis import analyse
    from graphplan.cli import main
    from graphplan.scene import loads

    text = (Path(__file__).resolve().parent.parent / "fixtures" / "shaper_six_bar.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^sheet\s*=.*$", 'sheet = "A3"', re.sub(r"(?m)^length_scale\s*=.*$", "length_scale = 0.004",
                                                                text))
    scene = tmp_path / "shaper.toml"
    scene.write_text(text, encoding="utf-8")
    # The note and the force drawings with their levers, which are read, and the sheets, which fit the levers to
    # the A3: the force drawings written on their own are not fitted to it.
    pieces = "note,forces,lever,sheets"
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--locale", "en", "--only", pieces]) == 0
    analysis = analyse(loads(text))
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    pas = [float(value) for value in re.findall(r"Fb = \|Σ\(F·h\)\|/pa = [^/]+/([\d.]+) = ", note)]
    assert len(pas) == len(analysis.plans)
    # The lever's caption, "μV = 0.004 (m/s)/mm, arrows: μF = …", broken after the comma where it is too long.
    lever = r"μV = ([\d.]+) \(m/s\)/mm,"
    on_sheets = {float(value) for sheet in (tmp_path / "out").glob("sheet_*.svg")
                 for value in re.findall(lever, flat(sheet.read_text(encoding="utf-8")))}
    smaller = 0
    for pa, position in zip(pas, analysis.plans, strict=True):
        figure = flat((tmp_path / "out" / f"forces_{position.number}.svg").read_text(encoding="utf-8"))
        drawn_at = float(re.search(lever, figure)[1])
        velocity = position.velocity
        assert pa == pytest.approx(abs(velocity.points[velocity.images["A"]]) / drawn_at, abs=0.006)
        enlarged = force_lever.enlarged_lever_scale(velocity, position.lever)
        assert drawn_at == pytest.approx(enlarged or velocity.scale)
        smaller += enlarged is not None and any(scale > 1.1 * enlarged for scale in on_sheets)
    assert smaller  # the case in point: a lever drawn smaller than enlarged for the small sheet


def test_the_lever_is_laid_out_once_whatever_the_length_scale_its_sheet_is_tried_at(monkeypatch):
    """The lever is drawn at μV: choosing μl laid each force sheet out at every μl it tried, and the lever's lettering
    was placed again each time (three quarters of a class III triad's run on A3). At another μV it is drawn anew."""
    analysis = analysis_of("triad_class_iii")
    position = next(position for position in analysis.plans if position.lever is not None)
    drawn = []
    original = force_lever._lever
    monkeypatch.setattr(force_lever, "_lever", lambda sheet, lever: drawn.append(sheet) or original(sheet, lever))
    sheet = force_sheet(analysis, position)
    first = force_layout.rows(sheet)
    before = len(drawn)
    again = force_layout.rows(dataclasses.replace(sheet, length_scale=sheet.length_scale * 2))
    assert len(drawn) == before and again.drawings[-1] == first.drawings[-1]
    larger = dataclasses.replace(sheet, lever_scale=sheet.lever_drawn_scale / 2)
    assert force_layout.rows(larger).drawings[-1] != first.drawings[-1] and len(drawn) == before + 1
