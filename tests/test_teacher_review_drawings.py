"""A teacher's review of the drawings: what the SVG files draw (their lines, arrowheads and texts read back from the
files) against a hand calculation on the scene's own dimensions that calls none of graphplan's solvers, and against
the scales and equations the drawings write beside it."""

from __future__ import annotations

import json
import math
import re
import tomllib
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest
from shapely.geometry import LineString

from graphplan.cli import main
from graphplan.render import force_lever
from graphplan.render.primitives import Arrow

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
SVG = "{http://www.w3.org/2000/svg}"
BLUE, RED = "#1f5fa8", "#a83a1f"  # the ω and ε arcs on the mechanism
NUMBER = r"(\d+(?:[.,]\d+)?)"


def number(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


def points_of(path: str) -> np.ndarray:
    """A path's vertices in paper millimetres with y up (the SVG's y points down)."""
    return np.array([(float(x), -float(y)) for x, y in re.findall(r"[ML]\s*(-?[\d.]+),(-?[\d.]+)", path)])


class Drawing:
    """An SVG drawing read back: each group's paths, arrows (start, tip), circles and texts by the group's id."""

    def __init__(self, path: Path):
        self.groups: dict[str, dict[str, list]] = {}
        self._walk(ElementTree.parse(path).getroot(), "")

    def _group(self, name: str) -> dict[str, list]:
        return self.groups.setdefault(name, {"paths": [], "arrows": [], "circles": [], "texts": []})

    def _walk(self, element, owner: str) -> None:
        for child in element:
            tag = child.tag.removeprefix(SVG)
            if tag == "g":
                paths = [p for p in child if p.tag.removeprefix(SVG) == "path"]
                # An arrow is a group of its shaft and its filled head, whose first vertex is the tip.
                if len(child) == 2 and len(paths) == 2 and paths[1].get("d", "").endswith("Z") \
                        and len(points_of(paths[0].get("d"))) == 2:
                    arrow = (points_of(paths[0].get("d"))[0], points_of(paths[1].get("d"))[0])
                    self._group(owner)["arrows"].append(arrow)
                    if child.get("id"):
                        self._group(child.get("id"))["arrows"].append(arrow)
                else:
                    self._walk(child, child.get("id") or owner)
            elif tag == "path":
                self._group(owner)["paths"].append((points_of(child.get("d")), child.get("d").endswith("Z"),
                                                    child.get("stroke")))
            elif tag == "circle":
                self._group(owner)["circles"].append(np.array([float(child.get("cx")), -float(child.get("cy"))]))
            elif tag == "text":
                self._group(owner)["texts"].append(("".join(child.itertext()),
                                                    np.array([float(child.get("x")), -float(child.get("y"))])))

    def vector(self, key: str) -> np.ndarray:
        start, tip = self.groups[key]["arrows"][0]
        return tip - start

    def caption(self, key: str) -> str:
        return " ".join(text for text, _ in self.groups[key]["texts"])

    def scale(self, key: str, symbol: str) -> float:
        return number(re.search(rf"{symbol} = {NUMBER}", self.caption(key)).group(1))


def arcs(paths: list) -> list[dict]:
    """The curved arrows among ``paths``: each arc's centre, colour and signed sweep (counter-clockwise positive),
    its head the closed path after it."""
    found = []
    for points, closed, colour in paths:
        if closed or len(points) < 5:
            continue
        design = np.c_[2 * points, np.ones(len(points))]
        cx, cy, _ = np.linalg.lstsq(design, (points ** 2).sum(axis=1), rcond=None)[0]
        turning = np.unwrap(np.arctan2(points[:, 1] - cy, points[:, 0] - cx))
        found.append({"centre": np.array([cx, cy]), "colour": colour, "sweep": turning[-1] - turning[0]})
    return found


def nearest_label(drawing: Drawing, group: str, at: np.ndarray, pattern: str) -> str:
    labels = [(text, where) for text, where in drawing.groups[group]["texts"] if re.fullmatch(pattern, text)]
    return min(labels, key=lambda label: np.linalg.norm(label[1] - at))[0]


def run(tmp_path: Path, scene: Path, *options: str) -> Path:
    out = tmp_path / scene.stem
    assert main(["run", str(scene), "--out", str(out), *options]) == 0
    return out


# Zhukovsky's lever: the note says which way the plan is turned, and the drawing turns it that way.

SENSES = {"en": ("counter-clockwise", "clockwise"), "ru": ("против часовой стрелки", "по часовой стрелке"),
          "zh": ("逆时针", "顺时针")}


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_note_names_the_sense_the_lever_drawing_turns_the_velocity_plan(tmp_path, locale):
    out = run(tmp_path, FIXTURES / "engine_slider_crank.toml", "--only", "velocity,forces,lever,note", "--locale", locale)
    plan, forces = Drawing(out / "plan_2.svg"), Drawing(out / "forces_2.svg")
    # The velocity plan's pa and pb as drawn, and the same images on the lever, at each drawing's own μV.
    plan_scale = plan.scale("velocity-caption", "μV")
    lever_scale = forces.scale("lever-caption", "μV")
    pole = forces.groups["lever-points"]["circles"][0]
    images = [circle - pole for circle in forces.groups["lever-points"]["circles"][1:]]
    senses = set()
    for key in ("velocity-p-a", "velocity-p-b"):
        drawn = plan.vector(key) * plan_scale / lever_scale
        for sense, turned in (("clockwise", np.array([drawn[1], -drawn[0]])),
                              ("counter-clockwise", np.array([-drawn[1], drawn[0]]))):
            if min(np.linalg.norm(image - turned) for image in images) < 0.05:
                senses.add(sense)
    assert len(senses) == 1, f"the lever is the velocity plan turned neither way, or both: {senses}"
    drawn_sense = senses.pop()
    note = (out / "note.md").read_text(encoding="utf-8")
    intro = next(line for line in note.splitlines() if "90°" in line and "ΣMp" in line)
    # The sense the moments F·h count positive in, which the intro says too, is no turn of the plan.
    from graphplan.locale import strings
    intro = intro.replace(strings(locale)["note_lever_sign"], "")
    against, along = SENSES[locale]
    stated = "counter-clockwise" if against in intro else "clockwise" if along in intro else None
    assert stated == drawn_sense, f"the note's lever turns the plan {stated}, the drawing {drawn_sense}: {intro}"
    # And the drawing's own caption, for the sheet read without the note: its words may be broken over lines.
    caption = forces.caption("lever-caption")
    written = "counter-clockwise" if against in caption else "clockwise" if along in caption else None
    assert written == drawn_sense and "90°" in caption, caption


# The plan sheet of the centric slider-crank, position 2 (crank at 60° from the top dead centre, turning
# counter-clockwise at 1500 rpm), against the textbook's closed form.

def engine_by_hand(phi: float) -> dict[str, complex | float]:
    """Positions of the centric slider-crank by hand (r = 0.05 m, l = 0.19 m, the piston on +x): O, A, B, the rod's
    angle; rates by central differences over the crank angle, at ω = 1500 rpm."""
    r, l, omega = 0.05, 0.19, 1500.0 * math.pi / 30.0

    def at(angle: float) -> tuple[complex, complex, float]:
        a = r * complex(math.cos(angle), math.sin(angle))
        beta = math.asin(r * math.sin(angle) / l)
        return a, complex(a.real + l * math.cos(beta), 0.0), -beta

    h = 1e-4
    (a0, b0, t0), (a1, b1, t1), (a2, b2, t2) = at(phi - h), at(phi), at(phi + h)
    return {"A": a1, "B": b1, "omega": omega, "omega3": (t2 - t0) / (2 * h) * omega,
            "epsilon3": (t2 - 2 * t1 + t0) / h ** 2 * omega ** 2,
            "vA": (a2 - a0) / (2 * h) * omega, "vB": (b2 - b0) / (2 * h) * omega,
            "aA": (a2 - 2 * a1 + a0) / h ** 2 * omega ** 2, "aB": (b2 - 2 * b1 + b0) / h ** 2 * omega ** 2}


@pytest.fixture(scope="module")
def engine(tmp_path_factory):
    return run(tmp_path_factory.mktemp("engine"), FIXTURES / "engine_slider_crank.toml",
               "--only", "velocity,acceleration,forces")


def test_the_engine_plan_sheet_draws_its_vectors_at_the_scales_it_writes(engine):
    drawing = Drawing(engine / "plan_2.svg")
    hand = engine_by_hand(math.radians(60.0))
    mu_l = drawing.scale("mechanism-caption", "μl")
    mu_v, mu_a = drawing.scale("velocity-caption", "μV"), drawing.scale("acceleration-caption", "μa")

    def xy(value: complex) -> np.ndarray:
        return np.array([value.real, value.imag])

    # The mechanism at μl: the crank pin and the gudgeon pin from O, drawn as the links' ends.
    ends = [points for points, closed, _ in drawing.groups["mechanism-links"]["paths"] if not closed]
    crank = next(points for points in ends if abs(np.linalg.norm(points[1] - points[0]) - 50.0) < 1.0)
    pin_a, pivot = crank
    rod = next(points for points in ends if points is not crank)
    pin_b = rod[1] if np.linalg.norm(rod[0] - pin_a) < 0.01 else rod[0]
    np.testing.assert_allclose(pin_a - pivot, xy(hand["A"]) / mu_l, atol=0.01)
    np.testing.assert_allclose(pin_b - pivot, xy(hand["B"]) / mu_l, atol=0.01)
    # The velocity plan: pa ⊥ OA of VA/μV, ab ⊥ AB, pb along the guide.
    ab = hand["vB"] - hand["vA"]
    for key, value in (("velocity-p-a", hand["vA"]), ("velocity-a-b", ab), ("velocity-p-b", hand["vB"])):
        np.testing.assert_allclose(drawing.vector(key), xy(value) / mu_v, atol=0.02, err_msg=key)
    assert abs(np.dot(drawing.vector("velocity-p-a"), xy(hand["A"]))) < 1e-3 * 100 * 0.05
    # The acceleration plan: πa toward O, the normal a n3 toward A of ω3²·lAB, n3b ⊥ AB, πb along the guide.
    along_rod = hand["B"] - hand["A"]
    normal, tangential = -hand["omega3"] ** 2 * along_rod, 1j * hand["epsilon3"] * along_rod
    for key, value in (("acceleration-p-a", hand["aA"]), ("acceleration-a-n3", normal),
                       ("acceleration-n3-b", tangential), ("acceleration-p-b", hand["aB"])):
        np.testing.assert_allclose(drawing.vector(key), xy(value) / mu_a, atol=0.05, err_msg=key)
    # The arcs on the links turn as ω and ε are signed (counter-clockwise positive).
    signs = {"ω2": hand["omega"], "ω3": hand["omega3"], "ε3": hand["epsilon3"]}
    turned = arcs(drawing.groups["mechanism-senses"]["paths"])
    assert len(turned) == 3
    for arc in turned:
        name = nearest_label(drawing, "mechanism-labels", arc["centre"], "ω3|ε3" if arc["centre"][0] > 100 else "ω2")
        name = {BLUE: "ω", RED: "ε"}[arc["colour"]] + name[1:]
        assert math.copysign(1, arc["sweep"]) == math.copysign(1, signs[name]), name


# The shaper's slotted lever: the Coriolis vector of the block's pin.

def test_the_shaper_coriolis_vector_is_the_relative_velocity_turned_with_the_lever(tmp_path):
    scene = tomllib.loads((FIXTURES / "shaper_six_bar.toml").read_text(encoding="utf-8"))
    out = run(tmp_path, FIXTURES / "shaper_six_bar.toml", "--only", "velocity,acceleration")
    drawing = Drawing(out / "plan_3.svg")
    position = next(p for p in json.loads((out / "results.json").read_text())["positions"] if p["index"] == 3)
    phi, omega2 = math.radians(position["driver"]["angle_deg"]), scene["driver"]["omega"]
    frame = scene["frame"]["points"]
    centre_c, centre_o = complex(*frame["C"]), complex(*frame["O"])
    crank = scene["driver"]["length"]

    def pin(angle: float) -> complex:
        return centre_o + crank * complex(math.cos(angle), math.sin(angle))

    h = 1e-6
    lever = [math.atan2((pin(phi + k * h) - centre_c).imag, (pin(phi + k * h) - centre_c).real) for k in (-1, 1)]
    omega4 = (lever[1] - lever[0]) / (2 * h) * omega2
    a = pin(phi)
    # The pin A3 moves with the crank, the lever's point A4 under it about C; A4 relative to A3 runs along the slot.
    relative = 1j * omega4 * (a - centre_c) - 1j * omega2 * (a - centre_o)
    coriolis = 2j * omega4 * relative
    mu_a = drawing.scale("acceleration-caption", "μa")
    np.testing.assert_allclose(drawing.vector("acceleration-a-k"), [coriolis.real / mu_a, coriolis.imag / mu_a],
                               atol=0.02)
    # The relative acceleration k a4 then runs along the slot.
    slot = (a - centre_c) / abs(a - centre_c)
    along = drawing.vector("acceleration-k-a4")
    assert abs(along[0] * slot.imag - along[1] * slot.real) < 0.01


# Force sheets: polygons that close, in the equation's order, at the μF they write, as the statics finds them.

def test_the_shaper_force_polygons_close_at_their_scale_on_the_reactions_of_the_statics(tmp_path):
    out = run(tmp_path, FIXTURES / "shaper_six_bar.toml", "--only", "forces")
    drawing = Drawing(out / "forces_3.svg")
    position = next(p for p in json.loads((out / "results.json").read_text())["positions"] if p["index"] == 3)
    reactions = {name: np.array(value) for name, value in position["equilibrium"]["reactions"].items()}
    polygons: dict[str, list[tuple[str, np.ndarray, np.ndarray]]] = {}
    for key, group in drawing.groups.items():
        found = re.fullmatch(r"(polygon-[IVX]+-[\d-]+?)-(\w+)", key)
        if found and group["arrows"] and found.group(2) not in ("vectors", "lines", "leaders", "labels", "caption"):
            polygons.setdefault(found.group(1), []).append((found.group(2), *group["arrows"][0]))
    assert set(polygons) == {"polygon-II-5-6", "polygon-II-3-4-1", "polygon-II-3-4-2", "polygon-I-1-2"}
    for name, vectors in polygons.items():
        caption = name if f"{name}-caption" in drawing.groups else name.rsplit("-", 1)[0]
        mu_force = drawing.scale(f"{caption}-caption", "μF")
        links = set(caption.split("-")[2:])
        names = [vector for vector, _, _ in vectors]
        chain = np.zeros(2)
        for vector, start, tip in vectors:
            pair = re.fullmatch(r"R(\d)(\d)(tau|n)?", vector)
            inner = pair and {pair.group(1), pair.group(2)} <= links and "1" not in pair.groups()[:2] \
                and caption == name
            whole = pair and not pair.group(3) and f"{vector}tau" in names
            if not (inner or whole):
                chain += tip - start
            if pair and not pair.group(3):
                acting = pair.group(0)
                expected = reactions[acting] if acting in reactions else -reactions[f"R{pair.group(2)}{pair.group(1)}"]
                np.testing.assert_allclose((tip - start) * mu_force, expected, atol=0.3 * mu_force, err_msg=vector)
        # A vector under 0.25 mm is left out of a polygon (the block's Fu3 of 5 N at 50 N/mm): the gap it leaves
        # is within the drafting precision.
        assert np.linalg.norm(chain) < 0.25, (name, chain)
    # Each load on a group cut free points as its polygon's vector does.
    for key, group in drawing.groups.items():
        found = re.fullmatch(r"body-([IVX]+-[\d-]+?)-(G\d|Fu\d|F\d|R\d\d(?:tau|n)?)", key)
        if not found or not group["arrows"]:
            continue
        body = group["arrows"][0][1] - group["arrows"][0][0]
        twins = [f"polygon-{found.group(1)}{part}-{found.group(2)}" for part in ("", "-1", "-2")]
        twin = next((drawing.vector(name) for name in twins if name in drawing.groups), None)
        if twin is not None:
            assert np.dot(body, twin) / np.linalg.norm(body) / np.linalg.norm(twin) > 0.9999, key


# The dynamics sheet: the works integrate the moments, the energy–mass diagram's tangents at the book's slopes.

def test_the_shaper_dynamics_sheet_draws_its_integrals_and_tangents_at_the_written_scales(tmp_path):
    scene_path = tmp_path / "shaper.toml"
    assert main(["new", "shaper", "--out", str(scene_path)]) == 0
    scene = tomllib.loads(scene_path.read_text(encoding="utf-8"))
    out = run(tmp_path, scene_path, "--only", "dynamics")
    drawing = Drawing(out / "dynamics.svg")

    def curves(group: str) -> list[np.ndarray]:
        return [points for points, _, _ in drawing.groups[group]["paths"] if len(points) > 100]

    def origin(group: str) -> np.ndarray:
        return drawing.groups[group]["arrows"][0][0]

    radians_per_mm = number(re.search(rf"\({NUMBER} rad/mm\)", drawing.caption("moments")).group(1))
    mu_moment, mu_work = drawing.scale("moments", "μM"), drawing.scale("works", "μA")
    mu_energy = drawing.scale("energy", "μT")
    driving, resisting = curves("moments")[:2]
    driving_work, resisting_work = curves("works")[:2]
    phi = (driving[:, 0] - origin("moments")[0]) * radians_per_mm

    def integral(curve: np.ndarray) -> np.ndarray:
        values = (curve[:, 1] - origin("moments")[1]) * mu_moment
        return np.r_[0.0, np.cumsum((values[1:] + values[:-1]) / 2 * np.diff(phi))]

    for work, moment, sign in ((driving_work, driving, 1.0), (resisting_work, resisting, -1.0)):
        drawn = (work[:, 1] - origin("works")[1]) * mu_work
        at = (work[:, 0] - origin("works")[0]) * radians_per_mm
        # The 4 digits of μφ written and the polyline's own rounding: within 0.2 J of some 670 J.
        assert np.max(np.abs(np.interp(at, phi, sign * integral(moment)) - drawn)) < 0.3
    energy = curves("energy")[0]
    change = (energy[:, 1] - origin("energy")[1]) * mu_energy
    written = number(re.search(rf"ΔWmax = {NUMBER} J", drawing.caption("results")).group(1))
    assert abs((change.max() - change.min()) - written) < 0.05
    # Wittenbauer: tangents at tan ψ = μJ/(2μT)·ω², ω of the speed's ends ωm(1 ± δ/2), touching the curve.
    mu_inertia = drawing.scale("energy-mass", "μJ")
    omega_mean, delta = abs(scene["driver"]["rpm"]) * math.pi / 30.0, scene["dynamics"]["delta"]
    curve = curves("energy-mass")[0]
    tangents = [points for points, _, colour in drawing.groups["energy-mass"]["paths"]
                if len(points) == 2 and colour not in ("black", "#333333", "#9a9a9a")]
    assert len(tangents) == 2
    tangents.sort(key=lambda line: -line[0][1])
    for line, speed, side in zip(tangents, (1 + delta / 2, 1 - delta / 2), (-1, 1)):
        slope = (line[1][1] - line[0][1]) / (line[1][0] - line[0][0])
        book = mu_inertia / (2 * mu_energy) * (omega_mean * speed) ** 2
        assert slope == pytest.approx(book, rel=2e-3)
        off = side * (curve[:, 1] - (line[0][1] + slope * (curve[:, 0] - line[0][0])))
        assert off.min() > -0.01 and off.min() < 0.05  # the whole curve on one side, touching
    intercept = tangents[0][0][1] - tangents[1][0][1]
    assert f"ab = {intercept:.1f} mm" in drawing.caption("energy-mass")
    flywheel = number(re.search(rf"JF = ab·μT/.*? = {NUMBER}", drawing.caption("results")).group(1))
    assert flywheel == pytest.approx(intercept * mu_energy / (omega_mean ** 2 * delta), rel=2e-3)


# The rotor's balancing polygons: each plane's shares by the lever rule, the correction closing them.

def test_the_rotor_balancing_polygons_close_on_the_hand_corrections(tmp_path):
    scene_path = tmp_path / "rotor.toml"
    assert main(["new", "rotor", "--out", str(scene_path)]) == 0
    scene = tomllib.loads(scene_path.read_text(encoding="utf-8"))["balancing"]
    out = run(tmp_path, scene_path, "--only", "balancing")
    drawing = Drawing(out / "rotor_balancing.svg")
    left, right = scene["planes"]
    corrections = {}
    for plane, near, far in (("L", left, right), ("R", right, left)):
        shares = [m["mass"] * m["radius"] * (far - m["plane"]) / (far - near)
                  * complex(math.cos(math.radians(m["angle"])), math.sin(math.radians(m["angle"])))
                  for m in scene["masses"]]
        corrections[plane] = -sum(shares)
        mu = drawing.scale(f"plane-{plane}-caption", "μ")
        for k, share in enumerate(shares, start=1):
            np.testing.assert_allclose(drawing.vector(f"plane-{plane}-m{k}r{k}{plane}"),
                                       [share.real / mu, share.imag / mu], atol=0.01)
        drawn = drawing.vector(f"plane-{plane}-m{plane}r{plane}") * mu
        np.testing.assert_allclose(drawn, [corrections[plane].real, corrections[plane].imag], atol=0.01 * mu)
        angle = math.degrees(math.atan2(corrections[plane].imag, corrections[plane].real)) % 360
        caption = drawing.caption(f"plane-{plane}-caption")
        assert f"θ{plane} = {angle:.1f}°" in caption
        assert number(re.search(rf"m{plane}r{plane} = {NUMBER} kg", caption).group(1)) == pytest.approx(
            abs(corrections[plane]), rel=1e-3)


# A load drawn beside its link: on its true line's side of the point its moment is taken about.

@pytest.mark.parametrize("index", [3, 9])
def test_a_crank_weight_set_beside_the_crank_turns_about_o_as_its_equation_signs_it(tmp_path, index):
    """The Stephenson six-bar's crank stands nearly upright in positions 3 and 9: G2's line passes half a
    millimetre from O on the paper, and its arrow, which would lie on the crank's bar, is drawn 2.5 mm beside it.
    Drawn on the far side of O, it turned about O against the term +G2·h1 written under it."""
    scene_path = FIXTURES / "stephenson_six_bar.toml"
    scene = tomllib.loads(scene_path.read_text(encoding="utf-8"))
    out = run(tmp_path, scene_path, "--only", "forces")
    position = next(p for p in json.loads((out / "results.json").read_text())["positions"] if p["index"] == index)
    phi = math.radians(position["driver"]["angle_deg"])
    # By hand: S2 lies 0.08 m from O along OA (O at the origin); the weight, straight down, turns the crank about O
    # counter-clockwise where S2 is left of O.
    centre_of_mass = scene["points"]["S2"]["at"] * math.cos(phi)
    by_hand = -math.copysign(1.0, centre_of_mass)
    drawing = Drawing(out / f"forces_{index}.svg")
    pivot = min(drawing.groups["body-I-1-2-links"]["circles"],
                key=lambda circle: np.linalg.norm(circle - next(where for text, where in drawing.groups[
                    "body-I-1-2-labels"]["texts"] if text == "O")))
    start, tip = drawing.groups["body-I-1-2-G2"]["arrows"][0]
    direction = tip - start
    drawn = math.copysign(1.0, (start - pivot)[0] * direction[1] - (start - pivot)[1] * direction[0])
    written = re.search(r"ΣMO\(2\):.*?([+−]) G2·h\d", drawing.caption("body-I-1-2-caption")).group(1)
    assert {"+": 1.0, "−": -1.0}[written] == by_hand
    assert drawn == by_hand, f"G2 drawn turning {'counter-' if drawn > 0 else ''}clockwise about O, written {written}"


def test_a_lever_load_set_beside_another_keeps_to_its_lines_side_of_the_pole():
    """Two loads at one image on one line: the second stands 6 mm beside the first where its other side is taken.
    Its line 1 mm left of the pole, the side to the right would carry it across the pole the lever's moments are
    taken about, turning it on the drawing against its term in ΣMp."""
    image, load = complex(-1.0, 5.0), complex(0.0, -10.0)
    first = [Arrow((-1.0, 5.0), (-1.0, -5.0))]  # drawn before from the same image down the same line
    taken = LineString(((-1.0, 5.0), (-1.0, 20.0))).buffer(0.8)  # the line's other side, an arm there
    start, end, shift = force_lever._pushing_or_pulling(image, load, first, lambda: taken)
    assert abs(shift) == pytest.approx(force_lever.LEVER_BESIDE_MM)
    assert start.real < 0 and end.real < 0, f"drawn at x = {start.real:.1f} mm, its line at x = −1 mm, the pole at 0"


def test_the_lever_at_a_scotch_yokes_dead_centre_writes_no_load_that_does_no_work(tmp_path):
    """At the top dead centre (position 1, the crank at 90°) the yoke stands still and the crank pin moves across
    the guide: by hand no load does work (the weights and the pin's inertia force are vertical, the yoke's loads act
    on a link at rest), so Mb = 0 and the lever's equation has no load in it. The drawing wrote every load with arms
    of 10⁻¹⁴ mm and Mb = −0.00000000000001040 N·m, its rounding."""
    text = (FIXTURES / "scotch_yoke.toml").read_text(encoding="utf-8")
    scene_path = tmp_path / "scotch_yoke.toml"
    scene_path.write_text(re.sub(r"(?m)^plans\s*=.*$", "plans = [1]", text), encoding="utf-8")
    scene = tomllib.loads(scene_path.read_text(encoding="utf-8"))
    out = run(tmp_path, scene_path, "--only", "forces,lever")
    position = next(p for p in json.loads((out / "results.json").read_text())["positions"] if p["index"] == 1)
    phi = math.radians(position["driver"]["angle_deg"])
    pin_velocity = scene["driver"]["omega"] * scene["driver"]["length"] * np.array([-math.sin(phi), math.cos(phi)])
    assert abs(pin_velocity[1]) < 1e-9  # the dead centre: the yoke, moving with the pin's vertical part, at rest
    caption = Drawing(out / "forces_1.svg").caption("lever-caption")
    assert "ΣMp: Fb·hb = 0" in caption, caption
    assert not re.search(r"\bh\d+ = ", caption), caption
    assert number(re.search(rf"Mb = (−?{NUMBER}) N·m \(Zhukovsky's lever\)", caption).group(1)) == 0.0
