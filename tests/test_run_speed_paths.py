"""What a cold run of the bundled scene no longer does (bench/cold_run.py), each held to an independent reckoning of
what it gives: the fonts' advances read without their glyph names, the symbols' shapes tried only where one may
begin, the obstacles and the bounds of a drawing found for all its items at once, a page's spots tried only against
the boxes level with them, no subprocess machinery loaded and no distribution searched for a library the run has
imported.
"""

from __future__ import annotations

import importlib.util
import json
import random
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
import shapely
from fontTools.ttLib import TTFont
from fontTools.ttLib.tables import _p_o_s_t

from graphplan.render import labels, packing, primitives
from graphplan.render.primitives import Arrow, Circle, Polyline, Stroke, Text
from graphplan.report import symbols

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "fixtures" / "ratchet_crank_rocker.toml"


def _fresh(code: str) -> list:
    """What ``code``, run in a fresh interpreter from the project's root, prints last as JSON."""
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    return json.loads(done.stdout.splitlines()[-1])


def test_a_run_of_the_bundled_scene_loads_no_subprocess_machinery(tmp_path):
    """Only a text mixing Chinese with Latin letters asks fontconfig for its fonts: the bundled scene has none."""
    out = tmp_path / "ratchet"
    status, loaded = _fresh("import json, sys\nfrom graphplan.cli import main\n"
                            f"status = main(['run', {str(SCENE)!r}, '--out', {str(out)!r}])\n"
                            "print(json.dumps([status, 'subprocess' in sys.modules]))")
    assert status == 0 and (out / "sheet_1.svg").is_file()
    assert not loaded


def test_a_scene_loads_the_solvers_of_its_own_group_kinds_alone(tmp_path):
    """The bundled scene's RRR loads rrr.py (and the driver's module) of the seven kinds' modules; a triad's scene
    loads triad.py; every kind the registry names is the class of that kind."""
    from graphplan.groups import GROUPS

    assert {kind: GROUPS[kind].kind for kind in GROUPS} == {kind: kind for kind in GROUPS}
    assert set(GROUPS) == {"RRR", "RRP", "RPR", "PRP", "RPP", "triad"}
    loaded = {}
    for name in ("ratchet_crank_rocker", "triad_class_iii"):
        loaded[name] = _fresh("import json, sys, graphplan\n"
                              f"graphplan.solve(graphplan.load({str(ROOT / 'fixtures' / f'{name}.toml')!r}))\n"
                              "print(json.dumps(sorted(m for m in sys.modules if m.startswith('graphplan.groups.'))))")
    kinds = ("rrr", "rrp", "rpr", "prp", "rpp", "triad")
    assert [m for m in loaded["ratchet_crank_rocker"] if m.rsplit(".", 1)[1] in kinds] == ["graphplan.groups.rrr"]
    assert "graphplan.groups.triad" in loaded["triad_class_iii"]
    assert "graphplan.groups.rpp" not in loaded["triad_class_iii"]


def test_the_versions_of_imported_libraries_are_their_own_and_only_the_others_are_searched_for():
    """numpy's and shapely's versions from their __version__; scipy (which a run never imports) and svgwrite (not
    yet imported when results.json is written) from their distributions, without importing them."""
    asked, scipy_loaded, found, expected = _fresh(
        "import json, sys\nfrom importlib import metadata\nimport numpy, shapely\n"
        "asked = []\nreal = metadata.version\n"
        "metadata.version = lambda name: asked.append(name) or real(name)\n"
        "from graphplan.report.results import versions\n"
        "found = versions()\n"
        "expected = {name: real(name) for name in ('numpy', 'scipy', 'shapely', 'svgwrite')}\n"
        "print(json.dumps([asked, 'scipy' in sys.modules, found, expected]))")
    assert sorted(asked) == ["scipy", "svgwrite"]
    assert not scipy_loaded
    assert {name: found[name] for name in expected} == expected


@pytest.mark.parametrize("weight", ["normal", "bold"])
def test_the_fonts_advances_are_read_without_their_glyph_names(monkeypatch, weight):
    """Every character's advance is the one fontTools gives by the glyph's name, read the usual way; the post table's
    names are never decoded."""
    folder = Path(importlib.util.find_spec("matplotlib").submodule_search_locations[0]) / "mpl-data" / "fonts" / "ttf"
    font = TTFont(folder / ("DejaVuSans-Bold.ttf" if weight == "bold" else "DejaVuSans.ttf"))
    names, metrics, units = font.getBestCmap(), font["hmtx"], font["head"].unitsPerEm

    def refuse(*_arguments):
        raise AssertionError("the glyph names were read")

    monkeypatch.setattr(_p_o_s_t.table__p_o_s_t, "decode_format_2_0", refuse)
    primitives._dejavu_advances.cache_clear()
    try:
        advance = primitives._dejavu_advances(weight)
    finally:
        monkeypatch.undo()
        primitives._dejavu_advances.cache_clear()
    characters = [chr(code) for code in names if not primitives.is_wide(chr(code))]
    assert len(characters) > 5000
    assert all(advance(character) == metrics[names[ord(character)]][0] / units for character in characters)
    assert advance("\U0001F600") is None  # no glyph: measured by its class


def _shapes_without_the_guard() -> re.Pattern[str]:
    """The symbols' shapes as :data:`~graphplan.report.symbols.SYMBOL` has them, without its first-character guard."""
    guard = f"(?=[{re.escape(symbols.FIRST_CHARACTERS)}])"
    assert symbols.SYMBOL.pattern.startswith(guard)
    return re.compile(symbols.SYMBOL.pattern.removeprefix(guard))


def test_the_symbols_are_found_where_every_shape_is_tried_at_every_character():
    """The locales' strings and a run's tables, scanned with the guard and without it: the same symbols at the same
    places; and every symbol the shapes find begins with a character of the guard."""
    shapes = _shapes_without_the_guard()
    texts = []
    for locale in ("en", "ru", "zh"):
        texts += tomllib.loads((ROOT / "graphplan" / "locales" / f"{locale}.toml").read_text(encoding="utf-8")).values()
    texts += ["VBA = VB + VBA", "aBAτ, aBA^τ, aBB4ʳ", "ω3, ε4, ψ4; μV μa μF", "R23τ R43n", "Fu3 Mu3 Mb Fb Mf12",
              "II2(3,4)", "ΔWmax ΔTнб Je,mean Jп,ср", "(m1r1)L (m·r)A mi·ri zR", "dωd/dt", "ΣMp = 0", "πn2/30"]
    found = 0
    for text in texts:
        guarded = [(match.span(), match.groupdict()) for match in symbols.SYMBOL.finditer(text)]
        assert guarded == [(match.span(), match.groupdict()) for match in shapes.finditer(text)], text
        found += len(guarded)
    assert found > 500
    # Every symbol found begins with a character the guard lets through.
    assert {match[0][0] for text in texts for match in shapes.finditer(text)} <= set(symbols.FIRST_CHARACTERS)


def _random_items(generator: random.Random, count: int) -> list:
    """Primitives of every kind at random, some of them filled, closed or turned."""
    def point() -> tuple[float, float]:
        return (generator.uniform(-50, 50), generator.uniform(-50, 50))

    items: list = []
    for _ in range(count):
        kind = generator.randrange(5)
        if kind == 0:
            items.append(Polyline(tuple(point() for _ in range(generator.randrange(0, 6))), Stroke(0.25),
                                  closed=generator.random() < 0.5, fill="black" if generator.random() < 0.3 else None))
        elif kind == 1:
            items.append(Arrow(point(), point(), Stroke(0.35)))
        elif kind == 2:
            items.append(Circle(point(), generator.uniform(0.1, 5.0), Stroke(0.25)))
        else:
            items.append(Text(point(), generator.choice(["B", "ω3", "Fu23", "力 F", ""]), generator.uniform(2, 5),
                              generator.choice(["start", "middle", "end"]), rotation=generator.choice([0.0, 30.0])))
    return items


def test_a_drawings_obstacles_and_bounds_are_each_items_own():
    """The shapes made for all the items at once are those shapely makes of each alone, in the items' order; the
    bounds are the least and greatest of every item's own."""
    generator = random.Random(11)
    for count in (0, 1, 2, 7, 60):
        items = _random_items(generator, count)
        alone = []
        for item in items:
            if isinstance(item, Polyline) and item.closed and item.fill and len(item.points) >= 3:
                alone.append(shapely.Polygon(item.points))
            elif isinstance(item, Polyline) and len(item.points) >= 2:
                alone.append(shapely.LineString(item.points + ((item.points[0],) if item.closed else ())))
            elif isinstance(item, Arrow):
                alone += [shapely.LineString((item.start, item.end)), shapely.Polygon(item.tip().points)]
            elif isinstance(item, Circle):
                alone.append(shapely.Point(item.centre).buffer(item.radius))
            elif isinstance(item, Text):
                alone.append(shapely.box(*primitives.text_extent(item)))
        made = labels.obstacles_of(items)
        assert [shapely.to_wkb(shape) for shape in made] == [shapely.to_wkb(shape) for shape in alone]
        assert primitives.bounds_of(items) == _each_items_bounds(items)


def _each_items_bounds(items) -> tuple[float, float, float, float]:
    """The least and greatest of every item's own extent, each item measured alone; a unit square for none."""
    extents = []
    for item in items:
        if isinstance(item, Polyline) and item.points:
            extents.append((min(x for x, _ in item.points), min(y for _, y in item.points),
                            max(x for x, _ in item.points), max(y for _, y in item.points)))
        elif isinstance(item, Arrow):
            extents.append((min(item.start[0], item.end[0]), min(item.start[1], item.end[1]),
                            max(item.start[0], item.end[0]), max(item.start[1], item.end[1])))
        elif isinstance(item, Circle):
            extents.append((item.centre[0] - item.radius, item.centre[1] - item.radius,
                            item.centre[0] + item.radius, item.centre[1] + item.radius))
        elif isinstance(item, Text):
            extents.append(primitives.text_extent(item))
    return (min(e[0] for e in extents), min(e[1] for e in extents), max(e[2] for e in extents),
            max(e[3] for e in extents)) if extents else (0.0, 0.0, 1.0, 1.0)


def test_moved_layers_are_measured_by_shifting_their_lines_and_are_bit_for_bit_their_items_bounds(monkeypatch):
    """A measured layer moved (again and again, and renamed) keeps its lines' and arrows' bounds shifted, not
    measured again: the bounds of layers so moved are exactly those of their moved items each measured alone,
    turned texts and circles included, whose corners do not shift bit for bit and are measured anew."""
    measured: list = []
    whole = primitives._bounds_or_none

    def recorded(items):
        items = list(items)
        measured.extend(items)
        return whole(items)

    monkeypatch.setattr(primitives, "_bounds_or_none", recorded)
    generator = random.Random(5)
    for _ in range(40):
        layers = [primitives.Layer(f"layer-{k}", tuple(_random_items(generator, generator.randrange(0, 8))))
                  for k in range(generator.randrange(1, 5))]
        assert primitives.bounds(layers) == _each_items_bounds([item for layer in layers for item in layer.items])
        for _ in range(3):
            dx, dy = generator.uniform(-300, 300) / 7, generator.uniform(-300, 300) / 3
            layers = primitives.prefixed(primitives.moved_layers(layers, dx, dy), "field")
            measured.clear()
            got = primitives.bounds(layers)
            assert got == _each_items_bounds([item for layer in layers for item in layer.items])
            assert not [item for item in measured if isinstance(item, (Polyline, Arrow))]


def test_a_page_puts_each_drawing_where_trying_every_spot_against_every_box_puts_it():
    """Drawings of random sizes put one after another on A3 and A1 pages with and without a corner box: each where
    the spot of :meth:`Page._spots`' candidates that is inside the area, clear of every box and most compact
    stands, found by trying each spot against each box."""
    generator = random.Random(5)

    def panel(name: str) -> packing.Panel:
        width, height = generator.uniform(20, 250), generator.uniform(20, 200)
        return packing.Panel(name, (primitives.Layer(name, (Polyline(((0.0, 0.0), (width, height)), Stroke(0.25)),)),))

    def exhaustive(page: packing.Page, drawing: packing.Panel):
        x0, y0, x1, y1 = drawing.extent
        width, height = x1 - x0, y1 - y0
        rects = [rect for _, rect, _ in page.placed]
        same = [rect for placed, rect, _ in page.placed if packing._kind(placed) == packing._kind(drawing)]
        xs = {page.area[0], page.area[2] - width, *(r[2] + packing.GAP_MM for r in rects),
              *(r[0] - packing.GAP_MM - width for r in rects), *(r[0] for r in rects)}
        tops = {page.area[3], page.block[3] + packing.PADDING_MM + height, *(r[1] - packing.GAP_MM for r in rects),
                *(r[3] for r in rects)}
        if page.corner is not None:
            xs.add(page.corner[2] + packing.PADDING_MM)
            tops.add(page.corner[1] - packing.PADDING_MM)
        blocked = [*page.obstacles(), *(packing._grown(r, packing.GAP_MM - packing._EDGE) for r in rects)]
        highest = page.area[3] if page.corner is None or not page.tuck else page.corner[1] - packing.PADDING_MM
        edge = packing._EDGE
        best = None
        for top in tops:
            for left in xs:
                rect = (left, top - height, left + width, top)
                inside = (rect[0] >= page.area[0] - edge and rect[1] >= page.area[1] - edge
                          and rect[2] <= page.area[2] + edge and rect[3] <= page.area[3] + edge)
                clear = not any(rect[0] < b[2] and b[0] < rect[2] and rect[1] < b[3] and b[1] < rect[3]
                                for b in blocked)
                after = all(packing._reads_after(rect, earlier) for earlier in same)
                if not (inside and clear and after):
                    continue
                every = [*rects, rect]
                union = (min(r[0] for r in every), min(r[1] for r in every), max(r[2] for r in every),
                         max(r[3] for r in every))
                key = page._compactness((union[2] - union[0]) / (page.area[2] - page.area[0]),
                                        (union[3] - union[1]) / (page.area[3] - page.area[1]))
                key += (-min(top, highest), left, top)
                if best is None or key < best[0]:
                    best = (key, rect)
        return None if best is None else best[1]

    tried = 0
    for sheet, form in (("A3", "iso"), ("A1", "eskd"), ("A3", "eskd")):
        for portrait in (False, True):
            page = packing._empty_page(sheet, form, portrait)
            for number in range(12):
                drawing = panel(f"{('plan', 'forces')[number % 2]}-{number}")
                assert next(iter(page._spots(drawing, 1)), None) == exhaustive(page, drawing)
                tried += 1
                page.place(drawing)
    assert tried == 72
