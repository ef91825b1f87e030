"""Report figures of vibration from rotating unbalance: the magnification factor and the transmissibility.

Each figure draws its curve against the frequency ratio r = ω/ωn for
several damping ratios ζ, from :mod:`graphplan.vibration`, and marks a
machine's working point when one is given.  Every word comes from ``text``,
the ``vib_`` keys of a locale (:func:`graphplan.locale.strings`); English when
none is given.  matplotlib is imported only inside the functions, with the Agg
backend; the SVG has no date and a fixed hash salt, so the same call writes
the same bytes.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from ..locale import strings as locale_strings
from ..vibration import transmissibility, unbalance_magnification
from .plot_style import settings, with_decimal_mark

#: Damping ratios drawn when none are asked for (as in the textbooks' charts).
DEFAULT_ZETAS = (0.05, 0.1, 0.15, 0.25, 0.375, 0.5, 1.0)
# Samples along r: dense enough that the sharpest peak drawn (ζ = 0.05) reads smooth.
SAMPLES = 1201



def magnification_figure(path: str | Path, zetas: Sequence[float] = DEFAULT_ZETAS, *,
                         ratio_max: float = 3.0, operating: tuple[float, float] | None = None,
                         text: Mapping[str, str] | None = None) -> Path:
    """Write the magnification factor M·X/(m·e) against r for each ζ in ``zetas`` to ``path`` as SVG.

    ``operating`` = (r, ζ) marks a machine's working point on its curve.
    The ordinate stops at a little above the highest drawn peak (an
    undamped curve is cut there).
    """
    words = {**locale_strings("en"), **(text or {})}
    ratios = np.linspace(0.0, _reaching(ratio_max, operating), SAMPLES)
    curves = [(zeta, unbalance_magnification(ratios, zeta)) for zeta in _checked(zetas)]
    damped = [1.0 / (2.0 * zeta * math.sqrt(1.0 - zeta * zeta)) for zeta in zetas if 0 < zeta < math.sqrt(0.5)]
    top = 1.15 * max([*damped, 2.0])
    return _plot(path, ratios, curves, words, words["vib_magnification"], words["vib_magnification_title"], ylim=(0.0, top), log=False,
                 operating=None if operating is None else (operating[0], unbalance_magnification(*operating)))


def transmissibility_figure(path: str | Path, zetas: Sequence[float] = DEFAULT_ZETAS, *,
                            ratio_max: float = 5.0, operating: tuple[float, float] | None = None,
                            text: Mapping[str, str] | None = None) -> Path:
    """Write the transmissibility TR against r for each ζ in ``zetas`` to ``path`` as SVG, TR on a log scale.

    The isolating range r > √2, where every curve falls below 1, is shaded;
    ``operating`` = (r, ζ) marks a machine's working point.
    """
    words = {**locale_strings("en"), **(text or {})}
    ratios = np.linspace(0.0, _reaching(ratio_max, operating), SAMPLES)
    curves = [(zeta, transmissibility(ratios, zeta)) for zeta in _checked(zetas)]
    working = None if operating is None else (operating[0], transmissibility(*operating))
    lowest = 0.02 if working is None else min(0.02, 0.5 * working[1])
    return _plot(path, ratios, curves, words, words["vib_transmissibility"], words["vib_transmissibility_title"],
                 ylim=(lowest, 20.0), log=True, operating=working, isolation=True)


def _reaching(ratio_max: float, operating: tuple[float, float] | None) -> float:
    """The frequency ratio the plot runs to: ``ratio_max``, or on past a working point beyond it (a fast machine at
    r = 6 fell off the plot its legend named it in)."""
    return ratio_max if operating is None else max(ratio_max, float(math.ceil(1.2 * operating[0])))


def _checked(zetas: Sequence[float]) -> list[float]:
    values = [float(zeta) for zeta in zetas]
    if not values:
        raise ValueError("zetas: must hold at least one damping ratio")
    for k, zeta in enumerate(values):
        if not (math.isfinite(zeta) and zeta >= 0):
            raise ValueError(f"zetas[{k}]: a damping ratio must be >= 0 (got {zeta!r})")
    return values


def _plot(path: str | Path, ratios: np.ndarray, curves: list[tuple[float, np.ndarray]], text: Mapping[str, str],
          ylabel: str, title: str, *, ylim: tuple[float, float], log: bool,
          operating: tuple[float, float] | None, isolation: bool = False) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    # A stream takes the SVG text as it is (a run writes its whole folder at once).
    target = path if hasattr(path, "write") else Path(path)
    with matplotlib.rc_context(settings()):
        figure = Figure(figsize=(7.0, 4.2), dpi=100)
        plot = figure.add_subplot()
        colours = matplotlib.colormaps["viridis"](np.linspace(0.0, 0.85, len(curves)))
        for (zeta, values), colour in zip(curves, colours, strict=True):
            shown = np.where(np.isfinite(values), values, np.nan)
            plot.plot(ratios, shown, color=colour, linewidth=1.3, label=text["vib_zeta"].format(value=f"{zeta:g}"))
        if isolation:
            plot.axvspan(math.sqrt(2.0), ratios[-1], color="#1f7a3a", alpha=0.08, label=text["vib_isolation"])
            plot.axvline(math.sqrt(2.0), color="#1f7a3a", linewidth=0.8, linestyle="--")
            plot.axhline(1.0, color="black", linewidth=0.6)
        else:
            plot.axhline(1.0, color="black", linewidth=0.6, linestyle=":")
        plot.axvline(1.0, color="black", linewidth=0.5, linestyle=":")
        if operating is not None:
            plot.plot([operating[0]], [operating[1]], "o", color="#a83a1f", markersize=6,
                      label=text["vib_operating"])
        if log:
            plot.set_yscale("log")
        plot.set_xlim(ratios[0], ratios[-1])
        plot.set_ylim(*ylim)
        plot.set_xlabel(text["vib_ratio"])
        plot.set_ylabel(ylabel)
        plot.set_title(title, fontsize=11)
        plot.grid(True, which="both", linewidth=0.3)
        plot.legend(fontsize=8, loc="upper right")
        figure.tight_layout()
        with_decimal_mark(figure, text["decimal_mark"])
        if isinstance(target, Path):
            target.parent.mkdir(parents=True, exist_ok=True)
        figure.savefig(target, format="svg", metadata={"Date": None})
    return target


__all__ = ["DEFAULT_ZETAS", "magnification_figure", "transmissibility_figure"]
