"""A spring between two points: ``[[loads]] kind = "force"`` with ``along = "D"``, ``stiffness`` and ``free_length``.

Its force at each position is −k·(L − L0)·e, e the unit vector from D to its point and L their distance: stretched
past its free length it pulls its point toward D, squeezed short of it it pushes it away.  Nothing here reads
graphplan's loads: L and e are worked out in the test from the analytic positions (``motion``'s r), and

* the balancing moment of the linear system at every position is that of virtual work, Mb = −F·vB/ω1;
* the spring is conservative: its work over a whole turn is zero, and the dynamics' reduced moment of it, integrated
  over the crank's angle from the first sample, is −ΔU with U = ½·k·(L − L0)² (trapezoids on a fine sweep);
* the force polygons and Zhukovsky's lever at the plan positions give the linear system's balancing moment, and the
  polygons its reactions;
* a plain force along D of the value −k·(L − L0) the test works out at one position gives the same reactions there;
* forces.md writes k·(L − L0) with k, L and L0; a spring has no load diagram;
* each key a spring cannot take is refused at its own key path.
"""

from __future__ import annotations

import functools
import re

import numpy as np
import pytest
from test_force_along_a_turning_line import CRANK_ROCKER, SLIDER_CRANK, _with_loads

import graphplan
from graphplan import load_diagrams
from graphplan.analysis import analyse
from graphplan.dynamics import equivalent_model_of
from graphplan.errors import SceneError
from graphplan.loads import given_value, motion_state
from graphplan.report.forces import external_load_lines
from graphplan.scene import loads as scene_of_text

# The crank-rocker with a frame pin D (and E on the coupler) and the slider-crank whose slider is held from D, above
# and behind the guide (L runs from some 0.43 m to 0.6 m, so that a free length of 0.5 m has it squeezed and
# stretched), of the force along a turning line; no gravity and no masses, so that the loads' power is the spring's
# alone.  Each case: its scene and its spring as (link, point, the point it is along, stiffness N/m, free length m).
CASES = {
    "stretched spring from the frame on the rocker": (CRANK_ROCKER, (4, "B", "D", 4000.0, 0.1)),
    "squeezed spring from the frame on the coupler": (CRANK_ROCKER, (3, "E", "D", 2500.0, 0.6)),
    "spring on the slider squeezed and stretched": (SLIDER_CRANK, (4, "B", "D", 3000.0, 0.5)),
}


def _spring(link: int, point: str, far: str, stiffness: float, free_length: float, extra: str = "") -> str:
    return (f'\n[[loads]]\nkind = "force"\nlink = {link}\npoint = "{point}"\nalong = "{far}"\n'
            f"stiffness = {stiffness!r}\nfree_length = {free_length!r}\n{extra}")


def _text(case: str, count: int | None = None) -> str:
    base, spring = CASES[case]
    text = _with_loads(base, _spring(*spring))
    return text if count is None else text.replace("count = 12", f"count = {count}")


@functools.cache
def analysis(case: str):
    return analyse(scene_of_text(_text(case)))


def _xy(array) -> np.ndarray:
    array = np.asarray(array, dtype=float)
    return array[..., 0] + 1j * array[..., 1]


def _spring_force(case: str, motion) -> tuple[np.ndarray, np.ndarray]:
    """The spring's force (as x + iy, N) and its length L (m) at each position of ``motion``: −k·(L − L0)·e."""
    _, (_, point, far, stiffness, free_length) = CASES[case]
    reach = _xy(motion.point(point).r) - _xy(motion.point(far).r)
    length = np.abs(reach)
    return -stiffness * (length - free_length) * reach / length, length


def _power(force: np.ndarray, velocity: np.ndarray) -> np.ndarray:
    return (np.conj(force) * velocity).real


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_balancing_moment_at_every_position_is_that_of_virtual_work(case):
    found = analysis(case)
    point = CASES[case][1][1]
    force, _ = _spring_force(case, found.motion)
    expected = -_power(force, _xy(found.motion.point(point).v)) / found.scene.driver.omega
    scale = float(np.max(np.abs(expected)))
    assert scale > 1.0
    np.testing.assert_allclose(found.equilibrium.balancing, expected, rtol=0, atol=1e-9 * scale)


def test_the_cases_hold_a_stretched_a_squeezed_and_a_crossing_spring():
    """The cases are what their names say: the sign convention is tried both ways, and through L = L0."""
    lengths = {case: _spring_force(case, analysis(case).motion)[1] - CASES[case][1][4] for case in CASES}
    assert np.all(lengths["stretched spring from the frame on the rocker"] > 0)
    assert np.all(lengths["squeezed spring from the frame on the coupler"] < 0)
    crossing = lengths["spring on the slider squeezed and stretched"]
    assert np.any(crossing > 0) and np.any(crossing < 0)


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_spring_has_no_value_to_take_for_a_force_and_its_given_value_is_its_length_s(case):
    """A spring stored value = 0.0, which code reading ``value`` without asking whether the load is a spring would
    take for a force of 0 N: it holds None, which no sum takes, and :func:`graphplan.loads.given_value` gives its
    force along D at each position, −k·(L − L0), as any other load's value."""
    found = analysis(case)
    (spec,) = found.scene.loads
    assert spec.spring and spec.value is None
    with pytest.raises(TypeError):
        abs(spec.value)
    _, length = _spring_force(case, found.motion)
    stiffness, free_length = CASES[case][1][3:]
    np.testing.assert_allclose(given_value(spec, motion_state(found.motion)), -stiffness * (length - free_length),
                               rtol=1e-12, atol=1e-9)
    plain = scene_of_text(_with_loads(CASES[case][0], '\n[[loads]]\nkind = "force"\nlink = 2\npoint = "A"\n'
                                      'angle = 30.0\nvalue = -125.0\n'))
    assert given_value(plain.loads[0], motion_state(found.motion)) == -125.0


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_stretched_spring_pulls_its_point_toward_the_far_end_and_a_squeezed_one_pushes_it_away(case):
    found = analysis(case)
    (_, point, far, _, free_length) = CASES[case][1]
    (load,) = [each for each in found.loads if each.name.startswith("F")]
    reach = _xy(found.motion.point(point).r) - _xy(found.motion.point(far).r)
    outward = (np.conj(reach) * np.asarray(load.force)).real
    stretched = np.abs(reach) > free_length
    assert np.all(outward[stretched] < 0) and np.all(outward[~stretched] > 0)


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_spring_s_work_is_minus_the_rise_of_its_energy_and_none_over_a_turn(case):
    scene = scene_of_text(_text(case))
    model = equivalent_model_of(scene, count=720, constant="none")
    motion = graphplan.solve(scene, driver=np.asarray(model.driver))
    (_, point, _, stiffness, free_length) = CASES[case][1]
    force, length = _spring_force(case, motion)
    # The reduced moment is the spring's power over the crank's speed: ∫ M dψ is its work.
    expected = _power(force, _xy(motion.point(point).v)) / abs(scene.driver.omega)
    np.testing.assert_allclose(model.moment, expected, rtol=0, atol=1e-9 * float(np.max(np.abs(expected))))
    angle = np.asarray(model.coordinate)
    assert angle[-1] - angle[0] == pytest.approx(2 * np.pi)
    steps = np.diff(angle) * (model.moment[1:] + model.moment[:-1]) / 2
    work = np.concatenate(([0.0], np.cumsum(steps)))
    energy = 0.5 * stiffness * (length - free_length) ** 2
    # The trapezoids' error is some (Δψ)²/12 · ∫|M''| dψ: under 1e-4 of the energy's swing at 720 steps.
    swing = float(np.max(energy) - np.min(energy))
    assert swing > 1.0
    np.testing.assert_allclose(work, -(energy - energy[0]), rtol=0, atol=1e-4 * swing)
    assert abs(work[-1]) <= 1e-6 * swing
    assert abs(float(model.integral(model.moment)[-1])) <= 1e-6 * swing


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_polygons_and_the_lever_agree_with_the_linear_system(case):
    found = analysis(case)
    drawn = [plan for plan in found.plans if plan.forces is not None]
    assert len(drawn) == 2
    scale = float(np.max(np.abs(found.equilibrium.balancing)))
    for plan in drawn:
        exact = float(found.equilibrium.balancing[plan.index])
        assert plan.forces.balancing == pytest.approx(exact, abs=1e-7 * scale), plan.number
        assert plan.lever.balancing == pytest.approx(exact, abs=1e-7 * scale), plan.number
        for reaction in plan.forces.reactions.values():
            solved = complex(found.equilibrium.reaction(reaction.name).force[plan.index])
            assert abs(reaction.force - solved) <= 1e-7 * max(abs(solved), 1.0), (plan.number, reaction.name)


@pytest.mark.parametrize("case", sorted(CASES))
@pytest.mark.parametrize("index", [0, 7])
def test_a_plain_force_of_the_spring_s_value_there_gives_the_same_reactions(case, index):
    spring = analysis(case)
    base, (link, point, far, stiffness, free_length) = CASES[case]
    length = _spring_force(case, spring.motion)[1][index]
    value = float(-stiffness * (length - free_length))
    plain = analyse(scene_of_text(_with_loads(base, f'\n[[loads]]\nkind = "force"\nlink = {link}\npoint = "{point}"'
                                                    f'\nalong = "{far}"\nvalue = {value!r}\n')))
    assert plain.equilibrium.balancing[index] == pytest.approx(spring.equilibrium.balancing[index], rel=1e-12)
    for reaction in spring.equilibrium.reactions:
        there = complex(plain.equilibrium.reaction(reaction.name).force[index])
        assert abs(complex(reaction.force[index]) - there) <= 1e-9 * abs(there), reaction.name


def test_forces_md_writes_k_times_the_stretch_with_its_numbers():
    case = "stretched spring from the frame on the rocker"
    found = analysis(case)
    plan = next(plan for plan in found.plans if plan.forces is not None)
    (line,) = [line for line in external_load_lines(found, plan) if "F4" in line]
    written = re.search(r"k·\(L − L0\) = 4000 N/m · \(([\d.]+) m − 0\.1 m\) = ([\d.]+) N; stretched, it pulls B "
                        r"toward D: ", line)
    assert written, line
    length = _spring_force(case, found.motion)[1][plan.index]
    assert float(written.group(1)) == pytest.approx(length, rel=1e-4)
    assert float(written.group(2)) == pytest.approx(4000.0 * (length - 0.1), rel=1e-4)
    assert "along the line DB" in line


def test_forces_md_writes_a_squeezed_spring_pushing_its_point_away():
    case = "squeezed spring from the frame on the coupler"
    found = analysis(case)
    plan = next(plan for plan in found.plans if plan.forces is not None)
    (line,) = [line for line in external_load_lines(found, plan) if "F3" in line]
    length = _spring_force(case, found.motion)[1][plan.index]
    written = re.search(r"\(([\d.]+) m − 0\.6 m\) = −([\d.]+) N; squeezed, it pushes E away from D: ", line)
    assert written, line
    assert float(written.group(2)) == pytest.approx(2500.0 * (0.6 - length), rel=1e-4)


@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_forces_md_writes_the_spring_in_the_scene_s_language(locale):
    text = _text("stretched spring from the frame on the rocker").replace("[scene]", f'[scene]\nlocale = "{locale}"')
    found = analyse(scene_of_text(text))
    plan = next(plan for plan in found.plans if plan.forces is not None)
    (line,) = [line for line in external_load_lines(found, plan) if "F4" in line]
    assert "k·(L − L0) = 4000" in line and "DB" in line and "External" not in line


def test_a_spring_alone_has_no_load_diagram_and_beside_a_windowed_load_is_left_out_of_it():
    alone = analysis("stretched spring from the frame on the rocker")
    assert "a spring acts always" in load_diagrams.unavailable(alone)
    text = _text("stretched spring from the frame on the rocker").replace(
        "plans = [2, 7]", 'plans = [2, 7]\nworking = { link = 4, sense = "ccw" }')
    text = _with_loads(text, '\n[[loads]]\nkind = "moment"\nlink = 4\nvalue = 40.0\nresisting = true\n'
                             'during = "working"\n')
    found = analyse(scene_of_text(text))
    assert load_diagrams.unavailable(found) is None
    (diagram,) = load_diagrams.of_analysis(found)
    assert [load.name for load in diagram.loads] == ["M4.2"]


def test_a_spring_is_sorted_apart_from_a_cylinder_on_its_line():
    """A cylinder and a spring along one line are two forces, not one given over several strokes: each is sorted by
    its own work.  Over a turn both do none (a force of set value along a line from a frame point does F·ΔL), so
    each goes with the weights on its own."""
    text = _with_loads(_text("stretched spring from the frame on the rocker"),
                       '\n[[loads]]\nkind = "force"\nlink = 4\npoint = "B"\nalong = "D"\nvalue = 300.0\n')
    model = equivalent_model_of(scene_of_text(text), constant="none")
    assert model.driving_loads == ()
    assert sorted(load.loads for load in model.moved) == [("loads[0]",), ("loads[1]",)]
    assert all(load.work == 0.0 for load in model.moved)


def _swinging(stiffness: float, free_length: float) -> str:
    """The crank-rocker's crank rocking over 80°, a spring from the frame on the rocker, a resistance on it."""
    text = CRANK_ROCKER.replace("omega = 12.0", "omega = -3.0\nswing = [120.0, 40.0]")
    text = text.replace("plans = [2, 7]", 'plans = [2, 7]\nworking = { link = 4, sense = "cw" }')
    text = _with_loads(text, _spring(4, "B", "D", stiffness, free_length)
                       + '\n[[loads]]\nkind = "moment"\nlink = 4\nvalue = 2.0\nresisting = true\n')
    return text + "\n[dynamics]\ncount = 81\n"


def test_a_spring_that_gives_work_over_a_swing_goes_with_the_weights_all_the_same():
    """Squeezed (L0 = 1 m) and let out over the swing, the spring gives work; it is the machine's own, as a weight
    is, and is not made a driving load that a constant driving moment would stand in for."""
    scene = scene_of_text(_swinging(1000.0, 1.0))
    model = equivalent_model_of(scene, constant="none")
    motion = graphplan.solve(scene, driver=np.asarray(model.driver))
    length = np.abs(_xy(motion.point("B").r) - _xy(motion.point("D").r))
    energy = 0.5 * 1000.0 * (length - 1.0) ** 2
    given = float(energy[0] - energy[-1])
    assert given > 10.0
    assert model.driving_loads == ()
    (moved,) = model.moved
    assert moved.loads == ("loads[0]",) and moved.work == pytest.approx(given, rel=1e-6)


@pytest.mark.parametrize(("locale", "said"), [
    ("en", "The spring F4.1 is counted with the resistances, as the weights are: its work over the swing, A = "),
    ("ru", "Пружина F4.1 отнесена к силам сопротивления, как и силы тяжести: её работа за качание A = "),
    ("zh", "弹簧 F4.1 与重力一样计入阻力：其在整个摆角内的功 W = "),
])
def test_the_note_says_a_spring_goes_with_the_weights(tmp_path, locale, said):
    from graphplan.cli import main

    scene = tmp_path / "spring.toml"
    scene.write_text(_swinging(1000.0, 1.0).replace("[scene]", f'[scene]\nlocale = "{locale}"'), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    note = (out / "note.md").read_text(encoding="utf-8")
    assert said in note
    assert "F4.1" in note and "задана как движущая" not in note and "given as a driving load" not in note


def _refused(extra: str, kind: str = "force") -> SceneError:
    text = _with_loads(CRANK_ROCKER, f'\n[[loads]]\nkind = "{kind}"\nlink = 4\n{extra}\n')
    with pytest.raises(SceneError) as caught:
        scene_of_text(text)
    return caught.value


_SPRING = 'point = "B"\nalong = "D"\nstiffness = 4000.0\nfree_length = 0.1'


@pytest.mark.parametrize(("extra", "where", "told"), [
    (_SPRING + "\nvalue = 300.0", "loads[0].value", "leave value out"),
    ('point = "B"\nalong = "D"\nstiffness = 4000.0', "loads[0].free_length", "is required but missing"),
    ('point = "B"\nalong = "D"\nfree_length = 0.1', "loads[0].stiffness", "is required but missing"),
    ('point = "B"\nangle = 30.0\nstiffness = 4000.0\nfree_length = 0.1', "loads[0].along", "in place of angle"),
    ('point = "B"\nstiffness = 4000.0\nfree_length = 0.1', "loads[0].along", "is required but missing"),
    (_SPRING + "\nresisting = true", "loads[0].resisting", "sense is its length's"),
    (_SPRING + '\nduring = "working"', "loads[0].during", "acts always"),
    (_SPRING + "\ndiagram = [[0.0, 100.0], [1.0, 200.0]]", "loads[0].diagram", "acts always"),
    (_SPRING + '\nstroke = { link = 4, sense = "ccw" }', "loads[0].stroke", "acts always"),
    ('point = "B"\nalong = "D"\nstiffness = 0.0\nfree_length = 0.1', "loads[0].stiffness", "(got 0"),
    ('point = "B"\nalong = "D"\nstiffness = -4000.0\nfree_length = 0.1', "loads[0].stiffness", "(got -4000"),
    ('point = "B"\nalong = "D"\nstiffness = 4000.0\nfree_length = -0.1', "loads[0].free_length", "(got -0.1"),
], ids=["value", "no free length", "no stiffness", "angle", "no along", "resisting", "during", "diagram", "stroke",
        "zero stiffness", "negative stiffness", "negative free length"])
def test_what_a_spring_cannot_take_is_refused_at_its_own_key(extra, where, told):
    error = _refused(extra)
    assert error.where == where, str(error)
    assert told in str(error), str(error)


def test_a_spring_on_a_moment_is_refused_at_its_stiffness():
    error = _refused("stiffness = 4000.0\nfree_length = 0.1", kind="moment")
    assert error.where == "loads[0].stiffness" and "kind = \"force\"" in str(error)


def test_a_free_length_of_zero_is_a_spring_that_always_pulls():
    """L0 = 0 (a zero-length spring, as a counterbalance's is drawn) is allowed: its force is k·L toward D."""
    text = _with_loads(CRANK_ROCKER, _spring(4, "B", "D", 1000.0, 0.0))
    found = analyse(scene_of_text(text))
    reach = _xy(found.motion.point("B").r) - _xy(found.motion.point("D").r)
    (load,) = [each for each in found.loads if each.name == "F4"]
    np.testing.assert_allclose(np.asarray(load.force), -1000.0 * reach, rtol=1e-12)


@pytest.mark.parametrize(("free_length", "told"), [
    (500.0, "mm typed for m? 500 mm is loads[0].free_length = 0.5"),
    (5e6, "no unit explains it: a mistaken value?"),
    (0.5, None),
    (2.0, None),  # squeezed to 0.215–0.302 of L0: past a coil spring's solid length, but told only past a fifth
], ids=["in millimetres", "mistaken", "as meant", "squeezed hard"])
def test_a_free_length_typed_in_millimetres_is_warned_of(free_length, told):
    """The slider-crank's spring from D to B, 0.43–0.6 m long, given the free length 0.5 m as 500: squeezed by
    499.5 m, its force dwarfs every load, with no word of why.  The lengths are worked out here from the positions."""
    found = analyse(scene_of_text(_with_loads(SLIDER_CRANK, _spring(4, "B", "D", 3000.0, free_length))))
    warnings = [warning.detail for warning in found.warnings if warning.code == "free-length-in-mm"]
    if told is None:
        assert not warnings
        return
    length = np.abs(_xy(found.motion.point("B").r) - _xy(found.motion.point("D").r))
    (detail,) = warnings
    from graphplan.render.numerals import number  # the warnings' way of writing numbers, not of working them out

    assert detail.startswith(f"loads[0].free_length = {free_length:g} m is {number(free_length / length.max(), 3)} times "
                             f"the longest the spring from D to B gets ({length.min():.3g}–{length.max():.3g} m over "
                             "the positions), squeezed far past any spring's solid length")
    assert told in detail


@pytest.mark.parametrize(("locale", "said"), [
    ("en", "the free length was probably given in millimetres where metres are asked for"),
    ("ru", "вероятно, свободная длина задана в миллиметрах, а не в метрах"),
    ("zh", "自由长度很可能按毫米而非米给出"),
])
def test_the_note_tells_of_a_free_length_in_millimetres(tmp_path, locale, said):
    from graphplan.cli import main

    scene = tmp_path / "spring.toml"
    text = _with_loads(SLIDER_CRANK, _spring(4, "B", "D", 3000.0, 500.0))
    scene.write_text(text.replace("[scene]", f'[scene]\nlocale = "{locale}"'), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "note"]) == 0
    assert said in (out / "note.md").read_text(encoding="utf-8")
