"""Lengths typed in millimetres where the scene asks for metres: the mechanism a thousand times too large, every
result wrong by as much, and nothing said (a class III course project ran with its crank pin at 750 m/s)."""

from __future__ import annotations

import json
import tomllib

import pytest
from drawn_lines import whole_lines
from scene_texts import piston_compressor
from shapely.geometry import LineString

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main

FIXTURE = "fixtures/ratchet_crank_rocker.toml"


def scaled(factor: float, omega: float | None = None) -> dict:
    """The ratchet's crank-rocker (its kinematics alone) with every length times ``factor``."""
    with open(FIXTURE, "rb") as file:
        data = tomllib.load(file)
    for name in ("links", "loads", "forces", "measured", "dynamics"):
        data.pop(name, None)
    data["frame"]["points"] = {name: [x * factor for x in xy] for name, xy in data["frame"]["points"].items()}
    data["driver"]["length"] *= factor
    if omega is not None:
        data["driver"]["omega"] = omega
    data["groups"][0]["lengths"] = [length * factor for length in data["groups"][0]["lengths"]]
    data["points"] = {name: point | {"at": point["at"] * factor, "offset": point.get("offset", 0.0) * factor}
                      for name, point in data["points"].items()}
    data.pop("drawing", None)
    return data


def _toml(data: dict, where: str = "") -> str:
    """``data`` as TOML (its tables, lists of tables, numbers, strings and lists of them)."""
    head = [f"{key} = {json.dumps(value, ensure_ascii=False)}" for key, value in data.items()
            if not isinstance(value, dict) and not (isinstance(value, list) and value and isinstance(value[0], dict))]
    lines = ([f"[{where}]"] if where else []) + head
    for key, value in data.items():
        if isinstance(value, dict):
            lines.append(_toml(value, f"{where}.{key}" if where else key))
        elif isinstance(value, list) and value and isinstance(value[0], dict):
            lines += [f"[[{key}]]\n" + _toml(item).strip() for item in value]
    return "\n".join(lines) + "\n"


def told(data: dict) -> list[str]:
    return [warning.detail for warning in analyse(graphplan.load(data)).warnings if warning.code == "lengths-in-mm"]


def test_lengths_in_millimetres_are_warned_of_by_check_and_run_and_kept_in_the_results(tmp_path, capsys):
    scene = tmp_path / "in_mm.toml"
    scene.write_text(_toml(scaled(1000.0)))
    assert main(["check", str(scene)]) == 0
    out = capsys.readouterr().out
    # About the scene as a whole, not its first position (where results.json, by position, records it).
    warning = ("warning: groups[0].lengths[0] = 550 m is longer than any machine's link (over 20 m); "
               "driver.length = 175 m at ω = 17 rad/s moves the crank pin A at 2975 m/s, faster than any machine's "
               "(over 100 m/s): are the lengths in millimetres? The scene's lengths are in metres (divide them by "
               "1000)")
    assert warning in out
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "positions"]) == 0
    assert warning in capsys.readouterr().out
    (kept,) = [w for w in json.loads((tmp_path / "out" / "results.json").read_text())["warnings"]
               if w["code"] == "lengths-in-mm"]
    assert kept["position"] == 0 and f"warning: {kept['detail']}" == warning
    assert "warning: position" not in out


def test_a_small_mechanism_in_millimetres_is_given_away_by_its_crank_pins_speed():
    """Lengths of 4.5 to 16.5 "m" are no machine's, but under what a press may measure: the crank pin's 135 m/s is."""
    (detail,) = told(scaled(30.0, omega=-30.0))
    assert detail.startswith("driver.length = 5.25 m at ω = 30 rad/s moves the crank pin A at 157.5 m/s")
    assert "are the lengths in millimetres?" in detail and "rev/min are given as driver.rpm" in detail
    assert "longer than any machine's link" not in detail


def test_a_frame_far_larger_than_its_links_is_warned_of():
    """A frame point typed in millimetres, the links in metres: a pivot 550 m away that no link reaches."""
    data = scaled(1.0)
    data["frame"]["points"]["D"] = [0.0, 550.0]
    (detail,) = told(data)
    assert detail.startswith("frame.points.D = [0, 550] lies 550 m from O, farther apart than any machine's pivots")


@pytest.mark.parametrize(("factor", "omega"), [(1.0, None), (10.0, -5.0), (0.2, -300.0)])
def test_machines_of_a_real_size_and_speed_are_not_warned_of(factor, omega):
    """The ratchet as drawn, a 5.5 m press turning slowly, a small fast mechanism (crank pin at 10.5 m/s)."""
    assert told(scaled(factor, omega)) == []


def refusal(data: dict) -> str:
    with pytest.raises(graphplan.AssemblyError) as refused:
        analyse(graphplan.load(data))
    return str(refused.value)


def test_one_length_in_millimetres_among_metres_is_named_where_the_mechanism_cannot_assemble():
    """lBC typed as 325 (mm) beside the crank's 0.175 m: no crank angle assembles it, and a swing to rock it over,
    or "check the lengths", sends the student after the geometry instead of the typo."""
    data = scaled(1.0)
    data["groups"][0]["lengths"][1] = 325.0
    said = refusal(data)
    assert ("groups[0].lengths[1] = 325 m beside driver.length = 0.175 m: are some lengths in millimetres? The "
            "scene's lengths are all in metres") in said
    assert "driver.swing" not in said and "check the lengths" not in said


def test_links_in_millimetres_on_a_frame_in_metres_are_told_so():
    """Every link in millimetres, the frame's pivots in metres: the links are all alike, the frame is not."""
    data = scaled(1.0)
    data["driver"]["length"] = 175.0
    data["groups"][0]["lengths"] = [550.0, 325.0]
    assert ("groups[0].lengths[0] = 550 m beside frame.points.C (0.55 m from O): are some lengths in millimetres?"
            in refusal(data))


def test_a_mechanism_of_plausible_lengths_that_cannot_turn_round_keeps_its_reach_advice():
    data = scaled(1.0)
    data["driver"]["length"] = 0.5
    said = refusal(data)
    assert "millimetres" not in said and "driver.swing = [" in said


# A student's compressor with its lengths typed in millimetres (75, 300, 100 for 0.075, 0.30, 0.10 m), its
# dynamics drawn on A1 sheets: its energy–mass diagram's tangents stand at ψ ≈ 89.9°.
COMPRESSOR_IN_MM = piston_compressor(radius=75.0, rod=300.0, rod_centre=100.0) + """
[[loads]]
kind = "force"
link = 4
point = "B"
angle = 180.0
resisting = true
diagram = [[0.0, 0.0], [0.2, 400.0], [0.4, 1000.0], [0.6, 2200.0], [0.75, 5300.0], [1.0, 5300.0]]
[positions]
count = 12
start = "extreme"
working = { link = 4, sense = "forward" }
plans = [1]
[dynamics]
delta = 0.0125
[drawing]
sheet = "A1"
"""


def _compressor_in_mm(tmp_path, drawing: str = ""):
    scene = tmp_path / "compressor_mm.toml"
    scene.write_text(COMPRESSOR_IN_MM + drawing, encoding="utf-8")
    return scene


def test_the_energy_mass_diagram_of_steep_tangents_stays_about_its_curve(tmp_path):
    """Tangents at ψ ≈ 89.9° cut three heights of ΔT beyond the curve each way made the diagram 685 mm tall, which no
    A1 sheet held, and the run was refused; cut a little past the curve's band, it stays near the curve's size."""
    from graphplan.machine_dynamics import MachineDynamics
    from graphplan.render import dynamics as dynamics_layout
    from graphplan.render.primitives import Polyline, bounds_of

    dynamics = MachineDynamics(analyse(graphplan.load(_compressor_in_mm(tmp_path))))
    layers = {layer.name: layer.items for layer in dynamics_layout.layout(dynamics.model, dynamics.flywheel)}
    scales = dynamics_layout.scales_for(dynamics.model)
    curve = dynamics.model.energy / scales.energy
    _, bottom, _, top = bounds_of(layers["energy-mass"])
    assert top - bottom < float(curve.max() - curve.min()) + 2 * dynamics_layout.CUT_TANGENT_RUN_MM + 40.0
    # Both tangents are still drawn across the curve's band.
    # A tangent broken under a Je number it crosses is drawn in pieces on one line: taken whole again.
    tangents = whole_lines(LineString(item.points) for item in layers["energy-mass"]
                           if isinstance(item, Polyline) and item.stroke.colour == "#b22222")
    assert len(tangents) == 2
    for tangent in tangents:
        (_, y0), (_, y1) = tangent.coords
        assert abs(y1 - y0) >= float(curve.max() - curve.min())


def test_check_and_run_agree_on_a_compressor_in_millimetres(tmp_path, capsys):
    scene = _compressor_in_mm(tmp_path)
    assert main(["check", str(scene)]) == 0
    assert "are the lengths in millimetres?" in capsys.readouterr().out
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "sheets"]) == 0
    assert "are the lengths in millimetres?" in capsys.readouterr().out


def test_check_refuses_a_dynamics_drawing_no_sheet_holds_as_the_run_does_without_offering_a_length_scale(
        tmp_path, capsys, monkeypatch):
    """The dynamics diagrams are at scales the program fits to the machine: no μl changes them.  A drawing of them no
    sheet holds (here the steep tangents run on as far as they once did) is refused by check as by the run, and the
    advice names a bigger sheet or none, not drawing.length_scale.  It names the diagram by its heading, as a reader
    knows it: its id ('Dynamics of the machine: dynamics-flywheel') told them nothing."""
    from graphplan.locale import strings
    from graphplan.render import dynamics as dynamics_layout

    monkeypatch.setattr(dynamics_layout, "CUT_TANGENT_RUN_MM", 300.0)
    scene = _compressor_in_mm(tmp_path)
    assert main(["check", str(scene)]) == 2
    checked = capsys.readouterr().err
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "sheets"]) == 2
    ran = capsys.readouterr().err
    error = checked.strip().splitlines()[-1]
    assert error.startswith(f"graphplan: error: drawing.sheet: the drawing '{strings('en')['dyn_energy_mass']}' (")
    assert error in ran.splitlines()
    assert "length_scale" not in error and error.endswith("clear of its title block); sheet = \"none\" (got 'A1')")


def test_a_refused_run_tells_the_scene_s_warnings_before_its_error(tmp_path, capsys):
    """The plan of positions of a mechanism in millimetres drawn at a μl for metres fits no paper: the run's error
    comes after the warning that names the cause, not alone."""
    scene = _compressor_in_mm(tmp_path, "length_scale = 0.002\n")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    lines = capsys.readouterr().err.strip().splitlines()
    assert lines[-1].startswith("graphplan: error: drawing.length_scale: draws the paths of the points")
    told_at = next(k for k, line in enumerate(lines) if "are the lengths in millimetres?" in line)
    assert lines[told_at].startswith("warning: ") and told_at < len(lines) - 1
