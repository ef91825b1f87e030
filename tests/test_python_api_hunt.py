"""The Python interface called as a student's notebook calls it, wrongly: each misuse is told in a line that names the
argument and what is wrong, never passed on as a traceback from deep inside nor taken silently."""

from __future__ import annotations

from pathlib import Path

import pytest

import graphplan

RATCHET = "fixtures/ratchet_crank_rocker.toml"
SHAPER = "fixtures/shaper_six_bar.toml"


@pytest.fixture(scope="module")
def ratchet():
    return graphplan.load(RATCHET)


@pytest.mark.parametrize("wrong", [RATCHET, Path(RATCHET), None, {}])
def test_build_given_no_scene_says_it_takes_one(wrong):
    """build(path) raised AttributeError: 'str' object has no attribute 'driver', from inside the mechanism."""
    with pytest.raises(TypeError, match=r"^build takes a scene, as graphplan\.load\(path\) reads it \(got "):
        graphplan.build(wrong)


def test_a_mechanism_prints_in_a_line_and_solve_given_one_says_where_its_scene_is(ratchet):
    """A mechanism's repr printed its whole scene (3 000 characters), and so did solve's error given one."""
    mechanism = graphplan.build(ratchet)
    assert repr(mechanism) == "<Mechanism of 'Crank-rocker of a ratchet feed': driver link 2, groups II(3,4)>"
    with pytest.raises(TypeError) as raised:
        graphplan.solve(mechanism, driver=[0.1])
    assert str(raised.value) == ("solve takes a scene, as graphplan.load(path) reads it (got <Mechanism of "
                                 "'Crank-rocker of a ratchet feed': driver link 2, groups II(3,4)>); its scene is "
                                 "mechanism.scene")
    with pytest.raises(TypeError, match=r"\(got <Analysis of .*>\); its scene is analysis\.scene$"):
        graphplan.build(ratchet.analyse())


def test_a_point_typed_in_cyrillic_is_told_apart_from_the_latin_one(ratchet):
    """point('В') with a Cyrillic В was told «no point 'В'; points are O, C, A, S2, B, …»: the B it meant stood in
    the list, looking the same."""
    motion = ratchet.solve(driver=[0.1])
    with pytest.raises(KeyError, match=r"no point 'В'.*the Cyrillic 'В' \(U\+0412\) where 'B' has the Latin 'B'"):
        motion.point("В")


def test_a_sliding_pair_is_named_by_its_slider_s_number_and_an_unknown_one_lists_the_pairs():
    """slide('6') on the shaper, whose link 6 does slide, was told «link 6 slides in no pair»."""
    motion = graphplan.load(SHAPER).solve(driver=[0.1])
    assert [(slide.slider, slide.guide) for slide in motion.slides] == [(3, 4), (6, 1)]
    with pytest.raises(TypeError, match=r"^a sliding pair is named by its slider's number, an integer: slide\(6\), "
                                        r"not slide\('6'\)$"):
        motion.slide("6")
    with pytest.raises(KeyError, match=r"link 9 slides in no pair; the sliding pairs are link 3 on link 4, "
                                       r"link 6 on link 1"):
        motion.slide(9)
    assert motion.slide(6).guide == 1
