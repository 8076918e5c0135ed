"""``dataclass``: :func:`dataclasses.dataclass` that builds a class's methods when the class is
first used, and its comparison and text methods when one of them is first looked up.

A terminal command imports some thirty dataclasses, creates instances of two thirds of them
and compares, hashes or prints few; :mod:`dataclasses` compiles every method it adds from
source text, and that is most of what a dataclass costs at import. This decorator takes the
same arguments and gives the same class, built in two steps:

1. at the first instance (or the first look at its fields, ``__init__``, a frozen class's
   ``__setattr__`` and ``__delattr__``, ``__match_args__`` or ``__dataclass_params__``):
   those (a class with a ``field(...)`` default is built so at once, its class attribute then
   being the default as :mod:`dataclasses` leaves it). :mod:`dataclasses` collects the fields;
   for a class of plain fields (:func:`plain_fields`: the package's) the three methods are
   functions of this module that do what those of :mod:`dataclasses` do without compiling
   source text (:func:`plain_init`, :func:`frozen_methods`), else :mod:`dataclasses` builds
   them;
2. at the first look at ``__repr__``, ``__eq__``, ``__hash__`` or an order method: all of
   these, built by :mod:`dataclasses` for a twin of the class with the same fields (these
   methods name no class: they read ``self.__class__``).

A class it cannot treat so (``slots=True``, a dataclass base, no docstring, one of those methods
of its own, ``order`` without ``eq``) goes to :func:`dataclasses.dataclass` as it is. Type
checkers see :func:`dataclasses.dataclass` itself. Each step runs once, under a lock; a thread
that creates the first instance of a class while another thread is building it may still find
no ``__init__`` for that moment (the package starts no threads).
"""

from __future__ import annotations

import dataclasses
from _thread import RLock
from typing import TYPE_CHECKING, Any

#: The methods of step 2, each with the option that asks for it.
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
#: What step 1 puts in the class, each with the option that asks for it (None: always).
FIRST_STEP = {
    "__init__": "init",
    "__setattr__": "frozen",
    "__delattr__": "frozen",
    "__match_args__": "match_args",
    "__dataclass_fields__": None,
    "__dataclass_params__": None,
}
#: The defaults of the options of step 1, as :func:`dataclasses.dataclass` has them.
FIRST_OPTIONS = {"init": True, "frozen": False, "match_args": True}
#: Held while a step runs (re-entered: step 2 runs step 1 first).
_BUILDING = RLock()


class Deferred:
    """Stands in a class's dict for what is not built yet; the first lookup builds it."""

    def __init__(self, name: str, cls: type, options: dict[str, Any]) -> None:
        self.name = name
        self.cls = cls
        self.options = options

    def __get__(self, obj: object, owner: type | None = None) -> Any:
        with _BUILDING:
            if self.name in DEFERRED:
                build_deferred(self.cls, self.options)
            else:
                build_class(self.cls, self.options)
        return getattr(obj if obj is not None else owner or self.cls, self.name)


def build_class(cls: type, options: dict[str, Any]) -> None:
    """Step 1: :func:`dataclasses.dataclass` with ``options`` but none of the methods of step
    2 (their stand-ins stay), then the ``__dataclass_params__`` of ``options`` themselves.

    A class of plain fields (:func:`plain_fields`) gets the ``__init__``, ``__setattr__`` and
    ``__delattr__`` of :func:`plain_init` and :func:`frozen_methods` (no source compiled)."""
    built = cls.__dict__.get("__dataclass_fields__")
    if built is not None and not isinstance(built, Deferred):
        return
    for name in FIRST_STEP:
        if isinstance(cls.__dict__.get(name), Deferred):
            delattr(cls, name)
    plain = plain_fields(cls, options)
    first = {k: options.get(k, v) for k, v in FIRST_OPTIONS.items()}
    skip = {"init": False, "frozen": False} if plain else {}
    dataclasses.dataclass(
        cls,
        **{**options, "repr": False, "eq": False, "order": False, "unsafe_hash": False, **skip},
    )
    params = cls.__dataclass_params__  # type: ignore[attr-defined]
    asked = {**METHOD_OPTIONS, "init": True, "frozen": False}  # the options asked for
    for option, value in asked.items():
        setattr(params, option, options.get(option, value))
    if plain:
        fields = dataclasses.fields(cls)
        if first["init"]:
            cls.__init__ = plain_init(cls, fields, first["frozen"])  # type: ignore[misc]
        if first["frozen"]:
            setter, deleter = frozen_methods(cls, fields)
            cls.__setattr__ = setter  # type: ignore[method-assign]
            cls.__delattr__ = deleter  # type: ignore[method-assign]


#: What a class annotation names that makes a field other than a plain one.
SPECIAL_TYPES = ("InitVar", "ClassVar", "KW_ONLY")


def plain_fields(cls: type, options: dict[str, Any]) -> bool:
    """Whether every field of ``cls`` is a plain one :func:`plain_init` sets as
    :mod:`dataclasses` would: its annotations text naming no ``InitVar``, ``ClassVar`` or
    ``KW_ONLY``, no ``kw_only`` option, each ``field(...)`` with ``init`` and without
    ``kw_only``, no ``__slots__`` in the class or a base, and, unless frozen, no
    ``__setattr__`` of its own or a base's."""
    notes = cls.__dict__.get("__annotations__", {})
    if options.get("kw_only") or not all(isinstance(t, str) for t in notes.values()):
        return False
    if any(kind in t for t in notes.values() for kind in SPECIAL_TYPES):
        return False
    for name in notes:
        f = cls.__dict__.get(name)
        if isinstance(f, dataclasses.Field) and (not f.init or f.kw_only is True):
            return False
    if any("__slots__" in c.__dict__ for c in cls.__mro__):  # no instance dict to fill
        return False
    return bool(options.get("frozen")) or cls.__setattr__ is object.__setattr__


class Factory:
    """Stands for a field's default factory among the defaults of :func:`plain_init`."""

    def __init__(self, make: Any) -> None:
        self.make = make

    def __repr__(self) -> str:
        return "<factory>"  # as dataclasses shows it in the signature


def plain_init(cls: type, fields: tuple[dataclasses.Field, ...], frozen: bool) -> Any:
    """The ``__init__`` of a class of plain ``fields``: the values of the arguments, bound to
    the fields in order, or their defaults (a default factory called), set in the instance's
    dict in the fields' order, then ``__post_init__`` if the class has one. Arguments that do
    not bind go to the ``__init__`` :mod:`dataclasses` builds, which refuses them with its
    own message."""
    names = tuple(f.name for f in fields)
    start: dict[str, Any] = {}
    for f in fields:
        missing = f.default is dataclasses.MISSING
        start[f.name] = Factory(f.default_factory) if missing else f.default
    factories = tuple(n for n, v in start.items() if isinstance(v, Factory))
    needed = len([f for f in fields if f.default is f.default_factory])  # both MISSING
    for f in fields[needed:]:
        if f.default is f.default_factory:
            raise TypeError(f"non-default argument {f.name!r} follows default argument")
    post_init = hasattr(cls, "__post_init__")

    def __init__(self: Any, /, *args: Any, **kwargs: Any) -> None:
        given = len(args)
        if (
            given > len(names)
            or (given < needed and not all(n in kwargs for n in names[given:needed]))
            or (
                kwargs
                and not (kwargs.keys() <= start.keys() and kwargs.keys().isdisjoint(names[:given]))
            )
        ):
            dataclass_init(cls)(self, *args, **kwargs)  # refuses as dataclasses does
        else:
            values = start.copy()
            values.update(zip(names, args, strict=False))  # the rest: defaults
            values.update(kwargs)
            for name in factories:
                if values[name] is start[name]:
                    values[name] = start[name].make()
            self.__dict__.update(values)
        if post_init:
            self.__post_init__()

    __init__.__qualname__ = f"{cls.__qualname__}.__init__"
    __init__.__module__ = cls.__module__
    __init__.__signature__ = init_signature(fields)  # type: ignore[attr-defined]
    return __init__


def init_signature(fields: tuple[dataclasses.Field, ...]) -> Any:
    """The signature of the ``__init__`` :mod:`dataclasses` builds for ``fields``."""
    import inspect

    keyword = inspect.Parameter.POSITIONAL_OR_KEYWORD
    params = [inspect.Parameter("self", keyword)]
    for f in fields:
        default = f.default
        if default is dataclasses.MISSING and f.default_factory is not dataclasses.MISSING:
            default = Factory(f.default_factory)
        elif default is dataclasses.MISSING:
            default = inspect.Parameter.empty
        params.append(inspect.Parameter(f.name, keyword, default=default, annotation=f.type))
    return inspect.Signature(params, return_annotation=None)


def dataclass_init(cls: type) -> Any:
    """The ``__init__`` :mod:`dataclasses` builds for the fields of ``cls`` (built for a twin
    of the class; it names no class)."""
    frozen = cls.__dataclass_params__.frozen  # type: ignore[attr-defined]
    made = twin(
        cls,
        lambda f: {"default": f.default, "default_factory": f.default_factory},
        frozen=frozen,
        repr=False,
        eq=False,
    )
    return made.__init__  # type: ignore[misc]


def twin(cls: type, field_options: Any, **options: Any) -> type:
    """A new dataclass of the fields of ``cls`` (its module, name and field types), each
    field made with ``field_options(f)`` and the class with ``options``: whose methods
    :mod:`dataclasses` builds as for ``cls`` (they name no class)."""
    fields = dataclasses.fields(cls)
    body: dict[str, Any] = {
        "__module__": cls.__module__,
        "__qualname__": cls.__qualname__,
        "__annotations__": {f.name: f.type for f in fields},
    }
    for f in fields:
        body[f.name] = dataclasses.field(**field_options(f))
    return dataclasses.dataclass(type(cls.__name__, (), body), **options)


def frozen_methods(cls: type, fields: tuple[dataclasses.Field, ...]) -> tuple[Any, Any]:
    """The ``__setattr__`` and ``__delattr__`` of a frozen class, as :mod:`dataclasses`
    builds them: a field, or any name on the class itself, refused."""
    names = frozenset(f.name for f in fields)

    def __setattr__(self: Any, name: str, value: Any) -> None:
        if type(self) is cls or name in names:
            raise dataclasses.FrozenInstanceError(f"cannot assign to field {name!r}")
        super(cls, self).__setattr__(name, value)  # type: ignore[arg-type]

    def __delattr__(self: Any, name: str) -> None:
        if type(self) is cls or name in names:
            raise dataclasses.FrozenInstanceError(f"cannot delete field {name!r}")
        super(cls, self).__delattr__(name)  # type: ignore[arg-type]

    for method in (__setattr__, __delattr__):
        method.__qualname__ = f"{cls.__qualname__}.{method.__name__}"
        method.__module__ = cls.__module__
    return __setattr__, __delattr__


def build_deferred(cls: type, options: dict[str, Any]) -> None:
    """Step 2: put in place of the stand-ins of ``cls`` the methods :mod:`dataclasses` builds
    with ``options`` for a class of its fields; where it builds none, remove the stand-in (the
    method is inherited)."""
    waiting = [n for n in DEFERRED if isinstance(cls.__dict__.get(n), Deferred)]
    if not waiting:
        return
    later = {k: options.get(k, v) for k, v in METHOD_OPTIONS.items()}
    made = twin(  # (dataclasses.fields: step 1 first, if not done)
        cls,
        lambda f: {"repr": f.repr, "hash": f.hash, "compare": f.compare},
        init=False,
        frozen=options.get("frozen", False),
        **later,
    )
    for name in waiting:
        if name in made.__dict__:
            setattr(cls, name, made.__dict__[name])
        else:
            delattr(cls, name)


def _lazy(cls: type, options: dict[str, Any]) -> type:
    methods = {k: options.get(k, v) for k, v in METHOD_OPTIONS.items()}
    first = {k: options.get(k, v) for k, v in FIRST_OPTIONS.items()}
    own = cls.__dict__
    if (
        options.get("slots")
        or not own.get("__doc__")
        or (methods["order"] and not methods["eq"])
        or any(name in own for name in DEFERRED)
        or (first["frozen"] and ("__setattr__" in own or "__delattr__" in own))
        or any(hasattr(base, "__dataclass_fields__") for base in cls.__mro__[1:])
    ):
        return dataclasses.dataclass(cls, **options)
    for name, asked in DEFERRED.items():
        if methods[asked] or (name == "__hash__" and methods["unsafe_hash"]):
            setattr(cls, name, Deferred(name, cls, options))
    if any(isinstance(v, dataclasses.Field) for v in own.values()):
        build_class(cls, options)  # a field(...) default: the class attribute changes at once
        return cls
    for name, step in FIRST_STEP.items():
        if (step is None or first[step]) and name not in own:
            setattr(cls, name, Deferred(name, cls, options))
    return cls


if TYPE_CHECKING:
    from dataclasses import dataclass as dataclass
else:

    def dataclass(cls=None, /, **options):
        """:func:`dataclasses.dataclass`, built on first use (step 1) and its comparison and
        text methods on their first use (step 2)."""
        if cls is None:
            return lambda c: _lazy(c, options)
        return _lazy(cls, options)
