"""The force sheet with friction, tested on its primitives.

Each journal with friction is drawn with its friction circle ρ = f·r (at μl,
enlarged to a least radius when smaller), and the whole reaction of each outer
pair lies on the circle's tangent on the side whose moment about the joint is
the pair's friction moment on the group, ``ρ·|R|`` in size, the reactions a
later group found among them (the crank's R32 = −R23, on R23's line): the
textbook's construction, read back off the paper and compared with the force
records and with the crank's moment equation worked out afresh.
The sheet heads with the balancing load without friction and the efficiency;
its lever carries the friction loads and agrees with the polygons.  The
command line writes one such sheet per plan position whose reactions settle.
"""

import dataclasses
import math
import re

import pytest
from test_joint_friction import FIXTURES, ratchet_with_friction, slider_crank, slider_crank_text
from test_lever_with_friction import slotted_lever_with_friction

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.kinematics import cross
from graphplan.locale import load_symbol, strings
from graphplan.render import force_bodies
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet, forces_svg, length_scale, with_length_scale
from graphplan.render.primitives import Circle, Polyline, Text
from graphplan.render.sheet import course_sheets
from graphplan.scene import FrictionSpec

# Within this on the paper (mm) two drawn points are one.
CLOSE_MM = 1e-6

_analyses = {}


def analysis_of(name):
    if name not in _analyses:
        source = {"ratchet": lambda: ratchet_with_friction(0.12), "slotted lever": slotted_lever_with_friction}[name]
        _analyses[name] = with_length_scale(source())
    return _analyses[name]


CASES = [(name, k) for name in ("ratchet", "slotted lever") for k in (0, 1)]


@pytest.fixture(params=CASES, ids=[f"{name}-{k}" for name, k in CASES])
def case(request):
    """(analysis, plan position, layers by name) of the sheet with friction of a plan position."""
    name, k = request.param
    analysis = analysis_of(name)
    position = analysis.plans[k]
    layers = {layer.name: layer.items for layer in force_layout.layout(force_sheet(analysis, position, True))}
    return analysis, position, layers


def journals_of(analysis, group):
    return {pair.joint: pair for pair in analysis.friction
            if not pair.sliding and (pair.source in group.links or pair.target in group.links)}


def test_each_journal_with_friction_has_its_circle_at_scale_or_enlarged(case):
    analysis, position, layers = case
    scale = length_scale(analysis)
    checked = 0
    for group in position.with_friction.groups:
        drawn = layers.get(f"body-{force_layout.group_id(group.label)}-friction", ())
        circles = [item for item in drawn if isinstance(item, Circle)]
        expected = sorted(max(pair.radius / scale, force_bodies.LEAST_FRICTION_CIRCLE_MM)
                          for pair in journals_of(analysis, group).values())
        assert sorted(circle.radius for circle in circles) == pytest.approx(expected, abs=CLOSE_MM)
        # Each is centred on a pin of the group's drawing: on its joint.
        pins = [item.centre for item in layers[f"body-{force_layout.group_id(group.label)}-links"]
                if isinstance(item, Circle)]
        for circle in circles:
            assert min(math.dist(circle.centre, pin) for pin in pins) < CLOSE_MM
        checked += len(circles)
    assert checked >= 2


def test_the_whole_reaction_lies_on_the_tangent_on_the_side_of_the_friction_moment(case):
    analysis, position, layers = case
    checked = 0
    for group in position.with_friction.groups:
        drawn = layers.get(f"body-{force_layout.group_id(group.label)}-friction", ())
        circles = [item for item in drawn if isinstance(item, Circle)]
        lines = [item for item in drawn if isinstance(item, Polyline)]
        moments = {load.name: load.moment for load in group.loads if not load.is_force}
        journals = journals_of(analysis, group)
        outer = outer_reactions(position.with_friction, group, journals)
        assert len(lines) == len(outer), group.label
        for pair, joint, force in outer:
            unit = force / abs(force)
            line = next(line for line in lines if abs(cross(unit, _direction(line))) < 1e-9)
            start = complex(*line.points[0])
            # The friction moment on the group is ρ·|R|: the reaction's own, settled.
            moment = moments[f"Mf{pair}"]
            assert abs(moment) == pytest.approx(journals[joint].radius * abs(force), rel=1e-9)
            circle = min(circles, key=lambda c: abs(cross(unit, start - complex(*c.centre))) - c.radius)
            # A force along the line, in the reaction's sense, turns about the joint as the friction moment does.
            arm = cross(start - complex(*circle.centre), unit)
            assert abs(arm) == pytest.approx(circle.radius, abs=CLOSE_MM)
            assert math.copysign(1.0, arm) == math.copysign(1.0, moment)
            checked += 1
    assert checked >= 2


def outer_reactions(forces, group, journals):
    """(pair, joint, force on the group) of each journal with friction joining one of the group's links to a link
    outside it, the pair named from the outside in (``32``): the reaction its polygon finds (R12), or the one a later
    group found, reversed (R32 = −R23)."""
    outer = []
    for joint, pair in journals.items():
        ours, theirs = (pair.target, pair.source) if pair.target in group.links else (pair.source, pair.target)
        if theirs in group.links:
            continue
        found = next(found for found in forces.reactions.values() if {found.source, found.target} == {ours, theirs})
        outer.append((f"{theirs}{ours}", joint, found.force if found.target == ours else -found.force))
    return outer


def _direction(line: Polyline) -> complex:
    (x0, y0), (x1, y1) = line.points[0], line.points[-1]
    return complex(x1 - x0, y1 - y0) / math.hypot(x1 - x0, y1 - y0)


def large_journals(name):
    """The ratchet, or the slotted lever, with journals whose friction circles are drawn at μl, not enlarged:
    ρ = 0.3·60 mm = 18 mm (7.2 mm on the ratchet's paper, 9 mm on the lever's)."""
    if name not in _analyses:
        scene = graphplan.load(FIXTURES / {"large ratchet": "ratchet_crank_rocker.toml",
                                           "large slotted lever": "quick_return_slotted_lever.toml"}[name])
        journals = {"large ratchet": [(joint, None) for joint in "OABC"],
                    "large slotted lever": [("C", None), ("A", (2, 3))]}[name]
        specs = tuple(FrictionSpec(f"friction[{k}]", joint, links, 0.3, 0.06, None)
                      for k, (joint, links) in enumerate(journals))
        if name == "large slotted lever":
            specs += (FrictionSpec(f"friction[{len(specs)}]", "A", (3, 4), 0.15, None, None),)
        _analyses[name] = with_length_scale(analyse(dataclasses.replace(scene, friction=specs)))
    return _analyses[name]


LARGE = [(name, k) for name in ("large ratchet", "large slotted lever") for k in (0, 1)]


@pytest.mark.parametrize(("name", "k"), LARGE, ids=[f"{name}-{k}" for name, k in LARGE])
def test_the_crank_takes_its_rod_s_reaction_on_the_rod_s_tangent_and_its_moment_equation_there(name, k):
    """R32 = −R23 acts on the crank along the line R23 is drawn on at A, the tangent of A's friction circle whose
    moment about A is the friction moment on the crank, −sign(ω2 − ω3)·ρA·|R32|.  Taken there, with R12 on its own
    tangent at O, ΣMO of the crank gives the balancing moment the sheet writes; the caption's R32·h + Mf32, h
    drawn to R32's arrow through A, is R32's moment on that tangent, and so is the tangent's arm drawn at μl."""
    analysis = large_journals(name)
    position = analysis.plans[k]
    layers = {layer.name: layer.items for layer in force_layout.layout(force_sheet(analysis, position, True))}
    forces, driver, motion, i = position.with_friction, analysis.mechanism.driver, analysis.motion, position.index
    scale = length_scale(analysis)
    assert all(pair.radius / scale > force_bodies.LEAST_FRICTION_CIRCLE_MM for pair in analysis.friction
               if not pair.sliding)
    crank, rod = forces.groups[-1], next(group for group in forces.groups
                                         if any(found.source == driver.link for found in group.found))
    rod_on_crank = next(found for found in rod.found if found.source == driver.link and found.joint == driver.joint)
    force = -rod_on_crank.force
    pivot, joint = (complex(*motion.point(point).r[i]) for point in (driver.pivot, driver.joint))
    omega = {link: motion.link(link).omega[i] for link in (driver.link, rod_on_crank.target)}
    journals = journals_of(analysis, crank)
    rho = journals[driver.joint].radius
    relative = omega[driver.link] - omega[rod_on_crank.target]
    assert abs(relative) > 1e-6
    friction_at_joint = -math.copysign(rho * abs(force), relative)
    # The tangent's moment about O: the force's through A and the friction moment about A.
    on_tangent = cross(joint - pivot, force) + friction_at_joint
    at_pivot = 0.0
    if driver.pivot in journals:
        frame_on_crank = forces.reactions[f"R{analysis.mechanism.scene.frame_link}{driver.link}"].force
        at_pivot = -math.copysign(journals[driver.pivot].radius * abs(frame_on_crank), omega[driver.link])
    spec = analysis.mechanism.scene.links[driver.link]
    centre = complex(*motion.point(spec.centre).r[i])
    own = spec.mass * (-1j * analysis.mechanism.scene.gravity - complex(*motion.point(spec.centre).a[i]))
    own_moment = cross(centre - pivot, own) - spec.inertia * motion.link(driver.link).epsilon[i]
    balancing = -(own_moment + at_pivot + on_tangent)
    assert forces.balancing == pytest.approx(balancing, rel=1e-9)

    unit = force / abs(force)
    key, rod_key = force_layout.group_id(crank.label), force_layout.group_id(rod.label)
    paper = drawn_at(layers, key, scale, journals, motion, i)
    # The pivot is drawn where the crank's pin at A puts it, with a friction circle or without.
    paper_joint = paper[driver.joint]
    paper_pivot = paper_joint + (pivot - joint) / scale
    tangent = next(line for line in layers[f"body-{key}-friction"] if isinstance(line, Polyline)
                   and abs(cross(unit, _direction(line))) < 1e-9
                   and abs(abs(cross(complex(*line.points[0]) - paper_joint, unit)) - rho / scale) < 1e-6)
    assert cross(complex(*tangent.points[0]) - paper_pivot, unit) * scale * abs(force) == \
        pytest.approx(on_tangent, rel=1e-9)
    # R23's line on the rod's drawing is the same line, about A.
    rod_joint = drawn_at(layers, rod_key, scale, journals_of(analysis, rod), motion, i)[driver.joint]
    rod_tangent = next(line for line in layers[f"body-{rod_key}-friction"] if isinstance(line, Polyline)
                       and abs(cross(unit, _direction(line))) < 1e-9
                       and abs(abs(cross(complex(*line.points[0]) - rod_joint, unit)) - rho / scale) < 1e-6)
    assert cross(complex(*rod_tangent.points[0]) - rod_joint, unit) == \
        pytest.approx(cross(complex(*tangent.points[0]) - paper_joint, unit), abs=CLOSE_MM)

    caption = " ".join(item.text for item in layers[f"body-{key}-caption"])
    symbol = load_symbol("Mb", strings(analysis.scene.locale))  # the Russian ratchet's Mу
    equation = caption[caption.index(f"ΣM{driver.pivot}("):caption.index(f"{symbol} = {written(balancing)}")]
    pair = f"{rod_on_crank.target}{driver.link}"
    assert f"Mf{pair}" in equation and re.search(rf"R{pair}·h\d", equation)
    arm = abs(cross(joint - pivot, unit)) / scale
    assert any(isinstance(item, Polyline) and math.dist(item.points[0], (paper_pivot.real, paper_pivot.imag)) < 1e-6
               and math.dist(*item.points) == pytest.approx(arm, abs=CLOSE_MM)
               and abs(cross(complex(*item.points[-1]) - paper_joint, unit)) < 1e-6
               for item in layers[f"body-{key}-arms"])


def drawn_at(layers, key, scale, journals, motion, index):
    """Where the group's journals stand on its drawing (mm, by joint), found by its friction circles at μl."""
    joints = {joint: complex(*motion.point(joint).r[index]) / scale for joint in journals}
    centres = [complex(*item.centre) for item in layers[f"body-{key}-friction"] if isinstance(item, Circle)]
    for centre in centres:
        shift = centre - next(iter(joints.values()))
        if all(min(abs(other - where - shift) for other in centres) < 1e-6 for where in joints.values()):
            return {joint: where + shift for joint, where in joints.items()}
    raise AssertionError(f"no friction circles at {', '.join(joints)} on {key}")


def test_the_driving_link_s_caption_gives_the_load_without_friction_and_the_efficiency(case):
    analysis, position, layers = case
    driver = force_layout.group_id(position.with_friction.groups[-1].label)
    caption = " ".join(item.text for item in layers[f"body-{driver}-caption"])
    ideal, rubbing = position.forces.balancing, position.with_friction.balancing
    eta = ideal / rubbing if ideal * analysis.mechanism.driver.omega > 0 else rubbing / ideal
    assert 0.0 < eta < 1.0
    line = caption[caption.index(f"{load_symbol('Mb', strings(analysis.scene.locale))} = {written(rubbing)}"):]
    assert written(ideal) in line and written(eta) in line and str(position.with_friction.iterations) in line
    # Not in the heading: a sheet set part by part keeps it.
    assert not any("η" in item.text for item in layers["sheet-title"])


def written(value: float) -> str:
    """A number as the sheet writes it: four significant digits, a true minus sign."""
    return f"{value:.4g}".replace("-", "−")


def test_the_lever_on_the_sheet_carries_the_friction_and_agrees_with_the_polygons(case):
    _, position, layers = case
    lever = [item.text for item in layers["lever-caption"]]
    assert any(text.endswith(" 0.00 %") for text in lever)
    # The lever's own balancing load, with friction, is the one written as the lever's.
    assert sum(written(position.lever_with_friction.balancing) in text for text in lever) == 2
    names = {item.text for item in layers["lever-labels"] if isinstance(item, Text)}
    assert any(name.startswith("Mf") for name in names)


def test_a_russian_scene_writes_its_friction_in_russian():
    analysis = analysis_of("ratchet")
    layers = force_layout.layout(force_sheet(analysis, analysis.plans[0], True))
    captions = [item.text for layer in layers if layer.name.endswith("caption") for item in layer.items]
    assert any(text.startswith("круги трения ρ = f·r: ρA = ") for text in captions)
    assert any("с учётом трения" in item.text for layer in layers for item in layer.items if isinstance(item, Text))


def test_without_settled_reactions_there_is_no_sheet_with_friction(tmp_path):
    """The slider-crank's crank pushing its piston jams at f = 5 where f·tan β > 1 (position 17 of the four plan
    positions): the piston pushing the crank (1, 5, 9) does not, its rod force P/(cos β + f·sin β) only
    smaller; one sheet of friction less."""
    scene = tmp_path / "jamming.toml"
    scene.write_text(slider_crank_text('[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 5.0'))
    analysis = analyse(slider_crank('[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 5.0'))
    settled = [p.number for p in analysis.plans if not p.with_friction.locked]
    pushes_the_piston = [p.number for p in analysis.plans if analysis.motion.point("B").v[p.index, 0] > 0]
    beta = [math.asin(0.25 * math.sin(analysis.motion.driver[p.index])) for p in analysis.plans]
    jams = [p.number for p, angle in zip(analysis.plans, beta, strict=True)
            if p.number in pushes_the_piston and 5.0 * abs(math.tan(angle)) > 1.0]
    assert jams == [17] and settled == [1, 5, 9]
    with pytest.raises(ValueError, match="no settled force analysis with friction"):
        force_sheet(analysis, next(p for p in analysis.plans if p.with_friction.locked), True)
    # Only the force drawings, which are all that is read.
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "forces"]) == 0
    # The drawings whole (the note's parts of them, forces_friction_5-1.svg, left aside).
    written = sorted(path.name for path in (tmp_path / "out").glob("forces_friction_*.svg") if "-" not in path.stem)
    assert written == sorted(f"forces_friction_{number}.svg" for number in settled)
    assert len([path for path in (tmp_path / "out").glob("forces_[0-9]*.svg") if "-" not in path.stem]) == \
        len(analysis.plans)


def test_the_sheet_names_the_ratio_that_is_the_efficiency():
    """η = Mb0/Mb where the crank drives the load, Mb/Mb0 where the load drives the crank back."""
    analysis = with_length_scale(analyse(slider_crank('[[friction]]\njoint = "O"\nf = 0.1\nradius = 0.03')))
    omega, seen = analysis.mechanism.driver.omega, set()
    for position in analysis.plans:
        captions = " ".join(item.text for layer in force_layout.layout(force_sheet(analysis, position, True))
                            if layer.name.endswith("-caption") for item in layer.items)
        ideal, rubbing = position.forces.balancing, position.with_friction.balancing
        ratio, eta = ("Mb0/Mb", ideal / rubbing) if ideal * omega > 0 else ("Mb/Mb0", rubbing / ideal)
        assert f"η = {ratio} = {written(eta)}" in captions
        seen.add(ratio)
    assert seen == {"Mb0/Mb", "Mb/Mb0"}


def test_the_course_sheets_carry_each_settled_sheet_with_friction_after_its_position(tmp_path):
    """The jamming slider-crank: a sheet with friction only for the position that settles, named in its title
    block, and the drawing written on its own is the one on the sheet."""
    scene = tmp_path / "jamming.toml"
    scene.write_text(slider_crank_text('[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 5.0'))
    analysis = with_length_scale(analyse(graphplan.load(scene)))
    settled = [p.number for p in analysis.plans if not p.with_friction.locked]
    sheets = course_sheets(analysis, "A1")
    placed = [name for sheet in sheets for name in sheet.panels]
    with_friction = [name for name in placed if name.startswith("forces-friction-")]
    assert sorted({int(name.split("-")[2]) for name in with_friction}) == settled
    for number in settled:
        # Each after its own position's force sheet.
        assert placed.index(f"forces-{number}") < placed.index(f"forces-friction-{number}")
        sheet = next(sheet for sheet in sheets if f"forces-friction-{number}" in sheet.panels)
        written = [item.text for item in sheet.layers if item.name.startswith(f"forces-friction-{number}-")
                   for item in item.items if isinstance(item, Text)]
        assert f"Force analysis with friction, position {number}" in written
        assert not any(analysis.scene.title in line for line in written)
        assert any("η = " in line for line in written)
        block = [item.text for item in sheet.layers if item.name == "title-block" for item in item.items
                 if isinstance(item, Text)]
        if len(sheet.panels) == 1:
            assert " ".join(block).count(f"with friction, position {number}") == 1
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "sheets,forces,lever"]) == 0
    drawn = (tmp_path / "out" / f"forces_friction_{settled[0]}.svg").read_text()
    assert drawn == forces_svg(analysis, next(p for p in analysis.plans if p.number == settled[0]), True)
