"""What the command line loads before it works, and the work a run no longer does twice (bench/cold_run.py).

Each command is started in a fresh interpreter, as a user starts it, and asked which modules it imported: `graphplan
--help` lists the pieces and formats without the analysis; `graphplan check` measures the drawings against the sheet
without the SVG writer (svgwrite builds its validator's grammar on import) or any exporter; `import graphplan`
loads the analysis only when its interface is used; a run of the bundled scene does not load numpy.ma (np.median,
np.unique and np.setdiff1d import it to ask whether an array is masked), some 30 ms of its start.
"""

from __future__ import annotations

import dataclasses
import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "fixtures" / "ratchet_crank_rocker.toml"
# The libraries of the drawing files and the plots: none serves a command that writes no drawing.
DRAWING_STACK = ("svgwrite", "matplotlib", "scipy", "cairosvg", "docx", "ezdxf", "pylatexenc", "weasyprint")


def _loaded_by(*arguments: str, before: str = "") -> tuple[int, set[str], str]:
    """The exit status, the modules loaded and what was printed by ``graphplan ARGUMENTS`` in a fresh interpreter."""
    code = (f"import contextlib, io, json, sys\n{before}\n"
            "from graphplan.cli import main\n"
            "printed = io.StringIO()\n"
            "with contextlib.redirect_stdout(printed):\n"
            "    try:\n"
            f"        status = main({list(arguments)!r})\n"
            "    except SystemExit as ended:\n"
            "        status = ended.code\n"
            "print(json.dumps([status, sorted(sys.modules), printed.getvalue()]))\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    status, modules, printed = json.loads(done.stdout.splitlines()[-1])
    return status, set(modules), printed


def _packages(modules: set[str], names: tuple[str, ...]) -> list[str]:
    return sorted({module.split(".")[0] for module in modules} & set(names))


def test_help_lists_the_pieces_without_the_analysis_or_the_drawings():
    status, modules, printed = _loaded_by("--help")
    assert status == 0
    assert "run" in printed and "check" in printed
    status, modules, printed = _loaded_by("run", "--help")
    assert status == 0 and "load_diagrams" in printed and "docx" in printed  # PIECES and FORMATS, listed
    loaded = sorted(module for module in modules if module.startswith(("graphplan.analysis", "graphplan.motion",
                                                                        "graphplan.report", "graphplan.render.")))
    assert not [module for module in loaded if module not in ("graphplan.render.primitives",
                                                              "graphplan.render.numerals")], loaded
    assert not _packages(modules, DRAWING_STACK)


def test_help_lists_the_languages_sheets_and_pieces_without_the_scene_reader():
    """The choices the options list come from graphplan.choices: the scene's reader loads the groups' solvers, and
    numpy and shapely under them, which listing them needs none of."""
    status, modules, printed = _loaded_by("run", "--help")
    assert status == 0
    assert "{en,ru,zh}" in printed and "{A1,A2,A3,A4,none}" in printed and "positions, velocity" in printed
    assert not {"graphplan.scene", "graphplan.groups", "numpy", "shapely"} & modules


def test_check_measures_the_sheets_without_the_svg_writer(tmp_path):
    status, modules, printed = _loaded_by("check", str(SCENE))
    assert status == 0
    assert "structure: I(1,2) → II2(3,4)" in printed and "run writes:" in printed
    # It did measure the drawings against the sheet (the layouts are loaded): it only wrote no SVG.
    assert "graphplan.render.sheet" in modules
    assert not _packages(modules, DRAWING_STACK), _packages(modules, DRAWING_STACK)


def test_the_package_loads_the_analysis_only_when_its_interface_is_used():
    code = ("import sys, graphplan\n"
            "before = 'numpy' in sys.modules or 'graphplan.scene' in sys.modules\n"
            "scene = graphplan.load(sys.argv[1])\n"
            "motion = graphplan.solve(scene)\n"
            # A module that the package loaded with itself before is still an attribute of it.
            "again = graphplan.scene.loads(open(sys.argv[1], encoding='utf-8').read())\n"
            "print(before, type(scene).__name__, type(motion).__name__, again.title == scene.title,\n"
            "      graphplan.Scene is type(scene), 'Mechanism' in dir(graphplan))\n")
    done = subprocess.run([sys.executable, "-c", code, str(SCENE)], capture_output=True, text=True, cwd=ROOT,
                          check=True)
    assert done.stdout.split() == ["False", "Scene", "Motion", "True", "True", "True"]
    import graphplan

    with pytest.raises(AttributeError, match="no attribute 'nothing_of_the_kind'"):
        graphplan.nothing_of_the_kind  # noqa: B018


def test_a_russian_run_reads_the_english_strings_once():
    """A locale's strings fall back on English's, which the diagrams ask for too: en.toml was parsed twice."""
    code = ("import sys, tomllib\n"
            "from graphplan import locale\n"
            "parsed = []\n"
            "real = tomllib.loads\n"
            "locale.tomllib = type(sys)('counting')\n"
            "locale.tomllib.loads = lambda text: parsed.append(len(text)) or real(text)\n"
            "russian, english = locale.strings('ru'), locale.strings('en')\n"
            "print(len(parsed), russian['tb_eskd_scale'] != english['tb_eskd_scale'], english['tb_eskd_scale'])\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    count, differ, english_scale = done.stdout.split(maxsplit=2)
    assert (count, differ) == ("2", "True")  # en.toml and ru.toml, each once
    assert english_scale.strip() == "Scale"


def test_the_title_block_is_fitted_once_for_every_sheet_it_is_drawn_on(monkeypatch):
    """The same block on every sheet, and check's measure of it with each field left out, broke each text afresh:
    a bisection of forty rounds a field. The second block is the first's texts, and breaks nothing again."""
    from graphplan.render import title_block as block

    filled = []
    real = block._filled
    monkeypatch.setattr(block, "_filled", lambda *given: filled.append(1) or real(*given))
    fields = block.TitleBlockFields(title="Crank-rocker mechanism of a ratchet feed, unit 3 of the line",
                                    author="A. Student", organization="Department of machine theory, group 21",
                                    drawing="Kinematic analysis", scale="1:2", sheet=1, sheets=4)
    first = block.title_block("eskd", fields, block.labels("en"), (0.0, 0.0))
    breaks = len(filled)
    assert breaks > 40  # the title and the organisation broke over lines by bisection
    second = block.title_block("eskd", dataclasses.replace(fields, sheet=2), block.labels("en"), (0.0, 0.0))
    assert len(filled) == breaks
    texts = [item.text for item in first if isinstance(item, block.Text)]
    assert [item.text for item in second if isinstance(item, block.Text)] == [text if text != "1" else "2"
                                                                            for text in texts]
    # The title broken over lines, every word there and in order.
    title_lines = [text for text in texts if text in fields.title]
    assert len(title_lines) > 1 and " ".join(title_lines) == fields.title


def test_a_panel_replaced_in_another_field_is_not_measured_again(monkeypatch):
    """The packing replaces its panels a hundred times and more (their alternatives left off, a heading named): the
    layers stay the same, and so does their extent, which was measured once."""
    from graphplan.render import packing
    from graphplan.render.primitives import Circle, Layer, Polyline, Stroke

    measured = []
    real = packing.bounds
    monkeypatch.setattr(packing, "bounds", lambda layers: measured.append(1) or real(layers))
    layers = (Layer("lines", (Polyline(((0.0, 0.0), (30.0, 5.0)), Stroke(0.25)),)),
              Layer("dots", (Circle((40.0, -2.0), 1.0, Stroke(0.25)),)))
    panel = packing.Panel("drawing", layers)
    assert panel.extent == (0.0, -3.0, 41.0, 5.0)
    again = dataclasses.replace(panel, label="the same drawing", alternatives=(panel,))
    assert again.extent == panel.extent
    assert len(measured) == 1
    # Other layers are measured: a panel of layers whose items can still change (a list) every time.
    moved = packing.Panel("drawing", (Layer("lines", (Polyline(((5.0, 1.0), (9.0, 2.0)), Stroke(0.25)),)),))
    assert moved.extent == (5.0, 1.0, 9.0, 2.0)
    changing = [Polyline(((0.0, 0.0), (1.0, 1.0)), Stroke(0.25))]
    open_layers = (Layer("open", changing),)  # type: ignore[arg-type]
    packing.Panel("open", open_layers)
    changing.append(Polyline(((0.0, 0.0), (7.0, 1.0)), Stroke(0.25)))
    assert packing.Panel("open", open_layers).extent == (0.0, 0.0, 7.0, 1.0)


def test_a_page_measures_what_a_drawing_keeps_clear_of_once_for_all_the_spots_it_tries(monkeypatch):
    """A sheet tries some twenty thousand spots; each took the title block's and the corner box's grown boxes
    afresh. Where the drawing goes is what an exhaustive search of the same spots finds."""
    from graphplan.render import packing
    from graphplan.render.primitives import Layer, Polyline, Stroke

    def drawing(name: str, width: float, height: float) -> packing.Panel:
        return packing.Panel(name, (Layer(name, (Polyline(((0.0, 0.0), (width, height)), Stroke(0.25)),)),))

    page = packing.Page(size=(420.0, 297.0), frame=(20.0, 5.0, 415.0, 292.0), block=(230.0, 5.0, 415.0, 60.0),
                        area=(25.0, 10.0, 410.0, 287.0))
    assert page.place(drawing("plan-5", 150.0, 120.0))
    asked = []
    real = packing.Page.obstacles
    monkeypatch.setattr(packing.Page, "obstacles", lambda self: asked.append(1) or real(self))
    assert page.place(drawing("plan-11", 150.0, 120.0))
    assert len(asked) == 1
    (_, first, _), (_, second, _) = page.placed
    assert first == (25.0, 167.0, 175.0, 287.0)  # the top left corner of the area
    # Beside the first, a gap away, level with its top: the most compact of the spots, clear of the title block.
    assert second == (175.0 + packing.GAP_MM, 167.0, 340.0, 287.0)


def test_a_text_set_in_several_reports_is_scanned_for_symbols_once(monkeypatch):
    """The HTML, the LaTeX and the Word document set the same texts, a column's heading on every row: each was
    scanned with the symbols' long pattern afresh."""
    from graphplan.report import symbols

    text = "ω3 = VB / lBC, as read off the plan of position 7"
    first = list(symbols.pieces(text))
    scanned = []
    real = symbols.SYMBOL

    class Counting:
        def finditer(self, text: str):
            scanned.append(text)
            return real.finditer(text)

    monkeypatch.setattr(symbols, "SYMBOL", Counting())
    assert list(symbols.pieces(text)) == first
    assert not scanned
    # Nothing left out, in order; the symbols told apart from the plain runs.
    assert "".join(piece if isinstance(piece, str) else piece.base + piece.index for piece in first) == text
    assert symbols.Symbol("ω", "3", "") in first
    assert " as read off the plan of position 7" in "".join(piece for piece in first if isinstance(piece, str))


def test_the_run_lays_out_the_usual_kinematic_diagrams_once_for_its_drawing_and_its_sheet(monkeypatch, tmp_path):
    import graphplan
    from graphplan.render import diagrams
    from graphplan.run import run

    drawn = []
    real = diagrams.parts
    monkeypatch.setattr(diagrams, "parts", lambda record, text=None, lettered=True: drawn.append(
        (record.scales, lettered)) or real(record, text, lettered))
    done = run(graphplan.load(SCENE), tmp_path / "out", only=["diagrams", "sheets"])
    assert (tmp_path / "out" / "diagrams.svg") in done.files
    assert len(drawn) > 1  # the usual size and the larger ones the sheet tried
    assert len(set(drawn)) == len(drawn), "a size of the diagrams was laid out twice"
    # The larger sizes are measured unlettered: the sheet letters the one it draws, and the usual for diagrams.svg.
    assert sum(lettered for _, lettered in drawn) <= 2


def test_a_run_of_drawings_alone_loads_no_report_writer(tmp_path):
    """`--only velocity` writes the plan sheets and results.json: the LaTeX writer and markdown-it were loaded for
    the tables and the note it does not write."""
    out = tmp_path / "velocity"
    status, modules, _ = _loaded_by("run", str(SCENE), "--out", str(out), "--only", "velocity")
    assert status == 0
    assert sorted(path.name for path in out.iterdir()) == [".graphplan-written", "plan_11.svg", "plan_5.svg",
                                                           "results.json"]
    assert not {"graphplan.report.latex", "graphplan.report.markdown", "markdown_it"} & modules


def test_the_spots_round_a_label_share_their_directions_and_rings_with_every_other_label():
    """A run places a thousand labels, each at ninety-six spots: the order the directions are tried in and each
    spot's ring were built afresh for every one. Shared now, read-only, and the spots where they were."""
    import math

    import numpy as np

    from graphplan.render import labels
    from graphplan.render.primitives import text_width

    assert labels._turns(16) is labels._turns(16)
    assert labels._turns(16).tolist() == [0, 1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6, -6, 7, -7, 8]
    ring, order = labels._rings_and_orders(2, 16)
    assert labels._rings_and_orders(2, 16)[0] is ring
    assert ring.tolist() == [0] * 16 + [1] * 16 and order.tolist() == list(range(16)) * 2
    with pytest.raises(ValueError, match="read-only"):
        ring[0] = 5
    anchor = labels.Anchor((10.0, 20.0), "B", size=3.0, prefer=math.pi / 2)
    rings, orders, boxes = labels._candidates(anchor, 1.2, (0.0, 0.5))
    assert rings.tolist() == ring.tolist() and orders.tolist() == order.tolist()
    # The second ring's third spot: a turn of one sixteenth back from straight up, its near edge 1.2 + 1.5 mm out.
    width = text_width("B", 3.0)
    direction = math.pi / 2 - math.pi / 8
    x = 10.0 + math.cos(direction) * (1.2 + 0.5 * 3.0 + width / 2)
    y = 20.0 + math.sin(direction) * (1.2 + 0.5 * 3.0 + 0.55 * 3.0) - 0.45 * 3.0
    assert boxes[16 + 2] == pytest.approx([x - width / 2, y - 0.9, x + width / 2, y + 3.45], abs=1e-12)
    assert np.all(boxes[:, 2] - boxes[:, 0] == pytest.approx(width))


@pytest.fixture(scope="module")
def bundled_run(tmp_path_factory) -> tuple[set[str], Path]:
    """The modules a fresh interpreter loaded for `graphplan run` of the bundled scene with every piece it writes,
    and the folder written."""
    out = tmp_path_factory.mktemp("cold") / "ratchet"
    status, modules, _ = _loaded_by("run", str(SCENE), "--out", str(out))
    assert status == 0
    return modules, out


def test_a_run_asks_no_array_whether_it_is_masked(bundled_run):
    """np.median (the positions' middling speed), np.unique (a table's column widths) and np.setdiff1d (the label
    placer's whole shapes) each import numpy.ma to ask; nothing in a run is masked."""
    modules, out = bundled_run
    assert (out / "sheet_1.svg").is_file() and (out / "note.tex").is_file()
    assert "numpy.ma" not in modules
    assert not _packages(modules, ("matplotlib", "mpmath", "scipy"))


def test_the_positions_median_is_numpys():
    import numpy as np

    from graphplan.positions import _median

    generator = np.random.default_rng(7)
    for count in (1, 2, 3, 4, 35, 36, 360, 361):
        speeds = np.abs(generator.normal(size=count)) * 10.0 ** generator.integers(-6, 6, size=count)
        assert _median(speeds) == pytest.approx(np.median(speeds), rel=1e-15, abs=0.0)
    assert _median(np.array([3.0, 1.0, 2.0, 10.0])) == 2.5
    assert np.isnan(_median(np.array([])))


def test_a_driver_with_masked_values_is_still_refused_in_a_fresh_interpreter():
    """The solve asks numpy.ma only once something has imported it: a masked array's maker has."""
    code = ("import numpy as np, graphplan, sys\n"
            "scene = graphplan.load(sys.argv[1])\n"
            "try:\n"
            "    graphplan.solve(scene, driver=np.ma.masked_array([0.1, 0.2, 0.3], mask=[False, True, False]))\n"
            "except graphplan.SceneError as refused:\n"
            "    print(refused)\n")
    done = subprocess.run([sys.executable, "-c", code, str(SCENE)], capture_output=True, text=True, cwd=ROOT,
                          check=True)
    assert done.stdout.startswith("driver: has masked values (driver[1])")


def _crowded_labels():
    """A drawing's worth of labels crowded among lines, points and texts: some named on a line, some kept off a
    point, of several sizes and preferred directions."""
    import math

    from graphplan.render import labels
    from graphplan.render.primitives import Circle, Polyline, Stroke, Text

    items = [Polyline(((0.0, 0.0), (60.0 * math.cos(k * 0.7), 60.0 * math.sin(k * 0.7))), Stroke(0.35))
             for k in range(9)]
    items += [Circle((float(x), float(y)), 0.8, Stroke(0.25), fill="black") for x, y in ((10, 5), (-20, 12), (30, -8))]
    items += [Polyline(((-30.0, -30.0), (40.0, -30.0), (40.0, 30.0)), Stroke(0.25), closed=True),
              Text((5.0, 25.0), "a standing text", 3.5, "middle")]
    anchors = [labels.Anchor((4.0 * (k % 7) - 12.0, 3.5 * (k // 7) - 6.0), f"P{k}", size=2.5 + (k % 3) * 0.5,
                             prefer=k * 0.9, keep_off=((0.0, 0.0), 6.0) if k % 5 == 0 else None)
               for k in range(28)]
    anchors.append(labels.Anchor((30.0, 0.0), "F23", along=((20.0, 0.0), (45.0, 0.0))))
    return anchors, labels.obstacles_of(items), [Text((0.0, -3.0), "1", 3.0)]


@pytest.mark.parametrize("off_lines", [False, True])
def test_the_labels_first_spots_costed_together_are_placed_where_each_costed_alone_puts_them(monkeypatch, off_lines):
    """The spots beside every label's point are costed on the drawing for all the labels at once, in one query of the
    drawing's tree: where a label stands is where costing its spots one label at a time put it."""
    from graphplan.render import labels

    anchors, obstacles, standing = _crowded_labels()
    queries: list[int] = []

    class Counted(labels.STRtree):
        def query(self, geometry, *arguments, **keywords):
            queries.append(1)
            return super().query(geometry, *arguments, **keywords)

    monkeypatch.setattr(labels, "STRtree", Counted)
    placed = {}
    for together in (False, True):
        monkeypatch.setattr(labels, "FIRST_RINGS_TOGETHER", together)
        queries.clear()
        placed[together] = labels.place_labels(anchors, obstacles, standing=standing, off_lines=off_lines)
        placed[together, "queries"] = len(queries)
    assert placed[True] == placed[False]
    texts = placed[True].texts
    assert [text.text for text in texts] == [anchor.text for anchor in anchors]
    # Crowded enough that some are led out beyond their first rings, where each label's spots are costed alone.
    assert placed[True].leaders
    # A query of the tree a label, and more, one at a time; one for all the first spots together.
    assert placed[False, "queries"] >= len(anchors)
    assert placed[True, "queries"] <= placed[False, "queries"] - len(anchors) + 1


def test_real_labels_first_spots_costed_together_stand_where_each_costed_alone_puts_them(tmp_path, monkeypatch):
    """Every call of the placer in runs of the bundled scene and of a crowded triad (tests/label_bench.py's loader of
    bench/label_clutter.py records them), placed again with each label's first spots costed alone."""
    sys.path.insert(0, str(ROOT / "tests"))
    try:
        from label_bench import label_clutter
    finally:
        sys.path.remove(str(ROOT / "tests"))
    from graphplan.render import labels

    clutter = label_clutter()
    calls: list = []

    class Keeping(clutter.Recorder):
        def __call__(self, anchors, obstacles, *arguments, **keywords):
            placement = super().__call__(anchors, obstacles, *arguments, **keywords)
            calls.append((list(anchors), list(obstacles), arguments, keywords, placement))
            return placement

    for fixture in ("ratchet_crank_rocker", "triad_class_iii"):
        clutter.run_fixture(ROOT / "fixtures" / f"{fixture}.toml", "en", Keeping(labels.place_labels),
                            tmp_path / fixture)
    assert len(calls) > 30 and sum(len(call[0]) for call in calls) > 300
    assert sum(len(call[4].leaders) for call in calls) > 20 and any(call[3].get("standing") for call in calls)
    monkeypatch.setattr(labels, "FIRST_RINGS_TOGETHER", False)
    for anchors, obstacles, arguments, keywords, placement in calls:
        assert labels.place_labels(anchors, obstacles, *arguments, **keywords) == placement, [a.text for a in anchors]
