"""The report plots' lettering as a student pastes them into a report: ωₙ with its n set as a subscript, a log axis
numbered within its decades (at 2 and 5, as a printed chart is) in the language's decimal mark, the balancing plot's
legend under the plot (not on a curve, a number or a square), and the plots' PNG at a print's 300 dpi while the
drawings' stays at the export's 150.

The plots are made as a user makes them, from the starters (`graphplan new`), in English, Russian and Chinese."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from graphplan.cli import main

pytest.importorskip("matplotlib")

LOCALES = ("en", "ru", "zh")


def _starter(tmp_path: Path, kind: str, locale: str) -> Path:
    scene = tmp_path / f"{kind}-{locale}.toml"
    assert main(["new", kind, "--out", str(scene), "--locale", locale]) == 0
    return scene


def _made(monkeypatch, draw) -> list:
    """The matplotlib figures ``draw()`` saves, laid out by the Agg renderer as saved, with their renderer."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    made = []
    original = Figure.savefig

    def keep(self, *arguments, **options):
        made.append(self)
        return original(self, *arguments, **options)

    monkeypatch.setattr(Figure, "savefig", keep)
    draw()
    drawn = []
    for figure in made:
        canvas = FigureCanvasAgg(figure)
        canvas.draw()
        drawn.append((figure, canvas.get_renderer()))
    return drawn


def _vibration(tmp_path, monkeypatch, locale: str) -> list:
    """The rotor starter's magnification and transmissibility plots in ``locale``."""
    from graphplan.deliverables import vibration_figures
    from graphplan.scene import load

    return _made(monkeypatch, lambda: vibration_figures(load(_starter(tmp_path, "rotor", locale))))


# --- ωₙ -------------------------------------------------------------------------------------------------------------


def _font_has(text, character: str) -> bool:
    """Whether a font of ``text``'s family list, as matplotlib finds it, has ``character`` (fontTools' reading)."""
    from fontTools.ttLib import TTCollection, TTFont
    from matplotlib import font_manager

    for family in text.get_fontproperties().get_family():
        prop = text.get_fontproperties().copy()
        prop.set_family(family)
        try:
            path = font_manager.findfont(prop, fallback_to_default=False)
        except ValueError:
            continue
        faces = TTCollection(path).fonts if path.lower().endswith((".ttc", ".otc")) else [TTFont(path)]
        if any(ord(character) in face.getBestCmap() for face in faces):
            return True
    return False


@pytest.mark.parametrize("locale", LOCALES)
def test_the_natural_frequency_on_the_plots_axis_has_its_n_as_a_subscript(tmp_path, monkeypatch, locale):
    """"r = ω/ωn" printed the n as a letter of the line, as if ω times n; ωₙ (U+2099, in DejaVu Sans, which
    matplotlib ships) or mathtext's ω_n set it small and low."""
    pytest.importorskip("fontTools")
    for figure, _ in _vibration(tmp_path, monkeypatch, locale):
        (axes,) = figure.axes
        label = axes.xaxis.label
        words = label.get_text()
        assert "ω" in words and "ωn" not in words, words
        if "$" in words:  # mathtext
            assert re.search(r"\\omega_\{?n", words), words
        else:
            assert "ωₙ" in words and _font_has(label, "ₙ"), words
