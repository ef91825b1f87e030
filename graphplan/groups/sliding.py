"""What the sliding group kinds share while they construct their plans.

RRP, RPR, PRP and RPP all lay off a relative (sliding) vector along a guide
from the image of the guide link's point under the slider, and a Coriolis
component 2·ω × v_rel where the guide turns; the letters and helpers for
that are here.
"""

from __future__ import annotations

from ..geometry import turned
from ..plans import Builder, LineMeaning, image_name
from .base import Guide


def guide_link(mechanism, guide: Guide) -> int:
    """The link that carries ``guide`` (the frame's number for a frame guide or frame line)."""
    scene = mechanism.scene
    if guide.line is not None:
        guide = scene.frame_lines[guide.line]
    return scene.frame_link if guide.link is None else guide.link


def turns(mechanism, link: int) -> bool:
    """Whether ``link`` can turn: neither the frame nor a link translating on a frame guide."""
    return link != mechanism.scene.frame_link and link not in mechanism.translating


def coriolis_letter(board: Builder, slider: int) -> str:
    """``k`` for the end of the Coriolis component, ``k`` + the slider's link number when the mechanism has several.

    Primed (``k′``) when a point of the mechanism is named K, so that its image keeps the letter.
    """
    count = sum(len(group.coriolis_sliders(board.mechanism)) for group in board.mechanism.groups
                if hasattr(group, "coriolis_sliders"))
    base = free_letter(board, "k")
    return base if count <= 1 else f"{base}{slider}"


def coriolis(omega: float, relative: complex) -> complex:
    """2·ω × v_rel: the relative velocity turned by 90° in the sense of ω, 2|ω| times as long."""
    return turned(2.0 * abs(omega) * relative, omega)


def guide_meaning(guide: Guide) -> LineMeaning:
    """What a line of action along ``guide`` follows: the frame line it names, or the guide on its link."""
    if guide.line is not None:
        return LineMeaning("frame_line", name=guide.line)
    return LineMeaning("guide", link=guide.link)


def free_letter(board: Builder, letter: str) -> str:
    """``letter``, primed while it is the pole's or the image letter of a point of the mechanism.

    It depends on the mechanism alone, so that the velocity and the
    acceleration plan give an auxiliary point the same letter.
    """
    taken = {"p", *(image_name(name) for name in board.mechanism.point_names())}
    while letter in taken:
        letter += "′"
    return letter


def guide_point(board: Builder, link: int, point: str) -> str:
    """The plan letter of guide link ``link``'s point under mechanism point ``point`` (``b4``).

    On the frame it is the pole.  On a moving link it is put on the plan by
    the similarity theorem from that link's images already there, and a step
    records it.
    """
    if link == board.mechanism.scene.frame_link:
        return "p"
    letter = free_letter(board, f"{image_name(point)}{link}")
    board.mark(letter, board.image_on(link, board.positions[point]))
    board.similarity_step(letter, link, f"{point}{link}", board.widest(link))
    return letter
