"""Process-wide state that gmsh's OpenCASCADE kernel keeps after ``gmsh.finalize``, made harmless.

gmsh links OpenCASCADE (OCCT) statically, and OCCT keeps two kinds of process-wide state that
``gmsh.finalize`` does not reset. Both made later work of the same process hang (issue 19):

1. **OCCT's thread pool** (``OSD_ThreadPool::DefaultPool``). The first parallel OCCT call in a process
   (gmsh's triangulation of the CAD faces, e.g. for a ``Distance`` size field on the hole walls of
   :func:`mechverify.fea.mesh.block_with_holes`, or a bounding box from that triangulation) creates a pool of
   worker threads that stay until the process ends. It cannot be avoided from gmsh's options
   (``Geometry.OCCParallel = 0``, ``General.NumThreads = 1`` still make it; ``Geometry.OCCDisableStl`` changes
   the mesh) nor by pinning the creating thread to one CPU (the bounding-box path still made a worker).
   A process forked after that (the workers of a study's default process pool, after a solid_fea study ran
   in the same process) inherits the pool but not its threads: its first parallel OCCT call waits for them
   forever (``gmsh.model.mesh.generate``, 0 % CPU; gdb: the child blocked in ``pthread_cond_wait`` in
   libgmsh, called from ``gmsh::model::mesh::generate``, at the same place where the parent's extra thread
   waits for work). :func:`mechverify.studies.execution.process_pool` therefore starts its workers fresh,
   not by fork, once gmsh is loaded in the process.
2. **The STEP length unit** (OCCT's ``xstep.cascade.unit``, gmsh's ``Geometry.OCCTargetUnit``). gmsh sets it
   when it reads or writes STEP with that option given, and it stays: after a STEP file was read in metres
   (:func:`mechverify.fea.mesh.from_step`, :func:`mechverify.fea.study.step_volume`), any later gmsh session
   of the process wrote and read STEP in metres too: a 40 mm box written by a user's script came out 40 m
   long and meshing it at 5 mm never ended (the test-order hang of ``tests/test_fea_study.py`` then
   ``test_fea_solid.py::test_bolt_holes_as_regions_and_step_import``). :func:`restore_step_unit` puts OCCT's
   default (millimetres) back at the end of such a session.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator
from typing import Any


def restore_step_unit(gmsh: Any) -> None:
    """Put OCCT's STEP unit back to its default (millimetres) in an open gmsh session, after a STEP file was
    read with ``Geometry.OCCTargetUnit`` set. gmsh applies the option only when it reads or writes STEP, so
    this reads an empty file as STEP (fails at once, 0.5 ms; OCCT's complaint about it, written by native code
    to the process's stdout/stderr, is dropped); where there is no empty device file it does nothing."""
    gmsh.option.setString("Geometry.OCCTargetUnit", "MM")
    if os.path.exists(os.devnull):
        with _native_output_dropped(), contextlib.suppress(Exception):  # gmsh: a bare "Could not read file"
            gmsh.model.occ.importShapes(os.devnull, format="step")
    gmsh.option.setString("Geometry.OCCTargetUnit", "")


@contextlib.contextmanager
def _native_output_dropped() -> Iterator[None]:
    """File descriptors 1 and 2 on the null device inside the block (what native code prints there is lost;
    Python's and C's buffers are flushed on both sides, so nothing printed before or after is)."""
    import ctypes
    import sys

    def flush() -> None:
        for stream in (sys.stdout, sys.stderr):
            with contextlib.suppress(Exception):
                stream.flush()
        with contextlib.suppress(Exception):
            ctypes.CDLL(None).fflush(None)  # C stdio (std::cout writes through it)

    try:
        flush()
        saved = [os.dup(1), os.dup(2)]
    except OSError:  # (no descriptors 1/2 to save: run the block as it is)
        yield
        return
    null = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(null, 1)
        os.dup2(null, 2)
        yield
    finally:
        flush()
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in (*saved, null):
            os.close(fd)
