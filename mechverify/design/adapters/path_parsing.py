"""Parsing of a ``planar_arm``'s ``path`` table (no component type here): curves from expressions with units
(evaluated vectorised: the expression's postfix program on numpy arrays), sampled points, constant speed or a
trapezoidal walk; kinematics in :mod:`mechverify.mechanisms.paths`. Also the arm's ``bodies`` (``parse_bodies``)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from mechverify.design.expressions import ExpressionError
from mechverify.design.expressions import parse as parse_expression
from mechverify.errors import InputError, UnitError
from mechverify.mechanisms import paths as mp
from mechverify.units import Q, Quantity, to_si

#: Most samples of a path walk: 100 000 samples take ~3 s and ~110 MB for an RP arm with its drive (measured on a
#: 2-core box, 2026), a time step of 1e-5 of the walk; 50 million ran for minutes.
MAX_PATH_SAMPLES = 100_000

PATH_KEYS = {"curve": "str", "r": "str", "centre": "list", "phi": "list", "x": "str", "y": "str", "u": "list",
             "points": "list", "closed": "bool", "speed": "velocity", "acceleration": "acceleration",
             "samples": "int"}


# ------------------------------------------------------------------------------------------ expressions of a curve

def _vector(expr_text: str, var: str, params: Mapping[str, Any], where: str) -> Any:
    """A vectorised SI function of the curve parameter (radians for phi) from an expression with units; the
    expression must be a length (``"8 - 1.5 * cos(4*phi)"`` or ``"8 cm/s"`` is an error, not metres)."""
    try:
        e = parse_expression(expr_text)
    except ExpressionError as exc:
        raise InputError(f"{where}: {exc}") from None
    unknown = sorted(n for n in e.names if n != var and n not in params)
    if unknown:
        raise InputError(f"{where}: unknown name {unknown[0]!r} (the curve's variable is {var!r}; parameters: "
                         f"{', '.join(params) or 'none'})")
    code = e._code

    def value(w: np.ndarray) -> Any:
        env = {**params, var: Q(np.asarray(w, float), "rad" if var == "phi" else "")}
        stack: list[Any] = []
        for op, arg in code:
            if op == "const":
                stack.append(arg)
            elif op == "name":
                stack.append(env[arg])
            elif op == "neg":
                stack.append(-stack.pop())
            elif op == "op":
                b, a = stack.pop(), stack.pop()
                stack.append(a + b if arg == "+" else a - b if arg == "-" else a * b if arg == "*"
                             else a / b if arg == "/" else a ** _plain(b))
            else:
                fname, n = arg
                args = stack[len(stack) - n:]
                del stack[len(stack) - n:]
                stack.append(_call(fname, args))
        (v,) = stack
        return v

    def f(w: np.ndarray) -> np.ndarray:
        v = value(w)
        return np.asarray(Q(v).to_base_units().magnitude if isinstance(v, Quantity) else v, float)

    try:
        v = value(np.array([0.1, 0.2]))
    except Exception as exc:  # pint raises several types for mismatched units
        raise InputError(f"{where}: {expr_text!r} cannot be evaluated ({exc})") from None
    if not isinstance(v, Quantity) or v.dimensionality != _LENGTH:
        got = f"{v.units:~P} ({v.dimensionality})" if isinstance(v, Quantity) else "a bare number"
        raise UnitError(f"{where}: expected a length (e.g. \"8 cm - 1.5 cm * cos(4*phi)\"), {expr_text!r} is {got}")
    return f, e


_LENGTH = Q(1, "m").dimensionality


def _plain(v: Any) -> Any:
    return v.to("dimensionless").magnitude if isinstance(v, Quantity) else v


def _call(fname: str, args: list[Any]) -> Any:
    if fname in ("sin", "cos", "tan"):
        x = args[0].to("rad").magnitude if isinstance(args[0], Quantity) else args[0]
        return {"sin": np.sin, "cos": np.cos, "tan": np.tan}[fname](x)
    if fname == "sqrt":
        return args[0] ** 0.5
    if fname == "abs":
        return abs(args[0])
    if fname == "atan2":
        y, x = (Q(a) for a in args)
        return Q(np.arctan2(y.magnitude, x.to(y.units).magnitude), "rad")
    red = np.minimum if fname == "min" else np.maximum
    out = args[0]
    for a in args[1:]:
        out = Q(red(Q(out).magnitude, Q(a).to(Q(out).units).magnitude), Q(out).units)
    return out


def _length(v: Any, where: str) -> float:
    return to_si(v, "length", where)


def _pair(v: Any, where: str, kind: str) -> tuple[float, float]:
    if not isinstance(v, list) or len(v) != 2:
        raise InputError(f"{where}: expected two values [from, to] or [x, y], got {v!r}")
    if kind == "number":
        return tuple(float(to_si(x, "angle", where)) if isinstance(x, str) else float(x) for x in v)  # type: ignore
    return to_si(v[0], kind, f"{where}[0]"), to_si(v[1], kind, f"{where}[1]")


def walk_path(table: Mapping[str, Any], params: Mapping[str, Any]) -> mp.PathSamples:
    """The path table of a ``planar_arm`` walked in time (key paths start at ``path``)."""
    from mechverify.errors import suggest

    for k in table:
        if k not in PATH_KEYS:
            hint = suggest(k, PATH_KEYS, 1)
            raise InputError(f"path.{k}: unknown key" + (f"; did you mean {hint[0]!r}?" if hint
                                                          else f" (allowed: {', '.join(PATH_KEYS)})"))
    curve = table.get("curve")
    if curve not in ("polar", "cartesian", "points"):
        raise InputError(f"path.curve: expected 'polar', 'cartesian' or 'points', got {curve!r}")
    samples = table.get("samples", 400)
    if isinstance(samples, bool) or not isinstance(samples, int):
        raise InputError(f"path.samples: expected a whole number, got {samples!r}")
    if not 2 <= samples <= MAX_PATH_SAMPLES:
        raise InputError(f"path.samples: expected 2 to {MAX_PATH_SAMPLES:,} (time and memory of the walk), got "
                         f"{samples:,}")
    if "speed" not in table:
        raise InputError("path.speed: missing (the tangential speed, constant or the cruise speed with acceleration)")
    speed = to_si(table["speed"], "velocity", "path.speed")
    if not speed > 0:
        raise InputError(f"path.speed: must be > 0, got {table['speed']!r}")
    if curve == "polar":
        if "r" not in table:
            raise InputError("path.r: missing (r as an expression in phi, e.g. \"8 cm - 1.5 cm * cos(4*phi)\")")
        r, _ = _vector(str(table["r"]), "phi", params, "path.r")
        xc, yc = _pair(table.get("centre", ["0 m", "0 m"]), "path.centre", "length")
        rng = _pair(table.get("phi", ["0 deg", "360 deg"]), "path.phi", "angle")
        w = np.linspace(rng[0], rng[1], max(samples, 1001))
        rw = np.broadcast_to(r(w), w.shape)
        if np.any(rw < 0):
            i = int(np.argmin(rw))
            raise InputError(f"path.r: the radius must not be negative, {table['r']!r} is {rw[i] * 100:.4g} cm at "
                             f"phi = {np.degrees(w[i]):.4g} deg")

        def fn(w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            rr = r(w)
            return xc + rr * np.cos(w), yc + rr * np.sin(w)
    elif curve == "cartesian":
        if "x" not in table or "y" not in table:
            raise InputError("path.x, path.y: a Cartesian curve needs both, as expressions in u")
        fx, _ = _vector(str(table["x"]), "u", params, "path.x")
        fy, _ = _vector(str(table["y"]), "u", params, "path.y")
        rng = _pair(table.get("u", [0.0, 1.0]), "path.u", "number")

        def fn(w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            return fx(w), fy(w)
    else:
        pts = table.get("points")
        if not isinstance(pts, list):
            raise InputError("path.points: expected a list of [x, y] pairs with units")
        xy = np.array([_pair(p, f"path.points[{i}]", "length") for i, p in enumerate(pts)])
        fn, rng = mp.spline_through(xy, bool(table.get("closed", False)))
    for k in (("r",) if curve != "polar" else ()) + (("x", "y") if curve != "cartesian" else ()) + \
            (("points",) if curve != "points" else ()):
        if k in table:
            raise InputError(f"path.{k}: not a key of a {curve} curve")
    if "acceleration" in table:
        acc = to_si(table["acceleration"], "acceleration", "path.acceleration")
        if not acc > 0:
            raise InputError(f"path.acceleration: must be > 0, got {table['acceleration']!r}")

        def timing(length: float) -> mp.Timing:
            from mechverify.motion.profiles import trapezoidal

            prof = trapezoidal(Q(length, "m"), max_velocity=Q(speed, "m/s"), acceleration=Q(acc, "m/s**2"))
            t = np.linspace(0.0, prof.duration.m_as("s"), samples + 1)
            st = prof.at(Q(t, "s"))
            return mp.Timing(t, st["x"].m_as("m"), st["v"].m_as("m/s"), st["a"].m_as("m/s**2"))

        return mp.walk_curve(fn, rng, timing=timing, samples=samples)
    return mp.walk_curve(fn, rng, Q(speed, "m/s"), samples=samples)



# ------------------------------------------------------------------------------------------ bodies on the links

def parse_bodies(p: Mapping[str, Any], link: int | None) -> list[mp.LinkBody]:
    """A ``planar_arm``'s ``bodies`` on link ``link`` (1 or 2; None: an RP arm, all on link 1) as LinkBody."""
    out = []
    for i, b in enumerate(p.get("bodies", [])):
        where = f"bodies[{i}]"
        if not isinstance(b, dict):
            raise InputError(f"{where}: expected a table such as {{ shape = \"rod\", mass = \"99 g\", length = "
                             f"\"25 cm\" }}")
        extra = [k for k in b if k not in ("shape", "mass", "length", "radius", "inner_radius", "start", "name",
                                           "link")]
        if extra:
            raise InputError(f"{where}.{extra[0]}: unknown key (allowed: shape, mass, length, radius, inner_radius, "
                             "start, name, link)")
        if "shape" not in b or "mass" not in b:
            raise InputError(f"{where}: needs shape and mass")
        on = int(b.get("link", 1))
        if link is None and on != 1:
            raise InputError(f"{where}.link: an RP arm's bodies turn with q1 (link 1); the carriage is carriage_mass")
        if link is not None and on not in (1, 2):
            raise InputError(f"{where}.link: expected 1 or 2, got {b.get('link')!r}")
        if link is None or on == link:
            out.append(mp.LinkBody(b["shape"], b["mass"], b.get("length"), b.get("radius"), b.get("inner_radius"),
                                   b.get("start", "0 m"), b.get("name", where)))
    return out


__all__ = ["walk_path", "PATH_KEYS", "MAX_PATH_SAMPLES", "parse_bodies"]
