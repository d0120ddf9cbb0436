"""Two caches in front of pint's registry: parsed unit strings and multiplicative conversion factors.

Profiling a study sample of the lead-screw lift (issue 19) showed ~70 % of its CPU time in pint itself:
every ``q.to("kN")`` parses the unit string again (pint's own parse cache only answers for single unit
names it has already defined, never for ``"N*m"`` or ``"m/s**2"``), and every conversion runs pint's
offset-unit analysis (``_validate_and_extract``) and its context machinery before it multiplies by a
factor that pint has cached already. :func:`install` replaces, on one registry instance only:

- ``parse_units_as_container(text, as_delta, case_sensitive)``: answered from a dict once a string has
  been parsed (a failed parse is not cached; :meth:`define` clears the dict);
- ``convert(value, src, dst, inplace)``: for two units containers without offset units and no active
  context it returns ``value`` when ``src == dst`` and otherwise ``value * factor`` with the factor pint's
  ``_get_conversion_factor`` gives, exactly what pint's multiplicative path computes (so results are
  bit-identical); anything else (offset units such as degC, contexts, Decimal or Fraction magnitudes,
  strings, keyword arguments, dimension errors) goes to pint's own ``convert``.

It also builds this registry's quantities from a float and a units container without pint's general
argument analysis, and remembers the text of each unit per format (pint's formatter is slow). A unit
conversion by string drops from ~90-170 us to ~10 us and one study sample of the lift from ~27 ms to
~8 ms CPU (docs/performance.md).
"""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction
from typing import Any

_SLOW = object()  # conversion that must go through pint (offset units)
_SAME = object()  # src == dst: pint returns the value unchanged


def install(ureg: Any) -> None:
    """Put the parse and conversion caches in front of ``ureg`` (idempotent)."""
    if getattr(ureg, "_mechverify_fast", False):
        return
    from pint.util import UnitsContainer

    parse = ureg.parse_units_as_container
    convert = ureg.convert
    define = ureg.define
    parsed: dict[tuple[Any, Any, Any], Any] = {}
    factors: dict[tuple[Any, Any], Any] = {}

    def parse_units_as_container(input_string: str, as_delta: bool | None = None,
                                 case_sensitive: bool | None = None) -> Any:
        key = (input_string, as_delta, case_sensitive)
        try:
            return parsed[key]
        except (KeyError, TypeError):  # TypeError: an unhashable argument (pint then says what is wrong)
            pass
        out = parse(input_string, as_delta, case_sensitive)
        if type(input_string) is str:
            parsed[key] = out
        return out

    import numpy as np

    plain = frozenset({float, int, np.float64, np.ndarray})
    # (id(src), id(dst)) -> (src, dst, factor): the factor of two units containers found again by identity (a
    # container's own __hash__/__eq__ are Python calls); holding both keeps their ids from being reused
    by_id: dict[tuple[int, int], tuple[Any, Any, Any]] = {}

    def fast_convert(value: Any, src: Any, dst: Any, inplace: bool = False, **ctx_kwargs: Any) -> Any:
        e = by_id.get((id(src), id(dst)))
        if (e is not None and e[0] is src and e[1] is dst and type(value) in plain and not ctx_kwargs
                and not ureg._active_ctx.contexts):
            f = e[2]
        else:
            if (ctx_kwargs or type(src) is not UnitsContainer or type(dst) is not UnitsContainer
                    or ureg._active_ctx or isinstance(value, Decimal | Fraction)):
                return convert(value, src, dst, inplace, **ctx_kwargs)
            key = (src, dst)
            f = factors.get(key)
            if f is None:
                f = _factor(ureg, src, dst)
                if f is None:  # a dimension error: pint raises it with its message
                    return convert(value, src, dst, inplace)
                factors[key] = f
            if len(by_id) >= 8192:
                by_id.clear()
            by_id[id(src), id(dst)] = (src, dst, f)
        if f is _SAME:
            return value
        if f is _SLOW:
            return convert(value, src, dst, inplace)
        if inplace:
            value *= f
            return value
        return value * f

    def fast_define(*args: Any, **kwargs: Any) -> Any:
        parsed.clear()
        factors.clear()
        by_id.clear()
        targets.clear()
        texts.clear()
        return define(*args, **kwargs)

    ureg.parse_units_as_container = parse_units_as_container
    ureg.convert = fast_convert
    ureg.define = fast_define
    texts = _fast_quantities(ureg, UnitsContainer)
    targets = _fast_to(ureg, UnitsContainer, fast_convert, by_id)
    _cached_unit_text(ureg)
    ureg._mechverify_fast = True


def _fast_quantities(ureg: Any, units_container: type) -> dict[str, Any]:
    """``Quantity(value, units)`` of this registry without pint's general argument analysis when ``value`` is a
    float, an int or an ndarray and ``units`` a units container, a unit of this registry or a unit string (what
    ``.to()``, arithmetic and ``Q(v, unit)`` pass; a string's container is pint's ``parse_units(text)._units``,
    remembered): the same two attributes pint sets (its ``_to_magnitude`` returns such values unchanged while the
    registry does not force arrays). Anything else goes to pint's ``__new__``. Returns the dict of unit strings
    (cleared when a unit is defined, and when the registry's preprocessors change)."""
    import numpy as np

    cls = ureg.Quantity
    unit_cls = ureg.Unit
    base_new = cls.__new__
    plain = (float, int, np.float64, np.ndarray)
    texts: dict[str, Any] = {}
    count = [len(ureg.preprocessors)]

    def __new__(klass: Any, value: Any, units: Any = None) -> Any:
        t = type(units)
        if t is unit_cls:  # pint takes a unit's container (Q(v, "mm") passes a parsed unit)
            units = units._units
        elif t is str and type(value) in plain:  # pint: parse_units(units)._units
            if len(ureg.preprocessors) != count[0]:
                texts.clear()
                count[0] = len(ureg.preprocessors)
            u = texts.get(units)
            if u is None:
                u = ureg.parse_units(units)._units
                if len(texts) < 4096:
                    texts[units] = u
            units = u
        if type(units) is units_container and type(value) in plain and not (ureg.force_ndarray
                                                                            or ureg.force_ndarray_like):
            inst = object.__new__(klass)
            inst._magnitude = value
            inst._units = units
            return inst
        return base_new(klass, value, units)

    cls.__new__ = __new__
    return texts


def _fast_to(ureg: Any, units_container: type, convert: Any, by_id: dict[tuple[int, int], Any]) -> dict[str, Any]:
    """``q.to(unit)`` and ``q.m_as(unit)`` of this registry's quantities with the target unit's container looked up
    in a dict (pint runs its preprocessors and ``to_units_container`` on every call) and converted by ``convert``
    (:func:`install`'s, the one pint's ``to`` reaches too): the same magnitude and units as pint's ``to``. Contexts,
    and any target that is not a string, a unit or a units container, go to pint's own methods. Returns the dict of
    targets (cleared with the other caches when a unit is defined, and when the registry's preprocessors change)."""
    from pint.util import to_units_container

    cls = ureg.Quantity
    unit_cls = ureg.Unit
    base_to, base_m_as = cls.to, cls.m_as
    targets: dict[str, Any] = {}
    count = [len(ureg.preprocessors)]

    def target(other: Any) -> Any:
        t = type(other)
        if t is str:
            if len(ureg.preprocessors) != count[0]:  # a preprocessor added or removed: parse anew
                targets.clear()
                count[0] = len(ureg.preprocessors)
            dst = targets.get(other)
            if dst is None:
                dst = to_units_container(other, ureg)
                if len(targets) < 4096:
                    targets[other] = dst
            return dst
        if t is unit_cls:
            return other._units
        if t is units_container:
            return other
        return None

    def to(self: Any, other: Any = None, *contexts: Any, **ctx_kwargs: Any) -> Any:
        if type(other) is str and type(self) is cls and not contexts and not ctx_kwargs:
            # the commonest call, q.to("mm") on a float quantity, with target() and convert() inlined
            dst = targets.get(other)
            m = self._magnitude
            if dst is not None and (type(m) is float or type(m) is int) and len(ureg.preprocessors) == count[0]:
                src = self._units
                e = by_id.get((id(src), id(dst)))
                if (e is not None and e[0] is src and e[1] is dst and e[2] is not _SLOW
                        and not ureg._active_ctx.contexts and not (ureg.force_ndarray or ureg.force_ndarray_like)):
                    q = object.__new__(cls)
                    q._magnitude, q._units = (m if e[2] is _SAME else m * e[2]), dst
                    return q
        if not contexts and not ctx_kwargs:
            dst = target(other)
            if dst is not None:
                m = convert(self._magnitude, self._units, dst)
                if type(m) is float and type(self) is cls and not (ureg.force_ndarray or ureg.force_ndarray_like):
                    # what _fast_quantities' constructor does, without the call
                    q = object.__new__(cls)
                    q._magnitude, q._units = m, dst
                    return q
                return self.__class__(m, dst)
        return base_to(self, other, *contexts, **ctx_kwargs)

    def m_as(self: Any, units: Any) -> Any:
        dst = target(units)
        if dst is not None:
            return convert(self._magnitude, self._units, dst)
        return base_m_as(self, units)

    to.__doc__, m_as.__doc__ = base_to.__doc__, base_m_as.__doc__
    cls.to, cls.m_as = to, m_as
    return targets


def _cached_unit_text(ureg: Any) -> None:
    """``f"{unit:~P}"`` and ``str(unit)`` remembered per (units, format, sort function): pint's formatter takes
    ~30-40 us a call and reports print a few hundred units per design."""
    formatter = ureg.formatter
    base = formatter.format_unit
    texts: dict[tuple[Any, ...], str] = {}

    def format_unit(unit: Any, uspec: str = "", sort_func: Any = None, **babel_kwds: Any) -> str:
        units = getattr(unit, "_units", None)
        if babel_kwds or units is None or not isinstance(unit, ureg.Unit):
            return base(unit, uspec, sort_func, **babel_kwds)
        key = (units, uspec or formatter.default_format, sort_func or formatter.default_sort_func,
               getattr(formatter, "locale", None))
        try:
            return texts[key]
        except (KeyError, TypeError):
            pass
        out = base(unit, uspec, sort_func)
        if len(texts) < 4096:
            texts[key] = out
        return out

    formatter.format_unit = format_unit


def factor_of(ureg: Any, src: Any, dst: Any) -> Any:
    """What the installed conversion multiplies a float by from units container ``src`` to ``dst``: a float,
    ``"same"`` (returned unchanged), or None (pint converts: offset units, or a dimension error)."""
    f = _factor(ureg, src, dst)
    if f is _SAME:
        return "same"
    return None if f is None or f is _SLOW else f


def _factor(ureg: Any, src: Any, dst: Any) -> Any:
    """What :func:`install`'s ``convert`` does for ``src -> dst``: ``_SAME``, ``_SLOW``, the factor, or None
    (pint reports an error)."""
    try:
        if ureg._validate_and_extract(src) or ureg._validate_and_extract(dst):
            return _SLOW
    except ValueError:
        return None
    if src == dst:
        return _SAME
    f = ureg._get_conversion_factor(src, dst)
    return None if isinstance(f, Exception) else f
