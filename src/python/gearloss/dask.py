"""Big sweeps on Dask: a scene's operating points in shards, one Dask task each, merged as
``gearloss merge`` merges them, into the same report as a single run.

>>> import gearloss, gearloss.dask
>>> scene = gearloss.Scene.from_file("specs/fzg_type_c.gear")
>>> whole = gearloss.run(scene)
>>> sharded = gearloss.dask.run(scene, shards=3)
>>> sharded.data == whole.data
True

With ``client=None`` the tasks run on Dask's default scheduler (threads in this process: the
computation releases the GIL); give a ``distributed.Client`` to run them on its cluster. The shard
folders go to a temporary folder the workers and this process share (``workdir``: give a shared
file system's path on a cluster). More shards than operating points are not made: ``shards`` is
capped at the scene's point count. A shard that fails raises :class:`gearloss.RunError` naming it
(``.shard``, ``.kind``, ``.hints``), once every other shard has finished: none writes after the
temporary folder is gone.
"""

from __future__ import annotations

import os
import tempfile
from typing import Optional, Union

import dask

from . import Report, RunError, Scene, _native
from . import merge as gearloss_merge
from . import run as gearloss_run


def _run_shard(name: str, text: str, k: int, n: int, workdir: str, records=None):
    """One shard's folder written into ``workdir``: ``("ok", path)``, or ``("failed", error)`` so
    that every task finishes before the folder is removed."""
    try:
        return ("ok", os.fspath(_native.run_to(name, text, workdir, f"{k}/{n}", records)))
    except Exception as e:  # noqa: BLE001 - handed back and raised, naming the shard
        return ("failed", e)


def run(
    scene: Scene, shards: int, client=None, workdir: Optional[Union[str, os.PathLike]] = None, records=None
) -> Report:
    """Runs ``scene`` in ``shards`` Dask tasks (``client``'s cluster, or Dask's default scheduler;
    at most one a point) and merges their folders into one :class:`~gearloss.Report` (``records``
    as :func:`gearloss.run` takes it: Parquet shards merge into one records.parquet)."""
    records = records if records is None or isinstance(records, str) else ",".join(records)
    if isinstance(shards, bool) or not isinstance(shards, int) or shards < 1:
        raise ValueError(f"shards must be a whole number, at least 1 (got {shards!r})")
    points = _native.operating_points(scene.name, scene.text)
    if points == 0:
        # A scene without operating points (a vehicle over a drive cycle only) is one piece of
        # work with nothing to share out: it runs whole, here.
        return gearloss_run(scene, records=records)
    shards = min(shards, points)
    with tempfile.TemporaryDirectory(prefix="gearloss-dask-", dir=workdir) as tmp:
        tasks = [
            dask.delayed(_run_shard)(scene.name, scene.text, k, shards, tmp, records) for k in range(1, shards + 1)
        ]
        if client is not None:
            results = client.gather(client.compute(tasks))
        else:
            results = list(dask.compute(*tasks))
        for k, (status, value) in enumerate(results, start=1):
            if status == "failed":
                err = RunError(f"shard {k} of {shards} failed: {value}")
                err.shard = k
                err.kind = getattr(value, "kind", "")
                err.hints = list(getattr(value, "hints", []))
                raise err from value
        return gearloss_merge([value for _, value in results])
