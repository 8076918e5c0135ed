"""``dataclass``: :func:`dataclasses.dataclass` that builds ``__repr__``, ``__eq__``, ``__hash__``
and the order methods when one of them is first looked up, not when the class is defined.

A terminal command imports some thirty dataclasses and compares, hashes or prints few of
them; :mod:`dataclasses` compiles every method it adds from source text, and that is most of
what a dataclass costs at import. This decorator takes the same arguments and gives the same
class: ``__init__`` (and a frozen class's ``__setattr__`` and ``__delattr__``), the fields,
``__match_args__`` and ``__dataclass_params__`` at once, as :mod:`dataclasses` does; the
comparison and text methods are the ones :mod:`dataclasses` builds, built by it for a twin of
the class with the same fields when the class first needs one (those methods name no class:
they read ``self.__class__``). A class it cannot treat so (``slots=True``, a dataclass base, one
of those methods of its own, ``order`` without ``eq``) goes to :func:`dataclasses.dataclass`
as it is.

Type checkers see :func:`dataclasses.dataclass` itself.
"""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING, Any

#: The methods built on first use, each with the option that asks for it.
DEFERRED = {
    "__repr__": "repr",
    "__eq__": "eq",
    "__hash__": "eq",  # eq: None or a hash of the fields, as dataclasses decides
    "__lt__": "order",
    "__le__": "order",
    "__gt__": "order",
    "__ge__": "order",
}
#: The options of those methods, with the defaults of :func:`dataclasses.dataclass`.
METHOD_OPTIONS = {"repr": True, "eq": True, "order": False, "unsafe_hash": False}


class Deferred:
    """Stands in a class's dict for a method not built yet; the first lookup builds them all."""

    def __init__(self, name: str, cls: type, options: dict[str, Any]) -> None:
        self.name = name
        self.cls = cls
        self.options = options

    def __get__(self, obj: object, owner: type | None = None) -> Any:
        build_deferred(self.cls, self.options)
        return getattr(obj if obj is not None else owner or self.cls, self.name)


def build_deferred(cls: type, options: dict[str, Any]) -> None:
    """Put in place of the stand-ins of ``cls`` the methods :mod:`dataclasses` builds with
    ``options`` (``repr``, ``eq``, ``order``, ``unsafe_hash``, ``frozen``) for a class of its
    fields; where it builds none, remove the stand-in (the method is inherited)."""
    waiting = [n for n in DEFERRED if isinstance(cls.__dict__.get(n), Deferred)]
    if not waiting:
        return
    fields = dataclasses.fields(cls)
    body: dict[str, Any] = {
        "__module__": cls.__module__,
        "__qualname__": cls.__qualname__,
        "__annotations__": {f.name: f.type for f in fields},
    }
    for f in fields:
        body[f.name] = dataclasses.field(repr=f.repr, hash=f.hash, compare=f.compare)
    twin: type = dataclasses.dataclass(type(cls.__name__, (), body), init=False, **options)
    for name in waiting:
        if name in twin.__dict__:
            setattr(cls, name, twin.__dict__[name])
        else:
            delattr(cls, name)


def _lazy(cls: type, options: dict[str, Any]) -> type:
    methods = {k: options.get(k, v) for k, v in METHOD_OPTIONS.items()}
    if (
        options.get("slots")
        or (methods["order"] and not methods["eq"])
        or any(name in cls.__dict__ for name in DEFERRED)
        or any(hasattr(base, "__dataclass_fields__") for base in cls.__mro__[1:])
    ):
        return dataclasses.dataclass(cls, **options)
    dataclasses.dataclass(
        cls, **{**options, "repr": False, "eq": False, "order": False, "unsafe_hash": False}
    )
    params = cls.__dataclass_params__  # type: ignore[attr-defined]
    for option, value in methods.items():  # the options asked for, not those of the light pass
        setattr(params, option, value)
    later = {**methods, "frozen": options.get("frozen", False)}
    for name, option in DEFERRED.items():
        if methods[option] or (name == "__hash__" and methods["unsafe_hash"]):
            setattr(cls, name, Deferred(name, cls, later))
    return cls


if TYPE_CHECKING:
    from dataclasses import dataclass as dataclass
else:

    def dataclass(cls=None, /, **options):
        """:func:`dataclasses.dataclass`, its comparison and text methods built on first use."""
        if cls is None:
            return lambda c: _lazy(c, options)
        return _lazy(cls, options)
