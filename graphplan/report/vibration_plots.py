"""Report figures of vibration from rotating unbalance: the magnification factor and the transmissibility.

Each figure draws its curve against the frequency ratio r = ω/ωn for
several damping ratios ζ, from :mod:`graphplan.vibration`, and marks a
machine's working point when one is given, on the curve of the machine's
own ζ, drawn thicker in the point's colour (added where the textbook set
lacks it); the transmissibility also marks the isolating mounts' design
point.  A machine on a moving base with no unbalance of its own reads the
same curves as Z/Y and X/Y (:func:`words_for`).  Every word comes from ``text``,
the ``vib_`` keys of a locale (:func:`graphplan.locale.strings`); English when
none is given.  matplotlib is imported only inside the functions, and its figures made without
pyplot (a notebook's backend is left as it was); the SVG has no date and a fixed hash salt, so the same call writes
the same bytes.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from ..locale import strings as locale_strings
from ..render.numerals import short
from ..vibration import LARGE_MAGNIFICATION, VibrationSpec, transmissibility, unbalance_magnification
from .plot_style import (
    PAGE_WIDTH_INCHES,
    legend_under,
    new_figure,
    number_log_axes,
    settings,
    with_decimal_mark,
    write_svg,
)

#: Damping ratios drawn when none are asked for (as in the textbooks' charts).
DEFAULT_ZETAS = (0.05, 0.1, 0.15, 0.25, 0.375, 0.5, 1.0)
# Samples along r: dense enough that the sharpest peak drawn (ζ = 0.05) reads smooth.
SAMPLES = 1201
# The machine's own curve and its working point.
MACHINE_COLOUR = "#a83a1f"
#: A damped peak or a working point's magnification above this sets no ordinate: drawn to scale, ζ = 1e-9's peak of
#: 5·10⁸ flattened every other curve and the working point to nought.  Such a curve is cut at the top as an undamped
#: one is, and such a point marked on the top edge with its value.  Ten times the warning's large magnification,
#: the peak of ζ = 0.005, while the textbooks' charts stop at ζ = 0.05 (a peak of 10).
MOST_TO_SCALE = 10.0 * LARGE_MAGNIFICATION
#: A plot that has to run past this frequency ratio (a working point or isolating mounts far above resonance: r = 200
#: for TR = 0.01 at ζ = 1) runs on a logarithmic axis from :data:`LEAST_LOG_RATIO`: on a linear one to 240 the
#: resonance, where the curves differ, was squeezed into the first two millimetres.
LOG_RATIO_FROM = 20.0
LEAST_LOG_RATIO = 0.1


def magnification_figure(path: str | Path, zetas: Sequence[float] = DEFAULT_ZETAS, *,
                         ratio_max: float = 3.0, operating: tuple[float, float] | None = None,
                         text: Mapping[str, str] | None = None) -> Path:
    """Write the magnification factor M·X/(m·e) against r for each ζ in ``zetas`` to ``path`` as SVG.

    ``operating`` = (r, ζ) marks a machine's working point on the curve of its ζ.
    The ordinate stops at a little above the highest damped peak drawn and the working point (an
    undamped curve is cut there), leaving out peaks and a working point above :data:`MOST_TO_SCALE`: a damping
    so small is drawn as none is.
    """
    words = {**locale_strings("en"), **(text or {})}
    ratios = _ratios(_reaching(ratio_max, operating))
    drawn = _with_machine(_checked(zetas), operating)
    curves = [(zeta, unbalance_magnification(ratios, zeta)) for zeta in drawn]
    working = None if operating is None else (operating[0], unbalance_magnification(*operating))
    peaks = [1.0 / (2.0 * zeta * math.sqrt(1.0 - zeta * zeta)) for zeta in drawn if 0 < zeta < math.sqrt(0.5)]
    shown = [value for value in [*peaks, *([] if working is None else [working[1]])] if value <= MOST_TO_SCALE]
    top = 1.15 * max([*shown, 2.0])
    return _plot(path, ratios, curves, words, words["vib_magnification"], words["vib_magnification_title"],
                 ylim=(0.0, top), log=False, operating=working,
                 machine=None if operating is None else operating[1])


def transmissibility_figure(path: str | Path, zetas: Sequence[float] = DEFAULT_ZETAS, *,
                            ratio_max: float = 5.0, operating: tuple[float, float] | None = None,
                            design: tuple[float, float] | None = None,
                            text: Mapping[str, str] | None = None) -> Path:
    """Write the transmissibility TR against r for each ζ in ``zetas`` to ``path`` as SVG, TR on a log scale.

    The isolating range r > √2, where every curve falls below 1, is shaded;
    ``operating`` = (r, ζ) marks a machine's working point on the curve of its ζ, and ``design`` = (r, TR)
    the isolating mounts' (the ratio that gives the wanted TR at the machine's ζ).
    """
    words = {**locale_strings("en"), **(text or {})}
    reach = _reaching(ratio_max, operating)
    if design is not None:
        reach = max(reach, float(math.ceil(1.2 * design[0])))
    ratios = _ratios(reach)
    curves = [(zeta, transmissibility(ratios, zeta)) for zeta in _with_machine(_checked(zetas), operating)]
    working = None if operating is None else (operating[0], transmissibility(*operating))
    lowest = min([0.02, *(0.5 * point[1] for point in (working, design) if point is not None)])
    return _plot(path, ratios, curves, words, words["vib_transmissibility"], words["vib_transmissibility_title"],
                 ylim=(lowest, 20.0), log=True, operating=working, isolation=True,
                 machine=None if operating is None else operating[1], design=design)


def words_for(spec: VibrationSpec, text: Mapping[str, str] | None) -> Mapping[str, str] | None:
    """The plots' words for ``spec`` (``text`` as the figures take it; None: English): a machine with no unbalance
    on a moving base reads the magnification as its motion relative to the base, Z/Y, and the transmissibility as
    the motion passed to it, X/Y (the same curves), not as a rotating unbalance and a force.  A disc on a shaft
    has its whole support designed, the shaft and any mounts under its bearings, not mounts alone, and passes the
    force through its bearings to the frame."""
    moved = spec.unbalance == 0 and spec.base_amplitude is not None
    if not (moved or spec.on_shaft):
        return text
    words = {**locale_strings("en"), **(text or {})}
    if spec.on_shaft:
        # Its bearings pass the force to the frame, as the note says, not mounts to a base.
        words["vib_design"] = words["vib_design_shaft"]
        words["vib_transmissibility_title"] = words["vib_transmissibility_title_shaft"]
    if moved:
        words.update({"vib_magnification": words["vib_relative"], "vib_magnification_title": words["vib_relative_title"],
                      "vib_transmissibility": words["vib_motion"], "vib_transmissibility_title": words["vib_motion_title"],
                      "vib_zeta_machine": words["vib_zeta_instrument"]})
    return words


def _with_machine(zetas: list[float], operating: tuple[float, float] | None) -> list[float]:
    """The damping ratios drawn: the set asked for and the machine's own, in order (once, if the set has it)."""
    if operating is None or any(math.isclose(zeta, operating[1], rel_tol=1e-9, abs_tol=1e-12) for zeta in zetas):
        return zetas
    return sorted([*zetas, float(operating[1])])


def _reaching(ratio_max: float, operating: tuple[float, float] | None) -> float:
    """The frequency ratio the plot runs to: ``ratio_max``, or on past a working point beyond it (a fast machine at
    r = 6 fell off the plot its legend named it in)."""
    return ratio_max if operating is None else max(ratio_max, float(math.ceil(1.2 * operating[0])))


def _ratios(reach: float) -> np.ndarray:
    """The frequency ratios sampled up to ``reach``: evenly from 0, or beyond :data:`LOG_RATIO_FROM` evenly in log r
    from :data:`LEAST_LOG_RATIO` (the plot then runs on a log axis)."""
    if reach > LOG_RATIO_FROM:
        return np.geomspace(LEAST_LOG_RATIO, reach, SAMPLES)
    return np.linspace(0.0, reach, SAMPLES)


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
          operating: tuple[float, float] | None, isolation: bool = False, machine: float | None = None,
          design: tuple[float, float] | None = None) -> Path:
    import matplotlib

    # A stream takes the SVG text as it is (a run writes its whole folder at once).
    target = path if hasattr(path, "write") else Path(path)
    with matplotlib.rc_context(settings()):
        figure = new_figure(figsize=(PAGE_WIDTH_INCHES, 5.0), dpi=100)
        plot = figure.add_subplot()
        colours = matplotlib.colormaps["viridis"](np.linspace(0.0, 0.85, len(curves)))
        for (zeta, values), colour in zip(curves, colours, strict=True):
            shown = np.where(np.isfinite(values), values, np.nan)
            if machine is not None and math.isclose(zeta, machine, rel_tol=1e-9, abs_tol=1e-12):
                plot.plot(ratios, shown, color=MACHINE_COLOUR, linewidth=2.4, zorder=3,
                          label=text["vib_zeta_machine"].format(value=short(zeta, 6)))
            else:
                # A number as a textbook writes it, 0.00001, not 1e-05.
                plot.plot(ratios, shown, color=colour, linewidth=1.3, label=text["vib_zeta"].format(value=short(zeta, 6)))
        if isolation:
            plot.axvspan(math.sqrt(2.0), ratios[-1], color="#1f7a3a", alpha=0.08, label=text["vib_isolation"])
            plot.axvline(math.sqrt(2.0), color="#1f7a3a", linewidth=0.8, linestyle="--")
            plot.axhline(1.0, color="black", linewidth=0.6)
        else:
            plot.axhline(1.0, color="black", linewidth=0.6, linestyle=":")
        plot.axvline(1.0, color="black", linewidth=0.5, linestyle=":")
        if operating is not None and operating[1] <= ylim[1]:
            plot.plot([operating[0]], [operating[1]], "o", color=MACHINE_COLOUR, markersize=6, zorder=4,
                      label=text["vib_operating"])
        elif operating is not None:  # above the ordinate: on its top edge, pointing up, its value in the legend
            plot.plot([operating[0]], [ylim[1]], "^", color=MACHINE_COLOUR, markersize=7, zorder=4, clip_on=False,
                      label=text["vib_operating_off"].format(value=short(operating[1], 3)))
        if design is not None:
            plot.plot([design[0]], [design[1]], "D", color="#1f7a3a", markeredgecolor="black", markersize=6, zorder=4,
                      label=text["vib_design"].format(tr=short(design[1], 6), ratio=short(design[0], 3)))
        if log:
            plot.set_yscale("log")
        if ratios[0] > 0:  # sampled in log r (:func:`_ratios`)
            plot.set_xscale("log")
        plot.set_xlim(ratios[0], ratios[-1])
        plot.set_ylim(*ylim)
        plot.set_xlabel(text["vib_ratio"])
        plot.set_ylabel(ylabel)
        plot.set_title(title, fontsize=11)
        plot.grid(True, which="both", linewidth=0.3)
        figure.tight_layout()
        # Numbered once laid out, where the room between the numbers is known.
        number_log_axes(figure)
        # Under the plot, not on it: inside, it hid a curve wherever the curves ran (ζ = 1 at r ≈ 3.3–4.3); beside it,
        # on a figure as wide as a report's page, it left the curves half the width.
        legend_under(figure, plot, ncol=3, laid_out=True)
        with_decimal_mark(figure, text["decimal_mark"])
        if isinstance(target, Path):
            target.parent.mkdir(parents=True, exist_ok=True)
        write_svg(figure, target)
    return target


__all__ = ["DEFAULT_ZETAS", "magnification_figure", "transmissibility_figure", "words_for"]
