"""A light real machine is not told its eccentricity is millimetres.  `[vibration]`'s lengths-in-mm caution took the
machine for at least a 1 mm steel sheet filling the circle of radius e (24.7 kg at e = 1 m), and warned a plastic fan,
a ceiling fan, a bicycle's wheel, a drone's propeller or a model helicopter that its e = 0.3 m was 0.3 mm: blades and
spokes fill little of the circle they sweep, and are plastic, aluminium or carbon.  The slips the caution was made for
(a 100 kg machine with e = 5 typed for 5 mm) are still told.  And the refusal of a run-down that nothing brings to rest
names the scene key that ends it, dynamics.brake, with its keys as the scene format gives them."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from graphplan.cli import main

# Real machines, each as the whole machine on its mounts with an unbalanced mass at its rim (the worst case: e as
# large as the machine reaches).  Masses and radii are typical catalogue figures, rounded towards the light side.
LIGHT_REAL_MACHINES = {
    # The brief's own: a plastic fan on its shaft, blades 0.3 m long, the whole of it 0.5 kg.
    "plastic fan on a shaft": (0.5, 0.3),
    # A 52-inch (1.32 m sweep) ceiling fan weighs some 5–7 kg with its motor; its blade tips turn 0.66 m out.
    "ceiling fan": (5.0, 0.66),
    # A 10-inch (254 mm) multirotor propeller, some 12 g, on its 2212-size brushless motor, some 55 g, on a test stand.
    "drone propeller on its motor": (0.067, 0.127),
    # A 700c road wheel (ISO 622 mm bead seat; with a 25 mm tyre some 0.67 m across) weighs some 1 kg with tyre and
    # tube; spun in a truing stand or a wheel-on trainer, its valve or a reflector is the unbalance at the rim.
    "bicycle wheel": (1.0, 0.336),
    # A 450-size model helicopter: main rotor some 0.71 m across, all up some 0.7 kg.
    "model helicopter": (0.7, 0.355),
    # A micro wind turbine (1.17 m rotor) of some 6 kg with its alternator.
    "micro wind turbine": (6.0, 0.585),
}
# Machines the steel sheet already let by, to be let by still.
HEAVY_REAL_MACHINES = {
    # A 3.5-inch hard disk: platters 95 mm across in a 0.6 kg drive.
    "hard-disk platter": (0.6, 0.0475),
    # A washing machine's drum some 0.5 m across in a 65 kg machine.
    "washing machine drum": (65.0, 0.25),
    # A 21-inch (0.53 m) rotary lawn-mower's blade on a 25 kg mower.
    "lawn-mower blade": (25.0, 0.267),
    # A 16-inch desk fan of some 3 kg.
    "desk fan": (3.0, 0.2),
    # NREL's 5 MW reference turbine: rotor radius 63 m, rotor 110 t and nacelle 240 t.
    "wind turbine": (350000.0, 63.0),
}
# An eccentricity typed in millimetres: (the machine's mass, kg; e as typed, meant as mm).
SLIPS = {
    "the existing slip: 100 kg, e = 5 mm": (100.0, 5.0),
    "an electric motor of 25 kg, e = 10 mm": (25.0, 10.0),
    "a 200 kg machine, e = 30 mm": (200.0, 30.0),
    "a 1 t machine, e = 20 mm": (1000.0, 20.0),
}


def _run(tmp_path: Path, capsys, mass: float, eccentricity: float, locale: str = "en"):
    scene = tmp_path / "machine.toml"
    scene.write_text(f'[scene]\ntitle = "Machine"\nlocale = "{locale}"\n[vibration]\nmass = {mass!r}\n'
                     f"unbalanced_mass = {mass * 0.01!r}\neccentricity = {eccentricity!r}\n"
                     "stiffness = 1.0e5\ndamping_ratio = 0.1\nrpm = 600.0\n", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 0
    told = capsys.readouterr().out
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    return told, results, (out / "note.md").read_text(encoding="utf-8")


@pytest.mark.parametrize("machine", [*LIGHT_REAL_MACHINES, *HEAVY_REAL_MACHINES])
def test_a_real_machine_is_not_told_its_eccentricity_is_millimetres(tmp_path, capsys, machine):
    mass, eccentricity = {**LIGHT_REAL_MACHINES, **HEAVY_REAL_MACHINES}[machine]
    told, results, note = _run(tmp_path, capsys, mass, eccentricity)
    assert "lengths-in-mm" not in {found["code"] for found in results["vibration"]["warnings"]}
    assert "millimetres" not in told and "millimetres" not in note


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
@pytest.mark.parametrize("slip", SLIPS)
def test_an_eccentricity_typed_in_millimetres_is_still_told(tmp_path, capsys, slip, locale):
    mass, eccentricity = SLIPS[slip]
    told, results, note = _run(tmp_path, capsys, mass, eccentricity, locale)
    (found,) = [found for found in results["vibration"]["warnings"] if found["code"] == "lengths-in-mm"]
    assert f"vibration.eccentricity = {eccentricity:g} m" in found["detail"]
    assert f"vibration.mass = {mass:g} kg" in found["detail"]
    assert f"(as millimetres, vibration.eccentricity = {eccentricity / 1000:g})" in found["detail"]
    assert f"warning: vibration: vibration.eccentricity = {eccentricity:g} m" in told
    written = f"{eccentricity:g}"
    assert {"en": f"e = {written} m", "ru": f"e = {written} м", "zh": f"e = {written} m"}[locale] in note


def test_the_rule_lets_every_light_real_machine_by_with_room_to_spare():
    """Not on the edge: each light real machine weighs at least twice the least the rule asks of its e, and each slip
    at most the least it asks."""
    from graphplan.rotor_lengths import lightest_rotor

    for mass, eccentricity in LIGHT_REAL_MACHINES.values():
        assert mass >= 2.0 * lightest_rotor(eccentricity), (mass, eccentricity)
    for mass, eccentricity in SLIPS.values():
        assert mass < lightest_rotor(eccentricity), (mass, eccentricity)


def test_the_endless_run_down_refusal_names_the_brake_key(tmp_path, capsys):
    """The refusal advised `brake = { torque, at }`: no such table stands at the scene's top level; the brake is
    dynamics.brake = { torque, damping, at }, and only its torque brings the machine to rest."""
    from test_more_unit_slips import LINKAGE_RUN_DOWN

    scene = tmp_path / "run_down.toml"
    scene.write_text(LINKAGE_RUN_DOWN, encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    err = capsys.readouterr().err
    assert "dynamics.motor.off_at:" in err and "never comes to rest" in err
    assert "dynamics.brake = { torque, damping, at }" in err
    assert "with torque > 0" in err and "dynamics.duration" in err
    assert "(brake = {" not in err
