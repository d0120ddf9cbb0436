"""The report figure of a plate-bending FEA result: von Mises stress and deflection on the plate, with
its supports and where the loads act (used by the ``plate_fea`` design-file type)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from mechverify.components import plates as pl

if TYPE_CHECKING:
    from mechverify.fea.results import FieldResults


def plate_figure(plate: pl.Plate, supports: tuple[Any, ...], res: FieldResults, title: str,
                 loads: tuple[Any, ...] = ()) -> Any:
    """Von Mises contour (left) and deflection (right) on the plate, the maxima marked with a star; the
    supports in magenta and where the ``loads`` act in red (point forces as triangles, patches hatched)."""
    import matplotlib.pyplot as plt
    from matplotlib.figure import Figure
    from matplotlib.tri import Triangulation

    del plt  # the object-oriented API only: no global figure state
    x, y = res.points[:, 0] * 1e3, res.points[:, 1] * 1e3
    tri = Triangulation(x, y, res.surface)
    x0, y0, x1, y1 = plate.region.bounds
    wide = (x1 - x0) >= (y1 - y0)
    fig = Figure(figsize=(9.0, 3.6) if wide else (9.0, 5.0))
    axes = fig.subplots(1, 2)
    fields = ((res.von_mises.m_as("MPa"), "von Mises stress at the surfaces [MPa] (worse face)", "turbo", True),
              (res.u[:, 2] * 1e3, "deflection w [mm]", "viridis", False))
    for ax, (vals, label, cmap, is_stress) in zip(axes, fields, strict=True):
        cs = ax.tripcolor(tri, vals, shading="gouraud", cmap=cmap, rasterized=True)
        k = int(np.argmax(vals if is_stress else np.abs(vals)))
        for ring in (plate.region.exterior, *plate.region.interiors):
            rx, ry = np.asarray(ring.coords).T * 1e3
            ax.plot(rx, ry, color="k", lw=0.6)
        for s in supports:
            _draw_support(ax, plate, s)
        for ld in loads:
            _draw_load(ax, ld)
        ax.plot(x[k], y[k], marker="*", color="white", mec="k", ms=14)
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
        ax.set_title(f"max {abs(vals[k]):.3g} {'MPa' if is_stress else 'mm'} (★)", fontsize=9)
        fig.colorbar(cs, ax=ax, label=label, shrink=0.8)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return fig


def design_figure(name: str, model: Any, supports: tuple[Any, ...], res: FieldResults, case: str
                  ) -> tuple[str, Any]:
    """The ``plate_fea`` report figure of one load case (:func:`plate_figure`) with its caption: the largest von Mises
    stress at the faces (membrane + bending) and deflection, where they are, the supports and the loads drawn."""
    from mechverify.units import fmt

    vm, k = res.max_von_mises, int(res.max_von_mises.node)
    x, y = res.points[k, :2] * 1e3
    loads = tuple(getattr(model, "loads", ()) or ())
    parts = "bending"
    if "bending_xx_Pa" in res.extra and any(np.any(res.extra[f"membrane_{c}_Pa"]) for c in ("xx", "yy", "xy")):
        from mechverify.fea.plate_stress import governing_stress

        g = governing_stress(res, k)
        parts = (f"membrane + bending, the worse face; there on the {g.face} face sigma_x = {g.membrane[0] / 1e6:.4g} "
                 f"+ {g.bending[0] / 1e6:.4g} MPa, sigma_y = {g.membrane[1] / 1e6:.4g} + {g.bending[1] / 1e6:.4g} MPa, "
                 f"tau_xy = {g.membrane[2] / 1e6:.4g} + {g.bending[2] / 1e6:.4g} MPa (membrane + bending)")
    caption = (f"{name}, load case '{case}': von Mises stress at the plate surfaces ({parts}; largest "
               f"{fmt(vm.value, 'MPa')} at ({x:.4g}, {y:.4g}) mm, ★) and deflection (largest "
               f"{fmt(res.max_displacement.value, 'mm')}); supports in magenta (solid: fixed, dashed: pinned)")
    if loads_caption(loads):
        caption += f"; {loads_caption(loads)}"
    return caption, plate_figure(model.plate, supports, res, f"{name}, load case '{case}'", loads)


def _draw_load(ax: Any, ld: Any) -> None:
    """Where a load acts: a point force as a red triangle pointing along its sign (▼ along -z, ▲ along +z; a
    pure moment as a red circle), a patch as its hatched red outline. Uniform pressure and self-weight act
    everywhere and are named in the caption."""
    if hasattr(ld, "point"):
        f = float(getattr(ld, "force", 0.0) or 0.0)
        marker = "v" if f < 0 else "^" if f > 0 else "o"
        ax.plot(ld.point[0] * 1e3, ld.point[1] * 1e3, marker=marker, color="red", mec="k", ms=9, zorder=5)
    elif getattr(ld, "polygon", None) is not None:
        from matplotlib.patches import Polygon as MplPolygon

        pts = np.asarray(ld.polygon) * 1e3
        ax.add_patch(MplPolygon(pts, closed=True, fill=False, edgecolor="red", hatch="////", lw=1.2, zorder=5))


def loads_caption(loads: tuple[Any, ...]) -> str:
    """The caption's words for the loads: what is drawn and what acts over the whole plate."""
    drawn = [ld for ld in loads if hasattr(ld, "point") or getattr(ld, "polygon", None) is not None]
    spread = [type(ld).__name__ for ld in loads if ld not in drawn]
    parts = []
    if drawn:
        parts.append("loads in red (▼ force along -z, ▲ along +z, ● moment only, hatched: patch load)")
    if any("Pressure" in n for n in spread):
        parts.append("uniform pressure over the whole plate")
    if any("Weight" in n for n in spread):
        parts.append("self-weight")
    return "; ".join(parts)


def _draw_support(ax: Any, plate: pl.Plate, s: Any) -> None:
    style = {"color": "magenta", "lw": 2.5 if s.condition == "clamped" else 1.5,
             "ls": "-" if s.condition == "clamped" else "--"}
    if isinstance(s, pl.EdgeSupport):
        edges = plate.edges()
        for i in s.edge_indices(plate):
            (ax_, ay), (bx, by) = edges[i]
            ax.plot([ax_ * 1e3, bx * 1e3], [ay * 1e3, by * 1e3], **style)
    elif isinstance(s, pl.PointSupport):
        ax.plot(s.point[0] * 1e3, s.point[1] * 1e3, marker="^", color="magenta", mec="k", ms=8)
    else:
        for h in s.resolve(plate):
            r = (s.washer_diameter or h.diameter) / 2
            th = np.linspace(0, 2 * np.pi, 49)
            ax.plot((h.center[0] + r * np.cos(th)) * 1e3, (h.center[1] + r * np.sin(th)) * 1e3, **style)
