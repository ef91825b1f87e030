"""A force typed in kN or a moment in kN·m where the scene takes N and N·m: the engine's 4.5 kN gas force typed 4.5
ran as a force of 4.5 N, which the piston's own inertia force dwarfs three hundred times, and every reaction and
the balancing moment came out of the inertia alone, without a word.  Each such load is told, at its key, with the
loads of its own link it is weighed against and the value meant; the note says so under its initial data."""

from __future__ import annotations

import dataclasses
import math
import re
from pathlib import Path

import pytest

from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.report.note import note_markdown
from graphplan.scene import loads

# Scenes given their slips on purpose: scene.analyse() warns of each with a UserWarning, as the command line does,
# and these tests read the analysis's warnings themselves.
pytestmark = pytest.mark.filterwarnings(r"ignore:[a-z]+(-[a-z]+)+\b:UserWarning")

ENGINE = Path("fixtures/engine_slider_crank.toml").read_text(encoding="utf-8")
RATCHET = Path("fixtures/ratchet_crank_rocker.toml").read_text(encoding="utf-8")
GAS_FORCE = "value     = 4500.0        # N, mean gas force of the expansion stroke"


def _edited(text: str, old: str, new: str) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


def _told(text: str) -> list[str]:
    return [warning.detail for warning in loads(text).analyse().warnings if warning.code == "load-in-kn"]


def test_a_gas_force_typed_in_kilonewtons_is_told_against_the_pistons_inertia_force():
    """The piston's inertia force is largest at top dead centre, the first position: m·ω²·r·(1 + r/l) by the
    slider-crank's closure differentiated twice, 0.9 kg at 1500 rpm, r = 0.05 m, l = 0.19 m."""
    (detail,) = _told(_edited(ENGINE, GAS_FORCE, "value     = 4.5"))
    omega, r, length, mass = 1500.0 * math.pi / 30.0, 0.05, 0.19, 0.9
    inertia = mass * omega ** 2 * r * (1.0 + r / length)
    share, weight, told_inertia = re.fullmatch(
        r"loads\[0\]\.value = 4\.5 N is ([\d.]+) % of the largest load link 4 carries of itself \(its weight m·g "
        r"([\d.]+) N, its inertia force m·aS up to ([\d.]+) N\): kN typed for N\? 4\.5 kN is loads\[0\]\.value = "
        r"4500: the scene's forces are in N, its moments in N·m", detail).groups()
    assert float(told_inertia) == pytest.approx(inertia, rel=5e-3)
    assert float(weight) == pytest.approx(mass * 9.81, rel=5e-3)
    assert float(share) == pytest.approx(100.0 * 4.5 / inertia, rel=2e-2)


def test_a_moment_typed_in_kilonewton_metres_is_told():
    """The ratchet's 1500 N·m on its rocker typed 1.5: under 3 % of the rocker's own weight's moment over B–C."""
    (detail,) = _told(_edited(RATCHET, "value     = 1500.0", "value     = 1.5"))
    assert detail.startswith("loads[0].value = 1.5 N·m is ")
    assert "its weight's moment m·g·l " in detail and "l = 0.325 m its span (B–C)" in detail
    assert detail.endswith("kN·m typed for N·m? 1.5 kN·m is loads[0].value = 1500: the scene's forces are in N, its "
                           "moments in N·m")


def test_a_diagram_typed_in_kilonewtons_is_told_by_its_largest_value():
    diagram = 'diagram   = [[0.0, 4.5], [0.5, 2.0], [1.0, 0.5]]'
    (detail,) = _told(_edited(_edited(ENGINE, GAS_FORCE, diagram), 'during    = "working"\n', ""))
    assert detail.startswith("loads[0].diagram with values up to 4.5 N is ")
    assert "4.5 kN is its values × 1000" in detail


@pytest.mark.parametrize(("value", "told"), [("4500.0", False), ("100.0", False), ("60.0", True), ("0.0", False)],
                         ids=["as given", "a fourteenth of the inertia force", "a twenty-third", "none"])
def test_a_load_its_link_does_not_dwarf_twenty_times_is_not_told(value, told):
    assert bool(_told(_edited(ENGINE, GAS_FORCE, f"value     = {value}"))) is told


def test_a_load_a_thousand_times_too_small_even_in_kilonewtons_is_not_said_to_be_in_them():
    (detail,) = _told(_edited(ENGINE, GAS_FORCE, "value     = 1e-06"))
    assert detail.startswith("loads[0].value = 1e-06 N is ")
    assert detail.endswith("): no unit explains it: a mistaken value?: the scene's forces are in N, its moments in N·m")


def test_masses_in_grams_are_told_instead():
    """The piston typed as 900 g: its inertia force 1000 times too large would make the true gas force a slip."""
    text = _edited(ENGINE, "mass    = 0.9\n", "mass    = 900.0\n")
    warnings = loads(text).analyse().warnings
    assert [warning.code for warning in warnings if warning.code in ("masses-in-grams", "load-in-kn")] == \
           ["masses-in-grams"]


def test_a_speed_typed_in_rpm_is_told_instead():
    """The ratchet's crank at 1450 typed for its 17 rad/s: the rocker's inertia moment J·ε, some seven thousand times
    too large, dwarfed its true 1500 N·m, which was told as typed in kN·m, to be multiplied by 1000."""
    text = _edited(RATCHET, "omega   = -17.0 ", "omega   = -1450.0 ")
    warnings = loads(text).analyse().warnings
    assert [warning.code for warning in warnings if warning.code in ("speed-in-rpm", "load-in-kn")] == \
           ["speed-in-rpm"]
    # At its speed in rad/s the same moment typed in kN·m is told still.
    assert _told(_edited(text.replace("omega   = -1450.0 ", "omega   = -17.0 "), "value     = 1500.0",
                         "value     = 1.5"))


def test_a_load_only_an_absurd_motion_dwarfs_is_told_the_motion_may_be_the_slip():
    """The ratchet's crank given epsilon = 1e9 rad/s²: the rocker's J·ε dwarfed its true 1500 N·m, which was told
    only as "a mistaken value?".  Its weight's moment alone does not dwarf it, so the motion is asked of too."""
    (detail,) = _told(_edited(RATCHET, "epsilon = 0.0", "epsilon = 1e9"))
    assert detail.startswith("loads[0].value = 1500 N·m is ")
    assert detail.endswith("no unit explains it: a mistaken value?; or driver.omega or driver.epsilon given too "
                           "large, which the inertia grows with?: the scene's forces are in N, its moments in N·m")


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_note_says_so_under_its_initial_data(locale):
    scene = loads(_edited(ENGINE, GAS_FORCE, "value     = 4.5"))
    note = note_markdown(analyse(dataclasses.replace(scene, locale=locale)))
    said = strings(locale)["note_warning_load_in_kn"]
    assert said in note and note.index(said) < note.index("\n## 3")
    assert said not in note_markdown(analyse(dataclasses.replace(loads(ENGINE), locale=locale)))


FIXTURES = sorted(Path("fixtures").glob("*.toml"))


@pytest.mark.parametrize("path", FIXTURES, ids=lambda path: path.stem)
def test_every_fixture_s_load_typed_in_kilonewtons_is_told(path):
    """Each fixture's force or moment divided by 1000, as typed in kN or kN·m: the same warning, at its key, every
    time (the fixtures' loads, as given, are told nothing: test_more_unit_slips)."""
    text = path.read_text(encoding="utf-8")
    given = [spec for spec in loads(text).loads if spec.value and not spec.diagram]
    if not given:
        pytest.skip("no load with a value")
    typed = list(re.finditer(r"(?m)^(value\s*=\s*)([-\d.e]+)", text))
    for index, spec in enumerate(given):
        # Loads of one value (the V-twin's two cylinders) are told apart by their order in the file.
        same = [match for match in typed if float(match[2]) == spec.value]
        assert len(same) == sum(other.value == spec.value for other in given)
        line = same[sum(other.value == spec.value for other in given[:index])]
        slipped = text[:line.start(2)] + repr(spec.value / 1000.0) + text[line.end(2):]
        (detail,) = _told(slipped)
        assert detail.startswith(f"{spec.where}.value = {spec.value / 1000.0:g} N")
        assert f"is {spec.where}.value = {spec.value:g}:" in detail
