"""A dynamics diagram too wide for a sheet only for its heading: the Russian flywheel starter's reduced moments,
headed «Приведённые моменты движущих сил и сил сопротивления» (259 mm in 7 mm bold over a diagram some 200 mm wide),
was refused on A4, whose sheet holds 256 mm beside its title block, while the English and Chinese ran.  The heading
is broken at its phrases to the diagram's width there; a diagram that fits keeps its heading on one line."""

from __future__ import annotations

from pathlib import Path
from xml.etree import ElementTree

from graphplan.cli import main
from graphplan.locale import strings
from graphplan.starters import starter

SVG = "{http://www.w3.org/2000/svg}"


def _headings(tmp_path: Path, locale: str, sheet: str) -> list[list[tuple[str, float, float]]]:
    """The lines (text, x, y) of the reduced moments' heading on each sheet that draws it."""
    tmp_path.mkdir(exist_ok=True)
    scene = tmp_path / "flywheel.toml"
    scene.write_text(starter("flywheel", locale), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "sheets", "--sheet", sheet]) == 0
    heading = strings(locale)["dyn_moments"]
    found = []
    for path in out.glob("sheet_*.svg"):
        for group in ElementTree.parse(path).getroot().iter(f"{SVG}g"):
            if not (group.get("id") or "").startswith("dynamics-moments"):
                continue
            bold = [t for t in group.iter(f"{SVG}text") if t.get("font-weight") == "bold"]
            lines = [("".join(t.itertext()), float(t.get("x")), float(t.get("y"))) for t in bold]
            if lines and heading.startswith(lines[0][0]):
                found.append(lines)
    return found


def test_the_russian_flywheels_moments_stand_on_an_a4_under_their_heading_broken(tmp_path):
    (lines,) = _headings(tmp_path, "ru", "A4")
    assert " ".join(text for text, _, _ in lines) == strings("ru")["dyn_moments"]
    assert len(lines) == 2
    # Flush left, the second line under the first (SVG's y runs down).
    (_, x0, y0), (_, x1, y1) = lines
    assert x0 == x1 and y1 > y0


def test_a_diagram_that_fits_keeps_its_heading_on_one_line(tmp_path):
    for locale, sheet in (("en", "A4"), ("ru", "A3")):
        (lines,) = _headings(tmp_path / f"{locale}-{sheet}", locale, sheet)
        assert [text for text, _, _ in lines] == [strings(locale)["dyn_moments"]]


def test_check_passes_the_scene_the_run_draws(tmp_path, capsys):
    """`check` packs the dynamics drawing as the sheets do, to refuse what no sheet holds: it packed it without the
    scene's sheet, so it refused the Russian flywheel on A4 that the run then drew."""
    text = starter("flywheel", "ru")
    assert "[drawing]" not in text
    scene = tmp_path / "flywheel.toml"
    scene.write_text(f'{text}\n[drawing]\nsheet = "A4"\n', encoding="utf-8")
    assert main(["check", str(scene)]) == 0, capsys.readouterr().err
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "sheets"]) == 0
