"""A diagram that stands on a sheet after the one its drawing begins on says whose it is: "continued".

On an A3 the shaper's acceleration diagram stood alone on the sheet after
its displacement and velocity diagrams, under its caption alone, and read as
a drawing of its own; so did the ratchet's in Russian and in Chinese.  Each
sheet of kinematic diagrams now carries one
heading, the title on the sheet they begin on and the title "continued" on
each sheet after, as the force sheets' parts and the velocity plans' rows do.
The load diagrams too: the V-twin's two stand one to an upright A4.
"""

from __future__ import annotations

import dataclasses
import functools
from pathlib import Path

import pytest

import graphplan
from graphplan import load_diagrams
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.render.primitives import Text, bounds_of
from graphplan.render.sheet import diagrams_panel, kinematics_sheet, load_diagrams_panel

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"


@functools.cache
def analysis_of(name: str, locale: str):
    return analyse(dataclasses.replace(graphplan.load(FIXTURES / f"{name}.toml"), locale=locale))


def headings_on(sheet, drawing: str = "diagrams") -> list[str]:
    """The headings of ``drawing`` (its parts') on ``sheet``, each its lines joined as one title."""
    return [" ".join(item.text for item in layer.items if isinstance(item, Text))
            for layer in sheet.layers if layer.name.startswith(drawing + "-") and layer.name.endswith("title")]


def diagrams_on(sheet, drawing: str = "diagrams") -> list[str]:
    return [name for name in sheet.panels if name.startswith(drawing)]


def assert_headed_continued(panel, sheets, locale: str) -> None:
    """Each of ``sheets`` holds one heading of ``panel``: its title on the first, the title "continued" after."""
    # The case at issue: the diagrams do not stand on one sheet.
    assert len(sheets) > 1
    for number, sheet in enumerate(sheets):
        title = panel.label if number == 0 else strings(locale)["force_sheet_continued"].format(title=panel.label)
        # Broken onto lines where the diagram is narrower than the title: the words, not the breaks, are read.
        assert [heading.split() for heading in headings_on(sheet, panel.name)] == [title.split()], \
            (number, diagrams_on(sheet, panel.name))


@pytest.mark.parametrize(("name", "locale"), [("shaper_six_bar", "en"), ("shaper_six_bar", "ru"),
                                              ("ratchet_crank_rocker", "ru"), ("ratchet_crank_rocker", "zh")])
def test_every_sheet_of_diagrams_after_the_first_is_headed_continued(name, locale):
    panel = diagrams_panel(analysis_of(name, locale), "A3")
    assert_headed_continued(panel, kinematics_sheet([panel], "A3", locale), locale)


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_every_sheet_of_load_diagrams_after_the_first_is_headed_continued(locale):
    panel = load_diagrams_panel(load_diagrams.of_analysis(analysis_of("v_twin_engine", locale)), locale, "A4")
    assert_headed_continued(panel, kinematics_sheet([panel], "A4", locale), locale)


def test_a_diagram_on_the_sheet_of_the_one_before_stands_under_that_one_s_heading():
    """The shaper's displacement and velocity diagrams share the first English A3: the velocity diagram is not
    headed "continued" there, and stands under the displacement diagram, as in the drawing whole."""
    sheets = kinematics_sheet([diagrams_panel(analysis_of("shaper_six_bar", "en"), "A3")], "A3", "en")
    first = sheets[0]
    assert diagrams_on(first) == ["diagrams-1", "diagrams-2"]
    assert len(headings_on(first)) == 1

    def extent(part: str) -> tuple[float, float, float, float]:
        return bounds_of(item for layer in first.layers if layer.name.startswith(part + "-") for item in layer.items)

    displacement, velocity = extent("diagrams-1"), extent("diagrams-2")
    assert velocity[3] < displacement[1]
