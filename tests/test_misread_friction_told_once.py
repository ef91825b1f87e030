"""Force readings off a drawing with friction are told once, naming the drawing: the general line that every reading
stands nearer the polygons with friction than those without is left out where the readings were found on a drawing
with friction, on a course sheet as on the record's own forces_friction_N.svg.  It was left out only for the record's,
and a course sheet's drawing with friction at the μF of the polygons the readings are checked against had both lines.

The shaper starter with the ram's slide at f = 0.3, position 10, its crank's R12 read with friction: 31 % longer than
without, its reaction with friction of the linear system over the crank polygon's μF.  The course sheet that draws the
crank cut free with friction, its arrows at that μF, is given as the run would find it on sheet 5.
"""

import functools

from test_misread_record_friction_polygons import NUMBER, _exact, _scene

from graphplan.analysis import analyse, read_off_sheets
from graphplan.misreadings import SheetPolygons
from graphplan.report.tables import slip_lines

NEARER = "nearer the polygons with friction"
CRANK = "I(1,2)"


@functools.cache
def _analysis():
    plain = analyse(_scene())
    crank_scale = next(plan for plan in plain.plans if plan.number == NUMBER).forces.group_scales[CRANK]
    plain_reading, friction_reading = (value / crank_scale for value in _exact()["R12"])
    # The friction moves R12 beyond a misreading's bound, so a reading with friction is far off the one without.
    assert friction_reading / plain_reading - 1.0 > 0.15
    analysis = analyse(_scene({"R12": round(friction_reading, 2)}))
    return analysis, next(plan for plan in analysis.plans if plan.number == NUMBER), crank_scale


def test_readings_off_a_course_sheets_arrows_with_friction_are_told_that_drawing_alone():
    analysis, plan, crank_scale = _analysis()
    arrows = SheetPolygons(5, {}, friction=True, arrows={CRANK: (crank_scale, ("R32", "R12"))})
    told = read_off_sheets(analysis, {NUMBER: (arrows,)})
    for in_note in (False, True):
        lines = slip_lines(told, plan, in_note=in_note)
        (line,) = [line for line in lines if "with friction" in line]
        assert f"fits the arrows of the groups cut free with friction of position {NUMBER}" in line
        assert not any(NEARER in line for line in lines), lines


def test_readings_off_no_drawing_the_run_knows_are_still_told_nearer_the_polygons_with_friction():
    analysis, plan, _ = _analysis()
    for in_note in (False, True):
        lines = slip_lines(analysis, plan, in_note=in_note)
        (line,) = [line for line in lines if NEARER in line]
        assert f"R12 = {_exact()['R12'][1]:.1f} N" in line
        assert not any("fits the" in line for line in lines)
