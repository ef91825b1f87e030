"""The public contract read as a user who scripts against it: docs/scene-format.md and its extensions' page
against the results.json of every fixture and every starter, and against the keys the reader takes.

Each scene's results are made as `graphplan run` makes them (the same pieces, the same writer), so the walk
reads the file a user would read; one test checks that the command line writes those very bytes.
"""

from __future__ import annotations

import ast
import cmath
import json
import math
import re
import tomllib
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from markdown_it import MarkdownIt

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.deliverables import chosen, document
from graphplan.errors import GraphplanError
from graphplan.report.results import dumps
from graphplan.starters import KINDS, starter

ROOT = Path(__file__).resolve().parent.parent
CONTRACT = ROOT / "docs" / "scene-format.md"
EXTENSIONS = ROOT / "docs" / "scene-format-extensions.md"
FIXTURES = sorted((ROOT / "fixtures").glob("*.toml"))
SCENES = [*(f"fixture:{path.stem}" for path in FIXTURES), *(f"starter:{kind}" for kind in KINDS)]


def scene_text(name: str) -> str:
    source, stem = name.split(":")
    return starter(stem) if source == "starter" else (ROOT / "fixtures" / f"{stem}.toml").read_text(encoding="utf-8")


@cache
def tables_of(name: str) -> dict:
    """The scene's TOML tables, as a user's script would read them beside the results."""
    return tomllib.loads(scene_text(name))


@cache
def outcome(name: str) -> tuple[dict, bytes]:
    """The scene's TOML tables and the bytes of the results.json a default run of it writes."""
    scene = graphplan.scene.loads(scene_text(name))
    analysis = analyse(scene) if scene.has_linkage else None
    return tables_of(name), dumps(document(scene, analysis, chosen(scene, analysis))).encode("utf-8")


def strict(raw: bytes):
    """results.json as a strict parser reads it: UTF-8, and no NaN or Infinity, which JSON has no word for."""
    def refuse(word):
        raise ValueError(f"{word} is no JSON number")
    return json.loads(raw.decode("utf-8"), parse_constant=refuse)


def results_of(name: str) -> dict:
    return strict(outcome(name)[1])


# --- the documents ------------------------------------------------------------------------------------------------


@cache
def code_spans_by_row() -> dict[str, list[tuple[list[str], list[str]]]]:
    """Each section's table rows of the extensions' page as (the first cell's code spans, every code span of the
    row), read by a Markdown parser: a cell's `` ` `` or `\\|` would throw a hand-made pairing of backquotes out."""
    tokens = MarkdownIt("commonmark").enable("table").parse(EXTENSIONS.read_text(encoding="utf-8"))
    sections: dict[str, list[tuple[list[str], list[str]]]] = {}
    heading, row, cell = "", None, None
    for k, token in enumerate(tokens):
        if token.type == "inline" and tokens[k - 1].type == "heading_open":
            heading = token.content
        elif token.type == "tr_open":
            row = []
        elif token.type in ("td_open", "th_open"):
            cell = []
        elif token.type == "inline" and cell is not None:
            cell += [child.content for child in token.children if child.type == "code_inline"]
        elif token.type in ("td_close", "th_close"):
            row.append(cell)
            cell = None
        elif token.type == "tr_close":
            sections.setdefault(heading, []).append((row[0], [span for spans in row for span in spans]))
            row = None
    return sections


# Objects whose keys are the scene's own names (points, links, reactions, the plans' letters and values, the groups'
# labels, the friction pairs' loads), or the packages of `versions`: their keys are data, not the contract's words.
NAMED_BY_THE_SCENE = {"points", "links", "reactions", "points_mm", "values", "polygon_scales", "offsets", "loads",
                      "versions", "same_as"}


def key_paths(node, path: str = ""):
    """Every key of a results document as a path (`positions[].forces.reactions.*`), keys named by the scene
    written `*`."""
    if isinstance(node, dict):
        named = path.rsplit(".", 1)[-1] in NAMED_BY_THE_SCENE and path != ""
        for key, value in node.items():
            here = f"{path}.*" if named else f"{path}.{key}"
            if not named:
                yield here
            yield from key_paths(value, here)
    elif isinstance(node, list):
        for value in node:
            yield from key_paths(value, f"{path}[]")


@cache
def contract_paths() -> frozenset[str]:
    example = re.search(r"```json\n(.*?)```", CONTRACT.read_text(encoding="utf-8"), flags=re.DOTALL)[1]
    return frozenset(key_paths(json.loads(example)))


def words(span: str) -> set[str]:
    return set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", span))


def documented(path: str) -> bool:
    """A results key is documented where the contract's example shows it at that path, or where a row of the
    extensions' Results table for it or for an object it lies in names it in code (`omega_max`; a suffix the row
    gives for several keys, `_exact`, counts for the key it ends)."""
    if path in contract_paths():
        return True
    bare, leaf = path.lstrip("."), path.rsplit(".", 1)[-1]
    for first, spans in code_spans_by_row()["Results"]:
        for key in first:
            key = key.split(" ")[0].removesuffix("[]")
            if bare == key or bare.startswith((f"{key}.", f"{key}[]")):
                named = set().union(*(words(span) for span in spans))
                if leaf in named or any(leaf.endswith(word) and word.startswith("_") for word in named):
                    return True
    return False


# --- 1. every key written is documented -----------------------------------------------------------------------------


@pytest.mark.parametrize("name", SCENES)
def test_every_results_key_is_documented(name):
    found = sorted({path for path in key_paths(results_of(name)) if not documented(path)})
    assert not found, f"results.json keys no document names where they stand: {found}"


def test_the_command_line_writes_the_results_these_tests_walk(tmp_path, capsys):
    """The file on disk is the bytes the walk reads, UTF-8 whatever the platform's encoding: a Russian title's
    letters as they are."""
    scene = tmp_path / "slider-crank.toml"
    scene.write_text(starter("slider-crank", "ru"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "positions,forces,errors"]) == 0
    loaded = graphplan.scene.loads(scene.read_text(encoding="utf-8"))
    analysis = analyse(loaded)
    expected = dumps(document(loaded, analysis, chosen(loaded, analysis, ["positions", "forces", "errors"])))
    written = (tmp_path / "out" / "results.json").read_bytes()
    assert written == expected.encode("utf-8")
    title = strict(written)["scene"]
    assert title == loaded.title and re.search("[а-яА-Я]", title)


# --- 2. the keys promised for a scene of its kind, with their shapes --------------------------------------------------


def is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def is_xy(value) -> bool:
    return isinstance(value, list) and len(value) == 2 and all(is_number(x) for x in value)


def position_numbers(tables: dict) -> list[int]:
    positions = tables.get("positions", {})
    first = positions.get("number_from", 1)
    return list(range(first, first + positions.get("count", 12)))


def listed(tables: dict, key: str) -> list[int]:
    value = tables.get("positions", {}).get(key, [])
    return position_numbers(tables) if value == "all" else list(value)


def point_names(tables: dict) -> set[str]:
    """The points a scene names: the joints of its driver and groups and its `[points]`."""
    names = {tables["driver"]["joint"], *tables.get("points", {})}
    for group in tables.get("groups", []):
        names |= set(group["joints"])
    return names


def has_force_analysis(tables: dict) -> bool:
    return bool(tables.get("loads")) or any(link.get("mass", 0) > 0 for link in tables.get("links", {}).values())


LINKAGES = [name for name in SCENES if "driver" in tables_of(name)]


@pytest.mark.parametrize("name", SCENES)
def test_the_head_of_every_results_file_is_as_documented(name):
    tables, results = tables_of(name), results_of(name)
    assert isinstance(results["graphplan"], str) and results["scene"] == tables["scene"]["title"]
    assert {"python", "graphplan", "numpy", "scipy", "shapely", "svgwrite"} <= set(results["versions"])
    assert all(isinstance(version, str) for version in results["versions"].values())
    for section in ("dynamics", "balancing", "vibration"):
        assert (section in results) == (section in tables), section
    for section in ("balancing", "vibration"):
        if section in results:   # "always a list (empty where there is nothing to warn of), each {code, detail}"
            assert isinstance(results[section]["warnings"], list)
            assert all(set(w) == {"code", "detail"} for w in results[section]["warnings"])


@pytest.mark.parametrize("name", LINKAGES)
def test_every_position_holds_what_the_contract_promises(name):
    tables, results = tables_of(name), results_of(name)
    driver = tables["driver"]
    assert isinstance(results["structure"], str)
    assert set(results["degrees_of_freedom"]) == {"moving_links", "lower_pairs", "W"}
    assert [group["links"] for group in results["groups"]] == [group["links"] for group in tables.get("groups", [])]
    assert all(set(group) == {"label", "kind", "links", "joints"} for group in results["groups"])
    numbers = position_numbers(tables)
    assert [entry["index"] for entry in results["positions"]] == numbers   # index follows number_from
    moving = {str(driver["link"]), *(str(n) for group in tables.get("groups", []) for n in group["links"])}
    forces, plans, velocity_plans = has_force_analysis(tables), listed(tables, "plans"), listed(tables, "velocity_plans")
    driver_keys = {"angle_deg", "omega", "epsilon"} if driver["kind"] == "crank" else {
        "displacement", "velocity", "acceleration"}
    for entry in results["positions"]:
        assert set(entry["driver"]) == driver_keys
        assert point_names(tables) <= set(entry["points"]), entry["index"]
        for point in entry["points"].values():
            assert set(point) == {"r", "v", "a"} and is_xy(point["r"])
        assert moving <= set(entry["links"])
        for link in entry["links"].values():
            assert set(link) == {"angle_deg", "omega", "epsilon"} and -180 < link["angle_deg"] <= 180
        assert ("plans" in entry) == (entry["index"] in plans), entry["index"]
        if "plans" in entry:
            assert set(entry["plans"]) == {"velocity", "acceleration"}
            for plan in entry["plans"].values():
                # same_as: where a link's ε is another's reading (an RPR's rod), beside the values.
                assert set(plan) - {"same_as"} == {"scale", "points_mm", "values"} and plan["scale"] > 0
                assert all(is_xy(mm) for mm in plan["points_mm"].values())
            assert ("forces" in entry) == forces
        if "forces" in entry:
            balancing = "balancing_moment" if driver["kind"] == "crank" else "balancing_force"
            assert {"reactions", balancing, f"lever_{balancing}", "polygon_scale", "polygon_scales"} <= set(
                entry["forces"])
            assert all(is_xy(force) for force in entry["forces"]["reactions"].values())
            # Each group's polygon and the driving link's, by the labels `groups` and `structure` give them; the
            # position's one μF the coarsest, unless the scene sets one for all.
            scales = entry["forces"]["polygon_scales"]
            labels = {group["label"] for group in results["groups"]} | {results["structure"].split(" → ")[0]}
            assert set(scales) == labels
            assert entry["forces"]["polygon_scale"] == tables.get("drawing", {}).get("force_scale", max(scales.values()))
            polygons, lever = entry["forces"][balancing], entry["forces"][f"lever_{balancing}"]
            parted = 100 * (lever - polygons) / polygons if polygons else 0.0
            assert entry["forces"]["lever_difference_percent"] == pytest.approx(parted, abs=1e-8)
        assert ("velocity_plan" in entry) == (entry["index"] in velocity_plans)
        if "velocity_plan" in entry:   # "as plans.velocity has them"
            assert set(entry["velocity_plan"]) == {"scale", "points_mm", "values"}
        assert ("equilibrium" in entry) == forces
        for slide in entry.get("slides", []):
            assert set(slide) == {"slider", "guide", "joint", "velocity", "acceleration"}
        # A slider's travel or a swing has strokes but no crank angles of extremes; a link turning round, neither.
        if "extremes_deg" in results:
            assert "stroke" in entry
        if "stroke" in entry:
            assert entry["stroke"] in ("working", "idle") and "working" in tables["positions"]
    for warning in results["warnings"]:
        assert set(warning) == {"position", "code", "detail"} and warning["position"] in numbers
    for row in results["errors"]:
        assert set(row) == {"position", "quantity", "analytic", "plan", "source", "percent"}
        assert row["source"] in ("construction", "drafting", "measured")
        assert row["position"] in {*plans, *velocity_plans}   # numbered as `index` is, a position with a plan
        if row["analytic"]:   # δ = (analytic − plan)/analytic·100, the sign of the contract's example
            relative = 100 * (row["analytic"] - row["plan"]) / row["analytic"]
            assert row["percent"] == pytest.approx(relative, rel=1e-6, abs=1e-7), row
    if "extremes_deg" in results:
        assert len(results["extremes_deg"]) == 2 and set(results["strokes"]) == {"working_deg", "idle_deg",
                                                                                  "time_ratio"}
        working, idle = results["strokes"]["working_deg"], results["strokes"]["idle_deg"]
        assert working + idle == pytest.approx(360.0)
        assert results["strokes"]["time_ratio"] == pytest.approx(working / idle)


@pytest.mark.parametrize("name", [name for name in SCENES if "dynamics" in tables_of(name)])
def test_the_dynamics_samples_are_lists_over_the_cycle(name):
    dynamics = results_of(name)["dynamics"]
    coordinate = dynamics.get("angle_deg", dynamics.get("displacement"))
    for key in ("travel", "reduced_inertia", "reduced_moment", "driving_moment", "resisting_moment", "driving_work",
                "resisting_work", "kinetic_energy_change"):
        assert len(dynamics[key]) == len(coordinate) and all(is_number(x) for x in dynamics[key]), key
    assert dynamics["reduced_moment"] == pytest.approx(
        [d + r for d, r in zip(dynamics["driving_moment"], dynamics["resisting_moment"], strict=True)])


@pytest.mark.parametrize("name", [name for name in SCENES if "balancing" in tables_of(name)])
def test_the_balancing_gives_a_correction_per_plane(name):
    tables, balancing = tables_of(name)["balancing"], results_of(name)["balancing"]
    planes = balancing["planes"]
    assert len(planes) == len(tables.get("planes", [0.0])) and balancing["kind"] == (
        "dynamic" if len(planes) == 2 else "static")
    for plane in planes:
        assert {"plane", "position", "mass_radius", "angle_deg"} <= set(plane)
        assert ("mass" in plane) == ("radius" in plane) == ("correction_radius" in tables)


# --- 1. the units the documents state, against independent calculations ---------------------------------------------


def crank_speed(driver: dict) -> float:
    return driver["omega"] if "omega" in driver else driver["rpm"] * 2 * math.pi / 60


def vector(xy) -> complex:
    return complex(*xy)


CRANKS = [name for name in LINKAGES if tables_of(name)["driver"]["kind"] == "crank"]


@pytest.mark.parametrize("name", CRANKS)
def test_the_crank_pin_moves_at_omega_times_the_crank_length(name):
    """r in m, v in m/s and a in m/s² of the crank pin, from the scene's length and speed alone: v = ω·l, square to
    the crank, at the crank angle the results give in degrees."""
    tables, results = tables_of(name), results_of(name)
    driver = tables["driver"]
    omega, epsilon, length = crank_speed(driver), driver.get("epsilon", 0.0), driver["length"]
    pivot = vector(tables["frame"]["points"][driver["pivot"]])
    for entry in results["positions"]:
        assert entry["driver"]["omega"] == pytest.approx(omega, rel=1e-11)
        assert entry["driver"]["epsilon"] == pytest.approx(epsilon, abs=1e-11)
        assert 0 <= entry["driver"]["angle_deg"] < 360
        crank = length * cmath.exp(1j * math.radians(entry["driver"]["angle_deg"]))
        pin = entry["points"][driver["joint"]]
        scale = abs(omega) * length + abs(epsilon) * length + omega * omega * length
        assert abs(vector(pin["r"]) - pivot - crank) < 1e-9 * length
        assert abs(vector(pin["v"]) - 1j * omega * crank) < 1e-9 * scale
        assert abs(vector(pin["a"]) - (1j * epsilon - omega * omega) * crank) < 1e-9 * scale
        turned = entry["links"][str(driver["link"])]["angle_deg"] - entry["driver"]["angle_deg"]
        assert math.remainder(turned, 360.0) == pytest.approx(0.0, abs=1e-9)


@pytest.mark.parametrize("name", [name for name in LINKAGES if name not in CRANKS])
def test_a_driving_slider_s_joint_moves_at_its_velocity(name):
    tables, results = tables_of(name), results_of(name)
    driver = tables["driver"]
    for entry in results["positions"]:
        assert entry["driver"]["velocity"] == pytest.approx(driver["velocity"])
        assert abs(vector(entry["points"][driver["joint"]]["v"])) == pytest.approx(abs(driver["velocity"]), rel=1e-9)


def binary_links(tables: dict):
    """(link, from, to) of each RRR group's links, as the extensions' page names their reference lines."""
    for group in tables.get("groups", []):
        if group["kind"] == "RRR":
            a, b = group["links"]
            first, inner, last = group["joints"]
            yield a, first, inner
            yield b, last, inner


@pytest.mark.parametrize("name", [name for name in LINKAGES if any(binary_links(tables_of(name)))])
def test_a_link_s_angle_omega_and_epsilon_are_degrees_rad_s_and_rad_s2(name):
    """Two points of a link move as a rigid body: vB − vA = ω × AB and aB − aA = ε × AB − ω²·AB, AB at the link's
    angle in degrees."""
    tables, results = tables_of(name), results_of(name)
    for entry in results["positions"]:
        for link, start, end in binary_links(tables):
            a, b, turning = entry["points"][start], entry["points"][end], entry["links"][str(link)]
            arm = vector(b["r"]) - vector(a["r"])
            assert math.remainder(math.degrees(cmath.phase(arm)) - turning["angle_deg"], 360) == pytest.approx(
                0, abs=1e-8)
            if turning["omega"] is None:   # a singular position: no velocities past the driver
                continue
            omega, epsilon = turning["omega"], turning["epsilon"]
            speed = abs(vector(a["v"])) + abs(omega * arm)
            assert abs(vector(b["v"]) - vector(a["v"]) - 1j * omega * arm) <= 1e-8 * speed
            rate = abs(vector(a["a"])) + abs(epsilon * arm) + omega * omega * abs(arm)
            assert abs(vector(b["a"]) - vector(a["a"]) - (1j * epsilon - omega * omega) * arm) <= 1e-8 * rate


@pytest.mark.parametrize("name", [name for name in LINKAGES if listed(tables_of(name), "plans")])
def test_a_plan_s_scale_and_values_are_in_m_s_per_mm_and_m_s(name):
    """μV times the pole's segment to the driver's joint is that joint's speed; a plan's `VB` is |vB|, m/s."""
    tables, results = tables_of(name), results_of(name)
    joint = tables["driver"]["joint"]
    for entry in results["positions"]:
        if "plans" not in entry:
            continue
        plan, points = entry["plans"]["velocity"], entry["points"]
        drawn = vector(plan["points_mm"][joint.lower()]) - vector(plan["points_mm"]["p"])
        assert plan["scale"] * abs(drawn) == pytest.approx(abs(vector(points[joint]["v"])), rel=1e-9)
        speeds = {quantity[1:]: value for quantity, value in plan["values"].items() if quantity[1:] in points}
        assert speeds
        for point, value in speeds.items():
            assert value == pytest.approx(abs(vector(points[point]["v"])), rel=1e-6, abs=1e-9), point
        rates = entry["plans"]["acceleration"]["values"]
        for quantity, value in rates.items():
            if quantity[1:] in points:
                assert value == pytest.approx(abs(vector(points[quantity[1:]]["a"])), rel=1e-6, abs=1e-9), quantity
        # ω and ε read off the plans are signed, counter-clockwise positive, as the links' are: rad/s and rad/s².
        for values, key in ((plan["values"], "omega"), (rates, "epsilon")):
            for quantity, value in values.items():
                link = quantity.removeprefix(key)
                if quantity.startswith(key) and link in entry["links"]:
                    assert value == pytest.approx(entry["links"][link][key], rel=1e-6, abs=1e-9), quantity


FLYWHEELS = [name for name in SCENES if "delta" in tables_of(name).get("dynamics", {})]


@pytest.mark.parametrize("name", FLYWHEELS)
def test_the_flywheel_s_numbers_are_in_their_documented_units(name):
    """`travel` in rad (the one angle in radians), speeds in rad/s, inertias in kg·m², energies in J: the speed at
    the first sample is √(2·T0/(Je + JF)), and JF on a shaft at n′ rpm is JF·(n/n′)²."""
    tables, dynamics = tables_of(name)["dynamics"], results_of(name)["dynamics"]
    travel, angles = np.array(dynamics["travel"]), np.radians(dynamics["angle_deg"])
    turned = np.abs(np.unwrap(angles) - angles[0])
    assert travel == pytest.approx(turned, abs=1e-9)
    assert travel[-1] == pytest.approx(2 * math.pi)
    speeds = np.array(dynamics["omega"])
    mounted = dynamics["flywheel_inertia"]
    start = 0.5 * (dynamics["reduced_inertia"][0] + mounted) * speeds[0] ** 2
    assert dynamics["kinetic_energy_start"] == pytest.approx(start, rel=1e-9)
    assert (dynamics["omega_max"], dynamics["omega_min"]) == (speeds.max(), speeds.min())
    assert dynamics["delta_reached"] == pytest.approx((speeds.max() - speeds.min()) / dynamics["omega_mean"])
    fastest = int(np.argmax(speeds[:-1]))
    assert dynamics["omega_max_angle_deg"] == pytest.approx(dynamics["angle_deg"][fastest])
    assert dynamics["omega_max_travel_deg"] == pytest.approx(math.degrees(travel[fastest]))
    assert dynamics["delta_w_max"] == pytest.approx(np.ptp(dynamics["kinetic_energy_change"]))
    if "flywheel_shaft_rpm" in tables:
        mean_rpm = dynamics["omega_mean"] * 60 / (2 * math.pi)
        assert dynamics["flywheel_shaft_rpm"] == tables["flywheel_shaft_rpm"]
        assert dynamics["flywheel_inertia_moved"] == pytest.approx(
            mounted * (mean_rpm / tables["flywheel_shaft_rpm"]) ** 2, rel=1e-9)


@pytest.mark.parametrize("name", [name for name in SCENES if "balancing" in tables_of(name)])
def test_the_balancing_mass_radii_are_kg_m_and_balance_the_rotor(name):
    """|Σ m·r| in kg·m and |Σ m·r·z| in kg·m² from the scene's masses; the corrections at their angles in degrees
    cancel both; a correction's mass is its m·r over its radius."""
    tables, balancing = tables_of(name)["balancing"], results_of(name)["balancing"]
    products = [(m["mass"] * m["radius"] * cmath.exp(1j * math.radians(m.get("angle", 0.0))), m.get("plane", 0.0))
                for m in tables["masses"]]
    force, moment = sum(p for p, _ in products), sum(p * z for p, z in products)
    unbalance = balancing["unbalance"]
    assert unbalance["mass_radius"] == pytest.approx(abs(force), rel=1e-9)
    assert unbalance["moment"] == pytest.approx(abs(moment), rel=1e-9)
    assert math.remainder(unbalance["angle_deg"] - math.degrees(cmath.phase(force)), 360) == pytest.approx(0, abs=1e-8)
    corrections = [(plane["mass_radius"] * cmath.exp(1j * math.radians(plane["angle_deg"])), plane["position"])
                   for plane in balancing["planes"]]
    assert abs(force + sum(c for c, _ in corrections)) < 1e-9 * abs(force)
    if len(corrections) == 2:
        assert abs(moment + sum(c * z for c, z in corrections)) < 1e-9 * abs(force)
    for plane in balancing["planes"]:
        if "mass" in plane:
            assert plane["mass"] * plane["radius"] == pytest.approx(plane["mass_radius"])


@pytest.mark.parametrize("name", [name for name in SCENES if "vibration" in tables_of(name)])
def test_the_vibration_s_numbers_are_in_their_documented_units(name):
    """ωn = √(k/M) in rad/s, the critical speed in rpm, m·e·ω² in N, the amplitude in m from the textbook's
    magnification, the isolating stiffness M·(ω/r)² in N/m."""
    tables, vibration = tables_of(name)["vibration"], results_of(name)["vibration"]
    mass, stiffness, zeta = tables["mass"], tables["stiffness"], tables["damping_ratio"]
    omega = tables["omega"] if "omega" in tables else tables["rpm"] * 2 * math.pi / 60
    natural = math.sqrt(stiffness / mass)
    ratio = omega / natural
    assert vibration["natural_frequency"] == pytest.approx(natural) == vibration["critical_speed"]
    assert vibration["critical_speed_rpm"] == pytest.approx(natural * 60 / (2 * math.pi))
    assert vibration["frequency_ratio"] == pytest.approx(ratio)
    assert vibration["exciting_force"] == pytest.approx(tables["unbalance"] * omega ** 2)
    magnification = ratio ** 2 / math.hypot(1 - ratio ** 2, 2 * zeta * ratio)
    assert vibration["magnification"] == pytest.approx(magnification)
    assert vibration["amplitude"] == pytest.approx(tables["unbalance"] / mass * magnification)
    assert vibration["transmissibility"] == pytest.approx(
        math.hypot(1, 2 * zeta * ratio) / math.hypot(1 - ratio ** 2, 2 * zeta * ratio))
    assert vibration["phase_deg"] == pytest.approx(math.degrees(math.atan2(2 * zeta * ratio, 1 - ratio ** 2)))
    assert vibration["transmitted_force"] == pytest.approx(vibration["transmissibility"] * vibration["exciting_force"])
    isolation = vibration["isolation"]
    assert isolation["stiffness"] == pytest.approx(mass * (omega / isolation["frequency_ratio"]) ** 2)


# --- 4. strict JSON, UTF-8, numbers as the page says -----------------------------------------------------------------


def numbers_in(node):
    if isinstance(node, dict):
        for value in node.values():
            yield from numbers_in(value)
    elif isinstance(node, list):
        for value in node:
            yield from numbers_in(value)
    elif is_number(node):
        yield node


@pytest.mark.parametrize("name", SCENES)
def test_the_results_are_strict_utf8_json_with_finite_numbers_of_12_digits(name):
    raw = outcome(name)[1]
    raw.decode("utf-8", errors="strict")
    results = strict(raw)   # no NaN, Infinity or -Infinity anywhere
    for value in numbers_in(results):
        assert math.isfinite(value)
        assert float(f"{value:.12g}") == value, value   # "rounded to 12 significant digits"


# --- 3. the scene keys: documented ones read, read ones documented, unknown ones refused by name ---------------------


# The methods of graphplan.reader.Table that take a key of the scene.
READING = {"raw", "take", "number", "speed", "integer", "string", "date", "boolean", "choice", "xy", "table", "items",
           "numbers", "names", "has", "misspelt"}


@cache
def parsed_sources() -> tuple[tuple[Path, ast.Module], ...]:
    return tuple((path, ast.parse(path.read_text(encoding="utf-8"))) for path in sorted((ROOT / "graphplan").rglob("*.py")))


@cache
def keys_the_reader_takes() -> dict[str, str]:
    """Each key a module of graphplan reads off a scene's table by name, with one place it does."""
    taken: dict[str, str] = {}
    for path, tree in parsed_sources():
        for node in ast.walk(tree):
            if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr in READING):
                continue
            named = [*node.args[:1], *(kw.value for kw in node.keywords if kw.arg in ("omega_key", "rpm_key"))]
            for argument in named:
                if isinstance(argument, ast.Constant) and isinstance(argument.value, str):
                    taken.setdefault(argument.value, f"{path.relative_to(ROOT)}:{node.lineno}")
    return taken


@cache
def words_in_code() -> set[str]:
    """Every word the two pages write in code: their examples' keys and the keys their tables name."""
    found: set[str] = set()
    for page in (CONTRACT, EXTENSIONS):
        tokens = MarkdownIt("commonmark").enable("table").parse(page.read_text(encoding="utf-8"))
        for token in tokens:
            if token.type == "fence":
                found |= words(token.content)
            for child in token.children or ():
                if child.type == "code_inline":
                    found |= words(child.content)
    return found


def test_every_key_the_reader_takes_is_documented():
    assert len(keys_the_reader_takes()) > 100
    unnamed = {key: where for key, where in keys_the_reader_takes().items() if key not in words_in_code()}
    assert not unnamed, f"scene keys read but named in neither page: {unnamed}"


def test_every_scene_key_the_extensions_page_names_is_one_the_reader_knows():
    """The keys in the first column of the Scene table (`[drawing] force_scale`, `lines = { NAME = … }`) are strings
    graphplan's reading code holds: a key no code names is one no scene can give."""
    strings = set()
    for _, tree in parsed_sources():
        strings |= {node.value for node in ast.walk(tree)
                    if isinstance(node, ast.Constant) and isinstance(node.value, str)}
    named = set()
    for first, _ in code_spans_by_row()["Scene"]:
        for span in first:
            named |= set(re.findall(r"([a-z_][a-z0-9_]*)\s*=", span))
            named |= set(re.findall(r"^\[+[a-z_.N]+\]+\s+([a-z_]+)", span))
            if re.fullmatch(r"[a-z_]+", span):
                named.add(span)
    assert len(named) > 50
    assert not named - strings, sorted(named - strings)


def tables_in(node, path=()):
    if isinstance(node, dict):
        yield path
        for key, value in node.items():
            yield from tables_in(value, (*path, key))
    elif isinstance(node, list):
        for index, value in enumerate(node):
            yield from tables_in(value, (*path, index))


def refuses_a_stray_key_in_every_table(tables: dict) -> None:
    """A key added to any table of the scene is refused with its name; a `[measured.N]` plan's readings, which take
    any segment's name, by the analysis that looks the segment up on the plan."""
    import copy

    for path in tables_in(tables):
        scene = copy.deepcopy(tables)
        table = scene
        for key in path:
            table = table[key]
        table["stray_key"] = 1.0
        with pytest.raises(GraphplanError) as refused:
            loaded = graphplan.load(scene)
            if loaded.has_linkage:
                analyse(loaded)
        assert "stray_key" in str(refused.value), (path, str(refused.value))


@pytest.mark.parametrize("name", SCENES)
def test_an_unknown_key_in_any_table_is_refused_naming_it(name):
    refuses_a_stray_key_in_every_table(tables_of(name))


def test_the_keys_the_pages_add_beyond_the_fixtures_are_taken():
    """Keys of the extensions' Scene table that no fixture or starter gives, on the crank-rocker starter: read, and
    read as the page says."""
    import datetime

    tables = tomllib.loads(starter("crank-rocker"))
    plan = tables["positions"]["plans"][0]
    tables["project"] = {"author": "A. Student", "checked_by": "B", "approved_by": "C", "organization": "D",
                         "designation": "E", "date": datetime.date(2026, 12, 1)}
    tables["forces"] = {"inertia": "displaced"}
    del tables["drawing"]["velocity_pole"], tables["drawing"]["acceleration_pole"]
    tables["drawing"].update(velocity_scale=0.02, acceleration_scale=0.5, force_scale=20.0, velocity_plans_pole=50.0,
                             length_scale=0.005)
    tables["positions"]["velocity_plans"] = "all"
    tables["output"] = {"include": ["positions", "velocity", "forces", "errors", "diagrams", "load_diagrams"]}
    tables["loads"][0]["stroke"] = {"link": 4, "sense": tables["positions"]["working"]["sense"]}
    tables["loads"].append({"kind": "force", "link": 3, "point": "S3", "angle": 90.0, "resisting": False,
                            "diagram": [[0.0, 1.0], [1.0, 2.0]]})
    tables["measured"] = {str(plan): {"velocity": {"pa": 100.0}, "balancing": 10.0}}
    tables["friction"] = [{"joint": "A", "f": 0.1, "radius": 0.01}]
    tables["dynamics"] = {"count": 72}
    scene = graphplan.load(tables)
    analyse(scene)
    assert scene.project.author == "A. Student" and scene.inertia == "displaced"
    assert (scene.drawing.velocity_scale, scene.drawing.force_scale, scene.drawing.velocity_plans_pole) == (
        0.02, 20.0, 50.0)
    assert len(scene.positions.velocity_plans) == tables["positions"]["count"]
    assert scene.measured[plan]["balancing"] == 10.0


def flywheel_starting(start: dict, clutch: bool) -> dict:
    tables = tomllib.loads(starter("flywheel"))
    if clutch:
        tables["dynamics"]["clutch"] = {"torque": 900.0, "engage_at": 0.2, "inertia": 0.1}
    tables["dynamics"]["start"] = start
    return tables


def test_a_clutch_s_driving_half_may_start_at_a_speed_of_its_own():
    """`start.driving_omega` or `driving_rpm`, which the reader took but neither page named: the speed of the
    clutch's driving half at the start, in rad/s or rev/min, refused without a clutch."""
    from graphplan.errors import SceneError

    in_rpm = graphplan.load(flywheel_starting({"rpm": 0.0, "driving_rpm": 60.0}, clutch=True))
    assert in_rpm.dynamics.motion.start.driving_omega == pytest.approx(2 * math.pi)
    in_rad = graphplan.load(flywheel_starting({"omega": 0.0, "driving_omega": 3.0}, clutch=True))
    assert in_rad.dynamics.motion.start.driving_omega == 3.0
    with pytest.raises(SceneError, match=r"dynamics\.start\.driving_rpm: only with a clutch"):
        graphplan.load(flywheel_starting({"driving_rpm": 60.0}, clutch=False))


def test_a_scene_without_plans_writes_an_empty_list_of_errors():
    """The contract shows `errors` beside `warnings`; without plan positions the key was left out, and a script's
    results["errors"] failed where `warnings` held an empty list."""
    tables = tomllib.loads(starter("crank-rocker"))
    del tables["positions"]["plans"]
    scene = graphplan.load(tables)
    analysis = analyse(scene)
    results = strict(dumps(document(scene, analysis, chosen(scene, analysis))).encode("utf-8"))
    assert results["errors"] == [] and results["warnings"] == []


def cross(arm: complex, force: complex) -> float:
    """The moment (N·m) of ``force`` at the end of ``arm``, counter-clockwise positive."""
    return arm.real * force.imag - arm.imag * force.real


def test_the_balancing_moment_is_n_m_counter_clockwise_by_the_power_it_gives():
    """With no masses and no weight, the crank's balancing moment gives the power the resisting moment takes:
    Mb·ω2 = M·|ω4| in the working stroke (N·m, counter-clockwise positive), 0 in the idle one; and the reactions
    are named as the contract says, R23 the force of link 2 on link 3."""
    tables = tomllib.loads(starter("crank-rocker"))
    tables["scene"]["gravity"] = 0.0
    del tables["links"]
    load, = tables["loads"]
    assert (load["kind"], load["link"], load["during"], load["resisting"]) == ("moment", 4, "working", True)
    scene = graphplan.load(tables)
    analysis = analyse(scene)
    results = strict(dumps(document(scene, analysis, chosen(scene, analysis))).encode("utf-8"))
    omega = crank_speed(tables["driver"])
    for entry in results["positions"]:
        taken = load["value"] * abs(entry["links"]["4"]["omega"]) if entry["stroke"] == "working" else 0.0
        moment = entry["equilibrium"]["balancing_moment"]
        assert moment * omega == pytest.approx(taken, rel=1e-9, abs=1e-9 * load["value"]), entry["index"]
        if "forces" in entry:
            assert entry["forces"]["balancing_moment"] == pytest.approx(moment, rel=1e-9)
        # R23 is the force link 2 exerts on link 3 (N): the coupler 3 is pressed along AB by 2 and 4 alike, the
        # rocker 4 held by R34 and the frame's R14 against the moment, the crank by R12 and R32 = −R23.
        r = {name: vector(xy) for name, xy in entry["equilibrium"]["reactions"].items()}
        points = {name: vector(entry["points"][name]["r"]) for name in ("O", "A", "B", "C")}
        size = max(abs(force) for force in r.values()) or 1.0
        assert abs(r["R23"] - r["R34"]) < 1e-9 * size and abs(r["R34"] + r["R14"]) < 1e-9 * size
        assert abs(r["R12"] - r["R23"]) < 1e-9 * size
        assert abs(cross(points["B"] - points["A"], r["R23"])) < 1e-9 * size
        # Against the rocker's motion, or at its extreme the motion about to begin (ε's sense), as the page says.
        rocker = entry["links"]["4"]
        about_to = rocker["omega"] or rocker["epsilon"]
        resisting = -math.copysign(load["value"], about_to) if entry["stroke"] == "working" else 0.0
        assert resisting + cross(points["B"] - points["C"], r["R34"]) == pytest.approx(0, abs=1e-9 * load["value"])
        assert moment + cross(points["A"] - points["O"], -r["R23"]) == pytest.approx(0, abs=1e-9 * load["value"])


@pytest.mark.parametrize("name", [name for name in SCENES if "dynamics" in tables_of(name)])
def test_the_works_are_joules_over_the_travel_in_radians(name):
    """The works are the moments (N·m) integrated over `travel` (rad), the resistances' taken as positive, and ΔT
    is what the driving work leaves over them."""
    dynamics = results_of(name)["dynamics"]
    travel = np.array(dynamics["travel"])
    driving = np.array(dynamics["driving_work"])
    resisting = np.array(dynamics["resisting_work"])
    scale = max(abs(driving).max(), abs(resisting).max())
    assert driving[-1] == pytest.approx(np.trapezoid(dynamics["driving_moment"], travel), abs=1e-4 * scale)
    assert resisting[-1] == pytest.approx(-np.trapezoid(dynamics["resisting_moment"], travel), abs=1e-4 * scale)
    assert dynamics["kinetic_energy_change"] == pytest.approx(driving - resisting, abs=1e-9 * scale)


@pytest.mark.parametrize("name", [name for name in LINKAGES if tables_of(name).get("dynamics")])
def test_a_plan_s_reduced_inertia_is_kg_m2_from_the_positions_speeds(name):
    """Je = Σ (m·vS² + JS·ω²)/ω1², from the masses of the scene and the speeds results.json gives at the position."""
    tables, results = tables_of(name), results_of(name)
    positions = {entry["index"]: entry for entry in results["positions"]}
    driving = crank_speed(tables["driver"])
    plans = results["dynamics"]["plans"]
    with_a_velocity_plan = sorted({*listed(tables, "velocity_plans"), *listed(tables, "plans")})
    assert [plan["index"] for plan in plans] == with_a_velocity_plan   # "each position with a velocity plan"
    for plan in plans:
        entry = positions[plan["index"]]
        energy = sum(link["mass"] * abs(vector(entry["points"][link["centre"]]["v"])) ** 2
                     + link.get("inertia", 0.0) * entry["links"][number]["omega"] ** 2
                     for number, link in tables["links"].items())
        assert plan["reduced_inertia_exact"] == pytest.approx(energy / driving ** 2, rel=1e-9)


@pytest.mark.parametrize("name", [name for name in LINKAGES if "working" in tables_of(name).get("positions", {})])
def test_the_strokes_are_where_the_working_link_moves_in_its_sense(name):
    """A position's `stroke` is `working` where the working link moves in `positions.working.sense`; the crank turns
    `strokes.working_deg` from the first of `extremes_deg` to the second, in degrees."""
    tables, results = tables_of(name), results_of(name)
    working = tables["positions"]["working"]
    ours = [entry for entry in results["positions"] if "stroke" in entry]
    sense = 1.0 if working["sense"] in ("ccw", "forward") else -1.0
    if working["sense"] in ("ccw", "cw"):
        speeds = [entry["links"][str(working["link"])]["omega"] for entry in ours]
    else:   # a slider's velocity along its guide's direction
        speeds = [next((slide["velocity"] for slide in entry.get("slides", []) if slide["slider"] == working["link"]),
                       None) for entry in ours]
    if any(speed is not None for speed in speeds):
        largest = max(abs(speed) for speed in speeds if speed is not None)
        for entry, speed in zip(ours, speeds, strict=True):
            if speed is not None and abs(speed) > 1e-6 * largest:
                assert (entry["stroke"] == "working") == (sense * speed > 0), entry["index"]
    if "extremes_deg" in results:
        start, end = results["extremes_deg"]
        turn = 1.0 if crank_speed(tables["driver"]) > 0 else -1.0
        assert results["strokes"]["working_deg"] == pytest.approx((turn * (end - start)) % 360.0)


@pytest.mark.parametrize("name", LINKAGES)
def test_a_slider_on_the_frame_moves_at_its_slide_s_velocity(name):
    """A slide's `velocity` and `acceleration` (m/s, m/s²) relative to a frame guide are its joint's whole motion."""
    tables, results = tables_of(name), results_of(name)
    frame = tables["frame"]["link"]
    checked = 0
    for entry in results["positions"]:
        for slide in entry.get("slides", []):
            if slide["guide"] != frame or slide["velocity"] is None:
                continue
            joint = entry["points"][slide["joint"]]
            assert abs(vector(joint["v"])) == pytest.approx(abs(slide["velocity"]), rel=1e-9, abs=1e-12)
            assert abs(vector(joint["a"])) == pytest.approx(abs(slide["acceleration"]), rel=1e-9, abs=1e-12)
            checked += 1
    has_frame_slides = any(slide["guide"] == frame for entry in results["positions"] for slide in entry.get("slides", []))
    assert checked or not has_frame_slides


def scenes_beyond_the_fixtures() -> dict[str, dict]:
    """Tables no fixture or starter gives: a clutch, a brake and a start; a rotor on a shaft with named masses and
    planes; a mechanism's [project], [forces], [output], a load's stroke, hand readings of every kind, friction."""
    import datetime

    flywheel = flywheel_starting({"rpm": 0.0, "driving_rpm": 60.0, "angle_deg": 10.0}, clutch=True)
    flywheel["dynamics"]["brake"] = {"torque": 50.0, "at": 30.0}
    rotor = tomllib.loads(starter("rotor"))
    del rotor["vibration"]["stiffness"]
    rotor["vibration"]["shaft"] = {"modulus": 2.1e11, "diameter": 0.03, "length": 0.8}
    rotor["balancing"]["masses"][0]["name"] = "A"
    rotor["balancing"]["plane_names"] = ["L", "R"]
    mechanism = tomllib.loads(starter("crank-rocker"))
    plan = mechanism["positions"]["plans"][0]
    mechanism["project"] = {"author": "A", "date": datetime.date(2026, 12, 1)}
    mechanism["forces"] = {"inertia": "displaced"}
    mechanism["output"] = {"include": ["positions", "velocity", "forces", "errors"]}
    mechanism["loads"][0]["stroke"] = {"link": 4, "sense": mechanism["positions"]["working"]["sense"]}
    mechanism["measured"] = {str(plan): {"velocity": {"pa": 100.0}, "forces": {"R23": 10.0}, "balancing": 10.0}}
    mechanism["friction"] = [{"joint": "A", "f": 0.1, "radius": 0.01}]
    return {"flywheel": flywheel, "rotor": rotor, "crank-rocker": mechanism}


@pytest.mark.parametrize("name", ["flywheel", "rotor", "crank-rocker"])
def test_an_unknown_key_in_a_table_no_fixture_gives_is_refused_naming_it(name):
    tables = scenes_beyond_the_fixtures()[name]
    loaded = graphplan.load(tables)
    if loaded.has_linkage:
        analyse(loaded)   # the scene itself is taken
    refuses_a_stray_key_in_every_table(tables)


def test_the_friction_loads_are_f_times_the_reactions_against_the_motion():
    """On the shaper starter, the one scene with friction (the ram's flat guide along x and the crank's journal): a
    slide's `Ff` (N) is f·|R| against the sliding, a journal's `Mf` (N·m) f·r·|R| against the turning; η is Mb0/Mb
    where the driver drives; over the cycle η = A0/A and the friction's work is A − A0 (J)."""
    assert [name for name in LINKAGES if tables_of(name).get("friction")] == ["starter:shaper"]
    tables, results = tables_of("starter:shaper"), results_of("starter:shaper")
    frame, driver = tables["frame"]["link"], tables["driver"]["link"]
    pairs = tables["friction"]
    assert all("links" in pair or pair["joint"] == tables["driver"]["pivot"] for pair in pairs)
    checked = 0
    for entry in results["positions"]:
        friction = entry.get("forces", {}).get("friction")
        if friction is None or friction["self_locking"]:
            continue
        for pair in pairs:
            later, earlier = pair.get("links", [driver, frame])
            reaction = abs(vector(friction["reactions"][f"R{earlier}{later}"]))
            if "radius" in pair:
                moment = friction["loads"][f"Mf{earlier}{later}"]
                assert abs(moment) == pytest.approx(pair["f"] * pair["radius"] * reaction, rel=1e-9)
                assert moment * entry["links"][str(later)]["omega"] < 0   # the journal turns with the later link
            else:
                force = vector(friction["loads"][f"Ff{earlier}{later}"])
                assert abs(force) == pytest.approx(pair["f"] * reaction, rel=1e-9)
                sliding = next(slide for slide in entry["slides"] if slide["slider"] == later)
                assert abs(force.imag) <= 1e-12 * abs(force)   # the starter's ram slides along x
                assert force.real * sliding["velocity"] < 0
            checked += 1
        without, with_friction = entry["forces"]["balancing_moment"], friction["balancing_moment"]
        if without * with_friction > 0 and abs(with_friction) >= abs(without):
            assert friction["efficiency"] == pytest.approx(without / with_friction, rel=1e-9)
    assert checked
    cycle = results["cycle_efficiency"]
    assert cycle["friction_work"] == pytest.approx(cycle["work_with_friction"] - cycle["work_without_friction"])
    assert cycle["efficiency"] == pytest.approx(cycle["work_without_friction"] / cycle["work_with_friction"])


@cache
def warning_codes_written() -> dict[str, str]:
    """Each warning code graphplan can write, with one place: a position's (`PositionWarning(index, "singular", …)`) and
    a rotor's or a machine's (`code = "couple-left"` on its caution's class)."""
    codes: dict[str, str] = {}
    for path, tree in parsed_sources():
        for node in ast.walk(tree):
            code = None
            if isinstance(node, ast.Call) and getattr(node.func, "id", getattr(node.func, "attr", "")).endswith("Warning") \
                    and len(node.args) > 1 and isinstance(node.args[1], ast.Constant):
                code = node.args[1].value
            elif isinstance(node, ast.Assign) and [getattr(t, "id", "") for t in node.targets] == ["code"] \
                    and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str):
                code = node.value.value
            if code is not None:
                codes.setdefault(code, f"{path.relative_to(ROOT)}:{node.lineno}")
    return codes


def test_every_warning_code_graphplan_writes_is_documented():
    documented_codes = {code for _, spans in code_spans_by_row()["Results"] for span in spans
                        for code in re.findall(r'code = "([a-z-]+)"', span)}
    assert len(warning_codes_written()) >= 20
    unnamed = {code: where for code, where in warning_codes_written().items() if code not in documented_codes}
    assert not unnamed, unnamed


@pytest.mark.parametrize("name", SCENES)
def test_every_warning_a_results_file_holds_has_a_documented_code(name):
    results = results_of(name)
    written = [w["code"] for w in results.get("warnings", [])]
    written += [w["code"] for section in ("balancing", "vibration") for w in results.get(section, {}).get("warnings", [])]
    assert set(written) <= set(warning_codes_written())


@pytest.mark.parametrize("name", CRANKS)
def test_the_positions_are_equally_spaced_from_where_the_scene_starts_them(name):
    """`count` equally spaced driver positions in the crank's sense, the first at `start` (degrees), or at the start
    of the working stroke for `"extreme"`; a swing's from φ0 to φ1 inclusive."""
    tables, results = tables_of(name), results_of(name)
    count = tables["positions"]["count"]
    angles = np.array([entry["driver"]["angle_deg"] for entry in results["positions"]])
    if "swing" in tables["driver"]:
        first, last = tables["driver"]["swing"]
        expected = np.linspace(first, last, count)
    else:
        start = tables["positions"].get("start", 0.0)
        first = results["extremes_deg"][0] if start == "extreme" else start
        turn = 1.0 if crank_speed(tables["driver"]) > 0 else -1.0
        expected = first + turn * 360.0 / count * np.arange(count)
    apart = np.remainder(angles - expected + 180.0, 360.0) - 180.0
    assert np.abs(apart).max() < 1e-8
