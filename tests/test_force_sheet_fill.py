"""A force sheet with room to spare on its sheet draws its groups cut free and its force polygons larger.

The slotted-lever starter's force sheets on A1 drew group II(3,4) at the mechanism's μl = 0.004 m/mm and its
polygons at 5 and 2.5 N/mm, a third of the sheet's field used. Where the sheets hold it, the groups are drawn a
standard step or more finer in μl and the polygons in μF, on no more sheets. The scales are read back off the
drawn sheet: each polygon's reactions, measured as arrow lengths at the μF its caption writes, must be the
reactions of the linear system (statics), and the title block's scale must be the μl the groups are drawn at.
"""

import re

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.render import force_sheet_choice
from graphplan.render import sheet as sheet_module
from graphplan.render.forces import group_id
from graphplan.render.primitives import Arrow, Text, bounds_of
from graphplan.render.sheet import course_sheets
from graphplan.starters import starter

STANDARD = sorted(m * 10.0 ** p for p in range(-6, 6) for m in (1.0, 2.0, 2.5, 4.0, 5.0))


def finer(scale):
    """The standard scale just below ``scale``, from the series itself."""
    return max(value for value in STANDARD if value < scale * (1 - 1e-9))


# The starter's two force sheets share one A1 with their rows apart, drawn at the record's scales: what is
# checked here is a sheet drawn larger where it has room.
pytestmark = pytest.mark.usefixtures("no_rows_apart")


@pytest.fixture(scope="module")
def slotted_lever(tmp_path_factory):
    path = tmp_path_factory.mktemp("scene") / "slotted-lever.toml"
    path.write_text(starter("slotted-lever", "en"), encoding="utf-8")
    return analyse(graphplan.load(path))


def force_sheets(analysis, sheet):
    return [page for page in course_sheets(analysis, sheet)
            if any(layer.name.startswith("forces-") for layer in page.layers)]


def texts(layers):
    return [item.text for layer in layers for item in layer.items if isinstance(item, Text)]


def written(pattern, lines):
    found = {float(match.group(1)) for line in lines for match in [re.search(pattern, line)] if match}
    assert len(found) == 1, (pattern, lines)
    return found.pop()


def drawings(page, analysis):
    """Each drawing of a force sheet on ``page`` (a group cut free, a polygon, the lever, the heading, the load
    diagrams) by its name, with all its layers."""
    keys = [group_id(group.label) for plan in analysis.plans for group in plan.forces.groups]
    found = {}
    for layer in page.layers:
        if not layer.items or layer.name in ("sheet-frame", "title-block"):
            continue
        name = next((f"{kind}-{key}" for key in keys for kind in ("body", "polygon")
                     if f"-{kind}-{key}-" in layer.name), None)
        name = name or next((kind for kind in ("lever", "sheet-title", "load-diagrams") if kind in layer.name),
                            layer.name)
        found.setdefault(name, []).append(layer)
    return found


def test_the_slotted_lever_force_sheets_on_a1_are_drawn_a_step_finer_and_read_back_true(slotted_lever):
    pages = force_sheets(slotted_lever, "A1")
    assert pages
    plans = {plan.number: plan for plan in slotted_lever.plans if plan.forces is not None}
    seen = set()
    for page in pages:
        number = int(re.search(r"forces-(\d+)-", next(layer.name for layer in page.layers
                                                     if layer.name.startswith("forces-"))).group(1))
        plan = plans[number]
        seen.add(number)
        lines = texts(page.layers)
        drawn_length = written(r"^μl = ([\d.]+) m/mm", [line for line in lines if "arrows" in line])
        # At least a standard step finer than the mechanism's own μl (the record's polygons are at their fields').
        mechanism = sheet_module.length_scale(slotted_lever)
        assert drawn_length <= finer(mechanism) * (1 + 1e-9)
        # The title block's scale is the groups' μl: 0.002 m/mm is 1:2.
        block = texts([layer for layer in page.layers if layer.name == "title-block"])
        assert f"1:{drawn_length * 1000:g}" in block
        for group in plan.forces.groups:
            key = group_id(group.label)
            caption = texts([layer for layer in page.layers if layer.name.endswith(f"polygon-{key}-caption")])
            drawn_force = written(r"^μF = ([\d.]+) N/mm", caption)
            assert drawn_force <= finer(group.scale) * (1 + 1e-9)
            arrows = [item for layer in page.layers if f"-polygon-{key}" in layer.name and
                      layer.name.endswith("-vectors") for item in layer.items if isinstance(item, Arrow)]
            measured = 0
            for arrow in arrows:
                name = arrow.key.rsplit("-", 1)[1]
                if not name.startswith("R"):
                    continue
                reaction = name if name in [r.name for r in slotted_lever.equilibrium.reactions] else \
                    f"R{name[2]}{name[1]}"
                exact = abs(complex(slotted_lever.equilibrium.reaction(reaction).force[plan.index]))
                length = abs(complex(*arrow.end) - complex(*arrow.start))
                assert length * drawn_force == pytest.approx(exact, rel=2e-3), (name, length, drawn_force, exact)
                measured += 1
            assert measured >= 2
    assert seen == set(plans)


def test_the_larger_force_drawings_stay_in_the_field_apart_from_one_another(slotted_lever):
    for sheet in ("A1", "A3"):
        for page in force_sheets(slotted_lever, sheet):
            x0, y0, x1, y1 = page.frame
            bx0, by0, bx1, by1 = page.title_block
            boxes = {name: bounds_of(item for layer in layers for item in layer.items)
                     for name, layers in drawings(page, slotted_lever).items()}
            for name, (a0, b0, a1, b1) in boxes.items():
                assert x0 <= a0 and a1 <= x1 and y0 <= b0 and b1 <= y1, (sheet, name)
                assert a1 <= bx0 or a0 >= bx1 or b1 <= by0 or b0 >= by1, (sheet, name, "title block")
            names = sorted(boxes)
            for i, first in enumerate(names):
                for second in names[i + 1:]:
                    p0, q0, p1, q1 = boxes[first]
                    r0, s0, r1, s1 = boxes[second]
                    assert p1 <= r0 or r1 <= p0 or q1 <= s0 or s1 <= q0, (sheet, first, second)


@pytest.mark.parametrize("sheet", ["A1", "A3"])
def test_drawing_the_force_sheets_larger_takes_no_more_sheets(slotted_lever, sheet, monkeypatch):
    larger = course_sheets(slotted_lever, sheet)
    monkeypatch.setattr(force_sheet_choice, "LARGER_FORCE_STEPS", ())
    sheet_module._laid_out_panels.__init__()  # the force sheets laid out again, with no larger way to take
    usual = course_sheets(slotted_lever, sheet)
    assert len(larger) == len(usual)
    bodies = [written(r"^μl = ([\d.]+) m/mm", [line for line in texts(page.layers) if "arrows" in line])
              for page in usual if any(layer.name.startswith("forces-") for layer in page.layers)]
    assert bodies and all(scale == pytest.approx(sheet_module.length_scale(slotted_lever)) for scale in bodies)
