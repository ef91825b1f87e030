"""The efficiency over the cycle, η = A0/A = ∫Mb0 dφ / ∫Mb dφ, against closed forms of the massless central
slider-crank (crank r, rod l, rod angle β with sin β = r·sin φ / l, ω counter-clockwise), its piston forward
(φ from 180° to 360°) its working stroke, with the friction circle ρ at the crank's pivot O and f in the guide.

* A force P against the piston in the working stroke: the rod's force S = P/(cos β − f·|sin β|), and
  Mb = (P·r·|sin(φ + β)| + ρ·P)/(cos β − f·|sin β|) there, 0 in the idle stroke; without friction ∫Mb0 dφ = P·2r.
* P driving the piston on in the working stroke: S = P/(cos β + f·|sin β|), Mb = (ρ·P − P·r·|sin(φ + β)|)/(cos β +
  f·|sin β|); the loads give the driver P·2r without friction, and η = ∫Mb dφ / ∫Mb0 dφ.
* P always along −x (not resisting): it takes no work over a turn, and all the driver's work goes into friction.

The balancing moment jumps where the load's window opens and closes and where a pair's motion turns back, none
of which the positions hit (they start at 7.5°): the works must come out to the closed form's digits all the same.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scene_texts import central_slider_crank
from scipy.integrate import quad

from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.report import forces as force_report
from graphplan.report.results import results
from graphplan.scene import loads as scene_from_text

RADIUS, ROD, PUSH = 0.1, 0.4, 1000.0
JOURNAL_F, JOURNAL_RADIUS, GUIDE_F = 0.2, 0.05, 0.15
RHO = JOURNAL_F * JOURNAL_RADIUS
FRICTION = f"""
[[friction]]
joint = "O"
f = {JOURNAL_F}
radius = {JOURNAL_RADIUS}
[[friction]]
joint = "B"
links = [1, 4]
f = {GUIDE_F}
"""
PRESSING = 'angle = 180.0\nresisting = true\nduring = "working"'
DRIVING = 'angle = 0.0\nduring = "working"'
PUSHING = "angle = 180.0"


def scene_text(load: str, friction: str = FRICTION, locale: str = "en", omega: float = 10.0) -> str:
    return central_slider_crank(RADIUS, ROD, omega, named_guide=True, locale=locale) + f"""
[[loads]]
kind = "force"
link = 4
point = "B"
value = {PUSH}
{load}
[positions]
count = 24
start = 7.5
working = {{ link = 4, sense = "forward" }}
plans = [1]
{friction}
"""


def rod_angle(phi: float) -> float:
    return math.asin(RADIUS * math.sin(phi) / ROD)


def pressing_moment(phi: float) -> float:
    beta = rod_angle(phi)
    return (PUSH * RADIUS * abs(math.sin(phi + beta)) + RHO * PUSH) / (math.cos(beta) - GUIDE_F * abs(math.sin(beta)))


def driven_moment(phi: float) -> float:
    beta = rod_angle(phi)
    return (RHO * PUSH - PUSH * RADIUS * abs(math.sin(phi + beta))) / (math.cos(beta) + GUIDE_F * abs(math.sin(beta)))


def working_stroke_integral(moment) -> float:
    return quad(moment, math.pi, 2.0 * math.pi, epsabs=1e-12, epsrel=1e-13, limit=200)[0]


@pytest.mark.parametrize("omega", [10.0, -10.0])
def test_a_press_does_the_work_of_its_resistance_and_loses_the_friction_circle_and_guide_s_share(omega):
    """Turned clockwise the press is the mirror image of itself: the same works (a clockwise crank's press was taken
    for loads driving the driver)."""
    cycle = analyse(scene_from_text(scene_text(PRESSING, omega=omega))).cycle
    useful, driving = PUSH * 2.0 * RADIUS, working_stroke_integral(pressing_moment)
    assert cycle.without_friction == pytest.approx(useful, rel=1e-8)
    # Summed over even 1° steps across the jumps, A came out 2e-4 off; the jumps put in, to the closed form's digits.
    assert cycle.with_friction == pytest.approx(driving, rel=1e-7)
    assert cycle.efficiency == pytest.approx(useful / driving, rel=1e-7)
    assert cycle.friction == pytest.approx(driving - useful, rel=1e-6)
    assert not cycle.locked and not cycle.loads_drive


def test_the_cycle_s_works_do_not_move_with_a_finer_sweep():
    from graphplan.cycle_work import cycle_work

    analysis = analyse(scene_from_text(scene_text(PRESSING)))
    finer = cycle_work(analysis.mechanism, analysis.positions, analysis.friction, count=3600)
    assert analysis.cycle.with_friction == pytest.approx(finer.with_friction, rel=1e-7)


def test_loads_that_drive_the_driver_give_the_efficiency_as_the_work_taken_off_over_the_work_given():
    analysis = analyse(scene_from_text(scene_text(DRIVING)))
    cycle = analysis.cycle
    given, taken = PUSH * 2.0 * RADIUS, -working_stroke_integral(driven_moment)
    assert cycle.loads_drive
    assert -cycle.without_friction == pytest.approx(given, rel=1e-9)
    assert -cycle.with_friction == pytest.approx(taken, rel=1e-7)
    assert cycle.efficiency == pytest.approx(taken / given, rel=1e-7)
    sentence = force_report.cycle_efficiency_lines(analysis)[0]
    assert f"η = ∫Mb·dφ/∫Mb0·dφ = {force_report.number(taken / given, 4)}" in sentence


def test_the_cycle_table_says_where_its_efficiency_is_the_reverse_ratio_and_where_it_is_not_defined():
    """With P driving, the loads drive the crank all the working stroke, but within |sin(φ + β)| < ρ/r of the dead
    centres the journal's friction takes more than P gives there: the driver must drive it (η′ ≤ 0)."""
    analysis = analyse(scene_from_text(scene_text(DRIVING)))
    phi = np.radians(7.5 + 15.0 * np.arange(24))
    moments = np.array([driven_moment(angle) for angle in phi])
    working = np.sin(phi) < 0
    numbers = analysis.positions.numbers
    reverse = ", ".join(str(numbers[i]) for i in np.flatnonzero(working & (moments < 0)))
    held = ", ".join(str(numbers[i]) for i in np.flatnonzero(working & (moments > 0)))
    assert held and reverse
    notes = force_report.cycle_notes(analysis)

    def at(numbers: str) -> str:   # one position is named in the singular
        return f"At position{'s' if ',' in numbers else ''} {numbers}"

    assert notes == [(f"{at(reverse)} the loads drive the driver (Mb0 and Mb against its motion): η there "
                      "is the ratio Mb/Mb0."),
                     (f"{at(held)} the loads would drive the mechanism, but the friction holds them and the "
                      "driver has to drive it: the mechanism locks itself against its loads driving it (η′ ≤ 0), and η "
                      "is not defined (—).")]
    assert all(note in force_report.markdown(analysis) for note in notes)
    # A press has neither: every position passes power on, or the loads take none.
    assert force_report.cycle_notes(analyse(scene_from_text(scene_text(PRESSING)))) == []


def test_a_load_that_takes_no_work_over_the_turn_leaves_the_friction_all_the_driver_s_work():
    analysis = analyse(scene_from_text(scene_text(PUSHING, friction=FRICTION.split("[[friction]]")[0]
                                                  + '[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 0.1')))
    cycle = analysis.cycle

    def moment(phi: float) -> float:
        beta = rod_angle(phi)
        piston = -math.copysign(1.0, math.sin(phi + beta))
        return -PUSH * RADIUS * math.sin(phi + beta) / (math.cos(beta) - 0.1 * piston * abs(math.sin(beta)))

    driving = sum(quad(moment, low, high, epsabs=1e-12, epsrel=1e-13)[0]
                  for low, high in ((0.0, math.pi), (math.pi, 2.0 * math.pi)))
    assert cycle.without_friction == 0.0 and cycle.efficiency == 0.0
    assert cycle.with_friction == pytest.approx(driving, rel=1e-7)
    assert "the efficiency over the cycle η = 0." in force_report.cycle_efficiency_lines(analysis)[0]


def test_a_mechanism_that_locks_on_the_way_has_no_efficiency_over_the_cycle(tmp_path):
    """f = 3.9 in the guide locks the piston for 13° about φ = 270° with the positions either side moving."""
    text = scene_text(PRESSING, friction='[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 3.9')
    analysis = analyse(scene_from_text(text))
    assert analysis.locked_spans and not analysis.with_friction.locked.any()
    cycle = analysis.cycle
    assert cycle.locked and math.isnan(cycle.with_friction) and math.isnan(cycle.efficiency)
    assert cycle.without_friction == pytest.approx(PUSH * 2.0 * RADIUS, rel=1e-9)
    (sentence,) = force_report.cycle_efficiency_lines(analysis)
    assert "no efficiency over the cycle" in sentence and "η =" not in sentence
    scene = tmp_path / "locks.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "forces"]) == 0
    written = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["cycle_efficiency"]
    assert written["self_locking"] and written["efficiency"] is None and written["work_with_friction"] is None


def test_results_forces_md_and_the_note_give_the_efficiency_over_the_cycle_in_each_language(tmp_path):
    useful, driving = PUSH * 2.0 * RADIUS, working_stroke_integral(pressing_moment)
    eta = force_report.number(useful / driving, 4)
    said = {"en": f"η = Au/Ab = {eta}", "ru": f"КПД за цикл η = Aпс/Aдв = {eta.replace('.', ',')}",
            "zh": f"一个运动循环的机械效率 η = Wr/Wb = {eta}"}
    for locale, words in said.items():
        scene = tmp_path / f"{locale}.toml"
        scene.write_text(scene_text(PRESSING, locale=locale), encoding="utf-8")
        out = tmp_path / locale
        assert main(["run", str(scene), "--out", str(out), "--only", "forces,note"]) == 0
        assert words in (out / "forces.md").read_text(encoding="utf-8")
        assert words in (out / "note.md").read_text(encoding="utf-8")
        works = {"en": ("A", "u", "b", "f"), "ru": ("A", "пс", "дв", "тр"), "zh": ("W", "r", "b", "f")}[locale]
        html = (out / "note.html").read_text(encoding="utf-8")
        assert all(f"{works[0]}<sub>{index}</sub> = " in html for index in works[1:])
    written = results(analyse(scene_from_text(scene_text(PRESSING))))["cycle_efficiency"]
    assert written["work_without_friction"] == pytest.approx(useful, rel=1e-9)
    assert written["work_with_friction"] == pytest.approx(driving, rel=1e-7)
    assert written["efficiency"] == pytest.approx(useful / driving, rel=1e-7)
    assert written["self_locking"] is False


def test_without_friction_there_is_no_efficiency_over_the_cycle_to_give():
    analysis = analyse(scene_from_text(scene_text(PRESSING, friction="")))
    assert analysis.cycle is None and force_report.cycle_efficiency_lines(analysis) == []
    assert "cycle_efficiency" not in results(analysis)


def test_the_balancing_plot_shades_a_lock_and_keeps_its_axis_to_the_loads_that_move():
    """f = 3.9 in the guide locks the piston for φ from 180° + e to 360° − e, sin e = (l/r)·sin(arctan 1/f): toward
    the lock the moment with friction ran to 1e5 N·m on the axis and every other value lay flat on zero."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import pyplot

    from graphplan.report.figures import LOCKED_REACH, _balancing_figure

    f = 3.9
    analysis = analyse(scene_from_text(scene_text(PRESSING, friction=f'[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = {f}')))
    figure = _balancing_figure(analysis)
    (plot,) = figure.axes
    edge = math.degrees(math.asin(ROD / RADIUS * math.sin(math.atan(1.0 / f))))
    (shade,) = [patch for patch in plot.patches if patch.get_label() == "self-locking"]
    low, high = shade.get_x(), shade.get_x() + shade.get_width()
    # From the first position (7.5°), to the half degree the sweep shades to.
    assert (low, high) == pytest.approx((180.0 + edge - 7.5, 360.0 - edge - 7.5), abs=0.6)
    phi = np.linspace(0.0, 2.0 * math.pi, 3601)
    frictionless = [PUSH * RADIUS * abs(math.sin(angle + rod_angle(angle))) / math.cos(rod_angle(angle))
                    for angle in phi if math.sin(angle) < 0]
    bottom, top = plot.get_ylim()
    assert max(frictionless) < top <= 1.1 * LOCKED_REACH * max(frictionless) and bottom < 0.0
    pyplot.close(figure)


def test_a_scene_without_friction_is_analysed_without_importing_scipy_s_integrators():
    """The cycle's works imported scipy.integrate with the analysis, for every scene: a cold run of the bundled
    scene, which has no friction, took a fifth longer (bench/cold_run.py)."""
    import subprocess
    import sys

    code = ("import sys, graphplan; from graphplan.analysis import analyse; "
            "analyse(graphplan.load('fixtures/ratchet_crank_rocker.toml')); print('scipy.integrate' in sys.modules)")
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert found.stdout.strip() == "False"
