"""Hand readings far off their own segments that are other segments of the plans as constructed are named as such: a
segment swapped for another (``pb = 100.98 is the plan's ab``), or a whole table of the other plan's readings typed
under the wrong plan.  They were told only the generic "a length misread, or a segment taken for another?".

Every reading here is a length of the plans as the program constructs them, read in the test off its plan points.
"""

import dataclasses

import graphplan
from graphplan.analysis import analyse
from graphplan.report.tables import markdown

FIXTURE = "fixtures/ratchet_crank_rocker.toml"
POSITION = 5


def _scene():
    return dataclasses.replace(graphplan.load(FIXTURE), measured={})


def _lengths(kind, segments):
    """The segments' lengths (mm) on the plan of ``kind`` of the position as constructed, to 0.01 mm."""
    plan = next(p for p in analyse(_scene()).plans if p.number == POSITION).plans[kind]
    return {name: round(abs(plan.mm(name[1:]) - plan.mm(name[0])), 2) for name in segments}


def _far_off(measured, locale="en"):
    scene = dataclasses.replace(_scene(), locale=locale, measured={POSITION: measured})
    analysis = analyse(scene)
    (warning,) = [w for w in analysis.warnings if w.code == "measured-far-off"]
    return warning.detail, markdown(analysis)


def test_two_segments_swapped_are_named():
    velocity = _lengths("velocity", ("pb", "ab", "pe", "ps3"))
    swapped = {**velocity, "pb": velocity["ab"], "ab": velocity["pb"]}
    detail, _ = _far_off({"velocity": swapped})
    assert (f"pb = {velocity['ab']:g} mm is the velocity plan's ab ({velocity['ab']:.2f} mm as constructed); "
            f"ab = {velocity['pb']:g} mm is the velocity plan's pb ({velocity['pb']:.2f} mm as constructed): "
            "segments taken for one another?") in detail, detail
    assert "a length misread" not in detail
    for locale, words in (("ru", "— это отрезок ab плана скоростей"), ("zh", "即速度多边形上的 ab")):
        _, table = _far_off({"velocity": swapped}, locale)
        assert words in table, table
    # Far off, and no two points of either plan within the drafting precision of it.
    plans = next(p for p in analyse(_scene()).plans if p.number == POSITION).plans.values()
    lengths = [abs(plan.mm(b) - plan.mm(a)) for plan in plans for a in plan.points for b in plan.points]
    odd = next(value for value in (200.0, 210.0, 220.0, 230.0) if all(abs(value - each) > 0.5 for each in lengths))
    detail, _ = _far_off({"velocity": {**velocity, "pb": odd}})
    assert "a length misread, or a segment taken for another?" in detail
    assert "taken for one another" not in detail and "typed under" not in detail


def test_the_other_plan_s_readings_typed_under_the_wrong_table_are_named():
    velocity = _lengths("velocity", ("pb", "pe", "ps3"))
    detail, table = _far_off({"acceleration": velocity})
    assert ("the readings given for the acceleration plan are the velocity plan's pb, pe, ps3 (each to the drafting "
            "precision, 0.5 mm): readings of the velocity plan typed under acceleration?") in detail, detail
    assert "a length misread" not in detail
    assert "The readings given for the acceleration plan are the velocity plan's pb, pe, ps3" in table
    _, russian = _far_off({"acceleration": velocity}, "ru")
    assert "Замеры, данные для плана ускорений, — это отрезки pb, pe, ps3 плана скоростей" in russian
    # The other way round: the acceleration plan's lengths typed for the velocity plan.
    acceleration = _lengths("acceleration", ("pb", "pe", "ps3"))
    detail, _ = _far_off({"velocity": acceleration})
    assert "the readings given for the velocity plan are the acceleration plan's pb, pe, ps3" in detail, detail


def test_a_velocity_reading_is_not_named_an_acceleration_plans_component():
    """A component (an3, pn4) is laid off on the acceleration plan beside the segment it is typed under there; a
    velocity plan has none, and a far-off velocity reading of a component's length was named it by chance."""
    position = next(p for p in analyse(_scene()).plans if p.number == POSITION)
    components = {f"{vector.start}{vector.end}": abs(position.plans["acceleration"].mm(vector.end)
                                                     - position.plans["acceleration"].mm(vector.start))
                  for step in position.plans["acceleration"].steps for vector in step.vectors
                  if "ⁿ" in vector.meaning}
    (name, length), = [(key, value) for key, value in components.items() if key.endswith("n3")]
    velocity = _lengths("velocity", ("pb", "ab", "pe", "ps3"))
    assert abs(length - velocity["ab"]) > 0.15 * velocity["ab"]  # far off its own segment
    detail, _ = _far_off({"velocity": {**velocity, "ab": round(length, 2)}})
    assert f"ab = {round(length, 2):g} mm gives" in detail
    assert f"{name} (" not in detail and "a length misread, or a segment taken for another?" in detail
    # On its own plan a component typed under its segment is still named (n3b given an3's length).
    acceleration = _lengths("acceleration", ("pb", "pe"))
    detail, _ = _far_off({"acceleration": {**acceleration, "n3b": round(length, 2)}})
    assert f"n3b = {round(length, 2):g} mm is the acceleration plan's {name} (" in detail, detail


def test_a_tangential_component_typed_as_its_value_is_told_so():
    """n3b gives ε3 alone; typed as aBAτ = ε3·lAB in m/s² it was told a length misread, where aBA typed so was told
    the value it stands for.  The value is worked out here from the plan's ε3 and the coupler's length."""
    from graphplan.scene import loads
    from graphplan.starters import starter

    text = starter("slider-crank", "en")
    scene = loads(text)
    position = next(p for p in analyse(scene).plans if p.number == 2)
    (epsilon3,) = [row.plan for row in position.errors if row.source == "construction" and row.quantity == "epsilon3"]
    coupler = scene.groups[0].length
    typed = round(abs(epsilon3) * coupler, 1)
    acceleration = {"pb": round(abs(position.plans["acceleration"].mm("b")), 2), "n3b": typed}
    analysis = analyse(loads(text + f"\n[measured.2]\nacceleration = {{ pb = {acceleration['pb']}, n3b = {typed} }}\n"))
    (detail,) = [w.detail for w in analysis.warnings if w.code == "measured-far-off"]
    assert f"n3b = {typed:g} mm is aBAτ = {typed:.4g} m/s²" in detail, detail
    assert "a length misread" not in detail
    assert f"n3b = {typed:g} мм — это aBAτ = {typed:.4g} м/с²".replace(".", ",") in markdown(
        analyse(dataclasses.replace(analysis.scene, locale="ru")))


def test_a_plan_drawn_at_another_pole_with_one_segment_misread_is_told_both():
    """Drawn at pa = 120 mm for the fixture's 150 with ps3 given pb's length: the four readings agreed at no one
    scale, and the student was told four lengths misread, no word of the pole.  The three that agree give the pole;
    the fourth is told misread."""
    velocity = _lengths("velocity", ("pb", "ab", "pe", "ps3"))
    drawn = {name: round(value * 120.0 / 150.0, 2) for name, value in velocity.items()}
    drawn["ps3"] = drawn["pb"]
    detail, table = _far_off({"velocity": drawn})
    assert "every reading of the velocity plan but ps3 is 0.8" in detail, detail
    assert "give `[drawing] velocity_pole = 120`" in detail and "every reading but ps3 is within" in detail
    # The fourth told apart, as misread (here by chance another segment's length, which it is named).
    assert f"ps3 = {drawn['ps3']:g} mm" in detail.split("velocity_pole = 120`")[1]
    assert "Every reading of the velocity plan but ps3 is 0.8" in table, table
    _, russian = _far_off({"velocity": drawn}, "ru")
    assert "Все замеры на плане (план скоростей), кроме ps3, отличаются" in russian, russian
    # Three readings, one off: too few to tell a scale from one misreading.
    three = {name: drawn[name] for name in ("pb", "ab", "ps3")}
    detail, _ = _far_off({"velocity": three})
    assert "but ps3" not in detail and "velocity_pole" not in detail, detail
