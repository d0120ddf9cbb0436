"""Safe arithmetic expressions with units for design files: ``"(payload + carriage_mass) * g"``.

The grammar is a small subset of Python's expression syntax, checked node by node on the tree that
:mod:`ast` parses (nothing is ever passed to ``eval``):

- numbers, and numbers with units written right after them: ``2 kN``, ``9.80665 m/s^2``, ``66 ozf*in``
  (inside a unit ``*``, ``/``, ``·`` and ``^`` join without spaces; ``350 N / g`` divides by ``g``);
- names of parameters (``payload``) and another component's value (``lift_screw.axial_force``);
- ``+ - * /``, power ``**`` or ``^``, parentheses, unary minus and plus;
- the functions ``sqrt sin cos tan atan2 min max abs`` and the constant ``pi``.

Anything else (other attributes, subscripts, lambda, comparisons, other calls, keyword arguments,
strings, names starting with ``_``) is an :class:`ExpressionError` naming what was found. An
expression is parsed once (:func:`parse`, cached) and evaluated many times with
:meth:`Expression.evaluate` on a mapping of names to values; division by zero, overflow and
non-finite results are errors too. Values are pint quantities or plain floats (dimensionless).
"""

from __future__ import annotations

import ast
import functools
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError, suggest
from mechverify.units import DIMENSIONS, Quantity, ureg

MAX_LENGTH = 1000
FUNCTIONS = ("sqrt", "sin", "cos", "tan", "atan2", "min", "max", "abs")
CONSTANTS = {"pi": math.pi}
_ARITY = {"sqrt": (1, 1), "sin": (1, 1), "cos": (1, 1), "tan": (1, 1), "atan2": (2, 2), "min": (1, 32),
          "max": (1, 32), "abs": (1, 1)}

_NUM = r"(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_ATOM = r"[A-Za-z°µΩ%][A-Za-z0-9_°µΩ]*"
_POW = r"(?:(?:\^|\*\*)-?\d+(?:\.\d+)?)"
_UNIT = rf"{_ATOM}{_POW}?(?:[*/·]{_ATOM}{_POW}?)*"
# a number (not part of a name) optionally followed by a unit
_LITERAL = re.compile(rf"(?<![A-Za-z0-9_.])({_NUM})(?:[ \t]*({_UNIT}))?")
_PLACEHOLDER = "_mvq{}_"


class ExpressionError(InputError):
    """An expression is not in the grammar, names something unknown, or does not evaluate to a finite value."""


@dataclass(frozen=True)
class Expression:
    """A parsed expression: ``source`` as written, ``names`` it reads (``"payload"``, ``"screw.axial_force"``)."""

    source: str
    names: frozenset[str]
    _code: tuple[tuple[str, Any], ...]  # postfix program: ("const", v) ("name", n) ("op", sym) ("call", (f, n))
    #: ``_code`` with its constant parts done once (:func:`_fold`); what :meth:`evaluate` runs
    _run: tuple[tuple[str, Any], ...] = field(default=(), compare=False, repr=False)

    @property
    def is_constant(self) -> bool:
        return not self.names

    def evaluate(self, env: Mapping[str, Any] | None = None) -> Any:
        """The value (a quantity, or a float when dimensionless without units) with ``env`` giving the names."""
        env = env or {}
        stack: list[Any] = []
        try:
            for op, arg in self._run or self._code:
                if op == "const":
                    stack.append(arg)
                elif op == "name":
                    if arg not in env:
                        raise ExpressionError(f"{self.source!r}: unknown name {arg!r}" + _hint(arg, env))
                    v = env[arg]
                    stack.append(float(v) if isinstance(v, int | float) and not isinstance(v, bool) else v)
                elif op == "neg":
                    stack.append(-stack.pop())
                elif op == "op":
                    b = stack.pop()
                    a = stack.pop()
                    stack.append(_binary(arg, a, b, self.source))
                else:
                    fname, n = arg
                    args = stack[len(stack) - n:]
                    del stack[len(stack) - n:]
                    stack.append(_call(fname, args, self.source))
        except ZeroDivisionError:
            raise ExpressionError(f"{self.source!r}: division by zero") from None
        except OverflowError:
            raise ExpressionError(f"{self.source!r}: the value overflows") from None
        except pint.DimensionalityError as exc:
            raise ExpressionError(f"{self.source!r}: units do not match ({_dim_text(exc)})") from None
        except (pint.errors.PintError, TypeError, ValueError) as exc:
            if isinstance(exc, ExpressionError):
                raise
            raise ExpressionError(f"{self.source!r}: cannot evaluate ({exc})") from None
        (result,) = stack
        _finite(result, self.source)
        return result

    def evaluate_as(self, kind: str, env: Mapping[str, Any] | None = None) -> Any:
        """Evaluate and check the result is of dimension ``kind`` (a name of :data:`mechverify.units.DIMENSIONS`)."""
        return check_kind(self.evaluate(env), kind, self.source)

    def __str__(self) -> str:
        return self.source


def _hint(name: str, env: Mapping[str, Any]) -> str:
    h = suggest(name, list(env), 1)
    return f"; did you mean {h[0]!r}?" if h else ""


def _dim_text(exc: pint.DimensionalityError) -> str:
    """'a force and a length': mechverify's names of the two dimensions (pint's ``[mass] * [length] / [time] ** 2``
    only for a dimension it has no name for)."""
    if not exc.dim1 and not exc.dim2:  # (pint gives the units only: 1 m + 1)
        from mechverify.units import ureg

        def dims(u: Any) -> str:
            try:
                return str(ureg.Quantity(1.0, u).dimensionality)
            except Exception:  # (not a unit pint builds: its text)
                return str(u)
        d1, d2 = _dim_name(dims(exc.units1)), _dim_name(dims(exc.units2))
    else:
        d1, d2 = _dim_name(exc.dim1), _dim_name(exc.dim2)
    return f"{d1} and {d2}" if d2 else d1


def _dim_name(dim: Any) -> str:
    from mechverify.units import DIMENSIONS, ureg

    text = str(dim) if dim is not None else ""
    if not text:
        return ""
    try:
        d = ureg.get_dimensionality(text)
    except Exception:  # (not a dimensionality pint reads back: its text)
        return text
    if not d:
        return "dimensionless"
    names = [n.replace("_", " ") for n, (dd, _) in DIMENSIONS.items() if dd and ureg.get_dimensionality(dd) == d]
    if not names:
        return text
    listed = names[0] if len(names) == 1 else ", ".join(names[:-1]) + " or " + names[-1]
    return ("an " if names[0][0] in "aeiou" else "a ") + listed


def _finite(v: Any, source: str) -> None:
    m = v._magnitude if isinstance(v, Quantity) else v
    if type(m) is float or type(m) is int:  # (the usual scalar: no array round trip)
        if not math.isfinite(m):
            raise ExpressionError(f"{source!r}: the result is not finite ({m!r})")
        return
    if isinstance(m, complex):
        raise ExpressionError(f"{source!r}: the result is not a real number")
    if not np.all(np.isfinite(np.asarray(m, dtype=float))):
        raise ExpressionError(f"{source!r}: the result is not finite ({m!r})")


def _dimensionless(v: Any, what: str, source: str) -> float:
    if isinstance(v, Quantity):
        if not v.dimensionless:
            raise ExpressionError(f"{source!r}: {what} must be dimensionless (or an angle), got {v.units:~P}")
        return float(v.to("dimensionless").magnitude)
    return float(v)


def _binary(op: str, a: Any, b: Any, source: str) -> Any:
    if op == "+":
        r = a + b
    elif op == "-":
        r = a - b
    elif op == "*":
        r = a * b
    elif op == "/":
        if (b.magnitude if isinstance(b, Quantity) else b) == 0:
            raise ZeroDivisionError
        r = a / b
    else:  # power
        e = _dimensionless(b, "an exponent", source)
        if isinstance(a, Quantity) and a.dimensionless:
            a = float(a.to("dimensionless").magnitude)
        if isinstance(a, Quantity):
            if abs(e) > 64:
                raise ExpressionError(f"{source!r}: exponent {e:g} too large for a quantity with units")
            r = a ** e
        else:
            if float(a) < 0 and not float(e).is_integer():
                raise ExpressionError(f"{source!r}: a negative number to a fractional power is not a real number")
            r = math.pow(float(a), e)
    _finite(r, source)
    return r


def _angle(v: Any, fname: str, source: str) -> float:
    if isinstance(v, Quantity):
        if not v.dimensionless:
            raise ExpressionError(f"{source!r}: {fname}() needs an angle or a number, got {v.units:~P}")
        return float(v.to("radian").magnitude)
    return float(v)


def _call(fname: str, args: list[Any], source: str) -> Any:
    if fname == "sqrt":
        (a,) = args
        if isinstance(a, Quantity):
            if a.magnitude < 0:
                raise ExpressionError(f"{source!r}: sqrt of a negative value")
            return a ** 0.5
        if a < 0:
            raise ExpressionError(f"{source!r}: sqrt of a negative value")
        return math.sqrt(a)
    if fname in ("sin", "cos", "tan"):
        x = _angle(args[0], fname, source)
        return {"sin": math.sin, "cos": math.cos, "tan": math.tan}[fname](x)
    if fname == "atan2":
        y, x = args
        if isinstance(y, Quantity) or isinstance(x, Quantity):
            y, x = Quantity(y), Quantity(x)
            x = x.to(y.units)  # DimensionalityError when they differ
            return Quantity(math.atan2(float(y.magnitude), float(x.magnitude)), "rad")
        return Quantity(math.atan2(y, x), "rad")
    if fname == "abs":
        return abs(args[0])
    units = [a for a in args if isinstance(a, Quantity)]
    if units and len(units) < len(args) and not all(a.dimensionless for a in units):
        raise ExpressionError(f"{source!r}: {fname}() of values with and without units")
    if units:
        ref = units[0].units
        conv = [Quantity(a).to(ref) for a in args]  # DimensionalityError when they differ
        pick = (min if fname == "min" else max)(range(len(args)), key=lambda i: conv[i].magnitude)
        return args[pick]
    return (min if fname == "min" else max)(args)


def check_kind(value: Any, kind: str, source: str) -> Any:
    """``value`` as a quantity of dimension ``kind``; an :class:`ExpressionError` names the expression otherwise."""
    from mechverify.units import _dimension_matches

    q = value if isinstance(value, Quantity) else Quantity(value, "dimensionless")
    if kind not in DIMENSIONS:
        raise KeyError(kind)
    if not _dimension_matches(q, kind):
        word = kind.replace("_", " ")
        got = f"{q.units:~P}" if not q.dimensionless else "a plain number"
        raise ExpressionError(f"{source!r} gives {got} ({_describe_dim(q)}), expected "
                              f"{'an' if word[0] in 'aeiou' else 'a'} {word}")
    if kind == "angle" and q.unitless:
        raise ExpressionError(f"{source!r} gives a plain number, expected an angle; give a unit (deg or rad)")
    return q


def _describe_dim(q: Any) -> str:
    for name, (dim, _) in DIMENSIONS.items():
        if dim and q.dimensionality == ureg.get_dimensionality(dim):
            return f"{'an' if name[0] in 'aeiou' else 'a'} {name.replace('_', ' ')}"
    return "dimensionless" if q.dimensionless else str(q.dimensionality)


# ----------------------------------------------------------------------------------------------- parsing


@functools.lru_cache(maxsize=1024)
def _parse_units(text: str) -> Any:
    """A literal's unit text parsed once (a study's drawn values repeat a few units in new strings every sample)."""
    return ureg.parse_units(text)


def _literal_value(number: str, unit: str | None, source: str) -> Any:
    value: float | int = int(number) if re.fullmatch(r"\d+", number) else float(number)
    if not unit:
        return float(value)
    text = unit.replace("·", "*").replace("^", "**")
    try:
        u = _parse_units(text)
    except Exception:
        raise ExpressionError(f"{source!r}: unknown unit {unit!r} after {number} (to multiply by a parameter, "
                              f"write {number} * {unit})") from None
    return Quantity(value, u)


_ALLOWED_OPS = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**"}
_WHAT = {ast.Subscript: "subscripts", ast.Lambda: "lambda", ast.Compare: "comparisons", ast.BoolOp: "and/or",
         ast.IfExp: "if-else", ast.Starred: "starred arguments", ast.Tuple: "tuples", ast.List: "lists",
         ast.Dict: "dicts", ast.Set: "sets", ast.ListComp: "comprehensions", ast.GeneratorExp: "generators",
         ast.DictComp: "comprehensions", ast.SetComp: "comprehensions", ast.JoinedStr: "strings",
         ast.NamedExpr: "assignments", ast.Await: "await", ast.Slice: "slices"}


def _not_allowed(node: ast.AST, source: str) -> ExpressionError:
    what = _WHAT.get(type(node))
    if what is None:
        if isinstance(node, ast.BinOp | ast.UnaryOp):
            op = type(node.op).__name__
            what = f"the operator {op}"
        elif isinstance(node, ast.Constant):
            what = f"the constant {node.value!r}"
        else:
            what = type(node).__name__
    return ExpressionError(f"{source!r}: {what} not allowed (only numbers with units, names, + - * / ** "
                           f"( ) and {', '.join(FUNCTIONS)}, pi)")


def parse(text: str) -> Expression:
    """Parse and check ``text`` once (cached); raise :class:`ExpressionError` when it is not in the grammar."""
    if not isinstance(text, str):
        raise ExpressionError(f"expected an expression string, got {text!r}")
    out = _parse_or_error(text)
    if isinstance(out, ExpressionError):  # a fresh error each time (a re-raised one would grow its traceback)
        raise ExpressionError(str(out)) from None
    return out


@functools.lru_cache(maxsize=8192)
def _parse_or_error(text: str) -> Expression | ExpressionError:
    """:func:`parse`'s work; text that is not an expression (a motor's name, free text read by the loader on every
    variant of a study) is remembered as its error too, not parsed again."""
    try:
        return _parse(text)
    except ExpressionError as exc:
        return exc.with_traceback(None)  # (its frames are not kept)


def _parse(text: str) -> Expression:
    source = text.strip()
    if len(text) > MAX_LENGTH:
        raise ExpressionError(f"expression longer than {MAX_LENGTH} characters ({len(text)})")
    if not source:
        raise ExpressionError("empty expression")
    if "\n" in source or "\r" in source or "\\" in source or "#" in source or ";" in source:
        raise ExpressionError(f"{source!r}: line breaks, backslashes, ';' and '#' are not allowed")
    whole = _LITERAL.match(source)  # one number with its unit (a study's drawn value): the program the walk below
    if whole is not None and whole.end() == len(source):  # would make, without Python's parser
        return Expression(source, frozenset(), (("const", _literal_value(whole.group(1), whole.group(2), source)),))
    literals: list[Any] = []

    def sub(m: re.Match[str]) -> str:
        literals.append(_literal_value(m.group(1), m.group(2), source))
        return " " + _PLACEHOLDER.format(len(literals) - 1) + " "

    py = _LITERAL.sub(sub, source).replace("^", "**").strip()
    try:
        tree = ast.parse(py, mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError) as exc:
        msg = exc.msg if isinstance(exc, SyntaxError) else type(exc).__name__
        raise ExpressionError(f"{source!r}: not a valid expression ({msg})") from None
    code: list[tuple[str, Any]] = []
    names: set[str] = set()
    # iterative post-order walk: no recursion limit on long sums
    todo: list[tuple[ast.AST, bool]] = [(tree.body, False)]
    while todo:
        node, done = todo.pop()
        if isinstance(node, ast.BinOp):
            if type(node.op) not in _ALLOWED_OPS:
                raise _not_allowed(node, source)
            if done:
                code.append(("op", _ALLOWED_OPS[type(node.op)]))
            else:
                todo += [(node, True), (node.right, False), (node.left, False)]
        elif isinstance(node, ast.UnaryOp):
            if not isinstance(node.op, ast.USub | ast.UAdd):
                raise _not_allowed(node, source)
            if done:
                if isinstance(node.op, ast.USub):
                    code.append(("neg", None))
            else:
                todo += [(node, True), (node.operand, False)]
        elif isinstance(node, ast.Constant):
            v = node.value
            if isinstance(v, bool) or not isinstance(v, int | float):
                raise _not_allowed(node, source)
            code.append(("const", float(v)))
        elif isinstance(node, ast.Name):
            n = node.id
            m = re.fullmatch(_PLACEHOLDER.replace("{}", r"(\d+)"), n)
            if m:
                code.append(("const", literals[int(m.group(1))]))
            elif n.startswith("_"):
                raise ExpressionError(f"{source!r}: names starting with '_' are not allowed ({n!r})")
            elif n in CONSTANTS:
                code.append(("const", CONSTANTS[n]))
            elif n in FUNCTIONS:
                raise ExpressionError(f"{source!r}: {n} is a function; call it as {n}(...)")
            else:
                names.add(n)
                code.append(("name", n))
        elif isinstance(node, ast.Attribute):
            if not isinstance(node.value, ast.Name) or node.value.id.startswith("_") or node.attr.startswith("_"):
                raise ExpressionError(f"{source!r}: only <component>.<value> may use a dot (attribute chains and "
                                      f"private names are not allowed)")
            if node.value.id in CONSTANTS or node.value.id in FUNCTIONS or re.match(r"_mvq", node.value.id):
                raise ExpressionError(f"{source!r}: only <component>.<value> may use a dot")
            n = f"{node.value.id}.{node.attr}"
            names.add(n)
            code.append(("name", n))
        elif isinstance(node, ast.Call):
            f = node.func
            if not isinstance(f, ast.Name) or f.id not in FUNCTIONS:
                what = f.id if isinstance(f, ast.Name) else ast.unparse(f)[:40]
                hint = suggest(what, FUNCTIONS, 1)
                raise ExpressionError(f"{source!r}: function {what!r} not allowed (allowed: {', '.join(FUNCTIONS)})"
                                      + (f"; did you mean {hint[0]!r}?" if hint else ""))
            if node.keywords or any(isinstance(a, ast.Starred) for a in node.args):
                raise ExpressionError(f"{source!r}: {f.id}() takes plain arguments only")
            lo, hi = _ARITY[f.id]
            if not lo <= len(node.args) <= hi:
                raise ExpressionError(f"{source!r}: {f.id}() takes {lo if lo == hi else f'{lo} to {hi}'} "
                                      f"argument{'s' if hi > 1 else ''}, got {len(node.args)}")
            if done:
                code.append(("call", (f.id, len(node.args))))
            else:
                todo.append((node, True))
                todo += [(a, False) for a in reversed(node.args)]
        else:
            raise _not_allowed(node, source)
    return Expression(source, frozenset(names), tuple(code), _fold(tuple(code), source) if names else ())


def _fold(code: tuple[tuple[str, Any], ...], source: str) -> tuple[tuple[str, Any], ...]:
    """``code`` with every operation whose operands are all constants done now, once: ``2 * (120 N * 400 mm + 30 N *
    800 mm) / lifted_load`` keeps one constant and one division, where a study's every sample repeated five pint
    operations. The same operations on the same values in the same order: the same results, bit for bit. An
    operation that fails (a division by zero, a unit mismatch) is left in place, to fail where it always did."""
    out: list[tuple[str, Any]] = []
    const: list[bool] = []  # per stack slot: a constant (then the last instruction in ``out`` pushes it)
    for op, arg in code:
        if op == "const":
            out.append((op, arg))
            const.append(True)
            continue
        if op == "name":
            out.append((op, arg))
            const.append(False)
            continue
        n = 1 if op == "neg" else 2 if op == "op" else arg[1]
        args = const[len(const) - n:] if n else []
        del const[len(const) - n:]
        if n and all(args):
            values = [v for _, v in out[len(out) - n:]]
            try:
                if op == "neg":
                    r = -values[0]
                elif op == "op":
                    r = _binary(arg, values[0], values[1], source)
                else:
                    r = _call(arg[0], values, source)
                _finite(r, source)
            except Exception:  # (left to evaluate, which reports it as before)
                r = None
            if r is not None:
                del out[len(out) - n:]
                out.append(("const", r))
                const.append(True)
                continue
        out.append((op, arg))
        const.append(False)
    return tuple(out)


def is_expression(text: Any) -> bool:
    """``text`` is a string that parses and reads at least one name (a parameter or a component value)."""
    if not isinstance(text, str):
        return False
    try:
        return bool(parse(text).names)
    except ExpressionError:
        return False


def evaluate(text: str, env: Mapping[str, Any] | None = None, kind: str | None = None) -> Any:
    """Parse (cached) and evaluate ``text``; with ``kind`` check the result's dimension."""
    e = parse(text)
    return e.evaluate(env) if kind is None else e.evaluate_as(kind, env)


def format_value(v: Any) -> str:
    """A value as a string the quantity parser reads back exactly (``repr`` of the magnitude + pint's units)."""
    if isinstance(v, Quantity):
        m = v.magnitude
        m = float(m) if isinstance(m, float | np.floating) else m
        u = format(v.units, "D")
        return f"{m!r} {u}" if u and u != "dimensionless" else repr(m)
    return repr(float(v)) if isinstance(v, float) else str(v)
