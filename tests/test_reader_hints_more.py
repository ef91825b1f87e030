"""Hints that fit the slip: a TOML error at a line's end is not taken for a degree sign (every string holds the
empty one), a coordinate list [0,0] is not taken for a decimal comma, a misspelt optional table or a key written
as the textbook's symbol or in American spelling is named with the key meant, one position cannot run over a
travel or a swing, driving = "constant" in a linkage scene is told the linkage's spelling, a damping ratio
above 1 is warned of (above 2 asked whether it is a percentage), a guide whose angle is left out is told it
runs at 0°, a paper size the sheets are not laid out on (A0) is told so rather than taken for a slip of A4, a velocity
plan listed twice is refused as a plan sheet listed twice is, load given no path says what it takes, and sheets asked
for with --sheet none blame --sheet, not the scene's drawing.sheet."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
from test_scene_errors import first_error

import graphplan
from graphplan.deliverables import outcome_warnings
from graphplan.scene import guides_without_angle
from graphplan.starters import starter
from graphplan.vibration import damping_warning

CRANK_ROCKER = starter("crank-rocker")
SHAPER = starter("shaper")
FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"


def changed(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


@pytest.mark.parametrize(("old", "new", "hint"), [
    ("[positions]", "[positions", ""),
    ('title   = "Crank-rocker mechanism"', 'title   = "Crank-rocker mechanism',
     '; the string opened on this line is not closed: end it with "'),
    ('title   = "Crank-rocker mechanism"', 'title   = "a"\ntitle = "b"', "; a key or a table given twice: keep one"),
    ('points = { O = [0.0, 0.0], C = [0.0, 0.55] }', 'points = { O = [0,0], C = [0,0.55]',
     "; an inline table { … } ends on the line it starts: close it with }"),
], ids=["open-bracket", "open-quote", "key-twice", "open-inline-table"])
def test_a_toml_error_at_a_lines_end_gets_a_hint_that_fits_or_none(old, new, hint) -> None:
    stage, error = first_error(changed(CRANK_ROCKER, old, new))
    message = str(error)
    assert stage == "load" and "degree sign" not in message and "decimal comma" not in message
    assert message.endswith(")" + hint)


def test_a_decimal_comma_outside_a_list_is_still_told() -> None:
    stage, error = first_error(changed(CRANK_ROCKER, "length  = 0.175", "length  = 0,175"))
    assert stage == "load" and str(error).endswith("; a decimal comma? TOML numbers take a point: write 0.175")


@pytest.mark.parametrize(("table", "meant"), [
    ("dynamic", "dynamics"), ("Dynamics", "dynamics"), ("balance", "balancing"), ("vibrations", "vibration"),
])
def test_a_misspelt_optional_table_is_named_with_the_one_meant(table, meant) -> None:
    stage, error = first_error(changed(CRANK_ROCKER, "[links.3]", f"[{table}]\n[links.3]"))
    assert (stage, str(error)) == ("load", f"{table}: unknown key; did you mean {meant!r}?")


@pytest.mark.parametrize(("old", "new", "message"), [
    ('centre  = "S3"', 'center  = "S3"', "links.3.center: unknown key; did you mean 'centre'?"),
    ("inertia = 0.51", "J = 0.51", "links.3.J: unknown key; did you mean 'inertia'?"),
    ('mass    = 17.0\ncentre  = "S3"', 'm = 17.0\ncentre  = "S3"', "links.3.m: unknown key; did you mean 'mass'?"),
    ("gravity = 9.81", "g = 9.81", "scene.g: unknown key; did you mean 'gravity'?"),
    ('locale  = "en"', 'language = "en"', "scene.language: unknown key; did you mean 'locale'?"),
    ("length  = 0.175", "r = 0.175", "driver.r: unknown key; did you mean 'length'?"),
    # The crank's length as l: was told "driver.length: is required but missing", the l left unexplained.
    ("length  = 0.175", "l = 0.175", "driver.l: unknown key; did you mean 'length'?"),
    # The moment of inertia about the centre as the textbooks letter it: was "unknown key" and nothing more.
    ("inertia = 0.51", "Js = 0.51", "links.3.Js: unknown key; did you mean 'inertia'?"),
    ("inertia = 0.51", "I_S = 0.51", "links.3.I_S: unknown key; did you mean 'inertia'?"),
    ("inertia = 0.51", "I = 0.51", "links.3.I: unknown key; did you mean 'inertia'?"),
    # 2.5 rev/s is 150 rev/min, exactly in binary.
    ("omega   = -17.0", "rps = 2.5",
     "driver.rps: unknown key; a speed in rev/s is given in rev/min as rpm: write rpm = 150.0"),
], ids=["center", "J", "m", "g", "language", "r", "l", "Js", "I_S", "I", "rps"])
def test_a_key_under_its_symbol_or_american_spelling_is_named_with_the_key(old, new, message) -> None:
    stage, error = first_error(changed(CRANK_ROCKER, old, new))
    assert (stage, str(error)) == ("load", message)


@pytest.mark.parametrize("fixture", ["slider_driven", "double_rocker_swing"])
def test_one_position_over_a_travel_or_a_swing_is_refused_naming_count(fixture) -> None:
    text = (FIXTURES / f"{fixture}.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^count\s*=.*$", "count = 1", text)
    text = re.sub(r"(?m)^plans\s*=.*$", "plans = [1]", text)
    stage, error = first_error(text)
    assert stage == "load" and str(error).startswith("positions.count: a ")
    assert "to the other, which takes at least 2 (got 1)" in str(error)


def test_driving_constant_in_a_linkage_scene_is_told_the_linkages_spelling() -> None:
    """The flywheel starter teaches driving = "constant"; a scene with a linkage writes constant = "driving"."""
    text = changed(SHAPER, "delta              = 0.05", 'delta              = 0.05\ndriving = "constant"')
    stage, error = first_error(text)
    assert stage == "load" and str(error).startswith("dynamics.driving: is for a scene without a linkage")
    assert str(error).endswith('leave it out, or leave out the linkage; with a linkage write constant = "driving"')


@pytest.mark.parametrize(("zeta", "percentage"), [(50.0, True), (1.5, False), (0.7, None), (0.1, None)])
def test_an_over_critical_damping_ratio_is_warned_of_and_a_large_one_asked_if_a_percentage(zeta, percentage) -> None:
    """f = 8 and delta = 1 are asked whether they are percentages; damping_ratio = 50 was taken as ζ = 50, with only
    the mounts' sag to hint at it.  ζ < 1 (0.7, an instrument's design damping) is a damping some mount may have: no
    word; ζ = 1 exactly is asked as a percentage (tests/test_unit_slip_probes.py)."""
    scene = graphplan.load_text(changed(starter("rotor"), "damping_ratio = 0.1 ", f"damping_ratio = {zeta}"))
    line = damping_warning(scene.vibration)
    if percentage is None:
        assert line is None
        return
    assert line.startswith(f"vibration.damping_ratio: ζ = {zeta:g} is over-critical (above 1)")
    assert line.endswith(f"; a percentage typed for a fraction? ({zeta:g} % is ζ = {zeta / 100:g})") == percentage


def test_the_damping_warning_is_among_what_check_and_run_tell() -> None:
    scene = graphplan.load_text(changed(starter("rotor"), "damping_ratio = 0.1 ", "damping_ratio = 50.0"))
    told = outcome_warnings(scene, ("vibration",), None)
    assert any(line.startswith("vibration.damping_ratio: ζ = 50 is over-critical") for line in told)


@pytest.mark.parametrize(("old", "new", "told"), [
    ("lines  = { ram = { through = [0.0, 0.64], angle = 0.0 } }", "lines  = { ram = { through = [0.0, 0.64] } }",
     "frame.lines.ram: no angle, so the guide is taken at 0°, along +x"),
    ('guide    = "ram"', "guide    = { through = [0.0, 0.64] }",
     "groups[1].guide: no angle, so the guide is taken at 0°, along +x"),
], ids=["frame-line", "group-guide"])
def test_a_guide_without_its_angle_is_told_it_runs_along_x(old, new, told) -> None:
    """The contract always writes a guide's angle and gives it no default: one left out runs along +x, another
    mechanism than the one meant, so check and run say so."""
    scene = graphplan.load_text(changed(SHAPER, old, new))
    assert guides_without_angle(scene) == [f"{told}: write angle = 0.0 if that is meant"]
    assert f"{told}: write angle = 0.0 if that is meant" in outcome_warnings(scene, (), None)


def test_a_triad_leg_guide_without_its_angle_is_told() -> None:
    text = starter("triad")
    lengths = next(line for line in text.splitlines() if line.startswith("lengths"))
    scene = graphplan.load_text(text.replace(lengths, lengths + "\nguides = { F = {} }", 1).replace(
        lengths, "lengths = " + lengths.split("=", 1)[1].split("]")[0].rsplit(",", 1)[0] + "]", 1))
    assert [line.split(":")[0] for line in guides_without_angle(scene)] == ["groups[0].guides.F"]


@pytest.mark.parametrize("kind", ["crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad"])
def test_the_starters_write_every_guides_angle(kind) -> None:
    assert guides_without_angle(graphplan.load_text(starter(kind))) == []


def test_a_huge_integer_is_told_by_its_digits_not_spelt_out() -> None:
    """positions.count = 10**400 from Python printed all 401 digits, hiding the message around them."""
    text = re.sub(r"(?m)^count\s*=.*$", f"count = {10 ** 400}", CRANK_ROCKER)
    stage, error = first_error(text)
    assert stage == "load" and str(error).endswith("(got an integer of 401 digits)")
    assert str(error).startswith("positions.count: must be <= ")


@pytest.mark.parametrize("size", ["A0", "a5", "А0"])
def test_a_paper_size_the_sheets_are_not_laid_out_on_is_told_so_not_offered_a4(size, tmp_path, capsys) -> None:
    from graphplan.cli import main

    stage, error = first_error(changed(CRANK_ROCKER, 'sheet              = "A1"', f'sheet = "{size}"'))
    assert (stage, error.where) == ("load", "drawing.sheet")
    assert "paper size the sheets are not laid out on: A1 is the largest" in str(error) or size == "a5"
    assert "paper size the sheets are not laid out on" in str(error) and "did you mean" not in str(error)
    scene = tmp_path / "scene.toml"
    scene.write_text(CRANK_ROCKER, encoding="utf-8")
    with pytest.raises(SystemExit):
        main(["run", str(scene), "--sheet", size, "--out", str(tmp_path / "out")])
    told = capsys.readouterr().err
    assert "paper size the sheets are not laid out on" in told and "did you mean" not in told
    assert not (tmp_path / "out").exists()


def test_a_sheet_name_mistyped_is_still_offered_the_one_meant() -> None:
    _, error = first_error(changed(CRANK_ROCKER, 'sheet              = "A1"', 'sheet = "A3x"'))
    assert "did you mean 'A3'?" in str(error)


def test_a_velocity_plan_listed_twice_is_refused_as_a_plan_sheet_listed_twice_is() -> None:
    text = changed(CRANK_ROCKER, "[positions]", "[positions]\nvelocity_plans = [2, 5, 2]")
    stage, error = first_error(text)
    assert (stage, error.where) == ("load", "positions.velocity_plans[2]")
    assert "already listed at positions.velocity_plans[0]" in str(error)


@pytest.mark.parametrize("given", [None, 123, [FIXTURES / "scotch_yoke.toml"]])
def test_load_given_no_path_says_what_it_takes(given) -> None:
    with pytest.raises(TypeError, match=r"load takes the path of a scene file.*got (NoneType|int|list)"):
        graphplan.load(given)


def test_sheets_asked_for_on_no_sheet_blame_the_option_that_said_none(tmp_path, capsys) -> None:
    from graphplan.cli import main
    from graphplan.run import run

    scene = tmp_path / "scene.toml"
    scene.write_text(CRANK_ROCKER, encoding="utf-8")
    assert 'sheet              = "A1"' in CRANK_ROCKER
    assert main(["run", str(scene), "--sheet", "none", "--only", "sheets", "--out", str(tmp_path / "out")]) == 2
    assert "'sheets' needs a sheet format: --sheet is \"none\"" in capsys.readouterr().err
    with pytest.raises(graphplan.SceneError, match='needs a sheet format: drawing.sheet is "none"'):
        run(graphplan.load_text(changed(CRANK_ROCKER, 'sheet              = "A1"', 'sheet = "none"')),
                      tmp_path / "out", only=["sheets"])
    assert not (tmp_path / "out").exists()


def test_a_slotted_lever_whose_crank_spans_the_pivots_is_told_why_its_lever_has_no_extremes() -> None:
    """lOA = lOC = 0.30 m: A's circle passes through C, and where A is at C (φ = 270° here, C straight below O)
    nothing fixes the lever's direction; the lever turns half a turn a cycle and flips back there, so it never
    reverses. The refusal named no cause. Solved alone there, the position is singular too: with A and C both at the
    origin the rounding was judged against a mechanism of their size (1e-16 m), and the lever was given the
    direction of the rounding noise without a word."""
    text = starter("slotted-lever")
    text = changed(text, "length  = 0.12 ", "length  = 0.30 ")
    text = changed(text, 'start       = "extreme"', "start = 0.0")
    text = changed(text, "during    = { from = 0.05, to = 0.95 }", 'during = "always"')
    scene = graphplan.load_text(text)
    assert abs(scene.frame_points["O"] - scene.frame_points["C"]) == pytest.approx(scene.driver.length)
    with pytest.raises(graphplan.GraphplanError, match="A passes over C"):
        graphplan.solve(scene, driver=[math.radians(270.0)])
    _, error = first_error(text)
    assert error.where == "positions.working"
    assert "never reverses its motion" in str(error)
    assert "its angle flips over by half a turn once a cycle (near φ = 270°)" in str(error)
    # A shorter crank swings the lever, which then has its extremes.
    assert graphplan.solve(graphplan.load_text(changed(text, "length  = 0.30 ", "length  = 0.12 "))) is not None


WHITWORTH_SPANNING = """\
[scene]
title = "Whitworth quick-return mechanism, its crank as long as the distance between its pivots"
[frame]
link = 1
points = { C = [0.0, 0.0], O = [0.0, 0.20] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.20
omega = 10.0
[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
offset = 0.0
[points]
D = { link = 4, from = "C", toward = "A", at = -0.15 }
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["D", "E"]
length = 0.45
assembly = "forward"
guide = { through = [0.0, 0.0], angle = 0.0 }
[positions]
count = 12
start = "extreme"
working = { link = 6, sense = "forward" }
"""


def test_a_slider_driven_off_a_lever_that_flips_over_is_told_the_lever_flips() -> None:
    """A Whitworth slider E driven through DE off the lever CA, the crank OA as long as OC: A passes over C at
    φ = 270° (C straight below O), where the lever's direction flips by half a turn, so the slider never reverses.
    The refusal looked only at the slider, which does not turn, and named no cause; it names the lever (not the block
    3 that turns with it) and the crank angle of the flip."""
    scene = graphplan.load_text(WHITWORTH_SPANNING)
    assert abs(scene.frame_points["O"] - scene.frame_points["C"]) == pytest.approx(scene.driver.length)
    _, error = first_error(WHITWORTH_SPANNING)
    assert error.where == "positions.working"
    assert str(error).startswith("positions.working: link 6 never reverses its motion, so it has no extreme position: "
                                 "the angle of link 4, which drives it, flips over by half a turn once a cycle "
                                 "(near φ = 270°), at a singular position")
    # With OC shorter than the crank the lever turns round smoothly, and the slider has its two extremes.
    assert graphplan.solve(graphplan.load_text(changed(WHITWORTH_SPANNING, "O = [0.0, 0.20]", "O = [0.0, 0.10]")))


@pytest.mark.parametrize("driver", [[1j], np.array([1j]), np.array([1 + 0j, 2.0])], ids=["list", "array", "real-as-complex"])
def test_complex_driver_values_are_refused_without_numpy_s_casting_warning(driver) -> None:
    import warnings

    scene = graphplan.load(FIXTURES / "ratchet_crank_rocker.toml")
    with warnings.catch_warnings(record=True) as printed:
        warnings.simplefilter("always")
        with pytest.raises(graphplan.SceneError) as caught:
            graphplan.solve(scene, driver=driver)
    assert caught.value.where == "driver" and "must be an array of numbers" in str(caught.value)
    assert [str(warning.message) for warning in printed] == []
