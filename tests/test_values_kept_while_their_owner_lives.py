"""graphplan.memo.OwnedMemo: a value worked out for an object is made once and given up with the object."""

import gc

import pytest

from graphplan.memo import OwnedMemo


class Owner:
    """Unhashable, as an analysis with its arrays is."""

    __hash__ = None


@pytest.fixture
def only_new_objects_collected():
    """gc.collect() within the test looks only at the objects made since it began (gc.freeze): a worker that has
    run other modules holds all they left, and each full collection walked it (12 s for the test's two, which take
    milliseconds alone)."""
    gc.freeze()
    try:
        yield
    finally:
        gc.unfreeze()


def test_a_value_is_made_once_for_each_owner_and_key_and_given_up_with_its_owner(only_new_objects_collected):
    memo: OwnedMemo[list] = OwnedMemo()
    made = []

    def make(tag):
        def value():
            made.append(tag)
            return [tag]
        return value

    first, second = Owner(), Owner()
    kept = memo.get(first, "a", make("first a"))
    assert memo.get(first, "a", make("again")) is kept
    assert memo.get(first, "b", make("first b")) == ["first b"]
    assert memo.get(second, "a", make("second a")) == ["second a"]
    assert made == ["first a", "first b", "second a"]
    assert len(memo) == 3
    del first, kept
    gc.collect()
    assert len(memo) == 1  # both of the first owner's values went with it
    del second
    gc.collect()
    assert len(memo) == 0


def test_a_failed_making_keeps_nothing():
    memo: OwnedMemo[int] = OwnedMemo()
    owner = Owner()

    def broken():
        raise ValueError("no value")

    try:
        memo.get(owner, "k", broken)
    except ValueError:
        pass
    assert len(memo) == 0
    assert memo.get(owner, "k", lambda: 5) == 5


def test_an_owner_made_after_another_is_gone_has_its_values_given_up_too(only_new_objects_collected):
    """The memo watches each owner once, however many keys it has; an owner made once the last is gone (often at
    the same address, so with the same id) is watched afresh."""
    memo: OwnedMemo[int] = OwnedMemo()
    for _ in range(5):
        owner = Owner()
        for key in range(3):
            memo.get(owner, key, lambda: 0)
        assert len(memo) == 3
        del owner
        gc.collect()
        assert len(memo) == 0
