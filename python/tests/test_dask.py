"""yamsc.dask.run on a real distributed.LocalCluster (two worker processes)
against the yamsc executable: the result files are the bytes `yamsc batch`
writes in one process and in four shards merged, the summaries the same lines
(but the wall times); a bad row fails alone, located; an unusable manifest
raises yamsc.Error with the CLI's message; a second run reuses the results."""
import os
import subprocess
import time
from pathlib import Path

import pytest

import yamsc

distributed = pytest.importorskip("distributed")
import yamsc.dask  # noqa: E402 (after the skip: it is only useful with distributed)

CASES = 24


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster:
        with distributed.Client(cluster) as c:
            yield c


@pytest.fixture(scope="module")
def manifest(models, tmp_path_factory):
    """A sweep of the floating 3-DOF model (as tests/batch): floater mass, shaft
    tilt, initial pitch; 2 s cases; and a row with a bad value."""
    folder = tmp_path_factory.mktemp("dask")
    model = models / "nrel5mw_floating_3dof.mbd"
    lines = ["id,model,tmax,dt,set:M_F,set:theta_t,ic:phi_y"]
    for i in range(CASES):
        lines.append(f"case{i},{model},2,0.05,{6.5e6 + 1e4 * (i % 17):.0f},{i % 7}deg,"
                     f"{0.01 + 0.001 * i:.3f}")
    lines.insert(8, f"bad,{model},2,0.05,nan,,")
    path = folder / "cases.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


def yamsc_batch(*args, status=1):
    """`yamsc batch ARGS...`: exit 1 when the bad row is among its rows."""
    done = subprocess.run([os.environ["YAMSC_EXE"], "batch", *map(str, args)],
                          capture_output=True, text=True)
    assert done.returncode == status, done.stderr
    return done


def results(folder):
    return {p.name: p.read_bytes() for p in sorted(Path(folder).glob("*.csv"))
            if not p.name.startswith("summary")}


def without_wall_times(summary):
    return [line.rsplit(",", 1)[0] for line in Path(summary).read_text().splitlines()]


@pytest.fixture(scope="module")
def one_process(manifest):
    """`yamsc batch` on one thread, timed."""
    out = manifest.parent / "one"
    start = time.perf_counter()
    yamsc_batch(manifest, "-o", out, "--threads", "1", "-q")
    return out, time.perf_counter() - start


def test_same_files_as_yamsc_batch_and_its_shards(client, manifest, one_process):
    one, one_seconds = one_process
    sharded = manifest.parent / "sharded"
    for k in range(1, 5):  # the bad row (index 7) is in shard 4
        yamsc_batch(manifest, "-o", sharded, "--shard", f"{k}/4", "-q", status=int(k == 4))
    yamsc_batch("merge", sharded)

    out = manifest.parent / "dask"
    start = time.perf_counter()
    summary = yamsc.dask.run(manifest, client, outdir=out)
    dask_seconds = time.perf_counter() - start
    print(f"\n{CASES + 1} cases: dask (2 workers) {dask_seconds:.2f} s, "
          f"one process {one_seconds:.2f} s")

    assert len(results(one)) == CASES
    assert results(out) == results(one)
    assert results(sharded) == results(one)
    assert without_wall_times(out / "summary.csv") == without_wall_times(one / "summary.csv")
    assert without_wall_times(sharded / "summary.csv") == without_wall_times(one / "summary.csv")
    # Two worker threads: two shards, whose summaries were merged.
    assert sorted(p.name for p in out.glob("summary-*")) == ["summary-1-of-2.csv",
                                                              "summary-2-of-2.csv"]

    # The summary returned is the file's: 25 rows in manifest order, the bad
    # row (the 8th data row) failed alone at its place.
    assert list(summary["id"][:9]) == [f"case{i}" for i in range(7)] + ["bad", "case7"]
    assert list(summary["row"]) == list(range(1, CASES + 2))
    assert (summary["status"] == "ok").sum() == CASES
    bad = summary[summary["status"] == "error"].iloc[0]
    line = manifest.read_text().splitlines()[8]
    column = line.index(",nan,") + 2
    assert bad["message"] == f"{manifest}:9:{column}: error: set:M_F: 'nan' is not a number"
    assert bad["final"] == ""
    # The final values of a case are its result's last row.
    last = (out / "case3.csv").read_text().splitlines()
    header, values = last[0].split(","), last[-1].split(",")
    final = dict(kv.split("=") for kv in summary.loc[summary["id"] == "case3", "final"].iloc[0]
                 .split(","))
    assert list(final) == header
    assert [float(final[h]) for h in header] == pytest.approx([float(v) for v in values],
                                                              rel=1e-9)


def test_a_second_run_reuses_the_results(client, manifest, one_process):
    one, _ = one_process
    out = manifest.parent / "again"
    yamsc.dask.run(manifest, client, outdir=out, shards=2)
    written = {p.name: p.stat().st_mtime_ns for p in out.glob("case*.csv")}
    # Another shard count: the earlier shards' summaries make way, the cases are done.
    summary = yamsc.dask.run(manifest, client, outdir=out, shards=3, frame=False)
    assert {p.name: p.stat().st_mtime_ns for p in out.glob("case*.csv")} == written
    assert sorted(p.name for p in out.glob("summary-*")) == [f"summary-{k}-of-3.csv"
                                                              for k in (1, 2, 3)]
    assert without_wall_times(out / "summary.csv") == without_wall_times(one / "summary.csv")
    assert isinstance(summary, list) and summary[0]["id"] == "case0"
    assert results(out) == results(one)


def test_an_unusable_manifest_raises_the_located_error(client, tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("id,model,tmax,dt,colour\nx,m.mbd,1,0.1,red\n")
    with pytest.raises(yamsc.Error, match=f"^{bad}:1:18: error: unknown column 'colour'"):
        yamsc.dask.run(bad, client)
    done = subprocess.run([os.environ["YAMSC_EXE"], "batch", bad], capture_output=True, text=True)
    assert f"{bad}:1:18: error: unknown column 'colour'" in done.stderr


def test_a_case_over_its_time_limit_fails_alone(client, models, tmp_path):
    # 10^8 steps: far beyond a second; the other case takes milliseconds.
    model = models / "nrel5mw_floating_3dof.mbd"
    path = tmp_path / "limit.csv"
    path.write_text(f"id,model,tmax,dt\nlong,{model},1e5,0.001\nshort,{model},2,0.05\n")
    start = time.perf_counter()
    summary = yamsc.dask.run(path, client, shards=2, frame=False, case_time_limit=1)
    assert time.perf_counter() - start < 30
    by_id = {row["id"]: row for row in summary}
    assert by_id["short"]["status"] == "ok"
    assert by_id["long"]["status"] == "error"
    assert by_id["long"]["message"] == f"{path}:2:1: error: time limit of 1 s exceeded"
    assert not (tmp_path / "limit.out" / "long.csv").exists()
