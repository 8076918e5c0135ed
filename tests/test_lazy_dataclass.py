"""bearingload.lazy_dataclass.dataclass gives the class dataclasses.dataclass gives, its
comparison and text methods built on first use."""

from __future__ import annotations

import dataclasses
import inspect
import pickle
import re

import pytest

from bearingload import lazy_dataclass
from bearingload.lazy_dataclass import dataclass as lazy


def twins(**options):
    """The same class body decorated by dataclasses and by the lazy decorator."""

    def body():
        class Point:
            """A point."""

            x: float
            label: str = "p"
            tags: list[str] = dataclasses.field(default_factory=list, compare=False)
            secret: int = dataclasses.field(default=0, repr=False)

        return Point

    return dataclasses.dataclass(**options)(body()), lazy(**options)(body())


OPTIONS = [
    {},
    {"frozen": True},
    {"order": True},
    {"eq": False},
    {"unsafe_hash": True},
    {"frozen": True, "order": True},
    {"repr": False},
]


def test_the_comparison_and_text_methods_wait_for_their_first_use():
    _, cls = twins(frozen=True)  # a field(...) default: __init__ is built at once
    assert isinstance(vars(cls)["__repr__"], lazy_dataclass.Deferred)
    assert isinstance(vars(cls)["__eq__"], lazy_dataclass.Deferred)
    assert inspect.isfunction(vars(cls)["__init__"])
    assert cls(1.0) == cls(1.0)
    assert inspect.isfunction(vars(cls)["__repr__"])
    assert inspect.isfunction(vars(cls)["__eq__"])


def test_a_class_is_built_at_its_first_instance():
    @lazy(frozen=True)
    class Plain:
        """Plain defaults only."""

        x: float
        label: str = "p"

    assert isinstance(vars(Plain)["__init__"], lazy_dataclass.Deferred)
    assert isinstance(vars(Plain)["__setattr__"], lazy_dataclass.Deferred)
    p = Plain(1.0)
    assert inspect.isfunction(vars(Plain)["__init__"])
    assert isinstance(vars(Plain)["__repr__"], lazy_dataclass.Deferred)  # not asked for yet
    with pytest.raises(dataclasses.FrozenInstanceError):
        p.x = 2.0
    assert Plain.label == "p"
    assert repr(p).endswith("Plain(x=1.0, label='p')")


def test_a_class_not_yet_built_answers_as_a_dataclass():
    @lazy
    class Unused:
        """Never instantiated before the questions."""

        x: int
        y: int = 2

    assert dataclasses.is_dataclass(Unused)
    assert [f.name for f in dataclasses.fields(Unused)] == ["x", "y"]
    assert str(inspect.signature(Unused)) == "(x: 'int', y: 'int' = 2) -> None"
    assert Unused.__match_args__ == ("x", "y")


@pytest.mark.parametrize("options", OPTIONS, ids=str)
def test_the_class_behaves_as_the_dataclass(options):
    real, cls = twins(**options)
    a, b, c = (cls(1.0, "a", ["t"], 5), cls(1.0, "a", ["u"], 5), cls(2.0))
    ra, rb, rc = (real(1.0, "a", ["t"], 5), real(1.0, "a", ["u"], 5), real(2.0))
    assert repr(a).split(" at 0x")[0] == repr(ra).split(" at 0x")[0]
    assert (a == b, a == c, a != c, a == 1) == (ra == rb, ra == rc, ra != rc, ra == 1)
    assert (cls.__hash__ is None) == (real.__hash__ is None)
    if real.__hash__ is not None and real.__hash__ is not object.__hash__:
        assert (hash(a) == hash(b)) == (hash(ra) == hash(rb))
    if options.get("order"):
        assert (a < c, c <= a, c > a, a >= b) == (ra < rc, rc <= ra, rc > ra, ra >= rb)
    else:
        with pytest.raises(TypeError):
            a < c  # noqa: B015
    assert repr(cls.__dataclass_params__) == repr(real.__dataclass_params__)
    assert [(f.name, f.repr, f.compare, f.hash) for f in dataclasses.fields(cls)] == [
        (f.name, f.repr, f.compare, f.hash) for f in dataclasses.fields(real)
    ]
    assert str(inspect.signature(cls)) == str(inspect.signature(real))
    assert cls.__match_args__ == real.__match_args__
    assert dataclasses.asdict(dataclasses.replace(a, x=3.0))["x"] == 3.0


def test_an_unhashable_class_stays_unhashable():
    _, cls = twins()
    with pytest.raises(TypeError, match="unhashable type"):
        hash(cls(1.0))


def test_a_frozen_class_refuses_assignment_before_and_after_the_methods_are_built():
    _, cls = twins(frozen=True)
    p = cls(1.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        p.x = 2.0
    assert hash(p) == hash(cls(1.0))
    with pytest.raises(dataclasses.FrozenInstanceError):
        p.x = 2.0


def test_an_instance_pickles_and_compares_equal():
    p = PICKLED(1.0, "a")
    assert pickle.loads(pickle.dumps(p)) == p


def test_a_subclass_dataclass_inherits_the_fields():
    _, base = twins(frozen=True)

    @lazy(frozen=True)
    class Labelled(base):  # type: ignore[valid-type, misc]
        """A point with a note."""

        note: str = ""

    q = Labelled(1.0, note="n")
    assert [f.name for f in dataclasses.fields(Labelled)][-1] == "note"
    assert "note='n'" in repr(q) and q == Labelled(1.0, note="n") and q != Labelled(1.0)


def test_a_class_with_its_own_repr_keeps_it():
    @lazy
    class Own:
        """Its own text."""

        x: int

        def __repr__(self) -> str:
            return "own"

    assert repr(Own(1)) == "own" and Own(1) == Own(1)


@lazy(frozen=True)
class PICKLED:
    """A module-level class, for pickle."""

    x: float
    label: str = ""


@pytest.mark.parametrize("frozen", [False, True])
def test_init_binds_and_refuses_as_the_dataclass(frozen):
    real, cls = twins(frozen=frozen)
    calls = [((1.0,), {}), ((1.0, "a"), {"secret": 3}), ((), {"x": 2.0, "tags": ["t"]})]
    for args, kwargs in calls:
        assert vars(cls(*args, **kwargs)) == vars(real(*args, **kwargs))
        assert list(vars(cls(*args, **kwargs))) == list(vars(real(*args, **kwargs)))
    assert cls(1.0).tags is not cls(1.0).tags  # a new list from the factory each time
    wrong = [((), {}), ((1.0, "a", [], 0, 9), {}), ((1.0,), {"x": 2.0}), ((1.0,), {"y": 2})]
    for args, kwargs in wrong:
        with pytest.raises(TypeError) as theirs:
            real(*args, **kwargs)
        with pytest.raises(TypeError, match=f"^{re.escape(str(theirs.value))}$"):
            cls(*args, **kwargs)


def test_init_runs_post_init():
    @lazy(frozen=True)
    class Checked:
        """Refuses a negative x."""

        x: float = 0.0

        def __post_init__(self) -> None:
            if self.x < 0:
                raise ValueError("x")

    assert Checked(1.0).x == 1.0
    with pytest.raises(ValueError, match="x"):
        Checked(-1.0)


def test_a_non_default_field_after_a_default_is_refused_at_the_first_instance():
    @lazy
    class Bad:
        """Out of order."""

        x: int = 0
        y: int  # type: ignore[misc]

    with pytest.raises(TypeError, match="non-default argument 'y' follows default argument"):
        Bad(1, 2)
