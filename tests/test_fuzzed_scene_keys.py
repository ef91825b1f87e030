"""Scenes a fuzzer of the linkage's keys ([scene], [frame], [driver], [[groups]], [points], [links.N], [[loads]],
[positions], [drawing], [project], [output]: each value given another type, 0, a negative, NaN, inf, 1e300,
1e-300, an empty, long or non-Latin string; each key deleted; a table emptied; an array emptied or lengthened; a
key misspelled; the keys no fixture uses added) found answered wrongly: each as the small scene it came down to,
and the answer a student should get instead."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from graphplan.cli import main

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"

CENTRAL_SLIDER_CRANK = """
[scene]
title = "A central slider-crank"
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
[positions]
count = 12
working = {{ link = 4, sense = "backward" }}
plans = [2]
{velocity_plans}
[drawing]
{drawing}
"""


def _scene(tmp_path: Path, velocity_plans: str = "", drawing: str = "") -> Path:
    scene = tmp_path / "scene.toml"
    scene.write_text(CENTRAL_SLIDER_CRANK.format(velocity_plans=velocity_plans, drawing=drawing), encoding="utf-8")
    return scene


def test_a_pole_for_the_velocity_plans_of_every_position_none_of_which_is_drawn_runs(tmp_path, capsys) -> None:
    """`[drawing] velocity_plans_pole` given where `positions.velocity_plans` lists no position ended the run in a
    ValueError (max() of an empty sequence) after the analysis: the plan sheets' plans were taken for the velocity
    plans of every position, for a position with plan sheets is also a position with a velocity plan.  The pole
    draws nothing here; the run writes the plan sheet, and no output is left half-written."""
    out = tmp_path / "out"
    scene = _scene(tmp_path, drawing="velocity_plans_pole = 60.0")
    assert main(["run", str(scene), "--out", str(out), "--only", "velocity"]) == 0
    told = capsys.readouterr()
    assert "Traceback" not in told.err
    assert (out / "plan_2.svg").is_file()


def test_a_plan_sheet_drawn_too_small_is_told_at_its_pole_beside_the_grid_s_pole(tmp_path, capsys) -> None:
    """A plan sheet's velocity plan at `velocity_pole = 1` is drawn with pa 1 mm long, the whole plan (pa, ab, pb
    of a slider-crank, none longer than pa·(1 + r/l) at position 2) a few millimetres across, under a tenth of its
    150 mm field: told at `drawing.velocity_pole` without the pole of the velocity plans of every position and,
    as it must be, with it (that pole was taken to draw the plan sheet's plan, which was then judged as one of
    the grid's and not as its own)."""
    for pole in ("", "velocity_plans_pole = 60.0"):
        scene = _scene(tmp_path, velocity_plans="velocity_plans = [1, 2, 3, 4]",
                       drawing=f"velocity_pole = 1.0\n{pole}")
        out = tmp_path / f"out{len(pole)}"
        assert main(["run", str(scene), "--out", str(out), "--only", "velocity"]) == 0
        told = capsys.readouterr()
        assert "drawing.velocity_pole: draws the largest velocity plan" in told.out + told.err, (pole, told)


def _point_velocities(tmp_path: Path, name: str, start: float) -> list[list[float]]:
    scene = tmp_path / f"{name}.toml"
    scene.write_text(CENTRAL_SLIDER_CRANK.format(velocity_plans="", drawing="").replace(
        "count = 12", f"count = 12\nstart = {start!r}"), encoding="utf-8")
    out = tmp_path / name
    assert main(["run", str(scene), "--out", str(out), "--only", "velocity"]) == 0
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))
    return [position["points"]["B"]["v"] for position in document["positions"]]


def test_a_start_angle_of_many_turns_gives_the_motion_of_its_angle_within_the_turn(tmp_path, capsys) -> None:
    """`positions.start = 1e15` (degrees, within the magnitudes a scene takes) is 280° and 2 777 777 777 777 whole
    turns: the same positions.  Turned into radians whole, the angle kept only a few digits after the point, and
    the piston's velocities came out 0.2 % off those of `start = 280` while results.json wrote both positions'
    angle as 280°.  They are the same to the 12 digits results.json writes."""
    assert (1e15 - 280.0) % 360.0 == 0.0
    many_turns = _point_velocities(tmp_path, "many", 1e15)
    within_the_turn = _point_velocities(tmp_path, "within", 280.0)
    capsys.readouterr()
    for far, near in zip(many_turns, within_the_turn, strict=True):
        assert far == pytest.approx(near, rel=1e-10, abs=1e-12)


def test_a_swing_of_many_turns_gives_the_motion_of_its_angles_within_the_turn(tmp_path, capsys) -> None:
    """A rocking crank's `swing = [T + 20, T + 65]`, T = 999 999 999 999 720 a whole number of turns (a magnitude
    the scene reader takes), is the swing [20, 65]: results.json wrote its positions at 20°, 27.5°, … as for
    [20, 65], but the point's velocities came out 0.1 % off theirs, the ends turned into radians whole.  They are
    the same to the 12 digits results.json writes."""
    turns = 999_999_999_999_720.0
    assert turns % 360.0 == 0.0
    fixture = (FIXTURES / "double_rocker_swing.toml").read_text(encoding="utf-8")
    assert "swing   = [20.0, 65.0]" in fixture
    velocities = []
    for name, ends in (("many", f"[{turns + 20.0!r}, {turns + 65.0!r}]"), ("within", "[20.0, 65.0]")):
        scene = tmp_path / f"{name}.toml"
        scene.write_text(fixture.replace("swing   = [20.0, 65.0]", f"swing = {ends}"), encoding="utf-8")
        out = tmp_path / name
        assert main(["run", str(scene), "--out", str(out), "--only", "velocity"]) == 0
        document = json.loads((out / "results.json").read_text(encoding="utf-8"))
        velocities.append([position["points"]["B"]["v"] for position in document["positions"]])
    capsys.readouterr()
    for far, near in zip(*velocities, strict=True):
        assert far == pytest.approx(near, rel=1e-10, abs=1e-12)


def test_directions_of_many_turns_give_the_motion_and_forces_of_their_angles_within_the_turn(tmp_path, capsys) -> None:
    """A guide's `angle` and a force's `angle` of T + 0° and T + 180°, T = 999 999 999 999 720 a whole number of
    turns (a magnitude the scene reader takes), are the directions 0° and 180°; turned into radians whole they
    kept few digits after the point and tilted the piston's guide and the gas force off them.  The piston's
    velocities and the crank's balancing moment are the same as at 0° and 180° to the digits results.json
    writes."""
    turns = 999_999_999_999_720.0
    assert turns % 360.0 == 0.0
    fixture = (FIXTURES / "engine_slider_crank.toml").read_text(encoding="utf-8")
    guide, force = 'guide    = { through = "O", angle = 0.0 }', "angle     = 180.0"
    assert guide in fixture and force in fixture
    found = []
    for name, offset in (("many", turns), ("within", 0.0)):
        scene = tmp_path / f"{name}.toml"
        scene.write_text(fixture.replace(guide, guide.replace("0.0 }", f"{offset + 0.0!r} }}")).replace(
            force, f"angle = {offset + 180.0!r}"), encoding="utf-8")
        out = tmp_path / name
        assert main(["run", str(scene), "--out", str(out), "--only", "velocity,forces"]) == 0
        found.append((out / "results.json").read_text(encoding="utf-8"))
    capsys.readouterr()
    many, within = (json.loads(text) for text in found)
    for far, near in zip(many["positions"], within["positions"], strict=True):
        assert far["points"]["B"]["v"] == pytest.approx(near["points"]["B"]["v"], rel=1e-10, abs=1e-12)
        assert far["points"]["B"]["r"] == pytest.approx(near["points"]["B"]["r"], rel=1e-10, abs=1e-12)
        assert far["equilibrium"]["balancing_moment"] == pytest.approx(near["equilibrium"]["balancing_moment"],
                                                                      rel=1e-9, abs=1e-9)


def test_a_mechanism_far_from_the_origin_is_told_at_the_frame_point_not_as_a_piston_at_rest(tmp_path, capsys) -> None:
    """The central slider-crank with its pivot O at x = 1e9 m was refused with "link 4 does not move over the
    crank's turn: its travel is 0.1 m": a travel of 2r = 0.1 m told as rest, for rest was weighed against the
    joints' distance from the origin, not against the mechanism's size.  Placed at 1e9 m a position is told from
    rest only to 1e-9 of that, 1 m, which hides the stroke: the error names the frame point that stands so far
    and leaves the piston's 0.1 m stroke out of it; and at 1e3 m, where that is 1 µm, the same mechanism is
    checked with its strokes equal (K = 1) as at the origin."""
    for x in (0.0, 1e3):
        scene = _scene(tmp_path).read_text(encoding="utf-8").replace("O = [0.0, 0.0]", f"O = [{x!r}, 0.0]")
        (tmp_path / "near.toml").write_text(scene, encoding="utf-8")
        assert main(["check", str(tmp_path / "near.toml")]) == 0
        assert "K = φw/φi = 1.0000" in capsys.readouterr().out
    far = _scene(tmp_path).read_text(encoding="utf-8").replace("O = [0.0, 0.0]", "O = [1e9, 0.0]")
    (tmp_path / "far.toml").write_text(far, encoding="utf-8")
    assert main(["check", str(tmp_path / "far.toml")]) == 2
    told = capsys.readouterr().err
    assert told.startswith("graphplan: error: frame.points.O: "), told
    assert "does not move" not in told and "Traceback" not in told


def test_a_plan_larger_than_any_paper_is_given_the_pole_that_draws_it_at_its_size(tmp_path, capsys) -> None:
    """The crank and slotted lever with its lever's pivot C 0.5 mm inside the crank's circle: at position 10 (φ =
    270°) the crank pin A passes 0.5 mm from C, the lever turns at ω2·lOA/0.5 mm and its end D 0.55 m out moves
    over a thousand times faster than A, so its velocity plan is 1.1e5 mm across at `velocity_pole = 100`.  The
    pole that fits, under a millimetre, was rounded up to 1, which draws the plan a thousand millimetres across.  A
    plan's size is in proportion to its pole: the pole told draws it at the 150 mm said, to the two digits it is
    told in."""
    from graphplan.starters import starter

    lever = starter("slotted-lever")
    mutations = (("O = [0.0, 0.30]", "O = [0.0, 0.1195]"), ('start       = "extreme"', "start       = 0.0"),
                 ('working     = { link = 4, sense = "ccw" }', ""), ("plans       = [4, 11]", "plans = [10]"),
                 ("during    = { from = 0.05, to = 0.95 }", 'during = "always"'))
    for typed, mutated in mutations:
        assert typed in lever, typed
        lever = lever.replace(typed, mutated)
    assert "length  = 0.12" in lever and "velocity_pole      = 100.0" in lever
    scene = tmp_path / "near_toggle.toml"
    scene.write_text(lever, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "velocity"]) == 2
    told = capsys.readouterr().err
    assert not out.exists()
    found = re.search(r"drawing\.velocity_pole: draws the velocity plan of position 10 ([0-9.e+]+) mm across, "
                      r"more than any paper \(5000 mm\): give ([0-9.e+-]+) \(a 150 mm plan\)", told)
    assert found, told
    across, pole = float(found.group(1)), float(found.group(2))
    assert pole < 1.0
    assert across * pole / 100.0 == pytest.approx(150.0, rel=0.06)


def test_a_slide_set_off_its_guide_farther_than_any_machine_s_is_told_at_its_offset(tmp_path, capsys) -> None:
    """The tangent mechanism with its ram's block set 1e7 m off the lever's slot (`offsets = [1e7, 0]`) still
    assembles, for a PRP's sliders meet however far off, and draws the paths of the points 4.3e9 mm across: it
    was refused at `drawing.length_scale` (checked) or `drawing.velocity_pole` (the velocity plans run), scales the
    student never changed and that fit once the offset is a machine's.  Both are refused at the offset, named, and
    the fixture's own offsets are not (the 0.55 m from C to the ram's guide is what sets the ram)."""
    fixture = (FIXTURES / "tangent_mechanism_prp.toml").read_text(encoding="utf-8")
    assert "offsets = [0.0, 0.0]" in fixture
    scene = tmp_path / "far_offset.toml"
    scene.write_text(fixture.replace("offsets = [0.0, 0.0]", "offsets = [1e7, 0.0]"), encoding="utf-8")
    assert main(["check", str(FIXTURES / "tangent_mechanism_prp.toml")]) == 0
    capsys.readouterr()
    for command in (["check", str(scene)], ["run", str(scene), "--out", str(tmp_path / "out"), "--only", "velocity"]):
        assert main(command) == 2
        told = capsys.readouterr().err
        error = told[told.index("graphplan: error: "):]
        assert error.startswith("graphplan: error: groups[1].offsets[0]: sets the slide at B 1e+07 m off its "
                                "guide"), told
        assert "(got 10000000.0)" in error and "Traceback" not in told
    assert not (tmp_path / "out").exists()


def test_a_frame_pivot_farther_off_than_any_machine_s_is_told_at_that_point_not_as_a_link_at_rest(tmp_path,
                                                                                                  capsys) -> None:
    """The crank and slotted lever with its lever's pivot C moved to x = 1e15 m: the 0.12 m crank then turns the
    lever through some lOA/lOC = 1.2e-16 rad, rest, and the scotch yoke with its crank's pivot O 1e15 m from its yoke's
    guide moves the yoke its 2·lOA = 0.15 m where a position 1e15 m out is told from rest only to 1e6 m.  Both
    were refused as "link 4 does not move", sending the student to the lengths and guides, which are right: each
    is told at the frame point moved off, with how far it stands from the rest of the frame.  The starter as
    written checks."""
    from graphplan.starters import starter

    lever = starter("slotted-lever")
    assert "C = [0.0, 0.0], O = [0.0, 0.30]" in lever and "length  = 0.12" in lever
    (tmp_path / "lever.toml").write_text(lever, encoding="utf-8")
    assert main(["check", str(tmp_path / "lever.toml")]) == 0
    capsys.readouterr()
    yoke = (FIXTURES / "scotch_yoke.toml").read_text(encoding="utf-8")
    assert "points = { O = [0.0, 0.0] }" in yoke and "length  = 0.075" in yoke
    cases = ((lever.replace("C = [0.0, 0.0]", "C = [1e15, 0.0]"), "frame.points.C: stands 1e+15 m from O, ", "rad"),
             (yoke.replace("O = [0.0, 0.0]", "O = [1e15, 0.0]"),
              "frame.points.O: stands 1e+15 m from the guide's point groups[0].guide.through, ", "m"))
    for text, opening, unit in cases:
        scene = tmp_path / "far.toml"
        scene.write_text(text, encoding="utf-8")
        assert main(["check", str(scene)]) == 2
        told = capsys.readouterr().err
        assert f"graphplan: error: {opening}" in told, told
        assert "does not move" not in told and "Traceback" not in told
        travel = float(re.search(rf"link 4 moves ([0-9.e+-]+) {unit} over the crank's turn", told).group(1))
        # The lever's turn, some 1e-16 rad, is lost in the rounding of positions 1e15 m out: only that it is rest.
        assert travel == pytest.approx(0.15, rel=1e-6) if unit == "m" else travel <= 1e-9


def test_a_swing_too_small_for_its_positions_to_be_drawn_apart_is_told_at_the_swing(tmp_path, capsys) -> None:
    """The double rocker's hand lever swung through 1e-12° (`swing = [20, 20.000000000001]`) was taken, and its 7
    positions drawn as one line.  Drawn on the largest paper (5000 mm) a crank pin moves at most 5000 mm·δ for a
    step δ (rad), and lines are told apart to the drafting precision (0.5 mm): the 6 steps need a swing of at least
    6 · 0.5/5000 rad = 0.0344°.  Refused at `driver.swing` with that value, before anything is written; the swing
    told checks, and so does the fixture's 45°."""
    fixture = (FIXTURES / "double_rocker_swing.toml").read_text(encoding="utf-8")
    assert "swing   = [20.0, 65.0]" in fixture and "count = 7" in fixture and "drafting_precision" not in fixture
    scene = tmp_path / "tiny_swing.toml"
    scene.write_text(fixture.replace("swing   = [20.0, 65.0]", "swing = [20.0, 20.000000000001]"), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    told = capsys.readouterr().err
    assert not out.exists()
    assert told.startswith("graphplan: error: driver.swing: "), told
    least = float(re.search(r"give a swing of at least ([0-9.e+-]+)°", told).group(1))
    assert least == pytest.approx(math.degrees(6 * 0.5 / 5000), rel=0.02)
    for swing in (f"[20.0, {20.0 + least!r}]", "[20.0, 65.0]"):
        scene.write_text(fixture.replace("swing   = [20.0, 65.0]", f"swing = {swing}"), encoding="utf-8")
        assert main(["check", str(scene)]) == 0, capsys.readouterr().err
    capsys.readouterr()


@pytest.mark.parametrize(("kind", "other"), [("crank-rocker", "errors"), ("rotor", "balancing")])
def test_a_piece_listed_twice_in_output_include_is_told_at_the_repeat(tmp_path, capsys, kind, other) -> None:
    """`[output] include = ["note", "note"]` was taken as ["note"]: a repeat, most likely a slip for another piece
    that the run then left out without a word, refused as a position listed twice under `positions.plans` is, at
    the repeat with the place it was first listed; of a linkage's scene and of one without, which read `[output]`
    alike.  Each piece listed once is taken."""
    from graphplan.starters import starter

    text = starter(kind)
    assert "[output]" not in text
    scene = tmp_path / "scene.toml"
    repeats = (('["note", "note"]', "output.include[1]: note is already listed at output.include[0]"),
               (f'["note", "{other}", "note"]', "output.include[2]: note is already listed at output.include[0]"))
    for include, told in (('["note"]', None), *repeats):
        scene.write_text(f"{text}\n[output]\ninclude = {include}\n", encoding="utf-8")
        if told is None:
            assert main(["check", str(scene)]) == 0, capsys.readouterr().err
            assert "run writes: note" in capsys.readouterr().out
            continue
        assert main(["check", str(scene)]) == 2
        error = capsys.readouterr().err
        assert error.startswith(f"graphplan: error: {told}"), error


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_position_the_lengths_do_not_close_at_names_the_keys_that_set_them(tmp_path, capsys, locale) -> None:
    """The crank-rocker starter with its coupler shortened to 0.3 m (`lengths = [0.3, 0.325]`) cannot close where
    A–C = |A − C| passes AB + BC = 0.625 m, and was refused with the joints' letters alone ("A–C = 0.625948 m > AB +
    BC = 0.625 m"), no key of the scene among them.  The refusal names the keys that set A–C, AB and BC (the
    group's lengths, the crank's length, the frame points) beside the angle where it fails, in a scene of each
    language alike, and the reach advice still follows.  The angle told is one where the crank pin, 0.175 m from O
    at [0, 0], stands farther than 0.625 m from C at [0, 0.55]."""
    from graphplan.starters import starter

    text = starter("crank-rocker", locale)
    assert "lengths  = [0.55, 0.325]" in text and "length  = 0.175" in text
    assert "O = [0.0, 0.0], C = [0.0, 0.55]" in text
    scene = tmp_path / "short_coupler.toml"
    scene.write_text(text.replace("lengths  = [0.55, 0.325]", "lengths  = [0.3, 0.325]"), encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    told = capsys.readouterr().err
    found = re.search(r"graphplan: error: B cannot be assembled at φ = ([0-9.-]+)° in group II\(3,4\): A–C = "
                      r"([0-9.]+) m > AB \+ BC = 0\.625 m; the scene's keys that set it: groups\[0\]\.lengths = "
                      r"\[0\.3, 0\.325\], driver\.length = 0\.175, frame\.points\.O, frame\.points\.C; link 2 reaches "
                      r"only from ", told)
    assert found, told
    angle = math.radians(float(found.group(1)))
    apart = abs(0.175 * complex(math.cos(angle), math.sin(angle)) - 0.55j)
    assert apart > 0.625 and apart == pytest.approx(float(found.group(2)), abs=1e-6)
    assert "driver.swing = [" in told


def test_a_slider_driver_s_position_the_lengths_do_not_close_at_names_its_travel_and_guide(tmp_path, capsys) -> None:
    """The slider-driven fixture with its links shortened to `lengths = [0.1, 0.1]`: the rod's end A, 0.2915 m from
    C at the travel's start, is beyond AB + BC = 0.2 m.  The refusal names the group's lengths, and what places A,
    the driver's travel and guide, not "driver" alone."""
    fixture = (FIXTURES / "slider_driven.toml").read_text(encoding="utf-8")
    assert "lengths  = [0.225, 0.15]" in fixture
    scene = tmp_path / "short_links.toml"
    scene.write_text(fixture.replace("lengths  = [0.225, 0.15]", "lengths  = [0.1, 0.1]"), encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    told = capsys.readouterr().err
    assert ("AB + BC = 0.2 m; the scene's keys that set it: groups[0].lengths = [0.1, 0.1], driver.travel = [0.0, "
            "0.2], driver.guide, frame.points.C; ") in told, told


@pytest.mark.parametrize("working", [True, False], ids=["working-link", "no-working-link"])
def test_a_travel_too_short_for_its_positions_to_be_drawn_apart_is_told_at_the_travel(tmp_path, capsys,
                                                                                     working) -> None:
    """The slider-driven fixture's rod given `travel = [0, 1e-15]` was refused at positions.working, its lever
    "does not move", and without a working link taken, its 12 positions drawn as one.  The plan of positions is
    drawn at most 5000 mm across (the largest paper), and the mechanism at its first position already spans the
    0.25 m from G = [0, 0] up to C = [0.15, 0.25]: a step of the slider is drawn at most travel/11 · 5000/0.25 mm,
    and lines are told apart to the drafting precision (0.5 mm), so the 11 steps need a travel of at least
    11 · 0.5 · 0.25/5000 m.  Refused at `driver.travel` with that value by run and check alike, before anything is
    written; the travel told checks, and so does the fixture's 0.2 m."""
    fixture = (FIXTURES / "slider_driven.toml").read_text(encoding="utf-8")
    typed = "travel       = [0.0, 0.20]"
    assert typed in fixture and "G = [0.0, 0.0], C = [0.15, 0.25]" in fixture and "count       = 12" in fixture
    if not working:
        fixture = fixture.replace('working     = { link = 4, sense = "ccw" }', "").replace(
            'during    = "working"', 'during    = "always"')
    scene = tmp_path / "tiny_travel.toml"
    scene.write_text(fixture.replace(typed, "travel = [0.0, 1e-15]"), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    told = capsys.readouterr().err
    assert not out.exists()
    assert told.startswith("graphplan: error: driver.travel: "), told
    least = float(re.search(r"give a travel of at least ([0-9.e+-]+) m", told).group(1))
    assert least == pytest.approx(11 * 0.5 * 0.25 / 5000, rel=0.02)
    assert main(["check", str(scene)]) == 2
    assert capsys.readouterr().err == told
    for travel in (f"[0.0, {least!r}]", "[0.0, 0.20]"):
        scene.write_text(fixture.replace(typed, f"travel = {travel}"), encoding="utf-8")
        assert main(["check", str(scene)]) == 0, capsys.readouterr().err
    capsys.readouterr()


def test_an_rpr_slide_out_of_reach_names_its_offset_once(tmp_path, capsys) -> None:
    """The quick-return fixture's slide set 0.25 m off the lever's pivot C (`offset = 0.25`): the crank pin A, 0.12 m
    from O and O 0.30 m from C, comes as near C as 0.18 m, where the block cannot reach the slide.  The refusal named
    groups[0].offset twice, in its arithmetic ("0.25 m from C (groups[0].offset)") and in the list of the scene's
    keys that set it: named in the list with its value, by check and run alike, and again only in the advice that
    turns the crank round, with the size under A's nearest to C that does (the crank pointing down from O to C)."""
    fixture = (FIXTURES / "quick_return_slotted_lever.toml").read_text(encoding="utf-8")
    typed = "offset = 0.0             # the slot's centre line passes through C"
    assert typed in fixture and "C = [0.0, 0.0], O = [0.0, 0.30]" in fixture and "length  = 0.12" in fixture
    assert 0.30 - 0.12 < 0.25
    scene = tmp_path / "offset_slide.toml"
    scene.write_text(fixture.replace(typed, "offset = 0.25"), encoding="utf-8")
    for command in (["check", str(scene)], ["run", str(scene), "--out", str(tmp_path / "out")]):
        assert main(command) == 2
        told = capsys.readouterr().err
        assert "the slide runs 0.25 m from C but A is only " in told, told
        assert "the scene's keys that set it: groups[0].offset = 0.25, " in told, told
        assert told.count("groups[0].offset") == 2, told
        assert told.rstrip().endswith("; or, if link 2 is meant to turn round, check the lengths: over the turn A "
                                      "comes as near as 0.18 m to C (at φ = 270°), inside the slide's 0.25 m, so the "
                                      "crank turns round only with groups[0].offset of a size up to 0.1799 m"), told
    assert not (tmp_path / "out").exists()
