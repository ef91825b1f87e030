"""A link's centre of mass placed ``at`` a share of its line, as a student reads "S3 at 0.29 of AB": ``at`` is metres
from ``from``, so the centre lands past the joint it is measured toward, outside the link, and every weight and
inertia load follows it there.  The run and ``check`` warn, naming the key and the metres that share would be; the
note says so in each language.  A centre within the link's reach is never told."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.starters import starter

# The slider-crank starter's connecting rod AB, and where its centre S3 stands on it (m from A).
ROD = 0.19
CENTRE_AT = 0.055
CAUTION = {"en": "Caution: a link's centre of mass is placed past the point it is measured toward",
           "ru": "Внимание: центр масс звена задан за точкой, к которой отсчитано его положение",
           "zh": "注意：给定的构件质心位于其量取方向所指的点之外"}


def _slider_crank(centre_at: float, extra_point: str = "") -> str:
    text = starter("slider-crank", "en")
    old = f'S3 = {{ link = 3, from = "A", toward = "B", at = {CENTRE_AT} }}'
    assert old in text
    return text.replace(old, f'S3 = {{ link = 3, from = "A", toward = "B", at = {centre_at!r} }}{extra_point}', 1)


def _run(tmp_path: Path, text: str, locale: str = "en") -> tuple[list[str], str]:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "note", "--locale", locale]) == 0
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    told = [warning["detail"] for warning in results["warnings"] if warning["code"] == "centre-as-share"]
    return told, (out / "note.md").read_text(encoding="utf-8")


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_centre_typed_as_a_share_of_the_rod_is_told_with_the_metres_meant(tmp_path, locale):
    share = 0.29                       # 0.055 m of 0.19 m, as a share
    told, note = _run(tmp_path, _slider_crank(share), locale)
    assert len(told) == 1
    past = share - ROD                 # A–S3 is 0.29 m along AB, 0.19 m long
    assert told[0] == (f"points.S3.at = 0.29 m puts link 3's centre of mass S3 {past:.3g} m past B, beyond the "
                       f"link's other points (its span grows from {ROD:g} m, A–B, to {share:g} m): a share of AB "
                       f"typed for metres? at is metres from A; 0.29 of AB ({ROD:g} m) is points.S3.at = "
                       f"{share * ROD:.4g}")
    assert round(share * ROD, 3) == CENTRE_AT     # the advice gives back the starter's own place
    assert CAUTION[locale] in note


def test_check_tells_it_too(tmp_path, capsys):
    scene = tmp_path / "scene.toml"
    scene.write_text(_slider_crank(0.29), encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    assert "warning: points.S3.at = 0.29 m puts link 3's centre of mass S3 0.1 m past B" in capsys.readouterr().out


@pytest.mark.parametrize(("centre_at", "extra_point"), [
    (CENTRE_AT, ""),                  # the starter's own, metres from A
    (ROD, ""),                        # at B itself: the span does not grow
    (-0.02, ""),                      # behind A: a counterweight's place, at a negative at
    # Past B, but within the reach of the rod's other point E, 0.3 m out along AB: the link reaches on past B.
    (0.25, '\nE = { link = 3, from = "A", toward = "B", at = 0.3 }'),
])
def test_a_centre_within_the_links_reach_or_behind_its_pivot_is_not_told(tmp_path, centre_at, extra_point):
    told, note = _run(tmp_path, _slider_crank(centre_at, extra_point))
    assert told == []
    assert CAUTION["en"] not in note
