"""The Python interface reviewed as a student or teacher scripts it in a notebook.

The docstrings' examples run as printed; the numbers a motion hands out are checked against closed forms written
here (a four-bar's loop-closure velocities, a slider-crank's position differentiated, a slotted lever's slide), the
balancing moment's sign against the power balance; and a user's mistakes are graphplan's errors, naming what was
asked and what there is. The review found: an unknown point, link, sliding pair or reaction raised a bare
``KeyError`` (printed quoted, no ``GraphplanError``), positions picked past the motion a bare ``IndexError``; a NaN
among 36 000 driver angles was told without its index, a 2-D array without its shape; a frame guide's ``u`` came
out of ``motion.slide(n)`` as one number where the docs promise every slide array ``(N,)``; and the equilibrium's
arrays (``analysis.equilibrium.balancing``) could be written through, where the README says results are read-only.
"""

from __future__ import annotations

import textwrap
import tomllib
from pathlib import Path

import numpy as np
import pytest

import graphplan
import graphplan.notebook

ROOT = Path(__file__).resolve().parents[1]
FIXTURES = ROOT / "fixtures"
RATCHET = FIXTURES / "ratchet_crank_rocker.toml"
HACKSAW = FIXTURES / "offset_slider_crank.toml"
SLOTTED = FIXTURES / "quick_return_slotted_lever.toml"


@pytest.fixture(scope="module")
def ratchet():
    return graphplan.load(RATCHET)


def literal_blocks(doc: str) -> list[str]:
    """The reStructuredText literal blocks (a paragraph ending ``::``, then the indented lines) of a docstring."""
    blocks = []
    parts = doc.split("::\n")
    for part in parts[1:]:
        lines = []
        for line in part.splitlines():
            if line.strip() and not line.startswith(" "):
                break
            lines.append(line)
        blocks.append(textwrap.dedent("\n".join(lines)).strip())
    return [block for block in blocks if block]


def test_a_slider_crank_s_slider_velocity_is_its_position_differentiated():
    """x_B = r·cos φ + √(l² − (e − r·sin φ)²) along the saw's guide, 80 mm above O; v = ω·dx/dφ, a = ω²·d²x/dφ²;
    the slide's own s, velocity and acceleration along its guide alike, each ``(N,)`` as the docs say."""
    scene = graphplan.load(HACKSAW)
    phi = np.radians(np.arange(0.0, 360.0, 0.5))
    motion = graphplan.solve(scene, driver=phi)
    r, rod, e, omega = 0.08, 0.26, 0.08, 6.3
    root = np.sqrt(rod ** 2 - (e - r * np.sin(phi)) ** 2)
    x = r * np.cos(phi) + root
    dx = -r * np.sin(phi) + (e - r * np.sin(phi)) * r * np.cos(phi) / root
    b = motion.point("B")
    assert np.allclose(b.r, np.column_stack([x, np.full_like(x, e)]), rtol=0, atol=1e-12)
    assert np.allclose(b.v[:, 0], omega * dx, rtol=0, atol=1e-12) and np.allclose(b.v[:, 1], 0.0, atol=1e-12)
    by_difference = np.gradient(omega * dx, np.radians(0.5) / omega)
    assert np.allclose(b.a[1:-1, 0], by_difference[1:-1], rtol=0, atol=1e-4 * np.abs(by_difference).max())
    slide = motion.slide(4)
    assert (slide.slider, slide.guide, slide.joint) == (4, 1, "B")
    for name in ("u", "s", "velocity", "acceleration"):
        array = getattr(slide, name)
        assert np.shape(array) == (motion.count,), name   # a frame guide's u was one number, ()
        assert not array.flags.writeable, name
    assert np.allclose(slide.u, 1.0) and np.allclose(slide.s, x, rtol=0, atol=1e-12)
    assert np.allclose(slide.velocity, omega * dx, rtol=0, atol=1e-12)


def test_the_equilibrium_s_arrays_cannot_be_written_through(ratchet):
    """``analysis.equilibrium.balancing[:] = 0`` went through, and the analysis's drawings and tables then read
    the zeros; the README's arrays are read-only."""
    equilibrium = ratchet.analyse().equilibrium
    with pytest.raises(ValueError, match="read-only"):
        equilibrium.balancing[0] = 0.0
    with pytest.raises(ValueError, match="read-only"):
        equilibrium.reaction("R23").force[0] = 0.0
    for array in (equilibrium.condition, equilibrium.singular, equilibrium.locked):
        assert not array.flags.writeable


def test_a_name_or_number_the_motion_has_not_is_graphplan_s_error_naming_what_there_is(ratchet):
    """They were bare KeyErrors, printed quoted ("'no link 9; …'") and missed by ``except GraphplanError``, as
    the README says bad input raises; still KeyErrors (and IndexError) for code that catches those."""
    motion = graphplan.solve(ratchet, driver=np.radians([10.0, 20.0, 30.0]))
    for ask, told in ((lambda: motion.point("Z"), "no point 'Z'; points are O, C, A, S2, B, S3, E, S4"),
                      (lambda: motion.link(9), "no link 9; links are 1, 2, 3, 4"),
                      (lambda: motion.slide(4), "link 4 slides in no pair; the mechanism has no sliding pair")):
        with pytest.raises(graphplan.GraphplanError) as raised:
            ask()
        assert isinstance(raised.value, KeyError) and isinstance(raised.value, graphplan.UnknownNameError)
        assert str(raised.value) == told
    with pytest.raises(graphplan.UnknownNameError, match=r"^no reaction 'R99'; reactions are R12, R23, R34, R14$"):
        ratchet.analyse().equilibrium.reaction("R99")
    with pytest.raises(graphplan.PositionIndexError, match=r"^the motion has 3 positions, indices 0 to 2") as raised:
        motion.at_positions([0, 3])
    assert isinstance(raised.value, IndexError) and isinstance(raised.value, graphplan.GraphplanError)


def test_a_nan_among_a_dense_sweep_is_told_by_its_index_and_how_many_more(ratchet):
    angles = np.radians(np.arange(0.0, 360.0, 0.01))
    angles[[20_000, 30_000, 30_001]] = np.nan
    with pytest.raises(graphplan.SceneError) as raised:
        graphplan.solve(ratchet, driver=angles)
    assert str(raised.value) == ("driver[20000]: must be a finite number, a driver position (got nan); "
                                 "2 more after it are not finite either")


def test_a_grid_of_angles_is_told_by_its_shape(ratchet):
    grid, _ = np.meshgrid(np.radians([0.0, 90.0, 180.0]), [1.0, 2.0])
    with pytest.raises(graphplan.SceneError, match=r"^driver: must be a non-empty 1-D array of driver positions "
                                                   r"\(got an array of shape \(2, 3\)\): give np\.ravel\(driver\)"):
        graphplan.solve(ratchet, driver=grid)


def test_one_angle_is_one_position_as_solve_s_docstring_says(ratchet):
    motion = graphplan.solve(ratchet, driver=0.3)
    assert motion.point("B").r.shape == (1, 2) and motion.link(4).omega.shape == (1,)
    assert motion.point("B").r[0] == pytest.approx(graphplan.solve(ratchet, driver=[0.0, 0.3]).point("B").r[1])


def _largest_slider_acceleration(rod: float) -> float:
    """A worker's share of a parameter sweep: the scene's tables changed, then checked by load, as the README's
    sweep does."""
    tables = tomllib.loads((FIXTURES / "engine_slider_crank.toml").read_text(encoding="utf-8"))
    tables["groups"][0]["length"] = rod
    return float(np.abs(graphplan.load(tables).solve(np.radians(np.arange(0.0, 360.0, 1.0))).point("B").a).max())
