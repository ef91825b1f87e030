"""The explanatory note read as a teacher marks a course project: every number the note works out is worked out
again from the note's own numbers (a segment times its scale, ω = v/l, aⁿ = ω²·l, the Coriolis term 2·ω·vrel and
its direction, similar points, m·aS and J·ε, each moment F·h and the moment equations' sums, the force polygons'
closure, Zhukovsky's lever against the polygons), and the values the note states against results.json.

Nothing here calls graphplan's own formulas again: the note is parsed as text, and results.json is the analytic
solution the note is checked against. The numbers are compared to the precision the note prints them at.
"""

from __future__ import annotations

import cmath
import dataclasses
import math
import re

import pytest
from note_lines import items_on_one_line

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import load_symbol, strings
from graphplan.report.note import note_markdown
from graphplan.report.results import results

FIXTURES = ("shaper_six_bar", "triad_with_slider", "engine_slider_crank")
LOCALES = ("en", "ru")
G = 9.81

NUMBER = r"−?\d+(?:[.,]\d+)?"
POSITION = re.compile(r"^### [\d.]+ (?:Position|Положение|位置) (\d+)")


def value(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


def places(text: str) -> float:
    """Half a unit of the last digit the note printed ``text`` to: the most its rounding can have moved it."""
    digits = text.replace("−", "").replace(",", ".")
    whole, _, fraction = digits.partition(".")
    if fraction:
        return 0.5 * 10.0 ** -len(fraction)
    # An integer of many digits is printed to about five significant figures (385490, 13222).
    return 0.5 * 10.0 ** max(0, len(whole.lstrip("0")) - 5)


def close(worked: float, printed: str, *inputs: str, rel: float = 0.0) -> bool:
    """``worked`` (from printed ``inputs``) equals ``printed`` to the rounding of both: each input's rounding
    carries through a product or quotient as its share of its size."""
    spread = sum(places(text) / abs(value(text)) for text in inputs if value(text) != 0)
    tolerance = places(printed) + abs(worked) * (spread + rel) + 1e-12
    return abs(worked - value(printed)) <= tolerance


@pytest.fixture(scope="module", params=[(name, locale) for name in FIXTURES for locale in LOCALES],
                ids=lambda param: f"{param[0]}-{param[1]}")
def read(request):
    name, locale = request.param
    scene = dataclasses.replace(graphplan.load(f"fixtures/{name}.toml"), locale=locale)
    analysis = analyse(scene)
    return scene, items_on_one_line(note_markdown(analysis), strings(locale)["semicolon"]), results(analysis)


def sections(lines: list[str]):
    """Each line with the position it belongs to and the plan it is written under (velocity, acceleration, forces)."""
    position, plan = None, None
    for line in lines:
        if match := POSITION.match(line):
            position = int(match.group(1))
            plan = "forces" if line.startswith("### 5") else None
            continue
        if line.startswith("#### "):
            lower = line.lower()
            plan = "velocity" if ("скорост" in lower or "velocity" in lower) else "acceleration"
        elif line.startswith("## "):
            position, plan = None, None
        yield position, plan, line


def position_of(document: dict, number: int) -> dict:
    return next(item for item in document["positions"] if item["index"] == number)


def plan_points(document: dict, number: int, plan: str) -> dict[str, complex]:
    points = position_of(document, number)["plans"][plan]["points_mm"]
    return {name: complex(*xy) for name, xy in points.items()}


def segment_length(points: dict[str, complex], segment: str) -> float | None:
    """The length of a segment named by its two plan letters run together (``pa4``, ``σ6b``, ``πs4``)."""
    segment = segment.replace("π", "p")
    for cut in range(1, len(segment)):
        first, second = segment[:cut], segment[cut:]
        if first in points and second in points:
            return abs(points[second] - points[first])
    return None


def scales(lines: list[str]) -> dict[tuple[int, str], float]:
    """μV and μa of each position's plans as the note states them."""
    found = {}
    for position, plan, line in sections(lines):
        if plan in ("velocity", "acceleration") and (match := re.search(rf"μ[Va] = (?:[^=(]+= )*({NUMBER}) \(", line)):
            found.setdefault((position, plan), value(match.group(1)))
    return found


def test_each_reading_is_its_segment_times_the_scale(read):
    _, lines, document = read
    checked = 0
    for position, plan, line in sections(lines):
        match = re.match(rf"- (\S+) = (\S+)·(μ[Va]) = ({NUMBER})·({NUMBER}) = ({NUMBER}) ", line)
        if not match:
            continue
        _, segment, _, length, scale, reading = match.groups()
        assert close(value(length) * value(scale), reading, length, scale), line
        measured = segment_length(plan_points(document, position, plan), segment)
        assert measured is not None, f"{segment} is no segment of the plan: {line}"
        assert value(length) == pytest.approx(measured, abs=0.006), line
        checked += 1
    assert checked > 20


def test_angular_velocities_and_accelerations_are_the_relative_term_over_the_length(read):
    _, lines, document = read
    checked = 0
    for position, _, line in sections(lines):
        match = re.match(rf"- ([ωε])(\d+) = [^=]+= [^=]+= ({NUMBER})·({NUMBER})/({NUMBER}) = ({NUMBER}) "
                         r"[^,]+, (.+?)(?:;|$)", line)
        if not match:
            continue
        kind, link, length, scale, arm, printed, sense = match.groups()
        assert close(value(length) * value(scale) / value(arm), printed, length, scale, arm), line
        exact = position_of(document, position)["links"][link]["omega" if kind == "ω" else "epsilon"]
        assert abs(exact) == pytest.approx(value(printed), rel=2e-4, abs=1e-9), line
        clockwise = sense.startswith(("clockwise", "по часовой"))
        assert clockwise == (exact < 0), line
        checked += 1
    assert checked >= 6


def test_normal_components_are_omega_squared_times_the_length_and_drawn_at_mu_a(read):
    _, lines, _ = read
    mu = scales(lines)
    checked = 0
    for position, plan, line in sections(lines):
        match = re.search(rf"\| ω\d+²·l\S+ = ({NUMBER})²·({NUMBER}) = ({NUMBER}) \S+ \| \S+ = ({NUMBER}) \|", line)
        if not match:
            continue
        omega, length, normal, drawn = match.groups()
        assert close(value(omega) ** 2 * value(length), normal, omega, omega, length), line
        assert close(value(normal) / mu[(position, "acceleration")], drawn, normal), line
        checked += 1
    assert checked >= 2


def test_coriolis_term_is_twice_omega_times_the_sliding_and_turned_in_the_sense_of_omega(read):
    scene, lines, document = read
    checked = 0
    mu = scales(lines)
    for position, plan, line in sections(lines):
        match = re.search(rf"\| a(\w+?)ᵏ \| 2·ω(\d+)·V\w+ \([^)]*\) = 2·({NUMBER})·({NUMBER}) = ({NUMBER}) \S+ "
                          rf"\| (\w)(\w) = ({NUMBER}) \| [^|]*?"
                          r"(clockwise|counter-clockwise|по часовой стрелке|против часовой стрелки)", line)
        if not match:
            continue
        _, link, omega, sliding, term, start, end, drawn, sense = match.groups()
        assert close(2 * value(omega) * value(sliding), term, omega, sliding), line
        assert close(value(term) / mu[(position, "acceleration")], drawn, term), line
        exact = position_of(document, position)
        omega_exact = exact["links"][link]["omega"]
        assert (sense in ("clockwise", "по часовой стрелке")) == (omega_exact < 0), line
        # The term as constructed (a to k on the acceleration plan) is the relative velocity (a to a4 on the
        # velocity plan) turned by 90° in the sense of ω and scaled by 2ω: 2·ω × vrel.
        velocity = plan_points(document, position, "velocity")
        acceleration = plan_points(document, position, "acceleration")
        relative = (velocity[f"{start}4"] - velocity[start]) * mu[(position, "velocity")]
        drawn_term = (acceleration[end] - acceleration[start]) * mu[(position, "acceleration")]
        assert drawn_term == pytest.approx(2 * omega_exact * 1j * relative, abs=1e-9 + 1e-6 * abs(drawn_term)), line
        checked += 1
    rpr = any(group.kind == "RPR" for group in scene.groups)
    assert checked == (2 if rpr else 0)


def test_points_by_similarity_are_in_proportion_and_where_the_plan_has_them(read):
    _, lines, document = read
    checked = 0
    for position, plan, line in sections(lines):
        if not line.startswith("- ") or plan not in ("velocity", "acceleration"):
            continue
        for segment, length, numerator, denominator, printed in re.findall(
                rf"(\S+) = \S+·l\S+/l\S+ = ({NUMBER})·({NUMBER})/({NUMBER}) = ({NUMBER}) ", line):
            assert close(value(length) * value(numerator) / value(denominator), printed, length, numerator,
                         denominator), line
            measured = segment_length(plan_points(document, position, plan), segment)
            assert measured == pytest.approx(value(printed), abs=0.006), line
            checked += 1
    assert checked >= 6


def test_inertia_loads_weights_and_moments(read):
    scene, lines, document = read
    # The inertia loads as the note's locale writes them: the Russian Fи3, Mи3 of Fu3, Mu3.
    force, moment = (load_symbol(name, strings(scene.locale)) for name in ("Fu", "Mu"))
    checked = 0
    for position, plan, line in sections(lines):
        if plan != "forces" or not line.startswith("- ") or "G" not in line:
            continue
        for name, link, left, right, printed in re.findall(
                rf"(G|{force}|{moment})(\d+) = \S+ = ({NUMBER})·({NUMBER}) = ({NUMBER}) ", line):
            data = scene.links[int(link)]
            if name == "G":
                assert value(left) == data.mass and value(right) == G
            elif name == force:
                assert value(left) == data.mass
                centre = position_of(document, position)["points"][data.centre]["a"]
                assert value(right) == pytest.approx(math.hypot(*centre), rel=1e-4), line
            else:
                assert value(left) == data.inertia
                epsilon = position_of(document, position)["links"][link]["epsilon"]
                assert value(right) == pytest.approx(abs(epsilon), rel=1e-4), line
                clockwise = re.search(rf"{moment}{link} = [^;]*?, (clockwise|по часовой стрелке)", line) is not None
                assert clockwise == (epsilon > 0), f"−J·ε turns against ε: {line}"
            assert close(value(left) * value(right), printed, left, right), line
            checked += 1
    assert checked >= 12


def moment_terms(text: str) -> list[str]:
    return [term.replace(" ", "") for term in re.findall(rf"[+−] ?{NUMBER.removeprefix('−?')}", text)]


def test_moment_equations_add_up_and_give_the_unknown(read):
    _, lines, _ = read
    checked = 0
    for _, plan, line in sections(lines):
        if plan != "forces" or not line.startswith("- "):
            continue
        moments = {}
        for found in re.finditer(rf"M\((\w+)\) = (−?)\w+·h\d* = −?({NUMBER})·({NUMBER}) = ({NUMBER}) ", line):
            _, sign, force, arm, printed = found.groups()
            assert close(value(force) * value(arm), printed.lstrip("−"), force, arm), line
            assert printed.startswith("−") == (sign == "−"), line
            moments[found.start()] = value(printed)
        for found in re.finditer(rf"M\((\w+)\) = ({NUMBER}) ", line):
            moments[found.start()] = value(found.group(2))
        moments = dict(sorted(moments.items()))
        match = re.search(rf"ΣM\S+ = (−?)(\S+?)(?:·({NUMBER}))? (.*?) = 0 ⇒ (\S+) = (−?)\(?({NUMBER})\)?"
                          rf"(?:/({NUMBER}) = ({NUMBER}))? ", line)
        if not match:
            continue
        sign, unknown, arm, rest, solved, minus, numerator, divisor, printed = match.groups()
        printed = printed or minus + numerator
        terms = [value(term) for term in moment_terms(rest)]
        assert solved == unknown, line
        # Every term of the sum is a moment worked out before it on the line, in its order.
        assert terms == pytest.approx(list(moments.values()), abs=1e-12), line
        total = sum(terms)
        coefficient = (-1.0 if sign else 1.0) * (value(arm) if arm else 1.0)
        assert close(-total / coefficient, printed, *(t for t in moment_terms(rest)), *([arm] if arm else []),
                     rel=2e-4), line
        shown = value(numerator) * (-1.0 if minus else 1.0)
        read = [numerator, *([divisor] if divisor else [])]
        assert close(shown / (value(divisor) if divisor else 1.0), printed, *read), line
        checked += 1
    assert checked >= 4


def polygon_tables(lines: list[str]):
    """Each force polygon: its μF, and its rows (name, magnitude, angle, length, role) as printed."""
    for index, line in enumerate(lines):
        match = re.search(rf"μF = ({NUMBER}) ", line)
        if not match or not line.startswith(("Force polygon", "План сил")):
            continue
        rows = []
        # Under the paragraph its table's caption, then its header and rule.
        header = next(k for k in range(index + 1, len(lines)) if lines[k].startswith("|"))
        for row in lines[header + 2:]:
            if not row.startswith("| "):
                break
            cells = [cell.strip() for cell in row.strip("|").split("|")]
            magnitude, angle = re.match(rf"({NUMBER}) ∠ ({NUMBER})°", cells[1]).groups()
            rows.append((cells[0], magnitude, angle, cells[2], cells[3]))
        yield value(match.group(1)), rows


def test_force_polygons_close_and_are_drawn_at_their_scale(read):
    scene, lines, _ = read
    text = strings(scene.locale)
    checked = 0
    for scale, rows in polygon_tables(lines):
        total, largest = 0j, 0.0
        for name, magnitude, angle, length, role in rows:
            if length == "—":   # too short to draw: under the drawings' 0.25 mm
                assert 0 < value(magnitude) / scale < 0.25, (name, magnitude)
            else:
                assert close(value(magnitude) / scale, length, magnitude), (name, length)
            if role != text["note_role_inner"]:
                total += cmath.rect(value(magnitude), math.radians(value(angle)))
                largest = max(largest, value(magnitude))
        # Each side to five figures and its angle to four: the polygon closes to about a thousandth of its sides.
        assert abs(total) <= 2e-3 * largest, rows
        checked += 1
    assert checked >= 4


def test_single_unknown_closes_the_polygon_and_two_are_found_where_their_lines_cross(read):
    scene, lines, _ = read
    text = strings(scene.locale)
    for _, rows in polygon_tables(lines):
        crossing = [name for name, *_, role in rows if role == text["note_role_closing"]]
        # Two lines of action crossing fix two unknowns at once; an unknown alone is its polygon's last side.
        assert len(crossing) in (0, 2), rows
    driver = [rows for _, rows in polygon_tables(lines) if rows[-1][0].startswith("R12")]
    assert driver and all(rows[-1][4] == text["note_role_closes"] for rows in driver)


def reaction(document: dict, number: int, name: str) -> complex:
    found = position_of(document, number)["equilibrium"]["reactions"]
    if name in found:
        return complex(*found[name])
    return -complex(*found[f"R{name[2]}{name[1]}"])


def test_reactions_found_are_the_equilibrium_of_results_json(read):
    _, lines, document = read
    checked = 0
    for position, plan, line in sections(lines):
        if plan != "forces" or not line.startswith(("Found:", "Найдено:")):
            continue
        for name, magnitude, angle in re.findall(rf"(R\d\d) = ({NUMBER}) ∠ ({NUMBER})°", line):
            exact = reaction(document, position, name)
            assert abs(exact) == pytest.approx(value(magnitude), rel=1e-4), line
            turn = (math.degrees(cmath.phase(exact)) - value(angle) + 180) % 360 - 180
            assert abs(turn) <= 0.06, line
            checked += 1
    assert checked >= 8


def test_zhukovsky_lever_sums_to_the_balancing_moment_of_the_polygons(read):
    scene, lines, document = read
    checked = 0
    lever_scale = None  # the lever's own μV where it is drawn larger than the plan, said just before its table
    crank = scene.driver.length
    # The balancing load and the lever's force as the note's locale writes them: the Russian Mу, Fу.
    mb_name, fb_name = (load_symbol(name, strings(scene.locale)) for name in ("Mb", "Fb"))
    for position, plan, line in sections(lines):
        if match := re.search(rf"μV = ({NUMBER}) \(", line):
            if plan == "forces":
                lever_scale = value(match.group(1))
            continue
        if plan != "forces" or f"{fb_name} = |Σ(F·h)|/pa" not in line:
            continue
        index = lines.index(line)
        rows = []
        for row in reversed(lines[:index - 1]):
            if not row.startswith("| "):
                break
            rows.append([cell.strip() for cell in row.strip("|").split("|")])
        rows = [row for row in reversed(rows) if re.fullmatch(NUMBER, row[2].replace("−", ""))]
        for name, _, force, arm, moment in rows:
            arm = re.sub(r"^h\S* = ", "", arm)  # the arm's length after its name on the lever, h2 = 49.19
            assert close(value(force) * value(arm), moment.lstrip("−"), force, arm), name
        total = sum(value(row[4]) for row in rows)
        summed, pa, fb, fb_again, arm, mb = re.search(
            rf"{fb_name} = \|Σ\(F·h\)\|/pa = ({NUMBER})/({NUMBER}) = ({NUMBER}) \S+ "
            rf"\|{mb_name}\| = {fb_name}·l\S+ = ({NUMBER})·({NUMBER}) = ({NUMBER}) ", line).groups()
        assert close(abs(total), summed, *(row[4] for row in rows)), line
        driver = position_of(document, position)
        velocity_a = abs(complex(*driver["points"][scene.driver.joint]["v"]))
        mu = lever_scale or position_of(document, position)["plans"]["velocity"]["scale"]
        assert close(velocity_a / mu, pa), line
        assert close(value(summed) / value(pa), fb, summed, pa) and fb == fb_again, line
        assert value(arm) == crank and close(value(fb) * crank, mb, fb, rel=1e-4), line
        assert abs(driver["equilibrium"]["balancing_moment"]) == pytest.approx(value(mb), rel=1e-5), line
        lever_scale = None
        checked += 1
    assert checked == 2


def test_balancing_moment_over_the_cycle_is_results_json(read):
    _, lines, document = read
    start = next(k for k, line in enumerate(lines) if line.startswith("### 5.3"))
    rows = [line for line in lines[start:] if re.match(rf"\| \d+ \| {NUMBER} \|$", line)]
    assert len(rows) == len(document["positions"])
    for row in rows:
        number, moment = row.strip("|").split("|")
        exact = position_of(document, int(number))["equilibrium"]["balancing_moment"]
        assert exact == pytest.approx(value(moment.strip()), rel=1e-5), row


def test_structure_and_time_ratio(read):
    _, lines, document = read
    text = "\n".join(lines)
    n, p5, p4, w = map(int, re.search(r"= 3·(\d+) − 2·(\d+) − (\d+) = (\d+)", text).groups())
    assert 3 * n - 2 * p5 - p4 == w == document["degrees_of_freedom"]["W"]
    assert (n, p5) == (document["degrees_of_freedom"]["moving_links"], document["degrees_of_freedom"]["lower_pairs"])
    working, idle, ratio, theta, ratio_again = re.search(
        rf"= ({NUMBER})°[^=]+= ({NUMBER})°.*?K = \S+ = ({NUMBER})\..*?θ = \|[^=]+= ({NUMBER})°.*?K = \(180° \+ θ\)/"
        rf"\(180° − θ\) = ({NUMBER})", text).groups()
    assert value(working) + value(idle) == pytest.approx(360, abs=0.02)
    assert value(working) == pytest.approx(document["strokes"]["working_deg"], abs=0.006)
    assert close(value(working) / value(idle), ratio, working, idle)
    assert abs(abs(value(working) - value(idle)) / 2 - value(theta)) <= places(working) + places(theta)
    assert close((180 + value(theta)) / (180 - value(theta)), ratio_again, theta) and ratio == ratio_again
    assert value(ratio) == pytest.approx(document["strokes"]["time_ratio"], abs=6e-4)


def test_time_ratio_angle_written_to_the_places_of_the_crank_angles(read):
    """θ = |φw − φi|/2 is worked from the two φ the note writes to five digits (187.7°, 213.2°: to hundredths at
    most); θ written to five digits of its own (7.7047°) claimed places those angles do not have."""
    _, lines, document = read
    text = "\n".join(lines)
    working, theta = re.search(rf"= ({NUMBER})°[^=]+= {NUMBER}°.*?θ = \|[^=]+= ({NUMBER})°", text).groups()
    whole = working.replace("−", "").replace(",", ".").partition(".")[0]
    written_places = len(theta.replace(",", ".").partition(".")[2])
    assert written_places <= 5 - len(whole), (working, theta)
    exact = abs(document["strokes"]["working_deg"] - 180.0)
    assert value(theta) == pytest.approx(exact, abs=0.5 * 10.0 ** -(5 - len(whole)) + 1e-9)


def test_error_tables_delta_and_drafting_to_the_precision(read):
    scene, lines, _ = read
    precision = scene.drawing.drafting_precision
    mu = scales(lines)
    lengths = {}
    for position, _, line in sections(lines):
        if match := re.match(rf"\| ([Va]\S*) \| (\S+) \| ({NUMBER}) \| ({NUMBER}) \| ({NUMBER}) \| \S+ \|$", line):
            lengths[(position, match.group(1))] = match.group(3)
    checked = 0
    current = None
    for line in lines:
        if match := re.search(r"(?:position|положение) (\d+)$", line):
            current = int(match.group(1))
        match = re.match(rf"\| ([Va]\w*|[ωε]\d+) \| [^|]+ \| ({NUMBER}) \| ({NUMBER}) \| ({NUMBER}) \| ({NUMBER}) \| "
                         rf"({NUMBER}) \|$", line)
        if not match or current is None:
            continue
        name, exact, built, drafted, delta_built, delta_drafted = match.groups()
        # The plan as constructed is exact: its δ is nought, whatever the printed values' last digits.
        assert abs((value(exact) - value(built)) / value(exact) * 100) <= 5e-4 + 1e-9 and value(delta_built) == 0, line
        # δ is a difference of two printed numbers: their roundings add, over the exact value.
        rounding = 100 * (places(exact) + places(drafted)) / abs(value(exact)) + places(delta_drafted)
        assert abs((value(exact) - value(drafted)) / value(exact) * 100 - value(delta_drafted)) <= rounding, line
        if name[0] in "Va" and (current, name) in lengths:
            length = lengths[(current, name)]
            per_mm = mu[(current, "velocity" if name[0] == "V" else "acceleration")]
            rounded = {round(value(length) / precision) * precision,
                       round((value(length) + 0.006) / precision) * precision,
                       round((value(length) - 0.006) / precision) * precision}
            assert any(close(step * per_mm, drafted, rel=1e-4) for step in rounded), line
        checked += 1
    assert checked >= 20


def test_error_intro_names_the_measured_column_only_where_a_table_has_one():
    for name, has in (("shaper_six_bar", False), ("ratchet_crank_rocker", True)):
        for locale in ("en", "ru", "zh"):
            scene = graphplan.load(f"fixtures/{name}.toml")
            analysis = analyse(dataclasses.replace(scene, locale=locale))
            note = note_markdown(analysis)
            text = strings(locale)
            column = f"| {text['source_measured']} |"
            assert (column in note) == has
            assert (text["note_errors_measured"] in note) == has, (name, locale)
            assert text["source_measured"] not in text["note_errors_intro"]


def test_coriolis_row_names_the_acceleration_as_the_textbooks_do(read):
    """«ускорение Кориолиса» (or «кориолисово ускорение»), not a bare adjective «кориолисово:» with no noun."""
    _, lines, _ = read
    rows = [line for line in lines if re.match(r"\| a\w+ᵏ \|", line)]
    for row in rows:
        direction = row.strip("|").split("|")[3].strip()
        assert direction.startswith(("Coriolis", "ускорение Кориолиса")), row


def test_the_strokes_paragraph_names_the_output_link_one_way(read):
    """The paragraph on the strokes and K calls link 6 one thing throughout, as the section on the kinematic
    diagrams does ("output link"), not "working link" in one sentence and "output link" in the next."""
    scene, lines, _ = read
    paragraph = next(line for line in lines if "K = φ" in line)
    kinematic_diagrams = strings(scene.locale)["kd_title"].format(link="", point="").split()
    if scene.locale == "en":
        assert "working link" not in paragraph and "output link" in " ".join(kinematic_diagrams)
    else:
        assert "Выходное звено" in paragraph
