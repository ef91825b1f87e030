"""No load's name on Zhukovsky's lever lies on a line: read back from the SVG a run writes, by the bench's measure.

On the crowded levers of the triads and of the Stephenson six-bar the names of a few loads lay on bars, rays and
other arrows where no spot within reach of their arrows was clear: the class III triad's G6 and Mu6″ at position 8
(and its Mu6″ at position 2), the Stephenson six-bar's Fu3 at position 9, the triad with a slider's Fu4 at position 8.
Each is now lettered off the lines or, where it cannot be, given under the lever by the point its arrow stands at,
that point keeping no other arrow unnamed, so that a reader still finds which arrow it names.

A label lies on a line as ``bench/label_clutter.py`` counts it: its box as graphplan sets it (``text_extent``, read
back from the SVG text's position and size) meets a drawn path, an arrow's shaft or head, a circle's outline but a
point's dot, or another label's leader.  The fixture's count of labels on lines over all its drawings, by the bench's
own recorder, must not rise above the count at the commit this work started from.
"""

import re
from pathlib import Path
from xml.etree import ElementTree

import pytest
from label_bench import label_clutter
from shapely.geometry import LineString, Point, Polygon

from graphplan.render import labels
from graphplan.render.primitives import FONT_SIZE_PER_CAP, Text, svg_id

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"
# The bench's own: a circle smaller than this (radius, mm) is a point's dot, not a line a label lies on.
DOT_RADIUS = 1.5
# A label's own leader ends 0.3 mm short of its box; every other label's box stands 0.8 mm off it.
OWN_LEADER_MM = 0.5
# Labels on lines per fixture (en, `--sheet none`) by bench/label_clutter.py at 7067bd2, where this work started.
ON_LINES_BEFORE = {"triad_class_iii": 4, "stephenson_six_bar": 1, "triad_with_slider": 3}
# The names that lay on lines: (fixture, position, load).
NAMES = [("triad_class_iii", 8, "G6"), ("triad_class_iii", 8, "Mu6″"), ("triad_class_iii", 2, "Mu6″"),
         ("stephenson_six_bar", 9, "Fu3"), ("triad_with_slider", 8, "Fu4")]


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """Each fixture run as the bench runs it (English, no sheets): its labels on lines counted, its folder."""
    clutter = label_clutter()
    found = {}
    for fixture in ON_LINES_BEFORE:
        out = tmp_path_factory.mktemp("runs") / fixture
        counted = clutter.run_fixture(ROOT / "fixtures" / f"{fixture}.toml", "en", labels.place_labels, out)
        found[fixture] = (counted.on_line, out)
    return found


def points_of(d: str) -> list[tuple[float, float]]:
    # SVG's y points down; the paper's, which graphplan's text boxes are measured in, up.
    return [(float(x), -float(y)) for x, y in re.findall(r"(-?[\d.]+),(-?[\d.]+)", d)]


def lever(svg: Path):
    """The lever's labels (as graphplan's Texts), its drawn lines, its leaders and its caption's lines."""
    texts, lines, leaders, caption = [], [], [], []
    for group in ElementTree.parse(svg).getroot().iter(f"{SVG}g"):
        name = group.get("id") or ""
        if not name.startswith("lever"):
            continue
        if name == "lever-labels":
            texts += [Text((float(text.get("x")), -float(text.get("y"))), "".join(text.itertext()),
                           float(text.get("font-size")) / FONT_SIZE_PER_CAP, text.get("text-anchor", "start"))
                      for text in group.iter(f"{SVG}text")]
        elif name == "lever-caption":
            caption += ["".join(text.itertext()) for text in group.iter(f"{SVG}text")]
        elif name == "lever-leaders":
            leaders += [LineString(points_of(path.get("d"))) for path in group.iter(f"{SVG}path")]
        else:
            for path in group.iter(f"{SVG}path"):
                points, closed = points_of(path.get("d")), path.get("d").rstrip().endswith("Z")
                if closed and path.get("fill", "none") != "none":
                    lines.append(Polygon(points))  # an arrowhead
                else:
                    lines.append(LineString(points + points[:1] if closed else points))
            lines += [Point(float(c.get("cx")), -float(c.get("cy"))).buffer(float(c.get("r"))).boundary
                      for c in group.iter(f"{SVG}circle") if float(c.get("r")) >= DOT_RADIUS]
    return texts, lines, leaders, caption


def on_lines(svg: Path) -> list[str]:
    """The lever's labels whose boxes meet one of its lines or a leader not their own."""
    texts, lines, leaders, _ = lever(svg)
    lying = []
    for text in texts:
        box = labels.text_box(text)
        others = [leader for leader in leaders if box.distance(Point(leader.coords[-1])) > OWN_LEADER_MM]
        if any(box.intersects(line) for line in lines + others):
            lying.append(text.text)
    return lying


def unnamed(caption: list[str]) -> list[tuple[str, str]]:
    """The (load, point) pairs the caption gives under the lever: ``arrows left unnamed: G6 at s6,  Mu6″ at σ6``."""
    given = " ".join(line.split(": ", 1)[1] for line in caption if line.startswith("arrows left unnamed: "))
    return re.findall(r"(\S+) at ([^,\s]+)", given)


def test_the_reading_back_sees_a_label_laid_on_a_line(tmp_path):
    # The check itself: a name set over a bar is seen on it, one set clear of it is not, nor one by its own leader.
    svg = tmp_path / "lever.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg"><g id="lever-plan"><path d="M0,10 L40,10" /></g>'
                   '<g id="lever-leaders"><path d="M30,20 L30,8.6" /></g>'
                   '<g id="lever-labels"><text font-size="4.444" text-anchor="middle" x="10" y="11.5">Fu4</text>'
                   '<text font-size="4.444" text-anchor="middle" x="30" y="4">h8</text></g></svg>', encoding="utf-8")
    assert on_lines(svg) == ["Fu4"]


@pytest.mark.parametrize(("fixture", "position", "name"), NAMES)
def test_the_load_s_name_is_off_the_lines_and_names_its_arrow(runs, fixture, position, name):
    svg = runs[fixture][1] / f"forces_{position}.svg"
    texts, _, _, caption = lever(svg)
    lettered = [text.text for text in texts]
    given = unnamed(caption)
    assert name not in on_lines(svg)
    # Its arrow is drawn, and its name is either beside it or under the lever with the point its arrow stands at.
    assert svg_id("lever", name) in {group.get("id") for group in ElementTree.parse(svg).getroot().iter(f"{SVG}g")}
    at = [point for load, point in given if load == name]
    assert (name in lettered) != bool(at), f"{name}: lettered {name in lettered}, given under the lever at {at}"
    if at:
        # The point is lettered on the lever (alone or among the points it shares its image with), and it keeps no
        # other arrow unnamed: the one arrow there without a name is this load's.
        assert any(at[0] in text.split(", ") for text in lettered), (at, lettered)
        assert [point for _, point in given].count(at[0]) == 1, given


@pytest.mark.parametrize("fixture", ON_LINES_BEFORE)
def test_no_more_labels_of_the_fixture_lie_on_lines_than_before(runs, fixture):
    assert runs[fixture][0] <= ON_LINES_BEFORE[fixture]
