"""``mechverify faces part.step``: the faces of a STEP (or STL) file with the ids solid_fea uses (``face = 7``), each
with its type, position, normal or axis and area (review 3 finding 24; STL files: review 4 finding 23)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ORDER = 65


def add_parser(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("faces", help="list the faces of a STEP or STL file with the ids solid_fea uses",
                       description="List the faces of a STEP or STL file as solid_fea names them (face<k>; a STEP "
                                   "file's solids bonded first, an STL file's triangles split into faces at 40 deg): "
                                   "type, plane and normal or cylinder radius and axis, centroid, area. Needs the "
                                   "gmsh extra.")
    p.add_argument("step", type=Path, help="the STEP or STL file")
    p.add_argument("--unit", default="mm", help="unit of an STL file's coordinates (as solid_fea's unit; default mm)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from mechverify.fea.stepfaces import describe_faces

    sys.stdout.write(describe_faces(args.step, args.unit) + "\n")
    return 0
