"""What the sliding group kinds share while they construct their plans.

RRP, RPR, PRP, RPP and a triad's sliding leg all lay off a relative (sliding)
vector along a guide from the image of the guide link's point under the
slider, and a Coriolis component 2·ω × v_rel where the guide turns; the
letters and helpers for that are here, and the whole step of a slider's pin
on a link that turns about a point already on the plan (an RRP's rod, a
triad's ternary link about Assur's point).
"""

from __future__ import annotations

from ..geometry import Line
from ..plans import Builder, DrawnLine, LaidVector, LineMeaning, Plan, Step, image_name
from .base import Guide


def guide_link(mechanism, guide: Guide) -> int:
    """The link that carries ``guide`` (the frame's number for a frame guide or frame line)."""
    scene = mechanism.scene
    if guide.line is not None:
        guide = scene.frame_lines[guide.line]
    return scene.frame_link if guide.link is None else guide.link


def coriolis_letter(board: Builder, slider: int) -> str:
    """``k`` for the end of the Coriolis component, ``k`` + the slider's link number (``k3``) when the mechanism
    has several, or when a point of it is named K, whose image keeps the letter k.

    Not primed, as a free letter otherwise is: k′ is the Chinese textbooks' letter of K's own image on the
    acceleration plan, and the readings would take a segment to K's image for the Coriolis component.
    """
    count = sum(len(group.coriolis_sliders(board.mechanism)) for group in board.mechanism.groups)
    if count <= 1 and free_letter(board, "k") == "k":
        return "k"
    return free_letter(board, f"k{slider}")


def coriolis_end(board: Builder, velocities: Plan, point: str, slider: int, carrier: int, on_guide: str) -> str:
    """The end of the Coriolis part 2·ωg × vPPg laid from ``on_guide`` (the image of the guide link's point under
    the pin ``point``), vPPg read off the velocity plan; marked and returned."""
    relative = velocities.value(point) - velocities.points[on_guide]
    return board.lay_coriolis(coriolis_letter(board, slider), on_guide, velocities.rates.get(carrier, 0.0), relative)


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
    board.similarity_step(letter, link, f"{point}{link}", board.widest(link), from_pole=True)
    return letter


def velocity_on_guide(board: Builder, point: str, pivot: tuple[str, str, complex], guide: Guide, slider: int) -> str:
    """vP = vX + vPX (⊥ XP) = vPg + vPPg (∥ guide): P's image, fixed and returned.

    P is the pin of ``slider`` on ``guide`` and a point of a link that turns about the point X of
    ``pivot`` (name, plan letter, position), whose image is known: an RRP's rod about A, a triad's
    ternary link about Assur's point.  Pg is the guide link's point under P (the pole on the frame).
    """
    pivot_name, pivot_letter, pivot_position = pivot
    across = 1j * (board.positions[point] - pivot_position)
    carrier = board.guide_line(guide)[2]
    on_guide = guide_point(board, carrier, point)
    fixed, angle, along_guide, meaning = _crossed_on_guide(board, point, (pivot_letter, across, f"⊥{pivot_name}{point}"),
                                                           guide, slider, on_guide)
    g = f"{point}{carrier}"
    relative = () if on_guide == "p" else (LaidVector(on_guide, fixed, f"v{point}{g}"),)
    board.step(Step(
        equation=f"v{point} = v{pivot_name} + v{point}{pivot_name} = v{g} + v{point}{g}",
        vectors=(LaidVector(pivot_letter, fixed, f"v{point}{pivot_name}"), *relative, LaidVector("p", fixed, f"v{point}")),
        lines=(DrawnLine(pivot_letter, across, LineMeaning("perpendicular", (pivot_name, point))),
               DrawnLine(on_guide, along_guide, meaning)),
        fixes=(fixed,), crossing_deg=angle))
    return fixed


def acceleration_on_guide(board: Builder, velocities: Plan, point: str, pivot: tuple[str, str, complex, float, str],
                          guide: Guide, slider: int, turning: bool) -> str:
    """aP = aX + aPXⁿ + aPX^τ (⊥ XP) = aPg + aPPgᵏ + aPPg^r (∥ guide): P's image, fixed and returned.

    ``pivot`` is (name, plan letter, position, ω of the link turning about it, letter of the normal
    part's end): the normal part ω²·XP points from P toward X.  The Coriolis part 2·ωg × vPPg, only
    where the guide is ``turning``, is vPPg read off the velocity plan turned 90° in the sense of ωg;
    the relative part runs along the guide.
    """
    pivot_name, pivot_letter, pivot_position, omega, normal_letter = pivot
    where = board.positions[point]
    across = 1j * (where - pivot_position)
    normal = board.mark(normal_letter, board.points[pivot_letter] - omega ** 2 * (where - pivot_position))
    carrier = board.guide_line(guide)[2]
    on_guide = guide_point(board, carrier, point)
    g = f"{point}{carrier}"
    laid = [LaidVector(pivot_letter, normal, f"a{point}{pivot_name}ⁿ")]
    equation = f"a{point} = a{pivot_name} + a{point}{pivot_name}ⁿ + a{point}{pivot_name}^τ = a{g}"
    start = on_guide
    if turning:
        start = coriolis_end(board, velocities, point, slider, carrier, on_guide)
        laid.append(LaidVector(on_guide, start, f"a{point}{g}ᵏ"))
        equation += f" + a{point}{g}ᵏ"
    equation += f" + a{point}{g}^r"
    fixed, angle, along_guide, meaning = _crossed_on_guide(board, point, (normal, across, f"⊥{pivot_name}{point}"),
                                                           guide, slider, start)
    laid.append(LaidVector(normal, fixed, f"a{point}{pivot_name}^τ"))
    if start != "p":  # from the pole it would be aP itself
        laid.append(LaidVector(start, fixed, f"a{point}{g}^r"))
    laid.append(LaidVector("p", fixed, f"a{point}"))
    board.step(Step(
        equation=equation, vectors=tuple(laid),
        lines=(DrawnLine(normal, across, LineMeaning("perpendicular", (pivot_name, point))),
               DrawnLine(start, along_guide, meaning)),
        fixes=(normal, *((start,) if start != on_guide else ()), fixed), crossing_deg=angle))
    return fixed


def _crossed_on_guide(board: Builder, point: str, from_pivot: tuple[str, complex, str], guide: Guide, slider: int,
                      on_guide_line: str) -> tuple[str, float, complex, LineMeaning]:
    """P's image: the line through ``from_pivot`` (letter, direction, label) crossed with the line along the guide
    through ``on_guide_line``; recorded on the slider with its sliding.  Returns the image, the crossing angle, the
    guide's direction and what its line means."""
    _, along_guide, carrier = board.guide_line(guide)
    meaning = guide_meaning(guide)
    start, direction, label = from_pivot
    value, angle = board.cross(Line(board.points[start], direction, label),
                               Line(board.points[on_guide_line], along_guide, meaning.text))
    fixed = board.fix(point, value)
    record_slide(board, slider, point, carrier, on_guide_line, fixed)
    return fixed, angle, along_guide, meaning


def record_slide(board: Builder, slider: int, point: str, carrier: int, start: str, end: str) -> None:
    """Put ``slider`` on the plan by its pin ``point`` (image ``end``): it turns with its guide's link ``carrier``, and
    its sliding is the vector from ``start`` (the guide's point under the pin, or the Coriolis part's end) to ``end``."""
    board.on_link(slider, board.positions[point], end)
    board.turns_with[slider] = carrier
    board.slides(slider, start, end)
