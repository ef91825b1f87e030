"""The kinematic diagrams stand to no length scale: a run that chooses μl lays them out once, for the choice and for
the sheets at the μl chosen alike (each layout tries the larger ways a sheet with room takes), and the sheets are the
same as when each laid them out afresh."""

from __future__ import annotations

from pathlib import Path

import graphplan
from graphplan.render import sheet as sheet_module
from graphplan.run import run

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml"
GIVEN_SCALE = "length_scale      = 0.0025"


def ratchet_choosing_its_length_scale():
    text = FIXTURE.read_text(encoding="utf-8")
    assert text.count(GIVEN_SCALE) == 1
    return graphplan.load_text(text.replace(GIVEN_SCALE, ""))


def test_a_run_that_chooses_its_length_scale_lays_the_kinematic_diagrams_out_once(tmp_path, monkeypatch):
    scene = ratchet_choosing_its_length_scale()
    assert scene.drawing.length_scale is None and scene.drawing.sheet != "none"
    laid_out = []
    original = sheet_module._diagrams_panel

    def counted(analysis, sheet):
        laid_out.append((analysis.scene.drawing.length_scale, sheet))
        return original(analysis, sheet)

    monkeypatch.setattr(sheet_module, "_diagrams_panel", counted)
    shared = run(scene, tmp_path / "shared", only=["sheets", "diagrams"])
    assert len(laid_out) == 1, laid_out
    # Laid out afresh each time it is asked for, the sheets come out the same.
    monkeypatch.setattr(sheet_module, "diagrams_panel", lambda analysis, sheet: original(analysis, sheet))
    afresh = run(ratchet_choosing_its_length_scale(), tmp_path / "afresh", only=["sheets", "diagrams"])
    names = sorted(path.name for path in shared.files)
    assert names == sorted(path.name for path in afresh.files) and any(name.startswith("sheet") for name in names)
    for name in names:
        assert (tmp_path / "shared" / name).read_bytes() == (tmp_path / "afresh" / name).read_bytes(), name


def test_check_weighs_the_dynamics_on_one_equivalent_model(tmp_path, monkeypatch, capsys):
    """check asks for the machine's dynamics three times (what the run would refuse, the dynamics drawing on the
    sheets, the stall it warns of): the equivalent model is reduced once for the analysis, and is the one a fresh
    reduction gives."""
    from graphplan import dynamics
    from graphplan.analysis import analyse
    from graphplan.cli import main
    from graphplan.starters import starter

    made = []
    original = dynamics._model_over

    def counted(*arguments):
        made.append(arguments[2])
        return original(*arguments)

    monkeypatch.setattr(dynamics, "_model_over", counted)
    scene = tmp_path / "shaper.toml"
    scene.write_text(starter("shaper"), encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    assert "dynamics" in capsys.readouterr().out
    assert len(made) == 1 and made[0] is not None
    # Asked again for the same analysis, the same model; a new analysis of the scene reduces its own, equal to it.
    analysis = analyse(graphplan.load(scene))
    first = dynamics.equivalent_model_of(analysis)
    assert dynamics.equivalent_model_of(analysis) is first and len(made) == 2
    fresh = original(analysis.mechanism, analysis.positions, analysis, dynamics.DEFAULT_COUNT, "auto")
    assert (fresh.inertia == first.inertia).all() and (fresh.resisting == first.resisting).all()
    assert dynamics.equivalent_model_of(analysis, dynamics.DEFAULT_COUNT + 1) is not first and len(made) == 3
