"""The search for the way a course sheet draws a force sheet larger (`force_sheet_choice.first_fitting`) finds the way that
trying every way in order, largest first, finds, wherever a larger drawing needs more room, and lays out fewer.

Every set of ways that pack which a larger drawing needing more room allows (a way packs only where every way
fewer steps larger in both packs too) is tried against the plain scan of the ways in order.
"""

import itertools

import pytest

from graphplan.render import force_sheet_choice
from graphplan.render.force_sheet_choice import LARGER_FORCE_STEPS, PROBE_STEPS, first_fitting


def packing_sets():
    """Every set of the ways closed under fewer steps in both: what may pack where a larger drawing needs more
    room."""
    ways = LARGER_FORCE_STEPS
    for chosen in itertools.product((False, True), repeat=len(ways)):
        packing = {way for way, packs in zip(ways, chosen, strict=True) if packs}
        if all(smaller in packing for way in packing for smaller in ways
               if smaller[0] <= way[0] and smaller[1] <= way[1]):
            yield frozenset(packing)


SETS = sorted(set(packing_sets()), key=sorted)


def test_the_packing_sets_are_those_of_the_steps_in_both():
    assert frozenset() in SETS and frozenset(LARGER_FORCE_STEPS) in SETS
    assert frozenset({(1, 1)}) not in SETS  # (1, 1) packing where (1, 0) and (0, 1) do not is no such set


@pytest.mark.parametrize("packing", SETS, ids=lambda packing: "+".join(f"{a}{b}" for a, b in sorted(packing)) or "none")
def test_the_search_finds_the_first_way_in_order_that_packs(packing):
    tried = []

    def taken(way):
        tried.append(way)
        return [way] if way in packing else None

    scanned = next(([way] for way in LARGER_FORCE_STEPS if way in packing), None)
    assert first_fitting(LARGER_FORCE_STEPS, taken) == scanned
    assert len(tried) == len(set(tried)), "no way laid out twice"
    assert tried[0] == PROBE_STEPS


def test_where_only_the_probe_and_those_under_it_pack_fewer_ways_are_laid_out_than_the_scan_from_the_probe():
    packing = {(1, 1), (1, 0), (0, 1)}
    tried = []

    def taken(way):
        tried.append(way)
        return [way] if way in packing else None

    first_fitting(LARGER_FORCE_STEPS, taken)
    # The probe, then every larger way, largest first, as the search was: seven.
    larger = LARGER_FORCE_STEPS.index(PROBE_STEPS)
    assert len(tried) < 1 + larger


def test_a_probe_not_among_the_ways_starts_in_their_middle(monkeypatch):
    monkeypatch.setattr(force_sheet_choice, "PROBE_STEPS", (9, 9))
    tried = []
    first_fitting(LARGER_FORCE_STEPS, lambda way: tried.append(way))
    assert tried[0] == LARGER_FORCE_STEPS[len(LARGER_FORCE_STEPS) // 2]
