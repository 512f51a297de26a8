"""Batch runs on a Dask cluster (docs/batch.md, "Dask").

    from distributed import Client, LocalCluster
    import yamsc.dask
    with LocalCluster(n_workers=4, threads_per_worker=1) as cluster, Client(cluster) as client:
        summary = yamsc.dask.run("cases.csv", client)

The manifest's rows are split as `yamsc batch --shard k/N` splits them, and
each shard is one task: `yamsc batch` itself (the same C++ function, on one
thread) runs inside the worker and writes its results into the output folder.
The shards' summaries are then merged as `yamsc batch merge` merges them, so
the files are those of a `yamsc batch` run in one process, byte for byte.
Workers need the same yamsc build, and the manifest, models and output folder
at the same paths (a shared filesystem on a cluster).
"""
import os
import re
import sys
import uuid

from . import _yamsc
from . import _pandas

__all__ = ["run", "default_output_dir", "read_summary"]


def default_output_dir(manifest):
    """`yamsc batch`'s default output folder: the manifest without .csv, plus .out."""
    manifest = os.fspath(manifest)
    stem = manifest[:-4] if len(manifest) > 4 and manifest.endswith(".csv") else manifest
    return stem + ".out"


def read_summary(path, frame=None):
    """A summary file (summary.csv or a shard's) as a pandas DataFrame with the
    file's columns (row, id, status, final, message, wall_s) when pandas is
    present and frame is not False, else a list of dicts."""
    rows = _yamsc.read_batch_summary(os.fspath(path))
    pandas = _pandas(frame)
    if pandas is not None:
        columns = ["row", "id", "status", "final", "message", "wall_s"]
        return pandas.DataFrame(rows, columns=columns)
    return rows


def _run_shard(manifest, outdir, shard, shards, case_time_limit=0.0):
    """The task of shard k/N: `yamsc batch MANIFEST -o OUTDIR --shard k/N --threads 1 -q
    [--case-time-limit S]`. One case at a time: the cluster's threads are the
    parallelism; each case in a process forked from the worker's, so a case that
    crashes fails alone. A failure of the whole shard raises yamsc.Error with the
    CLI's message."""
    status, out, err = _yamsc.batch(manifest, outdir, shard, shards, 1, True,
                                    case_time_limit)
    if err:
        # A model's compile notice and diagnostics, the failed rows: the worker's log.
        sys.stderr.write(err)
    return status, out, err


def _worker_threads(client):
    """The threads of the cluster's workers (waiting for a first worker when it has none)."""
    threads = sum(client.nthreads().values())
    if threads == 0:
        client.wait_for_workers(1)
        threads = sum(client.nthreads().values())
    return threads


def _remove_other_summaries(outdir, shards):
    """Shard summaries of an earlier run with another N: `yamsc batch merge`
    refuses to mix shard counts, and this run's N shards supersede them."""
    if not os.path.isdir(outdir):
        return
    for name in os.listdir(outdir):
        match = re.fullmatch(r"summary-([0-9]+)-of-([0-9]+)\.csv", name)
        if match and int(match.group(2)) != shards:
            os.remove(os.path.join(outdir, name))


def run(manifest, client=None, outdir=None, shards=None, frame=None, case_time_limit=None):
    """Runs a `yamsc batch` manifest on a Dask cluster and returns its summary.

    client: a distributed.Client (default: the current one). outdir: the output
    folder (default: as `yamsc batch`, the manifest without .csv plus .out).
    shards: the number of tasks N (default: the workers' threads at the call;
    give it for an adaptive cluster). case_time_limit: seconds after which a
    case is stopped and failed (`--case-time-limit`; a row's time_limit wins).
    A task that was run before in the same folder reuses its finished cases,
    as `yamsc batch` does.

    Returns the merged summary (OUTDIR/summary.csv, see read_summary); a row
    that failed has status "error" and its located message, as in `yamsc
    batch`. A failure of a whole task (an unusable manifest, an output folder
    that cannot be written) raises yamsc.Error with yamsc's message.
    """
    if client is None:
        from distributed import default_client
        client = default_client()
    # Absolute paths: a worker's working directory may be another.
    manifest = os.path.abspath(os.fspath(manifest))
    outdir = os.path.abspath(os.fspath(outdir) if outdir is not None
                             else default_output_dir(manifest))
    n = int(shards) if shards is not None else _worker_threads(client)
    if n < 1:
        raise ValueError(f"shards must be at least 1, not {n}")
    _remove_other_summaries(outdir, n)
    tag = uuid.uuid4().hex[:8]
    limit = float(case_time_limit) if case_time_limit is not None else 0.0
    futures = [client.submit(_run_shard, manifest, outdir, k, n, limit, pure=False,
                             key=f"yamsc-batch-{k}-of-{n}-{tag}")
               for k in range(1, n + 1)]
    try:
        client.gather(futures)
    except BaseException:
        client.cancel(futures)
        raise
    _yamsc.batch_merge([outdir], "")
    return read_summary(os.path.join(outdir, "summary.csv"), frame)
