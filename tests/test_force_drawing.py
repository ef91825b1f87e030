"""The force sheet of one position, tested on its primitives: polygons, labels, the lever's arms.

The sheet is laid out from the force records (graphplan.forces, graphplan.lever); these tests read
the layers the layout returns, find the polygon vectors by their keys (``polygon-II-3-4-R23tau``)
and compare them with the records over μF, check that each polygon closes on the paper, that every
reaction is named, that no two texts overlap, that a Russian scene says everything in Russian, that
the lever's arms as drawn give the lever's moments, and that the command line writes the sheets.
"""

import dataclasses
import itertools
import math
import re

import pytest
from lever_equation import unfactored
from shapely.geometry import Point as shapely_point
from test_polygon_arrows_unnamed_before_crossed import unnamed_arrows
from test_stroke_choice import TOGGLE

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.kinematics import at
from graphplan.locale import load_symbol, strings
from graphplan.render import force_bodies, force_polygons
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet, forces_svg
from graphplan.render.labels import text_box
from graphplan.render.numerals import significant
from graphplan.render.plans import ZERO_MM
from graphplan.render.primitives import Arrow, Circle, Polyline, Text, svg_id
from graphplan.scales import format_scale, standard_scale

FIXTURES = "fixtures"
SCENES = ["ratchet_crank_rocker", "engine_slider_crank", "quick_return_slotted_lever", "shaper_six_bar",
          "tangent_mechanism_prp", "scotch_yoke", "slider_driven", "stephenson_six_bar", "double_rocker_swing"]
# Within this on the paper (mm) two drawn points are one.
CLOSE_MM = 0.01

_analyses = {}


def analysis_of(name):
    if name not in _analyses:
        _analyses[name] = analyse(graphplan.load(f"{FIXTURES}/{name}.toml"))
    return _analyses[name]


CASES = [(name, k) for name in SCENES for k in (0, 1)]


@pytest.fixture(params=CASES, ids=[f"{name}-{k}" for name, k in CASES])
def case(request):
    """(analysis, plan position, layers by name) of a scene's first or second plan position."""
    name, k = request.param
    analysis = analysis_of(name)
    position = [p for p in analysis.plans if p.forces is not None][k]
    layers = {layer.name: layer.items for layer in force_layout.layout(force_sheet(analysis, position))}
    return analysis, position, layers


def polygon_layers(layers, group):
    """(layer prefix, arrows) of each polygon of ``group`` on the sheet: one, or two for a polygon closed twice."""
    pattern = re.compile(rf"polygon-{re.escape(force_layout.group_id(group.label))}(-\d)?-vectors")
    return [(name[:-len("-vectors")], [item for item in items if isinstance(item, Arrow)])
            for name, items in layers.items() if pattern.fullmatch(name)]


def keyed_vectors(prefix, group):
    return {svg_id(prefix, vector.name): vector for vector in group.polygon.vectors}


def test_every_polygon_closes_on_the_paper(case):
    """Known and closing vectors head to tail, and the last ends where the first starts."""
    _, position, layers = case
    scale = position.forces.scale
    for group in position.forces.groups:
        drawn = polygon_layers(layers, group)
        assert drawn, f"no polygon drawn for {group.label}"
        for prefix, arrows in drawn:
            vectors = keyed_vectors(prefix, group)
            chain = [arrow for arrow in arrows if arrow.key in vectors and vectors[arrow.key].role in ("load", "closing")]
            assert len(chain) >= 2, f"{prefix}: a polygon of fewer than two vectors"
            # A vector too short to draw leaves a gap as long as itself, and no more.
            drawn_names = {vectors[arrow.key].name for arrow in arrows if arrow.key in vectors}
            gap = sum(abs(v.force) / scale for v in group.polygon.vectors
                      if v.role in ("load", "closing") and v.name not in drawn_names)
            for first, second in zip(chain, chain[1:] + chain[:1]):
                if math.dist(first.end, second.start) <= CLOSE_MM + gap:
                    continue
                # A side running back along another is drawn beside its line, square to itself, both heads seen.
                step = complex(*second.start) - complex(*first.end)
                aside = [arrow for arrow in (first, second)
                         if abs(abs(step) - force_polygons.SIDE_BY_SIDE_MM) < CLOSE_MM + gap
                         and abs(((complex(*arrow.end) - complex(*arrow.start)) * step.conjugate()).real)
                         < CLOSE_MM * arrow.length]
                assert aside, (prefix, first.key, second.key)


def test_every_polygon_vector_is_its_force_over_the_force_scale(case):
    """Each drawn vector is |F|/μF long at its polygon's μF and points along F; every vector long enough to draw
    is drawn."""
    _, position, layers = case
    for group in position.forces.groups:
        scale = group.scale
        seen = set()
        for prefix, arrows in polygon_layers(layers, group):
            vectors = keyed_vectors(prefix, group)
            for arrow in arrows:
                vector = vectors.get(arrow.key)
                if vector is None:  # a reaction drawn whole, R23 = R23τ + R23n
                    found = next(f for f in group.found if arrow.key == svg_id(prefix, f.name))
                    assert arrow.length == pytest.approx(abs(found.force) / scale, abs=CLOSE_MM)
                    assert abs(complex(*arrow.end) - complex(*arrow.start) - found.force / scale) < CLOSE_MM
                    continue
                seen.add(vector.name)
                assert arrow.length == pytest.approx(abs(vector.force) / scale, abs=CLOSE_MM), arrow.key
                drawn = complex(*arrow.end) - complex(*arrow.start)
                assert abs(drawn - vector.force / scale) < CLOSE_MM, arrow.key
        expected = {v.name for v in group.polygon.vectors if abs(v.force) / scale >= ZERO_MM}
        assert seen == expected, group.label



STANDARD_STEP = 2.0   # the widest step between standard scales (1 → 2, 5 → 10)


def test_each_polygon_is_drawn_as_large_as_its_field_at_its_own_standard_scale(case):
    """Left to the program, each group's polygon takes the least standard μF at which it spans at most
    150 mm: it spans more than 150/2 mm, so that a small group's polygon is not drawn at the large one's μF.
    The position's μF (the contract's polygon_scale) is the coarsest, at which every polygon fits."""
    analysis, position, layers = case
    assert analysis.scene.drawing.force_scale is None
    for group in position.forces.groups:
        vectors = group.polygon.vectors
        span = max(abs(v.end - w.end) for v in vectors for w in vectors) / group.scale
        assert 150.0 / STANDARD_STEP < span <= 150.0 + 1e-9, group.label
        assert group.scale == standard_scale(group.scale)
    assert position.forces.scale == max(group.scale for group in position.forces.groups)
    # Each polygon's caption gives its μF; the sheet's head gives one only when they share it.
    captions = [item.text for name, items in layers.items() if name.endswith("-caption") and "polygon" in name
                for item in items if isinstance(item, Text)]
    words = strings(analysis.scene.locale)
    for group in position.forces.groups:
        assert words["force_scale"].format(value=format_scale(group.scale)) in captions
    head = " ".join(item.text for item in layers["sheet-title"] if isinstance(item, Text))
    shared = len(set(position.forces.group_scales.values())) == 1
    assert (words["force_scale"].format(value=format_scale(position.forces.scale)) in head) == shared


def test_a_scene_s_force_scale_draws_every_polygon_at_it():
    scene = graphplan.load(f"{FIXTURES}/stephenson_six_bar.toml")
    analysis = analyse(dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, force_scale=25.0)))
    for position in analysis.plans:
        assert position.forces.scale == 25.0
        assert set(position.forces.group_scales.values()) == {25.0}

def test_a_vector_too_short_to_draw_is_left_out():
    """The scotch yoke's guide reaction R14 is nought at position 4 (its line through the joint): no arrow."""
    analysis = analysis_of("scotch_yoke")
    position = next(p for p in analysis.plans if p.number == 4)
    assert abs(position.forces.reactions["R14"].force) < 1e-9
    layers = force_layout.layout(force_sheet(analysis, position))
    keys = [item.key for layer in layers for item in layer.items if isinstance(item, Arrow)]
    assert not any(key.endswith("-R14") for key in keys)
    assert all(item.length >= ZERO_MM for layer in layers for item in layer.items if isinstance(item, Arrow))


def test_every_reaction_is_named_on_the_sheet(case):
    """Each reaction found is written with its value under its group; each drawn vector has its label."""
    analysis, position, layers = case
    captions = " ".join(item.text for name, items in layers.items() if name.endswith("-caption")
                        for item in items)
    for name, found in position.forces.reactions.items():
        if abs(found.force) / position.forces.scale < ZERO_MM:
            continue
        listed = re.search(rf"(?<![\w]){re.escape(name)} = ([\d.]+) ", captions)
        assert listed, f"{name} is not named on the sheet"
        assert float(listed.group(1)) == pytest.approx(abs(found.force), rel=1e-3)
    words = strings(analysis.scene.locale)
    for group in position.forces.groups:
        # An arrow whose name could only be led across another is left unnamed, and its polygon's caption says so.
        caption = [item.text for item in layers[f"polygon-{force_layout.group_id(group.label)}-caption"]]
        unnamed = unnamed_arrows(caption, words)
        for prefix, arrows in polygon_layers(layers, group):
            labels = [item.text for item in layers[f"{prefix}-labels"]]
            vectors = keyed_vectors(prefix, group)
            for arrow in arrows:
                name = vectors[arrow.key].name if arrow.key in vectors else arrow.key.rsplit("-", 1)[1]
                name = load_symbol(name, words)  # drawn as the locale writes it: the Russian Fи3 of Fu3
                assert (name in labels) != (name in unnamed), f"{arrow.key} is not labelled, or labelled twice"


def test_no_two_texts_overlap(case):
    _, _, layers = case
    texts = [(name, item) for name, items in layers.items() for item in items if isinstance(item, Text)]
    boxes = [(name, item.text, text_box(item)) for name, item in texts]
    crossing = [(a[:2], b[:2]) for a, b in itertools.combinations(boxes, 2) if a[2].intersects(b[2])]
    assert not crossing


def test_the_scotch_yoke_cut_free_is_its_rod_and_its_slot_not_a_triangle():
    # The yoke's points are B, P and the slot's point under the block A: their hull would join P to A, a bar the
    # yoke does not have.  It is drawn as on the plan sheet: the rod B–P and the slot along B–A, past the block.
    analysis = analysis_of("scotch_yoke")
    position = next(p for p in analysis.plans if p.forces is not None)
    layers = {layer.name: layer.items for layer in force_layout.layout(force_sheet(analysis, position))}
    group = next(group for group in position.forces.groups if 4 in group.links)
    items = layers[f"body-{force_layout.group_id(group.label)}-links"]
    links = [[complex(*point) for point in item.points] for item in items if isinstance(item, Polyline)
             and not item.fill]
    assert not [item for item in items if isinstance(item, Polyline) and item.closed and not item.fill]
    # The drawing stands anywhere on the sheet: the pin at A, the one joint of the group's links, places it.
    (pin,) = [complex(*item.centre) for item in items if isinstance(item, Circle) and item.fill == "white"]
    mm = {name: position.positions[name] / analysis.scene.drawing.length_scale for name in "ABP"}
    at = {name: pin + r - mm["A"] for name, r in mm.items()}

    def reach(points, start, end):  # where the points lie along start→end (0 at start, 1 at end), or None off it
        along = [(point - start) / (end - start) for point in points]
        return sorted(t.real for t in along) if all(abs(t.imag) < 1e-6 for t in along) else None

    assert not [points for points in links if reach(points, at["P"], at["A"])], "no bar P–A"
    assert [points for points in links if reach(points, at["B"], at["P"])], "the rod B–P"
    (slot,) = [found for points in links for found in [reach(points, at["B"], at["A"])] if found]
    assert slot[0] < 0 and slot[-1] > 1, "the slot runs across the yoke, past B and past the block"


def test_a_russian_scene_has_a_russian_sheet():
    analysis = analysis_of("ratchet_crank_rocker")
    assert analysis.scene.locale == "ru"
    position = analysis.plans[0]
    layers = force_layout.layout(force_sheet(analysis, position))
    texts = [item.text for layer in layers for item in layer.items if isinstance(item, Text)]
    joined = " ".join(texts)  # a caption line may break between words
    for phrase in ("Силовой анализ, положение 5", "Силовой анализ группы II(3,4)", "Силовой анализ начального звена",
                   "План сил", "Рычаг Жуковского", "Mу = ", "(планы сил)",
                   "(рычаг Жуковского)", "расхождение", "μF = 20 Н/мм", "Н·м"):
        assert phrase in joined, phrase
    # Nothing in English, not even the scene's own title (as on the plan sheets).
    words = re.compile(r"\b(force|forces|polygon|polygons|lever|balancing|analysis|group|difference|position|"
                       r"driving|moment|none|shorter|than|N|mm|N/mm|m/mm)\b", re.IGNORECASE)
    for text in texts:
        assert not words.search(text) and analysis.scene.title not in text, text


def test_a_chinese_sheet_uses_its_own_strings():
    from graphplan.locale import strings

    text = strings("zh")
    assert text["force_polygon_title"] == "力多边形" and text["lever_title"] == "茹可夫斯基杠杆"
    assert text["group_forces_title"].format(group="II(3,4)") == "杆组 II(3,4) 的力分析"
    assert text["balancing_moment"] == "平衡力矩"


def test_the_lever_arms_as_drawn_give_the_lever_moments(case):
    """|F|·h·μV of every force on the lever is its term's moment; the arm runs from the pole square to the force.

    Forces on one line have one arm, drawn once (in the layer of the first of them): a force whose own arm layer
    does not start at the pole takes the arm from the pole whose foot is on its line."""
    analysis, position, layers = case
    lever = position.lever
    scale = force_sheet(analysis, position).lever_scale or position.velocity.scale  # a crowded plan drawn larger
    arrows = {item.key: item for item in layers["lever-forces"] if isinstance(item, Arrow)}
    pole = None
    checked = 0
    total = sum(term.moment for term in lever.terms)
    entries = [(term.name, term.force, term.moment) for term in lever.terms if term.image and term.force != 0]
    entries.append(("Fb", lever.balancing_force, -total))
    largest = max(abs(force) for _, force, _ in entries)
    # The arms from the pole: the first line of each arm's layer, the most of which start at one point, the pole.
    firsts = [items[0] for key, items in layers.items()
              if key.startswith("lever-arm-") and isinstance(items[0], Polyline)]
    starts = max((complex(*item.points[0]) for item in firsts),
                 key=lambda start: sum(abs(complex(*item.points[0]) - start) < CLOSE_MM for item in firsts))
    arms = [item for item in firsts if abs(complex(*item.points[0]) - starts) < CLOSE_MM]
    for name, force, moment in entries:
        if abs(force) <= 1e-9 * largest:
            continue
        arrow = arrows[svg_id("lever", name)]
        along = (complex(*arrow.end) - complex(*arrow.start)) / arrow.length
        # An arrow set beside its line (a second load on one line at one point) is tied to its point by a leader.
        through = next((complex(*leader.points[0]) for leader in layers["lever-forces"]
                        if isinstance(leader, Polyline) and leader.points[-1] == arrow.start), complex(*arrow.start))
        layer = layers.get(svg_id("lever-arm", name))
        if layer is None and abs(moment) / abs(force) / scale < ZERO_MM:  # the force's line passes through the pole
            continue
        if layer is None or abs(complex(*layer[0].points[0]) - starts) >= CLOSE_MM:
            # Its line is another force's: the arm drawn from the pole whose foot is on it.
            layer = next(([item] for item in arms
                          if abs(((complex(*item.points[-1]) - through) * along.conjugate()).imag) < CLOSE_MM), None)
        assert layer is not None, f"{name}: no arm drawn to its line"
        arm = layer[0]
        assert isinstance(arm, Polyline)
        start, foot = (complex(*p) for p in arm.points)
        pole = start if pole is None else pole
        assert abs(start - pole) < CLOSE_MM, "every arm starts at the pole"
        assert abs(((foot - start) * along.conjugate()).real) < CLOSE_MM, f"{name}: the arm is not square"
        assert abs(((foot - through) * along.conjugate()).imag) < CLOSE_MM, f"{name}: foot off the line"
        assert abs(foot - start) * scale * abs(force) == pytest.approx(abs(moment), rel=1e-6, abs=1e-9), name
        checked += 1
    assert checked >= 2


def test_the_lever_and_the_polygons_agree_on_the_sheet():
    analysis = analysis_of("engine_slider_crank")
    position = analysis.plans[0]
    layers = force_layout.layout(force_sheet(analysis, position))
    texts = [item.text for layer in layers for item in layer.items if isinstance(item, Text)]
    difference = position.lever.difference_percent(position.forces.balancing)
    assert f"difference {abs(difference):.2f} %" in texts
    value = significant(position.forces.balancing)
    assert value.startswith("−")  # the engine's crank is driven: the balancing moment resists
    assert f"Mb = {value} N·m (force polygons)" in texts


def test_the_sheet_is_the_same_every_time():
    analysis = analysis_of("slider_driven")
    position = analysis.plans[0]
    assert forces_svg(analysis, position) == forces_svg(analysis, position)


def test_a_position_without_forces_has_no_sheet():
    analysis = analysis_of("ratchet_crank_rocker")
    position = analysis.plans[0]
    without = dataclasses.replace(position, forces=None)
    with pytest.raises(ValueError, match="no force analysis"):
        force_sheet(analysis, without)


def test_the_command_line_writes_a_force_sheet_beside_each_plan_sheet(tmp_path, capsys):
    assert main(["run", f"{FIXTURES}/slider_driven.toml", "--out", str(tmp_path / "out")]) == 0
    analysis = analysis_of("slider_driven")
    for position in analysis.plans:
        assert (tmp_path / "out" / f"plan_{position.number}.svg").exists()
        sheet = tmp_path / "out" / f"forces_{position.number}.svg"
        assert sheet.exists() == (position.forces is not None)
        if position.forces is not None:
            assert "polygon-II-3-4-vectors" in sheet.read_text(encoding="utf-8")


def test_the_force_tables_give_each_polygon_s_scale_where_they_differ():
    from graphplan.report.forces import markdown, number

    analysis = analysis_of("stephenson_six_bar")
    text = markdown(analysis)
    for position in analysis.plans:
        scales = position.forces.group_scales
        assert len(set(scales.values())) > 1
        listed = "; ".join(f"{label}: {number(scale)}" for label, scale in scales.items())
        assert f"Force polygons each at its own μF, N/mm: {listed}." in text


def test_labels_that_took_each_other_s_only_spot_are_placed_again():
    # The triad's levers crowd sixteen arms and their loads round the pole.  Lettered one by one, a label took the
    # only clear spot of a later one, which was then written over it (σ6 on d, h9 on p, h16 on Mu4″: nine in
    # position 8, one in 2).  Placed again among all the others, none are left in 2 and at most two in 8.
    analysis = analyse(graphplan.load(f"{FIXTURES}/triad_class_iii.toml"))
    clashes = []
    for position in analysis.plans:
        layers = force_layout.layout(force_sheet(analysis, position))
        boxes = [text_box(item) for layer in layers if layer.name.startswith("lever") for item in layer.items
                 if isinstance(item, Text)]
        clashes.append(sum(a.intersection(b).area > 0.05 for a, b in itertools.combinations(boxes, 2)))
    assert clashes[0] == 0 and clashes[1] <= 2


# The teacher's sine mechanism with its rocker links in a regular proportion: group II(3,4)'s yoke 4 slides on the
# frame's guide, whose reaction R14 acts 190 mm along it from B in position 2. S4 is placed from B toward A, which is
# on the slot's negative side at φ = 0°: its offset is to the right of B→A.
SINE_ROCKER = TOGGLE.replace("lengths = [0.15, 0.123392747509]", "lengths = [0.25, 0.16]").replace(
    'S6 = { link = 6', 'S4 = { link = 4, from = "B", toward = "A", at = 0.0, offset = -0.12 }\nS6 = { link = 6').replace(
    "[links.6]", '[links.4]\nmass = 4.0\ncentre = "S4"\ninertia = 0.02\n\n[links.6]') + (
    "\n[drawing]\nlength_scale = 0.0025\n")


def test_a_reaction_acting_off_its_joint_along_a_guide_stands_on_the_guide_s_axis_run_on_to_it(tmp_path):
    scene = tmp_path / "sine.toml"
    scene.write_text(SINE_ROCKER, encoding="utf-8")
    analysis = analyse(graphplan.load(scene))
    position = analysis.plans[0]
    group = next(group for group in position.forces.groups if 4 in group.links)
    found = position.forces.reactions["R14"]
    shift_mm = found.offset / analysis.scene.drawing.length_scale
    assert abs(shift_mm) > 50.0  # far past the block
    layers = {layer.name: layer.items for layer in force_layout.layout(force_sheet(analysis, position))}
    items = layers[f"body-{force_layout.group_id(group.label)}-links"]
    axes = [item for item in items if isinstance(item, Polyline) and item.stroke == force_bodies._AXIS]
    (axis,) = axes
    start, end = (complex(*point) for point in axis.points)
    slide = next(s for s in analysis.motion.slides if s.joint == found.joint and s.slider == 4)
    u = complex(at(slide.u, position.index))
    # The axis runs along the guide and reaches past the reaction's point by the 6 mm an axis runs on.
    assert abs(((end - start) / abs(end - start) * u.conjugate()).imag) < 1e-9
    assert abs(end - start) >= abs(shift_mm) + 6.0 + 14.0 - 1e-6


def test_a_block_s_own_moment_enters_the_lever_as_its_power_over_the_plan_s_scale():
    """The lever's terms are F·h in N·mm at μV; a block's inertia moment was written «Mu3·ω», a power in W, though
    the lever took Mu3·ω3/μV."""
    from pathlib import Path

    from graphplan.report.note import note_markdown

    text = Path(FIXTURES, "quick_return_slotted_lever.toml").read_text(encoding="utf-8")
    text = text.replace('[links.3]\nmass    = 1.0\ncentre  = "A"', '[links.3]\nmass    = 1.0\ncentre  = "A"\ninertia = 0.004')
    analysis = analyse(dataclasses.replace(graphplan.load_text(text), locale="en"))
    plan = analysis.plans[0]
    motion = analysis.motion
    # d'Alembert: Mu3 = −JS3·ε3; its lever term M·ω over μV.
    expected = -0.004 * float(motion.link(3).epsilon[plan.index]) * float(motion.link(3).omega[plan.index])
    (term,) = [term for term in plan.lever.terms if not term.image]
    assert (term.name, term.link) == ("Mu3", 3) and term.moment == pytest.approx(expected, rel=1e-9)
    said = " ".join(item.text for layer in force_layout.layout(force_sheet(analysis, plan))
                    for item in layer.items if isinstance(item, Text))
    assert "Mu3·ω3/μV" in said and "Mu3·ω " not in said + " "
    note = note_markdown(analysis)
    assert "enters as its power over the plan's scale, Mu3·ω3/μV." in note
    row = next(line for line in note.splitlines() if line.startswith("| Mu3 |"))
    assert float(row.split("|")[-2].replace("−", "-")) == pytest.approx(expected / plan.velocity.scale, rel=1e-4)


def test_loads_along_a_slider_s_guide_stand_one_after_another_on_the_guide_clear_of_the_links():
    """The shaper's ram: the cutting force F6, the inertia force Fu6 and the friction Ff16 all act at E along
    the guide, and the connecting rod DE lies along it too.  They were drawn on top of the rod, one over the
    other, their heads lost in its heavy line; each now stands clear of every link's outline, on the guide's
    thin axis, none over another."""
    from graphplan.starters import starter

    analysis = analyse(graphplan.load_text(starter("shaper", "ru")))
    position = next(p for p in analysis.plans if p.with_friction is not None and not p.with_friction.locked)
    sheet = force_sheet(analysis, position, with_friction=True)
    group = next(group for group in sheet.forces.groups if 6 in group.links)
    key = force_layout.group_id(group.label)
    layers = {layer.name: layer.items for layer in force_layout.layout(sheet)}
    arrows = {item.key.rsplit("-", 1)[1]: item for item in layers[f"body-{key}-forces"] if isinstance(item, Arrow)}
    heavy = [item for item in layers[f"body-{key}-links"]  # the links' outlines, not the blocks they cross
             if isinstance(item, Polyline) and item.stroke == force_bodies._LINK and item.fill is None]
    assert heavy
    slide = next(slide for slide in analysis.motion.slides if slide.slider == 6)
    u = complex(at(slide.u, position.index))
    along = {name: arrow for name, arrow in arrows.items() if name in ("F6", "Fu6", "Ff16")}
    assert len(along) == 3
    segments = {}
    for name, arrow in along.items():
        start, end = complex(*arrow.start), complex(*arrow.end)
        assert abs(((end - start) * u.conjugate()).imag) < 1e-6 * abs(end - start)  # along the guide
        for outline in heavy:
            points = [complex(*point) for point in outline.points]
            for a, b in itertools.pairwise(points + points[:1] if outline.closed else points):
                assert _overlap_mm(start, end, a, b) < 1.0, (name, a, b)
        segments[name] = (start, end)
    for (first, (a, b)), (second, (c, d)) in itertools.combinations(segments.items(), 2):
        assert _overlap_mm(a, b, c, d) < 1.0, (first, second)


def _overlap_mm(a, b, c, d, within=0.8):
    """How much of segment ab lies within ``within`` mm of segment cd (mm), sampled finely."""
    samples = 400
    near = sum(1 for k in range(samples + 1) if _distance(a + (b - a) * k / samples, c, d) < within)
    return abs(b - a) * near / (samples + 1)


def _distance(p, c, d):
    t = max(0.0, min(1.0, ((p - c) * (d - c).conjugate()).real / max(abs(d - c) ** 2, 1e-18)))
    return abs(p - (c + t * (d - c)))


def test_a_reaction_along_a_plate_s_closing_edge_is_drawn_off_the_plate():
    """The ratchet's coupler is a plate A–E–B whose outline closes on its edge BA; R23n at A acts along BA and was
    judged clear of the links from its first two edges only.  Drawn along BA it lay on the plate's heavy line (once
    the joint's own corner stopped tipping the balance); it stands off the plate, onto A from outside."""
    analysis = analysis_of("ratchet_crank_rocker")
    position = next(p for p in analysis.plans if p.number == 5)
    sheet = force_sheet(analysis, position)
    group = next(group for group in sheet.forces.groups if 3 in group.links)
    key = force_layout.group_id(group.label)
    layers = {layer.name: layer.items for layer in force_layout.layout(sheet)}
    (plate,) = [item for item in layers[f"body-{key}-links"]
                if isinstance(item, Polyline) and item.closed and item.fill is None]
    corners = [complex(*point) for point in plate.points]
    (arrow,) = [item for item in layers[f"body-{key}-forces"] if item.key == svg_id("body", key, "R23n")]
    start, end = complex(*arrow.start), complex(*arrow.end)
    a = min(corners, key=lambda corner: min(abs(corner - start), abs(corner - end)))
    edges = [corner - a for corner in corners if corner != a]
    assert any(abs(((end - start) * edge.conjugate()).imag) < 1e-3 * abs(end - start) * abs(edge) for edge in edges)
    for first, second in itertools.pairwise([*corners, corners[0]]):
        assert _overlap_mm(start, end, first, second) < 6.0, (first, second)


@pytest.mark.parametrize("scene, number, link, names", [
    ("stephenson_six_bar", 3, 6, ("Fu6", "G6")),
    ("engine_slider_crank", 2, 2, ("Fu2",)),
    ("scotch_yoke", 4, 4, ("G4",)),
])
def test_a_load_along_its_own_link_at_a_point_inside_it_is_drawn_beside_the_link_tied_to_its_point(scene, number, link,
                                                                                                   names):
    """Stephenson's link 6 stands nearly upright: Fu6 and G6 at S6 both lay inside its heavy line, whichever way
    they were drawn from S6; so did the engine crank's Fu2 at S2 (a steady crank's inertia force runs along it) and
    the yoke's weight at S4.  Each now stands a few mm beside its link, parallel to its force, its near end a few mm
    from its point and joined to it by a thin leader, its arm still taken to the force's true line."""
    analysis = analysis_of(scene)
    position = next(p for p in analysis.plans if p.number == number)
    sheet = force_sheet(analysis, position)
    group = next(group for group in sheet.forces.groups if link in group.links)
    key = force_layout.group_id(group.label)
    # The drawing as laid out before it is moved onto the sheet: at μl from the mechanism's origin.
    (body,) = [drawing for row in force_layout.rows(sheet).drawings for drawing in row if drawing.name == f"body-{key}"]
    layers = {layer.name: layer.items for layer in body.layers}
    outlines = [item for item in layers[f"body-{key}-links"]
                if isinstance(item, Polyline) and item.stroke == force_bodies._LINK and item.fill is None]
    forces = {item.key: item for item in layers[f"body-{key}-forces"] if isinstance(item, Arrow)}
    leaders = [item for item in layers[f"body-{key}-forces"] if isinstance(item, Polyline)]
    loads = {load.name: load for load in group.loads}
    for name in names:
        arrow = forces[svg_id("body", key, name)]
        start, end = complex(*arrow.start), complex(*arrow.end)
        load = loads[name]
        point = sheet.positions[load.point] / sheet.length_scale
        unit = load.force / abs(load.force)
        assert abs(((end - start) * unit.conjugate()).imag) < 1e-6 * abs(end - start), name  # parallel to the force
        assert ((end - start) * unit.conjugate()).real > 0, name  # in its sense
        for outline in outlines:
            corners = [complex(*p) for p in outline.points]
            for a, b in itertools.pairwise(corners + corners[:1] if outline.closed else corners):
                assert _overlap_mm(start, end, a, b) < 1.0, (name, a, b)
        near = min((start, end), key=lambda p: abs(p - point))
        assert 1.0 < abs(near - point) < 4.0, name  # beside its point, not away from it
        assert any(abs(complex(*leader.points[0]) - point) < CLOSE_MM and abs(complex(*leader.points[-1]) - near)
                   < CLOSE_MM for leader in leaders), name


@pytest.mark.parametrize("scene, number, locale", [("shaper_six_bar", 3, "en"), ("quick_return_slotted_lever", 4, "zh")])
def test_loads_at_one_point_of_the_lever_on_one_line_are_drawn_apart_each_at_its_point(scene, number, locale):
    """On the shaper's lever F6 and Fu6 act at e along one line, and so do Mu5′ and G6; on the quick-return lever the
    couples' forces M4′ and Mu4′ at d, and M4″ and Mu4″ at p.  They were drawn one after another on their line, one
    head against the next one's tail, and read as one arrow.  Each now stands at its point (pulling from it, pushing
    onto it, or a few mm beside its line tied to it by a leader), and no arrow lies along another or has its head in
    another's stroke."""
    analysis = analyse(dataclasses.replace(graphplan.load(f"{FIXTURES}/{scene}.toml"), locale=locale))
    position = next(p for p in analysis.plans if p.number == number)
    sheet = force_sheet(analysis, position)
    (lever,) = [drawing for row in force_layout.rows(sheet).drawings for drawing in row if drawing.name == "lever"]
    items = next(layer.items for layer in lever.layers if layer.name == "lever-forces")
    arrows = {item.key: item for item in items if isinstance(item, Arrow)}
    leaders = [item for item in items if isinstance(item, Polyline)]
    scale = sheet.lever_drawn_scale
    at_points = {}
    for term in position.lever.terms:
        if term.image and term.force != 0:
            # The plan turned 90° clockwise about the pole, at the lever's μV.
            point = -1j * (position.velocity.points[term.image] + term.shift) / scale
            at_points.setdefault((round(point.real, 6), round(point.imag, 6)), []).append((term.name, point, term.force))
    pairs = 0
    for loads in at_points.values():
        for (first, point, force), (second, _, other) in itertools.combinations(loads, 2):
            if abs((force * other.conjugate()).imag) > math.sin(math.radians(10.0)) * abs(force) * abs(other):
                continue  # not along one line
            pairs += 1
            a, b = arrows[svg_id("lever", first)], arrows[svg_id("lever", second)]
            a0, a1, b0, b1 = (complex(*p) for p in (a.start, a.end, b.start, b.end))
            assert _overlap_mm(a0, a1, b0, b1) < 1.0 and _overlap_mm(b0, b1, a0, a1) < 1.0, (first, second)
            # Neither head in the other's stroke, but where one pushes onto the point the other pulls from.
            assert _distance(a1, b0, b1) > 0.8 or abs(a1 - point) < CLOSE_MM, (first, second)
            assert _distance(b1, a0, a1) > 0.8 or abs(b1 - point) < CLOSE_MM, (first, second)
    assert pairs >= 2
    for name, arrow in arrows.items():
        start, end = complex(*arrow.start), complex(*arrow.end)
        loads = [load for loads in at_points.values() for load in loads if svg_id("lever", load[0]) == name]
        if not loads:
            continue
        point = loads[0][1]
        # Beside its line by at most 6 mm: two parallel arrows' heads standing level need some 5 mm between them for
        # each name to stand by its own head (a name 3.2 mm high takes a box 4.6 mm high).
        tied = any(abs(complex(*leader.points[0]) - point) < CLOSE_MM and complex(*leader.points[-1]) in (start, end)
                   and abs(complex(*leader.points[-1]) - point) < 6.0 + CLOSE_MM for leader in leaders)
        assert min(abs(start - point), abs(end - point)) < CLOSE_MM or tied, name


@pytest.mark.parametrize("scene, number, locale, lever_scale", [
    ("stephenson_six_bar", 9, "en", None), ("shaper_six_bar", 3, "en", None),
    ("triad_class_iii", 2, "ru", 0.0025),  # as the A1 sheet draws it, smaller than on its own sheet
])
def test_the_lever_s_arms_are_lettered_clear_of_the_pole_or_given_under_it(scene, number, locale, lever_scale):
    """The arms h of Zhukovsky's lever all start at the pole p; their names were set about it, h6 on the pole's dot,
    among the names of the loads acting at p (Mu4″, Mu6″).  An arm whose name would stand by the pole is left
    unlettered, and the line under the equation gives its length on the drawing; every arm the equation names is
    lettered away from the pole or given there, at its length from the lever's records."""
    analysis = analyse(dataclasses.replace(graphplan.load(f"{FIXTURES}/{scene}.toml"), locale=locale))
    position = next(p for p in analysis.plans if p.number == number)
    sheet = force_sheet(analysis, position)
    if lever_scale is not None:
        sheet = dataclasses.replace(sheet, lever_scale=lever_scale)
    (lever,) = [drawing for row in force_layout.rows(sheet).drawings for drawing in row if drawing.name == "lever"]
    scale = sheet.lever_drawn_scale
    pole = -1j * position.velocity.points["p"] / scale
    labels = [item for layer in lever.layers if layer.name == "lever-labels" for item in layer.items]
    balancing_arm = load_symbol("hb", sheet.text)
    arms = {item.text: item for item in labels if re.fullmatch(r"h\d+", item.text) or item.text == balancing_arm}
    for name, label in arms.items():
        assert text_box(label).distance(shapely_point(pole.real, pole.imag)) >= 8.0, name
    equation = next(line for line in lever.caption if line.startswith("ΣMp:"))
    # Each term with its arm's name: loads on one line share one arm, named once.
    named = re.findall(r"([^\s+−]+)·(h\d+)\b", unfactored(equation))
    assert len(named) >= 5
    given = dict(re.findall(r"(h\d+) = ([\d.,]+)", " ".join(lever.caption[lever.caption.index(equation) + 1:])))
    assert given, "some arm by the pole is left unlettered"
    lengths = {load_symbol(term.name, sheet.text): abs(term.moment) / abs(term.force) / scale
               for term in position.lever.terms if term.image and term.force}
    for load, name in named:
        assert name in arms or name in given, name
        if name in given:
            assert float(given[name].replace(",", ".")) == pytest.approx(lengths[load], rel=2e-3), name


@pytest.mark.parametrize("scene, number, locale", [("shaper_six_bar", 3, "en"), ("quick_return_slotted_lever", 4, "zh"),
                                                   ("engine_slider_crank", 2, "en")])
def test_two_sides_of_a_polygon_on_one_line_in_opposite_senses_are_drawn_side_by_side(scene, number, locale):
    """R43 + ΣF3 + R23 = 0 closes on a straight line: the red R23 ran back over the black R43 and neither head showed
    (so did the engine's F4 over Fu4).  Of any two sides of a polygon along one line in opposite senses, neither
    head now lies in the other's stroke."""
    analysis = analyse(dataclasses.replace(graphplan.load(f"{FIXTURES}/{scene}.toml"), locale=locale))
    position = next(p for p in analysis.plans if p.number == number)
    layers = {layer.name: layer.items for layer in force_layout.layout(force_sheet(analysis, position))}
    pairs = 0
    for group in position.forces.groups:
        for _, arrows in polygon_layers(layers, group):
            for a, b in itertools.combinations(arrows, 2):
                a0, a1, b0, b1 = (complex(*p) for p in (a.start, a.end, b.start, b.end))
                along, back = (a1 - a0) / abs(a1 - a0), (b1 - b0) / abs(b1 - b0)
                if (along * back.conjugate()).real > -math.cos(math.radians(3.0)):
                    continue  # not in opposite senses along one direction
                if abs(((b0 - a0) * along.conjugate()).imag) > 2.0 or _overlap_mm(a0, a1, b0, b1, within=2.0) < 1.0:
                    continue  # not on one line, or not running along each other
                pairs += 1
                assert _distance(a1, b0, b1) > 0.8 and _distance(b1, a0, a1) > 0.8, (a.key, b.key)
    assert pairs >= 1


@pytest.mark.parametrize("locale", ["ru", "en", "zh"])
def test_the_lever_gives_each_balancing_load_on_one_line(locale):
    """In Russian the lever's two lines «уравновешивающий момент Mb = −267,7 Н·м (по рычагу Жуковского)» broke
    into four under the shaper's narrow lever (in English too), the value parted from how it was found (a hunt's
    sheet 4); the μF line above, as wide, kept whole.  Each balancing load now stands on a line of its own, its
    symbol, value and method together."""
    scene = graphplan.load("fixtures/shaper_six_bar.toml")
    analysis = analyse(dataclasses.replace(scene, locale=locale))
    text = strings(locale)
    for position in analysis.plans:
        settled = position.with_friction is not None and not position.with_friction.locked
        for with_friction in (False, True) if settled else (False,):
            lever = position.lever_with_friction if with_friction else position.lever
            layers = force_layout.layout(force_sheet(analysis, position, with_friction))
            caption = [item.text for layer in layers if layer.name == "lever-caption" for item in layer.items]
            unit = text["newton_metre"]
            found = (position.with_friction.balancing if with_friction else position.forces.balancing)
            name = load_symbol("Mb", text)
            wanted = [text["balancing_by_lever"].format(what="", name=name, value=significant(lever.balancing),
                                                        unit=unit).strip(),
                      text["balancing_by_polygons"].format(what="", name=name, value=significant(found),
                                                           unit=unit).strip()]
            assert [line for line in caption if f"{name} =" in line] == wanted, (locale, position.number, caption)
