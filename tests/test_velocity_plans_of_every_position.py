"""The velocity plans of every position (``positions.velocity_plans``): a course project's plans of the twelve
positions, drawn at one μV on one drawing and on the first sheet.

The plans are constructed group by group as the plan sheets' are; every value they give is checked
against the analytic solution at its position, and every vector drawn against the analytic velocity
divided by μV.
"""

import functools
import itertools
import json
import math
import re

import numpy as np
import pytest

import graphplan
from graphplan.analysis import VELOCITY_PLANS_FIELD_MM, analyse
from graphplan.cli import main
from graphplan.deliverables import chosen, missing
from graphplan.errors import SceneError
from graphplan.locale import strings
from graphplan.plans import spread
from graphplan.render import drawings
from graphplan.render import velocity_plans as velocity_plans_layout
from graphplan.render.primitives import Arrow
from graphplan.render.sheet import course_sheets
from graphplan.report import tables
from graphplan.scales import STANDARD_MANTISSAS
from graphplan.scene import loads

# One fixture of each group kind the plans construct: RRR, RPR (the slotted lever), two RRR/RRP dyads in
# series, RPP, PRP, a slider driver, the class III triad.
KINDS = ["ratchet_crank_rocker", "quick_return_slotted_lever", "shaper_six_bar", "scotch_yoke",
         "tangent_mechanism_prp", "slider_driven", "triad_class_iii"]


def scene_text(name: str, setting: str = 'velocity_plans = "all"', drawing: str = "") -> str:
    """The fixture's scene with ``setting`` added to its [positions] and ``drawing`` to its [drawing]."""
    with open(f"fixtures/{name}.toml", encoding="utf-8") as file:
        text = file.read()
    text = re.sub(r"^\[positions\]\s*$", lambda m: f"{m.group(0)}\n{setting}", text, count=1, flags=re.MULTILINE)
    if drawing:
        text = re.sub(r"^\[drawing\]\s*$", lambda m: f"{m.group(0)}\n{drawing}", text, count=1, flags=re.MULTILINE)
    return text


@functools.cache
def analysed(name: str, setting: str = 'velocity_plans = "all"', drawing: str = ""):
    # One analysis of a scene for the module: an analysis is frozen, and the same text analyses alike; the μl the
    # sheets choose for it is memoised with it, so each test after the first reads the same drawings sooner.
    return analyse(loads(scene_text(name, setting, drawing)))


@pytest.mark.parametrize("name", KINDS)
def test_every_position_velocity_plan_gives_the_analytic_velocities(name):
    analysis = analysed(name)
    every = analysis.velocity_plans
    assert [position.number for position in every] == list(analysis.positions.numbers)
    largest = max(abs(row.analytic) for position in every for row in position.errors if row.quantity.startswith("V"))
    for position in every:
        constructed = [row for row in position.errors if row.source == "construction"]
        assert {row.quantity for row in constructed} >= {f"V{analysis.mechanism.driver.joint}"}
        for row in constructed:
            scale = largest if row.quantity.startswith("V") else max(abs(row.analytic), 1.0)
            assert row.plan == pytest.approx(row.analytic, abs=1e-9 * scale), (position.number, row.quantity)
        # No acceleration is read off a velocity plan.
        assert not any(row.quantity.startswith(("a", "epsilon")) for row in position.errors)


@pytest.mark.parametrize("name", ["ratchet_crank_rocker", "shaper_six_bar", "slider_driven"])
def test_the_plans_of_every_position_share_the_standard_scale_that_fits_the_largest(name):
    analysis = analysed(name)
    scales = {position.velocity.scale for position in analysis.velocity_plans}
    assert len(scales) == 1
    (scale,) = scales
    widest = max(spread(position.velocity) for position in analysis.velocity_plans)
    assert widest / scale <= VELOCITY_PLANS_FIELD_MM * (1 + 1e-9)
    # The standard scale a step smaller would draw the largest plan too big for the field.
    smaller = max(m * 10.0 ** p for p in range(-6, 3) for m in STANDARD_MANTISSAS if m * 10.0 ** p < scale * (1 - 1e-12))
    assert widest / smaller > VELOCITY_PLANS_FIELD_MM * (1 - 1e-9)


def test_a_pole_distance_fixes_the_scale_of_every_plan_and_leaves_the_plan_sheets_alone():
    plain = analysed("ratchet_crank_rocker")
    analysis = analysed("ratchet_crank_rocker", drawing="velocity_plans_pole = 60.0")
    driver = analysis.mechanism.driver
    for position in analysis.velocity_plans:
        assert abs(position.velocity.mm(position.velocity.images[driver.joint])) == pytest.approx(60.0, rel=1e-12)
    for ours, theirs in zip(analysis.plans, plain.plans, strict=True):
        assert ours.velocity.scale == theirs.velocity.scale
        assert ours.errors == theirs.errors


def test_the_drawing_lays_each_vector_from_the_pole_as_long_as_the_analytic_velocity_over_mu_v():
    analysis = analysed("shaper_six_bar")
    drawing = drawings.velocity_plans_drawing(analysis)
    arranged = velocity_plans_layout.arrange(drawing)
    scale = analysis.velocity_plans[0].velocity.scale
    checked = 0
    for position in analysis.velocity_plans:
        prefix = velocity_plans_layout.field_name(position.number)
        assert prefix in arranged.fields
        arrows = {item.key: item for layer in arranged.layers if layer.name == f"{prefix}-velocity-vectors"
                  for item in layer.items if isinstance(item, Arrow)}
        for point, letter in position.velocity.images.items():
            key = f"{prefix}-velocity-p-{letter}"
            if letter == "p" or key not in arrows:
                continue
            arrow = arrows[key]
            drawn = math.dist(arrow.start, arrow.end)
            exact = float(np.hypot(*analysis.motion.point(point).v[position.index])) / scale
            assert drawn == pytest.approx(exact, rel=1e-9, abs=1e-9), (position.number, point)
            checked += 1
    assert checked >= 3 * len(analysis.velocity_plans)
    # Every plan stands in its own cell: no two fields overlap.
    fields = sorted(arranged.fields.values())
    for k, (x0, y0, x1, y1) in enumerate(fields):
        for u0, v0, u1, v1 in fields[k + 1:]:
            assert x1 <= u0 + 1e-9 or u1 <= x0 + 1e-9 or y1 <= v0 + 1e-9 or v1 <= y0 + 1e-9


def test_results_give_each_position_its_velocity_plan_and_the_errors_of_those_without_a_plan_sheet(tmp_path):
    scene = tmp_path / "ratchet.toml"
    scene.write_text(scene_text("ratchet_crank_rocker"), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "velocity,errors"]) == 0
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))
    for entry in document["positions"]:
        plan = entry["velocity_plan"]
        for name, value in plan["values"].items():
            if name.startswith("V") and name[1:] in entry["points"] and len(name) <= 3:
                assert value == pytest.approx(math.hypot(*entry["points"][name[1:]]["v"]), rel=1e-9, abs=1e-9)
    planned = {5, 11}
    by_position = {}
    for row in document["errors"]:
        by_position.setdefault(row["position"], set()).add(row["quantity"])
    assert set(by_position) == {entry["index"] for entry in document["positions"]}
    for number, quantities in by_position.items():
        assert any(q.startswith("a") for q in quantities) == (number in planned), number
    csv_rows = (out / "errors.csv").read_text(encoding="utf-8").splitlines()[1:]
    assert len(csv_rows) == len(document["errors"])
    assert (out / "velocity_plans.svg").exists()
    text = strings(document_locale := loads(scene.read_text(encoding="utf-8")).locale)
    section = (out / "errors.md").read_text(encoding="utf-8").split(f"## {text['velocity_plans_heading']}")[1]
    headers = [cell.strip() for line in section.splitlines() if line.startswith(f"| {text['errors_quantity']} |")
               for cell in line.strip("|").split("|")[2:]]
    assert headers == [str(n) for n in range(12)], document_locale


def test_the_table_of_every_position_gives_the_largest_drafting_error_of_its_row():
    analysis = analysed("quick_return_slotted_lever")
    text = strings(analysis.scene.locale)
    name = text["velocity_plans_largest"].format(source=text["source_drafting"])
    cells = [float(cell.replace("−", "-")) for line in tables.velocity_plans_lines(analysis)
             if line.startswith(f"| {name} |") for cell in line.strip("|").split("|")[2:]]
    # Signed, as each position's own table writes its largest.
    drafted = [max((row.percent for row in position.errors if row.source == "drafting"), key=abs)
               for position in analysis.velocity_plans]
    assert cells == pytest.approx(drafted, abs=5e-4)
    assert max(drafted) > 0 > min(drafted)


def test_the_first_sheet_holds_the_plan_of_positions_and_the_velocity_plans_of_every_position():
    sheets = course_sheets(analysed("ratchet_crank_rocker"), "A1")
    assert {"positions", "velocity-plans"} <= set(sheets[0].panels)


def test_on_a_small_sheet_the_plans_stand_apart_each_once_in_the_order_of_the_positions():
    analysis = analysed("ratchet_crank_rocker")
    sheets = course_sheets(analysis, "A2")
    placed = [(sheet.number, name, rect) for sheet in sheets for name, rect in sheet.panels.items()
              if name.startswith("velocity-plans")]
    names = [name for _, name, _ in placed]
    if names != ["velocity-plans"]:
        # Runs of the plans, each named after the plan it begins with, the first with the first plan; read sheet by
        # sheet, top to bottom, they run in order.
        starts = [int(name.rsplit("-", 1)[1]) for name in names]
        assert starts[0] == 1 and starts == sorted(set(starts))
        assert all(name.startswith("velocity-plans-from-") for name in names)
        by_sheet = {}
        for sheet_number, _, rect in placed:
            by_sheet.setdefault(sheet_number, []).append(rect)
        for rects in by_sheet.values():
            assert all(later[3] <= earlier[1] for earlier, later in itertools.pairwise(rects))


def test_a_grid_no_sheet_holds_stands_row_by_row_in_the_order_of_the_positions():
    """A teacher's A3 sheets of a shaper: the plans apart, each where it fitted best, read 1; 2, 3, 4; 5, 6 on
    the right; 7, 8; 10 before 9. The grid now stands row by row, each row left to right, the rows down the
    sheets in order, in runs as long as each sheet's room holds (``velocity-plans-from-K``)."""
    from graphplan.render.packing import pack
    from graphplan.render.sheet import velocity_plans_panel

    analysis = drawings.with_length_scale(analysed("shaper_six_bar"))
    panel = velocity_plans_panel(analysis)
    assert panel.in_order and all(part.name.startswith("velocity-plans-row-") for part in panel.parts)
    numbers_by_row = [[int(plan.name.rsplit("-", 1)[1]) for plan in row.parts] for row in panel.parts]
    assert [number for row in numbers_by_row for number in row] == list(analysis.positions.numbers)
    for sheet in ("A3", "A4"):
        pages = pack([panel], sheet, "iso")
        placed = [way for page in pages for way, _, _ in page.placed]
        assert len(placed) > 1, sheet  # the grid does not stand whole on these sheets
        # Whole rows, or the plans of a row apart, placed in the positions' order (each where it reads after the
        # ones before it: under them, or at the top of the next column).
        numbers = [int(plan.name.rsplit("-", 1)[1]) for way in placed
                   for plan in (way.parts if way.name.startswith("velocity-plans-from-") else (way,))]
        assert numbers == list(analysis.positions.numbers), sheet
        for page in pages:
            rects = [rect for _, rect, _ in page.placed]
            for k, rect in enumerate(rects):
                assert all(rect[0] >= before[2] - 1e-6 or rect[3] < before[3] - 1e-6 for before in rects[:k])


def test_a_grid_too_wide_for_a_sheet_stands_in_rows_as_wide_as_the_sheet_in_order():
    """48 plans of the triad with a slider: the grid's seven columns are wider than an A1, so each row stood
    apart plan by plan, each where it fitted best, and the sheet read 2, 7, 15, 34, 1, 10, … (a student's A1
    sheets).  The grid is taken in as many columns as the sheet holds, its rows whole and in order."""
    from graphplan.render.packing import pack
    from graphplan.render.sheet import velocity_plans_panel

    text = re.sub(r"^count\s*=\s*12", "count = 48", scene_text("triad_with_slider"), count=1, flags=re.MULTILINE)
    # μl is not fixed: the grid draws no linkage and reads none (choosing it laid every sheet out at each μl).
    analysis = analyse(loads(text))
    assert len(analysis.positions.numbers) == 48
    panel = velocity_plans_panel(analysis)
    pages = pack([panel], "A1", "iso")
    placed = [way for page in pages for way, _, _ in page.placed]
    assert all(way.name.startswith("velocity-plans-from-") for way in placed)   # runs of whole rows
    numbers = [int(plan.name.rsplit("-", 1)[1]) for way in placed for plan in way.parts]
    assert numbers == list(analysis.positions.numbers)
    for page in pages:
        rects = [rect for _, rect, _ in page.placed]
        for k, rect in enumerate(rects):
            assert all(rect[0] >= before[2] - 1e-6 or rect[3] < before[3] - 1e-6 for before in rects[:k])


def test_a_plan_set_apart_has_its_caption_under_its_middle_and_the_first_not_under_the_title():
    """Set apart on a small sheet, the first plan's caption was centred under the title it carries, 90 mm off
    its plan (a user's A4 sheet of a shaper)."""
    from graphplan.render.primitives import bounds
    from graphplan.render.sheet import split

    analysis = drawings.with_length_scale(analysed("ratchet_crank_rocker"))
    panel = split(velocity_plans_layout.arrange(drawings.velocity_plans_drawing(analysis)), "velocity-plans", "")
    first = {layer.name for layer in panel.parts[0].layers}
    assert "title" in first
    for part in panel.parts:
        caption = next(layer for layer in part.layers if layer.name == "caption").items[0]
        x0, _, x1, _ = bounds([layer for layer in part.layers if layer.name not in ("caption", "title")])
        assert caption.at[0] == pytest.approx((x0 + x1) / 2, abs=1e-9), part.name


def test_velocity_plans_alone_give_the_velocity_drawings_and_errors_but_no_accelerations():
    def without_plan_sheets(setting):
        scene = loads(scene_text("stephenson_six_bar", setting).replace("plans       = [3, 9]", "plans = []"))
        return scene, analyse(scene)

    scene, analysis = without_plan_sheets('velocity_plans = "all"')
    assert not analysis.plans and analysis.velocity_plans
    assert missing(scene, analysis, "velocity") is None
    assert missing(scene, analysis, "errors") is None
    assert "positions.plans lists none" in missing(scene, analysis, "acceleration")
    assert {"velocity", "errors"} <= set(chosen(scene, analysis))
    assert "velocity_plans list none" in missing(*without_plan_sheets("velocity_plans = []"), "velocity")


@pytest.mark.parametrize(("setting", "where", "says"), [
    ('velocity_plans = "some"', "positions.velocity_plans", '"all" or a list'),
    ("velocity_plans = [0, 12]", "positions.velocity_plans[1]", "from 0 to 11"),
    ("velocity_plans = [1.5]", "positions.velocity_plans[0]", "integer"),
])
def test_a_wrong_list_of_velocity_plans_is_refused_where_it_is(setting, where, says):
    with pytest.raises(SceneError) as caught:
        loads(scene_text("ratchet_crank_rocker", setting))
    assert caught.value.where == where
    assert says in str(caught.value)


def test_more_velocity_plans_than_a_drawing_can_hold_are_refused():
    with pytest.raises(SceneError) as caught:
        loads(scene_text("ratchet_crank_rocker").replace("count       = 12", "count = 60"))
    assert caught.value.where == "positions.velocity_plans"
    assert "at most 48" in str(caught.value)


def test_a_list_of_velocity_plans_is_taken_in_the_order_of_the_positions():
    analysis = analysed("ratchet_crank_rocker", "velocity_plans = [7, 2, 0]")
    assert [position.number for position in analysis.velocity_plans] == [0, 2, 7]


def test_a_pole_distance_for_them_must_be_positive():
    with pytest.raises(SceneError) as caught:
        loads(scene_text("ratchet_crank_rocker", drawing="velocity_plans_pole = -5"))
    assert caught.value.where == "drawing.velocity_plans_pole"


def test_the_scene_format_documents_the_keys():
    with open("docs/scene-format-extensions.md", encoding="utf-8") as file:
        text = file.read()
    for key in ("velocity_plans", "velocity_plans_pole", "velocity_plan", "velocity_plans.svg"):
        assert key in text
    assert graphplan  # the package imports whole


def test_the_equivalent_model_is_read_off_the_velocity_plans_of_every_position():
    from graphplan.dynamics import plan_reductions

    analysis = analysed("shaper_six_bar")
    reductions = plan_reductions(analysis)
    assert [reduction.number for reduction in reductions] == list(analysis.positions.numbers)
    inertia_scale = max(abs(reduction.inertia_exact) for reduction in reductions)
    moment_scale = max(abs(reduction.moment_exact) for reduction in reductions)
    assert moment_scale > 0
    for reduction in reductions:
        assert reduction.inertia == pytest.approx(reduction.inertia_exact, abs=1e-9 * inertia_scale)
        assert reduction.moment == pytest.approx(reduction.moment_exact, abs=1e-9 * moment_scale)


def test_the_dynamics_sheet_rings_each_plans_je_on_the_curve_of_the_exact_one():
    from graphplan.dynamics import equivalent_model_of
    from graphplan.render import dynamics as dynamics_layout
    from graphplan.render.primitives import Circle, Polyline

    analysis = analysed("shaper_six_bar")
    layers = dynamics_layout.layout(equivalent_model_of(analysis), None, strings("en"))
    inertia = next(layer for layer in layers if layer.name == "inertia")
    rings = [item for item in inertia.items if isinstance(item, Circle) and item.fill is None
             and item.radius == dynamics_layout.PLAN_RING_MM]
    curve = max((item for item in inertia.items if isinstance(item, Polyline)), key=lambda item: len(item.points))
    xs, ys = np.array(curve.points).T
    axis_y = ys[0]
    on_curve = [ring for ring in rings if ring.centre[1] <= axis_y + 1e-9]  # the legend's ring stands above
    assert len(on_curve) == len(analysis.velocity_plans) == len(rings) - 1
    for ring in on_curve:
        x, y = ring.centre
        # The curve runs down the page with φ: interpolate its Je at the ring's φ (y decreasing).
        assert x == pytest.approx(float(np.interp(-y, -ys, xs)), abs=0.05)


def measured_scene(position: int, readings: str, drawing: str = "velocity_plans_pole = 50.0") -> str:
    return scene_text("stephenson_six_bar", drawing=drawing) + f"\n[measured.{position}]\n{readings}\n"


def test_a_hand_drawn_velocity_plan_of_any_position_is_checked_at_the_mu_v_of_the_plans():
    # At pa = 50 mm μV is VA/50; a pb drawn 1 mm longer than the exact |VB|/μV reads VB that much too large.
    exact = analyse(loads(measured_scene(4, "velocity = { pb = 10.0 }")))
    position = next(p for p in exact.velocity_plans if p.number == 4)
    scale = position.velocity.scale
    vb = float(np.hypot(*exact.motion.point("B").v[position.index]))
    va = float(np.hypot(*exact.motion.point(exact.mechanism.driver.joint).v[position.index]))
    assert scale == pytest.approx(va / 50.0, rel=1e-12)
    drawn = vb / scale + 1.0
    analysis = analyse(loads(measured_scene(4, f"velocity = {{ pb = {drawn!r} }}")))
    # pb gives every quantity read from it: VB, and VBC and ω4 with C at the pole.
    rows = {row.quantity: row for row in analysis.errors if row.position == 4 and row.source == "measured"}
    assert "VB" in rows
    assert rows["VB"].plan == pytest.approx(drawn * scale, rel=1e-12)
    assert rows["VB"].percent == pytest.approx((vb - drawn * scale) / vb * 100.0, rel=1e-9)
    text = strings(analysis.scene.locale)
    largest = text["velocity_plans_largest"].format(source=text["source_measured"])
    assert any(line.startswith(f"| {largest} |") for line in tables.velocity_plans_lines(analysis))


def test_the_errors_of_a_hand_drawn_velocity_plan_stand_quantity_by_quantity_in_the_report_and_the_note(tmp_path):
    # The table of every position gives a position's largest error alone; the student checks each reading.
    scene = tmp_path / "six_bar.toml"
    scene.write_text(measured_scene(4, "velocity = { pb = 10.0 }"), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "velocity,errors,note"]) == 0
    analysis = analyse(loads(scene.read_text(encoding="utf-8")))
    text = strings(analysis.scene.locale)
    heading = text["velocity_plan_errors"].format(number=4)
    measured = [row for row in analysis.errors if row.position == 4 and row.source == "measured"]
    assert measured
    for name, mark in (("errors.md", "."), ("note.md", text["decimal_mark"])):
        written = (out / name).read_text(encoding="utf-8")
        table = written[written.index(heading):].split("\n\n")[1].splitlines()
        cells = {line.split(" | ")[0].lstrip("| "): line.split(" | ") for line in table[2:]}
        for row in measured:
            # The measured value and its δ, as the error tables of the plan positions write them.
            assert tables._percent(row.percent, mark) in cells[tables.quantity_symbol(row.quantity)][-1]
    unmeasured = [p.number for p in analysis.velocity_plans if p.number != 4]
    assert all(text["velocity_plan_errors"].format(number=n) not in written for n in unmeasured)


def test_only_the_velocity_plan_of_a_position_without_a_plan_sheet_can_be_measured():
    with pytest.raises(SceneError) as caught:
        analyse(loads(measured_scene(4, "acceleration = { pb = 10.0 }")))
    assert caught.value.where == "measured.4.acceleration"
    assert "positions.plans" in str(caught.value)


@pytest.mark.parametrize("name", ["ratchet_crank_rocker", "shaper_six_bar", "slider_driven", "scotch_yoke"])
def test_the_velocity_diagram_rings_the_output_velocity_of_each_plan_on_the_exact_curve(name):
    from graphplan.kinematic_diagrams import of_analysis
    from graphplan.render import diagrams as diagrams_layout
    from graphplan.render.primitives import Circle, Polyline

    analysis = analysed(name)
    record = of_analysis(analysis)
    assert len(record.v_plans) == len(analysis.velocity_plans) == len(analysis.positions.numbers)
    exact = dict(zip(record.nodes.tolist(), record.v_nodes.tolist(), strict=True))
    peak = record.v_peak
    for node, value in record.v_plans:
        assert value == pytest.approx(exact[node], abs=1e-9 * peak)
    layers = diagrams_layout.layout(record, strings(analysis.scene.locale))
    curves = next(layer for layer in layers if layer.name.endswith("velocity-curves"))
    rings = [item for item in curves.items if isinstance(item, Circle) and item.fill is None]
    assert len(rings) == len(record.v_plans)
    # The panel stands somewhere on the drawing: measure from the analytic curve, which starts at the origin.
    curve = next(item for item in curves.items if isinstance(item, Polyline))
    xs, ys = np.array(curve.points).T
    origin = (xs[0], ys[0] - record.v[0] / record.scales.velocity)
    along_mm = 1.0 / record.scales.along
    for ring, (node, value) in zip(rings, record.v_plans, strict=True):
        assert ring.centre[0] - origin[0] == pytest.approx(node * along_mm, abs=1e-9)
        assert ring.centre[1] - origin[1] == pytest.approx(value / record.scales.velocity, abs=1e-9)
        # ...and on the curve of the exact velocity, drawn through 360 samples.
        assert ring.centre[1] == pytest.approx(float(np.interp(ring.centre[0], xs, ys)), abs=0.3)


def test_the_largest_measured_error_of_a_position_skips_a_reading_of_what_stands_still_and_names_it():
    """At the shaper's extreme the ram is at rest: pe read as 0.5 mm has no finite δ, and the row of the largest
    measured errors wrote "—" for the position, hiding pa's finite error."""
    from graphplan.starters import starter

    scene = loads(starter("shaper") + "\n[measured.1]\nvelocity = { pe = 0.5, pd = 0.0, pa = 31.5 }\n")
    analysis = analyse(scene)
    position = next(p for p in analysis.velocity_plans if p.number == 1)
    va = float(np.hypot(*analysis.motion.point(analysis.mechanism.driver.joint).v[position.index]))
    ve = float(np.hypot(*analysis.motion.point("E").v[position.index]))
    assert ve < 1e-9 * va  # the extreme: VE vanishes, and pe = 0.5 mm reads a speed where there is none
    expected = abs(va - 31.5 * position.velocity.scale) / va * 100.0  # pa's error, which ω2's shares
    text = strings(analysis.scene.locale)
    name = text["velocity_plans_largest"].format(source=text["source_measured"])
    (line,) = [line for line in tables.velocity_plans_lines(analysis) if line.startswith(f"| {name} |")]
    cell = line.strip("|").split("|")[2 + [p.number for p in analysis.velocity_plans].index(1)].strip()
    value, undefined = re.fullmatch(r"(−?[\d.,]+) \((.*): —\)", cell).groups()
    signed = float(value.replace(",", ".").replace("−", "-"))
    assert abs(signed) == pytest.approx(expected, abs=5e-4) and expected > 0.1
    assert "VE" in undefined.split(", ")


@pytest.mark.parametrize("sheet", ["A3", "A4"])
def test_every_sheet_of_the_grid_states_its_mu_v_under_the_title_or_continued(sheet):
    """The shaper's grid on A3 and A4 went on onto later sheets bare: no heading, no μV, and a plan sheet's
    title block leaves the scale box empty, so a grader could not measure those plans (a hunt's sheets 3 to 6).
    Every sheet with plans of the grid now reads the μV they are drawn at, under the title on the first and
    under the title «continued» on the others."""
    import xml.etree.ElementTree as ET

    text = scene_text("shaper_six_bar")
    if sheet == "A4":  # the plans of positions and acceleration an A4 holds, as the refusals advise
        for key, value in (("acceleration_pole", "81.0"), ("length_scale", "0.004")):
            text = re.sub(rf"^{key}\s*=.*$", f"{key} = {value}", text, count=1, flags=re.MULTILINE)
    analysis = analyse(loads(text)) if sheet == "A4" else analysed("shaper_six_bar")   # on A3 the scene unchanged
    scale = analysis.velocity_plans[0].velocity.scale
    title = strings("en")["velocity_plans_heading"]
    holding = [page for page in course_sheets(analysis, sheet)
               if any(name.startswith("velocity-plans") for name in page.panels)]
    # The grid goes on onto another sheet on A4; an A3 holds it in two runs, the second beside the title block.
    assert len(holding) > (1 if sheet == "A4" else 0), sheet
    for k, page in enumerate(holding):
        lines = ["".join(text.itertext()) for text in ET.fromstring(page.svg()).iter("{http://www.w3.org/2000/svg}text")]
        values = [float(found[1]) for line in lines for found in [re.fullmatch(r"μV = ([\d.]+) \(m/s\)/mm", line)]
                  if found]
        assert values and all(value == pytest.approx(scale, rel=1e-3) for value in values), (sheet, page.number)
        # The heading's lines (broken where the sheet is narrow) run on into its μV line.
        at = lines.index(next(line for line in lines if line.startswith("μV")))
        heading = title if k == 0 else f"{title} (continued)"
        assert " ".join(lines[:at]).endswith(heading), (sheet, page.number, lines[:at])
