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
file system's path on a cluster).
"""

from __future__ import annotations

import os
import tempfile
from typing import Optional, Union

import dask

from . import Report, Scene, _native


def _run_shard(name: str, text: str, k: int, n: int, workdir: str) -> str:
    folder, files = _native.run(name, text, (k, n))
    return os.fspath(Report(folder, files).write(workdir))


def run(scene: Scene, shards: int, client=None, workdir: Optional[Union[str, os.PathLike]] = None) -> Report:
    """Runs ``scene`` in ``shards`` Dask tasks (``client``'s cluster, or Dask's default scheduler)
    and merges their folders into one :class:`~gearloss.Report`."""
    if shards < 1:
        raise ValueError("shards must be at least 1")
    with tempfile.TemporaryDirectory(prefix="gearloss-dask-", dir=workdir) as tmp:
        tasks = [dask.delayed(_run_shard)(scene.name, scene.text, k, shards, tmp) for k in range(1, shards + 1)]
        if client is not None:
            folders = client.gather(client.compute(tasks))
        else:
            folders = list(dask.compute(*tasks))
        name, files = _native.merge(folders)
        return Report(name, files)
